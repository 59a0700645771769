/*
 * Ray benchmark: bs_locator_intersect on the built-in teapot, one thread.
 *  - primary rays: an N x N pinhole camera (default 1024 x 1024) looking at the teapot;
 *  - secondary rays: from the primary hits, in uniformly random directions (incoherent).
 * Side by side in the same run, a baseline without a hierarchy over the patches: one locator per
 * patch, and every ray tested against every patch's box (bs_patch_bounds), the patch's locator
 * called where the box is hit (with the t range cut at the best hit so far). The ratio is the
 * figure; seconds vary from run to run on a loaded machine.
 * The same again on the teapot cut into 8 x 8 sub-patches per patch (2,048 patches), where the
 * hierarchy has more to do. Times are CPU time.
 * Usage: bench_rays [N] [stride: the ratio on every stride-th ray, default 16; 0: the teapot
 *        alone, no baseline, no cut teapot]
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include "rays_camera.h"

#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#ifdef __GLIBC__
#include <malloc.h> /* mallinfo2: the locator's memory */
#endif

typedef struct rays {
    size_t n;
    double *o[3], *d[3], *range[2];
    double *t, *u, *v;
    uint32_t *patch;
} rays;

static int rays_alloc(rays *r, size_t n)
{
    r->n = n;
    double **all[] = {&r->o[0], &r->o[1], &r->o[2], &r->d[0], &r->d[1], &r->d[2],
                      &r->range[0], &r->range[1], &r->t, &r->u, &r->v};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        if ((*all[k] = malloc(n * sizeof(double))) == NULL)
            return 0;
    return (r->patch = malloc(n * sizeof(uint32_t))) != NULL;
}

static void rays_free(rays *r)
{
    double *all[] = {r->o[0], r->o[1], r->o[2], r->d[0], r->d[1], r->d[2], r->range[0], r->range[1],
                     r->t, r->u, r->v};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        free(all[k]);
    free(r->patch);
}

/* Rays first .. first + n - 1 of r through L; with range when ranged. */
static bs_status trace(const bs_locator *L, const rays *r, size_t first, size_t n, int ranged)
{
    bs_cview o[3], d[3], g[2];
    bs_view uv[2] = {{r->u + first, n, 0}, {r->v + first, n, 0}}, t = {r->t + first, n, 0};
    for (int c = 0; c < 3; c++) {
        o[c] = (bs_cview){r->o[c] + first, n, 0};
        d[c] = (bs_cview){r->d[c] + first, n, 0};
    }
    for (int c = 0; c < 2; c++)
        g[c] = (bs_cview){r->range[c] + first, n, 0};
    return bs_locator_intersect(L, n, o, d, ranged ? g : NULL, r->patch + first, uv, &t, NULL);
}

/* The baseline: every patch's box, then that patch's own locator. */
typedef struct baseline {
    size_t np;
    bs_locator **L;
    double (*lo)[3], (*hi)[3];
} baseline;

static int box_hit(const double lo[3], const double hi[3], const double o[3], const double d[3],
                   double t0, double t1)
{
    for (int c = 0; c < 3; c++) {
        double a = (lo[c] - o[c]) / d[c], b = (hi[c] - o[c]) / d[c];
        if (a > b) {
            double x = a;
            a = b;
            b = x;
        }
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
    }
    return t0 <= t1;
}

static size_t baseline_trace(const baseline *b, const rays *r, size_t n, int ranged)
{
    size_t hits = 0;
    for (size_t k = 0; k < n; k++) {
        double o[3] = {r->o[0][k], r->o[1][k], r->o[2][k]}, d[3] = {r->d[0][k], r->d[1][k], r->d[2][k]};
        double range[2] = {ranged ? r->range[0][k] : 0x1p-60, ranged ? r->range[1][k] : 1e300}, best = INFINITY;
        for (size_t i = 0; i < b->np; i++) {
            if (!box_hit(b->lo[i], b->hi[i], o, d, range[0], best < range[1] ? best : range[1]))
                continue;
            double t, g[2] = {range[0], best < range[1] ? best : range[1]};
            uint32_t id;
            bs_cview ov[3], dv[3], gv[2] = {{&g[0], 1, 0}, {&g[1], 1, 0}};
            for (int c = 0; c < 3; c++) {
                ov[c] = (bs_cview){&o[c], 1, 0};
                dv[c] = (bs_cview){&d[c], 1, 0};
            }
            bs_view tv = {&t, 1, 0};
            if (bs_locator_intersect(b->L[i], 1, ov, dv, gv, &id, NULL, &tv, NULL) == BS_OK && t < best)
                best = t;
        }
        hits += best < INFINITY;
    }
    return hits;
}

/* The two locator passes as functions of their own, so that callgrind can count each:
 * valgrind --tool=callgrind --toggle-collect=primary_pass build/bench/bench_rays 256 0 */
__attribute__((noinline)) bs_status primary_pass(const bs_locator *L, const rays *r);
__attribute__((noinline)) bs_status primary_pass(const bs_locator *L, const rays *r)
{
    return trace(L, r, 0, r->n, 0);
}
__attribute__((noinline)) bs_status secondary_pass(const bs_locator *L, const rays *r);
__attribute__((noinline)) bs_status secondary_pass(const bs_locator *L, const rays *r)
{
    return trace(L, r, 0, r->n, 1);
}

static size_t count_hits(const rays *r, size_t n)
{
    size_t h = 0;
    for (size_t k = 0; k < n; k++)
        h += r->patch[k] != UINT32_MAX;
    return h;
}

static unsigned long long rng = 7;
static double uniform(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng >> 11) * 0x1p-53;
}

/* The N x N primary rays of the camera (rays_camera.h). */
static void camera(rays *pr, size_t N)
{
    camera_rays(N, pr->o, pr->d);
    for (size_t k = 0; k < N * N; k++) {
        pr->range[0][k] = 0.0; /* unused: primary rays take the default range */
        pr->range[1][k] = 1e300;
    }
}

/* Secondary rays: from the primary hits (each in turn, then random ones) in uniformly random
 * directions, leaving the surface they start on (t from 1e-6). 0 if no primary ray hit. */
static int scatter(const rays *pr, rays *sr)
{
    size_t nh = 0, *hits = malloc(pr->n * sizeof *hits);
    for (size_t k = 0; hits && k < pr->n; k++)
        if (pr->patch[k] != UINT32_MAX)
            hits[nh++] = k;
    if (nh == 0) {
        free(hits);
        return 0;
    }
    for (size_t k = 0; k < sr->n; k++) {
        size_t from = hits[k < nh ? k : (size_t)(uniform() * (double)nh)];
        double z = 2 * uniform() - 1, a = 2 * 3.14159265358979 * uniform(), r = sqrt(1 - z * z);
        double dir[3] = {r * cos(a), r * sin(a), z};
        for (int c = 0; c < 3; c++) {
            sr->o[c][k] = pr->o[c][from] + pr->t[from] * pr->d[c][from];
            sr->d[c][k] = dir[c];
        }
        sr->range[0][k] = 1e-6;
        sr->range[1][k] = 1e300;
    }
    free(hits);
    return 1;
}

/* Every stride-th ray of r into sub (allocated). */
static int every(const rays *r, size_t stride, rays *sub)
{
    if (!rays_alloc(sub, r->n / stride))
        return 0;
    for (size_t k = 0; k < sub->n; k++) {
        for (int c = 0; c < 3; c++) {
            sub->o[c][k] = r->o[c][k * stride];
            sub->d[c][k] = r->d[c][k * stride];
        }
        sub->range[0][k] = r->range[0][k * stride];
        sub->range[1][k] = r->range[1][k * stride];
    }
    return 1;
}

static bs_status baseline_create(const bs_surface *s, baseline *b)
{
    b->np = bs_surface_count(s);
    b->L = calloc(b->np, sizeof *b->L);
    b->lo = malloc(b->np * sizeof *b->lo);
    b->hi = malloc(b->np * sizeof *b->hi);
    if (!b->L || !b->lo || !b->hi)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 0; i < b->np; i++) {
        bs_surface *one = NULL;
        const bs_patch *p = bs_surface_get(s, i);
        bs_status st;
        if ((st = bs_surface_create(&one)) != BS_OK || (st = bs_surface_add(one, p, NULL)) != BS_OK ||
            (st = bs_locator_create(one, &b->L[i])) != BS_OK || (st = bs_patch_bounds(p, b->lo[i], b->hi[i])) != BS_OK)
            return st;
        bs_surface_destroy(one);
    }
    return BS_OK;
}

static void baseline_destroy(baseline *b)
{
    for (size_t i = 0; b->L && i < b->np; i++)
        bs_locator_destroy(b->L[i]);
    free(b->L);
    free(b->lo);
    free(b->hi);
}

/* The teapot with every patch cut into k x k sub-patches (bs_patch_subpatch). */
static bs_surface *cut(const bs_surface *s, int k)
{
    bs_surface *out = NULL;
    if (bs_surface_create(&out) != BS_OK)
        return NULL;
    for (size_t i = 0; i < bs_surface_count(s); i++)
        for (int a = 0; a < k; a++)
            for (int b = 0; b < k; b++) {
                bs_patch *p = NULL;
                if (bs_patch_subpatch(bs_surface_get(s, i), (double)a / k, (double)(a + 1) / k,
                                      (double)b / k, (double)(b + 1) / k, &p) != BS_OK ||
                    bs_surface_add(out, p, NULL) != BS_OK) {
                    bs_patch_destroy(p);
                    bs_surface_destroy(out);
                    return NULL;
                }
                bs_patch_destroy(p);
            }
    return out;
}

/* One surface: the locator on all the rays, and the locator and the baseline on every
 * stride-th ray (the same rays for both: their times make the ratio). */
static int bench(const char *name, const bs_surface *s, rays *pr, rays *sr, size_t stride, int make_secondary)
{
    bs_locator *L = NULL;
    double bytes = 0;
#ifdef __GLIBC__
    bytes = -(double)(mallinfo2().uordblks + mallinfo2().hblkhd); /* heap and mmap-ed blocks */
#endif
    double t0 = now();
    if (bs_locator_create(s, &L) != BS_OK)
        return 0;
    double build = now() - t0;
#ifdef __GLIBC__
    bytes += (double)(mallinfo2().uordblks + mallinfo2().hblkhd);
#endif
    size_t np = bs_surface_count(s);
    printf("%s: %zu patches, locator built in %.1f ms, %.0f bytes allocated (%.0f per patch)\n", name, np,
           build * 1e3, bytes, bytes / (double)np);
    t0 = now();
    if (primary_pass(L, pr) != BS_OK)
        return 0;
    double tp = now() - t0;
    if (make_secondary && !scatter(pr, sr))
        return 0;
    t0 = now();
    if (secondary_pass(L, sr) != BS_OK)
        return 0;
    double ts = now() - t0;
    printf("  all rays:  primary %.0f rays/s (%zu of %zu hit), secondary %.0f rays/s (%zu of %zu hit)\n",
           (double)pr->n / tp, count_hits(pr, pr->n), pr->n, (double)sr->n / ts, count_hits(sr, sr->n), sr->n);
    if (stride == 0) {
        bs_locator_destroy(L);
        return 1;
    }
    baseline b = {0, NULL, NULL, NULL};
    rays sub[2];
    int ok = baseline_create(s, &b) == BS_OK && every(pr, stride, &sub[0]) && every(sr, stride, &sub[1]);
    for (int k = 0; k < 2 && ok; k++) {
        t0 = now();
        ok = trace(L, &sub[k], 0, sub[k].n, k) == BS_OK;
        double tl = now() - t0;
        t0 = now();
        size_t hb = baseline_trace(&b, &sub[k], sub[k].n, k);
        double tb = now() - t0;
        printf("  1/%zu of the %s rays: locator %.0f rays/s (%zu hit), baseline (every patch's box, no "
               "hierarchy) %.0f rays/s (%zu hit): %.1fx\n",
               stride, k ? "secondary" : "primary", (double)sub[k].n / tl, count_hits(&sub[k], sub[k].n),
               (double)sub[k].n / tb, hb, tb / tl);
    }
    if (ok) {
        rays_free(&sub[0]);
        rays_free(&sub[1]);
    }
    baseline_destroy(&b);
    bs_locator_destroy(L);
    return ok;
}

int main(int argc, char **argv)
{
    size_t N = argc > 1 ? (size_t)atol(argv[1]) : 1024, nrays = N * N;
    size_t stride = argc > 2 ? (size_t)atol(argv[2]) : 16;
    bs_surface *s = NULL, *fine = NULL;
    rays pr, sr;
    if (N == 0 || bs_surface_create_builtin("teapot", &s) != BS_OK || (fine = cut(s, 8)) == NULL ||
        !rays_alloc(&pr, nrays) || !rays_alloc(&sr, nrays))
        return 1;
    camera(&pr, N);
    printf("%zux%zu primary rays (a camera at the teapot), as many secondary rays (from the primary "
           "hits, random directions); seconds of CPU time\n", N, N);
    int ok = bench("teapot", s, &pr, &sr, stride, 1) &&
             (stride == 0 || bench("teapot cut 8x8", fine, &pr, &sr, stride, 0));
    rays_free(&pr);
    rays_free(&sr);
    bs_surface_destroy(fine);
    bs_surface_destroy(s);
    return ok ? 0 : 1;
}
