/**
 * @file
 * libbezsurf geometric queries (from 1.1): curvature of a patch, certified closest points on a
 * patch, and a locator (bounding-volume hierarchy) for closest points and ray intersection on a
 * whole surface. Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_QUERY_H
#define BEZSURF_QUERY_H

#include "core.h"
#include "surface.h"

#include <stdint.h>

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

/**
 * @brief The globally closest point of a patch to each of n query points.
 *
 * Any dimension. The answer is global over the whole domain [0,1]^2, boundary included: the
 * distance returned is at most the exact minimum of |S(u,v) - q| plus tau = 1e-9 (D + d), D the
 * diagonal of the bounding box of the control points and d the exact minimum. Where several points
 * are equally close, any of them. `pos` is bit for bit what bs_patch_eval() gives at `uv`, and
 * `dist` is |pos - q| rounded. A query point with a NaN or infinite coordinate gives NaN in every
 * output of that point. Algorithm and cost: docs/queries.md.
 *
 * Views, NULL and n = 0 follow the rules of bs_patch_eval(); nothing is written when a check fails.
 * @param[in]  p     the patch.
 * @param[in]  n     number of query points.
 * @param[in]  q     dim views of n query coordinates.
 * @param[out] uv    NULL or 2 views receiving the parameters of the closest points.
 * @param[out] dist  NULL or 1 view receiving the distances.
 * @param[out] pos   NULL or dim views receiving the closest points.
 * @return BS_OK; BS_ERR_INVALID_ARG if p is NULL, q is NULL with n > 0, or a view's data is NULL or
 *         misaligned; BS_ERR_SIZE if a view holds fewer than n elements; BS_ERR_NO_MEMORY.
 * @return BS_ERR_PRECISION (from 1.2) if an answer cannot be certified within tau: a rational
 *         patch whose weights span more than 2^159 (max w / min w), or a query whose search meets
 *         the depth or box limits (docs/queries.md, "The limit of the guarantee"); nothing is
 *         written then. Never a wrong answer in its place.
 * @since 1.1
 */
BS_API bs_status bs_patch_closest_point(const bs_patch *p, size_t n, const bs_cview *q,
                                        const bs_view *uv, const bs_view *dist, const bs_view *pos);

/**
 * Opaque, immutable acceleration structure over a surface for closest points and rays. It keeps
 * its own copy of what it needs, so the surface may be changed or destroyed afterwards, and any
 * number of threads may query one locator at once. @since 1.1
 */
typedef struct bs_locator bs_locator;

/**
 * @brief Build a locator (a bounding-volume hierarchy over the patches and their sub-patches) for a
 * surface. Memory: docs/queries.md gives the bytes per patch.
 * @param[in]  s    the surface (any dimension; rays need dimension 3). An empty surface gives a
 *                  locator on which every query misses (distance +Inf, patch UINT32_MAX).
 * @param[out] out  receives the locator (NULL on failure); release with bs_locator_destroy().
 * @return BS_OK; BS_ERR_INVALID_ARG if s or out is NULL; BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_locator_create(const bs_surface *s, bs_locator **out);

/**
 * @brief Release a locator.
 * @param[in] L  the locator; NULL is a no-op.
 * @since 1.1
 */
BS_API void bs_locator_destroy(bs_locator *L);

/**
 * @brief Dimension of the locator's surface.
 * @param[in] L  the locator, or NULL.
 * @return the dimension; 0 for NULL or an empty surface.
 * @since 1.1
 */
BS_API size_t bs_locator_dim(const bs_locator *L);

/**
 * @brief The globally closest point of the whole surface to each of n query points, with the
 * guarantee of bs_patch_closest_point() (D now the diagonal of the surface's control points).
 * @param[in]  L      the locator.
 * @param[in]  n      number of query points.
 * @param[in]  q      dim views of n query coordinates.
 * @param[out] patch  NULL or n patch ids of the answers (UINT32_MAX where there is none: a NaN
 *                    query or an empty surface).
 * @param[out] uv     NULL or 2 views receiving the parameters.
 * @param[out] dist   NULL or 1 view receiving the distances.
 * @param[out] pos    NULL or dim views receiving the closest points.
 * On a model's locator (bs_locator_create_model(), since 1.2) the answer is the closest point of
 * the union of the trimmed faces, with the same guarantee: `patch` receives the face id and `uv`
 * the native face parameters (docs/models.md).
 * @return as bs_patch_closest_point(), with L in place of p (BS_ERR_PRECISION when a patch that
 *         could hold the answer cannot be certified, or on a model a trim near the answer;
 *         nothing is written then).
 * @since 1.1
 */
BS_API bs_status bs_locator_closest_point(const bs_locator *L, size_t n, const bs_cview *q,
                                          uint32_t *patch, const bs_view *uv, const bs_view *dist,
                                          const bs_view *pos);

/**
 * @brief The first hit of each of n rays o + t d with the surface, t in [t_min, t_max].
 *
 * A reported hit point S(u,v) lies within tau = 1e-9 D + 2^-40 |S - o| of the ray and t within
 * tau/|d| of the exact first hit (the second term, from 1.2, is the rounding of S - o for an
 * origin far from the surface; 1.1 stated 1e-9 D alone, which such rays exceeded). No ray whose
 * exact first hit is transversal (|d.N| >= 1e-3 |d|) is missed or answered with a later hit,
 * including rays through shared edges, corners and poles (measured on rational patches with
 * weights 2^-40 .. 2^40 up to degree (2,2) and 2^-12 .. 2^12 above; wider weights next to a pole
 * can exhaust the search's per-sub-patch budget: docs/queries.md). Tangent and grazing hits may
 * be reported or not. t is a double: hits beyond t = DBL_MAX are not looked for (a direction of subnormal
 * length reaches only DBL_MAX |d| along the ray; 1.1 reported them with t = +Inf). On a miss:
 * patch UINT32_MAX, t = +Inf, uv and nrm NaN. A NaN or Inf in o or d, a NaN in the range, an
 * infinite t_min, a t_max of -Inf, or d = 0, is a miss with t = NaN. A t_max of +Inf means no
 * upper limit (since 1.2; 1.1 took it for an invalid ray, so a program for both passes DBL_MAX).
 * Normals follow the rule of bs_patch_eval_normal() (limit normals at poles,
 * (0,0,0) where there is none: bs_locator_intersect_kind() tells which).
 * @param[in]  L       the locator (dimension 3).
 * @param[in]  n       number of rays.
 * @param[in]  org     3 views: ray origins.
 * @param[in]  dir     3 views: directions, any non-zero length.
 * @param[in]  trange  NULL for (0, +Inf), or 2 views: t_min (finite), t_max (finite or +Inf).
 * @param[out] patch   NULL or n patch ids; UINT32_MAX where the ray misses.
 * @param[out] uv      NULL or 2 views.
 * @param[out] t       NULL or 1 view: the ray parameter of the hit.
 * @param[out] nrm     NULL or 3 views: the unit normal at the hit.
 * @return BS_OK; BS_ERR_INVALID_ARG if L is NULL, org or dir is NULL with n > 0, or a view's data
 *         is NULL or misaligned; BS_ERR_DIMENSION if the surface is not 3-D (and not empty);
 *         BS_ERR_SIZE if a view holds fewer than n elements; BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_locator_intersect(const bs_locator *L, size_t n, const bs_cview *org,
                                      const bs_cview *dir, const bs_cview *trange, uint32_t *patch,
                                      const bs_view *uv, const bs_view *t, const bs_view *nrm);

/**
 * @brief bs_locator_intersect(), with the kind of each hit's normal: BS_NORMAL_REGULAR,
 * BS_NORMAL_LIMIT (a pole or a collapsed edge) or BS_NORMAL_UNDEFINED (a degenerate point, where
 * (0,0,0) is written), exactly bs_patch_eval_normal()'s kind at the hit's (u, v); misses and
 * invalid rays have kind BS_NORMAL_UNDEFINED. Same answers, bit for bit, as bs_locator_intersect().
 * @param[in]  L       the locator (dimension 3).
 * @param[in]  n       number of rays.
 * @param[in]  org     3 views: ray origins.
 * @param[in]  dir     3 views: directions, any non-zero length.
 * @param[in]  trange  NULL for (0, +Inf), or 2 views: t_min, t_max.
 * @param[out] patch   NULL or n patch ids; UINT32_MAX where the ray misses.
 * @param[out] uv      NULL or 2 views.
 * @param[out] t       NULL or 1 view: the ray parameter of the hit.
 * @param[out] nrm     NULL or 3 views: the unit normal at the hit.
 * @param[out] kind    NULL or n bytes receiving the normal kinds.
 * @return as bs_locator_intersect().
 * @since 1.2
 */
BS_API bs_status bs_locator_intersect_kind(const bs_locator *L, size_t n, const bs_cview *org,
                                           const bs_cview *dir, const bs_cview *trange,
                                           uint32_t *patch, const bs_view *uv, const bs_view *t,
                                           const bs_view *nrm, unsigned char *kind);

/**
 * @brief bs_locator_closest_point() on up to `threads` threads: the queries are cut into pieces of
 * 64, each answered by one thread, so every answer is bit-identical to bs_locator_closest_point()
 * whatever the thread count. Every thread started is joined before the call returns; a thread that
 * cannot be created leaves its share to the others. Arguments and statuses as
 * bs_locator_closest_point(), all checked before any thread starts; with more than one thread,
 * BS_ERR_NO_MEMORY may come after other pieces have been answered and written.
 * @param[in]  L        the locator.
 * @param[in]  n        number of query points.
 * @param[in]  q        dim views of n query coordinates.
 * @param[out] patch    NULL or n patch ids of the answers.
 * @param[out] uv       NULL or 2 views receiving the parameters.
 * @param[out] dist     NULL or 1 view receiving the distances.
 * @param[out] pos      NULL or dim views receiving the closest points.
 * @param[in]  threads  threads to use, the calling one included: 1 stays on the calling thread,
 *                      0 = one per online CPU.
 * @return as bs_locator_closest_point().
 * @since 1.1
 */
BS_API bs_status bs_locator_closest_point_mt(const bs_locator *L, size_t n, const bs_cview *q,
                                             uint32_t *patch, const bs_view *uv, const bs_view *dist,
                                             const bs_view *pos, size_t threads);

/**
 * @brief bs_locator_intersect() on up to `threads` threads: the rays are cut into pieces of 512,
 * each traced by one thread, so every answer is bit-identical to bs_locator_intersect() whatever
 * the thread count. Threads, argument checks and BS_ERR_NO_MEMORY as for
 * bs_locator_closest_point_mt().
 * @param[in]  L        the locator (dimension 3).
 * @param[in]  n        number of rays.
 * @param[in]  org      3 views: ray origins.
 * @param[in]  dir      3 views: directions, any non-zero length.
 * @param[in]  trange   NULL for (0, +Inf), or 2 views: t_min (finite), t_max (finite or +Inf).
 * @param[out] patch    NULL or n patch ids; UINT32_MAX where the ray misses.
 * @param[out] uv       NULL or 2 views.
 * @param[out] t        NULL or 1 view: the ray parameter of the hit.
 * @param[out] nrm      NULL or 3 views: the unit normal at the hit.
 * @param[in]  threads  threads to use, the calling one included: 1 stays on the calling thread,
 *                      0 = one per online CPU.
 * @return as bs_locator_intersect().
 * @since 1.1
 */
BS_API bs_status bs_locator_intersect_mt(const bs_locator *L, size_t n, const bs_cview *org,
                                         const bs_cview *dir, const bs_cview *trange, uint32_t *patch,
                                         const bs_view *uv, const bs_view *t, const bs_view *nrm,
                                         size_t threads);

#ifdef __cplusplus
}
#endif

#endif
