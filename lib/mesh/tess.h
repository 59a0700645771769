/*
 * The tessellator's shared state and phases, private to lib/mesh/ (the overview is at the top of
 * lib/mesh/tessellate.c). A tessellation runs the phases in order on one `tess`:
 *   1. rates   (tessellate.c, tess_plan.c)  segments per direction of each patch
 *   2. layout  (tess_plan.c)    topology, segments per side, grids; then the counts
 *      (tess_count.c), checked against the limits before anything large is allocated
 *   3. plan    (tess_plan.c)    sides sampled into slots, shared slots merged, vertex ids
 *   4. sample  (tess_sample.c)  parameters, positions and normals of every vertex
 *   5. emit    (tess_emit.c)    triangles, strips and the corners that keep their own (u,v)
 *   6. finish  (tess_sample.c, tess_emit.c, tess_reverse.c)  normals repaired, corner list
 *      trimmed, faced the other way for BS_TESS_REVERSE
 * The entry points with options and budgets are in tess_options.c.
 * Not installed.
 */
#ifndef BEZSURF_MESH_TESS_H
#define BEZSURF_MESH_TESS_H

#include "mesh/internal.h"
#include "surface/internal.h"

#include <stddef.h>
#include <stdint.h>

/* Output arrays, sized once before emission and filled without checks. */
typedef struct ubuf { uint32_t *v; size_t n, cap; } ubuf;
/* Triangle corners whose (u,v) on the triangle's patch is not their vertex's (struct bs_mesh). */
typedef struct xbuf { size_t *corner; double *uv; size_t n, cap; } xbuf;

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

/* Scratch of one sampling thread: grid parameters, 6 x GRID_CHUNK positions and normals of a
 * block of grid rows by coordinate, and the count of normals to repair it found. */
typedef struct tess_scratch { double *pu, *pv, *soa; size_t nbad; } tess_scratch;

typedef struct tess {
    const bs_surface *s;
    size_t np;
    bsi_topology topo;
    patch_plan *plan;
    size_t nslot;
    size_t *parent;     /* union-find over slots; the root of a set is its lowest slot */
    uint32_t *slot_vert;
    int strips;
    int reverse;        /* BS_TESS_REVERSE: faced the other way by bsi_tess_finish */
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
    size_t nbad; /* vertices whose normal bsi_tess_repair_normals must replace */
    size_t threads; /* the caller's thread count (0 = one per online CPU) */
    /* scratch of each sampling thread (work1 when there is one), freed with the rest: one
     * thread allocates as the tessellator always did, for malloc's heap trimming is sensitive
     * to it (an extra small block per call tripled the time by faulting the mesh in again) */
    tess_scratch *work, work1;
    size_t nwork;
} tess;

/* Grid points evaluated per call into packed scratch (the evaluator writes packed arrays in
 * place; the mesh's packed triples are filled from them). */
#define GRID_CHUNK ((size_t)4096)

/* ---- Slots, sides and grid parameters, used by every phase ---- */

static inline size_t uf_find(size_t *parent, size_t x)
{
    size_t r = x;
    while (parent[r] != r) // NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult): the callers start every set as itself
        r = parent[r];
    while (parent[x] != r) {
        size_t nx = parent[x];
        parent[x] = r;
        x = nx;
    }
    return r;
}

/* Merge the sets of a and b; the root stays the lowest element. */
static inline void uf_union(size_t *parent, size_t a, size_t b)
{
    a = uf_find(parent, a);
    b = uf_find(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

/* Corner (0:c00 1:c10 2:c11 3:c01) at the start (end 0) or the end (end 1) of side s. */
static inline size_t side_end_corner(int s, int end)
{
    static const unsigned char corner[2][4] = {{0, 1, 3, 0}, {1, 2, 2, 3}};
    return corner[end][s];
}

/* Slot of sample k (0..e) of side s of patch p. */
static inline size_t side_slot(const patch_plan *pl, int s, size_t k)
{
    if (k == 0)
        return pl->slot0 + side_end_corner(s, 0);
    if (k == pl->e[s])
        return pl->slot0 + side_end_corner(s, 1);
    return pl->slot0 + pl->side_off[s] + k - 1;
}

/* Parameters of sample k of side s. */
static inline void side_param(const patch_plan *pl, int s, size_t k, double *u, double *v)
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

static inline double grid_param(size_t i, size_t n)
{
    return i == 0 ? 0.0 : i == n ? 1.0 : (double)i / (double)n;
}

/* Grid parameters i/n, i = 0..n, exactly 0 and 1 at the ends. */
static inline void grid_params(double *dst, size_t n)
{
    for (size_t i = 0; i <= n; i++)
        dst[i] = grid_param(i, n);
}

/* ---- The phases ---- */

/* Rates (ru, rv) of patch p meeting tolerance tol by the second-difference bound (tess_plan.c). */
void bsi_tess_adaptive_rates(const bs_patch *p, double tol, size_t *ru, size_t *rv);
/* Largest control-point coordinate of the surface: sides are shared within 1e-9 of it. */
double bsi_tess_max_abs_coord(const bs_surface *s);
/* Topology, side counts and grids of every patch from the rates in t->plan; memory O(patches). */
bs_status bsi_tess_layout(tess *t);

/* What the laid-out tessellation will emit, computed in memory O(patches) (tess_count.c). */
typedef struct tess_counts { size_t vertices, triangles, strips, strip_indices; } tess_counts;
/* BS_ERR_SIZE only when a count does not fit in size_t. */
bs_status bsi_tess_count(const tess *t, tess_counts *c);

/* Slots, merges and vertex ids of the laid-out tessellation. */
bs_status bsi_tess_plan(tess *t);
/* Parameters, positions, normals and patch ids of every vertex (tess_sample.c). */
bs_status bsi_tess_evaluate(tess *t);
/* Replace normals the surface does not define (or that are not unit) by the adjacent triangles'. */
void bsi_tess_repair_normals(tess *t);
/* A triangle corner: vertex id and its (u,v) on the triangle's patch. */
typedef struct bsi_corner { uint32_t id; double u, v; } bsi_corner;
/* Append triangle a b c into reserved room, oriented counter-clockwise in (u,v) when asked, as a
 * strip of its own; dropped when a pole makes it degenerate (a repeated vertex). */
void bsi_tess_emit(tess *t, uint32_t patch, bsi_corner a, bsi_corner b, bsi_corner c, int orient);
/* Positions, normals and kinds of vertices first .. first + n - 1 of patch p from their (u,v) in
 * t->uv, with their patch id; adds the normals to repair to *nbad (tess_sample.c). */
bs_status bsi_tess_eval_list(const tess *t, uint32_t p, size_t first, size_t n, size_t *nbad);
/* Hand the arrays of a finished tessellation (status st) to a new mesh, or free them on failure
 * (tessellate.c). */
bs_status bsi_tess_finish(tess *t, bs_status st, bs_mesh **out);
/* Reserve the output arrays, then emit every patch's triangles, on up to t->threads threads
 * (tess_emit.c). */
bs_status bsi_tess_triangulate(tess *t);
/* The emission of bsi_tess_triangulate on `workers` threads, into reserved arrays. */
bs_status bsi_tess_emit_parallel(tess *t, size_t workers);
/* Face a finished tessellation the other way: normals, triangles, corners and strips
 * (tess_reverse.c; BS_ERR_NO_MEMORY, or BS_ERR_SIZE past 32-bit strip indices). */
bs_status bsi_tess_reverse(tess *t);
/* Shrink the corner list to the corners actually listed. */
bs_status bsi_tess_trim_corners(tess *t);

/* ---- The runs (tessellate.c) ---- */

/* BS_ERR_INVALID_ARG for a NULL surface or unknown flags, BS_ERR_DIMENSION for a surface not 3-D. */
bs_status bsi_tess_check(const bs_surface *s, int flags);
/* Start t with nu x nv segments on every patch (BS_ERR_DOMAIN for a rate out of range). */
bs_status bsi_tess_start_uniform(tess *t, const bs_surface *s, int flags, size_t nu, size_t nv);
/* Start t with each patch's rates for a tolerance (BS_ERR_DOMAIN unless finite and > 0). */
bs_status bsi_tess_start_adaptive(tess *t, const bs_surface *s, int flags, double tolerance);
/* The tolerance as a distance: with BS_TESS_RELATIVE a fraction of the control points' box diagonal. */
double bsi_tess_absolute_tolerance(const bs_surface *s, double tolerance, int flags);
/* Lay out and count a started t. */
bs_status bsi_tess_measure(tess *t, tess_counts *c);
/* Lay out and count a started t, refuse counts over the budgets (0: none) or the 32-bit indices
 * with BS_ERR_SIZE, then build the mesh. Frees t in every case. */
bs_status bsi_tess_build(tess *t, size_t max_vertices, size_t max_triangles, bs_mesh **out);
/* Release what a started t holds. */
void bsi_tess_free(tess *t);

#endif
