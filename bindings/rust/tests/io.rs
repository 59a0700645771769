//! The .bpt format and the built-in tea set, checked against the data files in data/.

use std::path::PathBuf;

use bezsurf::{ErrorKind, Patch, Surface};

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data").join(name)
}

fn nets(s: &Surface) -> Vec<Vec<f64>> {
    s.iter().map(|p| p.ctrl()).collect()
}

#[test]
fn builtin_tea_set_equals_the_data_files() {
    assert_eq!(bezsurf::builtin_names(), ["teapot", "teacup", "teaspoon"]);
    for (name, count) in [("teapot", 32), ("teacup", 26), ("teaspoon", 16)] {
        let built = Surface::builtin(name).unwrap();
        let file = Surface::read_bpt_file(data(&format!("{name}.bpt"))).unwrap();
        assert_eq!((built.len(), built.dim()), (count, 3), "{name}");
        assert!(built.iter().all(|p| p.degree_u() == 3 && p.degree_v() == 3 && !p.is_rational()));
        assert_eq!(nets(&built), nets(&file), "{name}");
    }
    assert_eq!(Surface::builtin("saucer").unwrap_err().kind(), ErrorKind::InvalidArg);
    assert_eq!(Surface::builtin("tea\0pot").unwrap_err().kind(), ErrorKind::InvalidArg);
}

#[test]
fn teapot_first_patch_starts_at_the_file_s_first_point() {
    let teapot = Surface::builtin("teapot").unwrap();
    let rim = teapot.get(0).unwrap();
    // data/teapot.bpt: first control point "1.4 0.0 2.4"; a patch interpolates its corners.
    assert_eq!(rim.ctrl()[..3], [1.4, 0.0, 2.4]);
    assert_eq!(rim.eval_point(0.0, 0.0).unwrap(), [1.4, 0.0, 2.4]);
}

#[test]
fn text_round_trip_is_exact() {
    let mut s = Surface::new().unwrap();
    s.add(
        &Patch::new(
            1,
            2,
            3,
            &[
                0.1,
                1e-300,
                -7.25,
                1.0 / 3.0,
                2.,
                3.,
                4.,
                5.,
                6.,
                7.,
                8.,
                9.,
                10.,
                11.,
                12.,
                13.,
                14.,
                2.0f64.sqrt(),
            ],
        )
        .unwrap(),
    )
    .unwrap();
    let w = [1., 2., 0.5, 3., 1.25, 1e-3];
    let ctrl: Vec<f64> = (0..18).map(|k| k as f64 * 0.7).collect();
    s.add(&Patch::new_rational(1, 2, 3, &ctrl, &w).unwrap()).unwrap();
    let text = s.write_bpt().unwrap();
    assert!(text.starts_with('2'));
    let back = Surface::read_bpt(&text).unwrap();
    assert_eq!(back.len(), 2);
    for (a, b) in s.iter().zip(back.iter()) {
        let bits = |v: Vec<f64>| v.into_iter().map(f64::to_bits).collect::<Vec<_>>();
        assert_eq!(bits(a.ctrl()), bits(b.ctrl()));
        assert_eq!(bits(a.weights()), bits(b.weights()));
        assert_eq!(a.is_rational(), b.is_rational());
    }
}

#[test]
fn file_round_trip() {
    let teapot = Surface::builtin("teapot").unwrap();
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("teapot_copy.bpt");
    teapot.write_bpt_file(&path).unwrap();
    let back = Surface::read_bpt_file(&path).unwrap();
    assert_eq!(nets(&back), nets(&teapot));
    let _ = std::fs::remove_file(&path);
}

#[test]
fn parse_errors_report_where() {
    let text = "1\n1 1\n0 0 0\n0 0 zz\n1 0 0\n1 1 0\n";
    let e = Surface::read_bpt(text).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Parse);
    assert_eq!(e.position(), Some((4, 5)));
    assert!(e.detail().is_some_and(|d| !d.is_empty()));
    assert!(e.to_string().contains("line 4, column 5"));
    assert_eq!(Surface::read_bpt("").unwrap_err().kind(), ErrorKind::Parse);
}

#[test]
fn io_errors() {
    let missing = data("no-such-file.bpt");
    let e = Surface::read_bpt_file(&missing).unwrap_err();
    assert_eq!((e.kind(), e.position()), (ErrorKind::Io, None));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("no-such-dir/x.bpt");
    let teapot = Surface::builtin("teapot").unwrap();
    assert_eq!(teapot.write_bpt_file(&dir).unwrap_err().kind(), ErrorKind::Io);
}

#[test]
fn only_3d_surfaces_are_written() {
    let mut s = Surface::new().unwrap();
    s.add(&Patch::new(0, 0, 2, &[1., 2.]).unwrap()).unwrap();
    assert_eq!(s.write_bpt().unwrap_err().kind(), ErrorKind::Dimension);
    assert_eq!(Surface::new().unwrap().write_bpt().unwrap().trim(), "0");
}
