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
 * The phases and their files are listed in lib/mesh/tess.h.
 */
#include "mesh/tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void tess_free(tess *t)
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
    free(t->soa);
}

static bs_status check_surface(const bs_surface *s, int flags, bs_mesh **out)
{
    if (out != NULL)
        *out = NULL;
    if (s == NULL || out == NULL || (flags & ~(BS_TESS_RELATIVE | BS_TESS_STRIPS)) != 0)
        return BS_ERR_INVALID_ARG;
    if (bs_surface_count(s) > 0 && bs_surface_dim(s) != 3)
        return BS_ERR_DIMENSION;
    return BS_OK;
}

/* Run the tessellation with rates already in t->plan, and hand the arrays to a new mesh. */
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
    if (st == BS_OK && (m = calloc(1, sizeof(*m))) == NULL)
        st = BS_ERR_NO_MEMORY;
    if (st != BS_OK) {
        tess_free(t);
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
    tess_free(t);
    *out = m;
    return BS_OK;
}

static bs_status tess_init(tess *t, const bs_surface *s, int flags)
{
    memset(t, 0, sizeof(*t));
    t->s = s;
    t->np = bs_surface_count(s);
    t->strips = (flags & BS_TESS_STRIPS) != 0;
    t->plan = calloc(t->np ? t->np : 1, sizeof(patch_plan));
    return t->plan ? BS_OK : BS_ERR_NO_MEMORY;
}

bs_status bs_surface_tessellate_uniform(const bs_surface *s, size_t nu, size_t nv, int flags, bs_mesh **out)
{
    bs_status st = check_surface(s, flags, out);
    if (st != BS_OK)
        return st;
    if (nu == 0 || nv == 0 || nu > BS_TESS_MAX_RATE || nv > BS_TESS_MAX_RATE)
        return BS_ERR_DOMAIN;
    tess t;
    if ((st = tess_init(&t, s, flags)) != BS_OK)
        return st;
    for (size_t p = 0; p < t.np; p++) {
        t.plan[p].ru = nu;
        t.plan[p].rv = nv;
    }
    return run(&t, out);
}

bs_status bs_surface_tessellate_adaptive(const bs_surface *s, double tolerance, int flags, bs_mesh **out)
{
    bs_status st = check_surface(s, flags, out);
    if (st != BS_OK)
        return st;
    if (!(tolerance > 0.0) || !isfinite(tolerance))
        return BS_ERR_DOMAIN;
    double tol = tolerance;
    if (flags & BS_TESS_RELATIVE) {
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < bs_surface_count(s); i++) {
            const bs_patch *p = bs_surface_get(s, i);
            for (size_t k = 0; k < p->nctrl; k++)
                for (size_t c = 0; c < 3; c++) {
                    lo[c] = fmin(lo[c], p->ctrl[3 * k + c]);
                    hi[c] = fmax(hi[c], p->ctrl[3 * k + c]);
                }
        }
        double d = bs_surface_count(s) ? hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]) : 0.0;
        tol = tolerance * d;
        if (!(tol > 0.0))
            tol = tolerance; /* a surface that is a point: any rate meets it */
    }
    tess t;
    if ((st = tess_init(&t, s, flags)) != BS_OK)
        return st;
    for (size_t p = 0; p < t.np; p++) {
        bsi_tess_adaptive_rates(bs_surface_get(s, p), tol, &t.plan[p].ru, &t.plan[p].rv);
    }
    return run(&t, out);
}
