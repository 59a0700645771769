/*
 * Tessellation by recursive subdivision (BS_TESS_SUBDIVIDE): the phases of mesh/subdiv.h run in
 * order, the counts known before any array of the mesh is allocated, then the vertices evaluated
 * patch by patch as lists and the leaves triangulated into the output the other methods finish.
 */
#include "mesh/subdiv.h"

#include <stdlib.h>
#include <string.h>

void bsi_subdiv_free(subdiv *s)
{
    bsi_topology_free(&s->topo);
    free(s->leaf);
    free(s->leaf0);
    free(s->uv);
    free(s->vu);
    free(s->vupos);
    free(s->corner);
    free(s->pt0);
    free(s->parent);
    free(s->vid);
    free(s->kind);
    free(s->vert0);
    free(s->cen0);
    memset(s, 0, sizeof(*s));
}

/* Trees, points, vertices and the triangle count. */
static bs_status prepare(subdiv *sd, const bs_surface *s, double tol, size_t max_tri, size_t max_vert)
{
    memset(sd, 0, sizeof(*sd));
    sd->s = s;
    sd->np = bs_surface_count(s);
    sd->tol = tol;
    sd->max_tri = max_tri;
    sd->max_vert = max_vert;
    bs_status st = bsi_topology_build(s, 1e-9 * bsi_tess_max_abs_coord(s), &sd->topo);
    if (st == BS_OK)
        st = bsi_subdiv_trees(sd);
    if (st == BS_OK)
        st = bsi_subdiv_weld(sd);
    if (st == BS_OK)
        st = bsi_subdiv_classify(sd);
    if (st == BS_OK)
        st = bsi_subdiv_emit(sd, NULL);
    return st;
}

bs_status bsi_tess_subdivide_count(const bs_surface *s, double tol, size_t max_vertices, size_t max_triangles,
                                   size_t *vertices, size_t *triangles)
{
    subdiv sd;
    bs_status st = prepare(&sd, s, tol, max_triangles, max_vertices);
    /* past a budget the trees stop growing: their lower bounds, already over it, are the answer */
    if (st == BS_ERR_SIZE && ((max_triangles && sd.tri_lower > max_triangles) ||
                              (max_vertices && sd.vert_lower > max_vertices))) {
        sd.nvert = sd.vert_lower;
        sd.ntri = sd.tri_lower;
        st = BS_OK;
    }
    if (st == BS_OK) {
        if (vertices)
            *vertices = sd.nvert;
        if (triangles)
            *triangles = sd.ntri;
    }
    bsi_subdiv_free(&sd);
    return st;
}

/* The mesh's arrays for sd's counts. */
static bs_status allocate(tess *t, const subdiv *sd)
{
    size_t nv = sd->nvert ? sd->nvert : 1, nt = sd->ntri ? sd->ntri : 1;
    t->nvert = sd->nvert;
    t->pos = malloc(3 * nv * sizeof(double));
    t->nrm = malloc(3 * nv * sizeof(double));
    t->uv = malloc(2 * nv * sizeof(double));
    t->vpatch = malloc(nv * sizeof(uint32_t));
    t->kind = malloc(nv);
    t->tri.v = malloc(3 * nt * sizeof(uint32_t));
    t->tpatch.v = malloc(nt * sizeof(uint32_t));
    t->xc.corner = malloc(3 * nt * sizeof(size_t));
    t->xc.uv = malloc(6 * nt * sizeof(double));
    if (!t->pos || !t->nrm || !t->uv || !t->vpatch || !t->kind || !t->tri.v || !t->tpatch.v || !t->xc.corner ||
        !t->xc.uv)
        return BS_ERR_NO_MEMORY;
    if (t->strips && ((t->sstart.v = malloc((nt + 1) * sizeof(uint32_t))) == NULL ||
                      (t->sidx.v = malloc(3 * nt * sizeof(uint32_t))) == NULL))
        return BS_ERR_NO_MEMORY;
    return BS_OK;
}

typedef struct sample_job { const tess *t; const subdiv *sd; size_t *nbad; } sample_job;

/* Patch p's own vertices: its points, then its leaf centres. */
static bs_status sample_patch(void *ctx, size_t p, size_t worker)
{
    sample_job *job = ctx;
    const subdiv *sd = job->sd;
    size_t *nbad = &job->nbad[worker];
    bs_status st = bsi_tess_eval_list(job->t, (uint32_t)p, sd->vert0[p], sd->vert0[p + 1] - sd->vert0[p], nbad);
    return st == BS_OK ? bsi_tess_eval_list(job->t, (uint32_t)p, sd->cen0[p], sd->cen0[p + 1] - sd->cen0[p], nbad)
                       : st;
}

/* (u,v) of every vertex, then positions and normals patch by patch, on up to `threads` threads. */
static bs_status evaluate(tess *t, const subdiv *sd, size_t threads)
{
    for (size_t k = 0; k < sd->pt0[sd->np]; k++) {
        if (sd->parent[k] != k)
            continue; /* evaluated as its root */
        uint64_t key = sd->uv[k];
        double *uv = t->uv + 2 * (size_t)sd->vid[k];
        uv[0] = (double)(key >> SD_BITS) / (double)SD_N;
        uv[1] = (double)(key & ((UINT64_C(1) << SD_BITS) - 1)) / (double)SD_N;
    }
    bsi_subdiv_centres(sd, t->uv);
    size_t workers = bsi_thread_count(threads, sd->np);
    sample_job job = {t, sd, calloc(workers, sizeof(size_t))};
    if (job.nbad == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status st = bsi_parallel(workers, sd->np, sample_patch, &job);
    for (size_t k = 0; k < workers; k++)
        t->nbad += job.nbad[k];
    free(job.nbad);
    return st;
}

bs_status bsi_tess_subdivide(const bs_surface *s, double tol, int flags, size_t max_vertices, size_t max_triangles,
                             size_t threads, bs_mesh **out)
{
    *out = NULL;
    subdiv sd;
    /* 32-bit indices: at most UINT32_MAX / 3 triangles, the limit when there is no budget */
    size_t max_tri = max_triangles && max_triangles < UINT32_MAX / 3 ? max_triangles : UINT32_MAX / 3;
    size_t max_vert = max_vertices && max_vertices < UINT32_MAX - 1 ? max_vertices : UINT32_MAX - 1;
    bs_status st = prepare(&sd, s, tol, max_tri, max_vert);
    if (st == BS_OK && (sd.nvert > max_vert || sd.ntri > max_tri))
        st = BS_ERR_SIZE;
    tess t;
    memset(&t, 0, sizeof(t));
    t.s = s;
    t.np = sd.np;
    t.strips = (flags & BS_TESS_STRIPS) != 0;
    t.reverse = (flags & BS_TESS_REVERSE) != 0;
    if (st == BS_OK)
        st = allocate(&t, &sd);
    if (st == BS_OK)
        st = evaluate(&t, &sd, threads);
    if (st == BS_OK)
        st = bsi_subdiv_emit(&sd, &t);
    if (st == BS_OK)
        st = bsi_tess_trim_corners(&t);
    bsi_subdiv_free(&sd);
    return bsi_tess_finish(&t, st, out);
}
