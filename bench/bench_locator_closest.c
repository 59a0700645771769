/*
 * Closest points on a whole surface: bs_locator_closest_point on the teapot against brute force
 * over its patches (bs_patch_closest_point on every patch, the nearest kept), on the same query
 * points, one thread, CPU time; the ratio is the figure. Queries: points of the surface moved by
 * up to 0.05 (near), points of its box (inside), and points up to 20 away (far), a third each.
 * Usage: bench_locator_closest [queries]
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include "rays_camera.h"

#include <bezsurf.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned long long rng = 11;
static double uniform(double lo, double hi)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(rng >> 11) * 0x1p-53;
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 3000;
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    double *q[3], *dist = malloc(n * sizeof(double)), *brute = malloc(n * sizeof(double));
    for (int c = 0; c < 3; c++)
        if ((q[c] = malloc(n * sizeof(double))) == NULL)
            return 1;
    if (n == 0 || !dist || !brute || bs_surface_create_builtin("teapot", &s) != BS_OK ||
        bs_locator_create(s, &L) != BS_OK)
        return 1;
    size_t np = bs_surface_count(s);
    for (size_t k = 0; k < n; k++) {
        double scale = k % 3 == 0 ? 0.05 : k % 3 == 1 ? 2 : 20, u = uniform(0, 1), v = uniform(0, 1), x[3];
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        if (bs_patch_eval(bs_surface_get(s, (size_t)uniform(0, (double)np)), 1, &cu, &cv, xv, NULL, NULL) != BS_OK)
            return 1;
        for (int c = 0; c < 3; c++)
            q[c][k] = x[c] + uniform(-scale, scale);
    }
    bs_cview qv[3] = {{q[0], n, 0}, {q[1], n, 0}, {q[2], n, 0}};
    bs_view dv = {dist, n, 0};
    double t0 = now();
    if (bs_locator_closest_point(L, n, qv, NULL, NULL, &dv, NULL) != BS_OK)
        return 1;
    double tl = now() - t0;
    t0 = now();
    for (size_t k = 0; k < n; k++) {
        double x[3] = {q[0][k], q[1][k], q[2][k]}, best = INFINITY, d;
        bs_cview one[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        bs_view d1 = {&d, 1, 0};
        for (size_t i = 0; i < np; i++)
            if (bs_patch_closest_point(bs_surface_get(s, i), 1, one, NULL, &d1, NULL) == BS_OK && d < best)
                best = d;
        brute[k] = best;
    }
    double tb = now() - t0;
    double worst = 0;
    for (size_t k = 0; k < n; k++)
        worst = fmax(worst, dist[k] - brute[k]);
    printf("teapot, %zu closest-point queries (near, inside, far), one thread, CPU time\n", n);
    printf("locator %.0f queries/s; brute force over the %zu patches %.0f queries/s: %.1fx "
           "(largest excess of the locator's distance over brute force %.2g)\n",
           (double)n / tl, np, (double)n / tb, tb / tl, worst);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    for (int c = 0; c < 3; c++)
        free(q[c]);
    free(dist);
    free(brute);
    return 0;
}
