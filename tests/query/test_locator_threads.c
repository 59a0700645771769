/* The locator's multi-threaded batch queries: bs_locator_closest_point_mt() and
 * bs_locator_intersect_mt() equal the single-threaded calls bit for bit on 1, 2, 5 and 0 (one per
 * CPU) threads, for batches cut into several pieces and a last short one, with strided and
 * reversed views and ranges; their argument errors come before anything is written. */
#include "harness.h"
#include "bpt_reader.h"

#include <bezsurf.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const size_t thread_counts[] = {1, 2, 5, 0};
#define NTHREADS (sizeof thread_counts / sizeof thread_counts[0])

/* Outputs of one call: patch ids, then 6 doubles per query (u, v, dist or t, and 3 coordinates of
 * the point or normal), interleaved so that the views have a stride. */
typedef struct answers {
    uint32_t *id;
    double *d;
} answers;

static void answers_views(const answers *a, size_t n, bs_view uv[2], bs_view *one, bs_view xyz[3])
{
    ptrdiff_t s = 6 * (ptrdiff_t)sizeof(double);
    uv[0] = (bs_view){a->d, n, s};
    uv[1] = (bs_view){a->d + 1, n, s};
    *one = (bs_view){a->d + 2, n, s};
    for (int c = 0; c < 3; c++) /* the last query first: a negative stride */
        xyz[c] = (bs_view){a->d + 6 * (n - 1) + 3 + c, n, -s};
}

static void answers_clear(answers *a, size_t n)
{
    memset(a->id, 0, n * sizeof(uint32_t));
    memset(a->d, 0, 6 * n * sizeof(double));
}

static int all_zero(const answers *a, size_t n)
{
    int zero = 1;
    for (size_t k = 0; k < n; k++)
        zero &= a->id[k] == 0;
    for (size_t k = 0; k < 6 * n; k++)
        zero &= a->d[k] == 0.0;
    return zero;
}

static void answers_free(answers *a)
{
    free(a->id);
    free(a->d);
}

static answers answers_new(size_t n)
{
    answers a = {malloc(n * sizeof(uint32_t)), malloc(6 * n * sizeof(double))};
    answers_clear(&a, n);
    return a;
}

static int same(const answers *a, const answers *b, size_t n)
{
    return memcmp(a->id, b->id, n * sizeof(uint32_t)) == 0 && memcmp(a->d, b->d, 6 * n * sizeof(double)) == 0;
}

static void closest(const bs_locator *L)
{
    size_t n = 5 * 64 + 9; /* five whole pieces and a short one */
    unsigned long long seed = 11;
    double *q = malloc(3 * n * sizeof(double));
    for (size_t k = 0; k < 3 * n; k++)
        q[k] = bs_test_rand(&seed, -4.0, 4.0);
    q[7] = NAN; /* a NaN query among them */
    bs_cview qv[3];
    for (int c = 0; c < 3; c++)
        qv[c] = (bs_cview){q + c, n, 3 * (ptrdiff_t)sizeof(double)};
    answers ref = answers_new(n), out = answers_new(n);
    bs_view uv[2], dist, pos[3];
    answers_views(&ref, n, uv, &dist, pos);
    CHECK_STATUS(bs_locator_closest_point(L, n, qv, ref.id, uv, &dist, pos), BS_OK);
    answers_views(&out, n, uv, &dist, pos);
    for (size_t t = 0; t < NTHREADS; t++) {
        memset(out.d, 0, 6 * n * sizeof(double));
        CHECK_STATUS(bs_locator_closest_point_mt(L, n, qv, out.id, uv, &dist, pos, thread_counts[t]), BS_OK);
        CHECKF(same(&out, &ref, n), "closest points on %zu threads differ", thread_counts[t]);
    }
    /* errors: nothing written */
    answers_clear(&out, n);
    CHECK_STATUS(bs_locator_closest_point_mt(NULL, n, qv, out.id, uv, &dist, pos, 2), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_closest_point_mt(L, n, NULL, out.id, uv, &dist, pos, 2), BS_ERR_INVALID_ARG);
    pos[2].count = n - 1;
    CHECK_STATUS(bs_locator_closest_point_mt(L, n, qv, out.id, uv, &dist, pos, 2), BS_ERR_SIZE);
    CHECK_STATUS(bs_locator_closest_point_mt(L, 0, NULL, NULL, NULL, NULL, NULL, 2), BS_OK);
    CHECK(all_zero(&out, n));
    answers_free(&ref);
    answers_free(&out);
    free(q);
}

static void rays(const bs_locator *L)
{
    size_t n = 3 * 512 + 100;
    unsigned long long seed = 12;
    double *o = malloc(3 * n * sizeof(double)), *d = malloc(3 * n * sizeof(double));
    double *range = malloc(2 * n * sizeof(double));
    for (size_t k = 0; k < n; k++) {
        /* from a sphere of radius 8 around the teapot towards points of its box (t = 1 there) */
        double a = bs_test_rand(&seed, 0.0, 6.283185307179586), z = bs_test_rand(&seed, -1.0, 1.0);
        double r = sqrt(1.0 - z * z);
        double to[3] = {bs_test_rand(&seed, -3.0, 3.4), bs_test_rand(&seed, -2.0, 2.0), bs_test_rand(&seed, 0.0, 3.1)};
        o[3 * k] = 8.0 * r * cos(a);
        o[3 * k + 1] = 8.0 * r * sin(a);
        o[3 * k + 2] = 1.5 + 8.0 * z;
        for (int c = 0; c < 3; c++)
            d[3 * k + (size_t)c] = to[c] - o[3 * k + (size_t)c];
        range[2 * k] = 0.0;
        range[2 * k + 1] = k % 3 == 0 ? 0.9 : 1e30; /* some rays end near the surface */
    }
    bs_cview ov[3], dv[3], rv[2];
    for (int c = 0; c < 3; c++) {
        ov[c] = (bs_cview){o + c, n, 3 * (ptrdiff_t)sizeof(double)};
        dv[c] = (bs_cview){d + c, n, 3 * (ptrdiff_t)sizeof(double)};
    }
    rv[0] = (bs_cview){range, n, 2 * (ptrdiff_t)sizeof(double)};
    rv[1] = (bs_cview){range + 1, n, 2 * (ptrdiff_t)sizeof(double)};
    answers ref = answers_new(n), out = answers_new(n);
    bs_view uv[2], t, nrm[3];
    answers_views(&ref, n, uv, &t, nrm);
    CHECK_STATUS(bs_locator_intersect(L, n, ov, dv, rv, ref.id, uv, &t, nrm), BS_OK);
    size_t hits = 0;
    for (size_t k = 0; k < n; k++)
        hits += ref.id[k] != UINT32_MAX;
    CHECKF(hits > n / 10 && hits < n, "%zu hits of %zu rays: the test aims badly", hits, n);
    answers_views(&out, n, uv, &t, nrm);
    for (size_t k = 0; k < NTHREADS; k++) {
        memset(out.d, 0, 6 * n * sizeof(double));
        CHECK_STATUS(bs_locator_intersect_mt(L, n, ov, dv, rv, out.id, uv, &t, nrm, thread_counts[k]), BS_OK);
        CHECKF(same(&out, &ref, n), "rays on %zu threads differ", thread_counts[k]);
    }
    /* errors: nothing written */
    answers_clear(&out, n);
    CHECK_STATUS(bs_locator_intersect_mt(NULL, n, ov, dv, rv, out.id, uv, &t, nrm, 2), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_intersect_mt(L, n, ov, NULL, rv, out.id, uv, &t, nrm, 2), BS_ERR_INVALID_ARG);
    rv[1].count = n - 1;
    CHECK_STATUS(bs_locator_intersect_mt(L, n, ov, dv, rv, out.id, uv, &t, nrm, 2), BS_ERR_SIZE);
    CHECK_STATUS(bs_locator_intersect_mt(L, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 2), BS_OK);
    CHECK(all_zero(&out, n));
    answers_free(&ref);
    answers_free(&out);
    free(o);
    free(d);
    free(range);
}

int main(void)
{
    bs_surface *s = test_load_bpt("teapot.bpt");
    bs_locator *L = NULL;
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    closest(L);
    rays(L);
    bs_locator_destroy(L);
    bs_surface_destroy(s);

    /* a 2-D surface: rays are BS_ERR_DIMENSION on any thread count, closest points work */
    double net[8] = {0, 0, 0, 1, 1, 0, 1, 1}, q[2] = {0.25, 2.0}, dist = 0.0;
    bs_patch *p = NULL;
    bs_surface *flat = NULL;
    bs_surface_create(&flat);
    bs_patch_create(1, 1, 2, net, NULL, &p);
    bs_surface_add(flat, p, NULL);
    bs_patch_destroy(p);
    CHECK_STATUS(bs_locator_create(flat, &L), BS_OK);
    bs_cview qv[2] = {{&q[0], 1, 0}, {&q[1], 1, 0}};
    bs_view dv = {&dist, 1, 0};
    CHECK_STATUS(bs_locator_closest_point_mt(L, 1, qv, NULL, NULL, &dv, NULL, 2), BS_OK);
    CHECK(fabs(dist - 1.0) <= 1e-12);
    CHECK_STATUS(bs_locator_intersect_mt(L, 1, qv, qv, NULL, NULL, NULL, NULL, NULL, 2), BS_ERR_DIMENSION);
    bs_locator_destroy(L);
    bs_surface_destroy(flat);
    return bs_test_exit("test_locator_threads");
}
