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
 */
#include "internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Output arrays, sized once before emission and filled without checks. */
typedef struct ubuf { uint32_t *v; size_t n, cap; } ubuf;
/* Triangle corners whose (u,v) on the triangle's patch is not their vertex's (struct bs_mesh). */
typedef struct xbuf { size_t *corner; double *uv; size_t n, cap; } xbuf;

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

/* Appends into reserved room. */
#define UPUT(b, x) ((b).v[(b).n++] = (x))

/* Per-patch sampling. */
typedef struct patch_plan {
    size_t ru, rv;      /* own rates */
    size_t e[4];        /* segments per side */
    size_t gu, gv;      /* grid used for the interior */
    int regular;        /* sides sampled at the own rates: plain grid */
    size_t slot0;       /* first slot: corners 0..3, then inner samples of sides 0..3 */
    size_t side_off[4]; /* offset of side s's inner samples from slot0 */
    size_t vert0;       /* first vertex id of this patch: its root slots, then the interior */
    size_t inner0;      /* first vertex id of the interior grid points */
} patch_plan;

typedef struct tess {
    const bs_surface *s;
    size_t np;
    bsi_topology topo;
    patch_plan *plan;
    size_t nslot;
    size_t *parent;     /* union-find over slots; the root of a set is its lowest slot */
    uint32_t *slot_vert;
    int strips;
    /* output */
    size_t nvert;
    double *pos, *nrm, *uv;
    uint32_t *vpatch;
    unsigned char *kind;
    ubuf tri, tpatch, sidx, sstart;
    xbuf xc;
    /* scratch: grid parameters i/g per direction, vertex ids of one patch's grid points */
    double *pu, *pv;
    uint32_t *gid;
    size_t nbad; /* vertices whose normal repair_normals must replace */
    double *soa; /* 6 x GRID_CHUNK: positions and normals of a block of grid rows, by coordinate */
} tess;

/* Grid points evaluated per call into packed scratch (the evaluator writes packed arrays in
 * place; the mesh's packed triples are filled from them). */
#define GRID_CHUNK ((size_t)4096)

static const int side_from[4] = {0, 1, 3, 0}; /* start corner of each side (0:c00 1:c10 2:c11 3:c01) */
static const int side_to[4] = {1, 2, 2, 3};

static size_t uf_find(size_t *parent, size_t x)
{
    size_t r = x;
    while (parent[r] != r)
        r = parent[r];
    while (parent[x] != r) {
        size_t nx = parent[x];
        parent[x] = r;
        x = nx;
    }
    return r;
}

static void uf_union(size_t *parent, size_t a, size_t b)
{
    a = uf_find(parent, a);
    b = uf_find(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

/* Slot of sample k (0..e) of side s of patch p. */
static size_t side_slot(const patch_plan *pl, int s, size_t k)
{
    if (k == 0)
        return pl->slot0 + (size_t)side_from[s];
    if (k == pl->e[s])
        return pl->slot0 + (size_t)side_to[s];
    return pl->slot0 + pl->side_off[s] + k - 1;
}

/* Parameters of sample k of side s. */
static void side_param(const patch_plan *pl, int s, size_t k, double *u, double *v)
{
    size_t e = pl->e[s];
    double t = k == 0 ? 0.0 : k == e ? 1.0 : (double)k / (double)e;
    switch (s) {
    case BSI_SIDE_V0: *u = t; *v = 0.0; break;
    case BSI_SIDE_U1: *u = 1.0; *v = t; break;
    case BSI_SIDE_V1: *u = t; *v = 1.0; break;
    default:          *u = 0.0; *v = t; break;
    }
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

static double grid_param(size_t i, size_t n)
{
    return i == 0 ? 0.0 : i == n ? 1.0 : (double)i / (double)n;
}

/* A triangle corner: vertex id and its (u,v) on the triangle's patch. */
typedef struct corner { uint32_t id; double u, v; } corner;

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

/* emit_plain, oriented counter-clockwise in (u,v) when asked, as a strip of its own. */
static void emit(tess *t, uint32_t patch, corner a, corner b, corner c, int orient)
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
            emit(t, patch, o0, side_corner(t, pl, s, i + 1), in0, 1);
            i++;
        } else {
            corner in1 = along_u ? grid_corner(t, pl, gi + 1, gj) : grid_corner(t, pl, gi, gj + 1);
            emit(t, patch, o0, in0, in1, 1);
            j++;
        }
    }
}

/* Second-difference bounds of the net: |S_uu| <= muu, |S_uv| <= muv, |S_vv| <= mvv everywhere. */
static void curvature_bounds(const bs_patch *p, double *muu, double *muv, double *mvv)
{
    size_t m = p->deg_u, n = p->deg_v, dim = p->dim;
    const double *P = p->ctrl;
    double a = 0.0, b = 0.0, c = 0.0;
#define AT(i, j, k) P[((i) * (n + 1) + (j)) * dim + (k)]
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            double s2 = 0.0, t2 = 0.0, x2 = 0.0;
            for (size_t k = 0; k < dim; k++) {
                if (i + 2 <= m) {
                    double d = AT(i + 2, j, k) - 2.0 * AT(i + 1, j, k) + AT(i, j, k);
                    s2 += d * d;
                }
                if (j + 2 <= n) {
                    double d = AT(i, j + 2, k) - 2.0 * AT(i, j + 1, k) + AT(i, j, k);
                    t2 += d * d;
                }
                if (i + 1 <= m && j + 1 <= n) {
                    double d = AT(i + 1, j + 1, k) - AT(i + 1, j, k) - AT(i, j + 1, k) + AT(i, j, k);
                    x2 += d * d;
                }
            }
            a = fmax(a, sqrt(s2));
            c = fmax(c, sqrt(t2));
            b = fmax(b, sqrt(x2));
        }
#undef AT
    double scale = 1.0;
    if (p->rational) {
        double wlo = p->weights[0], whi = p->weights[0];
        for (size_t k = 1; k < p->nctrl; k++) {
            wlo = fmin(wlo, p->weights[k]);
            whi = fmax(whi, p->weights[k]);
        }
        scale = whi / wlo;
    }
    *muu = scale * (double)(m * (m ? m - 1 : 0)) * a;
    *muv = scale * (double)(m * n) * b;
    *mvv = scale * (double)(n * (n ? n - 1 : 0)) * c;
}

/* Segments needed along one direction; the 1.5 covers the stretch of stitched triangles. */
static size_t rate_for(double mdir, double mmix, double tol)
{
    double r = ceil(1.5 * sqrt((mdir + mmix) / (4.0 * tol)));
    if (!(r >= 1.0))
        return 1;
    return r >= (double)BS_TESS_MAX_RATE ? BS_TESS_MAX_RATE : (size_t)r;
}

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

static double max_abs_coord(const bs_surface *s)
{
    double mx = 0.0;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        for (size_t k = 0; k < p->nctrl * p->dim; k++)
            mx = fmax(mx, fabs(p->ctrl[k]));
    }
    return mx;
}

/* Plan the sampling: side counts, slots, union-find merges, vertex ids. */
static bs_status plan(tess *t)
{
    size_t np = t->np;
    bs_status st = bsi_topology_build(t->s, 1e-9 * max_abs_coord(t->s), &t->topo);
    if (st != BS_OK)
        return st;
    size_t nslot = 0;
    for (size_t p = 0; p < np; p++) {
        patch_plan *pl = &t->plan[p];
        for (int s = 0; s < 4; s++) {
            const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
            size_t own = (s == BSI_SIDE_V0 || s == BSI_SIDE_V1) ? pl->ru : pl->rv;
            if (l->patch != BSI_NO_PATCH) {
                const patch_plan *q = &t->plan[l->patch];
                size_t other = (l->side == BSI_SIDE_V0 || l->side == BSI_SIDE_V1) ? q->ru : q->rv;
                own = own > other ? own : other;
            }
            pl->e[s] = own;
        }
        pl->regular = pl->e[BSI_SIDE_V0] == pl->ru && pl->e[BSI_SIDE_V1] == pl->ru &&
                      pl->e[BSI_SIDE_U0] == pl->rv && pl->e[BSI_SIDE_U1] == pl->rv;
        pl->gu = pl->regular || pl->ru >= 2 ? pl->ru : 2;
        pl->gv = pl->regular || pl->rv >= 2 ? pl->rv : 2;
        pl->slot0 = nslot;
        size_t off = 4;
        for (int s = 0; s < 4; s++) {
            pl->side_off[s] = off;
            off += pl->e[s] - 1;
        }
        nslot += off;
    }
    t->nslot = nslot;
    /* at least one element: malloc(0) may return NULL, which is not a failure */
    t->parent = malloc((nslot ? nslot : 1) * sizeof(size_t));
    t->slot_vert = malloc((nslot ? nslot : 1) * sizeof(uint32_t));
    if (t->parent == NULL || t->slot_vert == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < nslot; k++)
        t->parent[k] = k;
    for (size_t p = 0; p < np; p++) {
        const patch_plan *pl = &t->plan[p];
        for (int s = 0; s < 4; s++) {
            const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
            size_t e = pl->e[s];
            if (l->collapsed)
                for (size_t k = 1; k <= e; k++)
                    uf_union(t->parent, side_slot(pl, s, 0), side_slot(pl, s, k));
            if (l->patch == BSI_NO_PATCH)
                continue;
            const patch_plan *q = &t->plan[l->patch];
            for (size_t k = 0; k <= e; k++)
                uf_union(t->parent, side_slot(pl, s, k), side_slot(q, l->side, l->reversed ? e - k : k));
        }
    }
    /* Vertex ids: per patch, its root slots, then its interior grid points. */
    size_t nvert = 0;
    for (size_t p = 0; p < np; p++) {
        patch_plan *pl = &t->plan[p];
        size_t end = p + 1 < np ? t->plan[p + 1].slot0 : nslot;
        pl->vert0 = nvert;
        for (size_t k = pl->slot0; k < end; k++)
            if (uf_find(t->parent, k) == k)
                t->slot_vert[k] = (uint32_t)nvert++;
        pl->inner0 = nvert;
        size_t gi = pl->gu - 1, gj = pl->gv - 1;
        if (gj != 0 && gi > (SIZE_MAX - nvert) / gj)
            return BS_ERR_SIZE;
        nvert += gi * gj;
        if (nvert > UINT32_MAX - 1)
            return BS_ERR_SIZE;
    }
    t->nvert = nvert;
    return BS_OK;
}

/* Grid parameters i/n, i = 0..n, exactly 0 and 1 at the ends. */
static void grid_params(double *dst, size_t n)
{
    for (size_t i = 0; i <= n; i++)
        dst[i] = grid_param(i, n);
}

/* A normal the mesh cannot keep: undefined, or not of unit length (overflow, NaN). */
static int normal_bad(unsigned char kind, double x, double y, double z)
{
    double len = sqrt(x * x + y * y + z * z);
    return kind == BS_NORMAL_UNDEFINED || !(fabs(len - 1.0) < 1e-6);
}

/* Move nr x nj grid results (rows i0.., by coordinate in t->soa) into the mesh's packed arrays at
 * vertex `first`, with their (u,v) and patch id; count the normals to repair. */
static void store_block(tess *t, uint32_t patch, size_t first, size_t i0, size_t nr, size_t nj)
{
    const double *restrict x = t->soa, *restrict y = x + GRID_CHUNK, *restrict z = y + GRID_CHUNK;
    const double *restrict nx = z + GRID_CHUNK, *restrict ny = nx + GRID_CHUNK, *restrict nz = ny + GRID_CHUNK;
    const double *restrict pv = t->pv + 1;
    double *restrict pos = t->pos + 3 * first, *restrict nrm = t->nrm + 3 * first, *restrict uv = t->uv + 2 * first;
    uint32_t *restrict vp = t->vpatch + first;
    const unsigned char *restrict kind = t->kind + first;
    size_t bad = 0;
    for (size_t r = 0, k = 0; r < nr; r++) {
        double u = t->pu[1 + i0 + r];
        for (size_t j = 0; j < nj; j++, k++) {
            pos[3 * k] = x[k];
            pos[3 * k + 1] = y[k];
            pos[3 * k + 2] = z[k];
            nrm[3 * k] = nx[k];
            nrm[3 * k + 1] = ny[k];
            nrm[3 * k + 2] = nz[k];
            uv[2 * k] = u;
            uv[2 * k + 1] = pv[j];
            vp[k] = patch;
        }
    }
    /* |len^2 - 1| < 1e-6 implies |len - 1| < 1e-6: only the rest need normal_bad's square root */
    for (size_t k = 0; k < nr * nj; k++) {
        double q = nx[k] * nx[k] + ny[k] * ny[k] + nz[k] * nz[k];
        if (!(fabs(q - 1.0) < 1e-6) || kind[k] == BS_NORMAL_UNDEFINED)
            bad += (size_t)normal_bad(kind[k], nx[k], ny[k], nz[k]);
    }
    t->nbad += bad;
}

/* Views of coordinates 0..2 of the packed triples x[3*first ...], n elements. */
static void triple_views(double *x, size_t first, size_t n, bs_view out[3])
{
    for (size_t c = 0; c < 3; c++) {
        out[c].data = x + 3 * first + c;
        out[c].count = n;
        out[c].stride = (ptrdiff_t)(3 * sizeof(double));
    }
}

/* Parameters of every vertex, then positions and normals patch by patch: the patch's own side
 * samples (vertices vert0..inner0-1) as a list, its interior grid in one grid call. */
static bs_status evaluate(tess *t)
{
    size_t nv = t->nvert, gmax = 1;
    for (size_t p = 0; p < t->np; p++) {
        gmax = t->plan[p].gu > gmax ? t->plan[p].gu : gmax;
        gmax = t->plan[p].gv > gmax ? t->plan[p].gv : gmax;
    }
    t->pos = malloc((nv ? nv : 1) * 3 * sizeof(double));
    t->nrm = malloc((nv ? nv : 1) * 3 * sizeof(double));
    t->uv = malloc((nv ? nv : 1) * 2 * sizeof(double));
    t->vpatch = malloc((nv ? nv : 1) * sizeof(uint32_t));
    t->kind = malloc(nv ? nv : 1);
    t->pu = malloc((gmax + 1) * sizeof(double));
    t->pv = malloc((gmax + 1) * sizeof(double));
    t->soa = malloc(6 * GRID_CHUNK * sizeof(double));
    if (!t->pos || !t->nrm || !t->uv || !t->vpatch || !t->kind || !t->pu || !t->pv || !t->soa)
        return BS_ERR_NO_MEMORY;
    for (size_t p = 0; p < t->np; p++) {
        const patch_plan *pl = &t->plan[p];
        const bs_patch *patch = bs_surface_get(t->s, p);
        for (int s = 0; s < 4; s++)
            for (size_t k = 0; k <= pl->e[s]; k++) {
                size_t slot = side_slot(pl, s, k);
                if (uf_find(t->parent, slot) != slot)
                    continue;
                uint32_t id = t->slot_vert[slot];
                side_param(pl, s, k, &t->uv[2 * (size_t)id], &t->uv[2 * (size_t)id + 1]);
            }
        for (size_t id = pl->vert0; id < pl->inner0; id++)
            t->vpatch[id] = (uint32_t)p;
        size_t n = pl->inner0 - pl->vert0;
        ptrdiff_t s2 = (ptrdiff_t)(2 * sizeof(double));
        bs_view pos[3], nrm[3];
        if (n > 0) {
            bs_cview cu = {t->uv + 2 * pl->vert0, n, s2}, cv = {t->uv + 2 * pl->vert0 + 1, n, s2};
            triple_views(t->pos, pl->vert0, n, pos);
            triple_views(t->nrm, pl->vert0, n, nrm);
            bs_status st = bs_patch_eval_normal(patch, n, &cu, &cv, pos, nrm, t->kind + pl->vert0);
            if (st != BS_OK)
                return st;
            for (size_t id = pl->vert0; id < pl->inner0; id++) {
                const double *nr = t->nrm + 3 * id;
                t->nbad += (size_t)normal_bad(t->kind[id], nr[0], nr[1], nr[2]);
            }
        }
        size_t ni = pl->gu - 1, nj = pl->gv - 1;
        if (ni == 0 || nj == 0)
            continue;
        grid_params(t->pu, pl->gu);
        grid_params(t->pv, pl->gv);
        /* blocks of whole rows, evaluated by coordinate, then interleaved into the mesh */
        size_t rows = GRID_CHUNK / nj;
        for (size_t i0 = 0; i0 < ni; i0 += rows) {
            size_t nr = ni - i0 < rows ? ni - i0 : rows, npt = nr * nj, first = pl->inner0 + i0 * nj;
            bs_cview gu = {t->pu + 1 + i0, nr, (ptrdiff_t)sizeof(double)};
            bs_cview gv = {t->pv + 1, nj, (ptrdiff_t)sizeof(double)};
            for (size_t c = 0; c < 3; c++) {
                pos[c].data = t->soa + c * GRID_CHUNK;
                nrm[c].data = t->soa + (3 + c) * GRID_CHUNK;
                pos[c].count = nrm[c].count = npt;
                pos[c].stride = nrm[c].stride = (ptrdiff_t)sizeof(double);
            }
            bs_status st = bs_patch_eval_grid(patch, nr, &gu, nj, &gv, pos, NULL, NULL, nrm, t->kind + first);
            if (st != BS_OK)
                return st;
            store_block(t, (uint32_t)p, first, i0, nr, nj);
        }
    }
    return BS_OK;
}

/* Room for every triangle, strip and index the patches can emit (poles drop some). */
static bs_status reserve_output(tess *t)
{
    size_t ntri = 0, nstrip = 1, nsidx = 0, gids = 1, uv_cap = 0;
    for (size_t p = 0; p < t->np; p++) {
        const patch_plan *pl = &t->plan[p];
        size_t gu = pl->gu, gv = pl->gv; /* at most BS_TESS_MAX_RATE: no overflow per patch */
        size_t pt, ps, pi;
        if (pl->regular) {
            pt = 2 * gu * gv;
            ps = gu;
            pi = 2 * gu * (gv + 1);
        } else {
            size_t ring = pl->e[0] + pl->e[1] + pl->e[2] + pl->e[3] + 2 * (gu - 2) + 2 * (gv - 2);
            pt = 2 * (gu - 2) * (gv - 2) + ring;
            ps = (gu - 2) + ring;
            pi = 2 * (gu - 2) * (gv - 1) + 3 * ring;
        }
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

static bs_status triangulate(tess *t)
{
    bs_status st = reserve_output(t);
    if (st != BS_OK)
        return st;
    for (size_t p = 0; p < t->np; p++) {
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
    if (t->tri.n > UINT32_MAX || t->sidx.n > UINT32_MAX)
        return BS_ERR_SIZE;
    return BS_OK;
}

/* Replace normals the surface does not define (or that are not unit) by the adjacent triangles'. */
static void repair_normals(tess *t)
{
    if (t->nbad == 0)
        return; /* evaluate() checked every vertex */
    size_t bad = 0;
    for (size_t k = 0; k < t->nvert; k++) {
        double *n = t->nrm + 3 * k;
        if (normal_bad(t->kind[k], n[0], n[1], n[2])) {
            t->kind[k] = BS_NORMAL_UNDEFINED;
            n[0] = n[1] = n[2] = 0.0;
            bad++;
        }
    }
    if (bad == 0)
        return;
    for (size_t f = 0; f < t->tri.n / 3; f++) {
        const uint32_t *v = t->tri.v + 3 * f;
        const double *a = t->pos + 3 * (size_t)v[0], *b = t->pos + 3 * (size_t)v[1], *c = t->pos + 3 * (size_t)v[2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double fn[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            if (t->kind[v[k]] == BS_NORMAL_UNDEFINED)
                for (int c2 = 0; c2 < 3; c2++)
                    t->nrm[3 * (size_t)v[k] + (size_t)c2] += fn[c2];
    }
    for (size_t k = 0; k < t->nvert; k++) {
        if (t->kind[k] != BS_NORMAL_UNDEFINED)
            continue;
        double *n = t->nrm + 3 * k;
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0.0 && isfinite(len)) {
            n[0] /= len;
            n[1] /= len;
            n[2] /= len;
        } else {
            n[0] = 0.0;
            n[1] = 0.0;
            n[2] = 1.0;
        }
    }
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

/* The corner list had room for every corner; keep only the few used (the mesh lives long). */
static bs_status trim_corner_list(tess *t)
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

/* Run the tessellation with rates already in t->plan, and hand the arrays to a new mesh. */
static bs_status run(tess *t, bs_mesh **out)
{
    bs_status st = plan(t);
    if (st == BS_OK)
        st = evaluate(t);
    if (st == BS_OK)
        st = triangulate(t);
    if (st == BS_OK)
        st = trim_corner_list(t);
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
    repair_normals(t);
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
        double muu, muv, mvv;
        curvature_bounds(bs_surface_get(s, p), &muu, &muv, &mvv);
        t.plan[p].ru = rate_for(muu, muv, tol);
        t.plan[p].rv = rate_for(mvv, muv, tol);
    }
    return run(&t, out);
}
