/*
 * Ray benchmark: bs_locator_intersect on the built-in teapot, one thread.
 *  - primary rays: an N x N pinhole camera (default 1024 x 1024) looking at the teapot;
 *  - secondary rays: from the primary hits, in uniformly random directions (incoherent).
 * Side by side in the same run, a baseline without a hierarchy over the patches: one locator per
 * patch, and every ray tested against every patch's box (bs_patch_bounds), the patch's locator
 * called where the box is hit (with the t range cut at the best hit so far). The ratio is the
 * figure; seconds vary from run to run on a loaded machine.
 * Usage: bench_rays [N] [baseline rays as a fraction of N*N, default 1/16]
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#ifdef __GLIBC__
#include <malloc.h> /* mallinfo2: the locator's memory */
#endif

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

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

int main(int argc, char **argv)
{
    size_t N = argc > 1 ? (size_t)atol(argv[1]) : 1024, nrays = N * N;
    double frac = argc > 2 ? atof(argv[2]) : 1.0 / 16;
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    if (N == 0 || bs_surface_create_builtin("teapot", &s) != BS_OK)
        return 1;
    double bytes = -1;
#ifdef __GLIBC__
    bytes = -(double)(mallinfo2().uordblks + mallinfo2().hblkhd); /* heap and mmap-ed blocks */
#endif
    double t0 = now();
    if (bs_locator_create(s, &L) != BS_OK)
        return 1;
    double build = now() - t0;
#ifdef __GLIBC__
    bytes += (double)(mallinfo2().uordblks + mallinfo2().hblkhd);
#endif
    baseline b = {bs_surface_count(s), NULL, NULL, NULL};
    b.L = calloc(b.np, sizeof *b.L);
    b.lo = malloc(b.np * sizeof *b.lo);
    b.hi = malloc(b.np * sizeof *b.hi);
    rays pr, sr;
    if (!b.L || !b.lo || !b.hi || !rays_alloc(&pr, nrays) || !rays_alloc(&sr, nrays))
        return 1;
    for (size_t i = 0; i < b.np; i++) {
        bs_surface *one = NULL;
        const bs_patch *p = bs_surface_get(s, i);
        if (bs_surface_create(&one) != BS_OK || bs_surface_add(one, p, NULL) != BS_OK ||
            bs_locator_create(one, &b.L[i]) != BS_OK || bs_patch_bounds(p, b.lo[i], b.hi[i]) != BS_OK)
            return 1;
        bs_surface_destroy(one);
    }
    /* camera at eye looking at the teapot's middle, 40 degrees across */
    const double eye[3] = {6.0, -8.0, 5.5}, at[3] = {0.2, 0.0, 1.4}, up[3] = {0, 0, 1};
    double f[3], rgt[3], u[3], fl = 0, rl = 0, half = tan(20.0 * 3.14159265358979 / 180.0);
    for (int c = 0; c < 3; c++) {
        f[c] = at[c] - eye[c];
        fl += f[c] * f[c];
    }
    for (int c = 0; c < 3; c++)
        f[c] /= sqrt(fl);
    rgt[0] = f[1] * up[2] - f[2] * up[1];
    rgt[1] = f[2] * up[0] - f[0] * up[2];
    rgt[2] = f[0] * up[1] - f[1] * up[0];
    for (int c = 0; c < 3; c++)
        rl += rgt[c] * rgt[c];
    for (int c = 0; c < 3; c++)
        rgt[c] /= sqrt(rl);
    u[0] = rgt[1] * f[2] - rgt[2] * f[1];
    u[1] = rgt[2] * f[0] - rgt[0] * f[2];
    u[2] = rgt[0] * f[1] - rgt[1] * f[0];
    for (size_t y = 0; y < N; y++)
        for (size_t x = 0; x < N; x++) {
            size_t k = y * N + x;
            double px = (2.0 * ((double)x + 0.5) / (double)N - 1.0) * half;
            double py = (1.0 - 2.0 * ((double)y + 0.5) / (double)N) * half;
            for (int c = 0; c < 3; c++) {
                pr.o[c][k] = eye[c];
                pr.d[c][k] = f[c] + px * rgt[c] + py * u[c];
            }
        }
    t0 = now();
    if (primary_pass(L, &pr) != BS_OK)
        return 1;
    double tp = now() - t0;
    size_t hp = count_hits(&pr, nrays);
    /* secondary rays: from each primary hit (or, for a miss, from a random primary hit) */
    size_t ns = 0;
    for (size_t k = 0; k < nrays; k++)
        if (pr.patch[k] != UINT32_MAX)
            pr.patch[ns++] = (uint32_t)k; /* reuse: indices of hits */
    if (ns == 0)
        return 1;
    for (size_t k = 0; k < nrays; k++) {
        size_t from = pr.patch[k < ns ? k : (size_t)(uniform() * (double)ns)];
        double z = 2 * uniform() - 1, a = 2 * 3.14159265358979 * uniform(), r = sqrt(1 - z * z);
        double dir[3] = {r * cos(a), r * sin(a), z};
        for (int c = 0; c < 3; c++) {
            sr.o[c][k] = pr.o[c][from] + pr.t[from] * pr.d[c][from];
            sr.d[c][k] = dir[c];
        }
        sr.range[0][k] = 1e-6; /* leave the surface the ray starts on */
        sr.range[1][k] = 1e300;
    }
    t0 = now();
    if (secondary_pass(L, &sr) != BS_OK)
        return 1;
    double ts = now() - t0;
    size_t hs = count_hits(&sr, nrays);
    /* the baseline on the first fraction of each set (spread over the image: every k-th ray) */
    size_t nb = (size_t)((double)nrays * frac), stride = nb ? nrays / nb : 1;
    rays pb, sb;
    if (nb == 0) { /* no baseline */
        printf("primary %zux%zu: %.0f rays/s (%zu hits); secondary %.0f rays/s (%zu hits)\n", N, N,
               (double)nrays / tp, hp, (double)nrays / ts, hs);
        return 0;
    }
    if (!rays_alloc(&pb, nb) || !rays_alloc(&sb, nb))
        return 1;
    for (size_t k = 0; k < nb; k++)
        for (int c = 0; c < 3; c++) {
            pb.o[c][k] = pr.o[c][k * stride];
            pb.d[c][k] = pr.d[c][k * stride];
            sb.o[c][k] = sr.o[c][k * stride];
            sb.d[c][k] = sr.d[c][k * stride];
            if (c < 2) {
                sb.range[c][k] = sr.range[c][k * stride];
            }
        }
    t0 = now();
    size_t hbp = baseline_trace(&b, &pb, nb, 0);
    double tbp = now() - t0;
    t0 = now();
    size_t hbs = baseline_trace(&b, &sb, nb, 1);
    double tbs = now() - t0;
    printf("teapot: %zu patches, locator built in %.3f ms, %.0f bytes allocated (%.0f per patch)\n", b.np,
           build * 1e3, bytes, bytes / (double)b.np);
    printf("primary   %zux%zu: %9.0f rays/s (%zu hits); baseline (every patch box, no hierarchy) "
           "%9.0f rays/s on %zu of them (%zu hits): %.1fx\n",
           N, N, (double)nrays / tp, hp, (double)nb / tbp, nb, hbp, ((double)nb / tbp) > 0 ? ((double)nrays / tp) / ((double)nb / tbp) : 0);
    printf("secondary %zu random: %9.0f rays/s (%zu hits); baseline %9.0f rays/s on %zu (%zu hits): %.1fx\n",
           nrays, (double)nrays / ts, hs, (double)nb / tbs, nb, hbs, ((double)nrays / ts) / ((double)nb / tbs));
    for (size_t i = 0; i < b.np; i++)
        bs_locator_destroy(b.L[i]);
    free(b.L);
    free(b.lo);
    free(b.hi);
    rays_free(&pr);
    rays_free(&sr);
    rays_free(&pb);
    rays_free(&sb);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    return 0;
}
