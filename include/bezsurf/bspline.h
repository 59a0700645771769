/**
 * @file
 * libbezsurf B-spline and NURBS surfaces in: a B-spline surface is cut at its knots into Bezier
 * patches, one per knot span, appended to a surface. Include <bezsurf.h> rather than this file.
 *
 * The B-spline is described by a bs_bspline that points into the caller's arrays; nothing of it
 * is kept after a call. A knot vector of a direction with degree p and count control points has
 * count + p + 1 knots; the surface's domain is [knots[p], knots[count]] in that direction. A span
 * is a knot interval [knots[i], knots[i+1]) of positive length inside the domain, the last one
 * closed; spans are numbered from 0 along each direction, and span (a, b) becomes the patch with
 * index first + a * spans_v + b, its local (u,v) in [0,1]^2 mapped linearly onto the span.
 *
 * Checks, in this order, with the first failure returned and nothing changed: s or b NULL, or a
 * NULL array (BS_ERR_INVALID_ARG); a degree of 0 or over BS_MAX_DEGREE (BS_ERR_DEGREE); dim 0 or
 * over BS_MAX_DIM (BS_ERR_DIMENSION); a count below degree + 1 (BS_ERR_SIZE); a knot that is not
 * finite, knots that decrease, a knot value repeated more than degree + 1 times, an empty domain,
 * or knots spread over more than DBL_MAX (their differences overflow; since 1.2) (BS_ERR_DOMAIN); a control point coordinate that is not finite, or a weight that is not
 * finite and positive (BS_ERR_NONFINITE). bs_bspline_span_count() and bs_bspline_locate() need only
 * the knots: they check degrees, counts and knots, and do not read dim, ctrl or weights.
 */
#ifndef BEZSURF_BSPLINE_H
#define BEZSURF_BSPLINE_H

#include "core.h"
#include "surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * A B-spline or NURBS surface as the caller holds it. Frozen for version 1. @since 1.1
 */
typedef struct bs_bspline {
    size_t deg_u;           /**< degree along u, 1..BS_MAX_DEGREE */
    size_t deg_v;           /**< degree along v, 1..BS_MAX_DEGREE */
    size_t count_u;         /**< control points along u, >= deg_u + 1 */
    size_t count_v;         /**< control points along v, >= deg_v + 1 */
    size_t dim;             /**< dimension of a control point, 1..BS_MAX_DIM */
    const double *knots_u;  /**< count_u + deg_u + 1 finite, non-decreasing knots */
    const double *knots_v;  /**< count_v + deg_v + 1 finite, non-decreasing knots */
    const double *ctrl;     /**< point (i,j), coordinate c at ctrl[(i * count_v + j) * dim + c] */
    const double *weights;  /**< NULL, or count_u * count_v finite positive weights (NURBS) */
} bs_bspline;

/**
 * @brief Number of knot spans along u and v: the patches bs_surface_add_bspline() adds are
 * spans_u * spans_v.
 * @param[in]  b        the B-spline (its degrees, counts and knots).
 * @param[out] spans_u  receives the number of spans along u.
 * @param[out] spans_v  receives the number of spans along v.
 * @return BS_OK; BS_ERR_INVALID_ARG if b, spans_u or spans_v is NULL, or the statuses of the rules
 *         above (nothing written then).
 * @since 1.1
 */
BS_API bs_status bs_bspline_span_count(const bs_bspline *b, size_t *spans_u, size_t *spans_v);

/**
 * @brief Append a B-spline or NURBS surface as one Bezier patch per knot span.
 *
 * Each patch is the exact restriction of the B-spline to its span (rational for a NURBS), found
 * by evaluating the blossom at the span's end knots: clamped, unclamped and closed knot vectors
 * alike, interior knots of any multiplicity up to degree + 1 (a discontinuity between spans is
 * fine: each span is its own patch). Evaluated at local (u,v), a patch agrees with the B-spline at
 * the mapped parameter within a few units of rounding of max|P| (times wmax/wmin for a NURBS);
 * docs/bspline.md gives the measured figure.
 * @param[in,out] s          the surface; on any failure it is unchanged.
 * @param[in]     b          the B-spline.
 * @param[out]    spans      NULL, or room for spans_cap doubles receiving u0 u1 v0 v1 per added
 *                           patch: the knot span it covers.
 * @param[in]     spans_cap  number of doubles spans can hold (at least 4 per added patch).
 * @param[out]    count      NULL, or receives the number of patches added.
 * @return BS_OK; the statuses of the rules above; BS_ERR_INCOMPATIBLE if the surface already holds
 *         patches of another dimension; BS_ERR_SIZE if spans is too small or the surface would
 *         exceed UINT32_MAX patches; BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_surface_add_bspline(bs_surface *s, const bs_bspline *b, double *spans,
                                        size_t spans_cap, size_t *count);

/**
 * @brief Which patch of bs_surface_add_bspline() holds B-spline parameter (u,v), and where.
 *
 * Spans are half-open, [knots[i], knots[i+1]): a parameter on a knot between two spans belongs to
 * the later one, except at the end of the domain, which belongs to the last span.
 * @param[in]  b        the B-spline (its degrees, counts and knots).
 * @param[in]  u        parameter along u, in the domain [knots_u[deg_u], knots_u[count_u]].
 * @param[in]  v        parameter along v, in the domain.
 * @param[out] index    receives a * spans_v + b for span (a, b): add the index of the first patch
 *                      added to get the patch id in the surface.
 * @param[out] local_u  NULL, or receives the local u in [0,1] on that patch.
 * @param[out] local_v  NULL, or receives the local v in [0,1].
 * @return BS_OK; BS_ERR_INVALID_ARG if b or index is NULL; the statuses of the rules above;
 *         BS_ERR_DOMAIN if u or v is NaN or outside the domain. Nothing is written on failure.
 * @since 1.1
 */
BS_API bs_status bs_bspline_locate(const bs_bspline *b, double u, double v, size_t *index,
                                   double *local_u, double *local_v);

#ifdef __cplusplus
}
#endif

#endif
