/*
 * libbezsurf surfaces: ordered sets of patches (a quilt such as the Utah teapot).
 * Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_SURFACE_H
#define BEZSURF_SURFACE_H

#include "core.h"

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
 * @brief Release a surface and the patches it holds. NULL is a no-op.
 * @since 1.0
 */
BS_API void bs_surface_destroy(bs_surface *s);

/**
 * @brief Make an independent copy of a surface.
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

/** @brief Number of patches; 0 for NULL. @since 1.0 */
BS_API size_t bs_surface_count(const bs_surface *s);

/** @brief Dimension of the patches; 0 for an empty or NULL surface. @since 1.0 */
BS_API size_t bs_surface_dim(const bs_surface *s);

/**
 * @brief Borrow patch i. The pointer stays valid until the surface is destroyed.
 * @return the patch, or NULL if s is NULL or i >= bs_surface_count(s).
 * @since 1.0
 */
BS_API const bs_patch *bs_surface_get(const bs_surface *s, size_t i);

#ifdef __cplusplus
}
#endif

#endif
