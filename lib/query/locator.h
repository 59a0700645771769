/*
 * The locator (bezsurf/query.h), private to lib/query/: its layout, the bounding-volume hierarchy
 * over sub-patches, the exact halving of nets that builds the sub-patches and drives the ray test,
 * and the ray test against one sub-patch. Not installed.
 */
#ifndef BEZSURF_QUERY_LOCATOR_H
#define BEZSURF_QUERY_LOCATOR_H

#include "query/internal.h"

/* Every patch is cut into BSI_LOC_SPLIT x BSI_LOC_SPLIT sub-patches by halving its net twice in
 * each direction; each sub-patch is a leaf of the hierarchy. */
#define BSI_LOC_SPLIT 4

/* The normals of a polynomial 3-D sub-patch's net: every cross product a x b of a difference a
 * along u with one b along v lies within the angle whose sine is spread - 1e-3 of axis (unit),
 * and no difference is shorter than least. A ray of unit direction d with |d.axis| > spread
 * sees the net's projection one to one (the partials' cross product along d keeps its sign), if
 * the net lies within 2^24 least of its origin, so that the projection's rounding cannot turn
 * it. spread = 2 when no such cone was found (rational, degree 0, nearly parallel partials, a
 * net of over 64 points). */
typedef struct bsi_leaf_cone {
    double axis[3], spread, least;
} bsi_leaf_cone;
#define BSI_NO_CONE ((bsi_leaf_cone){{0.0, 0.0, 0.0}, 2.0, INFINITY})

/* One sub-patch: its patch, the corner (u0, v0) of its domain (side 1/BSI_LOC_SPLIT), where
 * its net is: (deg_u+1)(deg_v+1) points of dim+1 doubles, the Cartesian point then its weight,
 * and the cone of its normals (3-D locators; spread 2 otherwise). */
typedef struct bsi_loc_leaf {
    uint32_t patch;
    double u0, v0;
    size_t net;
    bsi_leaf_cone cone;
} bsi_loc_leaf;

/* Sub-patches per leaf node of the hierarchy at most (two: the walk orders them by entry). */
#define BSI_LOC_LEAF_MAX 2

/* A node of the hierarchy: an inner node (count 0) has its children at first and first + 1; a
 * leaf node holds leaves first .. first + count - 1 of the locator's leaf array. */
typedef struct bsi_loc_node {
    uint32_t first, count;
} bsi_loc_node;

/* The rays' tree: the binary tree collapsed into nodes of up to four children, so that a ray
 * tests four boxes at once (lib/query/locator_bvh.c, locator_ray.c). Slot k of a node has a box
 * (lower corner lo[c][k], upper hi[c][k]; 3-D locators) and is a wide node (leaf[k] = 0, ref its
 * index), a binary leaf node (BSI_WIDE_NODE, ref its index in L->nodes) or one sub-patch
 * (BSI_WIDE_PATCH, ref its index in L->leaves; the box its own). */
#define BSI_LOC_WIDE 4
#define BSI_WIDE_NODE 1
#define BSI_WIDE_PATCH 2
typedef struct bsi_loc_wide {
    double lo[3][BSI_LOC_WIDE], hi[3][BSI_LOC_WIDE];
    uint32_t ref[BSI_LOC_WIDE];
    unsigned char leaf[BSI_LOC_WIDE];
    uint32_t n; /* slots used */
} bsi_loc_wide;

/* What a locator of a model's trimmed faces adds (bs_locator_create_model, lib/model/), which
 * this layer sees only through these calls: a ray's hit on patch `patch` at (u, v) counts only
 * where inside() says so (the walk goes on to later hits otherwise), and answers are reported by
 * to_face() as a face id and native face parameters, the patch's normal nrm turned into the
 * face's outward one. release() frees the whole record with the locator. */
typedef struct bsi_loc_trim bsi_loc_trim;
struct bsi_loc_trim {
    int (*inside)(const bsi_loc_trim *t, uint32_t patch, double u, double v);
    void (*to_face)(const bsi_loc_trim *t, uint32_t patch, double u, double v, uint32_t *face,
                    double uv[2], double nrm[3]);
    void (*release)(bsi_loc_trim *t);
    /* Closest points (locator_closest.c): box() and point() are a bsi_cl_part's calls (ctx the
     * record) for the face of a patch; boundary() searches the faces' trims for a point nearer to
     * q than *best_d (within the tolerance of bsi_patch_closest_one): 1 when found (*best_d, *patch
     * and st set), 0 when none is nearer, -2 when the search cannot be certified. */
    int (*box)(const void *t, uint32_t patch, const double st[4]);
    int (*point)(const void *t, uint32_t patch, double s, double u);
    int (*boundary)(const bsi_loc_trim *t, const double *q, double *best_d, uint32_t *patch,
                    double st[2]);
};

/* A patch beyond 2^512 or below 2^-900: sig, the power of two of bsi_extreme_scale
 * (1 for the others), and its copy times sig (else NULL). Its leaves' nets are stored times sig,
 * so that they are halved and projected without losing bits, and its normals (nscale) are those
 * of the copy, as bs_patch_eval_normal takes them. */
typedef struct bsi_loc_scaled {
    double sig;
    bs_patch *copy;
} bsi_loc_scaled;

struct bs_locator {
    size_t dim;          /* 0 for an empty surface */
    size_t npatch, nleaf, nnode;
    double diag;         /* D: diagonal of the box of every control point of the surface */
    size_t max_ctrl;     /* the largest (deg_u+1)(deg_v+1) */
    bs_patch **patches;  /* copies of the surface's patches */
    bsi_loc_leaf *leaves;
    double *nets;        /* the leaves' nets */
    bsi_loc_node *nodes; /* nodes[0] is the root */
    double *box;         /* node k: lower corner box[2*k*dim ...], upper corner right after */
    double *leaf_box;    /* leaf k's box, as node boxes: tested before its net is projected */
    bsi_loc_wide *wide;  /* the rays' tree (3-D locators), wide[0] its root; NULL otherwise */
    bsi_nscale *nscale;  /* per patch, for its normals (3-D locators): bsi_normal_scale's once */
    bsi_loc_scaled *scaled; /* per patch; NULL when every patch lies within [2^-1000, 2^1000] */
    bsi_loc_trim *trim;  /* NULL, or the trimmed faces of a model's locator (owned) */
};

/* Patch i as rays and their normals take it: its scaled copy (*sig its scale) beyond 2^1000 or
 * below 2^-1000, else itself (*sig = 1). */
static inline const bs_patch *bsi_loc_patch(const bs_locator *L, size_t i, double *sig)
{
    const bsi_loc_scaled *ext = L->scaled ? &L->scaled[i] : NULL;
    *sig = ext && ext->copy ? ext->sig : 1.0;
    return ext && ext->copy ? ext->copy : L->patches[i];
}

/* Halve a net of (m+1) x (n+1) points of nc interleaved doubles at the parameter 1/2 along dir
 * (BS_DIR_U: along i, the rows) into lo and hi (either may be NULL). Only midpoints (a+b)/2 are
 * formed, so a shared side or a reversed one halves to the same bits in both patches. Inline, so
 * that the ray test's calls with nc = 4 are compiled for that nc. */
static inline void bsi_net_halve(const double *net, size_t m, size_t n, size_t nc, int dir,
                                 double *lo, double *hi)
{
    /* along u, curve q runs over i with a step of (n+1) points; along v over j, one point */
    size_t deg = dir == BS_DIR_U ? m : n, step = dir == BS_DIR_U ? (n + 1) * nc : nc;
    size_t ncurve = dir == BS_DIR_U ? n + 1 : m + 1, cstep = dir == BS_DIR_U ? nc : (n + 1) * nc;
    double b[(BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)];
    if (deg == 3 && lo && hi) { /* the loops below written out for cubics: the same midpoints */
        for (size_t q = 0; q < ncurve; q++) {
            const double *in = net + q * cstep;
            double *l = lo + q * cstep, *h = hi + q * cstep;
            for (size_t c = 0; c < nc; c++) {
                double p0 = in[c], p1 = in[step + c], p2 = in[2 * step + c], p3 = in[3 * step + c];
                double a = (p0 + p1) * 0.5, b1 = (p1 + p2) * 0.5, d = (p2 + p3) * 0.5;
                double e = (a + b1) * 0.5, f = (b1 + d) * 0.5, g = (e + f) * 0.5;
                l[c] = p0;
                l[step + c] = a;
                l[2 * step + c] = e;
                l[3 * step + c] = g;
                h[c] = g;
                h[step + c] = f;
                h[2 * step + c] = d;
                h[3 * step + c] = p3;
            }
        }
        return;
    }
    for (size_t q = 0; q < ncurve; q++) {
        const double *in = net + q * cstep;
        size_t base = q * cstep;
        for (size_t k = 0; k <= deg; k++)
            for (size_t c = 0; c < nc; c++)
                b[k * nc + c] = in[k * step + c]; // NOLINT(clang-analyzer-core.uninitialized.Assign): the caller's net is whole
        for (size_t c = 0; c < nc; c++) {
            if (lo)
                lo[base + c] = b[c];
            if (hi)
                hi[base + deg * step + c] = b[deg * nc + c];
        }
        for (size_t r = 1; r <= deg; r++) {
            for (size_t k = 0; k + r <= deg; k++)
                for (size_t c = 0; c < nc; c++)
                    b[k * nc + c] = (b[k * nc + c] + b[(k + 1) * nc + c]) * 0.5;
            for (size_t c = 0; c < nc; c++) {
                if (lo)
                    lo[base + r * step + c] = b[c];
                if (hi)
                    hi[base + (deg - r) * step + c] = b[(deg - r) * nc + c];
            }
        }
    }
}

/* Build the hierarchy over L->nleaf leaves whose boxes are in leaf_box (2*dim doubles each, as
 * node boxes): fills L->nodes, L->nnode, L->box, reorders L->leaves and puts their boxes, in the
 * same order, in L->leaf_box; for a 3-D locator also L->wide. BS_ERR_NO_MEMORY. */
bs_status bsi_loc_build_bvh(bs_locator *L, const double *leaf_box);

/* A ray in the frame it is tested in: origin o, unit direction d, and e1, e2 completing an
 * orthonormal frame (and 1 / d); t in units of |d| = 1, from tmin (exclusive when open) to tmax. */
typedef struct bsi_ray {
    double o[3], d[3], e1[3], e2[3];
    double inv[3]; /* 1 / d, for the slab tests */
    double tmin, tmax;
    int open;
} bsi_ray;

/* The best hit so far: t (unit direction), the leaf and its local (s, r). */
typedef struct bsi_ray_hit {
    double t, s, r;
    size_t leaf;
} bsi_ray_hit;

/* The cone of normals of a sub-patch's net of (m+1) x (n+1) points of 4 doubles (x, y, z, w;
 * rat: the weights are not all 1). */
void bsi_ray_leaf_cone(const double *net, size_t m, size_t n, int rat, bsi_leaf_cone *cone);

/* Doubles of scratch bsi_ray_leaf needs for nets of up to max_ctrl points. */
size_t bsi_ray_leaf_scratch(size_t max_ctrl);

/* Intersect the ray with leaf k of L; when a hit earlier than hit->t lies in the ray's range,
 * hit receives it. */
void bsi_ray_leaf(const bs_locator *L, size_t k, const bsi_ray *ray, double *scratch,
                  bsi_ray_hit *hit);

/* The argument checks of bs_locator_closest_point() and bs_locator_intersect(), with their statuses
 * (BS_OK for n = 0 once L is checked), so that the multi-threaded variants check everything before
 * any thread starts (lib/query/locator_mt.c). */
bs_status bsi_loc_closest_check(const bs_locator *L, size_t n, const bs_cview *q, const bs_view *uv,
                                const bs_view *dist, const bs_view *pos);
bs_status bsi_loc_intersect_check(const bs_locator *L, size_t n, const bs_cview *org, const bs_cview *dir,
                                  const bs_cview *trange, const bs_view *uv, const bs_view *t,
                                  const bs_view *nrm);

#endif
