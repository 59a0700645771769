/* Determinism beyond what test_eval (batch sizes, strides), test_deriv and test_grid (grid against
 * scattered) check: a grid equals its rows evaluated as one-row grids, normals and high
 * derivatives do not depend on the batch size, and a digest of all results is printed so that
 * separate runs can be compared (determinism_runs.sh runs the program twice and compares the digest
 * with the committed value). */
#include "eval_util.h"

#include <stdint.h>

enum { NU = 9, NV = 70, NPT = 203 };

static uint64_t digest = 1469598103934665603ull; /* FNV-1a over every result's bytes */

static void mix(const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t k = 0; k < n; k++)
        digest = (digest ^ b[k]) * 1099511628211ull;
}

static void grid_by_rows(const bs_patch *p, const double *u, const double *v)
{
    size_t dim = bs_patch_dim(p);
    int nr = dim == 3;
    static double full[4][BS_MAX_DIM][NU * NV], rows[4][BS_MAX_DIM][NU * NV];
    static unsigned char fk[NU * NV], rk[NU * NV];
    bs_view fv[4][BS_MAX_DIM], rv[4][BS_MAX_DIM];
    for (int d = 0; d < 4; d++)
        for (size_t c = 0; c < dim; c++)
            fv[d][c] = (bs_view){full[d][c], NU * NV, 0};
    bs_cview cu = {u, NU, 0}, cv = {v, NV, 0};
    CHECK_STATUS(bs_patch_eval_grid(p, NU, &cu, NV, &cv, fv[0], fv[1], fv[2], nr ? fv[3] : NULL, nr ? fk : NULL),
                 BS_OK);
    for (size_t a = 0; a < NU; a++) {
        for (int d = 0; d < 4; d++)
            for (size_t c = 0; c < dim; c++)
                rv[d][c] = (bs_view){rows[d][c] + a * NV, NV, 0};
        bs_cview one = {u + a, 1, 0};
        CHECK_STATUS(bs_patch_eval_grid(p, 1, &one, NV, &cv, rv[0], rv[1], rv[2], nr ? rv[3] : NULL,
                                        nr ? rk + a * NV : NULL),
                     BS_OK);
    }
    int same = nr ? memcmp(fk, rk, sizeof fk) == 0 : 1;
    for (int d = 0; d < (nr ? 4 : 3); d++)
        for (size_t c = 0; c < (d == 3 ? 3 : dim); c++)
            same &= memcmp(full[d][c], rows[d][c], sizeof full[d][c]) == 0;
    CHECKF(same, "grid of degree (%zu,%zu) differs from its rows", bs_patch_degree_u(p), bs_patch_degree_v(p));
    for (int d = 0; d < 4; d++)
        for (size_t c = 0; c < dim; c++)
            mix(full[d][c], sizeof full[d][c]);
}

/* Normals and (3,2) derivatives of all points in one call, then in batches of size b, with a
 * negative output stride: the same bits. */
static void batches(const bs_patch *p, const double *u, const double *v)
{
    size_t dim = bs_patch_dim(p);
    static double one[BS_MAX_DIM][NPT], many[BS_MAX_DIM][2 * NPT];
    static unsigned char k1[NPT], k2[NPT];
    static size_t where[NPT];
    bs_view ov[BS_MAX_DIM], bv[BS_MAX_DIM];
    bs_cview cu = {u, NPT, 0}, cv = {v, NPT, 0};
    for (size_t c = 0; c < dim; c++)
        ov[c] = (bs_view){one[c], NPT, 0};
    int normals = dim == 3;
    if (normals)
        CHECK_STATUS(bs_patch_eval_normal(p, NPT, &cu, &cv, NULL, ov, k1), BS_OK);
    else
        CHECK_STATUS(bs_patch_eval_deriv(p, 3, 2, NPT, &cu, &cv, ov), BS_OK);
    static const size_t sizes[] = {1, 2, 3, 7, 8, 16, 17, 64, 100};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t b = sizes[s];
        for (size_t k0 = 0; k0 < NPT; k0 += b) {
            size_t nb = NPT - k0 < b ? NPT - k0 : b;
            bs_cview bu = {u + k0, nb, 0}, bvv = {v + k0, nb, 0};
            /* the batch goes backwards into every other element: point k0+k lands at
             * many[c][2*(k0+nb-1-k)] */
            for (size_t k = 0; k < nb; k++)
                where[k0 + k] = 2 * (k0 + nb - 1 - k);
            for (size_t c = 0; c < dim; c++)
                bv[c] = (bs_view){&many[c][2 * (k0 + nb - 1)], nb, -2 * (ptrdiff_t)sizeof(double)};
            if (normals)
                CHECK_STATUS(bs_patch_eval_normal(p, nb, &bu, &bvv, NULL, bv, k2 + k0), BS_OK);
            else
                CHECK_STATUS(bs_patch_eval_deriv(p, 3, 2, nb, &bu, &bvv, bv), BS_OK);
        }
        int same = normals ? memcmp(k1, k2, sizeof k1) == 0 : 1;
        for (size_t c = 0; c < dim; c++)
            for (size_t k = 0; k < NPT; k++)
                same &= memcmp(&one[c][k], &many[c][where[k]], sizeof(double)) == 0;
        CHECKF(same, "batches of %zu differ from one call", b);
    }
    for (size_t c = 0; c < dim; c++)
        mix(one[c], sizeof one[c]);
}

/* The built-in teapot (bicubic, with collapsed edges) through the paths its degree has kernels
 * for: grid positions + normals alone (the fused path), grid and scattered first partials,
 * scattered normals. Only mixed into the digest, which .ci/isa.sh compares across instruction sets. */
static void teapot(const double *u0, const double *v0)
{
    /* non-finite parameters too, inside a block of the packed path and in the tail */
    double u[NPT], v[NPT];
    memcpy(u, u0, sizeof u);
    memcpy(v, v0, sizeof v);
    u[37] = NAN;
    v[70] = INFINITY;
    u[NPT - 2] = -INFINITY;
    enum { G = 33 };
    static double grid[9][G * G], pts[9][NPT];
    static unsigned char gk[G * G], pk[NPT];
    double t[G];
    for (size_t a = 0; a < G; a++)
        t[a] = (double)a / (G - 1);
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    bs_cview ct = {t, G, 0}, cu = {u, NPT, 0}, cv = {v, NPT, 0};
    bs_view gv[9], pv[9];
    for (size_t c = 0; c < 9; c++) {
        gv[c] = (bs_view){grid[c], G * G, 0};
        pv[c] = (bs_view){pts[c], NPT, 0};
    }
    for (size_t k = 0; s != NULL && k < bs_surface_count(s); k++) {
        const bs_patch *p = bs_surface_get(s, k);
        CHECK_STATUS(bs_patch_eval_grid(p, G, &ct, G, &ct, gv, NULL, NULL, gv + 3, gk), BS_OK);
        mix(grid, 6 * sizeof grid[0]);
        mix(gk, sizeof gk);
        CHECK_STATUS(bs_patch_eval_grid(p, G, &ct, G, &ct, gv, gv + 3, gv + 6, NULL, NULL), BS_OK);
        mix(grid, sizeof grid);
        CHECK_STATUS(bs_patch_eval(p, NPT, &cu, &cv, pv, pv + 3, pv + 6), BS_OK);
        mix(pts, sizeof pts);
        /* packed views take a path of their own: strided ones must give the same bits */
        static double wide[9][2 * NPT];
        bs_view sv[9];
        for (size_t c = 0; c < 9; c++)
            sv[c] = (bs_view){wide[c], NPT, 2 * (ptrdiff_t)sizeof(double)};
        CHECK_STATUS(bs_patch_eval(p, NPT, &cu, &cv, sv, sv + 3, sv + 6), BS_OK);
        int same = 1;
        for (size_t c = 0; c < 9; c++)
            for (size_t i = 0; i < NPT; i++)
                same &= memcmp(&pts[c][i], &wide[c][2 * i], sizeof(double)) == 0;
        CHECKF(same, "teapot patch %zu: strided views differ from packed ones", k);
        CHECKF(isnan(pts[0][37]) && isnan(pts[5][70]) && isnan(pts[8][NPT - 2]) && !isnan(pts[0][36]),
               "teapot patch %zu: non-finite parameters must give NaN, and only there", k);
        CHECK_STATUS(bs_patch_eval(p, NPT, &cu, &cv, pv, NULL, NULL), BS_OK);
        mix(pts, 3 * sizeof pts[0]);
        CHECK_STATUS(bs_patch_eval_normal(p, NPT, &cu, &cv, pv, pv + 3, pk), BS_OK);
        mix(pts, 6 * sizeof pts[0]);
        mix(pk, sizeof pk);
    }
    bs_surface_destroy(s);
}

int main(void)
{
    unsigned long long rng = 2026;
    double u[NPT], v[NPT];
    for (size_t k = 0; k < NPT; k++) {
        u[k] = k < 3 ? (double)k / 2 : bs_test_rand(&rng, -0.1, 1.1);
        v[k] = k < 3 ? 1.0 - (double)k / 2 : bs_test_rand(&rng, -0.1, 1.1);
    }
    static const size_t shapes[][3] = {{3, 3, 3}, {1, 5, 3}, {7, 2, 2}, {0, 4, 1}, {12, 9, 3}, {5, 5, 8}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; s++)
        for (int rational = 0; rational < 2; rational++) {
            tnet t = tnet_random(&rng, shapes[s][0], shapes[s][1], shapes[s][2], rational, 0.25, 4.0);
            bs_patch *p = NULL;
            CHECK_STATUS(bs_patch_create(t.m, t.n, t.dim, t.ctrl, t.w, &p), BS_OK);
            grid_by_rows(p, u, v);
            batches(p, u, v);
            bs_patch_destroy(p);
            tnet_free(&t);
        }
    teapot(u, v);
    printf("result digest %016llx\n", (unsigned long long)digest);
    return bs_test_exit("test_determinism");
}
