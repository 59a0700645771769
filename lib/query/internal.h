/*
 * Query layer, private to lib/query/: curvature at one point from its partial derivatives, and
 * its limit at degenerate points. Not installed.
 */
#ifndef BEZSURF_QUERY_INTERNAL_H
#define BEZSURF_QUERY_INTERNAL_H

#include "surface/internal.h"

#include <math.h>

/* min and max without the NaN rules of fmin and fmax, which keep them out of line (the ray test,
 * the walk, the closest-point bounds); a NaN in b is passed on, not dropped. */
static inline double lesser(double a, double b) { return a < b ? a : b; }
static inline double greater(double a, double b) { return a > b ? a : b; }

/* bsi_all_finite(x, 3) in line: a few of these a ray */
static inline int bsi_finite3(const double *x) { return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]); }

static inline double bsi_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void bsi_cross3(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Curvature at one point: K, H, k_min, k_max, and the principal directions. */
typedef struct bsi_curv {
    double k[4]; /* K, H, k_min, k_max */
    double dmin[3], dmax[3];
} bsi_curv;

/* The partials a curvature needs at one point: S_u, S_v, S_uu, S_uv, S_vv, and the unit normal. */
typedef struct bsi_partials {
    double d[5][3];
    double nrm[3];
} bsi_partials;

/* Curvature from the fundamental forms at a regular point; inv_d = 1/D (umbilic test scale). */
void bsi_curv_regular(const bsi_partials *q, double inv_d, bsi_curv *out);

/* Point k of the planes of bsi_curv_partials_chunk as one bsi_partials. */
void bsi_curv_gather(const double *d, const double *nrm, size_t k, bsi_partials *q);

/* The limit of the curvature at finite (u,v) along the line towards (1/2,1/2), nrm the limit
 * normal there (sc from bsi_normal_scale(p)): BS_CURV_LIMIT with out filled, or
 * BS_CURV_UNDEFINED when the limit does not exist or could not be found. */
unsigned char bsi_curv_limit(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                             const double nrm[3], double inv_d, bsi_curv *out);

/* Closest point of one patch to a finite point q (p->dim coordinates), certified global to
 * tau = 1e-9 (D + d) (D from the patch, or the caller's larger D: pass it in d_scale, 0 = the
 * patch's own). *best_d2 is the squared distance to beat (INFINITY when there is none yet): when
 * the patch has a point closer than that, uv and *best_d2 receive the answer and 1 is returned;
 * otherwise 0 and both are left alone, so a caller can run it over several patches and keep the
 * best. Returns -1 when out of memory, -2 when the answer cannot be certified (a weight ratio or a
 * search beyond what the method can certify; BS_ERR_PRECISION). Thread-safe; uses no global state.
 * (lib/query/closest.c) */
int bsi_patch_closest_one(const bs_patch *p, const double *q, double d_scale, double *best_d2,
                          double uv[2]);
/* bsi_patch_closest_one with the distance to beat, and the answer's, in *best_d (not squared:
 * the squares of huge coordinates overflow), counting in *boxes (may be NULL) the boxes whose
 * second-order bound was computed. The locator's step. */
int bsi_patch_closest_dist(const bs_patch *p, const double *q, double d_scale, double *best_d,
                           double uv[2], size_t *boxes);

/* A part of a patch's domain that a closest-point search is held to (a trimmed face of a model,
 * lib/model/): box() says where the box st = (s0, s1, t0, t1) of the domain of patch `patch`
 * lies, point() whether (s, t) is in the part (its boundary counted in). */
#define BSI_CL_OUT 0
#define BSI_CL_IN 1
#define BSI_CL_CROSS 2 /* the part's boundary may pass through the box */
typedef struct bsi_cl_part {
    int (*box)(const void *ctx, uint32_t patch, const double st[4]);
    int (*point)(const void *ctx, uint32_t patch, double s, double t);
    const void *ctx;
    uint32_t patch;
} bsi_cl_part;

/* bsi_patch_closest_dist over the part of the domain only, NULL for the whole domain. The answer
 * is certified for the part's interior: a closest point on the part's boundary is the caller's to
 * find (the search prunes boxes where f has no local minimum, which leaves such points out). */
int bsi_patch_closest_part(const bs_patch *p, const double *q, double d_scale, double *best_d,
                           double uv[2], const bsi_cl_part *part);

/* The part [a, b] of len lines of deg+1 values at once (value e of point k at x[k stride + e]),
 * in place: at b from the left, then at a/b from the right. */
BSI_INLINE void bsi_sub_line(double *x, size_t deg, size_t stride, size_t len, double a, double b)
{
    /* [0, b]: after step r the point r of the left part is x[0] of that step; keep them in
     * place by running the recurrence from the right end */
    for (size_t r = 1; r <= deg; r++)
        for (size_t k = deg; k >= r; k--)
            for (size_t e = 0; e < len; e++)
                x[k * stride + e] = (1.0 - b) * x[(k - 1) * stride + e] + b * x[k * stride + e];
    double t = b > 0.0 ? a / b : 0.0; /* [a, b] is [t, 1] of [0, b] */
    for (size_t r = 1; r <= deg; r++)
        for (size_t k = 0; k + r <= deg; k++)
            for (size_t e = 0; e < len; e++)
                x[k * stride + e] = (1.0 - t) * x[k * stride + e] + t * x[(k + 1) * stride + e];
}

#endif
