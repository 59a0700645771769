/**
 * @file
 * libbezsurf exact operations: subdivision, sub-patches, degree elevation, hodographs, iso-curves,
 * bounds, transforms, orientation and constructions from curves. Every result is a new, independent
 * patch (or values copied into caller buffers); inputs are never modified.
 * Include <bezsurf.h> rather than this file.
 *
 * Common rules (see docs/operations.md):
 * - Rational patches are processed in homogeneous coordinates (w*P, w); the Cartesian points of a
 *   result are recovered by one division per coordinate.
 * - On failure every output is untouched, except that new-handle outputs (`bs_patch **`) are set
 *   to NULL (all of them, when a call has several).
 * - A result coordinate that overflows, or a result weight that is not positive (possible only when
 *   a rational patch is extrapolated outside [0,1]), gives BS_ERR_NONFINITE.
 */
#ifndef BEZSURF_OPS_H
#define BEZSURF_OPS_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Split a patch at t along one direction (de Casteljau) into the parts over [0,t] and [t,1].
 * The two halves keep the parent's degrees and rationality; their common boundary row (dir BS_DIR_U)
 * or column (dir BS_DIR_V) of control points (and weights) is identical bit for bit.
 * @param[in]  p    the patch.
 * @param[in]  dir  BS_DIR_U (split u at t) or BS_DIR_V (split v at t).
 * @param[in]  t    split parameter, 0 < t < 1 (NaN, Inf, 0, 1 and values outside are rejected).
 * @param[out] lo   receives the part over [0,t] in that direction (NULL on failure).
 * @param[out] hi   receives the part over [t,1] in that direction (NULL on failure); must differ from lo.
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p, lo or hi is NULL, lo == hi, or dir is neither BS_DIR_U nor BS_DIR_V.
 * @return BS_ERR_DOMAIN if t is NaN or not strictly between 0 and 1.
 * @return BS_ERR_NONFINITE if a result coordinate is not representable.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_split(const bs_patch *p, int dir, double t, bs_patch **lo, bs_patch **hi);

/**
 * @brief Split a patch at (u,v) into four: first along u, then each half along v.
 * out[0] covers [0,u]x[0,v], out[1] [u,1]x[0,v], out[2] [0,u]x[v,1], out[3] [u,1]x[v,1].
 * Neighbouring parts share their common boundary control points bit for bit.
 * @param[in]  p    the patch.
 * @param[in]  u    split parameter along u, 0 < u < 1.
 * @param[in]  v    split parameter along v, 0 < v < 1.
 * @param[out] out  array of four handles; all four receive NULL on failure.
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or out is NULL.
 * @return BS_ERR_DOMAIN if u or v is NaN or not strictly between 0 and 1.
 * @return BS_ERR_NONFINITE if a result coordinate is not representable.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_split4(const bs_patch *p, double u, double v, bs_patch *out[4]);

/**
 * @brief The patch over the sub-rectangle [u0,u1] x [v0,v1], reparametrised over [0,1]^2.
 * The result Q satisfies Q(s,r) = P(u0 + s(u1-u0), v0 + r(v1-v0)); so u0 > u1 (v0 > v1) reverses
 * that direction. Any finite parameters are accepted: values outside [0,1] extrapolate the
 * polynomial (exact in exact arithmetic; accuracy degrades with the distance from [0,1]).
 * Computed by blossoming: control point (i,j) is the blossom at (u0^(m-i), u1^i; v0^(n-j), v1^j).
 * @param[in]  p    the patch.
 * @param[in]  u0   start of the u interval (finite).
 * @param[in]  u1   end of the u interval (finite, != u0).
 * @param[in]  v0   start of the v interval (finite).
 * @param[in]  v1   end of the v interval (finite, != v0).
 * @param[out] out  receives the sub-patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or out is NULL.
 * @return BS_ERR_DOMAIN if a parameter is NaN or infinite, or u0 == u1, or v0 == v1.
 * @return BS_ERR_NONFINITE if a result coordinate overflows or (rational, extrapolated) a result
 *         weight is not positive.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_subpatch(const bs_patch *p, double u0, double u1, double v0, double v1,
                                   bs_patch **out);

/**
 * @brief The same surface with its degrees raised by raise_u and raise_v (in one step each:
 * Q_k = sum_i C(m,i) C(r,k-i) / C(m+r,k) P_i, in homogeneous coordinates for rational patches).
 * Raising by 0 and 0 gives a copy.
 * @param[in]  p        the patch.
 * @param[in]  raise_u  how much to raise the degree along u; deg_u + raise_u <= BS_MAX_DEGREE.
 * @param[in]  raise_v  how much to raise the degree along v; deg_v + raise_v <= BS_MAX_DEGREE.
 * @param[out] out      receives the elevated patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or out is NULL.
 * @return BS_ERR_DEGREE if a resulting degree would exceed BS_MAX_DEGREE.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_elevate(const bs_patch *p, size_t raise_u, size_t raise_v, bs_patch **out);

/**
 * @brief The hodograph: the Bezier patch of d^(ku+kv)S / du^ku dv^kv, of degree (m-ku, n-kv), with
 * the scaled difference net m!/(m-ku)! n!/(n-kv)! Delta^(ku,kv) P. Polynomial patches only.
 * If ku > m or kv > n the derivative is identically zero and the result is the zero patch of
 * degree (0,0) (dim unchanged). (0,0) gives a copy.
 * @param[in]  p    the patch (polynomial).
 * @param[in]  ku   order along u, 0..BS_MAX_DEGREE.
 * @param[in]  kv   order along v, 0..BS_MAX_DEGREE.
 * @param[out] out  receives the hodograph (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or out is NULL.
 * @return BS_ERR_DEGREE if ku or kv exceeds BS_MAX_DEGREE.
 * @return BS_ERR_UNSUPPORTED if p is rational (its derivatives are not Bezier patches).
 * @return BS_ERR_NONFINITE if a coefficient of the result overflows.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_derivative(const bs_patch *p, unsigned ku, unsigned kv, bs_patch **out);

/**
 * @brief Control points (and weights) of an iso-parametric curve of the patch.
 * dir BS_DIR_U: the curve u = t, a Bezier curve in v of degree deg_v, (deg_v+1) points;
 * dir BS_DIR_V: the curve v = t, a Bezier curve in u of degree deg_u, (deg_u+1) points.
 * Points are packed, point k coordinate c at ctrl[k*dim + c], Cartesian. t = 0 and t = 1 copy the
 * net's boundary row or column (and weights) exactly. Any finite t is accepted (outside [0,1] the
 * curve is extrapolated). For a rational patch the curve is rational: its weights are written to
 * `weights` when it is not NULL; passing NULL is allowed but then the points alone do not describe
 * the curve. For a polynomial patch the weights written are all 1.0.
 * @param[in]  p            the patch.
 * @param[in]  dir          BS_DIR_U (u = t) or BS_DIR_V (v = t).
 * @param[in]  t            the fixed parameter (finite).
 * @param[out] ctrl         room for ctrl_cap doubles; receives (count)*dim doubles.
 * @param[in]  ctrl_cap     number of doubles ctrl can hold.
 * @param[out] weights      NULL (not wanted) or room for weights_cap doubles; receives count weights.
 * @param[in]  weights_cap  number of doubles weights can hold (ignored when weights is NULL).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or ctrl is NULL, or dir is neither BS_DIR_U nor BS_DIR_V.
 * @return BS_ERR_DOMAIN if t is NaN or infinite.
 * @return BS_ERR_SIZE if ctrl_cap or (weights given) weights_cap is too small; nothing is written.
 * @return BS_ERR_NONFINITE if a result value overflows or (rational, extrapolated) a weight is not
 *         positive; nothing is written.
 * @since 1.0
 */
BS_API bs_status bs_patch_isocurve(const bs_patch *p, int dir, double t, double *ctrl, size_t ctrl_cap,
                                   double *weights, size_t weights_cap);

/**
 * @brief Axis-aligned bounding box of the control net (Cartesian points). By the convex-hull
 * property it contains the patch over [0,1]^2 (rational ones too, weights being positive); it is
 * conservative, usually larger than the tightest box of the surface.
 * @param[in]  p   the patch.
 * @param[out] lo  room for dim doubles; receives the smallest coordinate of the net per axis.
 * @param[out] hi  room for dim doubles; receives the largest coordinate of the net per axis.
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p, lo or hi is NULL.
 * @since 1.0
 */
BS_API bs_status bs_patch_bounds(const bs_patch *p, double *lo, double *hi);

/**
 * @brief The patch with the affine map x -> A x + b applied to its control points. For rational
 * patches the Cartesian points are mapped and the weights kept (affine invariance makes this the
 * image of the surface).
 * @param[in]  p       the patch.
 * @param[in]  affine  dim x (dim+1) doubles, row-major: row r is (A[r][0..dim-1], b[r]).
 * @param[out] out     receives the transformed patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p, affine or out is NULL.
 * @return BS_ERR_NONFINITE if a mapped coordinate is NaN or infinite (a non-finite entry of affine,
 *         or overflow).
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_transform(const bs_patch *p, const double *affine, bs_patch **out);

/**
 * @brief The same surface with u and v exchanged: Q(u,v) = P(v,u), degree (deg_v, deg_u),
 * Q[j][i] = P[i][j]. Values are copied exactly. Note that the normal S_u x S_v changes sign.
 * @param[in]  p    the patch.
 * @param[out] out  receives the swapped patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or out is NULL.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_swap_uv(const bs_patch *p, bs_patch **out);

/**
 * @brief The same surface with one direction reversed: dir BS_DIR_U gives Q(u,v) = P(1-u,v),
 * Q[i][j] = P[m-i][j]; dir BS_DIR_V gives Q(u,v) = P(u,1-v). Values are copied exactly.
 * @param[in]  p    the patch.
 * @param[in]  dir  BS_DIR_U or BS_DIR_V.
 * @param[out] out  receives the reversed patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if p or out is NULL, or dir is neither BS_DIR_U nor BS_DIR_V.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_reverse(const bs_patch *p, int dir, bs_patch **out);

/**
 * A Bezier curve given to the constructions below; the caller owns the arrays, which are only read
 * during the call. Frozen for version 1.
 * @since 1.0
 */
typedef struct bs_curve {
    size_t degree;          /**< 0..BS_MAX_DEGREE */
    size_t dim;             /**< dimension of a control point, 1..BS_MAX_DIM */
    const double *ctrl;     /**< (degree+1)*dim doubles, point k coordinate c at ctrl[k*dim + c] */
    const double *weights;  /**< NULL (polynomial) or degree+1 finite positive weights */
} bs_curve;

/**
 * @brief The ruled patch joining two curves by straight segments: S(u,0) = c0(u), S(u,1) = c1(u),
 * degree (d, 1) with d the larger of the two curve degrees (the other curve is elevated, exactly
 * in exact arithmetic). Net: P[i][0] = c0's point i, P[i][1] = c1's point i.
 * Polynomial curves give S(u,v) = (1-v) c0(u) + v c1(u). Rational curves are allowed (a polynomial
 * curve then counts as weights 1): the homogeneous points are interpolated linearly, so the
 * segment at u still joins c0(u) to c1(u) exactly but is traversed in v at a rational speed, and
 * the result is rational.
 * @param[in]  c0   the curve at v = 0.
 * @param[in]  c1   the curve at v = 1 (same dim as c0).
 * @param[out] out  receives the patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if c0, c1, their ctrl or out is NULL.
 * @return BS_ERR_DEGREE if a curve degree exceeds BS_MAX_DEGREE.
 * @return BS_ERR_DIMENSION if a curve dim is 0 or exceeds BS_MAX_DIM.
 * @return BS_ERR_INCOMPATIBLE if the curves have different dims.
 * @return BS_ERR_NONFINITE if a coordinate is NaN or Inf, or a weight is not finite and > 0.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_ruled(const bs_curve *c0, const bs_curve *c1, bs_patch **out);

/**
 * @brief The bilinearly blended Coons patch of four polynomial boundary curves:
 * S(u,0) = v0(u), S(u,1) = v1(u), S(0,v) = u0(v), S(1,v) = u1(v), and
 * S = (1-v) v0(u) + v v1(u) + (1-u) u0(v) + u u1(v) - B(u,v), B the bilinear patch of the corners.
 * Degree (M, N): M the larger degree of v0 and v1, N that of u0 and u1, each at least 1; curves are
 * elevated to it. The corners must agree: v0(0) = u0(0), v0(1) = u1(0), v1(0) = u0(1),
 * v1(1) = u1(1) within tol = 1e-12 * max(1, largest absolute control coordinate of the four curves),
 * per coordinate. The boundary rows and columns of the result are copied from the (elevated)
 * curves, so the patch interpolates them exactly; the corners are taken from v0 and v1.
 * @param[in]  v0   boundary curve at v = 0, parametrised by u.
 * @param[in]  v1   boundary curve at v = 1, parametrised by u.
 * @param[in]  u0   boundary curve at u = 0, parametrised by v.
 * @param[in]  u1   boundary curve at u = 1, parametrised by v.
 * @param[out] out  receives the patch (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if a curve, its ctrl, or out is NULL.
 * @return BS_ERR_DEGREE if a curve degree exceeds BS_MAX_DEGREE.
 * @return BS_ERR_DIMENSION if a curve dim is 0 or exceeds BS_MAX_DIM.
 * @return BS_ERR_INCOMPATIBLE if the dims differ or the corners do not meet within tol.
 * @return BS_ERR_UNSUPPORTED if a curve has weights (rational Coons patches are not Bezier patches
 *         of the same form).
 * @return BS_ERR_NONFINITE if a coordinate is NaN or Inf, or a result coordinate overflows.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_coons(const bs_curve *v0, const bs_curve *v1, const bs_curve *u0,
                                const bs_curve *u1, bs_patch **out);

#ifdef __cplusplus
}
#endif

#endif
