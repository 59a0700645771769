//! Errors found by the binding name the argument they are about and say what is wrong; errors
//! the library reports about an output that is too small name that output.

use bezsurf::{
    Curve, Dir, ErrorKind, MeshFormat, Outputs, Patch, Strided, StridedMut, Surface, TessFlags, TessMethod,
    TessOptions,
};

fn plane() -> Patch {
    Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0.]).unwrap()
}

#[track_caller]
fn assert_names(e: &bezsurf::Error, kind: ErrorKind, arg: &str, words: &str) {
    assert_eq!(e.kind(), kind, "{e}");
    assert_eq!(e.argument(), Some(arg), "{e}");
    let text = e.to_string();
    assert!(text.contains(&format!("argument `{arg}`")), "{text}");
    assert!(text.contains(words), "{text}");
}

#[test]
fn u_v_length_mismatch_names_both() {
    let p = plane();
    let mut pos = [7.0; 9];
    let e = p.eval(&[0.0, 0.5, 1.0], &[0.5, 0.5], &mut pos).unwrap_err();
    assert_names(&e, ErrorKind::Size, "v", "has 2 values but `u` has 3; they must have the same length");
    assert_eq!(pos, [7.0; 9], "nothing written");
    let e = p.eval_deriv(1, 0, &[0.5], &[] as &[f64], &mut pos).unwrap_err();
    assert_names(&e, ErrorKind::Size, "v", "has 0 values but `u` has 1");
    let e = p.eval_normal(&[0.5], &[0.5, 0.5], Outputs::new().pos(&mut pos)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "v", "has 2 values but `u` has 1");
}

#[test]
fn surface_ids_length_mismatch_names_ids() {
    let mut s = Surface::new().unwrap();
    s.add(&plane()).unwrap();
    let mut pos = [0.0; 6];
    let e = s.eval(&[0], &[0.5, 0.5], &[0.5, 0.5], Outputs::new().pos(&mut pos)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "ids", "has 1 value but `u` and `v` have 2");
    let e = s.eval_normal(&[0, 0], &[0.5, 0.5], &[0.5], Outputs::new().pos(&mut pos)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "v", "has 1 value but `u` has 2");
}

#[test]
fn short_outputs_are_named() {
    let p = plane();
    let u = [0.0, 0.5, 1.0];
    let (mut pos, mut du, mut dv) = ([0.0; 9], [0.0; 9], [-1.0; 6]);
    let e = p.eval_with(&u, &u, Outputs::new().pos(&mut pos).du(&mut du).dv(&mut dv)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "dv", "has room for 2 points, but 3 points must be written");
    assert_eq!(dv, [-1.0; 6]);
    let mut x = [0.0; 3];
    let mut y = [0.0; 3];
    let mut z = [0.0; 1];
    let views = [StridedMut::from(&mut x), StridedMut::from(&mut y), StridedMut::from(&mut z)];
    let e = p.eval_normal(&u, &u, Outputs::new().normal(views)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "normal", "has room for 1 point, but 3 points must be written");
    let mut kind = [0u8; 2];
    let e = p.eval_normal(&u, &u, Outputs::new().kind(&mut kind)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "kind", "has room for 2 bytes, but 3 bytes must be written");
    let mut grid = [0.0; 3 * 8];
    let e = p.eval_grid(&u, &u, Outputs::new().pos(&mut grid)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "pos", "has room for 8 points, but 9 points must be written");
    let mut d = [0.0; 3];
    let e = p.eval_deriv(0, 1, &u, &u, &mut d).unwrap_err();
    assert_names(&e, ErrorKind::Size, "out", "has room for 1 point, but 3 points must be written");
}

#[test]
fn outputs_a_method_does_not_compute_are_named() {
    let p = plane();
    let mut buf = [0.0; 3];
    let mut kind = [0u8; 1];
    let e = p.eval_with(&[0.5], &[0.5], Outputs::new().normal(&mut buf)).unwrap_err();
    assert_names(&e, ErrorKind::InvalidArg, "normal", "is not an output of eval_with; use eval_normal");
    let e = p.eval_with(&[0.5], &[0.5], Outputs::new().kind(&mut kind)).unwrap_err();
    assert_names(&e, ErrorKind::InvalidArg, "kind", "eval_normal");
    let e = p.eval_normal(&[0.5], &[0.5], Outputs::new().dv(&mut buf)).unwrap_err();
    assert_names(&e, ErrorKind::InvalidArg, "dv", "is not an output of eval_normal; use eval_with");
    let mut a = [0.0; 1];
    let mut b = [0.0; 1];
    let views = [StridedMut::from(&mut a), StridedMut::from(&mut b)];
    let e = p.eval(&[0.5], &[0.5], views).unwrap_err();
    assert_names(&e, ErrorKind::Dimension, "pos", "has 2 views for points of dimension 3");
}

#[test]
fn construction_errors_name_the_argument() {
    let e = Patch::new(65, 1, 3, &[]).unwrap_err();
    assert_names(&e, ErrorKind::Degree, "deg_u", "is 65, at most 64 is possible");
    let e = Patch::new(1, 70, 3, &[]).unwrap_err();
    assert_names(&e, ErrorKind::Degree, "deg_v", "is 70");
    let e = Patch::new(1, 1, 9, &[]).unwrap_err();
    assert_names(&e, ErrorKind::Dimension, "dim", "is 9, 1 to 8 are possible");
    let e = Patch::new(1, 1, 3, &[0.0; 11]).unwrap_err();
    assert_names(
        &e,
        ErrorKind::Size,
        "ctrl",
        "has 11 values; a degree (1, 1) net of dimension 3 needs exactly 12",
    );
    let e = Patch::new_rational(1, 1, 1, &[0.0; 4], &[1.0; 5]).unwrap_err();
    assert_names(&e, ErrorKind::Size, "weights", "has 5 values; a degree (1, 1) net needs exactly 4");
    let e = Curve::new(1, 2, &[0.0; 3]).unwrap_err();
    assert_names(&e, ErrorKind::Size, "ctrl", "has 3 values, exactly 4 are needed");
    let e = Curve::new_rational(1, 2, &[0.0; 4], &[1.0]).unwrap_err();
    assert_names(&e, ErrorKind::Size, "weights", "has 1 value, exactly 2 are needed");
    let e = Curve::new(99, 2, &[]).unwrap_err();
    assert_names(&e, ErrorKind::Degree, "degree", "is 99");
}

#[test]
fn slice_arguments_of_patch_methods_are_named() {
    let p = plane();
    let (mut lo, mut hi) = ([0.0; 3], [0.0; 2]);
    assert_names(
        &p.bounds_into(&mut lo, &mut hi).unwrap_err(),
        ErrorKind::Size,
        "hi",
        "has 2 values, at least 3",
    );
    assert_names(&p.transform(&[0.0; 9]).unwrap_err(), ErrorKind::Size, "affine", "exactly 12");
    let mut ctrl = [0.0; 11];
    let e = p.get_ctrl(Some(&mut ctrl), None).unwrap_err();
    assert_names(&e, ErrorKind::Size, "ctrl", "has 11 values, at least 12 are needed");
    let mut w = [0.0; 3];
    let e = p.get_ctrl(None, Some(&mut w)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "weights", "has 3 values, at least 4 are needed");
    let mut iso = [0.0; 5];
    let e = p.isocurve_into(Dir::U, 0.5, &mut iso, None).unwrap_err();
    assert_names(&e, ErrorKind::Size, "ctrl", "has 5 values, at least 6 are needed");
    let mut iso = [0.0; 6];
    let mut w = [0.0; 1];
    let e = p.isocurve_into(Dir::U, 0.5, &mut iso, Some(&mut w)).unwrap_err();
    assert_names(&e, ErrorKind::Size, "weights", "has 1 value, at least 2 are needed");
}

#[test]
fn strings_with_nul_bytes_are_named() {
    assert_names(&Surface::builtin("tea\0pot").unwrap_err(), ErrorKind::InvalidArg, "name", "NUL byte at 3");
    assert_names(
        &Surface::read_bpt_file("a\0b").unwrap_err(),
        ErrorKind::InvalidArg,
        "path",
        "NUL byte at 1",
    );
}

#[test]
fn mesh_outputs_too_small_are_named() {
    let mut s = Surface::new().unwrap();
    s.add(&plane()).unwrap();
    let mesh = s.tessellate_uniform(2, 2, bezsurf::TessFlags::NONE).unwrap();
    assert_eq!(mesh.vertex_count(), 9);
    let mut xyz = vec![0.0; 3 * 8];
    assert_names(
        &mesh.copy_positions(&mut xyz).unwrap_err(),
        ErrorKind::Size,
        "out",
        "has room for 8 points, but 9 points must be written",
    );
    let mut uv = vec![0.0; 6 * mesh.triangle_count() - 1];
    assert_names(
        &mesh.copy_corner_uv(&mut uv).unwrap_err(),
        ErrorKind::Size,
        "out",
        "but 24 points must be written",
    );
}

#[test]
fn huge_strides_evaluate_without_panicking() {
    let p = plane();
    let uv = [0.25, 0.75, 0.5];
    for stride in [3, 1 << 20, isize::MAX as usize, isize::MAX as usize + 1, usize::MAX] {
        let u = Strided::new(&uv, stride);
        let v = Strided::new(&uv[1..], stride);
        let mut out = [0.0; 3];
        let mut buf = [9.0; 7];
        let [x, y, z] = StridedMut::split_interleaved::<3>(&mut buf);
        p.eval(u, v, [x, y, z]).unwrap();
        assert_eq!(buf, [0.25, 0.75, 0.0, 9.0, 9.0, 9.0, 9.0]);
        p.eval(u.rev(), v.rev(), &mut out).unwrap();
        assert_eq!(out, [0.25, 0.75, 0.0]);
        let (a, rest) = buf.split_at_mut(2);
        let (b, c) = rest.split_at_mut(2);
        let cols = [a, b, c].map(|s| StridedMut::new(s, stride));
        assert!(cols.iter().all(|c| c.len() == 1));
        p.eval_deriv(1, 0, u, v, PointsMut::views(cols)).unwrap();
        assert_eq!(buf, [1.0, 0.75, 0.0, 9.0, 0.0, 9.0, 9.0]);
    }
    let e = Strided::try_new(&uv, 0).unwrap_err();
    assert_names(&e, ErrorKind::InvalidArg, "stride", "must be at least 1, got 0");
}

#[test]
fn io_error_conversion_keeps_the_message() {
    let e = Patch::new(1, 1, 0, &[]).unwrap_err();
    let io: std::io::Error = e.clone().into();
    assert_eq!(io.kind(), std::io::ErrorKind::InvalidInput);
    assert_eq!(io.to_string(), e.to_string());
    let parse: std::io::Error = Surface::read_bpt("1\n3 3\nnot numbers").unwrap_err().into();
    assert_eq!(parse.kind(), std::io::ErrorKind::InvalidData);
}

use bezsurf::PointsMut;

#[test]
fn zero_points_need_no_room_and_short_buffers_are_named() {
    let p = plane();
    let none: [f64; 0] = [];
    let mut empty: [f64; 0] = [];
    p.eval(&none, &none, &mut empty).unwrap();
    let mut short = [5.0; 2]; // room for no 3-D point
    p.eval(&none, &none, &mut short).unwrap();
    let [x, y, z] = StridedMut::split_interleaved::<3>(&mut short);
    p.eval_grid(&none, &[0.5], Outputs::new().pos([x, y, z])).unwrap();
    assert_eq!(short, [5.0; 2]);
    let e = p.eval(&[0.5], &[0.5], &mut short).unwrap_err();
    assert_names(&e, ErrorKind::Size, "pos", "has room for 0 points, but 1 point must be written");
    assert_eq!(short, [5.0; 2]);
    let mut s = Surface::new().unwrap();
    s.add(&p).unwrap();
    s.eval(&[], &none, &none, Outputs::new().pos(&mut empty)).unwrap();
}

#[test]
fn library_errors_name_the_argument_the_value_and_the_limit() {
    let err = Surface::builtin("kettle").unwrap_err();
    assert_eq!((err.kind(), err.argument()), (ErrorKind::InvalidArg, Some("name")));
    assert!(err.to_string().contains("\"kettle\" is not a built-in surface"), "{err}");
    assert!(err.to_string().contains("teapot, teacup, teaspoon"), "{err}");

    let pot = Surface::builtin("teapot").unwrap();
    let mut pos = [0.0; 6];
    let err = pot.eval(&[0, 32], &[0.5, 0.5], &[0.5, 0.5], Outputs::new().pos(&mut pos)).unwrap_err();
    assert_eq!(err.argument(), Some("ids"));
    assert!(err.to_string().contains("[1] is 32, not a patch of this surface (patch ids 0..=31)"), "{err}");

    let err = pot.tessellate_uniform(0, 4, TessFlags::NONE).unwrap_err();
    assert_eq!((err.kind(), err.argument()), (ErrorKind::Domain, Some("nu")));
    assert!(err.to_string().contains("is 0 segments per patch, outside 1..=1024"), "{err}");
    let err = pot.tessellate_adaptive(-1.0, TessFlags::NONE).unwrap_err();
    assert_eq!(err.argument(), Some("tolerance"));
    let opts = TessOptions::new(TessMethod::Uniform { nu: 16, nv: 16 }).max_triangles(1000);
    let err = pot.tessellate(&opts).unwrap_err();
    assert_eq!((err.kind(), err.argument()), (ErrorKind::Size, Some("max_triangles")));
    assert!(
        err.to_string()
            .contains("the mesh would have 8258 vertices and 16256 triangles, over the budget of 1000"),
        "{err}"
    );

    let square = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.]).unwrap();
    let err = square.elevate(64, 0).unwrap_err();
    assert_eq!((err.kind(), err.argument()), (ErrorKind::Degree, Some("raise_u")));
    assert!(err.to_string().contains("degree 1 + 64 is above the limit 64"), "{err}");

    // file errors name the file
    let missing = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("no-such-dir/missing.bpt");
    let err = Surface::read_bpt_file(&missing).unwrap_err();
    assert_eq!(err.path(), Some(missing.as_path()));
    assert!(err.to_string().contains("no-such-dir/missing.bpt"), "{err}");
    let err = pot.write_obj_file(&missing).unwrap_err();
    assert_eq!(err.path(), Some(missing.as_path()));
    let mesh = pot.tessellate_uniform(1, 1, TessFlags::NONE).unwrap();
    assert_eq!(mesh.write(MeshFormat::Obj, &missing).unwrap_err().path(), Some(missing.as_path()));
}
