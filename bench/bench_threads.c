/*
 * One thread against two in the same run: teapot tessellation at 64 x 64 segments per patch
 * (uniform, bs_surface_tessellate with bs_tess_options.threads), the subdivision tessellator at
 * 1e-3 relative, and the 32 teapot patches on a G = 256 grid (bs_surface_eval_grid: positions, and
 * positions + normals), and a locator over the teapot answering 2,000 closest-point queries and
 * 65,536 rays from a camera (bs_locator_closest_point_mt, bs_locator_intersect_mt). The two thread
 * counts take turns, 1 2 1 2, each turn a quarter of the
 * time, so that both see the same machine load; each figure is the best of the calls. Not call
 * by call: glibc's malloc then gives the mesh's memory back to the system after every call and
 * faults it in again in the next (three times the time of a tessellation, for either count). The CPU time of the process per call (best
 * of the calls) shows what the threads cost in all, which a loaded machine does not inflate.
 * Usage: bench_threads [SECONDS per case].
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double clock_s(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double now(void) { return clock_s(CLOCK_MONOTONIC); }

typedef int (*job)(void *ctx, size_t threads); /* 1 on success */

typedef struct tess_case { const bs_surface *s; bs_tess_options o; } tess_case;

static int tessellate(void *ctx, size_t threads)
{
    tess_case *c = ctx;
    c->o.threads = threads;
    bs_mesh *m = NULL;
    int ok = bs_surface_tessellate(c->s, &c->o, &m) == BS_OK;
    bs_mesh_destroy(m);
    return ok;
}

#define G 256
typedef struct grid_case { const bs_surface *s; bs_cview t; bs_view out[6]; int normals; } grid_case;

static int grid(void *ctx, size_t threads)
{
    grid_case *c = ctx;
    return bs_surface_eval_grid(c->s, G, &c->t, G, &c->t, c->out, NULL, NULL, c->normals ? c->out + 3 : NULL,
                                NULL, threads) == BS_OK;
}

/* Best times of 1 and 2 threads, in turns of budget / 4 seconds and at least 5 calls. */
static void measure(const char *name, job f, void *ctx, double budget)
{
    double best[2] = {1e30, 1e30}, cpu[2] = {1e30, 1e30};
    for (int turn = 0; turn < 4; turn++) {
        size_t k = (size_t)turn % 2;
        double start = now();
        for (int runs = 0; runs < 5 || now() - start < budget / 4; runs++) {
            double t0 = now(), c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
            if (!f(ctx, k + 1)) {
                fprintf(stderr, "bench_threads: %s failed\n", name);
                exit(1);
            }
            double dt = now() - t0, dc = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
            best[k] = dt < best[k] ? dt : best[k];
            cpu[k] = dc < cpu[k] ? dc : cpu[k];
        }
    }
    printf("%-34s %9.2f ms %9.2f ms %7.2f %9.2f ms %9.2f ms\n", name, 1e3 * best[0], 1e3 * best[1],
           best[0] / best[1], 1e3 * cpu[0], 1e3 * cpu[1]);
}

/* Queries of a locator: n points (closest) or n rays from one camera point (rays). */
#define QUERIES 2000
#define RAYS (256 * 256)
typedef struct locator_case {
    const bs_locator *L;
    bs_cview q[3], org[3], dir[3];
    uint32_t *id;
    bs_view dist;
} locator_case;

static int closest(void *ctx, size_t threads)
{
    locator_case *c = ctx;
    return bs_locator_closest_point_mt(c->L, QUERIES, c->q, c->id, NULL, &c->dist, NULL, threads) == BS_OK;
}

static int rays(void *ctx, size_t threads)
{
    locator_case *c = ctx;
    return bs_locator_intersect_mt(c->L, RAYS, c->org, c->dir, NULL, c->id, NULL, &c->dist, NULL, threads) == BS_OK;
}

/* Queries spread over the teapot's box enlarged by 1 on every side, and rays from (10, -8, 6)
 * through a 256 x 256 grid of points on the plane x = 0 that covers the teapot. */
static void locator_queries(const bs_surface *s, double budget)
{
    bs_locator *L = NULL;
    double *q = malloc(3 * QUERIES * sizeof(double)), *dir = malloc(3 * RAYS * sizeof(double));
    double *org = malloc(3 * RAYS * sizeof(double)), *dist = malloc(RAYS * sizeof(double));
    const double origin[3] = {10.0, -8.0, 6.0};
    uint32_t *id = malloc(RAYS * sizeof(uint32_t));
    if (q == NULL || dir == NULL || org == NULL || dist == NULL || id == NULL || bs_locator_create(s, &L) != BS_OK)
        exit(1);
    unsigned long long x = 1;
    for (size_t k = 0; k < 3 * QUERIES; k++) {
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        double r = (double)(x >> 11) / 9007199254740992.0, lo[3] = {-4, -3, -1}, hi[3] = {4.5, 3, 4.2};
        q[k] = lo[k % 3] + r * (hi[k % 3] - lo[k % 3]);
    }
    for (size_t k = 0; k < RAYS; k++) {
        double to[3] = {0.0, -3.5 + 7.0 * (double)(k % 256) / 255.0, -0.5 + 4.0 * (double)(k / 256) / 255.0};
        for (int c = 0; c < 3; c++) {
            org[3 * k + (size_t)c] = origin[c];
            dir[3 * k + (size_t)c] = to[c] - origin[c];
        }
    }
    locator_case lc = {L, {{q, QUERIES, 24}, {q + 1, QUERIES, 24}, {q + 2, QUERIES, 24}},
                       {{org, RAYS, 24}, {org + 1, RAYS, 24}, {org + 2, RAYS, 24}},
                       {{dir, RAYS, 24}, {dir + 1, RAYS, 24}, {dir + 2, RAYS, 24}}, id, {dist, RAYS, 0}};
    measure("locator 2000 closest points", closest, &lc, budget);
    measure("locator 256x256 camera rays", rays, &lc, budget);
    bs_locator_destroy(L);
    free(q);
    free(dir);
    free(org);
    free(dist);
    free(id);
}

int main(int argc, char **argv)
{
    double budget = argc > 1 ? atof(argv[1]) : 2.0;
    bs_surface *s = NULL;
    if (bs_surface_create_builtin("teapot", &s) != BS_OK)
        return 1;
    printf("%-34s %12s %12s %7s %12s %12s\n", "case (best of 1 2 1 2 turns)", "1 thread", "2 threads", "ratio",
           "CPU 1", "CPU 2");
    tess_case tc = {s, {0}};
    bs_tess_options_init(&tc.o);
    tc.o.nu = tc.o.nv = 64;
    measure("tessellate teapot 64x64", tessellate, &tc, budget);
    bs_tess_options_init(&tc.o);
    tc.o.method = BS_TESS_SUBDIVIDE;
    tc.o.flags = BS_TESS_RELATIVE;
    measure("tessellate teapot subdivide 1e-3", tessellate, &tc, budget);

    size_t n = bs_surface_count(s) * G * G;
    double *t = malloc(G * sizeof(double)), *buf = malloc(6 * n * sizeof(double));
    if (t == NULL || buf == NULL)
        return 1;
    for (size_t k = 0; k < G; k++)
        t[k] = (double)k / (double)(G - 1);
    grid_case gc = {s, {t, G, 0}, {{0}}, 0};
    for (size_t c = 0; c < 6; c++)
        gc.out[c] = (bs_view){buf + c * n, n, 0};
    measure("grid 32 patches G=256 pos", grid, &gc, budget);
    gc.normals = 1;
    measure("grid 32 patches G=256 pos+normal", grid, &gc, budget);
    locator_queries(s, budget);
    free(t);
    free(buf);
    bs_surface_destroy(s);
    return 0;
}
