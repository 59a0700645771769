/* The per-patch closest-point step bsi_patch_closest_one (lib/query/internal.h), which the
 * surface locator runs over many patches with a shrinking best: a patch farther than the best
 * returns 0 without a box visited and leaves uv and the best alone; run over all the teapot's
 * patches it finds the same distance as the best of bs_patch_closest_point patch by patch; the
 * caller's larger D widens the tolerance; two threads at once get the same bits as one.
 * Built with the library's sources (the step is internal). */
#include "harness.h"
#include "query/closest.h"

#include <math.h>
#include <pthread.h>
#include <string.h>

static double public_distance(const bs_patch *p, const double *q)
{
    double d;
    bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    bs_view dv = {&d, 1, 0};
    CHECK_STATUS(bs_patch_closest_point(p, 1, qv, NULL, &dv, NULL), BS_OK);
    return d;
}

/* Over all patches with a shrinking best, as the locator does; returns the distance. */
static double over_surface(const bs_surface *s, const double *q, uint32_t *patch, double uv[2])
{
    double best = INFINITY;
    for (uint32_t i = 0; i < bs_surface_count(s); i++) {
        int r = bsi_patch_closest_one(bs_surface_get(s, i), q, 0.0, &best, uv);
        CHECK(r == 0 || r == 1);
        if (r == 1)
            *patch = i;
    }
    return sqrt(best);
}

static void teapot(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    unsigned long long rng = 3;
    double worst = 0;
    for (int k = 0; k < 40; k++) {
        double q[3] = {bs_test_rand(&rng, -4, 4), bs_test_rand(&rng, -3, 3), bs_test_rand(&rng, -1, 4)};
        double want = INFINITY, uv[2] = {-1, -1}, D = 0;
        uint32_t patch = UINT32_MAX;
        for (size_t i = 0; i < bs_surface_count(s); i++) {
            want = fmin(want, public_distance(bs_surface_get(s, i), q));
            double lo[3], hi[3];
            bs_patch_bounds(bs_surface_get(s, i), lo, hi);
            D = fmax(D, sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                             (hi[2] - lo[2]) * (hi[2] - lo[2])));
        }
        double got = over_surface(s, q, &patch, uv);
        CHECK(patch < bs_surface_count(s) && uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1);
        double tau = 1e-9 * (D + want);
        worst = fmax(worst, (got - want) / tau);
        CHECKF(got <= want + tau, "over the surface %.17g, patch by patch %.17g", got, want);
        /* the answer is where the patch is: |S(uv) - q| is the distance */
        CHECKF(fabs(public_distance(bs_surface_get(s, patch), q) - got) <= tau,
               "patch %u: its own distance differs", patch);
    }
    printf("teapot over all patches: largest excess %.3g tau\n", worst);
    bs_surface_destroy(s);
}

static void pruning(void)
{
    const double net[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}; /* S(u,v) = (v, u, 0) */
    bs_patch *p;
    CHECK_STATUS(bs_patch_create(1, 1, 3, net, NULL, &p), BS_OK);
    double q[3] = {0.25, 0.5, 3.0}, uv[2] = {7, 7}, best = 4.0;
    size_t boxes = 99;
    /* farther than the best: 0, nothing visited, nothing changed */
    CHECK(bsi_patch_closest_count(p, q, 0.0, &best, uv, &boxes) == 0);
    CHECK(boxes == 0 && best == 4.0 && uv[0] == 7 && uv[1] == 7);
    /* closer: 1, the answer */
    best = 9.5;
    CHECK(bsi_patch_closest_count(p, q, 0.0, &best, uv, &boxes) == 1);
    CHECKF(best == 9.0 && uv[0] == 0.5 && uv[1] == 0.25, "best %.17g at (%.17g, %.17g)", best, uv[0], uv[1]);
    /* equal to the best: not closer */
    uv[0] = uv[1] = 7;
    CHECK(bsi_patch_closest_one(p, q, 0.0, &best, uv) == 0 && best == 9.0 && uv[0] == 7);
    /* no best yet, q on the patch: found at once */
    double on[3] = {0.5, 0.125, 0.0};
    best = INFINITY;
    CHECK(bsi_patch_closest_count(p, on, 0.0, &best, uv, &boxes) == 1 && best <= 1e-30 && boxes <= 1);
    /* the caller's D: a far larger scale allows a larger tolerance, never a worse answer than it */
    double far_q[3] = {0.3, 0.7, 1e-3};
    best = INFINITY;
    CHECK(bsi_patch_closest_one(p, far_q, 1e6, &best, uv) == 1);
    CHECKF(sqrt(best) <= 1e-3 + 1e-9 * (1e6 + 1e-3), "with D = 1e6: %.17g", sqrt(best));
    bs_patch_destroy(p);
}

/* Thread safety: two threads on the same patch and points, the bits of one thread alone. */
typedef struct job {
    const bs_patch *p;
    double q[16][3], uv[16][2], d2[16];
} job;

static void *run_job(void *arg)
{
    job *j = arg;
    for (int k = 0; k < 16; k++) {
        j->d2[k] = INFINITY;
        (void)bsi_patch_closest_one(j->p, j->q[k], 0.0, &j->d2[k], j->uv[k]);
    }
    return NULL;
}

static void threads(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    static job a, b, alone;
    unsigned long long rng = 11;
    a.p = b.p = alone.p = bs_surface_get(s, 5);
    for (int k = 0; k < 16; k++)
        for (int c = 0; c < 3; c++)
            a.q[k][c] = b.q[k][c] = alone.q[k][c] = bs_test_rand(&rng, -3, 3);
    run_job(&alone);
    pthread_t ta, tb;
    CHECK(pthread_create(&ta, NULL, run_job, &a) == 0);
    CHECK(pthread_create(&tb, NULL, run_job, &b) == 0);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    CHECK(memcmp(a.uv, alone.uv, sizeof a.uv) == 0 && memcmp(b.uv, alone.uv, sizeof b.uv) == 0);
    CHECK(memcmp(a.d2, alone.d2, sizeof a.d2) == 0 && memcmp(b.d2, alone.d2, sizeof b.d2) == 0);
    bs_surface_destroy(s);
}

int main(void)
{
    pruning();
    teapot();
    threads();
    return bs_test_exit("test_closest_one");
}
