/* The locator's rules: argument checks (nothing written on failure), n = 0, an empty surface, a
 * 2-D surface, NaN, infinite and zero rays, strided and batched views against rays one by one,
 * the surface destroyed after the locator is made, and one locator queried from two threads at
 * once with the same results as from one. */
#include "harness.h"

#include <bezsurf.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define N 4096

typedef struct batch {
    const bs_locator *L;
    size_t n;
    double o[3][N], d[3][N];
    double u[N], v[N], t[N], nrm[3][N];
    uint32_t patch[N];
    bs_status st;
} batch;

static bs_status run(batch *b)
{
    bs_cview o[3], d[3];
    bs_view uv[2] = {{b->u, N, 0}, {b->v, N, 0}}, t = {b->t, N, 0}, nv[3];
    for (int c = 0; c < 3; c++) {
        o[c] = (bs_cview){b->o[c], N, 0};
        d[c] = (bs_cview){b->d[c], N, 0};
        nv[c] = (bs_view){b->nrm[c], N, 0};
    }
    return b->st = bs_locator_intersect(b->L, b->n, o, d, NULL, b->patch, uv, &t, nv);
}

static void *thread_main(void *arg)
{
    run(arg);
    return NULL;
}

static unsigned long long rng = 99;

/* Rays from around the teapot towards random points of its box. */
static void random_rays(batch *b, size_t n)
{
    b->n = n;
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 3; c++) {
            b->o[c][k] = bs_test_rand(&rng, -8, 8);
            b->d[c][k] = bs_test_rand(&rng, -2, 2) - b->o[c][k] + (c == 2 ? 1.5 : 0);
        }
}

static int same_bits(const batch *a, const batch *b, size_t first, size_t n)
{
    for (size_t k = first; k < first + n; k++) {
        if (a->patch[k] != b->patch[k] || memcmp(&a->t[k], &b->t[k], sizeof(double)) ||
            memcmp(&a->u[k], &b->u[k], sizeof(double)) || memcmp(&a->v[k], &b->v[k], sizeof(double)))
            return 0;
        for (int c = 0; c < 3; c++)
            if (memcmp(&a->nrm[c][k], &b->nrm[c][k], sizeof(double)))
                return 0;
    }
    return 1;
}

static void arguments(const bs_locator *L)
{
    double o[3] = {5, 0, 1}, d[3] = {-1, 0, 0}, u = 7, v = 7, t = 7, n3[3] = {7, 7, 7};
    uint32_t id = 7;
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
    bs_view uv[2] = {{&u, 1, 0}, {&v, 1, 0}}, tv = {&t, 1, 0};
    bs_view nv[3] = {{&n3[0], 1, 0}, {&n3[1], 1, 0}, {&n3[2], 1, 0}};
    CHECK_STATUS(bs_locator_intersect(NULL, 1, ov, dv, NULL, &id, uv, &tv, nv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_intersect(L, 1, NULL, dv, NULL, &id, uv, &tv, nv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, NULL, NULL, &id, uv, &tv, nv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_intersect(L, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL), BS_OK);
    bs_cview short_v = {&o[0], 0, 0}, odd = {(const double *)(const void *)((const char *)&o[0] + 1), 1, 0};
    bs_cview bad[3] = {ov[0], short_v, ov[2]};
    CHECK_STATUS(bs_locator_intersect(L, 1, bad, dv, NULL, &id, uv, &tv, nv), BS_ERR_SIZE);
    bad[1] = odd;
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, bad, NULL, &id, uv, &tv, nv), BS_ERR_INVALID_ARG);
    bad[1] = (bs_cview){NULL, 1, 0};
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, bad, NULL, &id, uv, &tv, nv), BS_ERR_INVALID_ARG);
    bs_cview range1[2] = {ov[0], short_v};
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, range1, &id, uv, &tv, nv), BS_ERR_SIZE);
    bs_view short_out = {&u, 0, 0}, uv_bad[2] = {{&u, 1, 0}, short_out};
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &id, uv_bad, &tv, nv), BS_ERR_SIZE);
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &id, uv, &short_out, nv), BS_ERR_SIZE);
    bs_view nv_bad[3] = {nv[0], nv[1], {&n3[2], 1, 3}};
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &id, uv, &tv, nv_bad), BS_ERR_INVALID_ARG);
    CHECK(id == 7 && u == 7 && v == 7 && t == 7 && n3[0] == 7 && n3[1] == 7 && n3[2] == 7);
    /* every output optional; a ray at the teapot's side hits */
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &id, NULL, &tv, NULL), BS_OK);
    CHECK(id != UINT32_MAX && t > 0 && t < 10);

    bs_locator *none = (bs_locator *)&id;
    CHECK_STATUS(bs_locator_create(NULL, &none), BS_ERR_INVALID_ARG);
    CHECK(none == NULL);
    CHECK(bs_locator_dim(NULL) == 0);
    bs_locator_destroy(NULL);
}

/* Rays with a NaN or infinite coordinate, range or a zero direction, mixed with good rays. */
static void invalid_rays(const bs_locator *L)
{
    static batch b, one;
    b.L = one.L = L;
    random_rays(&b, 64);
    for (size_t k = 0; k < 64; k += 8) {
        switch (k / 8) {
        case 0: b.o[0][k] = NAN; break;
        case 1: b.o[2][k] = INFINITY; break;
        case 2: b.d[1][k] = NAN; break;
        case 3: b.d[0][k] = -INFINITY; break;
        case 4: b.d[0][k] = b.d[1][k] = b.d[2][k] = 0; break;
        case 5: b.d[0][k] = b.d[1][k] = b.d[2][k] = -0.0; break;
        default: break;
        }
    }
    CHECK_STATUS(run(&b), BS_OK);
    for (size_t k = 0; k < 64; k++) {
        int bad = k % 8 == 0 && k < 48;
        if (bad)
            CHECK(b.patch[k] == UINT32_MAX && isnan(b.t[k]) && isnan(b.u[k]) && isnan(b.v[k]) &&
                  isnan(b.nrm[0][k]) && isnan(b.nrm[1][k]) && isnan(b.nrm[2][k]));
        /* each ray alone gives the same bits as in the batch */
        one.n = 1;
        for (int c = 0; c < 3; c++) {
            one.o[c][0] = b.o[c][k];
            one.d[c][0] = b.d[c][k];
        }
        CHECK_STATUS(run(&one), BS_OK);
        CHECKF(one.patch[0] == b.patch[k] && !memcmp(&one.t[0], &b.t[k], sizeof(double)) &&
                   !memcmp(&one.u[0], &b.u[k], sizeof(double)),
               "ray %zu alone differs", k);
    }
    /* ranges with a NaN or an infinity: (NaN, 1e30), (0, NaN), (-Inf, 1e30), (+Inf, +Inf),
     * (0, -Inf) make the ray invalid; (0, +Inf) and (1, +Inf) have no upper limit (1.2) */
    double ox[3][7], dx[3][7], t[7], tn[7];
    double g0[7] = {NAN, 0, -INFINITY, INFINITY, 0, 0, 1}, g1[7] = {1e30, NAN, 1e30, INFINITY, -INFINITY, INFINITY, INFINITY};
    uint32_t id[7], idn[7];
    bs_cview ov[3], dv[3], gv[2] = {{g0, 7, 0}, {g1, 7, 0}};
    for (int c = 0; c < 3; c++) {
        for (int k = 0; k < 7; k++) {
            ox[c][k] = c == 0 ? 5 : c == 2 ? 1 : 0;
            dx[c][k] = c == 0 ? -1 : 0;
        }
        ov[c] = (bs_cview){ox[c], 7, 0};
        dv[c] = (bs_cview){dx[c], 7, 0};
    }
    bs_view tv = {t, 7, 0}, tnv = {tn, 7, 0};
    CHECK_STATUS(bs_locator_intersect(L, 7, ov, dv, gv, id, NULL, &tv, NULL), BS_OK);
    CHECK_STATUS(bs_locator_intersect(L, 7, ov, dv, NULL, idn, NULL, &tnv, NULL), BS_OK);
    for (int k = 0; k < 5; k++)
        CHECKF(id[k] == UINT32_MAX && isnan(t[k]), "range (%g, %g): patch %u, t %g", g0[k], g1[k], id[k], t[k]);
    CHECKF(idn[5] != UINT32_MAX && id[5] == idn[5] && t[5] == tn[5] && id[6] == idn[6] && t[6] == tn[6],
           "range (0, +Inf): patch %u, t %g; (1, +Inf): patch %u, t %g; no range: patch %u, t %g", id[5], t[5],
           id[6], t[6], idn[5], tn[5]);
    CHECK_STATUS(bs_locator_intersect_mt(L, 7, ov, dv, gv, id, NULL, &tv, NULL, 2), BS_OK);
    CHECK(id[5] == idn[5] && t[5] == tn[5] && id[4] == UINT32_MAX && isnan(t[4]));
}

/* Rays from very far away, or with huge or tiny directions, end (the rounding of P - o then
 * exceeds the surface: pieces are taken whole) and answer a hit on the surface's side of the
 * origin or a miss. A hit whose t would be beyond DBL_MAX (directions of subnormal length, rays 4
 * and 5) is a miss: 1.1 reported it as a hit with t = +Inf, the miss value. */
static void extreme_rays(const bs_locator *L)
{
    static batch b;
    b.L = L;
    const double o[7][3] = {{1e15, 0, 1}, {1e300, 1e300, 1e300}, {0, 0, 1e200}, {5, 0, 1}, {5, 0, 1}, {-1e-300, 0, 1}, {5, 0, 1}};
    const double d[7][3] = {{-1, 0, 0}, {-1, -1, -1}, {0, 0, -1e-300}, {-1e300, 0, 0}, {-4.9e-324, 0, 0}, {1e-310, 1e-310, 0}, {-1e-300, 0, 0}};
    b.n = 7;
    for (int k = 0; k < 7; k++)
        for (int c = 0; c < 3; c++) {
            b.o[c][k] = o[k][c];
            b.d[c][k] = d[k][c];
        }
    CHECK_STATUS(run(&b), BS_OK);
    for (size_t k = 0; k < 7; k++)
        CHECKF((b.patch[k] == UINT32_MAX && b.t[k] == INFINITY) ||
                   (b.patch[k] < 32 && b.t[k] > 0 && isfinite(b.t[k]) && isfinite(b.u[k])),
               "extreme ray %zu: patch %u t %g", k, b.patch[k], b.t[k]);
    CHECK(b.patch[3] != UINT32_MAX && b.patch[6] != UINT32_MAX); /* the teapot is there */
    CHECK(b.patch[4] == UINT32_MAX && b.patch[5] == UINT32_MAX); /* but beyond t = DBL_MAX */
}

/* Strided (negative too) views give the bits of packed ones. */
static void strides(const bs_locator *L)
{
    static batch b;
    b.L = L;
    random_rays(&b, 100);
    CHECK_STATUS(run(&b), BS_OK);
    double o[3][200], d[3][200], t[200], u[100];
    uint32_t id[100];
    bs_cview ov[3], dv[3];
    for (int c = 0; c < 3; c++) {
        for (size_t k = 0; k < 100; k++) {
            o[c][2 * k] = b.o[c][k];
            d[c][199 - 2 * k] = b.d[c][k];
        }
        ov[c] = (bs_cview){o[c], 100, 2 * sizeof(double)};
        dv[c] = (bs_cview){&d[c][199], 100, -2 * (ptrdiff_t)sizeof(double)};
    }
    bs_view tv = {&t[0], 100, 2 * sizeof(double)}, uv[2] = {{u, 100, 0}, {&t[1], 100, 2 * sizeof(double)}};
    CHECK_STATUS(bs_locator_intersect(L, 100, ov, dv, NULL, id, uv, &tv, NULL), BS_OK);
    int same = 1;
    for (size_t k = 0; k < 100; k++)
        same &= id[k] == b.patch[k] && !memcmp(&t[2 * k], &b.t[k], 8) && !memcmp(&u[k], &b.u[k], 8) &&
                !memcmp(&t[2 * k + 1], &b.v[k], 8);
    CHECK(same);
}

static void empty_and_flat(void)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    CHECK(L != NULL && bs_locator_dim(L) == 0);
    static batch b;
    b.L = L;
    random_rays(&b, 10);
    b.d[0][9] = NAN;
    CHECK_STATUS(run(&b), BS_OK);
    for (size_t k = 0; k < 10; k++)
        CHECK(b.patch[k] == UINT32_MAX && (k == 9 ? isnan(b.t[k]) : b.t[k] == INFINITY) && isnan(b.u[k]) &&
              isnan(b.nrm[2][k]));
    bs_locator_destroy(L);
    bs_surface_destroy(s);

    /* a 2-D surface: the locator exists (closest points), rays are BS_ERR_DIMENSION */
    const double ctrl[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 2, ctrl, NULL, &p), BS_OK);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    CHECK(bs_locator_dim(L) == 2);
    b.L = L;
    CHECK_STATUS(run(&b), BS_ERR_DIMENSION);
    b.n = 0;
    CHECK_STATUS(run(&b), BS_ERR_DIMENSION);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
}

/* Two threads on one locator (made from a surface destroyed since) give the bits of one thread. */
static void threads(void)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    static batch ref, a, b;
    ref.L = L;
    random_rays(&ref, N);
    CHECK_STATUS(run(&ref), BS_OK);
    bs_surface_destroy(s); /* the locator keeps its own copy */
    a = ref;
    b = ref;
    memset(a.t, 0, sizeof a.t);
    memset(b.t, 0, sizeof b.t);
    pthread_t th[2];
    CHECK(pthread_create(&th[0], NULL, thread_main, &a) == 0);
    CHECK(pthread_create(&th[1], NULL, thread_main, &b) == 0);
    CHECK(pthread_join(th[0], NULL) == 0 && pthread_join(th[1], NULL) == 0);
    CHECK(a.st == BS_OK && b.st == BS_OK);
    CHECK(same_bits(&ref, &a, 0, N) && same_bits(&ref, &b, 0, N));
    size_t hits = 0;
    for (size_t k = 0; k < N; k++)
        hits += ref.patch[k] != UINT32_MAX;
    printf("threads: %d rays in each of 2 threads (%zu hits), the same bits as one thread\n", N, hits);
    CHECK(hits > N / 4);
    arguments(L);
    invalid_rays(L);
    strides(L);
    extreme_rays(L);
    bs_locator_destroy(L);
}

int main(void)
{
    empty_and_flat();
    threads();
    return bs_test_exit("test_locator_api");
}
