/*
 * libbezsurf exact operations: subdivision, sub-patches, degree elevation, hodographs, iso-curves,
 * bounds, transforms, orientation and constructions from curves. Every result is a new, independent
 * patch (or values copied into caller buffers); inputs are never modified.
 * Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_OPS_H
#define BEZSURF_OPS_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Split at t along dir (BS_DIR_U or BS_DIR_V), 0 < t < 1, into the parts over [0,t] and [t,1]. @since 1.0 */
BS_API bs_status bs_patch_split(const bs_patch *p, int dir, double t, bs_patch **lo, bs_patch **hi);

/** Split at (u,v) into four: out[0] [u low, v low], out[1] [u high, v low], out[2] [u low, v high],
 *  out[3] [u high, v high]. @since 1.0 */
BS_API bs_status bs_patch_split4(const bs_patch *p, double u, double v, bs_patch *out[4]);

/** The patch over [u0,u1] x [v0,v1]; u0 > u1 (v0 > v1) reverses that direction. @since 1.0 */
BS_API bs_status bs_patch_subpatch(const bs_patch *p, double u0, double u1, double v0, double v1,
                                   bs_patch **out);

/** The same surface with degrees raised by raise_u and raise_v. @since 1.0 */
BS_API bs_status bs_patch_elevate(const bs_patch *p, size_t raise_u, size_t raise_v, bs_patch **out);

/** The difference-net (hodograph) patch of d^(ku+kv)S/du^ku dv^kv; polynomial patches only. @since 1.0 */
BS_API bs_status bs_patch_derivative(const bs_patch *p, unsigned ku, unsigned kv, bs_patch **out);

/** Control points (and weights) of the iso-curve u = t (dir BS_DIR_U, a curve in v of degree deg_v)
 *  or v = t (dir BS_DIR_V, a curve in u of degree deg_u). @since 1.0 */
BS_API bs_status bs_patch_isocurve(const bs_patch *p, int dir, double t, double *ctrl, size_t ctrl_cap,
                                   double *weights, size_t weights_cap);

/** Bounding box of the control net (dim values each in lo and hi); contains the patch. @since 1.0 */
BS_API bs_status bs_patch_bounds(const bs_patch *p, double *lo, double *hi);

/** The patch with the affine map x -> A x + b applied to its net; affine is dim x (dim+1), row-major,
 *  the last column being b. @since 1.0 */
BS_API bs_status bs_patch_transform(const bs_patch *p, const double *affine, bs_patch **out);

#ifdef __cplusplus
}
#endif

#endif
