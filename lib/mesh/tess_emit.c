/*
 * Tessellation phase 4, and the corner-list trim of phase 5: triangles of each patch, a plain grid
 * where its sides are sampled at its own rates, else an inner grid zipped to the side samples.
 */
#include "mesh/tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Allocate room for exactly `need` elements (none when need is 0). */
static int reserve(void **v, size_t *cap, size_t need, size_t elem)
{
    if (need == 0)
        return 1;
    if (need > SIZE_MAX / elem)
        return 0;
    void *nv = malloc(need * elem);
    if (nv == NULL)
        return 0;
    *v = nv;
    *cap = need;
    return 1;
}

/* Vertex id and parameters of grid point (i,j) of patch p, 0 <= i <= gu, 0 <= j <= gv. On the
 * border of a regular patch the point is a side sample; inside it is an interior point. */
static uint32_t grid_vertex(const tess *t, const patch_plan *pl, size_t i, size_t j)
{
    if (j == 0)
        return t->slot_vert[uf_find(t->parent, side_slot(pl, BSI_SIDE_V0, i))];
    if (j == pl->gv)
        return t->slot_vert[uf_find(t->parent, side_slot(pl, BSI_SIDE_V1, i))];
    if (i == 0)
        return t->slot_vert[uf_find(t->parent, side_slot(pl, BSI_SIDE_U0, j))];
    if (i == pl->gu)
        return t->slot_vert[uf_find(t->parent, side_slot(pl, BSI_SIDE_U1, j))];
    return (uint32_t)(pl->inner0 + (i - 1) * (pl->gv - 1) + (j - 1));
}

typedef bsi_corner corner;

static corner grid_corner(const tess *t, const patch_plan *pl, size_t i, size_t j)
{
    corner c = {grid_vertex(t, pl, i, j), grid_param(i, pl->gu), grid_param(j, pl->gv)};
    return c;
}

static corner side_corner(const tess *t, const patch_plan *pl, int s, size_t k)
{
    corner c;
    c.id = t->slot_vert[uf_find(t->parent, side_slot(pl, s, k))];
    side_param(pl, s, k, &c.u, &c.v);
    return c;
}

/* Same value and sign: the same bits for the finite numbers parameters are. */
static int same_param(double a, double b) { return a == b && !signbit(a) == !signbit(b); }

/* Corner k (3 * triangle + corner) is c: listed when its (u,v) differs from its vertex's, so that
 * the corners rebuilt from the mesh are exactly those emitted. */
static void note_corner(tess *t, size_t k, corner c)
{
    const double *vuv = t->uv + 2 * (size_t)c.id;
    if (same_param(vuv[0], c.u) && same_param(vuv[1], c.v))
        return;
    xbuf *x = &t->xc;
    x->corner[x->n] = k;
    x->uv[2 * x->n] = c.u;
    x->uv[2 * x->n + 1] = c.v;
    x->n++;
}

/* Append triangle a b c (into reserved room) unless a pole makes it degenerate; 1 if appended. */
static int emit_plain(tess *t, uint32_t patch, corner a, corner b, corner c)
{
    if (a.id == b.id || b.id == c.id || a.id == c.id)
        return 0;
    size_t k = t->tri.n;
    UPUT(t->tri, a.id);
    UPUT(t->tri, b.id);
    UPUT(t->tri, c.id);
    UPUT(t->tpatch, patch);
    note_corner(t, k, a);
    note_corner(t, k + 1, b);
    note_corner(t, k + 2, c);
    return 1;
}

void bsi_tess_emit(tess *t, uint32_t patch, corner a, corner b, corner c, int orient)
{
    if (orient) {
        double area = (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
        if (area < 0.0) {
            corner x = b;
            b = c;
            c = x;
        }
    }
    if (!emit_plain(t, patch, a, b, c) || !t->strips)
        return;
    UPUT(t->sstart, (uint32_t)t->sidx.n);
    UPUT(t->sidx, a.id);
    UPUT(t->sidx, b.id);
    UPUT(t->sidx, c.id);
}

/* Vertex ids of the patch's grid points into t->gid ((gu+1) x (gv+1), row i = u index): the
 * interior always, the border too when the patch is regular (its border points are side samples). */
static void grid_ids(tess *t, const patch_plan *pl)
{
    size_t w = pl->gv + 1;
    uint32_t *g = t->gid;
    for (size_t i = 1; i < pl->gu; i++) {
        uint32_t first = (uint32_t)(pl->inner0 + (i - 1) * (pl->gv - 1));
        for (size_t j = 1; j < pl->gv; j++)
            g[i * w + j] = first + (uint32_t)(j - 1);
    }
    if (!pl->regular)
        return;
    for (size_t i = 0; i <= pl->gu; i++) {
        g[i * w] = grid_vertex(t, pl, i, 0);
        g[i * w + pl->gv] = grid_vertex(t, pl, i, pl->gv);
    }
    for (size_t j = 1; j < pl->gv; j++) {
        g[j] = grid_vertex(t, pl, 0, j);
        g[pl->gu * w + j] = grid_vertex(t, pl, pl->gu, j);
    }
}

/* A grid quad with a corner on the grid's border: its triangles (a b d, d b c) unless a pole
 * makes them degenerate, and the corners whose (u,v) is not their vertex's. */
static void border_quad(tess *t, uint32_t patch, const uint32_t *r0, const uint32_t *r1, size_t j,
                        double u0, double u1, double v0, double v1)
{
    corner a = {r0[j], u0, v0}, b = {r1[j], u1, v0}, c = {r1[j + 1], u1, v1}, d = {r0[j + 1], u0, v1};
    emit_plain(t, patch, a, b, d);
    emit_plain(t, patch, d, b, c);
}

/* Quads of grid rows i0..i1-1 and columns j0..j1-1 as two triangles each (a b d, d b c with
 * a = (i,j), b = (i+1,j), c = (i+1,j+1), d = (i,j+1)), and one strip per row; t->gid holds the
 * ids and t->pu, t->pv the parameters. Only quads touching the grid's border can have a repeated
 * vertex (a pole): interior ids are unique, so the degeneracy tests are made there only. */
static void emit_grid(tess *t, uint32_t patch, const patch_plan *pl, size_t i0, size_t i1, size_t j0, size_t j1)
{
    size_t w = pl->gv + 1;
    const double *pu = t->pu, *pv = t->pv;
    for (size_t i = i0; i < i1; i++) {
        const uint32_t *r0 = t->gid + i * w, *r1 = r0 + w;
        if (t->strips && j1 > j0) {
            UPUT(t->sstart, (uint32_t)t->sidx.n);
            uint32_t *o = t->sidx.v + t->sidx.n;
            for (size_t j = j0; j <= j1; j++) {
                *o++ = r0[j];
                *o++ = r1[j];
            }
            t->sidx.n += 2 * (j1 - j0 + 1);
        }
        double u0 = pu[i], u1 = pu[i + 1];
        /* columns [ja, jb) have no border corner in this row */
        int border_row = i == 0 || i + 1 == pl->gu;
        size_t ja = border_row ? j1 : (j0 == 0 ? 1 : j0), jb = border_row ? j1 : (j1 == pl->gv ? j1 - 1 : j1);
        if (ja > jb)
            ja = jb;
        for (size_t j = j0; j < ja; j++)
            border_quad(t, patch, r0, r1, j, u0, u1, pv[j], pv[j + 1]);
        /* Interior quads: two triangles each, corners at interior grid points of this patch,
         * whose vertices carry these very (u,v), so no corner is listed. */
        uint32_t *tri = t->tri.v + t->tri.n, *tp = t->tpatch.v + t->tpatch.n;
        for (size_t j = ja; j < jb; j++) {
            uint32_t a = r0[j], b = r1[j], c = r1[j + 1], d = r0[j + 1];
            tri[0] = a, tri[1] = b, tri[2] = d;
            tri[3] = d, tri[4] = b, tri[5] = c;
            tri += 6;
            tp[0] = tp[1] = patch;
            tp += 2;
        }
        t->tri.n = (size_t)(tri - t->tri.v);
        t->tpatch.n = (size_t)(tp - t->tpatch.v);
        for (size_t j = jb; j < j1; j++)
            border_quad(t, patch, r0, r1, j, u0, u1, pv[j], pv[j + 1]);
    }
}

/* Stitch side s's samples to the adjacent row of the inner grid. */
static void emit_ring_side(tess *t, uint32_t patch, const patch_plan *pl, int s)
{
    size_t e = pl->e[s];
    int along_u = (s == BSI_SIDE_V0 || s == BSI_SIDE_V1);
    size_t nin = (along_u ? pl->gu : pl->gv) - 1; /* inner points: 1 .. g-1 */
    size_t i = 0, j = 0;
    while (i < e || j + 1 < nin) {
        corner o0 = side_corner(t, pl, s, i);
        size_t gi, gj;
        switch (s) {
        case BSI_SIDE_V0: gi = j + 1; gj = 1; break;
        case BSI_SIDE_U1: gi = pl->gu - 1; gj = j + 1; break;
        case BSI_SIDE_V1: gi = j + 1; gj = pl->gv - 1; break;
        default:          gi = 1; gj = j + 1; break;
        }
        corner in0 = grid_corner(t, pl, gi, gj);
        int outer;
        if (j + 1 >= nin)
            outer = 1;
        else if (i >= e)
            outer = 0;
        else {
            corner o1 = side_corner(t, pl, s, i + 1);
            double mo = along_u ? o0.u + o1.u : o0.v + o1.v;
            double mi = along_u ? 2.0 * in0.u + 1.0 / (double)pl->gu : 2.0 * in0.v + 1.0 / (double)pl->gv;
            outer = mo <= mi;
        }
        if (outer) {
            bsi_tess_emit(t, patch, o0, side_corner(t, pl, s, i + 1), in0, 1);
            i++;
        } else {
            corner in1 = along_u ? grid_corner(t, pl, gi + 1, gj) : grid_corner(t, pl, gi, gj + 1);
            bsi_tess_emit(t, patch, o0, in0, in1, 1);
            j++;
        }
    }
}

/* Room for the triangles, strips and strip indices patch pl can emit (poles drop some). */
static void patch_room(const patch_plan *pl, size_t *pt, size_t *ps, size_t *pi)
{
    size_t gu = pl->gu, gv = pl->gv; /* at most BS_TESS_MAX_RATE: no overflow per patch */
    if (pl->regular) {
        *pt = 2 * gu * gv;
        *ps = gu;
        *pi = 2 * gu * (gv + 1);
    } else {
        size_t ring = pl->e[0] + pl->e[1] + pl->e[2] + pl->e[3] + 2 * (gu - 2) + 2 * (gv - 2);
        *pt = 2 * (gu - 2) * (gv - 2) + ring;
        *ps = (gu - 2) + ring;
        *pi = 2 * (gu - 2) * (gv - 1) + 3 * ring;
    }
}

/* Room for every triangle, strip and index the patches can emit. */
static bs_status reserve_output(tess *t)
{
    size_t ntri = 0, nstrip = 1, nsidx = 0, gids = 1, uv_cap = 0;
    for (size_t p = 0; p < t->np; p++) {
        const patch_plan *pl = &t->plan[p];
        size_t gu = pl->gu, gv = pl->gv, pt, ps, pi;
        patch_room(pl, &pt, &ps, &pi);
        if (pt > SIZE_MAX - ntri || ps > SIZE_MAX - nstrip || pi > SIZE_MAX - nsidx)
            return BS_ERR_NO_MEMORY;
        ntri += pt;
        nstrip += ps;
        nsidx += pi;
        gids = (gu + 1) * (gv + 1) > gids ? (gu + 1) * (gv + 1) : gids;
    }
    if (ntri > SIZE_MAX / 6)
        return BS_ERR_NO_MEMORY;
    t->gid = calloc(gids, sizeof(uint32_t)); /* entries an irregular patch leaves unset are never read */
    if (t->gid == NULL || !reserve((void **)&t->tri.v, &t->tri.cap, 3 * ntri, sizeof(uint32_t)) ||
        !reserve((void **)&t->tpatch.v, &t->tpatch.cap, ntri, sizeof(uint32_t)) ||
        !reserve((void **)&t->xc.corner, &t->xc.cap, 3 * ntri, sizeof(size_t)) ||
        !reserve((void **)&t->xc.uv, &uv_cap, 6 * ntri, sizeof(double)))
        return BS_ERR_NO_MEMORY;
    if (t->strips && (!reserve((void **)&t->sstart.v, &t->sstart.cap, nstrip, sizeof(uint32_t)) ||
                      !reserve((void **)&t->sidx.v, &t->sidx.cap, nsidx, sizeof(uint32_t))))
        return BS_ERR_NO_MEMORY;
    return BS_OK;
}

/* Every triangle of patch p, appended to t's arrays; t->pu, t->pv and t->gid are its scratch. */
static void emit_patch(tess *t, size_t p)
{
    const patch_plan *pl = &t->plan[p];
    uint32_t id = (uint32_t)p;
    grid_params(t->pu, pl->gu);
    grid_params(t->pv, pl->gv);
    grid_ids(t, pl);
    if (pl->regular) {
        emit_grid(t, id, pl, 0, pl->gu, 0, pl->gv);
    } else {
        emit_grid(t, id, pl, 1, pl->gu - 1, 1, pl->gv - 1);
        for (int s = 0; s < 4; s++)
            emit_ring_side(t, id, pl, s);
    }
}

bs_status bsi_tess_triangulate(tess *t)
{
    bs_status st = reserve_output(t);
    if (st != BS_OK)
        return st;
    size_t workers = bsi_thread_count(t->threads, t->np);
    if (workers > 1) {
        st = bsi_tess_emit_parallel(t, workers);
    } else {
        for (size_t p = 0; p < t->np; p++)
            emit_patch(t, p);
    }
    if (st == BS_OK && (t->tri.n > UINT32_MAX || t->sidx.n > UINT32_MAX))
        return BS_ERR_SIZE;
    return st;
}

/* ---- The same emission on several threads ----
 * Each patch emits into its own room (patch_room, at offsets summed in patch order) through a copy
 * of t whose arrays start there, with scratch of its worker; then the patches' parts are moved
 * down in patch order, their strip starts and corner numbers shifted to the final offsets. So the
 * arrays are those the loop above fills, bit for bit. */

typedef struct emit_part { size_t tri, strip, sidx, ntri, nstrip, nsidx, nx; } emit_part;
typedef struct emit_job { const tess *t; tess *scratch; emit_part *part; } emit_job;

static bs_status emit_task(void *ctx, size_t p, size_t worker)
{
    emit_job *job = ctx;
    const tess *t = job->t;
    emit_part *e = &job->part[p];
    tess local = *t, *w = &job->scratch[worker];
    local.pu = w->pu;
    local.pv = w->pv;
    local.gid = w->gid;
    local.tri = (ubuf){t->tri.v + 3 * e->tri, 0, 0};
    local.tpatch = (ubuf){t->tpatch.v + e->tri, 0, 0};
    local.xc = (xbuf){t->xc.corner + 3 * e->tri, t->xc.uv + 6 * e->tri, 0, 0};
    if (t->strips) {
        local.sstart = (ubuf){t->sstart.v + e->strip, 0, 0};
        local.sidx = (ubuf){t->sidx.v + e->sidx, 0, 0};
    }
    emit_patch(&local, p);
    e->ntri = local.tpatch.n;
    e->nstrip = local.sstart.n;
    e->nsidx = local.sidx.n;
    e->nx = local.xc.n;
    return BS_OK;
}

/* Move part e of the arrays down to the ends of t's arrays, shifting its offsets. */
static void append_part(tess *t, const emit_part *e)
{
    memmove(t->tri.v + t->tri.n, t->tri.v + 3 * e->tri, 3 * e->ntri * sizeof(uint32_t));
    memmove(t->tpatch.v + t->tpatch.n, t->tpatch.v + e->tri, e->ntri * sizeof(uint32_t));
    for (size_t k = 0; k < e->nx; k++) {
        t->xc.corner[t->xc.n + k] = t->xc.corner[3 * e->tri + k] + t->tri.n;
        memmove(t->xc.uv + 2 * (t->xc.n + k), t->xc.uv + 6 * e->tri + 2 * k, 2 * sizeof(double));
    }
    if (t->strips) {
        memmove(t->sidx.v + t->sidx.n, t->sidx.v + e->sidx, e->nsidx * sizeof(uint32_t));
        for (size_t k = 0; k < e->nstrip; k++)
            t->sstart.v[t->sstart.n + k] = t->sstart.v[e->strip + k] + (uint32_t)t->sidx.n;
    }
    t->tri.n += 3 * e->ntri;
    t->tpatch.n += e->ntri;
    t->xc.n += e->nx;
    t->sidx.n += e->nsidx;
    t->sstart.n += e->nstrip;
}

bs_status bsi_tess_emit_parallel(tess *t, size_t workers)
{
    /* find without compressing paths: the threads only read parent */
    for (size_t k = 0; k < t->nslot; k++)
        t->parent[k] = uf_find(t->parent, k);
    emit_part *part = calloc(t->np, sizeof(emit_part));
    tess *scratch = calloc(workers, sizeof(tess));
    size_t gmax = 1, gids = 1, tri = 0, strip = 0, sidx = 0;
    for (size_t p = 0; part != NULL && p < t->np; p++) {
        const patch_plan *pl = &t->plan[p];
        size_t pt, ps, pi;
        patch_room(pl, &pt, &ps, &pi);
        part[p] = (emit_part){tri, strip, sidx, 0, 0, 0, 0};
        tri += pt;
        strip += ps;
        sidx += pi;
        gmax = pl->gu > gmax ? pl->gu : gmax;
        gmax = pl->gv > gmax ? pl->gv : gmax;
        gids = (pl->gu + 1) * (pl->gv + 1) > gids ? (pl->gu + 1) * (pl->gv + 1) : gids;
    }
    bs_status st = part && scratch ? BS_OK : BS_ERR_NO_MEMORY;
    for (size_t k = 0; st == BS_OK && k < workers; k++) {
        scratch[k].pu = malloc((gmax + 1) * sizeof(double));
        scratch[k].pv = malloc((gmax + 1) * sizeof(double));
        scratch[k].gid = calloc(gids, sizeof(uint32_t));
        if (!scratch[k].pu || !scratch[k].pv || !scratch[k].gid)
            st = BS_ERR_NO_MEMORY;
    }
    emit_job job = {t, scratch, part};
    if (st == BS_OK)
        st = bsi_parallel(workers, t->np, emit_task, &job);
    for (size_t p = 0; st == BS_OK && p < t->np; p++)
        append_part(t, &part[p]);
    for (size_t k = 0; scratch != NULL && k < workers; k++) {
        free(scratch[k].pu);
        free(scratch[k].pv);
        free(scratch[k].gid);
    }
    free(scratch);
    free(part);
    return st;
}

/* The corner list had room for every corner; keep only the few used (the mesh lives long). */
bs_status bsi_tess_trim_corners(tess *t)
{
    xbuf *x = &t->xc, small = {NULL, NULL, x->n, x->n};
    if (x->n > 0) {
        small.corner = malloc(x->n * sizeof(size_t));
        small.uv = malloc(2 * x->n * sizeof(double));
        if (small.corner == NULL || small.uv == NULL) {
            free(small.corner);
            free(small.uv);
            return BS_ERR_NO_MEMORY;
        }
        memcpy(small.corner, x->corner, x->n * sizeof(size_t));
        memcpy(small.uv, x->uv, 2 * x->n * sizeof(double));
    }
    free(x->corner);
    free(x->uv);
    *x = small;
    return BS_OK;
}
