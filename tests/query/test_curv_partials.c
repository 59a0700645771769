/* The curvature's one-pass partials (bsi_curv_partials_chunk, lib/core/partials2.c; internal,
 * built with the library's sources): its S_u and S_v are the bits of bs_patch_eval's, its normal
 * and kind those of bs_patch_eval_normal, at every point of chunks of several sizes on the
 * teapot (bicubic, collapsed edges and poles), on random bicubic patches (whose sums, unlike the
 * teapot's, change with their order) and on polynomial patches of other degrees; the same
 * for rational patches (the teapot's nets with weights, random ones of several degrees), whose
 * partials come from the quotient rule on the homogeneous sums; its second partials agree with
 * bs_patch_eval_deriv's. */
#include "harness.h"
#include "core/internal.h"

#include <math.h>
#include <string.h>

#define L BSI_PCHUNK

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* nb points from u, v: the chunk against the public evaluators. */
static void one_chunk(const bs_patch *p, size_t nb, const double *u, const double *v)
{
    double d[15 * L], nrm[3 * L], ref[3][L], su[3][L], sv[3][L], rn[3][L];
    unsigned char kind[L], rk[L];
    bsi_nscale sc;
    bsi_normal_scale(p, &sc);
    bsi_curv_partials_chunk(p, &sc, nb, u, v, d, nrm, kind);
    bs_cview cu = {u, nb, 0}, cv = {v, nb, 0};
    bs_view vu[3], vv[3], vn[3], vr[3];
    for (int c = 0; c < 3; c++) {
        vu[c] = (bs_view){su[c], nb, 0};
        vv[c] = (bs_view){sv[c], nb, 0};
        vn[c] = (bs_view){rn[c], nb, 0};
        vr[c] = (bs_view){ref[c], nb, 0};
    }
    CHECK_STATUS(bs_patch_eval(p, nb, &cu, &cv, NULL, vu, vv), BS_OK);
    CHECK_STATUS(bs_patch_eval_normal(p, nb, &cu, &cv, NULL, vn, rk), BS_OK);
    int first = 1, normal = 1;
    for (size_t k = 0; k < nb; k++) {
        normal &= kind[k] == rk[k];
        for (size_t c = 0; c < 3; c++) {
            first &= same_bits(d[c * L + k], su[c][k]) && same_bits(d[(3 + c) * L + k], sv[c][k]);
            normal &= same_bits(nrm[c * L + k], rn[c][k]);
        }
    }
    CHECKF(first, "degree (%zu,%zu), %zu points: S_u, S_v differ from bs_patch_eval's",
           bs_patch_degree_u(p), bs_patch_degree_v(p), nb);
    CHECKF(normal, "degree (%zu,%zu), %zu points: normal or kind differs from bs_patch_eval_normal's",
           bs_patch_degree_u(p), bs_patch_degree_v(p), nb);
    static const unsigned ab[3][2] = {{2, 0}, {1, 1}, {0, 2}};
    for (int j = 0; j < 3; j++) {
        CHECK_STATUS(bs_patch_eval_deriv(p, ab[j][0], ab[j][1], nb, &cu, &cv, vr), BS_OK);
        double worst = 0.0, big = 1.0;
        for (size_t k = 0; k < nb; k++)
            for (size_t c = 0; c < 3; c++) {
                worst = fmax(worst, fabs(d[(3 * (2 + (size_t)j) + c) * L + k] - ref[c][k]));
                big = fmax(big, fabs(ref[c][k]));
            }
        CHECKF(worst <= 1e-12 * big, "degree (%zu,%zu): second partial %d off by %.3g of %.3g",
               bs_patch_degree_u(p), bs_patch_degree_v(p), j, worst, big);
    }
}

/* The parameters of a 17 x 17 grid with the edges and points just inside them, in chunks of
 * L, 7 and 1 points. */
static void chunks(const bs_patch *p)
{
    static const double t[17] = {0.0, 1e-12, 1e-6, 0.0625, 0.125, 0.25, 0.3, 0.375, 0.5, 0.6,
                                 0.7, 0.75, 0.875, 0.9375, 1.0 - 1e-6, 1.0 - 1e-12, 1.0};
    double u[289], v[289];
    for (int i = 0; i < 289; i++) {
        u[i] = t[i / 17];
        v[i] = t[i % 17];
    }
    static const size_t sizes[3] = {L, 7, 1};
    for (int s = 0; s < 3; s++)
        for (size_t k0 = 0; k0 < 289; k0 += sizes[s])
            one_chunk(p, 289 - k0 < sizes[s] ? 289 - k0 : sizes[s], u + k0, v + k0);
}

/* Random patches of several degrees, with weights in [0.5, 2] when rational, each also with
 * its row i = 0 collapsed to one point. */
static void random_patches(int rational, unsigned long long rng)
{
    static const size_t deg[][2] = {{3, 3}, {2, 3}, {3, 2}, {5, 1}, {1, 1}, {4, 4}, {0, 2}, {6, 3}, {2, 2}};
    double ctrl[7 * 7 * 3], w[7 * 7];
    for (size_t d = 0; d < sizeof deg / sizeof deg[0]; d++)
        for (int collapsed = 0; collapsed < 2; collapsed++) {
            size_t m = deg[d][0], n = deg[d][1];
            for (size_t k = 0; k < (m + 1) * (n + 1); k++)
                for (size_t c = 0; c < 3; c++) {
                    double base = c == 0 ? (double)(k / (n + 1)) : c == 1 ? (double)(k % (n + 1)) : 0.0;
                    /* collapsed: row i = 0 is one point */
                    ctrl[3 * k + c] = collapsed && k <= n ? 0.5 * (double)c
                                                          : base + bs_test_rand(&rng, -0.4, 0.4);
                }
            for (size_t k = 0; rational && k < (m + 1) * (n + 1); k++)
                w[k] = bs_test_rand(&rng, 0.5, 2.0);
            bs_patch *p;
            CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, rational ? w : NULL, &p), BS_OK);
            chunks(p);
            bs_patch_destroy(p);
        }
}

int main(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *q = bs_surface_get(s, i);
        chunks(q);
        double ctrl[16 * 3], w[16]; /* the same net, weights 1, 1.5, 2 */
        CHECK_STATUS(bs_patch_get_ctrl(q, ctrl, 48, NULL, 0), BS_OK);
        for (size_t k = 0; k < 16; k++)
            w[k] = 1.0 + 0.5 * (double)(k % 3);
        bs_patch *p;
        CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl, w, &p), BS_OK);
        chunks(p);
        bs_patch_destroy(p);
    }
    bs_surface_destroy(s);
    random_patches(0, 11);
    random_patches(1, 12);
    return bs_test_exit("test_curv_partials");
}
