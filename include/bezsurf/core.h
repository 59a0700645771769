/**
 * @file
 * libbezsurf core: status codes, version, strided views, patches and their evaluation.
 * Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_CORE_H
#define BEZSURF_CORE_H

#include <stddef.h>

/**
 * @def BS_API
 * Marks the library's exported functions (default visibility; dllexport/dllimport on Windows,
 * nothing with BS_STATIC). Not for use by callers.
 */
#if defined(_WIN32) && !defined(BS_STATIC)
#  if defined(BS_BUILDING_LIBRARY)
#    define BS_API __declspec(dllexport)
#  else
#    define BS_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) && __GNUC__ >= 4
#  define BS_API __attribute__((visibility("default")))
#else
#  define BS_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------------------------------
 * Status codes. 0 is success, failures are negative. The values are fixed forever; new codes are
 * only ever appended. On failure a function leaves every output untouched, except that a new-handle
 * output (`bs_patch **out`) is set to NULL.
 * ---------------------------------------------------------------------------------------------- */

/** Result of every fallible call: BS_OK or one of the negative BS_ERR_ codes. @since 1.0 */
typedef int bs_status;

#define BS_OK                 0  /**< success */
#define BS_ERR_INVALID_ARG   -1  /**< NULL where not allowed, bad flag or direction, misaligned view */
#define BS_ERR_NO_MEMORY     -2  /**< an allocation failed */
#define BS_ERR_DEGREE        -3  /**< degree > BS_MAX_DEGREE, or a derivative order out of range */
#define BS_ERR_DIMENSION     -4  /**< dim 0 or > BS_MAX_DIM; normals of a patch that is not 3-D */
#define BS_ERR_SIZE          -5  /**< a view or buffer holds fewer elements than needed; n too large */
#define BS_ERR_DOMAIN        -6  /**< a parameter outside its allowed range (split t outside (0,1), NaN) */
#define BS_ERR_NONFINITE     -7  /**< NaN or Inf in control points; a weight not finite and > 0 */
#define BS_ERR_PARSE         -8  /**< malformed input text (see the parse-error location struct) */
#define BS_ERR_IO            -9  /**< a file could not be opened, read or written */
#define BS_ERR_INCOMPATIBLE -10  /**< objects that cannot be combined (e.g. patches of different dim) */
#define BS_ERR_UNSUPPORTED  -11  /**< operation not defined for this input (e.g. hodograph of a rational patch) */
/** A certified result cannot be given in double precision for this input (a weight ratio or a range
 *  of magnitudes beyond what the method can certify): refused rather than answered wrongly.
 *  @since 1.2 */
#define BS_ERR_PRECISION    -12

/** Largest degree per direction. @since 1.0 */
#define BS_MAX_DEGREE 64
/** Largest dimension of a control point. @since 1.0 */
#define BS_MAX_DIM 8

/** Per-point normal kinds written by the normal evaluators. @since 1.0 */
#define BS_NORMAL_REGULAR   0  /**< from S_u x S_v */
#define BS_NORMAL_LIMIT     1  /**< S_u x S_v vanishes; the limit normal along the surface */
#define BS_NORMAL_UNDEFINED 2  /**< no normal exists here; (0,0,0) is written (NaN for a NaN parameter) */

/** Direction u, for the operations that act along one parameter. @since 1.0 */
#define BS_DIR_U 0
/** Direction v, for the operations that act along one parameter. @since 1.0 */
#define BS_DIR_V 1

/**
 * @brief Run-time library version, BS_VERSION_MAJOR*10000 + MINOR*100 + PATCH.
 * Compare with the compile-time BS_VERSION_NUMBER to detect a header/library mismatch.
 * @return the version number of the loaded library.
 * @since 1.0
 */
BS_API unsigned bs_version_number(void);

/**
 * @brief Run-time library version as "MAJOR.MINOR.PATCH".
 * @return a static string, never NULL.
 * @since 1.0
 */
BS_API const char *bs_version_string(void);

/**
 * @brief Human-readable text for a status code.
 * @param[in] s any value, valid or not.
 * @return a static string, never NULL ("unknown status" for values that are not codes).
 * @since 1.0
 */
BS_API const char *bs_status_string(bs_status s);

/* ------------------------------------------------------------------------------------------------
 * Views: one strided buffer per coordinate (structure of arrays).
 *
 * Element k of a view is the double at byte address `(char *)data + k * stride`; a stride of 0 means
 * packed (sizeof(double)). Negative strides are allowed (data then points at element 0, the one with
 * the highest address). `count` is how many elements the view can hold; a call that needs more
 * returns BS_ERR_SIZE and writes nothing, as does a view whose elements in use would not fit in the
 * address space (their span overflows ptrdiff_t, or an element address wraps around). `data` must be
 * aligned for double and `stride` a multiple of sizeof(double), else BS_ERR_INVALID_ARG. A set of
 * d-dimensional points is an array of d views.
 * Output views must not overlap each other or the inputs; if they do, the values written are
 * unspecified (but nothing is written outside the views).
 * The library never keeps a view after the call returns.
 * ---------------------------------------------------------------------------------------------- */

/** A strided output buffer of doubles. @since 1.0 */
typedef struct bs_view {
    double *data;      /**< element 0 */
    size_t count;      /**< number of elements the view can hold */
    ptrdiff_t stride;  /**< bytes between consecutive elements; 0 means sizeof(double) */
} bs_view;

/** A strided input buffer of doubles. @since 1.0 */
typedef struct bs_cview {
    const double *data; /**< element 0 */
    size_t count;       /**< number of elements the view holds */
    ptrdiff_t stride;   /**< bytes between consecutive elements; 0 means sizeof(double) */
} bs_cview;

/**
 * A strided output buffer of floats, for results wanted in single precision (e.g. for a GPU).
 * The rules of bs_view apply with float in place of double: a stride of 0 means sizeof(float),
 * `data` must be aligned for float and `stride` a multiple of sizeof(float).
 * @since 1.1
 */
typedef struct bs_fview {
    float *data;       /**< element 0 */
    size_t count;      /**< number of elements the view can hold */
    ptrdiff_t stride;  /**< bytes between consecutive elements; 0 means sizeof(float) */
} bs_fview;

/* ------------------------------------------------------------------------------------------------
 * Patches. A patch of degree (m, n) has an (m+1) x (n+1) net of control points of dimension dim.
 * Packed control points: point (i,j) coordinate c is at ctrl[(i*(n+1) + j)*dim + c], i along u, j
 * along v (row by row, as in the .bpt format and a numpy array of shape (m+1, n+1, dim)).
 * Weights (rational patches) are (m+1)(n+1) values in the same order; control points are always
 * Cartesian, never pre-multiplied by their weights. A patch never changes after creation, so any
 * number of threads may use the same `const bs_patch *` at once.
 * ---------------------------------------------------------------------------------------------- */

/** Opaque, immutable Bezier patch. @since 1.0 */
typedef struct bs_patch bs_patch;

/**
 * @brief Create a patch from its control net.
 * @param[in]  deg_u    degree along u, 0..BS_MAX_DEGREE (0: constant in u).
 * @param[in]  deg_v    degree along v, 0..BS_MAX_DEGREE.
 * @param[in]  dim      dimension of a control point, 1..BS_MAX_DIM.
 * @param[in]  ctrl     (deg_u+1)(deg_v+1)*dim doubles, packed as described above; copied.
 * @param[in]  weights  NULL for a polynomial patch, or (deg_u+1)(deg_v+1) finite positive weights; copied.
 * @param[out] out      receives the new patch (NULL on failure); release with bs_patch_destroy().
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if ctrl or out is NULL.
 * @return BS_ERR_DEGREE if deg_u or deg_v exceeds BS_MAX_DEGREE.
 * @return BS_ERR_DIMENSION if dim is 0 or exceeds BS_MAX_DIM.
 * @return BS_ERR_NONFINITE if a coordinate is NaN or Inf, a weight is not finite and > 0, or a
 *         weighted coordinate w*P overflows.
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_patch_create(size_t deg_u, size_t deg_v, size_t dim,
                                 const double *ctrl, const double *weights, bs_patch **out);

/**
 * @brief Release a patch. NULL is a no-op.
 * @param[in] p the patch, or NULL.
 * @since 1.0
 */
BS_API void bs_patch_destroy(bs_patch *p);

/**
 * @brief Make an independent copy of a patch.
 * @param[in]  p    the patch.
 * @param[out] out  receives the copy (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if p or out is NULL; BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_patch_clone(const bs_patch *p, bs_patch **out);

/**
 * @brief Degree along u.
 * @param[in] p  the patch, or NULL.
 * @return the degree m along u (0..BS_MAX_DEGREE); 0 for a NULL patch.
 * @since 1.0
 */
BS_API size_t bs_patch_degree_u(const bs_patch *p);
/**
 * @brief Degree along v.
 * @param[in] p  the patch, or NULL.
 * @return the degree n along v (0..BS_MAX_DEGREE); 0 for a NULL patch.
 * @since 1.0
 */
BS_API size_t bs_patch_degree_v(const bs_patch *p);
/**
 * @brief Dimension of a control point.
 * @param[in] p  the patch, or NULL.
 * @return the dimension (1..BS_MAX_DIM); 0 for a NULL patch.
 * @since 1.0
 */
BS_API size_t bs_patch_dim(const bs_patch *p);
/**
 * @brief Whether the patch is rational.
 * @param[in] p  the patch, or NULL.
 * @return 1 if the patch has weights, 0 if it is polynomial or NULL.
 * @since 1.0
 */
BS_API int bs_patch_is_rational(const bs_patch *p);

/**
 * @brief Copy the control net (and weights) out of a patch.
 * @param[in]  p            the patch.
 * @param[out] ctrl         NULL (not wanted) or room for ctrl_cap doubles; receives the packed net,
 *                          (deg_u+1)(deg_v+1)*dim doubles.
 * @param[in]  ctrl_cap     number of doubles ctrl can hold (ignored when ctrl is NULL).
 * @param[out] weights      NULL (not wanted) or room for weights_cap doubles; receives the
 *                          (deg_u+1)(deg_v+1) weights, all 1.0 for a polynomial patch.
 * @param[in]  weights_cap  number of doubles weights can hold (ignored when weights is NULL).
 * @return BS_OK; BS_ERR_INVALID_ARG if p is NULL; BS_ERR_SIZE if a capacity is too small (nothing
 *         is written then).
 * @since 1.0
 */
BS_API bs_status bs_patch_get_ctrl(const bs_patch *p, double *ctrl, size_t ctrl_cap,
                                   double *weights, size_t weights_cap);

/* ------------------------------------------------------------------------------------------------
 * Evaluation.
 *
 * Common rules for the four evaluators:
 * - `pos`, `du`, `dv`, `out`: NULL (not wanted) or an array of dim views. `nrm`: NULL or an array of
 *   3 views; normals of a patch whose dim is not 3 are BS_ERR_DIMENSION. `kind`: NULL or room for one
 *   byte per point (its size cannot be checked).
 * - Arguments are checked in this order, and the first failure is returned with nothing written:
 *   p NULL (BS_ERR_INVALID_ARG); derivative orders (BS_ERR_DEGREE); normals of a non-3-D patch
 *   (BS_ERR_DIMENSION); then, unless the count is 0, the views in the order of the parameters
 *   (u, v, then the outputs, each output's coordinates in order): a NULL view array where one is
 *   required or NULL data, misaligned data or stride (BS_ERR_INVALID_ARG), count below the number
 *   of points, a byte extent (n-1)*|stride| + sizeof(double) that overflows ptrdiff_t, or a first
 *   or last element whose address would wrap around the address space (BS_ERR_SIZE).
 * - n = 0 (or nu = 0 or nv = 0) is a successful no-op once p and the orders or dimension have been
 *   checked; the views are then neither checked nor read.
 * - u and v may lie outside [0,1]: the polynomial is extrapolated (and may overflow to Inf far away;
 *   a rational patch's denominator may vanish there, giving Inf or NaN).
 *   A NaN or infinite parameter gives NaN in every output of that point only (kind
 *   BS_NORMAL_UNDEFINED).
 * - Results do not depend on the batch size, the strides or the alignment of the buffers: the same
 *   (u,v) gives the same bits through every evaluator that returns the quantity (the grid and the
 *   scattered evaluators agree bit for bit; bs_patch_eval_deriv may differ in the last bits).
 * - Accuracy (docs/accuracy.md): for u, v in [0,1] every coordinate of d^(k+l)S/du^k dv^l is within
 *   2(m+n+1) eps max|P| 2^(k+l) m!/(m-k)! n!/(n-l)! of the exact value (eps = 2^-52), times
 *   (wmax/wmin)^(1+k+l) for rational patches.
 * - Rational patches are evaluated in homogeneous coordinates; derivatives by the quotient rule
 *   (Leibniz formula on A = w S).
 *
 * Normal rule (docs/normals.md). N = S_u x S_v / |S_u x S_v| where that cross product is not
 * (numerically) zero: kind BS_NORMAL_REGULAR. S_u or S_v counts as zero when its length is below
 * 2^-30 times its bound over the patch (m, resp. n, times the diagonal of the net's bounding box
 * times wmax/wmin), or below 4 times its accuracy bound; the cross product counts as zero when it is
 * below 2^-30 |S_u||S_v| (parallel derivatives). Where it vanishes (a collapsed row or column of
 * the net, as at the top of the Utah teapot's lid, or a corner where the derivatives are parallel or
 * both vanish) the normal is the limit of N as the point is approached along the straight line
 * towards the centre (1/2, 1/2) of the domain: the direction of the first Taylor coefficient of
 * S_u x S_v along that line that is not zero (orders 1 to 6, from the higher partial derivatives;
 * e.g. S_u x S_uv on a collapsed edge u = 0 and its opposite on u = 1, with the sign that matches
 * the regular normals nearby): kind BS_NORMAL_LIMIT. Only where no such coefficient exists (e.g. a
 * net that lies on a line or a point, or degree 0 in a direction) is (0,0,0) written, with kind
 * BS_NORMAL_UNDEFINED. Finite parameters never give a NaN normal (a result that is not finite,
 * far outside the domain, gives (0,0,0) and BS_NORMAL_UNDEFINED).
 * ---------------------------------------------------------------------------------------------- */

/**
 * @brief Evaluate positions and first partial derivatives at n scattered (u,v) pairs.
 * Point k is (u[k], v[k]) and is written at element k of every output. See the common rules above
 * for NULL outputs, n = 0, NaN and infinite parameters, and accuracy.
 * @param[in]  p    the patch (any degree and dimension a patch can have).
 * @param[in]  n    number of points; 0 is a no-op.
 * @param[in]  u    view of n u-parameters.
 * @param[in]  v    view of n v-parameters.
 * @param[out] pos  NULL or dim views receiving S(u,v).
 * @param[out] du   NULL or dim views receiving dS/du.
 * @param[out] dv   NULL or dim views receiving dS/dv.
 * @return BS_OK on success (also for n = 0).
 * @return BS_ERR_INVALID_ARG if p, u or v is NULL, or a view's data is NULL or misaligned or its
 *         stride not a multiple of sizeof(double).
 * @return BS_ERR_SIZE if a view holds fewer than n elements or its byte extent overflows.
 * @since 1.0
 */
BS_API bs_status bs_patch_eval(const bs_patch *p, size_t n, const bs_cview *u, const bs_cview *v,
                               const bs_view *pos, const bs_view *du, const bs_view *dv);

/**
 * @brief Evaluate the mixed partial derivative d^(ku+kv) S / du^ku dv^kv at n scattered points.
 * Orders beyond the degree give zero for polynomial patches (not for rational ones); (0,0) gives
 * the positions of bs_patch_eval, bit for bit. See the common rules above for n = 0, NaN and
 * infinite parameters, and accuracy.
 * @param[in]  p    the patch.
 * @param[in]  ku   order along u, 0..BS_MAX_DEGREE.
 * @param[in]  kv   order along v, 0..BS_MAX_DEGREE.
 * @param[in]  n    number of points; 0 is a no-op (out may then be NULL).
 * @param[in]  u    view of n u-parameters.
 * @param[in]  v    view of n v-parameters.
 * @param[out] out  dim views receiving the derivative (required).
 * @return BS_OK on success (also for n = 0).
 * @return BS_ERR_INVALID_ARG if p, u, v or out is NULL, or a view's data is NULL or misaligned or
 *         its stride not a multiple of sizeof(double).
 * @return BS_ERR_DEGREE if ku or kv exceeds BS_MAX_DEGREE (checked before the views).
 * @return BS_ERR_SIZE if a view holds fewer than n elements or its byte extent overflows.
 * @return BS_ERR_NO_MEMORY if the scratch space of a rational patch cannot be allocated.
 * @since 1.0
 */
BS_API bs_status bs_patch_eval_deriv(const bs_patch *p, unsigned ku, unsigned kv, size_t n,
                                     const bs_cview *u, const bs_cview *v, const bs_view *out);

/**
 * @brief Evaluate positions and unit normals (with their kind) at n scattered points of a 3-D patch.
 * See the normal rule above; positions are those of bs_patch_eval, bit for bit. A NaN or infinite
 * parameter gives NaN position and normal and kind BS_NORMAL_UNDEFINED.
 * @param[in]  p     the patch (dim 3).
 * @param[in]  n     number of points; 0 is a no-op.
 * @param[in]  u     view of n u-parameters.
 * @param[in]  v     view of n v-parameters.
 * @param[out] pos   NULL or 3 views receiving S(u,v).
 * @param[out] nrm   NULL or 3 views receiving the unit normal.
 * @param[out] kind  NULL or n bytes receiving BS_NORMAL_REGULAR, _LIMIT or _UNDEFINED.
 * @return BS_OK on success (also for n = 0).
 * @return BS_ERR_INVALID_ARG if p, u or v is NULL, or a view's data is NULL or misaligned or its
 *         stride not a multiple of sizeof(double).
 * @return BS_ERR_DIMENSION if the patch's dim is not 3 (checked before the views, also for n = 0).
 * @return BS_ERR_SIZE if a view holds fewer than n elements or its byte extent overflows.
 * @since 1.0
 */
BS_API bs_status bs_patch_eval_normal(const bs_patch *p, size_t n, const bs_cview *u, const bs_cview *v,
                                      const bs_view *pos, const bs_view *nrm, unsigned char *kind);

/**
 * @brief Evaluate a tensor grid: every u[a] with every v[b], written at output index a*nv + b.
 * Every output is bit-identical to what bs_patch_eval / bs_patch_eval_normal give for the same
 * pair; the work per point is only the v-direction (the u-direction is contracted once per row).
 * A NaN or infinite u[a] or v[b] gives NaN outputs in its row or column (kind UNDEFINED).
 * @param[in]  p     the patch.
 * @param[in]  nu    number of u-parameters; 0 is a no-op.
 * @param[in]  u     view of nu u-parameters.
 * @param[in]  nv    number of v-parameters; 0 is a no-op.
 * @param[in]  v     view of nv v-parameters.
 * @param[out] pos   NULL or dim views of nu*nv elements receiving S.
 * @param[out] du    NULL or dim views receiving dS/du.
 * @param[out] dv    NULL or dim views receiving dS/dv.
 * @param[out] nrm   NULL or 3 views receiving unit normals (dim must be 3 when not NULL).
 * @param[out] kind  NULL or nu*nv bytes receiving the normal kinds (dim must be 3 when not NULL).
 * @return BS_OK on success (also when nu or nv is 0).
 * @return BS_ERR_INVALID_ARG if p, u or v is NULL, or a view's data is NULL or misaligned or its
 *         stride not a multiple of sizeof(double).
 * @return BS_ERR_DIMENSION if nrm or kind is given and the patch's dim is not 3 (checked before
 *         the views).
 * @return BS_ERR_SIZE if u or v is shorter than nu or nv, nu*nv overflows size_t (checked after u
 *         and v), or an output view holds fewer than nu*nv elements or its byte extent overflows.
 * @return BS_ERR_NO_MEMORY if the scratch space (under 300 kB, independent of nu and nv) cannot be
 *         allocated.
 * @since 1.0
 */
BS_API bs_status bs_patch_eval_grid(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                                    const bs_cview *v, const bs_view *pos, const bs_view *du,
                                    const bs_view *dv, const bs_view *nrm, unsigned char *kind);

/**
 * @brief bs_patch_eval_grid() with float outputs: every value is the double result of
 * bs_patch_eval_grid() for the same arguments, correctly rounded to float (round to nearest even;
 * beyond the float range it becomes an infinity, a NaN stays a NaN). So the accuracy contract of
 * the double results holds with one float rounding added, and the normal kinds are the same.
 * Arguments are checked in the same order and with the same statuses as bs_patch_eval_grid(),
 * float views by the rules of bs_fview; on failure nothing is written.
 * @param[in]  p     the patch.
 * @param[in]  nu    number of u-parameters; 0 is a no-op.
 * @param[in]  u     view of nu u-parameters (double).
 * @param[in]  nv    number of v-parameters; 0 is a no-op.
 * @param[in]  v     view of nv v-parameters (double).
 * @param[out] pos   NULL or dim float views of nu*nv elements receiving S.
 * @param[out] du    NULL or dim float views receiving dS/du.
 * @param[out] dv    NULL or dim float views receiving dS/dv.
 * @param[out] nrm   NULL or 3 float views receiving unit normals (dim must be 3 when not NULL).
 * @param[out] kind  NULL or nu*nv bytes receiving the normal kinds (dim must be 3 when not NULL).
 * @return BS_OK on success (also when nu or nv is 0).
 * @return BS_ERR_INVALID_ARG if p, u or v is NULL, or a view's data is NULL or misaligned or its
 *         stride not a multiple of its element size.
 * @return BS_ERR_DIMENSION if nrm or kind is given and the patch's dim is not 3 (checked before
 *         the views).
 * @return BS_ERR_SIZE if u or v is shorter than nu or nv, nu*nv overflows size_t (checked after u
 *         and v), or an output view holds fewer than nu*nv elements or its byte extent overflows.
 * @return BS_ERR_NO_MEMORY if the scratch space (under 300 kB, independent of nu and nv) cannot be
 *         allocated.
 * @since 1.1
 */
BS_API bs_status bs_patch_eval_grid_f32(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                                        const bs_cview *v, const bs_fview *pos, const bs_fview *du,
                                        const bs_fview *dv, const bs_fview *nrm, unsigned char *kind);

#ifdef __cplusplus
}
#endif

#endif
