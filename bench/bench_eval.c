/*
 * Evaluation benchmark. Every figure is measured in the same run as two references:
 *   store-only  a plain loop that writes the same output arrays (what memory allows),
 *   naive-dC    a per-point de Casteljau evaluator written here (what a straightforward code does).
 * Workload: the 32 bicubic patches of the Utah teapot, a G x G grid of points per patch, outputs as
 * structure-of-arrays (one array per coordinate), for G = 64 and 256. A second table does the same
 * with float outputs (bs_patch_eval_grid_f32) against a store-only loop that writes floats.
 * Every rate is the best of repeated runs; store-only, grid and scattered (double and float) run in
 * turn, round after round, so that each sees the same load.
 * Usage: bench_eval [teapot.bpt] [seconds per measurement]
 *        bench_eval --once METHOD WORKLOAD G [teapot.bpt]   (one run, for bench/callgrind.sh)
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NPATCH 32
#define NCTRL 16

typedef struct workload {
    const char *name;
    int narrays;      /* output arrays written per point */
    int derivs;       /* positions + du + dv */
    int normals;      /* positions + normals */
} workload;

static const workload workloads[] = {
    {"pos", 3, 0, 0},
    {"pos+du+dv", 9, 1, 0},
    {"pos+normal", 6, 0, 1},
};

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int load_teapot(const char *path, double nets[NPATCH][NCTRL * 3])
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return 0;
    int count = 0, ok = fscanf(f, "%d", &count) == 1 && count == NPATCH;
    for (int k = 0; ok && k < NPATCH; k++) {
        int du, dv;
        ok = fscanf(f, "%d %d", &du, &dv) == 2 && du == 3 && dv == 3;
        for (int c = 0; ok && c < NCTRL * 3; c++)
            ok = fscanf(f, "%lf", &nets[k][c]) == 1;
    }
    fclose(f);
    return ok;
}

/* ---- the two references ---- */

#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif
#if defined(BENCH_CPU_DISPATCH) && defined(BENCH_CPU_NO_AVX512) /* -DBS_CPU_AVX512=OFF */
#define STORE_CLONES __attribute__((target_clones("avx2", "default")))
#elif defined(BENCH_CPU_DISPATCH) /* set by CMake when the library dispatches its loops */
#define STORE_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define STORE_CLONES
#endif

STORE_CLONES NOINLINE static void store_only(double **arrays, int narrays, size_t npts)
{
    for (int a = 0; a < narrays; a++) {
        double *out = arrays[a], x = 1.0 + a;
        for (size_t i = 0; i < npts; i++)
            out[i] = x;
    }
}

/* The float outputs' memory limit: the same loop writing floats. */
STORE_CLONES NOINLINE static void store_only_f32(float **arrays, int narrays, size_t npts)
{
    for (int a = 0; a < narrays; a++) {
        float *out = arrays[a], x = 1.0f + (float)a;
        for (size_t i = 0; i < npts; i++)
            out[i] = x;
    }
}

/* de Casteljau of 4 values down to the last two (a0, a1); the point is (1-t)a0 + t a1. */
static void casteljau_last_two(const double b[4], double t, double *a0, double *a1)
{
    double s = 1.0 - t;
    double c0 = s * b[0] + t * b[1], c1 = s * b[1] + t * b[2], c2 = s * b[2] + t * b[3];
    *a0 = s * c0 + t * c1;
    *a1 = s * c1 + t * c2;
}

static void naive_point(const double *net, double u, double v, const workload *w, double **out, size_t idx)
{
    double pos[3], du[3], dv[3];
    for (int c = 0; c < 3; c++) {
        double col_p[4], col_d[4], a0, a1;
        for (int j = 0; j < 4; j++) {
            double b[4];
            for (int i = 0; i < 4; i++)
                b[i] = net[(i * 4 + j) * 3 + c];
            casteljau_last_two(b, u, &a0, &a1);
            col_p[j] = (1.0 - u) * a0 + u * a1;
            col_d[j] = 3.0 * (a1 - a0);
        }
        casteljau_last_two(col_p, v, &a0, &a1);
        pos[c] = (1.0 - v) * a0 + v * a1;
        dv[c] = 3.0 * (a1 - a0);
        casteljau_last_two(col_d, v, &a0, &a1);
        du[c] = (1.0 - v) * a0 + v * a1;
    }
    for (int c = 0; c < 3; c++)
        out[c][idx] = pos[c];
    if (w->derivs)
        for (int c = 0; c < 3; c++) {
            out[3 + c][idx] = du[c];
            out[6 + c][idx] = dv[c];
        }
    if (w->normals) {
        double n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double inv = len > 0.0 ? 1.0 / len : 0.0;
        for (int c = 0; c < 3; c++)
            out[3 + c][idx] = n[c] * inv;
    }
}

NOINLINE static void naive_grid(double nets[NPATCH][NCTRL * 3], const double *t, size_t g, const workload *w, double **out)
{
    for (size_t k = 0; k < NPATCH; k++)
        for (size_t a = 0; a < g; a++)
            for (size_t b = 0; b < g; b++)
                naive_point(nets[k], t[a], t[b], w, out, (k * g + a) * g + b);
}

/* ---- libbezsurf ---- */

static void views_at(double **arrays, int first, int count, size_t offset, size_t n, bs_view *views)
{
    for (int c = 0; c < count; c++) {
        views[c].data = arrays[first + c] + offset;
        views[c].count = n;
        views[c].stride = 0;
    }
}

static void fviews_at(float **arrays, int first, size_t offset, size_t n, bs_fview *views)
{
    for (int c = 0; c < 3; c++) {
        views[c].data = arrays[first + c] + offset;
        views[c].count = n;
        views[c].stride = 0;
    }
}

/* The grid evaluator into out, or with float outputs into fout when it is not NULL. */
static int lib_grid(bs_patch **patches, const double *t, size_t g, const workload *w, double **out, float **fout)
{
    bs_cview tv = {t, g, 0};
    for (size_t k = 0; k < NPATCH; k++) {
        bs_view v[9];
        bs_fview f[9];
        size_t off = k * g * g;
        if (fout != NULL) {
            for (int a = 0; a < 9; a += 3)
                fviews_at(fout, a, off, g * g, f + a);
        } else {
            views_at(out, 0, 9, off, g * g, v);
        }
        /* normals go to the arrays of S_u */
        int d = w->derivs, n = w->normals;
        bs_status st = fout != NULL ? bs_patch_eval_grid_f32(patches[k], g, &tv, g, &tv, f, d ? f + 3 : NULL,
                                                             d ? f + 6 : NULL, n ? f + 3 : NULL, NULL)
                                    : bs_patch_eval_grid(patches[k], g, &tv, g, &tv, v, d ? v + 3 : NULL,
                                                         d ? v + 6 : NULL, n ? v + 3 : NULL, NULL);
        if (st != BS_OK)
            return 0;
    }
    return 1;
}

static int lib_scattered(bs_patch **patches, const double *u, const double *v, size_t g, const workload *w,
                         double **out)
{
    size_t n = g * g;
    for (size_t k = 0; k < NPATCH; k++) {
        size_t off = k * n;
        bs_cview uv = {u + off, n, 0}, vv = {v + off, n, 0};
        bs_view pos[3], du[3], dv[3];
        views_at(out, 0, 3, off, n, pos);
        bs_status st;
        if (w->normals) {
            views_at(out, 3, 3, off, n, du);
            st = bs_patch_eval_normal(patches[k], n, &uv, &vv, pos, du, NULL);
        } else {
            if (w->derivs) {
                views_at(out, 3, 3, off, n, du);
                views_at(out, 6, 3, off, n, dv);
            }
            st = bs_patch_eval(patches[k], n, &uv, &vv, pos, w->derivs ? du : NULL, w->derivs ? dv : NULL);
        }
        if (st != BS_OK)
            return 0;
    }
    return 1;
}

/* ---- timing ---- */

typedef struct context {
    double (*nets)[NCTRL * 3];
    bs_patch **patches;
    const double *t, *su, *sv;
    size_t g;
    const workload *w;
    double **out;
    float **fout; /* the same arrays, written as floats */
} context;

enum method { STORE, NAIVE, GRID, SCATTERED, STORE32, GRID32 };

static int run_once(const context *cx, enum method m)
{
    switch (m) {
    case STORE: store_only(cx->out, cx->w->narrays, NPATCH * cx->g * cx->g); return 1;
    case NAIVE: naive_grid(cx->nets, cx->t, cx->g, cx->w, cx->out); return 1;
    case GRID: return lib_grid(cx->patches, cx->t, cx->g, cx->w, cx->out, NULL);
    case SCATTERED: return lib_scattered(cx->patches, cx->su, cx->sv, cx->g, cx->w, cx->out);
    case STORE32: store_only_f32(cx->fout, cx->w->narrays, NPATCH * cx->g * cx->g); return 1;
    case GRID32: return lib_grid(cx->patches, cx->t, cx->g, cx->w, NULL, cx->fout);
    }
    return 0;
}

/* Best rate of each of nm methods, in million points per second, over rounds that run each method
 * once in turn for about nm * budget seconds: on a shared machine each method then sees the same
 * spread of load, and the ratios of one run compare like with like. */
static int measure_interleaved(const context *cx, const enum method *ms, int nm, double budget, double *rates)
{
    double points = (double)(NPATCH * cx->g * cx->g), start = now();
    for (int k = 0; k < nm; k++)
        rates[k] = 0.0;
    for (int rounds = 0; rounds < 3 || now() - start < budget * nm; rounds++)
        for (int k = 0; k < nm; k++) {
            double t0 = now();
            if (!run_once(cx, ms[k]))
                return 0;
            double dt = now() - t0;
            if (dt > 0.0 && 1e-6 * points / dt > rates[k])
                rates[k] = 1e-6 * points / dt;
        }
    return 1;
}

/* Best rate of one method over repeated runs for about `budget` seconds, in Mpts/s. */
static double measure(const context *cx, enum method m, double budget)
{
    double rate;
    return measure_interleaved(cx, &m, 1, budget, &rate) ? rate : -1.0;
}

#define NMETHOD 6
static const char *const method_names[NMETHOD] = {"store", "naive", "grid", "scattered", "store32", "grid32"};

/* One run of one method, so that an instruction counter sees exactly that work. */
static int run_single(double nets[NPATCH][NCTRL * 3], bs_patch **patches, char **argv)
{
    int m = -1;
    const workload *w = NULL;
    for (int k = 0; k < NMETHOD; k++)
        if (strcmp(argv[0], method_names[k]) == 0)
            m = k;
    for (size_t k = 0; k < sizeof workloads / sizeof workloads[0]; k++)
        if (strcmp(argv[1], workloads[k].name) == 0)
            w = &workloads[k];
    size_t g = (size_t)atoi(argv[2]);
    if (m < 0 || w == NULL || g < 2 || g > 4096) {
        fprintf(stderr, "bench_eval --once: METHOD is store|naive|grid|scattered|store32|grid32, WORKLOAD pos|pos+du+dv|pos+normal\n");
        return 2;
    }
    size_t npts = NPATCH * g * g;
    double *t = malloc(g * sizeof(double)), *su = malloc(npts * sizeof(double)), *sv = malloc(npts * sizeof(double));
    double *out[9];
    for (int a = 0; a < 9; a++)
        out[a] = malloc(npts * sizeof(double));
    for (size_t a = 0; a < g; a++)
        t[a] = (double)a / (double)(g - 1);
    for (size_t i = 0; i < npts; i++) {
        su[i] = t[i % g];
        sv[i] = t[(i / g) % g];
    }
    float *fout[9];
    for (int a = 0; a < 9; a++)
        fout[a] = (float *)(void *)out[a];
    context cx = {nets, patches, t, su, sv, g, w, out, fout};
    int ok = run_once(&cx, (enum method)m);
    printf("%s %s G=%zu: %zu points\n", method_names[m], w->name, g, npts);
    for (int a = 0; a < 9; a++)
        free(out[a]);
    free(t);
    free(su);
    free(sv);
    return ok ? 0 : 1;
}

/* Tessellating the built-in teapot at TESS x TESS segments per patch against evaluating the same
 * number of points, (TESS+1)^2 per patch, with bs_patch_eval_grid positions + normals. */
#define TESS 64
static void tessellation_vs_grid(bs_patch **patches, double budget)
{
    bs_surface *s = NULL;
    if (bs_surface_create_builtin("teapot", &s) != BS_OK)
        return;
    size_t g = TESS + 1, npts = NPATCH * g * g;
    double *t = malloc(g * sizeof(double)), *out[6];
    for (int a = 0; a < 6; a++)
        out[a] = malloc(npts * sizeof(double));
    for (size_t a = 0; a < g; a++)
        t[a] = (double)a / (double)TESS;
    context cx = {NULL, patches, t, NULL, NULL, g, &workloads[2], out, NULL};
    double grid = measure(&cx, GRID, budget); /* Mpts/s */
    double best = 0.0, start = now();
    size_t verts = 0;
    for (int runs = 0; runs < 3 || now() - start < budget; runs++) {
        bs_mesh *m = NULL;
        double t0 = now();
        if (bs_surface_tessellate_uniform(s, TESS, TESS, 0, &m) != BS_OK)
            break;
        double dt = now() - t0;
        verts = bs_mesh_vertex_count(m);
        bs_mesh_destroy(m);
        if (dt > 0.0 && 1.0 / dt > best)
            best = 1.0 / dt;
    }
    double tess_ms = 1e3 / best, grid_ms = 1e3 * (double)npts / (grid * 1e6);
    printf("tessellate teapot %dx%d/patch (%zu vertices): %.2f ms; grid pos+normal %zu points: %.2f ms; "
           "ratio %.2f\n", TESS, TESS, verts, tess_ms, npts, grid_ms, tess_ms / grid_ms);
    for (int a = 0; a < 6; a++)
        free(out[a]);
    free(t);
    bs_surface_destroy(s);
}

int main(int argc, char **argv)
{
    int once = argc >= 5 && strcmp(argv[1], "--once") == 0;
    const char *path = once ? (argc > 5 ? argv[5] : BS_BENCH_TEAPOT) : (argc > 1 ? argv[1] : BS_BENCH_TEAPOT);
    double budget = !once && argc > 2 ? atof(argv[2]) : 0.5;
    static double nets[NPATCH][NCTRL * 3];
    if (!load_teapot(path, nets)) {
        fprintf(stderr, "bench_eval: cannot read the teapot from %s\n", path);
        return 2;
    }
    bs_patch *patches[NPATCH];
    for (int k = 0; k < NPATCH; k++)
        if (bs_patch_create(3, 3, 3, nets[k], NULL, &patches[k]) != BS_OK)
            return 2;

    if (once) {
        int rc = run_single(nets, patches, argv + 2);
        for (int k = 0; k < NPATCH; k++)
            bs_patch_destroy(patches[k]);
        return rc;
    }
    printf("libbezsurf %s evaluation benchmark: %d teapot patches, G x G points each, Mpts/s\n",
           bs_version_string(), NPATCH);
    printf("%-5s %-11s %11s %11s %17s %17s\n", "G", "workload", "store-only", "naive-dC", "grid (x store)",
           "scattered (x st.)");
    const size_t sizes[2] = {64, 256};
    double f32[2][3][2]; /* float outputs: store-only and grid, per size and workload */
    for (int s = 0; s < 2; s++) {
        size_t g = sizes[s], npts = NPATCH * g * g;
        double *t = malloc(g * sizeof(double)), *su = malloc(npts * sizeof(double)), *sv = malloc(npts * sizeof(double));
        double *out[9];
        float *fout[9];
        for (int a = 0; a < 9; a++) {
            out[a] = malloc(npts * sizeof(double));
            fout[a] = (float *)(void *)out[a];
        }
        for (size_t a = 0; a < g; a++)
            t[a] = (double)a / (double)(g - 1);
        unsigned long long state = 12345;
        for (size_t i = 0; i < npts; i++) { /* scattered parameters: a fixed pseudo-random sequence */
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            su[i] = (double)(state >> 11) * 0x1.0p-53;
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            sv[i] = (double)(state >> 11) * 0x1.0p-53;
        }
        for (size_t wi = 0; wi < sizeof workloads / sizeof workloads[0]; wi++) {
            context cx = {nets, patches, t, su, sv, g, &workloads[wi], out, fout};
            /* the naive reference alone (one of its runs takes as long as dozens of the others) */
            static const enum method ms[5] = {STORE, GRID, SCATTERED, STORE32, GRID32};
            double r[5], naive = measure(&cx, NAIVE, budget);
            if (!measure_interleaved(&cx, ms, 5, budget, r))
                return 1;
            double store = r[0], grid = r[1], scat = r[2];
            f32[s][wi][0] = r[3];
            f32[s][wi][1] = r[4];
            printf("%-5zu %-11s %11.1f %11.1f %9.1f (%4.2f) %9.1f (%4.2f)\n", g, workloads[wi].name, store, naive,
                   grid, grid / store, scat, scat / store);
        }
        for (int a = 0; a < 9; a++)
            free(out[a]);
        free(t);
        free(su);
        free(sv);
    }
    printf("float outputs (bs_patch_eval_grid_f32), Mpts/s\n%-5s %-11s %11s %17s\n", "G", "workload",
           "store-only", "grid (x store)");
    for (int s = 0; s < 2; s++)
        for (int wi = 0; wi < 3; wi++)
            printf("%-5zu %-11s %11.1f %9.1f (%4.2f)\n", sizes[s], workloads[wi].name, f32[s][wi][0],
                   f32[s][wi][1], f32[s][wi][1] / f32[s][wi][0]);
    tessellation_vs_grid(patches, budget);
    for (int k = 0; k < NPATCH; k++)
        bs_patch_destroy(patches[k]);
    return 0;
}
