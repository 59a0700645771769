/* bs_patch_eval_grid_f32: every float is the double of bs_patch_eval_grid rounded to the nearest
 * float, for every set of outputs and kind of patch (rational, collapsed edges with limit normals,
 * NaN parameters, cubic rows across the column-pass boundary), through packed, interleaved and
 * negative-stride views; bad views are refused with nothing written. */
#include "eval_util.h"

#ifndef BS_DATA_DIR
#define BS_DATA_DIR "data"
#endif

/* f is d correctly rounded: the bits of (float)d, and no neighbour of f is nearer to d (a
 * property of rounding to nearest, checked apart from the conversion itself). */
static int rounded(double d, float f)
{
    if (isnan(d))
        return isnan(f);
    float r = (float)d;
    if (memcmp(&r, &f, sizeof f) != 0)
        return 0;
    if (!isfinite(f))
        return fabs(d) >= (double)FLT_MAX;
    double err = fabs((double)f - d);
    float up = nextafterf(f, INFINITY), down = nextafterf(f, -INFINITY);
    return (!isfinite(up) || err <= fabs((double)up - d)) &&
           (!isfinite(down) || err <= fabs((double)down - d));
}

/* The outputs asked for: positions, S_u, S_v, normals (each 1 or 0), and kinds. */
typedef struct outputs {
    int pos, du, dv, nrm, kind;
} outputs;

static const outputs workloads[] = {
    {1, 0, 0, 0, 0}, {1, 1, 1, 0, 0}, {1, 0, 0, 1, 1}, {1, 1, 1, 1, 1},
    {0, 1, 0, 0, 0}, {0, 0, 1, 0, 0}, {0, 0, 0, 1, 0}, {0, 0, 0, 0, 1},
};

/* One workload both ways, float views of the given byte stride (a multiple of 4, may be negative:
 * element 0 is then the last in memory). */
static void compare_workload(const bs_patch *p, size_t nu, const double *u, size_t nv,
                             const double *v, const outputs *w, ptrdiff_t stride)
{
    size_t dim = bs_patch_dim(p), tot = nu * nv;
    ptrdiff_t bytes = stride == 0 ? (ptrdiff_t)sizeof(float) : stride;
    size_t step = (size_t)(bytes < 0 ? -bytes : bytes) / sizeof(float);
    double *d = malloc(4 * BS_MAX_DIM * tot * sizeof(double));
    float *f = malloc(4 * BS_MAX_DIM * tot * step * sizeof(float));
    unsigned char *dk = malloc(tot), *fk = malloc(tot);
    bs_view dview[4][BS_MAX_DIM];
    bs_fview fview[4][BS_MAX_DIM];
    for (size_t o = 0; o < 4; o++)
        for (size_t c = 0; c < BS_MAX_DIM; c++) {
            dview[o][c].data = d + (o * BS_MAX_DIM + c) * tot;
            dview[o][c].count = tot;
            dview[o][c].stride = 0;
            float *base = f + (o * BS_MAX_DIM + c) * tot * step;
            fview[o][c].data = stride < 0 ? base + (tot - 1) * step : base;
            fview[o][c].count = tot;
            fview[o][c].stride = stride;
        }
    bs_cview cu = cview_of(u, nu), cv = cview_of(v, nv);
    int on[4] = {w->pos, w->du, w->dv, w->nrm};
    CHECK_STATUS(bs_patch_eval_grid(p, nu, &cu, nv, &cv, on[0] ? dview[0] : NULL,
                                    on[1] ? dview[1] : NULL, on[2] ? dview[2] : NULL,
                                    on[3] ? dview[3] : NULL, w->kind ? dk : NULL),
                 BS_OK);
    CHECK_STATUS(bs_patch_eval_grid_f32(p, nu, &cu, nv, &cv, on[0] ? fview[0] : NULL,
                                        on[1] ? fview[1] : NULL, on[2] ? fview[2] : NULL,
                                        on[3] ? fview[3] : NULL, w->kind ? fk : NULL),
                 BS_OK);
    size_t bad = 0;
    for (size_t o = 0; o < 4; o++)
        for (size_t c = 0; on[o] && c < (o == 3 ? 3 : dim); c++)
            for (size_t k = 0; k < tot; k++) {
                const float *fx = (const float *)(const void *)((const char *)fview[o][c].data +
                                                                (ptrdiff_t)k * bytes);
                bad += !rounded(dview[o][c].data[k], *fx);
            }
    if (w->kind)
        bad += memcmp(dk, fk, tot) != 0;
    CHECKF(bad == 0, "%zu x %zu, outputs %d%d%d%d%d, stride %td: %zu float(s) not the rounded double",
           nu, nv, w->pos, w->du, w->dv, w->nrm, w->kind, stride, bad);
    free(d);
    free(f);
    free(dk);
    free(fk);
}

static void compare_all(const bs_patch *p, size_t nu, const double *u, size_t nv, const double *v)
{
    size_t nw = sizeof workloads / sizeof workloads[0];
    int normals = bs_patch_dim(p) == 3;
    ptrdiff_t strides[] = {0, 4, 12, -12, -4};
    for (size_t k = 0; k < nw; k++) {
        if (!normals && (workloads[k].nrm || workloads[k].kind))
            continue;
        for (size_t s = 0; s < sizeof strides / sizeof strides[0]; s++)
            compare_workload(p, nu, u, nv, v, &workloads[k], strides[s]);
    }
}

/* Random nets of degree 0..7 (and 64 x 41), polynomial and rational, 2-D and 3-D, with
 * extrapolated, NaN and infinite parameters. */
static void test_random_patches(void)
{
    unsigned long long rng = 3200;
    size_t sizes[][2] = {{1, 1}, {3, 5}, {7, 1}, {4, 255}, {2, 300}, {9, 17}};
    for (int trial = 0; trial < 12; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 8), n = (size_t)(bs_test_rand_u64(&rng) % 8);
        if (trial == 5) {
            m = 64;
            n = 41;
        }
        if (trial == 4 || trial == 7) /* cubic rows, rational and not */
            n = 3;
        size_t dim = trial % 3 == 0 ? 2 : 3;
        tnet t = tnet_random(&rng, m, n, dim, trial % 2, 0.5, 2.0);
        bs_patch *p = tnet_patch(&t);
        size_t nu = sizes[trial % 6][0], nv = sizes[trial % 6][1];
        double *u = malloc(nu * sizeof(double)), *v = malloc(nv * sizeof(double));
        grid_params(&rng, nu, u, nv, v);
        if (trial % 4 == 1 && nv > 3)
            v[2] = NAN;
        if (trial % 4 == 3 && nu > 2)
            u[1] = -INFINITY;
        compare_all(p, nu, u, nv, v);
        free(u);
        free(v);
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* Bicubic polynomial patches of degree (m, 3) with finite parameters take the cubic-row loops;
 * 300 columns cross the 256-column pass boundary. Coordinates of 1e5 make the rounding to float
 * inexact everywhere. */
static void test_cubic_rows(void)
{
    unsigned long long rng = 3201;
    for (size_t m = 1; m <= 4; m++) {
        tnet t = tnet_random(&rng, m, 3, 3, 0, 1.0, 1.0);
        for (size_t k = 0; k < (m + 1) * 4 * 3; k++)
            t.ctrl[k] *= 1e5;
        bs_patch *p = tnet_patch(&t);
        double u[5], v[300];
        grid_params(&rng, 5, u, 300, v);
        compare_all(p, 5, u, 300, v);
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* The teapot: collapsed edges, where the normals are limit normals, and one patch with a NaN
 * parameter. */
static void test_teapot(void)
{
    bs_patch *patches[32];
    size_t np = teapot_patches(BS_DATA_DIR "/teapot.bpt", patches);
    CHECK(np == 32);
    double u[17], v[17];
    for (int k = 0; k <= 16; k++)
        u[k] = v[k] = k / 16.0;
    for (size_t k = 0; k < np; k++) {
        if (k == 31)
            v[5] = NAN;
        compare_all(patches[k], 17, u, 17, v);
        bs_patch_destroy(patches[k]);
    }
}

/* Views the call must refuse, with nothing written anywhere. */
static void test_refused(void)
{
    unsigned long long rng = 3202;
    tnet t = tnet_random(&rng, 3, 3, 3, 0, 1.0, 1.0);
    bs_patch *p = tnet_patch(&t);
    tnet t2 = tnet_random(&rng, 2, 2, 2, 0, 1.0, 1.0);
    bs_patch *p2 = tnet_patch(&t2);
    enum { N = 4, T = N * N };
    double u[N] = {0, 0.25, 0.5, 1}, v[N] = {0, 0.3, 0.6, 0.9};
    bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
    static float buf[4][3][T + 2];
    static unsigned char kind[T];
    bs_fview fv[4][3];
    for (int o = 0; o < 4; o++)
        for (int c = 0; c < 3; c++) {
            fv[o][c].data = &buf[o][c][0];
            fv[o][c].count = T;
            fv[o][c].stride = 0;
        }
    memset(buf, 0x5a, sizeof buf);
    memset(kind, 0x5a, sizeof kind);
    /* one short view among the outputs */
    for (int o = 0; o < 4; o++) {
        fv[o][2].count = T - 1;
        CHECK_STATUS(bs_patch_eval_grid_f32(p, N, &cu, N, &cv, fv[0], fv[1], fv[2], fv[3], kind),
                     BS_ERR_SIZE);
        fv[o][2].count = T;
    }
    /* misaligned data, a stride that is not a multiple of sizeof(float), NULL data */
    fv[1][0].data = (float *)(void *)((char *)&buf[1][0][0] + 2);
    CHECK_STATUS(bs_patch_eval_grid_f32(p, N, &cu, N, &cv, fv[0], fv[1], NULL, NULL, NULL),
                 BS_ERR_INVALID_ARG);
    fv[1][0].data = &buf[1][0][0];
    fv[3][1].stride = 6;
    CHECK_STATUS(bs_patch_eval_grid_f32(p, N, &cu, N, &cv, fv[0], NULL, NULL, fv[3], kind),
                 BS_ERR_INVALID_ARG);
    fv[3][1].stride = 0;
    fv[0][0].data = NULL;
    CHECK_STATUS(bs_patch_eval_grid_f32(p, N, &cu, N, &cv, fv[0], NULL, NULL, NULL, NULL),
                 BS_ERR_INVALID_ARG);
    fv[0][0].data = &buf[0][0][0];
    /* normals of a 2-D patch, before the views; a short parameter view; a NULL patch */
    CHECK_STATUS(bs_patch_eval_grid_f32(p2, N, &cu, N, &cv, fv[0], NULL, NULL, fv[3], NULL),
                 BS_ERR_DIMENSION);
    bs_cview short_v = {v, N - 1, 0};
    CHECK_STATUS(bs_patch_eval_grid_f32(p, N, &cu, N, &short_v, fv[0], NULL, NULL, NULL, NULL),
                 BS_ERR_SIZE);
    CHECK_STATUS(bs_patch_eval_grid_f32(NULL, N, &cu, N, &cv, fv[0], NULL, NULL, NULL, NULL),
                 BS_ERR_INVALID_ARG);
    int untouched = 1;
    const unsigned char *bytes = (const unsigned char *)buf;
    for (size_t k = 0; k < sizeof buf; k++)
        untouched &= bytes[k] == 0x5a;
    for (size_t k = 0; k < T; k++)
        untouched &= kind[k] == 0x5a;
    CHECK(untouched);
    /* n = 0 is a no-op that reads no view */
    CHECK_STATUS(bs_patch_eval_grid_f32(p, 0, &cu, N, &cv, NULL, NULL, NULL, NULL, NULL), BS_OK);
    bs_patch_destroy(p);
    bs_patch_destroy(p2);
    tnet_free(&t);
    tnet_free(&t2);
}

int main(void)
{
    test_random_patches();
    test_cubic_rows();
    test_teapot();
    test_refused();
    return bs_test_exit("test_grid_f32");
}
