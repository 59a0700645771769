/**
 * @file
 * libbezsurf continuity report: how the patches of a surface meet along their shared edges.
 * Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_CONTINUITY_H
#define BEZSURF_CONTINUITY_H

#include "core.h"
#include "surface.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Sides of a patch's unit square, counter-clockwise. The edge parameter t runs along u on the
 *  v sides and along v on the u sides. @since 1.0 */
#define BS_SIDE_V0 0 /**< v = 0, t = u */
#define BS_SIDE_U1 1 /**< u = 1, t = v */
#define BS_SIDE_V1 2 /**< v = 1, t = u */
#define BS_SIDE_U0 3 /**< u = 0, t = v */

/**
 * How two patches meet along one shared edge. Frozen for version 1.
 * Two sides are shared when their control points agree within the tolerance (walked in the same or
 * the opposite direction); collapsed sides (poles) and sides of different degree are never shared.
 * @since 1.0
 */
typedef struct bs_edge_continuity {
    uint32_t patch_a;  /**< the patch with the lower id (or the same patch, lower side) */
    uint32_t patch_b;  /**< the neighbour */
    int side_a;        /**< BS_SIDE_* of patch_a */
    int side_b;        /**< BS_SIDE_* of patch_b */
    int reversed;      /**< 1 if t on side_b is 1 - t on side_a */
    int c1;            /**< 1 if the cross-boundary derivatives are equal and opposite within tol
                            (polynomial patches; always 0 when either patch is rational) */
    int flipped;       /**< 1 if the two patches' normals point to opposite sides (at most samples) */
    int samples;       /**< samples at which both normals exist (used for g1_angle) */
    double c0_gap;     /**< largest distance between corresponding boundary control points */
    double g1_angle;   /**< largest angle in radians between the two tangent planes, sampled */
    double c1_defect;  /**< largest |D_a + D_b| over the edge's control points, D the outward
                            cross-boundary derivative net; NaN when a patch is rational */
} bs_edge_continuity;

/** A side of a patch that no other patch shares (and that is not collapsed to a point). @since 1.0 */
typedef struct bs_open_edge {
    uint32_t patch; /**< patch id */
    int side;       /**< BS_SIDE_* */
} bs_open_edge;

/**
 * @brief Find the shared and open edges of a 3-D surface and measure the continuity across each
 * shared edge (ask for the counts first: arrays NULL).
 *
 * C0 gap: the largest distance between corresponding boundary control points. G1: at t = (k+1/2)/
 * samples, k = 0..samples-1 (corners, where several patches meet and poles sit, are not sampled),
 * the unit normals of both patches from bs_patch_eval_normal(); samples where either normal is
 * BS_NORMAL_UNDEFINED are skipped; g1_angle is the largest angle between the tangent planes (normal
 * orientation ignored; `flipped` reports it). C1: the outward cross-boundary derivative of a patch
 * along a side is the Bezier curve with control points deg * (boundary row - next row inward); C1
 * holds when both curves are opposite, i.e. every |D_a + D_b| <= tol.
 *
 * @param[in]  s          the surface (dim 3; an empty surface has no edges).
 * @param[in]  tol        absolute tolerance, finite and >= 0: per coordinate for matching sides, and
 *                        the C1 test's bound.
 * @param[in]  samples    number of normal samples per edge, 1..4096.
 * @param[out] edges      NULL (count only) or room for edges_cap reports, one per shared edge, in
 *                        order of (patch_a, side_a).
 * @param[in]  edges_cap  number of reports edges can hold (ignored when edges is NULL).
 * @param[out] n_edges    NULL or receives the number of shared edges.
 * @param[out] open       NULL (count only) or room for open_cap open edges, in patch and side order.
 * @param[in]  open_cap   number of entries open can hold (ignored when open is NULL).
 * @param[out] n_open     NULL or receives the number of open edges.
 * @return BS_OK; BS_ERR_INVALID_ARG if s is NULL; BS_ERR_DIMENSION if the surface is not empty and
 *         its dim is not 3; BS_ERR_DOMAIN if tol is negative, NaN or infinite, or samples is 0 or
 *         above 4096; BS_ERR_SIZE if edges_cap or open_cap is too small (nothing is written then);
 *         BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_surface_continuity(const bs_surface *s, double tol, size_t samples,
                                       bs_edge_continuity *edges, size_t edges_cap, size_t *n_edges,
                                       bs_open_edge *open, size_t open_cap, size_t *n_open);

#ifdef __cplusplus
}
#endif

#endif
