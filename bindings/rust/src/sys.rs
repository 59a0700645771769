//! Raw declarations of the C API (`include/bezsurf/*.h`), written by hand.
//!
//! Everything here mirrors the header exactly: the `#[repr(C)]` structs have the C layout (checked
//! against the header by `tests/layout.rs`), the constants have the header's values and every
//! function has the C signature (`size_t` is `usize`, `ptrdiff_t` is `isize`, `int` is `c_int`,
//! `unsigned` is `c_uint`). Calling these is `unsafe`; the safe layer is the rest of the crate.

#![allow(non_camel_case_types)]

use std::os::raw::{c_char, c_int, c_uchar, c_uint, c_void};

/// `bs_status`: 0 is success, failures are negative.
pub type bs_status = c_int;

pub const BS_OK: bs_status = 0;
pub const BS_ERR_INVALID_ARG: bs_status = -1;
pub const BS_ERR_NO_MEMORY: bs_status = -2;
pub const BS_ERR_DEGREE: bs_status = -3;
pub const BS_ERR_DIMENSION: bs_status = -4;
pub const BS_ERR_SIZE: bs_status = -5;
pub const BS_ERR_DOMAIN: bs_status = -6;
pub const BS_ERR_NONFINITE: bs_status = -7;
pub const BS_ERR_PARSE: bs_status = -8;
pub const BS_ERR_IO: bs_status = -9;
pub const BS_ERR_INCOMPATIBLE: bs_status = -10;
pub const BS_ERR_UNSUPPORTED: bs_status = -11;

pub const BS_MAX_DEGREE: usize = 64;
pub const BS_MAX_DIM: usize = 8;

pub const BS_NORMAL_REGULAR: c_uchar = 0;
pub const BS_NORMAL_LIMIT: c_uchar = 1;
pub const BS_NORMAL_UNDEFINED: c_uchar = 2;

pub const BS_DIR_U: c_int = 0;
pub const BS_DIR_V: c_int = 1;

pub const BS_SIDE_V0: c_int = 0;
pub const BS_SIDE_U1: c_int = 1;
pub const BS_SIDE_V1: c_int = 2;
pub const BS_SIDE_U0: c_int = 3;

pub const BS_TESS_RELATIVE: c_int = 1;
pub const BS_TESS_STRIPS: c_int = 2;
pub const BS_TESS_MAX_RATE: usize = 1024;

pub const BS_MESH_OBJ: c_int = 0;
pub const BS_MESH_PLY: c_int = 1;
pub const BS_MESH_PLY_ASCII: c_int = 2;
pub const BS_MESH_STL: c_int = 3;

/// A strided output buffer of doubles (`bs_view`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_view {
    pub data: *mut f64,
    pub count: usize,
    pub stride: isize,
}

/// A strided input buffer of doubles (`bs_cview`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_cview {
    pub data: *const f64,
    pub count: usize,
    pub stride: isize,
}

/// A Bezier curve given to the constructions (`bs_curve`, ops.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_curve {
    pub degree: usize,
    pub dim: usize,
    pub ctrl: *const f64,
    pub weights: *const f64,
}

/// Where and why parsing failed (`bs_parse_error`, io.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_parse_error {
    pub line: usize,
    pub column: usize,
    pub message: [c_char; 96],
}

/// How two patches meet along one shared edge (`bs_edge_continuity`, continuity.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_edge_continuity {
    pub patch_a: u32,
    pub patch_b: u32,
    pub side_a: c_int,
    pub side_b: c_int,
    pub reversed: c_int,
    pub c1: c_int,
    pub flipped: c_int,
    pub samples: c_int,
    pub c0_gap: f64,
    pub g1_angle: f64,
    pub c1_defect: f64,
}

/// A side of a patch that no other patch shares (`bs_open_edge`, continuity.h).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct bs_open_edge {
    pub patch: u32,
    pub side: c_int,
}

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
    pub fn bs_version_number() -> c_uint;
    pub fn bs_version_string() -> *const c_char;
    pub fn bs_status_string(s: bs_status) -> *const c_char;

    // ---- core.h: patches ----
    pub fn bs_patch_create(
        deg_u: usize,
        deg_v: usize,
        dim: usize,
        ctrl: *const f64,
        weights: *const f64,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    pub fn bs_patch_destroy(p: *mut bs_patch);
    pub fn bs_patch_clone(p: *const bs_patch, out: *mut *mut bs_patch) -> bs_status;
    pub fn bs_patch_degree_u(p: *const bs_patch) -> usize;
    pub fn bs_patch_degree_v(p: *const bs_patch) -> usize;
    pub fn bs_patch_dim(p: *const bs_patch) -> usize;
    pub fn bs_patch_is_rational(p: *const bs_patch) -> c_int;
    pub fn bs_patch_get_ctrl(
        p: *const bs_patch,
        ctrl: *mut f64,
        ctrl_cap: usize,
        weights: *mut f64,
        weights_cap: usize,
    ) -> bs_status;

    // ---- core.h: evaluation ----
    pub fn bs_patch_eval(
        p: *const bs_patch,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        du: *const bs_view,
        dv: *const bs_view,
    ) -> bs_status;
    pub fn bs_patch_eval_deriv(
        p: *const bs_patch,
        ku: c_uint,
        kv: c_uint,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        out: *const bs_view,
    ) -> bs_status;
    pub fn bs_patch_eval_normal(
        p: *const bs_patch,
        n: usize,
        u: *const bs_cview,
        v: *const bs_cview,
        pos: *const bs_view,
        nrm: *const bs_view,
        kind: *mut c_uchar,
    ) -> bs_status;
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
    pub fn bs_patch_split(
        p: *const bs_patch,
        dir: c_int,
        t: f64,
        lo: *mut *mut bs_patch,
        hi: *mut *mut bs_patch,
    ) -> bs_status;
    pub fn bs_patch_split4(p: *const bs_patch, u: f64, v: f64, out: *mut *mut bs_patch) -> bs_status;
    pub fn bs_patch_subpatch(
        p: *const bs_patch,
        u0: f64,
        u1: f64,
        v0: f64,
        v1: f64,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    pub fn bs_patch_elevate(
        p: *const bs_patch,
        raise_u: usize,
        raise_v: usize,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    pub fn bs_patch_derivative(
        p: *const bs_patch,
        ku: c_uint,
        kv: c_uint,
        out: *mut *mut bs_patch,
    ) -> bs_status;
    pub fn bs_patch_isocurve(
        p: *const bs_patch,
        dir: c_int,
        t: f64,
        ctrl: *mut f64,
        ctrl_cap: usize,
        weights: *mut f64,
        weights_cap: usize,
    ) -> bs_status;
    pub fn bs_patch_bounds(p: *const bs_patch, lo: *mut f64, hi: *mut f64) -> bs_status;
    pub fn bs_patch_transform(p: *const bs_patch, affine: *const f64, out: *mut *mut bs_patch) -> bs_status;

    pub fn bs_patch_swap_uv(p: *const bs_patch, out: *mut *mut bs_patch) -> bs_status;
    pub fn bs_patch_reverse(p: *const bs_patch, dir: c_int, out: *mut *mut bs_patch) -> bs_status;
    pub fn bs_patch_ruled(c0: *const bs_curve, c1: *const bs_curve, out: *mut *mut bs_patch) -> bs_status;
    pub fn bs_patch_coons(
        v0: *const bs_curve,
        v1: *const bs_curve,
        u0: *const bs_curve,
        u1: *const bs_curve,
        out: *mut *mut bs_patch,
    ) -> bs_status;

    // ---- surface.h ----
    pub fn bs_surface_create(out: *mut *mut bs_surface) -> bs_status;
    pub fn bs_surface_destroy(s: *mut bs_surface);
    pub fn bs_surface_clone(s: *const bs_surface, out: *mut *mut bs_surface) -> bs_status;
    pub fn bs_surface_add(s: *mut bs_surface, p: *const bs_patch, index: *mut usize) -> bs_status;
    pub fn bs_surface_count(s: *const bs_surface) -> usize;
    pub fn bs_surface_dim(s: *const bs_surface) -> usize;
    pub fn bs_surface_get(s: *const bs_surface, i: usize) -> *const bs_patch;

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

    // ---- continuity.h ----
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
    pub fn bs_surface_tessellate_uniform(
        s: *const bs_surface,
        nu: usize,
        nv: usize,
        flags: c_int,
        out: *mut *mut bs_mesh,
    ) -> bs_status;
    pub fn bs_surface_tessellate_adaptive(
        s: *const bs_surface,
        tolerance: f64,
        flags: c_int,
        out: *mut *mut bs_mesh,
    ) -> bs_status;
    pub fn bs_mesh_destroy(m: *mut bs_mesh);
    pub fn bs_mesh_vertex_count(m: *const bs_mesh) -> usize;
    pub fn bs_mesh_triangle_count(m: *const bs_mesh) -> usize;
    pub fn bs_mesh_strip_count(m: *const bs_mesh) -> usize;
    pub fn bs_mesh_strip_index_count(m: *const bs_mesh) -> usize;
    pub fn bs_mesh_copy_positions(m: *const bs_mesh, xyz: *const bs_view) -> bs_status;
    pub fn bs_mesh_copy_normals(m: *const bs_mesh, nrm: *const bs_view) -> bs_status;
    pub fn bs_mesh_copy_uv(m: *const bs_mesh, uv: *const bs_view) -> bs_status;
    pub fn bs_mesh_copy_patch_ids(m: *const bs_mesh, ids: *mut u32, cap: usize) -> bs_status;
    pub fn bs_mesh_copy_triangles(m: *const bs_mesh, idx: *mut u32, cap: usize) -> bs_status;
    pub fn bs_mesh_copy_triangle_patch_ids(m: *const bs_mesh, ids: *mut u32, cap: usize) -> bs_status;
    pub fn bs_mesh_copy_corner_uv(m: *const bs_mesh, uv: *const bs_view) -> bs_status;
    pub fn bs_mesh_copy_strips(
        m: *const bs_mesh,
        idx: *mut u32,
        idx_cap: usize,
        start: *mut u32,
        start_cap: usize,
    ) -> bs_status;
    pub fn bs_mesh_write(m: *const bs_mesh, format: c_int, path: *const c_char) -> bs_status;
    pub fn bs_mesh_write_memory(
        m: *const bs_mesh,
        format: c_int,
        buf: *mut c_void,
        cap: usize,
        size: *mut usize,
    ) -> bs_status;

    // ---- io.h ----
    pub fn bs_surface_read_bpt(
        text: *const c_char,
        len: usize,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    pub fn bs_surface_read_bpt_file(
        path: *const c_char,
        err: *mut bs_parse_error,
        out: *mut *mut bs_surface,
    ) -> bs_status;
    pub fn bs_surface_write_bpt(
        s: *const bs_surface,
        buf: *mut c_char,
        cap: usize,
        size: *mut usize,
    ) -> bs_status;
    pub fn bs_surface_write_bpt_file(s: *const bs_surface, path: *const c_char) -> bs_status;
    pub fn bs_surface_create_builtin(name: *const c_char, out: *mut *mut bs_surface) -> bs_status;
    pub fn bs_builtin_name(i: usize) -> *const c_char;
}
