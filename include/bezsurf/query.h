/**
 * @file
 * libbezsurf geometric queries (from 1.1): curvature of a patch. Closest points and ray
 * intersection will join this header. Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_QUERY_H
#define BEZSURF_QUERY_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BS_CURV_REGULAR   0 /**< from the first and second fundamental forms at the point */
#define BS_CURV_LIMIT     1 /**< a limit point: the limit along the line towards (1/2,1/2) */
#define BS_CURV_UNDEFINED 2 /**< no finite curvature there (e.g. a cone's apex); NaN written */

/**
 * @brief Gaussian, mean and principal curvatures and principal directions at n scattered points
 * of a 3-D patch.
 *
 * Signs are taken with respect to the unit normal N of bs_patch_eval_normal() at the same point:
 * the normal curvature in a tangent direction t is II(t)/I(t), II built from S_uu.N, S_uv.N and
 * S_vv.N, so a sphere whose normals point outwards has k = -1/r. K = k_min k_max,
 * H = (k_min + k_max)/2, k_min <= k_max. The directions are unit tangent vectors with
 * (dmin, dmax, N) right-handed. Where the point is umbilic or planar,
 * k_max - k_min <= 1e-10 (|k_min| + |k_max| + 1/D) (D the diagonal of the bounding box of the
 * control points), every tangent direction is principal: dmin is S_u made unit (S_v where S_u
 * vanishes), and dmax = N x dmin.
 *
 * Where the normal is a limit normal (collapsed edges, poles: kind BS_NORMAL_LIMIT of
 * bs_patch_eval_normal()), the curvatures and directions are their limits along the straight line
 * from the point towards the domain centre (1/2,1/2), kind BS_CURV_LIMIT. Where that limit does not
 * exist or is not finite (a cone's apex), where the normal is undefined, and at the centre itself
 * when it is degenerate, the kind is BS_CURV_UNDEFINED and every output of the point is NaN.
 * Accuracy (docs/queries.md): at regular points within 1e-9 (|k_min| + |k_max| + 1/D) of the exact
 * values, directions within 1e-8 rad away from umbilics; at limit points within 1e-6 of that scale.
 *
 * Views, NULL and n = 0 follow the rules of bs_patch_eval(); parameters outside [0,1] are
 * extrapolated; a NaN or infinite parameter gives NaN outputs and BS_CURV_UNDEFINED for that point
 * only. Nothing is written when a check fails.
 * @param[in]  p     the patch (dim 3).
 * @param[in]  n     number of points.
 * @param[in]  u     view of n u-parameters.
 * @param[in]  v     view of n v-parameters.
 * @param[out] curv  NULL or 4 views receiving K, H, k_min and k_max.
 * @param[out] dmin  NULL or 3 views receiving the unit principal direction of k_min.
 * @param[out] dmax  NULL or 3 views receiving the unit principal direction of k_max.
 * @param[out] kind  NULL or n bytes receiving BS_CURV_REGULAR, BS_CURV_LIMIT or BS_CURV_UNDEFINED.
 * @return BS_OK; BS_ERR_INVALID_ARG if p is NULL (or u, v NULL with n > 0, or NULL or misaligned
 *         view data); BS_ERR_DIMENSION if the patch is not 3-D; BS_ERR_SIZE if a view holds fewer
 *         than n elements; BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_patch_eval_curvature(const bs_patch *p, size_t n, const bs_cview *u,
                                         const bs_cview *v, const bs_view *curv,
                                         const bs_view *dmin, const bs_view *dmax,
                                         unsigned char *kind);

#ifdef __cplusplus
}
#endif

#endif
