/*
 * Closest-point benchmark, built with the library's sources (for the count of boxes, an internal
 * figure).
 *   bench_closest [points]            the 32 teapot patches, each against `points` random query
 *                                     points around the teapot: queries per second of
 *                                     bs_patch_closest_point and, in the same run, of a naive
 *                                     dense grid (16 x 16) plus Newton, with how often the naive
 *                                     answer is not the global one (farther by more than tau).
 *   bench_closest --degrees [points]  random wavy patches of degree 3, 6, 10, 16: boxes visited
 *                                     and time per query, for queries near, on and far.
 *   bench_closest --once poly|rational [points]
 *                                     for callgrind: the teapot (poly) or the rational teapot
 *                                     (its nets with weight 1 + 0.5 (k % 3) on control point k,
 *                                     bench_curvature's teapot-rational), each patch against the
 *                                     same `points` random query points as above in one call of
 *                                     bs_patch_closest_point; then, outside that function, the
 *                                     boxes whose second-order bound was computed, per query.
 *   valgrind --tool=callgrind --toggle-collect=bs_patch_closest_point \
 *            build/bench/bench_closest --once rational 1000
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include "query/closest.h"
#include "rational_teapot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts); /* CPU time: steadier on a loaded machine */
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static unsigned long long rng = 12345;
static double rnd(double lo, double hi)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(rng >> 11) * 0x1.0p-53;
}

/* The naive baseline: the best of a 16 x 16 grid, then Newton from it (Gauss-Newton steps on
 * the derivatives of bs_patch_eval, clamped to the domain, 20 at most), the best point seen. */
static double naive(const bs_patch *p, const double *q, double uv[2])
{
    enum { N = 16 };
    static double grid[N];
    double pos[3][N * N];
    for (int k = 0; k < N; k++)
        grid[k] = k / (N - 1.0);
    bs_cview g = {grid, N, 0};
    bs_view pv[3] = {{pos[0], N * N, 0}, {pos[1], N * N, 0}, {pos[2], N * N, 0}};
    bs_patch_eval_grid(p, N, &g, N, &g, pv, NULL, NULL, NULL, NULL);
    double best = INFINITY;
    for (int k = 0; k < N * N; k++) {
        double d2 = 0;
        for (int c = 0; c < 3; c++)
            d2 += (pos[c][k] - q[c]) * (pos[c][k] - q[c]);
        if (d2 < best) {
            best = d2;
            uv[0] = grid[k / N];
            uv[1] = grid[k % N];
        }
    }
    double at[2] = {uv[0], uv[1]};
    for (int it = 0; it < 20; it++) {
        double s[3], su[3], sv[3];
        bs_cview cu = {&uv[0], 1, 0}, cv = {&uv[1], 1, 0};
        bs_view a[3] = {{&s[0], 1, 0}, {&s[1], 1, 0}, {&s[2], 1, 0}};
        bs_view b[3] = {{&su[0], 1, 0}, {&su[1], 1, 0}, {&su[2], 1, 0}};
        bs_view c3[3] = {{&sv[0], 1, 0}, {&sv[1], 1, 0}, {&sv[2], 1, 0}};
        bs_patch_eval(p, 1, &cu, &cv, a, b, c3);
        double r[3], a11 = 0, a12 = 0, a22 = 0, g1 = 0, g2 = 0, d2 = 0;
        for (int c = 0; c < 3; c++) {
            r[c] = s[c] - q[c];
            d2 += r[c] * r[c];
            a11 += su[c] * su[c];
            a12 += su[c] * sv[c];
            a22 += sv[c] * sv[c];
            g1 += su[c] * r[c];
            g2 += sv[c] * r[c];
        }
        if (d2 < best) {
            best = d2;
            at[0] = uv[0];
            at[1] = uv[1];
        }
        double det = a11 * a22 - a12 * a12;
        if (!(det > 1e-30))
            break;
        double du = -(a22 * g1 - a12 * g2) / det, dv = -(a11 * g2 - a12 * g1) / det;
        uv[0] = fmin(1, fmax(0, uv[0] + du));
        uv[1] = fmin(1, fmax(0, uv[1] + dv));
        if (fabs(du) + fabs(dv) < 1e-15)
            break;
    }
    uv[0] = at[0];
    uv[1] = at[1];
    return sqrt(best);
}

/* npts random points in the teapot's bounding box grown by 0.2 of its size each way (NULL when
 * out of memory). */
static double *query_points(const bs_surface *s, size_t npts)
{
    size_t np = bs_surface_count(s);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < np; i++) {
        double b[6];
        bs_patch_bounds(bs_surface_get(s, i), b, b + 3);
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], b[c]);
            hi[c] = fmax(hi[c], b[3 + c]);
        }
    }
    double *q = malloc(3 * npts * sizeof(double));
    if (q == NULL)
        return NULL;
    for (size_t k = 0; k < npts; k++)
        for (int c = 0; c < 3; c++) {
            double pad = 0.2 * (hi[c] - lo[c]);
            q[3 * k + (size_t)c] = rnd(lo[c] - pad, hi[c] + pad);
        }
    return q;
}

static int teapot(size_t npts)
{
    bs_surface *s;
    if (bs_surface_create_builtin("teapot", &s) != BS_OK)
        return 1;
    size_t np = bs_surface_count(s);
    double *q = query_points(s, npts), *ours = malloc(np * npts * sizeof(double));
    if (q == NULL || ours == NULL)
        return 1;
    double t0 = now();
    for (size_t i = 0; i < np; i++) {
        const bs_patch *p = bs_surface_get(s, i);
        bs_cview qv[3] = {{q, npts, 24}, {q + 1, npts, 24}, {q + 2, npts, 24}};
        bs_view d = {ours + i * npts, npts, 0};
        if (bs_patch_closest_point(p, npts, qv, NULL, &d, NULL) != BS_OK)
            return 1;
    }
    double t1 = now();
    size_t misses = 0, wrong = 0;
    double worst = 0;
    for (size_t i = 0; i < np; i++) {
        const bs_patch *p = bs_surface_get(s, i);
        double b[6];
        bs_patch_bounds(p, b, b + 3);
        double D = sqrt((b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) +
                        (b[5] - b[2]) * (b[5] - b[2]));
        for (size_t k = 0; k < npts; k++) {
            double uv[2], dn = naive(p, q + 3 * k, uv), d = ours[i * npts + k];
            double tau = 1e-9 * (D + d);
            misses += dn > d + tau;
            wrong += dn > d + 1e-4 * D;
            worst = fmax(worst, (dn - d) / D);
        }
    }
    double t2 = now(), total = (double)(np * npts);
    printf("teapot: %zu patches x %zu random points around it\n", np, npts);
    printf("  bs_patch_closest_point     %9.0f queries/s\n", total / (t1 - t0));
    printf("  grid 16x16 + Newton        %9.0f queries/s\n", total / (t2 - t1));
    printf("    of %.0f answers, %zu farther than tau, %zu farther by 1e-4 D, "
           "worst by %.3g D\n", total, misses, wrong, worst);
    free(q);
    free(ours);
    bs_surface_destroy(s);
    return 0;
}

static int degrees(size_t npts)
{
    static const size_t degs[] = {3, 6, 10, 16};
    static const char *kinds[3] = {"near (1e-3 D)", "on", "far (2 D)"};
    printf("degree  queries      boxes mean / max      time per query\n");
    for (size_t t = 0; t < sizeof degs / sizeof degs[0]; t++) {
        size_t m = degs[t], pts = (m + 1) * (m + 1);
        double ctrl[17 * 17 * 3];
        for (size_t k = 0; k < pts; k++)
            for (int c = 0; c < 3; c++)
                ctrl[3 * k + (size_t)c] = (c == 0 ? (double)(k / (m + 1)) / (double)m
                                  : c == 1 ? (double)(k % (m + 1)) / (double)m : 0.0) +
                                  rnd(-0.3, 0.3);
        bs_patch *p;
        if (bs_patch_create(m, m, 3, ctrl, NULL, &p) != BS_OK)
            return 1;
        for (int kind = 0; kind < 3; kind++) {
            double sum = 0, most = 0, t0 = now();
            for (size_t k = 0; k < npts; k++) {
                double uv[2] = {rnd(0, 1), rnd(0, 1)}, s[3], q[3], best = INFINITY;
                bs_cview cu = {&uv[0], 1, 0}, cv = {&uv[1], 1, 0};
                bs_view sv[3] = {{&s[0], 1, 0}, {&s[1], 1, 0}, {&s[2], 1, 0}};
                bs_patch_eval(p, 1, &cu, &cv, sv, NULL, NULL);
                double off = kind == 0 ? 1e-3 : kind == 1 ? 0.0 : 2.0;
                for (int c = 0; c < 3; c++)
                    q[c] = s[c] + off * rnd(-1, 1);
                size_t boxes;
                if (bsi_patch_closest_count(p, q, 0.0, &best, uv, &boxes) < 0)
                    return 1;
                sum += (double)boxes;
                most = fmax(most, (double)boxes);
            }
            double dt = (now() - t0) / (double)npts;
            printf("%4zu    %-13s %8.1f / %-8.0f %10.1f us\n", m, kinds[kind], sum / (double)npts,
                   most, 1e6 * dt);
        }
        bs_patch_destroy(p);
    }
    return 0;
}

/* The --once run: every patch (rational copies with rational) against the same npts points in
 * one call each, then the boxes per query and the mean distance (a check that both runs answer
 * alike). */
static int once(size_t npts, int rational)
{
    bs_surface *s;
    if (bs_surface_create_builtin("teapot", &s) != BS_OK)
        return 1;
    size_t np = bs_surface_count(s);
    double *q = query_points(s, npts), *d = malloc(npts * sizeof(double));
    if (q == NULL || d == NULL)
        return 1;
    double boxes = 0.0, sum = 0.0;
    for (size_t i = 0; i < np; i++) {
        const bs_patch *p0 = bs_surface_get(s, i);
        bs_patch *r = rational ? rational_copy(p0) : NULL;
        const bs_patch *p = rational ? r : p0;
        bs_cview qv[3] = {{q, npts, 24}, {q + 1, npts, 24}, {q + 2, npts, 24}};
        bs_view dv = {d, npts, 0};
        if (p == NULL || bs_patch_closest_point(p, npts, qv, NULL, &dv, NULL) != BS_OK)
            return 1;
        for (size_t k = 0; k < npts; k++) {
            double best = INFINITY, uv[2];
            size_t b = 0;
            if (bsi_patch_closest_count(p, q + 3 * k, 0.0, &best, uv, &b) < 0)
                return 1;
            boxes += (double)b;
            sum += d[k];
        }
        bs_patch_destroy(r);
    }
    double total = (double)(np * npts);
    printf("%s teapot: %zu patches x %zu points: %.2f boxes per query, mean distance %.17g\n",
           rational ? "rational" : "polynomial", np, npts, boxes / total, sum / total);
    free(q);
    free(d);
    bs_surface_destroy(s);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 2 && strcmp(argv[1], "--once") == 0) {
        size_t n = argc > 3 ? (size_t)atol(argv[3]) : 1000;
        return n == 0 ? 1 : once(n, strcmp(argv[2], "rational") == 0);
    }
    int deg = argc > 1 && strcmp(argv[1], "--degrees") == 0;
    const char *count = argc > (deg ? 2 : 1) ? argv[deg ? 2 : 1] : NULL;
    size_t npts = count != NULL ? (size_t)atol(count) : (deg ? 200 : 1000);
    if (npts == 0)
        return 1;
    return deg ? degrees(npts) : teapot(npts);
}
