/*
 * Tessellation of a surface into a welded, crack-free triangle mesh.
 *
 * Every patch has a segment count per direction (its rate). Each side is sampled at k/e, k = 0..e,
 * where e is the patch's own rate along the side, or for a shared side the larger of the two
 * patches' rates. Side samples are "slots": the four corners and the inner samples of each side.
 * Slots that are the same point are merged with a union-find: the samples of a shared side pairwise
 * (reversed when the link says so), every sample of a collapsed side (a pole) into one. Each merged
 * set becomes one vertex evaluated once, on the patch and parameters of its lowest slot, so both
 * sides of an edge reference the same vertex and no crack can open whatever the rounding of
 * k/e against 1 - k/e. A patch whose four sides are sampled at its own rates is triangulated as a
 * regular grid; otherwise an inner grid is stitched to the side samples by a zipper that walks both
 * rows by parameter (no T-junctions). Triangles with a repeated vertex (at poles) are dropped.
 *
 * Speed: a patch's interior points are one tensor grid, evaluated by bs_patch_eval_grid in blocks of
 * rows (bit-identical to the list evaluator, so the vertices are those a list would give); only the
 * side samples a patch owns go through bs_patch_eval_normal. Output arrays are sized from the
 * sampling before any triangle is emitted, and grid quads are emitted by plain loops over the
 * patch's table of vertex ids. A corner's (u,v) is stored only where it is not its vertex's (the
 * neighbour's side of a shared edge, poles), which halves the mesh.
 *
 * Bounds: the exact counts of the mesh are computed from the layout (memory O(patches)) and checked
 * against the 32-bit indices and the caller's budgets before the slots or any output array exist,
 * so an oversized request costs milliseconds, not gigabytes.
 *
 * The phases and their files are listed in lib/mesh/tess.h.
 */
#include "mesh/tess.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void bsi_tess_free(tess *t)
{
    bsi_topology_free(&t->topo);
    free(t->plan);
    free(t->parent);
    free(t->slot_vert);
    free(t->pos);
    free(t->nrm);
    free(t->uv);
    free(t->vpatch);
    free(t->kind);
    free(t->tri.v);
    free(t->tpatch.v);
    free(t->sidx.v);
    free(t->sstart.v);
    free(t->xc.corner);
    free(t->xc.uv);
    free(t->pu);
    free(t->pv);
    free(t->gid);
    for (size_t k = 0; t->work != NULL && k < t->nwork; k++) {
        if (t->work != &t->work1) { /* one thread's parameters are t->pu, t->pv */
            free(t->work[k].pu);
            free(t->work[k].pv);
        }
        free(t->work[k].soa);
    }
    if (t->work != &t->work1)
        free(t->work);
}

bs_status bsi_tess_check(const bs_surface *s, int flags)
{
    if (s == NULL || (flags & ~(BS_TESS_RELATIVE | BS_TESS_STRIPS | BS_TESS_REVERSE)) != 0)
        return BS_ERR_INVALID_ARG;
    if (bs_surface_count(s) > 0 && bs_surface_dim(s) != 3)
        return BS_ERR_DIMENSION;
    return BS_OK;
}

/* Over the budgets, or past what 32-bit vertex ids and index offsets can address. */
static int over_limits(const tess_counts *c, size_t max_vertices, size_t max_triangles)
{
    if (c->vertices > UINT32_MAX - 1 || c->triangles > UINT32_MAX / 3 || c->strip_indices > UINT32_MAX)
        return 1;
    return (max_vertices != 0 && c->vertices > max_vertices) ||
           (max_triangles != 0 && c->triangles > max_triangles);
}

bs_status bsi_tess_measure(tess *t, tess_counts *c)
{
    bs_status st = bsi_tess_layout(t);
    return st == BS_OK ? bsi_tess_count(t, c) : st;
}

/* Run the tessellation with the layout done, and hand the arrays to a new mesh. */
static bs_status run(tess *t, bs_mesh **out)
{
    bs_status st = bsi_tess_plan(t);
    if (st == BS_OK)
        st = bsi_tess_evaluate(t);
    if (st == BS_OK)
        st = bsi_tess_triangulate(t);
    if (st == BS_OK)
        st = bsi_tess_trim_corners(t);
    return bsi_tess_finish(t, st, out);
}

bs_status bsi_tess_finish(tess *t, bs_status st, bs_mesh **out)
{
    bs_mesh *m = NULL;
    if (st == BS_OK && t->strips)
        UPUT(t->sstart, (uint32_t)t->sidx.n);
    if (st == BS_OK && t->reverse)
        st = bsi_tess_reverse(t);
    if (st == BS_OK && (m = calloc(1, sizeof(*m))) == NULL)
        st = BS_ERR_NO_MEMORY;
    if (st != BS_OK) {
        bsi_tess_free(t);
        /* m is still NULL here: calloc is the last step that can fail */
        // cppcheck-suppress memleak
        return st;
    }
    bsi_tess_repair_normals(t);
    m->nvert = t->nvert;
    m->ntri = t->tri.n / 3;
    m->nstrip = t->strips ? t->sstart.n - 1 : 0;
    m->nstrip_idx = t->strips ? t->sidx.n : 0;
    m->pos = t->pos;
    m->nrm = t->nrm;
    m->uv = t->uv;
    m->vpatch = t->vpatch;
    m->tri = t->tri.v;
    m->tpatch = t->tpatch.v;
    m->nx = t->xc.n;
    m->xcorner = t->xc.corner;
    m->xuv = t->xc.uv;
    m->strip_idx = t->strips ? t->sidx.v : NULL;
    m->strip_start = t->strips ? t->sstart.v : NULL;
    if (!t->strips) {
        free(t->sidx.v);
        free(t->sstart.v);
    }
    t->pos = t->nrm = t->uv = NULL;
    t->vpatch = NULL;
    t->tri.v = t->tpatch.v = t->sidx.v = t->sstart.v = NULL;
    t->xc.corner = NULL;
    t->xc.uv = NULL;
    bsi_tess_free(t);
    *out = m;
    return BS_OK;
}

bs_status bsi_tess_build(tess *t, size_t max_vertices, size_t max_triangles, bs_mesh **out)
{
    tess_counts c;
    bs_status st = bsi_tess_measure(t, &c);
    if (st == BS_OK && over_limits(&c, max_vertices, max_triangles))
        st = BS_ERR_SIZE;
    if (st != BS_OK) {
        bsi_tess_free(t);
        return st;
    }
    return run(t, out);
}

static bs_status tess_init(tess *t, const bs_surface *s, int flags)
{
    memset(t, 0, sizeof(*t));
    t->s = s;
    t->np = bs_surface_count(s);
    t->strips = (flags & BS_TESS_STRIPS) != 0;
    t->reverse = (flags & BS_TESS_REVERSE) != 0;
    t->threads = 1;
    t->plan = calloc(t->np ? t->np : 1, sizeof(patch_plan));
    return t->plan ? BS_OK : BS_ERR_NO_MEMORY;
}

bs_status bsi_tess_start_uniform(tess *t, const bs_surface *s, int flags, size_t nu, size_t nv)
{
    if (nu == 0 || nv == 0 || nu > BS_TESS_MAX_RATE || nv > BS_TESS_MAX_RATE)
        return BS_ERR_DOMAIN;
    bs_status st = tess_init(t, s, flags);
    for (size_t p = 0; st == BS_OK && p < t->np; p++) {
        t->plan[p].ru = nu;
        t->plan[p].rv = nv;
    }
    return st;
}

double bsi_tess_absolute_tolerance(const bs_surface *s, double tolerance, int flags)
{
    if (!(flags & BS_TESS_RELATIVE))
        return tolerance;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        for (size_t k = 0; k < p->nctrl; k++)
            for (size_t c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], p->ctrl[3 * k + c]);
                hi[c] = fmax(hi[c], p->ctrl[3 * k + c]);
            }
    }
    /* halves: the extent of a net near DBL_MAX overflows (a tolerance of +Inf gave one segment
     * a side); the diagonal capped at DBL_MAX */
    double d = bs_surface_count(s)
                   ? fmin(DBL_MAX, 2.0 * hypot(hypot(0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1]),
                                               0.5 * hi[2] - 0.5 * lo[2]))
                   : 0.0;
    double tol = tolerance * d;
    return tol > 0.0 ? tol : tolerance; /* a surface that is a point: any rate meets it */
}

bs_status bsi_tess_start_adaptive(tess *t, const bs_surface *s, int flags, double tolerance)
{
    if (!(tolerance > 0.0) || !isfinite(tolerance))
        return BS_ERR_DOMAIN;
    double tol = bsi_tess_absolute_tolerance(s, tolerance, flags);
    bs_status st = tess_init(t, s, flags);
    for (size_t p = 0; st == BS_OK && p < t->np; p++)
        bsi_tess_adaptive_rates(bs_surface_get(s, p), tol, &t->plan[p].ru, &t->plan[p].rv);
    return st;
}

bs_status bs_surface_tessellate_uniform(const bs_surface *s, size_t nu, size_t nv, int flags, bs_mesh **out)
{
    if (out != NULL)
        *out = NULL;
    bs_status st = out == NULL ? BS_ERR_INVALID_ARG : bsi_tess_check(s, flags);
    tess t;
    if (st == BS_OK)
        st = bsi_tess_start_uniform(&t, s, flags, nu, nv);
    return st == BS_OK ? bsi_tess_build(&t, 0, 0, out) : st;
}

bs_status bs_surface_tessellate_adaptive(const bs_surface *s, double tolerance, int flags, bs_mesh **out)
{
    if (out != NULL)
        *out = NULL;
    bs_status st = out == NULL ? BS_ERR_INVALID_ARG : bsi_tess_check(s, flags);
    tess t;
    if (st == BS_OK)
        st = bsi_tess_start_adaptive(&t, s, flags, tolerance);
    return st == BS_OK ? bsi_tess_build(&t, 0, 0, out) : st;
}
