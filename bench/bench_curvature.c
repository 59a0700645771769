/*
 * Curvature benchmark: bs_patch_eval_curvature against bs_patch_eval_normal on the same points,
 * measured in one run (the ratio is the figure; seconds vary from run to run). Workload: the 32
 * patches of the built-in teapot, N pseudo-random (u,v) per patch, all outputs wanted; then the
 * same with the teapot made rational (weights 1, 1.5, 2 by control point, the net unchanged).
 * Usage: bench_curvature [points per patch] [seconds per measurement]
 *        bench_curvature --once curvature|normal [points per patch [m n [rational]]]
 * --once is for callgrind; with m n, one pseudo-random patch of degree (m,n) (weights too with
 * "rational") is evaluated 32 times in place of the teapot's 32 patches; with "teapot-rational"
 * in place of m, the rational teapot.
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <bezsurf.h>
#include "rational_teapot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct context {
    const bs_patch *patches[32];
    size_t n;
    double *u, *v, *out; /* 10 arrays of n doubles */
    unsigned char *kind;
} context;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int run(const context *cx, int curvature)
{
    bs_cview u = {cx->u, cx->n, 0}, v = {cx->v, cx->n, 0};
    bs_view o[10];
    for (int c = 0; c < 10; c++)
        o[c] = (bs_view){cx->out + (size_t)c * cx->n, cx->n, 0};
    for (size_t i = 0; i < 32; i++) {
        const bs_patch *p = cx->patches[i];
        bs_status st = curvature ? bs_patch_eval_curvature(p, cx->n, &u, &v, o, o + 4, o + 7, cx->kind)
                                 : bs_patch_eval_normal(p, cx->n, &u, &v, o, o + 3, cx->kind);
        if (st != BS_OK)
            return 0;
    }
    return 1;
}

static double measure(const context *cx, int curvature, double budget)
{
    double best = 1e300, end = now() + budget;
    do {
        double t0 = now();
        if (!run(cx, curvature))
            return -1.0;
        double t = now() - t0;
        best = t < best ? t : best;
    } while (now() < end);
    return best;
}

/* A wavy patch of degree (m,n) over the unit square, control points jittered by an LCG. */
static bs_patch *random_patch(size_t m, size_t n, int rational)
{
    if (m > 9 || n > 9)
        return NULL;
    double ctrl[100 * 3], w[100];
    unsigned long long x = 5;
    for (size_t k = 0; k < (m + 1) * (n + 1); k++) {
        for (size_t c = 0; c < 3; c++) {
            x = x * 6364136223846793005ull + 1442695040888963407ull;
            double r = (double)(x >> 11) * 0x1.0p-53 - 0.5;
            double base = c == 0 ? (double)(k / (n + 1)) : c == 1 ? (double)(k % (n + 1)) : 0.0;
            ctrl[3 * k + c] = base + 0.4 * r;
        }
        w[k] = 1.0 + 0.5 * (double)(k % 3);
    }
    bs_patch *p;
    return bs_patch_create(m, n, 3, ctrl, rational ? w : NULL, &p) == BS_OK ? p : NULL;
}


/* The ratio of curvature to normal on cx's patches, printed under title. */
static int report(const context *cx, double budget, const char *title)
{
    double tn = measure(cx, 0, budget), tc = measure(cx, 1, budget);
    if (!(tn > 0 && tc > 0))
        return 0;
    double pts = 32.0 * (double)cx->n;
    printf("%s, %zu random points per patch (best of %.1f s each)\n", title, cx->n, budget);
    printf("  bs_patch_eval_normal     %8.1f ns/point\n", 1e9 * tn / pts);
    printf("  bs_patch_eval_curvature  %8.1f ns/point   ratio %.2f (goal <= 3)\n", 1e9 * tc / pts, tc / tn);
    return 1;
}

int main(int argc, char **argv)
{
    int once = argc > 1 && strcmp(argv[1], "--once") == 0;
    context cx;
    cx.n = (size_t)atol(argc > (once ? 3 : 1) ? argv[once ? 3 : 1] : "4096");
    double budget = !once && argc > 2 ? atof(argv[2]) : 1.0;
    bs_surface *s;
    if (cx.n == 0 || bs_surface_create_builtin("teapot", &s) != BS_OK || bs_surface_count(s) != 32)
        return 1;
    bs_patch *own = NULL, *rat[32] = {NULL};
    for (size_t i = 0; i < 32; i++)
        if (!(rat[i] = rational_copy(bs_surface_get(s, i))))
            return 1;
    int rational_teapot = once && argc > 4 && strcmp(argv[4], "teapot-rational") == 0;
    if (once && argc > 5 && !rational_teapot) {
        if (!(own = random_patch((size_t)atol(argv[4]), (size_t)atol(argv[5]), argc > 6)))
            return 1;
    }
    for (size_t i = 0; i < 32; i++)
        cx.patches[i] = own ? own : rational_teapot ? rat[i] : bs_surface_get(s, i);
    cx.u = malloc(cx.n * sizeof(double));
    cx.v = malloc(cx.n * sizeof(double));
    cx.out = malloc(10 * cx.n * sizeof(double));
    cx.kind = malloc(cx.n);
    if (!cx.u || !cx.v || !cx.out || !cx.kind)
        return 1;
    unsigned long long x = 12345;
    for (size_t k = 0; k < cx.n; k++) { /* an LCG: the same points every run */
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        cx.u[k] = (double)(x >> 11) * 0x1.0p-53;
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        cx.v[k] = (double)(x >> 11) * 0x1.0p-53;
    }
    int ok;
    if (once) {
        ok = argc > 2 && run(&cx, strcmp(argv[2], "curvature") == 0);
    } else {
        ok = report(&cx, budget, "teapot");
        for (size_t i = 0; i < 32; i++)
            cx.patches[i] = rat[i];
        ok = ok && report(&cx, budget, "rational teapot");
    }
    free(cx.u);
    free(cx.v);
    free(cx.out);
    free(cx.kind);
    bs_patch_destroy(own);
    for (size_t i = 0; i < 32; i++)
        bs_patch_destroy(rat[i]);
    bs_surface_destroy(s);
    return ok ? 0 : 1;
}
