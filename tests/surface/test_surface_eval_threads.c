/* The multi-threaded surface evaluators: bs_surface_eval_mt() equals bs_surface_eval() and
 * bs_surface_eval_grid() equals bs_patch_eval_grid() patch by patch, bit for bit, on 1, 2, 5 and 0
 * (one per CPU) threads, for grids cut into several pieces per patch or one row per piece; errors
 * come before anything is written. */
#include "harness.h"
#include "shapes.h"

#include <bezsurf.h>

#include <stdlib.h>
#include <string.h>

static const size_t thread_counts[] = {1, 2, 5, 0};
#define NTHREADS (sizeof thread_counts / sizeof thread_counts[0])

/* k packed arrays of n doubles each, as views. */
static double *alloc_views(bs_view *views, size_t k, size_t n)
{
    double *a = malloc(k * n * sizeof(double) + 1);
    for (size_t c = 0; c < k; c++) {
        views[c].data = a + c * n;
        views[c].count = n;
        views[c].stride = (ptrdiff_t)sizeof(double);
    }
    return a;
}

static void scattered(const bs_surface *s)
{
    size_t n = 3 * 4096 + 17, np = bs_surface_count(s);
    unsigned long long seed = 7;
    uint32_t *ids = malloc(n * sizeof(uint32_t));
    double *u = malloc(n * sizeof(double)), *v = malloc(n * sizeof(double));
    for (size_t k = 0; k < n; k++) {
        ids[k] = (uint32_t)((k / 5) % np); /* runs of equal ids, cut by the pieces */
        u[k] = bs_test_rand(&seed, -0.1, 1.1);
        v[k] = bs_test_rand(&seed, 0.0, 1.0);
    }
    bs_cview cu = {u, n, 0}, cv = {v, n, 0};
    bs_view ref[9], out[9];
    double *r = alloc_views(ref, 9, n), *o = alloc_views(out, 9, n);
    CHECK_STATUS(bs_surface_eval(s, n, ids, &cu, &cv, ref, ref + 3, ref + 6), BS_OK);
    for (size_t t = 0; t < NTHREADS; t++) {
        memset(o, 0, 9 * n * sizeof(double));
        CHECK_STATUS(bs_surface_eval_mt(s, n, ids, &cu, &cv, out, out + 3, out + 6, thread_counts[t]), BS_OK);
        CHECKF(memcmp(o, r, 9 * n * sizeof(double)) == 0, "eval_mt on %zu threads differs", thread_counts[t]);
    }
    /* errors as bs_surface_eval's, nothing written */
    memset(o, 0, 9 * n * sizeof(double));
    CHECK_STATUS(bs_surface_eval_mt(NULL, n, ids, &cu, &cv, out, NULL, NULL, 2), BS_ERR_INVALID_ARG);
    ids[n - 1] = (uint32_t)np;
    CHECK_STATUS(bs_surface_eval_mt(s, n, ids, &cu, &cv, out, NULL, NULL, 2), BS_ERR_INVALID_ARG);
    ids[n - 1] = 0;
    out[2].count = n - 1;
    CHECK_STATUS(bs_surface_eval_mt(s, n, ids, &cu, &cv, out, NULL, NULL, 2), BS_ERR_SIZE);
    CHECK_STATUS(bs_surface_eval_mt(s, 0, ids, &cu, &cv, out, NULL, NULL, 2), BS_OK);
    for (size_t k = 0; k < 9 * n; k++)
        CHECK(o[k] == 0.0);
    free(r);
    free(o);
    free(ids);
    free(u);
    free(v);
}

/* An nu x nv grid on every patch against bs_patch_eval_grid, positions, partials, normals, kinds. */
static void grid(const bs_surface *s, size_t nu, size_t nv)
{
    size_t np = bs_surface_count(s), per = nu * nv, n = np * per;
    double *u = malloc(nu * sizeof(double)), *v = malloc(nv * sizeof(double));
    for (size_t a = 0; a < nu; a++)
        u[a] = (double)a / (double)(nu - 1);
    for (size_t b = 0; b < nv; b++)
        v[b] = (double)b / (double)(nv - 1);
    bs_cview cu = {u, nu, 0}, cv = {v, nv, 0};
    bs_view ref[12], out[12], one[12];
    double *r = alloc_views(ref, 12, n), *o = alloc_views(out, 12, n);
    unsigned char *rk = malloc(n), *ok = malloc(n);
    for (size_t p = 0; p < np; p++) {
        for (size_t c = 0; c < 12; c++) {
            one[c] = ref[c];
            one[c].data = ref[c].data + p * per;
            one[c].count = per;
        }
        CHECK_STATUS(bs_patch_eval_grid(bs_surface_get(s, p), nu, &cu, nv, &cv, one, one + 3, one + 6, one + 9,
                                        rk + p * per),
                     BS_OK);
    }
    for (size_t t = 0; t < NTHREADS; t++) {
        memset(o, 0, 12 * n * sizeof(double));
        memset(ok, 9, n);
        CHECK_STATUS(bs_surface_eval_grid(s, nu, &cu, nv, &cv, out, out + 3, out + 6, out + 9, ok, thread_counts[t]),
                     BS_OK);
        CHECKF(memcmp(o, r, 12 * n * sizeof(double)) == 0 && memcmp(ok, rk, n) == 0,
               "eval_grid %zux%zu on %zu threads differs", nu, nv, thread_counts[t]);
    }
    free(r);
    free(o);
    free(rk);
    free(ok);
    free(u);
    free(v);
}

static void grid_errors(const bs_surface *s)
{
    double u[4] = {0, 0.25, 0.5, 1}, buf[3 * 32 * 16];
    memset(buf, 0, sizeof buf);
    bs_cview cu = {u, 4, 0};
    bs_view pos[3];
    for (size_t c = 0; c < 3; c++) {
        pos[c].data = buf + c * 32 * 16;
        pos[c].count = 32 * 16;
        pos[c].stride = 0;
    }
    size_t np = bs_surface_count(s);
    CHECK(np == 32);
    CHECK_STATUS(bs_surface_eval_grid(NULL, 4, &cu, 4, &cu, pos, NULL, NULL, NULL, NULL, 2), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval_grid(s, 4, NULL, 4, &cu, pos, NULL, NULL, NULL, NULL, 2), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_eval_grid(s, 5, &cu, 4, &cu, pos, NULL, NULL, NULL, NULL, 2), BS_ERR_SIZE);
    pos[1].count = 32 * 16 - 1;
    CHECK_STATUS(bs_surface_eval_grid(s, 4, &cu, 4, &cu, pos, NULL, NULL, NULL, NULL, 2), BS_ERR_SIZE);
    pos[1].count = 32 * 16;
    pos[2].data = NULL;
    CHECK_STATUS(bs_surface_eval_grid(s, 4, &cu, 4, &cu, pos, NULL, NULL, NULL, NULL, 2), BS_ERR_INVALID_ARG);
    bs_cview huge = {u, SIZE_MAX / 16, 0};
    CHECK_STATUS(bs_surface_eval_grid(s, SIZE_MAX / 16, &huge, 4, &cu, pos, NULL, NULL, NULL, NULL, 2), BS_ERR_SIZE);
    for (size_t k = 0; k < 3 * 32 * 16; k++)
        CHECK(buf[k] == 0.0);

    /* normals need dim 3: a plane patch of dim 2, and an empty surface */
    bs_surface *flat = shape_flat_surface(), *empty = NULL;
    CHECK_STATUS(bs_surface_create(&empty), BS_OK);
    unsigned char kind[16];
    CHECK_STATUS(bs_surface_eval_grid(flat, 4, &cu, 4, &cu, NULL, NULL, NULL, NULL, kind, 2), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_eval_grid(empty, 4, &cu, 4, &cu, NULL, NULL, NULL, pos, NULL, 2), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_eval_grid(empty, 4, &cu, 4, &cu, NULL, NULL, NULL, NULL, NULL, 0), BS_OK);
    CHECK_STATUS(bs_surface_eval_grid(flat, 0, &cu, 4, &cu, NULL, NULL, NULL, NULL, NULL, 2), BS_OK);
    bs_surface_destroy(flat);
    bs_surface_destroy(empty);
}

int main(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    scattered(s);
    grid(s, 37, 29);     /* 4 pieces of rows per patch */
    grid(s, 3, 5000);    /* one row per piece */
    grid(s, 300, 2);
    grid_errors(s);
    bs_surface_destroy(s);
    return bs_test_exit("test_surface_eval_threads");
}
