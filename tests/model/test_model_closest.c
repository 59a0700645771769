/* Closest points on the trimmed faces of models (bs_locator_closest_point on a model's locator):
 * - every file of every CAD part of data/cad/ against the 200 distances of its .ref
 *   (OpenCASCADE's BRepExtrema_DistShapeShape on the faces): ours never farther than the
 *   kernel's by more than its own tolerance (1e-7 D) and tau = 1e-9 (D + d);
 * - every answer a point of the model: on its face's surface at the reported native (u, v),
 *   inside its trims (classified within 1e-9 D), at the reported distance;
 * - against brute force: points of the faces (the vertices of the model's mesh, which include
 *   points along every trim, and a grid of each face's parameter box classified inside) are never
 *   nearer than the answer by more than tau, for the .ref points and for points above the trims
 *   (off mesh vertices on face boundaries, along the normal and across), where the surface's own
 *   minimum lies outside the face;
 * - the _mt variant gives the same bits.
 * Files: STEP and IGES 144 of each part (BS_TEST_FULL: all four; BS_TEST_QUICK: the block's and
 * the bell's STEP files). */
#include "harness.h"
#include "cad_model.h"

#include <bezsurf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GRID 48 /* samples per direction of each face's box */

typedef struct query {
    double q[3], ref; /* ref: the kernel's distance, NAN for our own points */
} query;

/* The closest-point queries of NAME.ref, their count; *diag the box's diagonal. */
static size_t read_ref(const char *part, query *qs, size_t cap, double *diag)
{
    char line[512];
    FILE *f = open_ref(part);
    if (f == NULL)
        return 0;
    size_t n = 0;
    while (fgets(line, sizeof line, f)) {
        query x;
        (void)ref_box_diagonal(line, diag);
        if (n < cap && sscanf(line, "closest %lf %lf %lf dist %lf", &x.q[0], &x.q[1], &x.q[2], &x.ref) == 4)
            qs[n++] = x;
    }
    fclose(f);
    return n;
}

/* Points of the model's faces: its mesh's vertices, and grid points of each face's box that
 * classify inside (evaluated on the face). *count of them, 3 doubles each. */
static double *face_samples(const bs_model *m, double diag, size_t *count)
{
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = 1e-3 * diag;
    bs_mesh *mesh = NULL;
    CHECK_STATUS(bs_model_tessellate(m, &o, &mesh), BS_OK);
    size_t nv = mesh ? bs_mesh_vertex_count(mesh) : 0, nf = bs_model_face_count(m);
    double *pts = malloc((nv + nf * GRID * GRID) * 3 * sizeof *pts);
    double *tmp = malloc(nv * 3 * sizeof *tmp + 1);
    CHECK(pts != NULL && tmp != NULL);
    if (pts == NULL || tmp == NULL) {
        free(pts), free(tmp), bs_mesh_destroy(mesh);
        *count = 0;
        return NULL;
    }
    bs_view xyz[3] = {{tmp, nv, 24}, {tmp + 1, nv, 24}, {tmp + 2, nv, 24}};
    if (mesh)
        CHECK_STATUS(bs_mesh_copy_positions(mesh, xyz), BS_OK);
    memcpy(pts, tmp, nv * 3 * sizeof *tmp);
    size_t n = nv;
    for (uint32_t f = 0; f < nf; f++) {
        bs_face_info info;
        info.size = sizeof info;
        CHECK_STATUS(bs_model_face_info(m, f, &info), BS_OK);
        double box[4] = {info.u0, info.u1, info.v0, info.v1};
        uint32_t faces[GRID * GRID];
        double u[GRID * GRID], v[GRID * GRID], p[3 * GRID * GRID];
        unsigned char where[GRID * GRID];
        for (size_t i = 0; i < GRID; i++)
            for (size_t j = 0; j < GRID; j++) {
                faces[i * GRID + j] = f;
                u[i * GRID + j] = box[0] + (box[1] - box[0]) * ((double)i + 0.5) / GRID;
                v[i * GRID + j] = box[2] + (box[3] - box[2]) * ((double)j + 0.5) / GRID;
            }
        bs_cview uc = {u, GRID * GRID, 0}, vc = {v, GRID * GRID, 0};
        CHECK_STATUS(bs_model_classify(m, GRID * GRID, faces, &uc, &vc, 0.0, where), BS_OK);
        bs_view pv[3] = {{p, GRID * GRID, 24}, {p + 1, GRID * GRID, 24}, {p + 2, GRID * GRID, 24}};
        CHECK_STATUS(bs_model_face_eval(m, GRID * GRID, faces, &uc, &vc, pv, NULL, NULL), BS_OK);
        for (size_t k = 0; k < GRID * GRID; k++)
            if (where[k] == BS_TRIM_INSIDE && isfinite(p[3 * k])) {
                memcpy(pts + 3 * n, p + 3 * k, 3 * sizeof *p);
                n++;
            }
    }
    free(tmp);
    bs_mesh_destroy(mesh);
    *count = n;
    return pts;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Queries above the trims: off mesh vertices that lie near a face's boundary (within 1e-4 D of a
 * trim), moved out along a fixed mix of directions by up to 5% of D; count appended to qs. */
static size_t trim_queries(const bs_model *m, double diag, query *qs, size_t cap)
{
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = 3e-3 * diag;
    bs_mesh *mesh = NULL;
    if (bs_model_tessellate(m, &o, &mesh) != BS_OK)
        return 0;
    size_t nv = bs_mesh_vertex_count(mesh), nt = bs_mesh_triangle_count(mesh), n = 0;
    double *x = malloc(nv * 3 * sizeof *x + 1), *uv = malloc(nv * 2 * sizeof *uv + 1);
    uint32_t *tri = malloc(nt * 3 * sizeof *tri + 1), *face = malloc(nt * sizeof *face + 1);
    unsigned char *done = calloc(nv + 1, 1);
    bs_view xyz[3] = {{x, nv, 24}, {x + 1, nv, 24}, {x + 2, nv, 24}}, uvv[2] = {{uv, nv, 16}, {uv + 1, nv, 16}};
    if (x && uv && tri && face && done && bs_mesh_copy_positions(mesh, xyz) == BS_OK &&
        bs_mesh_copy_uv(mesh, uvv) == BS_OK && bs_mesh_copy_triangles(mesh, tri, nt * 3) == BS_OK &&
        bs_mesh_copy_triangle_patch_ids(mesh, face, nt) == BS_OK) {
        unsigned seed = 12345u;
        for (size_t t = 0; t < nt && n < cap; t++)
            for (size_t c = 0; c < 3 && n < cap; c++) {
                uint32_t k = tri[3 * t + c];
                double u = uv[2 * k], v = uv[2 * k + 1];
                unsigned char where;
                bs_cview uc = {&u, 1, 0}, vc = {&v, 1, 0};
                if (done[k] || bs_model_classify(m, 1, &face[t], &uc, &vc, 1e-4 * diag, &where) != BS_OK ||
                    where != BS_TRIM_ON)
                    continue;
                done[k] = 1;
                double d[3];
                for (int i = 0; i < 3; i++) {
                    seed = seed * 1103515245u + 12345u;
                    d[i] = ((double)(seed >> 8) / 16777216.0 - 0.5) * 0.1 * diag;
                }
                for (size_t i = 0; i < 3; i++)
                    qs[n].q[i] = x[3 * k + i] + d[i];
                qs[n++].ref = NAN;
            }
    }
    free(x), free(uv), free(tri), free(face), free(done);
    bs_mesh_destroy(mesh);
    return n;
}

/* The checks of one file; every query of qs. */
static void check_file(const char *file, const query *qs, size_t n, double diag)
{
    bs_model *m = read_model(file);
    if (m == NULL)
        return;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_locator_create_model(m, &L), BS_OK);
    size_t ns = 0;
    double *samples = face_samples(m, diag, &ns);
    query *all = malloc((n + 400) * sizeof *all);
    double *q = malloc((n + 400) * 3 * sizeof *q), *out = malloc((n + 400) * 12 * sizeof *out);
    uint32_t *face = malloc((n + 400) * 2 * sizeof *face);
    if (L == NULL || samples == NULL || all == NULL || q == NULL || out == NULL || face == NULL) {
        CHECK(0);
        goto done;
    }
    memcpy(all, qs, n * sizeof *qs);
    size_t total = n + trim_queries(m, diag, all + n, 400);
    for (size_t k = 0; k < total; k++)
        memcpy(q + 3 * k, all[k].q, 3 * sizeof *q);
    bs_cview qv[3] = {{q, total, 24}, {q + 1, total, 24}, {q + 2, total, 24}};
    double *uv = out, *dist = out + 2 * total, *pos = out + 3 * total, *dist2 = out + 6 * total,
           *uv2 = out + 7 * total;
    bs_view uvv[2] = {{uv, total, 16}, {uv + 1, total, 16}}, dv = {dist, total, 0};
    bs_view pv[3] = {{pos, total, 24}, {pos + 1, total, 24}, {pos + 2, total, 24}};
    CHECK_STATUS(bs_locator_closest_point(L, total, qv, face, uvv, &dv, pv), BS_OK);
    size_t nearer = 0, bad_ref = 0, bad_brute = 0, off = 0;
    for (size_t k = 0; k < total; k++) {
        double tau = 1e-9 * (diag + dist[k]);
        if (!isnan(all[k].ref)) {
            bad_ref += !(dist[k] <= all[k].ref + 1e-7 * diag + tau);
            nearer += dist[k] < all[k].ref - 1e-7 * diag;
        }
        /* the answer is a point of its face, at the distance given */
        double p[3];
        unsigned char where = BS_TRIM_OUTSIDE;
        bs_cview uc = {&uv[2 * k], 1, 0}, vc = {&uv[2 * k + 1], 1, 0};
        bs_view ev[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
        if (face[k] < bs_model_face_count(m)) {
            (void)bs_model_face_eval(m, 1, &face[k], &uc, &vc, ev, NULL, NULL);
            (void)bs_model_classify(m, 1, &face[k], &uc, &vc, 1e-9 * diag, &where);
        }
        off += !(where != BS_TRIM_OUTSIDE && dist3(p, pos + 3 * k) <= 1e-9 * diag &&
                 fabs(dist3(q + 3 * k, pos + 3 * k) - dist[k]) <= 1e-12 * (diag + dist[k]));
        double least = INFINITY;
        for (size_t i = 0; i < ns; i++)
            least = fmin(least, dist3(q + 3 * k, samples + 3 * i));
        if (!(dist[k] <= least + tau)) {
            bad_brute++;
            if (bad_brute <= 3)
                printf("  %s query %zu (%.17g %.17g %.17g): %.17g, a sample at %.17g\n", file, k,
                       q[3 * k], q[3 * k + 1], q[3 * k + 2], dist[k], least);
        }
    }
    CHECKF(bad_ref == 0, "%s: %zu answers farther than the kernel's", file, bad_ref);
    CHECKF(bad_brute == 0, "%s: %zu answers farther than a point of a face", file, bad_brute);
    CHECKF(off == 0, "%s: %zu answers not on their face", file, off);
    /* the threaded variant: the same bits */
    bs_view dv2 = {dist2, total, 0}, uvv2[2] = {{uv2, total, 16}, {uv2 + 1, total, 16}};
    CHECK_STATUS(bs_locator_closest_point_mt(L, total, qv, face + total, uvv2, &dv2, NULL, 2), BS_OK);
    CHECKF(memcmp(dist, dist2, total * sizeof *dist) == 0 && memcmp(uv, uv2, 2 * total * sizeof *uv) == 0 &&
               memcmp(face, face + total, total * sizeof *face) == 0,
           "%s: threads differ", file);
    printf("%-22s %4zu queries (%zu above trims), %zu nearer than the kernel's, %zu samples\n", file,
           total, total - n, nearer, ns);
done:
    free(samples), free(all), free(q), free(out), free(face);
    bs_locator_destroy(L);
    bs_model_destroy(m);
}

/* Points whose foot on a face lies exactly on its trim: below the rim of the cone's base disc
 * (radius 4 at z = 0), the disc's own closest point is the rim, where its boxes stay crossed by
 * the trim; the answer is the rim point, 1 away (also at the seam and the patch breaks of the
 * cone's side, angles k 45 degrees). */
static void rim_queries(void)
{
    bs_model *m = read_model("cone.step");
    bs_locator *L = NULL;
    if (m == NULL || bs_locator_create_model(m, &L) != BS_OK) {
        CHECK(0);
        bs_model_destroy(m);
        return;
    }
    for (int k = 0; k < 16; k++) {
        double a = k * 0.39269908169872414, q[3] = {4.0 * cos(a), 4.0 * sin(a), -1.0};
        double dist = NAN, pos[3] = {NAN, NAN, NAN};
        bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
        bs_view dv = {&dist, 1, 0}, pv[3] = {{&pos[0], 1, 0}, {&pos[1], 1, 0}, {&pos[2], 1, 0}};
        CHECK_STATUS(bs_locator_closest_point(L, 1, qv, NULL, NULL, &dv, pv), BS_OK);
        double rim[3] = {q[0], q[1], 0.0}, tau = 1e-9 * (10.0 + 1.0);
        CHECKF(fabs(dist - 1.0) <= tau && dist3(pos, rim) <= 1e-7, "angle %d x 22.5: %.17g at %g %g %g",
               k, dist, pos[0], pos[1], pos[2]);
    }
    bs_locator_destroy(L);
    bs_model_destroy(m);
}

int main(void)
{
    rim_queries();
    static const char *parts[] = {"bottle", "block", "sphere", "torus", "cone", "wedge", "bell", "duct"};
    static const char *kinds[] = {".step", ".igs", "-brep.igs", "-3d-edges.step"};
    int full = getenv("BS_TEST_FULL") != NULL, quick = bs_test_quick();
    query qs[256];
    for (size_t p = 0; p < sizeof parts / sizeof *parts; p++) {
        if (quick && p != 1 && p != 6) /* the block and the bell: holes, fillets, a revolution */
            continue;
        double diag = 0.0;
        size_t n = read_ref(parts[p], qs, 256, &diag);
        CHECKF(n == 200, "%s: %zu queries", parts[p], n);
        for (size_t k = 0; k < (full ? 4u : quick ? 1u : 2u); k++) {
            char file[64];
            (void)snprintf(file, sizeof file, "%s%s", parts[p], kinds[k]);
            check_file(file, qs, n, diag);
        }
    }
    return bs_test_exit("test_model_closest");
}
