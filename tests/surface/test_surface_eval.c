/* Scattered evaluation across a surface: equal, bit for bit, to the patch evaluators point by point
 * whatever the order of the ids and the strides; close to the long-double reference; error paths
 * write nothing. */
#include "harness.h"
#include "reference.h"

#include <bezsurf.h>

#include <math.h>
#include <string.h>

#define N 600

/* Relative-to-scale difference between a double and the reference. */
static double rel_err(double x, long double r, double scale)
{
    return (double)fabsl((long double)x - r) / scale;
}

static void test_against_patches(const char *name, int sorted)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin(name, &s), BS_OK);
    size_t np = bs_surface_count(s);
    unsigned long long seed = 4242 + (unsigned long long)sorted;
    static uint32_t ids[N];
    static double u[N], v[N];
    for (size_t k = 0; k < N; k++) {
        ids[k] = (uint32_t)(bs_test_rand_u64(&seed) % np);
        u[k] = bs_test_rand(&seed, -0.1, 1.1);
        v[k] = bs_test_rand(&seed, -0.1, 1.1);
    }
    if (sorted) /* counting sort by id: long runs */
        for (size_t k = 1; k < N; k++)
            for (size_t j = k; j > 0 && ids[j - 1] > ids[j]; j--) {
                uint32_t t = ids[j]; ids[j] = ids[j - 1]; ids[j - 1] = t;
                double a = u[j]; u[j] = u[j - 1]; u[j - 1] = a;
                a = v[j]; v[j] = v[j - 1]; v[j - 1] = a;
            }
    /* Outputs: positions interleaved (stride 24), du packed, dv packed but backwards (negative stride). */
    static double pos[3 * N], du[3 * N], dv[3 * N], nrm[3 * N];
    static unsigned char kind[N];
    bs_cview cu = {u, N, 0}, cv = {v, N, 0};
    bs_view vp[3], vdu[3], vdv[3], vn[3];
    for (size_t c = 0; c < 3; c++) {
        vp[c] = (bs_view){pos + c, N, 3 * sizeof(double)};
        vdu[c] = (bs_view){du + c * N, N, 0};
        vdv[c] = (bs_view){dv + c * N + N - 1, N, -(ptrdiff_t)sizeof(double)};
        vn[c] = (bs_view){nrm + c * N, N, 0};
    }
    CHECK_STATUS(bs_surface_eval(s, N, ids, &cu, &cv, vp, vdu, vdv), BS_OK);
    int same = 1;
    double worst = 0.0;
    for (size_t k = 0; k < N; k++) {
        const bs_patch *p = bs_surface_get(s, ids[k]);
        double q[3], qu[3], qv[3];
        bs_cview pu = {&u[k], 1, 0}, pv = {&v[k], 1, 0};
        bs_view wq[3] = {{q, 1, 0}, {q + 1, 1, 0}, {q + 2, 1, 0}};
        bs_view wu[3] = {{qu, 1, 0}, {qu + 1, 1, 0}, {qu + 2, 1, 0}};
        bs_view wv[3] = {{qv, 1, 0}, {qv + 1, 1, 0}, {qv + 2, 1, 0}};
        same &= bs_patch_eval(p, 1, &pu, &pv, wq, wu, wv) == BS_OK;
        double ctrl[48];
        bs_patch_get_ctrl(p, ctrl, 48, NULL, 0);
        ref_net net = {3, 3, 3, ctrl, NULL};
        long double r[3], ru[3], rv[3];
        ref_eval(&net, u[k], v[k], r);
        ref_deriv(&net, 1, 0, u[k], v[k], ru);
        ref_deriv(&net, 0, 1, u[k], v[k], rv);
        for (size_t c = 0; c < 3; c++) {
            same &= pos[3 * k + c] == q[c] && du[c * N + k] == qu[c] && dv[c * N + N - 1 - k] == qv[c];
            worst = fmax(worst, rel_err(pos[3 * k + c], r[c], 4.0));
            worst = fmax(worst, rel_err(du[c * N + k], ru[c], 40.0));
            worst = fmax(worst, rel_err(dv[c * N + N - 1 - k], rv[c], 40.0));
        }
    }
    CHECKF(same, "%s: surface and patch evaluation differ", name);
    CHECKF(worst < 1e-14, "%s: error %g against the reference", name, worst);

    memset(kind, 9, sizeof kind);
    CHECK_STATUS(bs_surface_eval_normal(s, N, ids, &cu, &cv, vp, vn, kind), BS_OK);
    same = 1;
    for (size_t k = 0; k < N; k++) {
        double q[3], qn[3];
        unsigned char qk = 7;
        bs_cview pu = {&u[k], 1, 0}, pv = {&v[k], 1, 0};
        bs_view wq[3] = {{q, 1, 0}, {q + 1, 1, 0}, {q + 2, 1, 0}};
        bs_view wn[3] = {{qn, 1, 0}, {qn + 1, 1, 0}, {qn + 2, 1, 0}};
        same &= bs_patch_eval_normal(bs_surface_get(s, ids[k]), 1, &pu, &pv, wq, wn, &qk) == BS_OK;
        for (size_t c = 0; c < 3; c++)
            same &= pos[3 * k + c] == q[c] && nrm[c * N + k] == qn[c];
        same &= kind[k] == qk;
    }
    CHECKF(same, "%s: surface and patch normals differ", name);
    bs_surface_destroy(s);
}

static void test_errors(void)
{
    bs_surface *s;
    bs_surface_create_builtin("teaspoon", &s);
    uint32_t ids[4] = {0, 15, 16, 3};
    double u[4] = {0.5, 0.5, 0.5, 0.5}, out[12];
    for (size_t k = 0; k < 12; k++)
        out[k] = -99.0;
    bs_cview cu = {u, 4, 0};
    bs_view vp[3] = {{out, 4, 0}, {out + 4, 4, 0}, {out + 8, 4, 0}};
    unsigned char kind[4] = {9, 9, 9, 9};
    /* Id 16 of 16 patches: rejected before anything is written, even the points before it. */
    CHECK_STATUS(bs_surface_eval(s, 4, ids, &cu, &cu, vp, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval_normal(s, 4, ids, &cu, &cu, vp, vp, kind), BS_ERR_INVALID_ARG);
    int untouched = kind[0] == 9;
    for (size_t k = 0; k < 12; k++)
        untouched &= out[k] == -99.0;
    CHECK(untouched);
    ids[2] = 2;
    CHECK_STATUS(bs_surface_eval(NULL, 4, ids, &cu, &cu, vp, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval(s, 4, NULL, &cu, &cu, vp, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval(s, 4, ids, NULL, &cu, vp, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval(s, 4, ids, &cu, NULL, vp, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval(s, 5, ids, &cu, &cu, vp, NULL, NULL), BS_ERR_SIZE);
    bs_view shortv[3] = {{out, 4, 0}, {out + 4, 3, 0}, {out + 8, 4, 0}};
    CHECK_STATUS(bs_surface_eval(s, 4, ids, &cu, &cu, shortv, NULL, NULL), BS_ERR_SIZE);
    CHECK_STATUS(bs_surface_eval_normal(s, 4, ids, &cu, &cu, NULL, shortv, NULL), BS_ERR_SIZE);
    bs_view odd[3] = {{out, 4, 4}, {out + 4, 4, 0}, {out + 8, 4, 0}};
    CHECK_STATUS(bs_surface_eval(s, 4, ids, &cu, &cu, odd, NULL, NULL), BS_ERR_INVALID_ARG);
    untouched = kind[0] == 9;
    for (size_t k = 0; k < 12; k++)
        untouched &= out[k] == -99.0;
    CHECK(untouched);
    CHECK_STATUS(bs_surface_eval(s, 0, NULL, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_surface_eval_normal(s, 0, NULL, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_surface_eval(NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval(s, 4, ids, &cu, &cu, vp, NULL, NULL), BS_OK);
    CHECK(out[0] != -99.0);
    bs_surface_destroy(s);
    /* Normals of a 2-D surface; an empty surface has no ids. */
    double net2[2] = {1, 2};
    bs_patch *p;
    bs_patch_create(0, 0, 2, net2, NULL, &p);
    bs_surface_create(&s);
    ids[0] = 0;
    CHECK_STATUS(bs_surface_eval(s, 1, ids, &cu, &cu, NULL, NULL, NULL), BS_ERR_INVALID_ARG);
    bs_surface_add(s, p, NULL);
    CHECK_STATUS(bs_surface_eval_normal(s, 1, ids, &cu, &cu, NULL, NULL, NULL), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_eval(s, 1, ids, &cu, &cu, vp, NULL, NULL), BS_OK);
    CHECK(out[0] == 1.0 && out[4] == 2.0);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
}

int main(void)
{
    test_against_patches("teapot", 0);
    test_against_patches("teapot", 1);
    test_against_patches("teacup", 1);
    test_errors();
    return bs_test_exit("test_surface_eval");
}
