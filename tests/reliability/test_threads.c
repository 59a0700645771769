/* Eight threads share one rational patch and one surface (the built-in teapot) and run every
 * reading function on them at once: scattered evaluation, derivatives, normals, grids, surface
 * evaluation, split, sub-patch, .bpt writing, the continuity report and tessellation. Every thread's results
 * must be bit-identical to a serial run. Built with -fsanitize=thread by .ci/tsan.sh, this is
 * also the data-race test. */
#include "harness.h"

#include <bezsurf.h>

#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { NTHREADS = 8, NPT = 257, GU = 13, GV = 11, REPEAT = 3 };

static bs_patch *shared_patch;
static bs_surface *shared_surface;
static double us[NPT], vs[NPT];
static uint32_t ids[NPT];

/* Everything one run computes, compared bit for bit. */
typedef struct results {
    double pos[3][NPT], du[3][NPT], dv[3][NPT], d21[3][NPT], nrm[3][NPT];
    unsigned char kind[NPT];
    double grid[3][GU * GV], gnrm[3][GU * GV];
    unsigned char gkind[GU * GV];
    double spos[3][NPT], snrm[3][NPT];
    unsigned char skind[NPT];
    double split_ctrl[2][3 * 3 * 3], split_w[2][9];
    double sub_ctrl[27], sub_w[9];
    size_t text_size, n_edges, n_open;
    char text[16384];
    bs_edge_continuity edges[64];
    size_t mesh_vertices, mesh_triangles;
    double mesh_xyz[3][2048];
    uint32_t mesh_tri[3 * 4096];
    int failures; /* calls that did not return BS_OK */
} results;

static void views(double (*a)[NPT], bs_view *v)
{
    for (int c = 0; c < 3; c++)
        v[c] = (bs_view){a[c], NPT, 0};
}

static void gviews(double (*a)[GU * GV], bs_view *v)
{
    for (int c = 0; c < 3; c++)
        v[c] = (bs_view){a[c], GU * GV, 0};
}

static void run(results *r)
{
    memset(r, 0, sizeof *r);
    bs_cview u = {us, NPT, 0}, v = {vs, NPT, 0}, gu = {us, GU, 0}, gv = {vs, GV, 0};
    bs_view a[3], b[3], c[3];
    views(r->pos, a);
    views(r->du, b);
    views(r->dv, c);
    r->failures += bs_patch_eval(shared_patch, NPT, &u, &v, a, b, c) != BS_OK;
    views(r->d21, a);
    r->failures += bs_patch_eval_deriv(shared_patch, 2, 1, NPT, &u, &v, a) != BS_OK;
    views(r->nrm, a);
    r->failures += bs_patch_eval_normal(shared_patch, NPT, &u, &v, NULL, a, r->kind) != BS_OK;
    gviews(r->grid, a);
    gviews(r->gnrm, b);
    r->failures += bs_patch_eval_grid(shared_patch, GU, &gu, GV, &gv, a, NULL, NULL, b, r->gkind) != BS_OK;
    views(r->spos, a);
    views(r->snrm, b);
    r->failures += bs_surface_eval_normal(shared_surface, NPT, ids, &u, &v, a, b, r->skind) != BS_OK;
    bs_patch *lo = NULL, *hi = NULL, *sub = NULL;
    r->failures += bs_patch_split(shared_patch, BS_DIR_V, 0.375, &lo, &hi) != BS_OK;
    r->failures += bs_patch_get_ctrl(lo, r->split_ctrl[0], 27, r->split_w[0], 9) != BS_OK;
    r->failures += bs_patch_get_ctrl(hi, r->split_ctrl[1], 27, r->split_w[1], 9) != BS_OK;
    r->failures += bs_patch_subpatch(shared_patch, 0.2, 0.7, 0.9, 0.1, &sub) != BS_OK;
    r->failures += bs_patch_get_ctrl(sub, r->sub_ctrl, 27, r->sub_w, 9) != BS_OK;
    bs_patch_destroy(lo);
    bs_patch_destroy(hi);
    bs_patch_destroy(sub);
    r->failures += bs_surface_write_bpt(shared_surface, r->text, sizeof r->text, &r->text_size) != BS_OK;
    bs_mesh *mesh = NULL;
    r->failures += bs_surface_tessellate_uniform(shared_surface, 4, 3, 0, &mesh) != BS_OK;
    r->mesh_vertices = bs_mesh_vertex_count(mesh);
    r->mesh_triangles = bs_mesh_triangle_count(mesh);
    bs_view mv[3];
    for (int i = 0; i < 3; i++)
        mv[i] = (bs_view){r->mesh_xyz[i], 2048, 0};
    r->failures += bs_mesh_copy_positions(mesh, mv) != BS_OK;
    r->failures += bs_mesh_copy_triangles(mesh, r->mesh_tri, 3 * 4096) != BS_OK;
    bs_mesh_destroy(mesh);
    r->failures += bs_surface_continuity(shared_surface, 1e-6, 4, r->edges, 64, &r->n_edges, NULL, 0,
                                         &r->n_open) != BS_OK;
}

static results serial, parallel[NTHREADS];
static int mismatches[NTHREADS];

static void *worker(void *arg)
{
    size_t t = (size_t)(uintptr_t)arg;
    for (int k = 0; k < REPEAT; k++) {
        run(&parallel[t]);
        mismatches[t] += memcmp(&parallel[t], &serial, sizeof serial) != 0;
    }
    return NULL;
}

int main(void)
{
    static const double net[27] = {0, 0, 0, 1, 0, 1, 2, 0, 0, 0, 1, 1, 1, 1, 2, 2, 1, 1, 0, 2, 0, 1, 2, 1, 2, 2, 0};
    static const double w[9] = {1, 2, 1, 0.5, 1, 3, 1, 1, 2};
    CHECK_STATUS(bs_patch_create(2, 2, 3, net, w, &shared_patch), BS_OK);
    CHECK_STATUS(bs_surface_create_builtin("teapot", &shared_surface), BS_OK);
    unsigned long long rng = 4242;
    for (int k = 0; k < NPT; k++) {
        us[k] = k % 10 == 0 ? (double)(k % 20 == 0) : bs_test_rand(&rng, 0.0, 1.0);
        vs[k] = bs_test_rand(&rng, 0.0, 1.0);
        ids[k] = (uint32_t)(bs_test_rand_u64(&rng) % 32);
    }
    run(&serial);
    CHECKF(serial.failures == 0, "%d calls failed in the serial run", serial.failures);
    CHECK(serial.n_edges > 0 && serial.text_size > 1000);
    pthread_t th[NTHREADS];
    for (size_t t = 0; t < NTHREADS; t++)
        CHECK(pthread_create(&th[t], NULL, worker, (void *)(uintptr_t)t) == 0);
    for (size_t t = 0; t < NTHREADS; t++)
        CHECK(pthread_join(th[t], NULL) == 0);
    for (size_t t = 0; t < NTHREADS; t++)
        CHECKF(mismatches[t] == 0, "thread %zu: %d of %d runs differ from the serial run", t, mismatches[t], REPEAT);
    printf("%d threads x %d runs: every result bit-identical to the serial run\n", NTHREADS, REPEAT);
    bs_patch_destroy(shared_patch);
    bs_surface_destroy(shared_surface);
    return bs_test_exit("test_threads");
}
