//! Raw declarations of the C API (`include/bezsurf/*.h`), written by hand.
//!
//! Everything here mirrors the header exactly: the `#[repr(C)]` structs have the C layout (checked
//! against the header by `tests/layout.rs`), the constants have the header's values and every
//! function has the C signature (`size_t` is `usize`, `ptrdiff_t` is `isize`, `int` is `c_int`,
//! `unsigned` is `c_uint`). Calling these is `unsafe`; the safe layer is the rest of the crate.
//!
//! Each declaration carries a one-line summary; the C header's documentation of the function is
//! the contract (NULL rules, units, every status). The common rules: the caller passes live
//! handles and buffers valid for the counts and capacities given; new handles come back through
//! the last argument and belong to the caller, who releases them with the matching `_destroy`;
//! on failure outputs are untouched and new-handle outputs are NULL; nothing is kept after a
//! call returns. Every function may be called from any thread.

#![allow(non_camel_case_types)]

use std::os::raw::{c_char, c_int, c_uchar, c_uint, c_void};

/// `bs_status`: 0 is success, failures are negative.
pub type bs_status = c_int;

/// Success.
pub const BS_OK: bs_status = 0;
/// A NULL or misaligned pointer, an unknown flag or direction, an id out of range.
pub const BS_ERR_INVALID_ARG: bs_status = -1;
/// An allocation failed.
pub const BS_ERR_NO_MEMORY: bs_status = -2;
/// A degree above `BS_MAX_DEGREE` or a derivative order out of range.
pub const BS_ERR_DEGREE: bs_status = -3;
/// A dimension of 0 or above `BS_MAX_DIM`, or normals asked of a patch that is not 3-D.
pub const BS_ERR_DIMENSION: bs_status = -4;
/// An output buffer or view too small for the result.
pub const BS_ERR_SIZE: bs_status = -5;
/// A parameter outside its allowed range.
pub const BS_ERR_DOMAIN: bs_status = -6;
/// NaN or infinity in control points, or a weight that is not positive.
pub const BS_ERR_NONFINITE: bs_status = -7;
/// Malformed input text (details in `bs_parse_error`).
pub const BS_ERR_PARSE: bs_status = -8;
/// A file could not be opened, read or written.
pub const BS_ERR_IO: bs_status = -9;
/// Objects that cannot be combined (different dimensions, corners that do not meet).
pub const BS_ERR_INCOMPATIBLE: bs_status = -10;
/// An operation not defined for this input (e.g. the hodograph of a rational patch).
pub const BS_ERR_UNSUPPORTED: bs_status = -11;
/// A certified result cannot be given in double precision for this input (a weight ratio or a
/// range of magnitudes beyond what the method certifies). Since 1.2.
pub const BS_ERR_PRECISION: bs_status = -12;

/// Largest degree per direction.
pub const BS_MAX_DEGREE: usize = 64;
/// Largest dimension of a control point.
pub const BS_MAX_DIM: usize = 8;

/// Normal kind: from S_u x S_v.
pub const BS_NORMAL_REGULAR: c_uchar = 0;
/// Normal kind: S_u x S_v vanishes; the limit normal along the surface.
pub const BS_NORMAL_LIMIT: c_uchar = 1;
/// Normal kind: no normal exists; (0, 0, 0) was written (NaN for a NaN parameter).
pub const BS_NORMAL_UNDEFINED: c_uchar = 2;

/// Curvature kind: from the fundamental forms at the point (since 1.1).
pub const BS_CURV_REGULAR: c_uchar = 0;
/// Curvature kind: the limit along the line towards (1/2, 1/2) (since 1.1).
pub const BS_CURV_LIMIT: c_uchar = 1;
/// Curvature kind: no finite curvature; NaN was written (since 1.1).
pub const BS_CURV_UNDEFINED: c_uchar = 2;

/// The u direction (first index of the control net).
pub const BS_DIR_U: c_int = 0;
/// The v direction (second index of the control net).
pub const BS_DIR_V: c_int = 1;

/// Side v = 0 of the unit square; its edge parameter runs along u.
pub const BS_SIDE_V0: c_int = 0;
/// Side u = 1; its edge parameter runs along v.
pub const BS_SIDE_U1: c_int = 1;
/// Side v = 1; its edge parameter runs along u.
pub const BS_SIDE_V1: c_int = 2;
/// Side u = 0; its edge parameter runs along v.
pub const BS_SIDE_U0: c_int = 3;

/// Tessellation flag: the adaptive tolerance is a fraction of the control-net bounding-box diagonal.
pub const BS_TESS_RELATIVE: c_int = 1;
/// Tessellation flag: also build triangle strips.
pub const BS_TESS_STRIPS: c_int = 2;
/// Tessellation flag: reverse the triangles' winding and the normals (since 1.2).
pub const BS_TESS_REVERSE: c_int = 4;
/// Largest number of segments per patch and direction of a uniform tessellation.
pub const BS_TESS_MAX_RATE: usize = 1024;
/// Tessellation method: nu x nv segments per patch (since 1.1).
pub const BS_TESS_UNIFORM: c_int = 0;
/// Tessellation method: one segment count per patch from a curvature bound (since 1.1).
pub const BS_TESS_PER_PATCH: c_int = 1;
/// Tessellation method: a quadtree of sub-patches per patch (since 1.1).
pub const BS_TESS_SUBDIVIDE: c_int = 2;

/// Mesh format: Wavefront OBJ with positions, parameters and normals.
pub const BS_MESH_OBJ: c_int = 0;
/// Mesh format: binary little-endian PLY.
pub const BS_MESH_PLY: c_int = 1;
/// Mesh format: ASCII PLY.
pub const BS_MESH_PLY_ASCII: c_int = 2;
/// Mesh format: binary STL.
pub const BS_MESH_STL: c_int = 3;

/// A strided output buffer of doubles (`bs_view`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_view {
    /// Element 0 (written).
    pub data: *mut f64,
    /// Number of elements.
    pub count: usize,
    /// Bytes from one element to the next; may be negative, a multiple of 8.
    pub stride: isize,
}

/// A strided input buffer of doubles (`bs_cview`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_cview {
    /// Element 0 (read).
    pub data: *const f64,
    /// Number of elements.
    pub count: usize,
    /// Bytes from one element to the next; may be negative, a multiple of 8.
    pub stride: isize,
}

/// A Bezier curve given to the constructions (`bs_curve`, ops.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_curve {
    /// Degree.
    pub degree: usize,
    /// Dimension of a control point.
    pub dim: usize,
    /// (degree + 1)·dim packed coordinates.
    pub ctrl: *const f64,
    /// degree + 1 weights, or NULL for a polynomial curve.
    pub weights: *const f64,
}

/// A B-spline or NURBS surface as the caller holds it (`bs_bspline`, bspline.h, since 1.1).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_bspline {
    /// Degree along u, 1..=`BS_MAX_DEGREE`.
    pub deg_u: usize,
    /// Degree along v, 1..=`BS_MAX_DEGREE`.
    pub deg_v: usize,
    /// Control points along u, at least `deg_u + 1`.
    pub count_u: usize,
    /// Control points along v, at least `deg_v + 1`.
    pub count_v: usize,
    /// Dimension of a control point.
    pub dim: usize,
    /// `count_u + deg_u + 1` finite, non-decreasing knots.
    pub knots_u: *const f64,
    /// `count_v + deg_v + 1` finite, non-decreasing knots.
    pub knots_v: *const f64,
    /// Point (i, j), coordinate c at `ctrl[(i * count_v + j) * dim + c]`.
    pub ctrl: *const f64,
    /// NULL, or `count_u * count_v` finite positive weights.
    pub weights: *const f64,
}

/// Where and why parsing failed (`bs_parse_error`, io.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_parse_error {
    /// 1-based line of the first error; 0 if none was recorded.
    pub line: usize,
    /// 1-based byte column of the first error.
    pub column: usize,
    /// The reason, NUL-terminated.
    pub message: [c_char; 96],
}

/// How two patches meet along one shared edge (`bs_edge_continuity`, continuity.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_edge_continuity {
    /// The patch with the lower id.
    pub patch_a: u32,
    /// The neighbour.
    pub patch_b: u32,
    /// Shared side of `patch_a` (`BS_SIDE_*`).
    pub side_a: c_int,
    /// Shared side of `patch_b` (`BS_SIDE_*`).
    pub side_b: c_int,
    /// 1 if the edge parameters run opposite ways.
    pub reversed: c_int,
    /// 1 if C1 within the tolerance (0 for rational patches).
    pub c1: c_int,
    /// 1 if the normals point to opposite sides.
    pub flipped: c_int,
    /// Number of samples at which both normals exist.
    pub samples: c_int,
    /// Largest distance between corresponding boundary control points.
    pub c0_gap: f64,
    /// Largest angle in radians between the tangent planes, sampled.
    pub g1_angle: f64,
    /// Largest |D_a + D_b| over the cross-boundary derivative nets; NaN for rational patches.
    pub c1_defect: f64,
}

/// A side of a patch that no other patch shares (`bs_open_edge`, continuity.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_open_edge {
    /// The patch id.
    pub patch: u32,
    /// Its unshared side (`BS_SIDE_*`).
    pub side: c_int,
}

/// Tessellation options (`bs_tess_options`, mesh.h, since 1.1; its first field is its size).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_tess_options {
    /// `sizeof(bs_tess_options)`, set by `bs_tess_options_init`.
    pub size: usize,
    /// `BS_TESS_UNIFORM`, `BS_TESS_PER_PATCH` or `BS_TESS_SUBDIVIDE`.
    pub method: c_int,
    /// `BS_TESS_RELATIVE` | `BS_TESS_STRIPS`.
    pub flags: c_int,
    /// Uniform: segments along u per patch.
    pub nu: usize,
    /// Uniform: segments along v per patch.
    pub nv: usize,
    /// The other methods: the chordal tolerance.
    pub tolerance: f64,
    /// Budget on vertices; 0 = only the 32-bit index limit.
    pub max_vertices: usize,
    /// Budget on triangles; 0 = only the 32-bit index limit.
    pub max_triangles: usize,
    /// Threads sampling the vertices, the calling one included; 1 (default) = none started,
    /// 0 = one per online CPU.
    pub threads: usize,
}

/// A strided float output view (`bs_fview`, core.h, since 1.1): stride in bytes, 0 = packed.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_fview {
    /// Element 0 (written).
    pub data: *mut f32,
    /// Number of elements.
    pub count: usize,
    /// Bytes between elements; 0 means `size_of::<f32>()`.
    pub stride: isize,
}

/// Opaque locator (`bs_locator`, since 1.1).
#[repr(C)]
pub struct bs_locator {
    _opaque: [u8; 0],
}

/// Opaque model handle (`bs_model`, model.h, since 1.2); only ever used behind a pointer.
#[repr(C)]
pub struct bs_model {
    _opaque: [u8; 0],
}

/// One face of a model (`bs_face_info`, since 1.2); `size` is set by the caller.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct bs_face_info {
    /// `size_of::<bs_face_info>()`, set before the call.
    pub size: usize,
    /// `BS_FACE_*`.
    pub kind: i32,
    /// 1: the outward normal is opposite the surface normal.
    pub reversed: i32,
    /// Shell id.
    pub shell: usize,
    /// Assembly placement id.
    pub instance: usize,
    /// First patch of the face in `bs_model_surface`.
    pub first_patch: usize,
    /// Number of its patches.
    pub patch_count: usize,
    /// Trim loops (0: untrimmed).
    pub loop_count: usize,
    /// Native parameter box: u from `u0` ...
    pub u0: f64,
    /// ... to `u1`.
    pub u1: f64,
    /// v from `v0` ...
    pub v0: f64,
    /// ... to `v1`.
    pub v1: f64,
}

/// Point outside the trimmed face (`BS_TRIM_OUTSIDE`).
pub const BS_TRIM_OUTSIDE: u8 = 0;
/// Point inside the trimmed face (`BS_TRIM_INSIDE`).
pub const BS_TRIM_INSIDE: u8 = 1;
/// Point within the tolerance of the face's boundary (`BS_TRIM_ON`).
pub const BS_TRIM_ON: u8 = 2;

/// Opaque mesh handle (`bs_mesh`, mesh.h); only ever used behind a pointer.
#[repr(C)]
pub struct bs_mesh {
    _opaque: [u8; 0],
}

/// Opaque patch handle (`bs_patch`); only ever used behind a pointer.
#[repr(C)]
pub struct bs_patch {
    _opaque: [u8; 0],
}

/// Opaque surface handle (`bs_surface`); only ever used behind a pointer.
#[repr(C)]
pub struct bs_surface {
    _opaque: [u8; 0],
}

extern "C" {
    // ---- core.h: status and version ----
    /// Run-time version, major*10000 + minor*100 + patch.
    pub fn bs_version_number() -> c_uint;
    /// Run-time version as a static NUL-terminated "MAJOR.MINOR.PATCH".
    pub fn bs_version_string() -> *const c_char;
    /// Static NUL-terminated text for any status value, never NULL.
    pub fn bs_status_string(s: bs_status) -> *const c_char;

    // ---- core.h: patches ----
    /// Creates a patch of degree (`deg_u`, `deg_v`) from (deg_u+1)(deg_v+1)·`dim` packed coordinates and, if `weights` is not NULL, (deg_u+1)(deg_v+1) weights; `*out` is set to the new patch (NULL on failure).
    pub fn bs_patch_create(
        deg_u: usize,
        deg_v: usize,
        dim: usize,
        ctrl: *const f64,
        weights: *const f64,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    /// Releases a patch; NULL does nothing.
    pub fn bs_patch_destroy(p: *mut bs_patch);
    /// Makes an independent copy of a patch in `*out`.
    pub fn bs_patch_clone(p: *const bs_patch, out: *mut *mut bs_patch) -> bs_status;
    /// Degree along u; 0 for NULL.
    pub fn bs_patch_degree_u(p: *const bs_patch) -> usize;
    /// Degree along v; 0 for NULL.
    pub fn bs_patch_degree_v(p: *const bs_patch) -> usize;
    /// Dimension of a control point; 0 for NULL.
    pub fn bs_patch_dim(p: *const bs_patch) -> usize;
    /// 1 if the patch has weights, else 0 (also for NULL).
    pub fn bs_patch_is_rational(p: *const bs_patch) -> c_int;
    /// Copies the packed control net and/or the weights into caller buffers of the given capacities (in doubles); either pointer may be NULL.
    pub fn bs_patch_get_ctrl(
        p: *const bs_patch,
        ctrl: *mut f64,
        ctrl_cap: usize,
        weights: *mut f64,
        weights_cap: usize,
    ) -> bs_status;

    // ---- core.h: evaluation ----
    /// Positions and first partials at `n` scattered (u, v) pairs into `dim` views each; `pos`, `du`, `dv` point to arrays of `dim` views or are NULL.
    pub fn bs_patch_eval(
        p: *const bs_patch,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        du: *const bs_view,
        dv: *const bs_view,
    ) -> bs_status;
    /// The mixed partial derivative of orders (`ku`, `kv`) at `n` scattered points into `dim` views.
    pub fn bs_patch_eval_deriv(
        p: *const bs_patch,
        ku: c_uint,
        kv: c_uint,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        out: *const bs_view,
    ) -> bs_status;
    /// Positions, unit normals (3 views) and normal kinds (`n` bytes, `BS_NORMAL_*`) at `n` scattered points of a 3-D patch; any output may be NULL.
    pub fn bs_patch_eval_normal(
        p: *const bs_patch,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        nrm: *const bs_view,
        kind: *mut c_uchar,
    ) -> bs_status;
    /// Every `u[a]` with every `v[b]`, written at index a·nv + b: positions, partials, normals and kinds, any of them NULL.
    pub fn bs_patch_eval_grid(
        p: *const bs_patch,
        nu: usize,
        u: *const bs_cview,
        nv: usize,
        v: *const bs_cview,
        pos: *const bs_view,
        du: *const bs_view,
        dv: *const bs_view,
        nrm: *const bs_view,
        kind: *mut c_uchar,
    ) -> bs_status;

    // ---- ops.h ----
    /// Splits at `t` (0 < t < 1) along `dir` into new patches over [0, t] and [t, 1].
    pub fn bs_patch_split(
        p: *const bs_patch,
        dir: c_int,
        t: f64,
        lo: *mut *mut bs_patch,
        hi: *mut *mut bs_patch,
    ) -> bs_status;
    /// Splits at (`u`, `v`) into four new patches written to `out[0..4]`.
    pub fn bs_patch_split4(p: *const bs_patch, u: f64, v: f64, out: *mut *mut bs_patch) -> bs_status;
    /// The patch over [u0, u1] x [v0, v1], reparametrised over the unit square.
    pub fn bs_patch_subpatch(
        p: *const bs_patch,
        u0: f64,
        u1: f64,
        v0: f64,
        v1: f64,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    /// The same surface with its degrees raised by `raise_u` and `raise_v`.
    pub fn bs_patch_elevate(
        p: *const bs_patch,
        raise_u: usize,
        raise_v: usize,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    /// The hodograph patch of the (`ku`, `kv`) derivative of a polynomial patch.
    pub fn bs_patch_derivative(
        p: *const bs_patch,
        ku: c_uint,
        kv: c_uint,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    /// Control points (and weights, if `weights` is not NULL) of the iso-curve u = t (`BS_DIR_U`) or v = t (`BS_DIR_V`), into buffers of the given capacities.
    pub fn bs_patch_isocurve(
        p: *const bs_patch,
        dir: c_int,
        t: f64,
        ctrl: *mut f64,
        ctrl_cap: usize,
        weights: *mut f64,
        weights_cap: usize,
    ) -> bs_status;
    /// Bounding box of the control net: `dim` values each into `lo` and `hi` (no capacity argument).
    pub fn bs_patch_bounds(p: *const bs_patch, lo: *mut f64, hi: *mut f64) -> bs_status;
    /// The patch with x -> A x + b applied to its net; `affine` holds dim·(dim+1) values, row-major, last column b.
    pub fn bs_patch_transform(p: *const bs_patch, affine: *const f64, out: *mut *mut bs_patch) -> bs_status;

    /// The same surface with u and v exchanged.
    pub fn bs_patch_swap_uv(p: *const bs_patch, out: *mut *mut bs_patch) -> bs_status;
    /// The same surface with direction `dir` reversed.
    pub fn bs_patch_reverse(p: *const bs_patch, dir: c_int, out: *mut *mut bs_patch) -> bs_status;
    /// The ruled patch between two curves, straight in v.
    pub fn bs_patch_ruled(c0: *const bs_curve, c1: *const bs_curve, out: *mut *mut bs_patch) -> bs_status;
    /// The bilinearly blended Coons patch of four polynomial boundary curves whose corners meet.
    pub fn bs_patch_coons(
        v0: *const bs_curve,
        v1: *const bs_curve,
        u0: *const bs_curve,
        u1: *const bs_curve,
        out: *mut *mut bs_patch,
    ) -> bs_status;

    // ---- surface.h ----
    /// Creates an empty surface in `*out`.
    pub fn bs_surface_create(out: *mut *mut bs_surface) -> bs_status;
    /// Releases a surface and its patches; NULL does nothing.
    pub fn bs_surface_destroy(s: *mut bs_surface);
    /// Makes an independent copy of a surface in `*out`.
    pub fn bs_surface_clone(s: *const bs_surface, out: *mut *mut bs_surface) -> bs_status;
    /// Appends a copy of `p`; its index goes to `*index` if that is not NULL.
    pub fn bs_surface_add(s: *mut bs_surface, p: *const bs_patch, index: *mut usize) -> bs_status;
    /// Number of patches; 0 for NULL.
    pub fn bs_surface_count(s: *const bs_surface) -> usize;
    /// Dimension of the patches; 0 for an empty or NULL surface.
    pub fn bs_surface_dim(s: *const bs_surface) -> usize;
    /// Borrows patch `i` (NULL if out of range); valid until the surface is destroyed.
    pub fn bs_surface_get(s: *const bs_surface, i: usize) -> *const bs_patch;

    /// Positions and first partials at `n` scattered points, point k on patch `ids[k]` at (`u[k]`, `v[k]`).
    pub fn bs_surface_eval(
        s: *const bs_surface,
        n: usize,
        ids: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        du: *const bs_view,
        dv: *const bs_view,
    ) -> bs_status;
    /// Positions, unit normals and kinds at `n` scattered points of a 3-D surface, point k on patch `ids[k]`.
    pub fn bs_surface_eval_normal(
        s: *const bs_surface,
        n: usize,
        ids: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        nrm: *const bs_view,
        kind: *mut c_uchar,
    ) -> bs_status;
    /// `bs_surface_eval` on up to `threads` threads (0 = one per online CPU), same results (since 1.1).
    pub fn bs_surface_eval_mt(
        s: *const bs_surface,
        n: usize,
        ids: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        du: *const bs_view,
        dv: *const bs_view,
        threads: usize,
    ) -> bs_status;
    /// `bs_surface_eval_normal` on up to `threads` threads (0 = one per online CPU), same results (since 1.2).
    pub fn bs_surface_eval_normal_mt(
        s: *const bs_surface,
        n: usize,
        ids: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        nrm: *const bs_view,
        kind: *mut c_uchar,
        threads: usize,
    ) -> bs_status;
    /// The same nu x nv grid on every patch, point (a, b) of patch p at (p*nu + a)*nv + b, on up to
    /// `threads` threads (since 1.1).
    pub fn bs_surface_eval_grid(
        s: *const bs_surface,
        nu: usize,
        u: *const bs_cview,
        nv: usize,
        v: *const bs_cview,
        pos: *const bs_view,
        du: *const bs_view,
        dv: *const bs_view,
        nrm: *const bs_view,
        kind: *mut c_uchar,
        threads: usize,
    ) -> bs_status;

    // ---- continuity.h ----
    /// Shared and open edges of a 3-D surface with the continuity across each shared edge; NULL arrays ask for the counts only.
    pub fn bs_surface_continuity(
        s: *const bs_surface,
        tol: f64,
        samples: usize,
        edges: *mut bs_edge_continuity,
        edges_cap: usize,
        n_edges: *mut usize,
        open: *mut bs_open_edge,
        open_cap: usize,
        n_open: *mut usize,
    ) -> bs_status;

    // ---- mesh.h ----
    /// Tessellates a 3-D surface with `nu` x `nv` segments per patch into a new mesh.
    pub fn bs_surface_tessellate_uniform(
        s: *const bs_surface,
        nu: usize,
        nv: usize,
        flags: c_int,
        out: *mut *mut bs_mesh,
    ) -> bs_status;
    /// Tessellates a 3-D surface within a chordal `tolerance` into a new mesh.
    pub fn bs_surface_tessellate_adaptive(
        s: *const bs_surface,
        tolerance: f64,
        flags: c_int,
        out: *mut *mut bs_mesh,
    ) -> bs_status;
    /// Fills tessellation options with the defaults (since 1.1).
    pub fn bs_tess_options_init(o: *mut bs_tess_options);
    /// Tessellates a 3-D surface as the options say, within their budgets (since 1.1).
    pub fn bs_surface_tessellate(
        s: *const bs_surface,
        o: *const bs_tess_options,
        out: *mut *mut bs_mesh,
    ) -> bs_status;
    /// The vertex and triangle counts `bs_surface_tessellate` would give (since 1.1).
    pub fn bs_surface_tessellate_count(
        s: *const bs_surface,
        o: *const bs_tess_options,
        vertices: *mut usize,
        triangles: *mut usize,
    ) -> bs_status;
    /// Releases a mesh; NULL does nothing.
    pub fn bs_mesh_destroy(m: *mut bs_mesh);
    /// Number of vertices; 0 for NULL.
    pub fn bs_mesh_vertex_count(m: *const bs_mesh) -> usize;
    /// Number of triangles; 0 for NULL.
    pub fn bs_mesh_triangle_count(m: *const bs_mesh) -> usize;
    /// Number of triangle strips (0 unless made with `BS_TESS_STRIPS`).
    pub fn bs_mesh_strip_count(m: *const bs_mesh) -> usize;
    /// Total number of indices in all strips.
    pub fn bs_mesh_strip_index_count(m: *const bs_mesh) -> usize;
    /// Copies the vertex positions into 3 views (x, y, z).
    pub fn bs_mesh_copy_positions(m: *const bs_mesh, xyz: *const bs_view) -> bs_status;
    /// Copies the unit vertex normals into 3 views.
    pub fn bs_mesh_copy_normals(m: *const bs_mesh, nrm: *const bs_view) -> bs_status;
    /// Copies the vertex (u, v) parameters into 2 views.
    pub fn bs_mesh_copy_uv(m: *const bs_mesh, uv: *const bs_view) -> bs_status;
    /// Copies the per-vertex patch ids into a buffer of `cap` values.
    pub fn bs_mesh_copy_patch_ids(m: *const bs_mesh, ids: *mut u32, cap: usize) -> bs_status;
    /// Copies 3 vertex indices per triangle into a buffer of `cap` values.
    pub fn bs_mesh_copy_triangles(m: *const bs_mesh, idx: *mut u32, cap: usize) -> bs_status;
    /// Copies the per-triangle patch ids into a buffer of `cap` values.
    pub fn bs_mesh_copy_triangle_patch_ids(m: *const bs_mesh, ids: *mut u32, cap: usize) -> bs_status;
    /// Copies the (u, v) of every triangle corner on its own patch into 2 views (3 corners per triangle).
    pub fn bs_mesh_copy_corner_uv(m: *const bs_mesh, uv: *const bs_view) -> bs_status;
    /// Copies the strip indices and the strip starts (strip count + 1 values) into buffers of the given capacities.
    pub fn bs_mesh_copy_strips(
        m: *const bs_mesh,
        idx: *mut u32,
        idx_cap: usize,
        start: *mut u32,
        start_cap: usize,
    ) -> bs_status;
    /// Writes the mesh to the file `path` in `format` (`BS_MESH_*`).
    pub fn bs_mesh_write(m: *const bs_mesh, format: c_int, path: *const c_char) -> bs_status;
    /// Writes the mesh into `buf` of `cap` bytes (NULL asks for the size), the size going to `*size`.
    pub fn bs_mesh_write_memory(
        m: *const bs_mesh,
        format: c_int,
        buf: *mut c_void,
        cap: usize,
        size: *mut usize,
    ) -> bs_status;

    // ---- io.h ----
    /// Parses `len` bytes of .bpt text into a new surface; on a parse error `err` (if not NULL) gets the line, column and reason.
    pub fn bs_surface_read_bpt(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    /// Reads a .bpt file into a new surface; `err` as for `bs_surface_read_bpt`.
    pub fn bs_surface_read_bpt_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    /// Writes the surface as NUL-terminated .bpt text into `buf` of `cap` bytes (NULL asks for the size, NUL included).
    pub fn bs_surface_write_bpt(
        s: *const bs_surface,
        buf: *mut c_char,
        cap: usize,
        size: *mut usize,
    ) -> bs_status;
    /// Writes the surface as a .bpt file.
    pub fn bs_surface_write_bpt_file(s: *const bs_surface, path: *const c_char) -> bs_status;
    /// Parses `len` bytes of OBJ text (its free-form surfaces) into a new surface; `err` as for `bs_surface_read_bpt`, also on `BS_ERR_UNSUPPORTED`.
    pub fn bs_surface_read_obj(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    /// Reads an OBJ file's free-form surfaces into a new surface.
    pub fn bs_surface_read_obj_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    /// Writes the surface as NUL-terminated OBJ free-form text into `buf` of `cap` bytes (NULL asks for the size, NUL included).
    pub fn bs_surface_write_obj(
        s: *const bs_surface,
        buf: *mut c_char,
        cap: usize,
        size: *mut usize,
    ) -> bs_status;
    /// Writes the surface as an OBJ file.
    pub fn bs_surface_write_obj_file(s: *const bs_surface, path: *const c_char) -> bs_status;
    /// Parses `len` bytes of IGES text (its entities 128) into a new surface; `err` as for `bs_surface_read_bpt`.
    pub fn bs_surface_read_iges(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    /// Reads an IGES file's entities 128 into a new surface.
    pub fn bs_surface_read_iges_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    /// Creates the built-in surface `name` ("teapot", "teacup", "teaspoon").
    pub fn bs_surface_create_builtin(name: *const c_char, out: *mut *mut bs_surface) -> bs_status;
    /// Name of built-in surface `i`, or NULL past the last.
    pub fn bs_builtin_name(i: usize) -> *const c_char;

    /// Knot spans along u and v of a B-spline (`bs_bspline_span_count`, since 1.1).
    pub fn bs_bspline_span_count(b: *const bs_bspline, spans_u: *mut usize, spans_v: *mut usize)
        -> bs_status;
    /// Appends one Bezier patch per knot span (`bs_surface_add_bspline`, since 1.1).
    pub fn bs_surface_add_bspline(
        s: *mut bs_surface,
        b: *const bs_bspline,
        spans: *mut f64,
        spans_cap: usize,
        count: *mut usize,
    ) -> bs_status;
    /// The patch index and local (u, v) of a B-spline parameter (`bs_bspline_locate`, since 1.1).
    pub fn bs_bspline_locate(
        b: *const bs_bspline,
        u: f64,
        v: f64,
        index: *mut usize,
        local_u: *mut f64,
        local_v: *mut f64,
    ) -> bs_status;
    /// Curvatures and principal directions at n points of a 3-D patch (`bs_patch_eval_curvature`,
    /// since 1.1).
    pub fn bs_patch_eval_curvature(
        p: *const bs_patch,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        curv: *const bs_view,
        dmin: *const bs_view,
        dmax: *const bs_view,
        kind: *mut c_uchar,
    ) -> bs_status;
    /// The grid evaluator with float outputs, each the double result rounded (since 1.1).
    pub fn bs_patch_eval_grid_f32(
        p: *const bs_patch,
        nu: usize,
        u: *const bs_cview,
        nv: usize,
        v: *const bs_cview,
        pos: *const bs_fview,
        du: *const bs_fview,
        dv: *const bs_fview,
        nrm: *const bs_fview,
        kind: *mut c_uchar,
    ) -> bs_status;
    /// Vertex positions as floats (since 1.1).
    pub fn bs_mesh_copy_positions_f32(m: *const bs_mesh, xyz: *const bs_fview) -> bs_status;
    /// Vertex normals as floats (since 1.1).
    pub fn bs_mesh_copy_normals_f32(m: *const bs_mesh, nrm: *const bs_fview) -> bs_status;
    /// Vertex (u, v) as floats (since 1.1).
    pub fn bs_mesh_copy_uv_f32(m: *const bs_mesh, uv: *const bs_fview) -> bs_status;
    /// Certified closest points of a patch to n query points (since 1.1).
    pub fn bs_patch_closest_point(
        p: *const bs_patch,
        n: usize,
        q: *const bs_cview,
        uv: *const bs_view,
        dist: *const bs_view,
        pos: *const bs_view,
    ) -> bs_status;
    /// Builds a locator over a surface (since 1.1).
    pub fn bs_locator_create(s: *const bs_surface, out: *mut *mut bs_locator) -> bs_status;
    /// Releases a locator; NULL does nothing (since 1.1).
    pub fn bs_locator_destroy(l: *mut bs_locator);
    /// Dimension of a locator's surface; 0 for NULL or empty (since 1.1).
    pub fn bs_locator_dim(l: *const bs_locator) -> usize;
    /// Certified closest points of the whole surface (since 1.1).
    pub fn bs_locator_closest_point(
        l: *const bs_locator,
        n: usize,
        q: *const bs_cview,
        patch: *mut u32,
        uv: *const bs_view,
        dist: *const bs_view,
        pos: *const bs_view,
    ) -> bs_status;
    /// First hits of n rays with the surface (since 1.1).
    pub fn bs_locator_intersect(
        l: *const bs_locator,
        n: usize,
        org: *const bs_cview,
        dir: *const bs_cview,
        trange: *const bs_cview,
        patch: *mut u32,
        uv: *const bs_view,
        t: *const bs_view,
        nrm: *const bs_view,
    ) -> bs_status;
    /// [`bs_locator_closest_point`] on up to `threads` threads (since 1.1).
    pub fn bs_locator_closest_point_mt(
        l: *const bs_locator,
        n: usize,
        q: *const bs_cview,
        patch: *mut u32,
        uv: *const bs_view,
        dist: *const bs_view,
        pos: *const bs_view,
        threads: usize,
    ) -> bs_status;
    /// [`bs_locator_intersect`] on up to `threads` threads (since 1.1).
    pub fn bs_locator_intersect_mt(
        l: *const bs_locator,
        n: usize,
        org: *const bs_cview,
        dir: *const bs_cview,
        trange: *const bs_cview,
        patch: *mut u32,
        uv: *const bs_view,
        t: *const bs_view,
        nrm: *const bs_view,
        threads: usize,
    ) -> bs_status;

    // model.h (since 1.2)
    /// `bs_model_read_step` (model.h, since 1.2).
    pub fn bs_model_read_step(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_model,
    ) -> bs_status;
    /// `bs_model_read_step_file` (model.h, since 1.2).
    pub fn bs_model_read_step_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_model,
    ) -> bs_status;
    /// `bs_model_read_iges` (model.h, since 1.2).
    pub fn bs_model_read_iges(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_model,
    ) -> bs_status;
    /// `bs_model_read_iges_file` (model.h, since 1.2).
    pub fn bs_model_read_iges_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_model,
    ) -> bs_status;
    /// `bs_model_read_obj` (model.h, since 1.2).
    pub fn bs_model_read_obj(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_model,
    ) -> bs_status;
    /// `bs_model_read_obj_file` (model.h, since 1.2).
    pub fn bs_model_read_obj_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_model,
    ) -> bs_status;
    /// `bs_model_from_surface` (model.h, since 1.2).
    pub fn bs_model_from_surface(s: *const bs_surface, out: *mut *mut bs_model) -> bs_status;
    /// `bs_model_destroy` (model.h, since 1.2).
    pub fn bs_model_destroy(m: *mut bs_model);
    /// `bs_model_write_obj` (model.h, since 1.2).
    pub fn bs_model_write_obj(
        m: *const bs_model,
        buf: *mut c_char,
        cap: usize,
        size: *mut usize,
    ) -> bs_status;
    /// `bs_model_write_obj_file` (model.h, since 1.2).
    pub fn bs_model_write_obj_file(m: *const bs_model, path: *const c_char) -> bs_status;
    /// `bs_model_face_count` (model.h, since 1.2).
    pub fn bs_model_face_count(m: *const bs_model) -> usize;
    /// `bs_model_edge_count` (model.h, since 1.2).
    pub fn bs_model_edge_count(m: *const bs_model) -> usize;
    /// `bs_model_shell_count` (model.h, since 1.2).
    pub fn bs_model_shell_count(m: *const bs_model) -> usize;
    /// `bs_model_shell_closed` (model.h, since 1.2).
    pub fn bs_model_shell_closed(m: *const bs_model, shell: usize) -> c_int;
    /// `bs_model_face_info` (model.h, since 1.2).
    pub fn bs_model_face_info(m: *const bs_model, face: usize, info: *mut bs_face_info) -> bs_status;
    /// `bs_model_surface` (model.h, since 1.2).
    pub fn bs_model_surface(m: *const bs_model) -> *const bs_surface;
    /// `bs_model_face_eval` (model.h, since 1.2).
    pub fn bs_model_face_eval(
        m: *const bs_model,
        n: usize,
        faces: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        nrm: *const bs_view,
        kind: *mut u8,
    ) -> bs_status;
    /// `bs_model_face_to_patch` (model.h, since 1.2).
    pub fn bs_model_face_to_patch(
        m: *const bs_model,
        n: usize,
        faces: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        patch: *mut u32,
        st: *const bs_view,
    ) -> bs_status;
    /// `bs_model_patch_to_face` (model.h, since 1.2).
    pub fn bs_model_patch_to_face(
        m: *const bs_model,
        n: usize,
        patch: *const u32,
        s: *const bs_cview,
        t: *const bs_cview,
        face: *mut u32,
        uv: *const bs_view,
    ) -> bs_status;
    /// `bs_model_classify` (model.h, since 1.2).
    pub fn bs_model_classify(
        m: *const bs_model,
        n: usize,
        faces: *const u32,
        u: *const bs_cview,
        v: *const bs_cview,
        tol: f64,
        where_: *mut u8,
    ) -> bs_status;
    /// `bs_locator_create_model` (model.h, since 1.2): a locator of a model's trimmed faces
    /// (rays only); the model must outlive it.
    pub fn bs_locator_create_model(m: *const bs_model, out: *mut *mut bs_locator) -> bs_status;
    /// `bs_model_tessellate` (model.h, since 1.2): one watertight mesh of a model's trimmed faces.
    pub fn bs_model_tessellate(
        m: *const bs_model,
        o: *const bs_tess_options,
        out: *mut *mut bs_mesh,
    ) -> bs_status;
    /// `bs_model_tessellate_count` (model.h, since 1.2).
    pub fn bs_model_tessellate_count(
        m: *const bs_model,
        o: *const bs_tess_options,
        vertices: *mut usize,
        triangles: *mut usize,
    ) -> bs_status;
    /// `bs_model_properties` (model.h, since 1.2).
    pub fn bs_model_properties(
        m: *const bs_model,
        rel_tol: f64,
        area: *mut f64,
        volume: *mut f64,
        centroid: *mut f64,
    ) -> bs_status;
    /// [`bs_locator_intersect`] with the kind of each hit's normal (`BS_NORMAL_*`; undefined
    /// for a miss) in `kind`, NULL or `n` bytes (since 1.2).
    pub fn bs_locator_intersect_kind(
        l: *const bs_locator,
        n: usize,
        org: *const bs_cview,
        dir: *const bs_cview,
        trange: *const bs_cview,
        patch: *mut u32,
        uv: *const bs_view,
        t: *const bs_view,
        nrm: *const bs_view,
        kind: *mut u8,
    ) -> bs_status;
}
