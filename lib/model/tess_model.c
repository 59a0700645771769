/*
 * Tessellation of a model: the entry points, and phase 3 (tess.h), the mesh. Vertices are the
 * edge phase's (model vertices and edge samples, shared by the faces on both sides) and then each
 * face's inner points; a vertex's (u, v), patch id and normal are those of the face it was made
 * on, and a triangle corner whose face or (u, v) differs keeps its own (u, v). Triangles wind
 * counter-clockwise seen from outside (the face's `reversed` applied); their patch id is the face.
 */
#include "mesh/build.h"
#include "model/tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Points closer than this, relative to the model's diagonal, are one mesh vertex: well above the
 * closeness of the edges of CAD files (about 1e-7 of the part), well below any tolerance asked. */
#define MERGE 1e-6

typedef struct counts {
    size_t nvert, ntri;
    size_t *inner0;  /* per face: the first vertex id of its inner points */
} counts;

static bs_status face_task(void *ctx, size_t item, size_t worker)
{
    (void)worker;
    return bsi_tm_face(ctx, item);
}

static void job_free(tm_job *j)
{
    if (j->face != NULL)
        for (size_t f = 0; f < j->m->nface; f++)
            bsi_tm_face_free(&j->face[f]);
    free(j->face);
    free(j->scale);
    bsi_tm_edges_free(&j->edges);
}

static bs_status check(const bs_model *m, const bs_tess_options *o)
{
    if (m == NULL || o == NULL || o->size < sizeof(bs_tess_options))
        return BS_ERR_INVALID_ARG;
    if ((o->flags & ~(BS_TESS_RELATIVE | BS_TESS_STRIPS | BS_TESS_REVERSE)) != 0)
        return BS_ERR_INVALID_ARG;
    if (o->method != BS_TESS_UNIFORM && o->method != BS_TESS_PER_PATCH && o->method != BS_TESS_SUBDIVIDE)
        return BS_ERR_INVALID_ARG;
    if (o->method == BS_TESS_UNIFORM || (o->flags & BS_TESS_STRIPS))
        return BS_ERR_UNSUPPORTED;
    if (!(o->tolerance > 0.0) || !isfinite(o->tolerance))
        return BS_ERR_DOMAIN;
    return BS_OK;
}

/* Phases 1 and 2, and the counts. */
static bs_status run(const bs_model *m, const bs_tess_options *o, tm_job *j, counts *c)
{
    memset(j, 0, sizeof *j);
    memset(c, 0, sizeof *c);
    j->m = m;
    double diag = bsi_model_diagonal(m);
    j->tol = (o->flags & BS_TESS_RELATIVE) ? o->tolerance * diag : o->tolerance;
    j->diag = diag;
    j->merge = MERGE * diag;
    j->max_points = o->max_vertices;
    j->face = calloc(m->nface ? m->nface : 1, sizeof(tm_face_mesh));
    c->inner0 = calloc(m->nface + 1, sizeof(size_t));
    if (j->face == NULL || c->inner0 == NULL)
        return BS_ERR_NO_MEMORY;
    if (m->nface == 0)
        return BS_OK; /* an empty mesh (its diagonal, and so a relative tolerance, is 0) */
    if (!(j->tol > 0.0) || !isfinite(j->tol))
        return BS_ERR_DOMAIN;
    bs_status st = bsi_tm_scales(j);
    if (st == BS_OK)
        st = bsi_tm_edges(j);
    if (st != BS_OK)
        return st;
    st = bsi_parallel(bsi_thread_count(o->threads, m->nface), m->nface, face_task, j);
    if (st != BS_OK)
        return st;
    c->nvert = j->edges.nvert;
    for (size_t f = 0; f < m->nface; f++) {
        c->inner0[f] = c->nvert;
        c->nvert += j->face[f].ninner;
        c->ntri += j->face[f].ntri;
    }
    c->inner0[m->nface] = c->nvert;
    if (c->nvert > UINT32_MAX - 1 || c->ntri > UINT32_MAX / 3)
        return BS_ERR_SIZE;
    if ((o->max_vertices && c->nvert > o->max_vertices) || (o->max_triangles && c->ntri > o->max_triangles))
        return BS_ERR_SIZE;
    return BS_OK;
}

/* The outward unit normal of face f at (u, v) into n: 1, or 0 where the surface has none. */
static int face_normal(const bs_model *m, size_t f, const double *uv, double *n)
{
    double p[3], pu[3], pv[3];
    if (!bsi_face_partials(m, f, uv[0], uv[1], p, pu, pv))
        return 0;
    bsi_cross3(pu, pv, n);
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double scale = sqrt((pu[0] * pu[0] + pu[1] * pu[1] + pu[2] * pu[2]) * (pv[0] * pv[0] + pv[1] * pv[1] + pv[2] * pv[2]));
    if (!(len > 1e-9 * scale) || !isfinite(len))
        return 0;
    double s = (m->faces[f].reversed ? -1.0 : 1.0) / len;
    for (int k = 0; k < 3; k++)
        n[k] *= s;
    return 1;
}

static void fill_vertices(const tm_job *j, const counts *c, bsi_mesh_parts *mp)
{
    const bs_model *m = j->m;
    for (size_t v = 0; v < j->edges.nvert; v++) {
        const tm_vertex *tv = &j->edges.vert[v];
        memcpy(mp->pos + 3 * v, tv->p, 3 * sizeof(double));
        mp->uv[2 * v] = tv->uv[0];
        mp->uv[2 * v + 1] = tv->uv[1];
        mp->vpatch[v] = tv->face;
    }
    for (size_t f = 0; f < m->nface; f++)
        for (size_t k = 0; k < j->face[f].ninner; k++) {
            size_t v = c->inner0[f] + k;
            const double *in = j->face[f].inner + 5 * k;
            memcpy(mp->pos + 3 * v, in + 2, 3 * sizeof(double));
            mp->uv[2 * v] = in[0];
            mp->uv[2 * v + 1] = in[1];
            mp->vpatch[v] = (uint32_t)f;
        }
}

/* The face's own unit normal at each vertex, or where it has none (poles) the triangles' around
 * the vertex. */
static void fill_normals(const tm_job *j, const counts *c, int reverse, bsi_mesh_parts *mp)
{
    const bs_model *m = j->m;
    /* normals: the face's own, or where it has none (poles) the triangles' around the vertex */
    memset(mp->nrm, 0, 3 * c->nvert * sizeof(double));
    for (size_t t = 0; t < mp->ntri; t++) {
        const uint32_t *id = mp->tri + 3 * t;
        const double *a = mp->pos + 3 * (size_t)id[0], *b = mp->pos + 3 * (size_t)id[1], *d = mp->pos + 3 * (size_t)id[2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]}, n[3];
        bsi_cross3(e1, e2, n);
        for (size_t k = 0; k < 3; k++)
            for (size_t q = 0; q < 3; q++)
                mp->nrm[3 * (size_t)id[k] + q] += n[q];
    }
    for (size_t v = 0; v < c->nvert; v++) {
        double *n = mp->nrm + 3 * v, own[3];
        if (face_normal(m, mp->vpatch[v], mp->uv + 2 * v, own)) {
            memcpy(n, own, sizeof own);
        } else {
            double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int k = 0; k < 3; k++)
                n[k] = len > 0.0 ? n[k] / len : (k == 2);
        }
        if (reverse)
            for (int k = 0; k < 3; k++)
                n[k] = -n[k];
    }
}

/* Triangles and the corners that keep their own (u, v). */
static bs_status fill_triangles(const tm_job *j, const counts *c, int reverse, bsi_mesh_parts *mp)
{
    const bs_model *m = j->m;
    size_t t = 0, nx = 0, xcap = 0;
    for (size_t f = 0; f < m->nface; f++) {
        const tm_face_mesh *fm = &j->face[f];
        int flip = (m->faces[f].reversed != 0) != (reverse != 0);
        for (size_t k = 0; k < fm->ntri; k++, t++) {
            static const int order[2][3] = {{0, 1, 2}, {0, 2, 1}};
            for (size_t q = 0; q < 3; q++) {
                size_t src = (size_t)order[flip][q];
                uint32_t id = fm->tri[3 * k + src];
                id = (id & TM_INNER) ? (uint32_t)(c->inner0[f] + (id & ~TM_INNER)) : id;
                mp->tri[3 * t + q] = id;
                const double *uv = fm->tuv + 6 * k + 2 * src;
                if (mp->vpatch[id] == f && mp->uv[2 * (size_t)id] == uv[0] && mp->uv[2 * (size_t)id + 1] == uv[1])
                    continue;
                if (nx == xcap) {
                    size_t ncap = xcap ? 2 * xcap : 1024;
                    size_t *xc = realloc(mp->xcorner, ncap * sizeof(size_t));
                    if (xc == NULL)
                        return BS_ERR_NO_MEMORY;
                    mp->xcorner = xc;
                    double *xu = realloc(mp->xuv, 2 * ncap * sizeof(double));
                    if (xu == NULL)
                        return BS_ERR_NO_MEMORY;
                    mp->xuv = xu;
                    xcap = ncap;
                }
                mp->xcorner[nx] = 3 * t + q;
                mp->xuv[2 * nx] = uv[0];
                mp->xuv[2 * nx + 1] = uv[1];
                nx++;
            }
            mp->tpatch[t] = (uint32_t)f;
        }
    }
    mp->nx = nx;
    return BS_OK;
}

bs_status bs_model_tessellate_count(const bs_model *m, const bs_tess_options *o, size_t *vertices,
                                    size_t *triangles)
{
    bs_status st = check(m, o);
    if (st != BS_OK)
        return st;
    tm_job j;
    counts c;
    st = run(m, o, &j, &c);
    if (st == BS_OK) {
        if (vertices != NULL)
            *vertices = c.nvert;
        if (triangles != NULL)
            *triangles = c.ntri;
    }
    free(c.inner0);
    job_free(&j);
    return st;
}

bs_status bs_model_tessellate(const bs_model *m, const bs_tess_options *o, bs_mesh **out)
{
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    *out = NULL;
    bs_status st = check(m, o);
    if (st != BS_OK)
        return st;
    tm_job j;
    counts c;
    bsi_mesh_parts mp;
    memset(&mp, 0, sizeof mp);
    st = run(m, o, &j, &c);
    if (st == BS_OK) {
        size_t nv = c.nvert ? c.nvert : 1, nt = c.ntri ? c.ntri : 1;
        mp.nvert = c.nvert;
        mp.ntri = c.ntri;
        mp.pos = malloc(3 * nv * sizeof(double));
        mp.nrm = malloc(3 * nv * sizeof(double));
        mp.uv = malloc(2 * nv * sizeof(double));
        mp.vpatch = malloc(nv * sizeof(uint32_t));
        mp.tri = malloc(3 * nt * sizeof(uint32_t));
        mp.tpatch = malloc(nt * sizeof(uint32_t));
        if (mp.pos == NULL || mp.nrm == NULL || mp.uv == NULL || mp.vpatch == NULL || mp.tri == NULL ||
            mp.tpatch == NULL)
            st = BS_ERR_NO_MEMORY;
    }
    int reverse = (o->flags & BS_TESS_REVERSE) != 0;
    if (st == BS_OK) {
        fill_vertices(&j, &c, &mp);
        st = fill_triangles(&j, &c, reverse, &mp);
    }
    if (st == BS_OK)
        fill_normals(&j, &c, reverse, &mp);
    free(c.inner0);
    job_free(&j);
    if (st != BS_OK) {
        bsi_mesh_parts_free(&mp);
        return st;
    }
    return bsi_mesh_adopt(&mp, out);
}
