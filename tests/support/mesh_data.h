/* Every array of a mesh read through the public accessors, for tests that compare or check them,
 * and the surfaces the mesh tests share. */
#ifndef BS_TEST_MESH_DATA_H
#define BS_TEST_MESH_DATA_H

#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct mesh_data {
    size_t nv, nt, ns, nsi;
    double *pos, *nrm, *uv, *cuv;
    uint32_t *tri, *tpatch, *vpatch, *sidx, *sstart;
} mesh_data;

static void *xmalloc(size_t n) { return malloc(n ? n : 1); }

static void read_mesh(const bs_mesh *m, mesh_data *d)
{
    d->nv = bs_mesh_vertex_count(m);
    d->nt = bs_mesh_triangle_count(m);
    d->ns = bs_mesh_strip_count(m);
    d->nsi = bs_mesh_strip_index_count(m);
    d->pos = xmalloc(3 * d->nv * sizeof(double));
    d->nrm = xmalloc(3 * d->nv * sizeof(double));
    d->uv = xmalloc(2 * d->nv * sizeof(double));
    d->cuv = xmalloc(6 * d->nt * sizeof(double));
    d->tri = xmalloc(3 * d->nt * sizeof(uint32_t));
    d->tpatch = xmalloc(d->nt * sizeof(uint32_t));
    d->vpatch = xmalloc(d->nv * sizeof(uint32_t));
    d->sidx = xmalloc(d->nsi * sizeof(uint32_t));
    d->sstart = xmalloc((d->ns + 1) * sizeof(uint32_t));
    ptrdiff_t s3 = 3 * sizeof(double), s2 = 2 * sizeof(double);
    bs_view p[3] = {{d->pos, d->nv, s3}, {d->pos + 1, d->nv, s3}, {d->pos + 2, d->nv, s3}};
    bs_view n[3] = {{d->nrm, d->nv, s3}, {d->nrm + 1, d->nv, s3}, {d->nrm + 2, d->nv, s3}};
    bs_view uv[2] = {{d->uv, d->nv, s2}, {d->uv + 1, d->nv, s2}};
    bs_view cuv[2] = {{d->cuv, 3 * d->nt, s2}, {d->cuv + 1, 3 * d->nt, s2}};
    CHECK_STATUS(bs_mesh_copy_positions(m, p), BS_OK);
    CHECK_STATUS(bs_mesh_copy_normals(m, n), BS_OK);
    CHECK_STATUS(bs_mesh_copy_uv(m, uv), BS_OK);
    CHECK_STATUS(bs_mesh_copy_corner_uv(m, cuv), BS_OK);
    CHECK_STATUS(bs_mesh_copy_triangles(m, d->tri, 3 * d->nt), BS_OK);
    CHECK_STATUS(bs_mesh_copy_triangle_patch_ids(m, d->tpatch, d->nt), BS_OK);
    CHECK_STATUS(bs_mesh_copy_patch_ids(m, d->vpatch, d->nv), BS_OK);
    CHECK_STATUS(bs_mesh_copy_strips(m, d->sidx, d->nsi, d->sstart, d->ns + 1), BS_OK);
}

static void free_mesh(mesh_data *d)
{
    free(d->pos); free(d->nrm); free(d->uv); free(d->cuv); free(d->tri);
    free(d->tpatch); free(d->vpatch); free(d->sidx); free(d->sstart);
}

static inline int same_bytes(const void *a, const void *b, size_t n) { return n == 0 || memcmp(a, b, n) == 0; }

/* Every array of both meshes equal, bit for bit. */
static inline int same_mesh(const bs_mesh *ma, const bs_mesh *mb)
{
    mesh_data a, b;
    read_mesh(ma, &a);
    read_mesh(mb, &b);
    int same = a.nv == b.nv && a.nt == b.nt && a.ns == b.ns && a.nsi == b.nsi;
    if (same)
        same = same_bytes(a.pos, b.pos, 3 * a.nv * sizeof(double)) &&
               same_bytes(a.nrm, b.nrm, 3 * a.nv * sizeof(double)) &&
               same_bytes(a.uv, b.uv, 2 * a.nv * sizeof(double)) &&
               same_bytes(a.cuv, b.cuv, 6 * a.nt * sizeof(double)) &&
               same_bytes(a.tri, b.tri, 3 * a.nt * sizeof(uint32_t)) &&
               same_bytes(a.tpatch, b.tpatch, a.nt * sizeof(uint32_t)) &&
               same_bytes(a.vpatch, b.vpatch, a.nv * sizeof(uint32_t)) &&
               same_bytes(a.sidx, b.sidx, a.nsi * sizeof(uint32_t)) &&
               same_bytes(a.sstart, b.sstart, (a.ns + 1) * sizeof(uint32_t));
    free_mesh(&a);
    free_mesh(&b);
    return same;
}

/* Append a 3-D patch of degrees (m, n) made from net (and weights w, or NULL) to s. */
static void add_patch(bs_surface *s, size_t m, size_t n, const double *net, const double *w)
{
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(m, n, 3, net, w, &p), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    bs_patch_destroy(p);
}

/* Grids of bicubic patches over cells of the plane, lifted by z = a(x) * sin(3x) cos(2y) with a
 * steepness a growing along x (so adaptive rates differ between neighbours), each cell's parameters
 * flipped and swapped at random. */
static inline bs_surface *bumpy_grid(int rows, int cols, unsigned long long seed)
{
    bs_surface *s = NULL;
    bs_surface_create(&s);
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            unsigned t = (unsigned)(bs_test_rand_u64(&seed) & 7u);
            double net[48];
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++) {
                    int a = (t & 4) ? j : i, b = (t & 4) ? i : j;
                    if (t & 1) a = 3 - a;
                    if (t & 2) b = 3 - b;
                    double x = c + a / 3.0, y = r + b / 3.0;
                    double *p = net + (i * 4 + j) * 3;
                    p[0] = x;
                    p[1] = y;
                    p[2] = 0.2 * x * x * sin(3 * x) * cos(2 * y);
                }
            add_patch(s, 3, 3, net, NULL);
        }
    return s;
}

#endif
