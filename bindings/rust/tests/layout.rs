//! The `sys` declarations against the C header: a small C program, compiled at test time with
//! the C compiler (`$CC`, else `cc`), prints the header's sizes, offsets and constants, and each
//! is compared with what the Rust side declares.

use std::collections::HashMap;
use std::mem::{align_of, offset_of, size_of};
use std::path::PathBuf;
use std::process::Command;

use bezsurf::sys;

const PROBE: &str = r#"
#include <stddef.h>
#include <stdio.h>
#include "bezsurf/core.h"
#include "bezsurf/ops.h"
#include "bezsurf/surface.h"
#include "bezsurf/io.h"
#include "bezsurf/continuity.h"
#include "bezsurf/mesh.h"
#include "bezsurf/bspline.h"
#include "bezsurf/query.h"
#include "bezsurf/model.h"

#define ALIGNOF(T) offsetof(struct { char c; T t; }, t)
#define SIZE(T) printf("size " #T " %zu\n", sizeof(T)); printf("align " #T " %zu\n", ALIGNOF(T))
#define OFF(T, f) printf("offset " #T "." #f " %zu\n", offsetof(T, f))
#define CONST(c) printf("const " #c " %lld\n", (long long)(c))

int main(void)
{
    SIZE(bs_view); OFF(bs_view, data); OFF(bs_view, count); OFF(bs_view, stride);
    SIZE(bs_cview); OFF(bs_cview, data); OFF(bs_cview, count); OFF(bs_cview, stride);
    SIZE(bs_fview); OFF(bs_fview, data); OFF(bs_fview, count); OFF(bs_fview, stride);
    SIZE(bs_curve); OFF(bs_curve, degree); OFF(bs_curve, dim); OFF(bs_curve, ctrl);
    OFF(bs_curve, weights);
    SIZE(bs_parse_error); OFF(bs_parse_error, line); OFF(bs_parse_error, column);
    OFF(bs_parse_error, message);
    SIZE(bs_edge_continuity); OFF(bs_edge_continuity, patch_a); OFF(bs_edge_continuity, patch_b);
    OFF(bs_edge_continuity, side_a); OFF(bs_edge_continuity, side_b);
    OFF(bs_edge_continuity, reversed); OFF(bs_edge_continuity, c1); OFF(bs_edge_continuity, flipped);
    OFF(bs_edge_continuity, samples); OFF(bs_edge_continuity, c0_gap);
    OFF(bs_edge_continuity, g1_angle); OFF(bs_edge_continuity, c1_defect);
    SIZE(bs_open_edge); OFF(bs_open_edge, patch); OFF(bs_open_edge, side);
    SIZE(bs_bspline); OFF(bs_bspline, deg_u); OFF(bs_bspline, deg_v); OFF(bs_bspline, count_u);
    OFF(bs_bspline, count_v); OFF(bs_bspline, dim); OFF(bs_bspline, knots_u);
    OFF(bs_bspline, knots_v); OFF(bs_bspline, ctrl); OFF(bs_bspline, weights);
    SIZE(bs_status); SIZE(size_t); SIZE(ptrdiff_t);
    CONST(BS_OK); CONST(BS_ERR_INVALID_ARG); CONST(BS_ERR_NO_MEMORY); CONST(BS_ERR_DEGREE);
    CONST(BS_ERR_DIMENSION); CONST(BS_ERR_SIZE); CONST(BS_ERR_DOMAIN); CONST(BS_ERR_NONFINITE);
    CONST(BS_ERR_PARSE); CONST(BS_ERR_IO); CONST(BS_ERR_INCOMPATIBLE); CONST(BS_ERR_UNSUPPORTED);
    CONST(BS_ERR_PRECISION);
    CONST(BS_MAX_DEGREE); CONST(BS_MAX_DIM);
    CONST(BS_NORMAL_REGULAR); CONST(BS_NORMAL_LIMIT); CONST(BS_NORMAL_UNDEFINED);
    CONST(BS_DIR_U); CONST(BS_DIR_V);
    CONST(BS_CURV_REGULAR); CONST(BS_CURV_LIMIT); CONST(BS_CURV_UNDEFINED);
    CONST(BS_SIDE_V0); CONST(BS_SIDE_U1); CONST(BS_SIDE_V1); CONST(BS_SIDE_U0);
    CONST(BS_TESS_RELATIVE); CONST(BS_TESS_STRIPS); CONST(BS_TESS_REVERSE); CONST(BS_TESS_MAX_RATE);
    CONST(BS_TESS_UNIFORM); CONST(BS_TESS_PER_PATCH); CONST(BS_TESS_SUBDIVIDE);
    SIZE(bs_tess_options); OFF(bs_tess_options, size); OFF(bs_tess_options, method);
    OFF(bs_tess_options, flags); OFF(bs_tess_options, nu); OFF(bs_tess_options, nv);
    OFF(bs_tess_options, tolerance); OFF(bs_tess_options, max_vertices);
    OFF(bs_tess_options, max_triangles); OFF(bs_tess_options, threads);
    CONST(BS_MESH_OBJ); CONST(BS_MESH_PLY); CONST(BS_MESH_PLY_ASCII); CONST(BS_MESH_STL);
    SIZE(bs_face_info); OFF(bs_face_info, size); OFF(bs_face_info, kind); OFF(bs_face_info, reversed);
    OFF(bs_face_info, shell); OFF(bs_face_info, instance); OFF(bs_face_info, first_patch);
    OFF(bs_face_info, patch_count); OFF(bs_face_info, loop_count); OFF(bs_face_info, u0);
    OFF(bs_face_info, u1); OFF(bs_face_info, v0); OFF(bs_face_info, v1);
    CONST(BS_TRIM_OUTSIDE); CONST(BS_TRIM_INSIDE); CONST(BS_TRIM_ON);
    return 0;
}
"#;

/// Compiles and runs the probe; returns its "kind name" -> value lines.
fn probe() -> HashMap<String, i64> {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let include = std::env::var_os("BEZSURF_INCLUDE_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| manifest.join("../../include"));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("layout_probe");
    std::fs::create_dir_all(&dir).unwrap();
    let src = dir.join("probe.c");
    let exe = dir.join("probe");
    std::fs::write(&src, PROBE).unwrap();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_owned());
    // A sanitizer runtime preloaded into this test (see run-sanitized-tests.sh) is not for the
    // compiler or the probe.
    let status = Command::new(&cc)
        .env_remove("LD_PRELOAD")
        .arg("-std=c99")
        .arg("-I")
        .arg(&include)
        .arg(&src)
        .arg("-o")
        .arg(&exe)
        .status()
        .unwrap_or_else(|e| panic!("cannot run the C compiler `{cc}`: {e}"));
    assert!(status.success(), "the layout probe did not compile");
    let out = Command::new(&exe).env_remove("LD_PRELOAD").output().expect("run the layout probe");
    assert!(out.status.success());
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|line| {
            let (key, value) = line.rsplit_once(' ').unwrap();
            (key.to_owned(), value.parse().unwrap())
        })
        .collect()
}

#[test]
fn sys_matches_the_c_header() {
    let c = probe();
    let mut rust: Vec<(&str, i64)> = vec![
        ("size bs_view", size_of::<sys::bs_view>() as i64),
        ("align bs_view", align_of::<sys::bs_view>() as i64),
        ("offset bs_view.data", offset_of!(sys::bs_view, data) as i64),
        ("offset bs_view.count", offset_of!(sys::bs_view, count) as i64),
        ("offset bs_view.stride", offset_of!(sys::bs_view, stride) as i64),
        ("size bs_cview", size_of::<sys::bs_cview>() as i64),
        ("align bs_cview", align_of::<sys::bs_cview>() as i64),
        ("offset bs_cview.data", offset_of!(sys::bs_cview, data) as i64),
        ("offset bs_cview.count", offset_of!(sys::bs_cview, count) as i64),
        ("offset bs_cview.stride", offset_of!(sys::bs_cview, stride) as i64),
        ("size bs_fview", size_of::<sys::bs_fview>() as i64),
        ("align bs_fview", align_of::<sys::bs_fview>() as i64),
        ("offset bs_fview.data", offset_of!(sys::bs_fview, data) as i64),
        ("offset bs_fview.count", offset_of!(sys::bs_fview, count) as i64),
        ("offset bs_fview.stride", offset_of!(sys::bs_fview, stride) as i64),
        ("size bs_curve", size_of::<sys::bs_curve>() as i64),
        ("align bs_curve", align_of::<sys::bs_curve>() as i64),
        ("offset bs_curve.degree", offset_of!(sys::bs_curve, degree) as i64),
        ("offset bs_curve.dim", offset_of!(sys::bs_curve, dim) as i64),
        ("offset bs_curve.ctrl", offset_of!(sys::bs_curve, ctrl) as i64),
        ("offset bs_curve.weights", offset_of!(sys::bs_curve, weights) as i64),
        ("size bs_parse_error", size_of::<sys::bs_parse_error>() as i64),
        ("align bs_parse_error", align_of::<sys::bs_parse_error>() as i64),
        ("offset bs_parse_error.line", offset_of!(sys::bs_parse_error, line) as i64),
        ("offset bs_parse_error.column", offset_of!(sys::bs_parse_error, column) as i64),
        ("offset bs_parse_error.message", offset_of!(sys::bs_parse_error, message) as i64),
        ("size bs_edge_continuity", size_of::<sys::bs_edge_continuity>() as i64),
        ("align bs_edge_continuity", align_of::<sys::bs_edge_continuity>() as i64),
        ("offset bs_edge_continuity.patch_a", offset_of!(sys::bs_edge_continuity, patch_a) as i64),
        ("offset bs_edge_continuity.patch_b", offset_of!(sys::bs_edge_continuity, patch_b) as i64),
        ("offset bs_edge_continuity.side_a", offset_of!(sys::bs_edge_continuity, side_a) as i64),
        ("offset bs_edge_continuity.side_b", offset_of!(sys::bs_edge_continuity, side_b) as i64),
        ("offset bs_edge_continuity.reversed", offset_of!(sys::bs_edge_continuity, reversed) as i64),
        ("offset bs_edge_continuity.c1", offset_of!(sys::bs_edge_continuity, c1) as i64),
        ("offset bs_edge_continuity.flipped", offset_of!(sys::bs_edge_continuity, flipped) as i64),
        ("offset bs_edge_continuity.samples", offset_of!(sys::bs_edge_continuity, samples) as i64),
        ("offset bs_edge_continuity.c0_gap", offset_of!(sys::bs_edge_continuity, c0_gap) as i64),
        ("offset bs_edge_continuity.g1_angle", offset_of!(sys::bs_edge_continuity, g1_angle) as i64),
        ("offset bs_edge_continuity.c1_defect", offset_of!(sys::bs_edge_continuity, c1_defect) as i64),
        ("size bs_open_edge", size_of::<sys::bs_open_edge>() as i64),
        ("align bs_open_edge", align_of::<sys::bs_open_edge>() as i64),
        ("offset bs_open_edge.patch", offset_of!(sys::bs_open_edge, patch) as i64),
        ("offset bs_open_edge.side", offset_of!(sys::bs_open_edge, side) as i64),
        ("size bs_bspline", size_of::<sys::bs_bspline>() as i64),
        ("align bs_bspline", align_of::<sys::bs_bspline>() as i64),
        ("offset bs_bspline.deg_u", offset_of!(sys::bs_bspline, deg_u) as i64),
        ("offset bs_bspline.deg_v", offset_of!(sys::bs_bspline, deg_v) as i64),
        ("offset bs_bspline.count_u", offset_of!(sys::bs_bspline, count_u) as i64),
        ("offset bs_bspline.count_v", offset_of!(sys::bs_bspline, count_v) as i64),
        ("offset bs_bspline.dim", offset_of!(sys::bs_bspline, dim) as i64),
        ("offset bs_bspline.knots_u", offset_of!(sys::bs_bspline, knots_u) as i64),
        ("offset bs_bspline.knots_v", offset_of!(sys::bs_bspline, knots_v) as i64),
        ("offset bs_bspline.ctrl", offset_of!(sys::bs_bspline, ctrl) as i64),
        ("offset bs_bspline.weights", offset_of!(sys::bs_bspline, weights) as i64),
        ("size bs_status", size_of::<sys::bs_status>() as i64),
        ("size size_t", size_of::<usize>() as i64),
        ("size ptrdiff_t", size_of::<isize>() as i64),
        ("align bs_status", align_of::<sys::bs_status>() as i64),
        ("align size_t", align_of::<usize>() as i64),
        ("align ptrdiff_t", align_of::<isize>() as i64),
        ("size bs_tess_options", size_of::<sys::bs_tess_options>() as i64),
        ("align bs_tess_options", align_of::<sys::bs_tess_options>() as i64),
        ("offset bs_tess_options.size", offset_of!(sys::bs_tess_options, size) as i64),
        ("offset bs_tess_options.method", offset_of!(sys::bs_tess_options, method) as i64),
        ("offset bs_tess_options.flags", offset_of!(sys::bs_tess_options, flags) as i64),
        ("offset bs_tess_options.nu", offset_of!(sys::bs_tess_options, nu) as i64),
        ("offset bs_tess_options.nv", offset_of!(sys::bs_tess_options, nv) as i64),
        ("offset bs_tess_options.tolerance", offset_of!(sys::bs_tess_options, tolerance) as i64),
        ("offset bs_tess_options.max_vertices", offset_of!(sys::bs_tess_options, max_vertices) as i64),
        ("offset bs_tess_options.max_triangles", offset_of!(sys::bs_tess_options, max_triangles) as i64),
        ("offset bs_tess_options.threads", offset_of!(sys::bs_tess_options, threads) as i64),
        ("size bs_face_info", size_of::<sys::bs_face_info>() as i64),
        ("align bs_face_info", align_of::<sys::bs_face_info>() as i64),
        ("offset bs_face_info.size", offset_of!(sys::bs_face_info, size) as i64),
        ("offset bs_face_info.kind", offset_of!(sys::bs_face_info, kind) as i64),
        ("offset bs_face_info.reversed", offset_of!(sys::bs_face_info, reversed) as i64),
        ("offset bs_face_info.shell", offset_of!(sys::bs_face_info, shell) as i64),
        ("offset bs_face_info.instance", offset_of!(sys::bs_face_info, instance) as i64),
        ("offset bs_face_info.first_patch", offset_of!(sys::bs_face_info, first_patch) as i64),
        ("offset bs_face_info.patch_count", offset_of!(sys::bs_face_info, patch_count) as i64),
        ("offset bs_face_info.loop_count", offset_of!(sys::bs_face_info, loop_count) as i64),
        ("offset bs_face_info.u0", offset_of!(sys::bs_face_info, u0) as i64),
        ("offset bs_face_info.u1", offset_of!(sys::bs_face_info, u1) as i64),
        ("offset bs_face_info.v0", offset_of!(sys::bs_face_info, v0) as i64),
        ("offset bs_face_info.v1", offset_of!(sys::bs_face_info, v1) as i64),
        ("const BS_TRIM_OUTSIDE", sys::BS_TRIM_OUTSIDE as i64),
        ("const BS_TRIM_INSIDE", sys::BS_TRIM_INSIDE as i64),
        ("const BS_TRIM_ON", sys::BS_TRIM_ON as i64),
    ];
    let consts: [(&str, i64); 38] = [
        ("BS_OK", sys::BS_OK as i64),
        ("BS_ERR_INVALID_ARG", sys::BS_ERR_INVALID_ARG as i64),
        ("BS_ERR_NO_MEMORY", sys::BS_ERR_NO_MEMORY as i64),
        ("BS_ERR_DEGREE", sys::BS_ERR_DEGREE as i64),
        ("BS_ERR_DIMENSION", sys::BS_ERR_DIMENSION as i64),
        ("BS_ERR_SIZE", sys::BS_ERR_SIZE as i64),
        ("BS_ERR_DOMAIN", sys::BS_ERR_DOMAIN as i64),
        ("BS_ERR_NONFINITE", sys::BS_ERR_NONFINITE as i64),
        ("BS_ERR_PARSE", sys::BS_ERR_PARSE as i64),
        ("BS_ERR_IO", sys::BS_ERR_IO as i64),
        ("BS_ERR_INCOMPATIBLE", sys::BS_ERR_INCOMPATIBLE as i64),
        ("BS_ERR_UNSUPPORTED", sys::BS_ERR_UNSUPPORTED as i64),
        ("BS_ERR_PRECISION", sys::BS_ERR_PRECISION as i64),
        ("BS_MAX_DEGREE", sys::BS_MAX_DEGREE as i64),
        ("BS_MAX_DIM", sys::BS_MAX_DIM as i64),
        ("BS_NORMAL_REGULAR", sys::BS_NORMAL_REGULAR as i64),
        ("BS_NORMAL_LIMIT", sys::BS_NORMAL_LIMIT as i64),
        ("BS_NORMAL_UNDEFINED", sys::BS_NORMAL_UNDEFINED as i64),
        ("BS_DIR_U", sys::BS_DIR_U as i64),
        ("BS_DIR_V", sys::BS_DIR_V as i64),
        ("BS_CURV_REGULAR", sys::BS_CURV_REGULAR as i64),
        ("BS_CURV_LIMIT", sys::BS_CURV_LIMIT as i64),
        ("BS_CURV_UNDEFINED", sys::BS_CURV_UNDEFINED as i64),
        ("BS_SIDE_V0", sys::BS_SIDE_V0 as i64),
        ("BS_SIDE_U1", sys::BS_SIDE_U1 as i64),
        ("BS_SIDE_V1", sys::BS_SIDE_V1 as i64),
        ("BS_SIDE_U0", sys::BS_SIDE_U0 as i64),
        ("BS_TESS_RELATIVE", sys::BS_TESS_RELATIVE as i64),
        ("BS_TESS_STRIPS", sys::BS_TESS_STRIPS as i64),
        ("BS_TESS_REVERSE", sys::BS_TESS_REVERSE as i64),
        ("BS_TESS_MAX_RATE", sys::BS_TESS_MAX_RATE as i64),
        ("BS_TESS_UNIFORM", sys::BS_TESS_UNIFORM as i64),
        ("BS_TESS_PER_PATCH", sys::BS_TESS_PER_PATCH as i64),
        ("BS_TESS_SUBDIVIDE", sys::BS_TESS_SUBDIVIDE as i64),
        ("BS_MESH_OBJ", sys::BS_MESH_OBJ as i64),
        ("BS_MESH_PLY", sys::BS_MESH_PLY as i64),
        ("BS_MESH_PLY_ASCII", sys::BS_MESH_PLY_ASCII as i64),
        ("BS_MESH_STL", sys::BS_MESH_STL as i64),
    ];
    let names: Vec<String> = consts.iter().map(|(n, _)| format!("const {n}")).collect();
    rust.extend(names.iter().zip(consts.iter()).map(|(k, (_, v))| (k.as_str(), *v)));
    assert_eq!(c.len(), rust.len(), "the probe and the Rust table list different items");
    for (key, value) in rust {
        assert_eq!(c.get(key), Some(&value), "{key}: C header vs Rust sys");
    }
}
