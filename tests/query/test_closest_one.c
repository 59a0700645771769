/* The per-patch closest-point step bsi_patch_closest_one (lib/query/internal.h), which the
 * surface locator runs over many patches with a shrinking best: a patch farther than the best
 * returns 0 without a box visited and leaves uv and the best alone; run over all the teapot's
 * patches it finds the same distance as the best of bs_patch_closest_point patch by patch; the
 * caller's larger D widens the tolerance; the rational teapot's answers match the general code's
 * and its minima on edges and corners are closed without splitting; two threads at once get the
 * same bits as one.
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

/* The teapot's patch i with weight 1 + 0.5 (k % 3) on control point k, in dim 3 or, with a zero
 * fourth coordinate, in dim 4 (the same surface through the general code). */
static bs_patch *rational_teapot(const bs_surface *s, size_t i, size_t dim)
{
    double ctrl[48], ctrl4[64], w[16];
    CHECK_STATUS(bs_patch_get_ctrl(bs_surface_get(s, i), ctrl, 48, NULL, 0), BS_OK);
    for (size_t k = 0; k < 16; k++) {
        w[k] = 1.0 + 0.5 * (double)(k % 3);
        for (size_t c = 0; c < 4; c++)
            ctrl4[4 * k + c] = c < 3 ? ctrl[3 * k + c] : 0.0;
    }
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(3, 3, dim, dim == 3 ? ctrl : ctrl4, w, &p), BS_OK);
    return p;
}

/* The rational teapot: the bicubic rational kernels give the general code's distances (the same
 * patches in dim 4) within tau, and minima on edges and corners are closed by the separable bound
 * on G = N - c W: 13.3 boxes a query on these points without it, under 9 with it. */
static void rational(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    unsigned long long rng = 11;
    size_t boxes = 0, queries = 0;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        bs_patch *p = rational_teapot(s, i, 3), *p4 = rational_teapot(s, i, 4);
        double lo[3], hi[3];
        bs_patch_bounds(p, lo, hi);
        double D = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                        (hi[2] - lo[2]) * (hi[2] - lo[2]));
        for (int k = 0; k < 20; k++, queries++) {
            double q[4] = {bs_test_rand(&rng, -4, 4), bs_test_rand(&rng, -3, 3), bs_test_rand(&rng, -1, 4), 0};
            double b3 = INFINITY, b4 = INFINITY, uv[2];
            size_t nb = 0;
            CHECK(bsi_patch_closest_count(p, q, 0.0, &b3, uv, &nb) == 1);
            CHECK(bsi_patch_closest_count(p4, q, 0.0, &b4, uv, NULL) == 1);
            boxes += nb;
            double tau = 1e-9 * (D + sqrt(b3));
            CHECKF(fabs(sqrt(b3) - sqrt(b4)) <= tau, "patch %zu: %.17g in 3-D, %.17g in 4-D", i,
                   sqrt(b3), sqrt(b4));
        }
        bs_patch_destroy(p);
        bs_patch_destroy(p4);
    }
    printf("rational teapot: %.2f boxes per query\n", (double)boxes / (double)queries);
    CHECKF(boxes < 9 * queries, "%zu boxes for %zu queries", boxes, queries);
    bs_surface_destroy(s);
}

/* Curves (degree 0 in one direction): an arc of the unit circle from angle -0.5 to 0.5 (its
 * cubic approximation) seen from far on the other side, where f is concave along it, so no square
 * around the nearer end is shown convex and none is bounded without it (kept open, the boxes
 * settle it). The answer is no farther than the best of 1,000 points of the arc. */
static void curves(void)
{
    double h = 4.0 / 3.0 * tan(0.25), c = cos(0.5), s = sin(0.5);
    double arc[12] = {c, -s, 0, c + h * s, -s + h * c, 0, c + h * s, s - h * c, 0, c, s, 0};
    double q[3] = {-10.0, 0.5, 0.0};
    for (int k = 0; k < 2; k++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(k ? 3 : 0, k ? 0 : 3, 3, arc, NULL, &p), BS_OK);
        double best = INFINITY, uv[2], sampled = INFINITY;
        CHECK(bsi_patch_closest_one(p, q, 0.0, &best, uv) == 1);
        for (int i = 0; i <= 1000; i++) {
            double t = i / 1000.0, pt[3];
            bs_cview ct = {&t, 1, 0}, c0 = {&(double){0.0}, 1, 0};
            bs_view o[3] = {{&pt[0], 1, 0}, {&pt[1], 1, 0}, {&pt[2], 1, 0}};
            CHECK_STATUS(bs_patch_eval(p, 1, k ? &ct : &c0, k ? &c0 : &ct, o, NULL, NULL), BS_OK);
            sampled = fmin(sampled, sqrt((pt[0] - q[0]) * (pt[0] - q[0]) + (pt[1] - q[1]) * (pt[1] - q[1])));
        }
        CHECKF(sqrt(best) <= sampled + 1e-9 * (2.0 + sampled), "curve %d: %.17g, sampled %.17g", k,
               sqrt(best), sampled);
        bs_patch_destroy(p);
    }
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
    rational();
    curves();
    threads();
    return bs_test_exit("test_closest_one");
}
