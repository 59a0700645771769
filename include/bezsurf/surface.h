/**
 * @file
 * libbezsurf surfaces: ordered sets of patches (a quilt such as the Utah teapot).
 * Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_SURFACE_H
#define BEZSURF_SURFACE_H

#include "core.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Opaque, growable, ordered set of patches of one dimension (degrees and rationality may differ).
 * Reading functions take `const bs_surface *` and may run in any number of threads at once;
 * bs_surface_add() must not run while another thread uses the same surface. @since 1.0
 */
typedef struct bs_surface bs_surface;

/**
 * @brief Create an empty surface. Its dimension is fixed by the first patch added.
 * @param[out] out receives the surface (NULL on failure); release with bs_surface_destroy().
 * @return BS_OK; BS_ERR_INVALID_ARG if out is NULL; BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_surface_create(bs_surface **out);

/**
 * @brief Release a surface and the patches it holds.
 * @param[in] s  the surface; NULL is a no-op.
 * @since 1.0
 */
BS_API void bs_surface_destroy(bs_surface *s);

/**
 * @brief Make an independent copy of a surface.
 * @param[in]  s    the surface.
 * @param[out] out  receives the copy (NULL on failure); release with bs_surface_destroy().
 * @return BS_OK; BS_ERR_INVALID_ARG if s or out is NULL; BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_surface_clone(const bs_surface *s, bs_surface **out);

/**
 * @brief Append a copy of a patch.
 * @param[in,out] s      the surface.
 * @param[in]     p      the patch; copied, the caller keeps ownership of p.
 * @param[out]    index  NULL or receives the new patch's index (its patch id).
 * @return BS_OK; BS_ERR_INVALID_ARG if s or p is NULL; BS_ERR_INCOMPATIBLE if p's dimension differs
 *         from the surface's; BS_ERR_SIZE if the surface already holds UINT32_MAX patches;
 *         BS_ERR_NO_MEMORY (the surface is unchanged then).
 * @since 1.0
 */
BS_API bs_status bs_surface_add(bs_surface *s, const bs_patch *p, size_t *index);

/**
 * @brief Number of patches.
 * @param[in] s  the surface, or NULL.
 * @return the number of patches; 0 for NULL.
 * @since 1.0
 */
BS_API size_t bs_surface_count(const bs_surface *s);

/**
 * @brief Dimension of the patches.
 * @param[in] s  the surface, or NULL.
 * @return the dimension of its patches; 0 for an empty or NULL surface.
 * @since 1.0
 */
BS_API size_t bs_surface_dim(const bs_surface *s);

/**
 * @brief Borrow patch i. The pointer stays valid until the surface is destroyed.
 * @param[in] s  the surface.
 * @param[in] i  the patch id, 0 .. bs_surface_count(s) - 1.
 * @return the patch, or NULL if s is NULL or i >= bs_surface_count(s).
 * @since 1.0
 */
BS_API const bs_patch *bs_surface_get(const bs_surface *s, size_t i);

/* ------------------------------------------------------------------------------------------------
 * Evaluation of scattered points across a surface: point k lies on patch ids[k] at (u[k], v[k]).
 * Consecutive points with the same id are evaluated in one call to the patch evaluator, so sorting
 * the points by id makes the per-point overhead vanish; results do not depend on the order.
 * Arguments are checked in this order, the first failure returned with nothing written: s, ids, u or
 * v NULL (BS_ERR_INVALID_ARG); normals of a surface whose dim is not 3 (BS_ERR_DIMENSION); each view
 * as for bs_patch_eval() (BS_ERR_INVALID_ARG, BS_ERR_SIZE); an id not below bs_surface_count()
 * (BS_ERR_INVALID_ARG). n = 0 with a non-NULL s is a successful no-op (nothing else is read).
 * Parameters outside [0,1] are extrapolated; a NaN or infinite parameter gives NaN outputs for that
 * point only (kind BS_NORMAL_UNDEFINED), as in bs_patch_eval(). Results are bit-identical to the
 * patch evaluators called point by point.
 * ---------------------------------------------------------------------------------------------- */

/**
 * @brief Evaluate positions and first partial derivatives at n scattered points of a surface.
 * NULL, n = 0, short views, NaN and Inf parameters: see the rules above.
 * @param[in]  s    the surface.
 * @param[in]  n    number of points.
 * @param[in]  ids  n patch ids (indices into the surface), each below bs_surface_count(s).
 * @param[in]  u    view of n u-parameters.
 * @param[in]  v    view of n v-parameters.
 * @param[out] pos  NULL or bs_surface_dim(s) views receiving S(u,v).
 * @param[out] du   NULL or bs_surface_dim(s) views receiving dS/du.
 * @param[out] dv   NULL or bs_surface_dim(s) views receiving dS/dv.
 * @return BS_OK; BS_ERR_INVALID_ARG (s, ids, u or v NULL, NULL or misaligned view data, an id out of
 *         range); BS_ERR_SIZE (a view shorter than n).
 * @since 1.0
 */
BS_API bs_status bs_surface_eval(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                                 const bs_cview *v, const bs_view *pos, const bs_view *du, const bs_view *dv);

/**
 * @brief Evaluate positions and unit normals (with their kind) at n scattered points of a 3-D surface.
 * Normals follow the rule of bs_patch_eval_normal(). NULL, n = 0, short views, NaN and Inf
 * parameters: see the rules above.
 * @param[in]  s     the surface (dim 3).
 * @param[in]  n     number of points.
 * @param[in]  ids   n patch ids, each below bs_surface_count(s).
 * @param[in]  u     view of n u-parameters.
 * @param[in]  v     view of n v-parameters.
 * @param[out] pos   NULL or 3 views receiving S(u,v).
 * @param[out] nrm   NULL or 3 views receiving the unit normal.
 * @param[out] kind  NULL or n bytes receiving BS_NORMAL_REGULAR, _LIMIT or _UNDEFINED.
 * @return BS_OK; BS_ERR_INVALID_ARG (s, ids, u or v NULL, NULL or misaligned view data, an id out of
 *         range); BS_ERR_DIMENSION (n > 0 and the surface's dim is not 3, including an empty surface);
 *         BS_ERR_SIZE (a view shorter than n).
 * @since 1.0
 */
BS_API bs_status bs_surface_eval_normal(const bs_surface *s, size_t n, const uint32_t *ids,
                                        const bs_cview *u, const bs_cview *v, const bs_view *pos,
                                        const bs_view *nrm, unsigned char *kind);

/**
 * @brief bs_surface_eval() on up to `threads` threads: the points are cut into pieces of 4096, each
 * evaluated by one thread, so the results are bit-identical to bs_surface_eval() whatever the
 * thread count. Every thread started is joined before the call returns; a thread that cannot be
 * created leaves its share to the calling thread. Arguments and statuses as bs_surface_eval()
 * (checked before any thread starts).
 * @param[in]  s        the surface.
 * @param[in]  n        number of points.
 * @param[in]  ids      n patch ids, each below bs_surface_count(s).
 * @param[in]  u        view of n u-parameters.
 * @param[in]  v        view of n v-parameters.
 * @param[out] pos      NULL or bs_surface_dim(s) views receiving S(u,v).
 * @param[out] du       NULL or bs_surface_dim(s) views receiving dS/du.
 * @param[out] dv       NULL or bs_surface_dim(s) views receiving dS/dv.
 * @param[in]  threads  threads to use, the calling one included: 1 stays on the calling thread,
 *                      0 = one per online CPU.
 * @return BS_OK; BS_ERR_INVALID_ARG (s, ids, u or v NULL, NULL or misaligned view data, an id out of
 *         range); BS_ERR_SIZE (a view shorter than n).
 * @since 1.1
 */
BS_API bs_status bs_surface_eval_mt(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                                    const bs_cview *v, const bs_view *pos, const bs_view *du,
                                    const bs_view *dv, size_t threads);

/**
 * @brief bs_surface_eval_normal() on up to `threads` threads: the points are cut into pieces of 4096,
 * each evaluated by one thread, so the results (positions, normals and kinds) are bit-identical to
 * bs_surface_eval_normal() whatever the thread count. Every thread started is joined before the call
 * returns; a thread that cannot be created leaves its share to the calling thread. Arguments and
 * statuses as bs_surface_eval_normal() (checked before any thread starts).
 * @param[in]  s        the surface (dim 3).
 * @param[in]  n        number of points.
 * @param[in]  ids      n patch ids, each below bs_surface_count(s).
 * @param[in]  u        view of n u-parameters.
 * @param[in]  v        view of n v-parameters.
 * @param[out] pos      NULL or 3 views receiving S(u,v).
 * @param[out] nrm      NULL or 3 views receiving the unit normal.
 * @param[out] kind     NULL or n bytes receiving BS_NORMAL_REGULAR, _LIMIT or _UNDEFINED.
 * @param[in]  threads  threads to use, the calling one included: 1 stays on the calling thread,
 *                      0 = one per online CPU.
 * @return BS_OK; BS_ERR_INVALID_ARG (s, ids, u or v NULL, NULL or misaligned view data, an id out of
 *         range); BS_ERR_DIMENSION (n > 0 and the surface's dim is not 3, including an empty surface);
 *         BS_ERR_SIZE (a view shorter than n).
 * @since 1.2
 */
BS_API bs_status bs_surface_eval_normal_mt(const bs_surface *s, size_t n, const uint32_t *ids,
                                           const bs_cview *u, const bs_cview *v, const bs_view *pos,
                                           const bs_view *nrm, unsigned char *kind, size_t threads);

/**
 * @brief Evaluate the same tensor grid on every patch of a surface, on up to `threads` threads:
 * point (u[a], v[b]) of patch p is written at output index (p*nu + a)*nv + b. Each output is
 * bit-identical to bs_patch_eval_grid() on that patch (and so to bs_patch_eval()), whatever the
 * thread count: the grids are cut into pieces of whole rows fixed by nv alone, each written by one
 * thread. Every thread started is joined before the call returns; a thread that cannot be created
 * leaves its share to the calling thread. An empty surface, nu = 0 or nv = 0 is a successful no-op
 * once the arguments are checked.
 * @param[in]  s        the surface.
 * @param[in]  nu       number of u-parameters.
 * @param[in]  u        view of nu u-parameters.
 * @param[in]  nv       number of v-parameters.
 * @param[in]  v        view of nv v-parameters.
 * @param[out] pos      NULL or bs_surface_dim(s) views of count*nu*nv elements receiving S.
 * @param[out] du       NULL or bs_surface_dim(s) views receiving dS/du.
 * @param[out] dv       NULL or bs_surface_dim(s) views receiving dS/dv.
 * @param[out] nrm      NULL or 3 views receiving unit normals (dim must be 3 when not NULL).
 * @param[out] kind     NULL or count*nu*nv bytes receiving the normal kinds (dim 3).
 * @param[in]  threads  threads to use, the calling one included: 1 stays on the calling thread,
 *                      0 = one per online CPU.
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if s, u or v is NULL, or a view's data is NULL or misaligned.
 * @return BS_ERR_DIMENSION if nrm or kind is given and the surface's dim is not 3 (an empty
 *         surface included; checked before the views).
 * @return BS_ERR_SIZE if u or v is shorter than nu or nv, count*nu*nv overflows size_t, or an output
 *         view holds fewer than count*nu*nv elements.
 * @return BS_ERR_NO_MEMORY if the scratch space of a piece (under 300 kB) cannot be allocated; the
 *         pieces evaluated before may then have been written.
 * @since 1.1
 */
BS_API bs_status bs_surface_eval_grid(const bs_surface *s, size_t nu, const bs_cview *u, size_t nv,
                                      const bs_cview *v, const bs_view *pos, const bs_view *du,
                                      const bs_view *dv, const bs_view *nrm, unsigned char *kind,
                                      size_t threads);

#ifdef __cplusplus
}
#endif

#endif
