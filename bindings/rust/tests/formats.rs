//! OBJ free-form and IGES surfaces: round trips, errors with their position, the IGES fixtures
//! written by OpenCASCADE (tests/io/data/iges/).

use std::path::PathBuf;

use bezsurf::{ErrorKind, Surface};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/io/data/iges").join(name)
}

#[test]
fn obj_round_trips_bit_for_bit() {
    let pot = Surface::builtin("teapot").unwrap();
    let text = pot.write_obj().unwrap();
    assert!(text.contains("cstype bezier\ndeg 3 3\nsurf 0 1 0 1 1 5 9 13 2"));
    assert_eq!(Surface::read_obj(&text).unwrap(), pot);
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("teapot_copy.obj");
    pot.write_obj_file(&path).unwrap();
    assert_eq!(Surface::read_obj_file(&path).unwrap(), pot);
}

#[test]
fn obj_errors_report_where() {
    let err = Surface::read_obj("v 0 0 0\nv 1 x 0\n").unwrap_err();
    assert_eq!((err.kind(), err.position()), (ErrorKind::Parse, Some((2, 5))));
    let err = Surface::read_obj("v 0 0 0\ncstype taylor\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n").unwrap_err();
    assert_eq!((err.kind(), err.position()), (ErrorKind::Unsupported, Some((4, 1))));
    assert!(err.detail().unwrap_or("").contains("taylor"));
    let missing = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("no-such-dir/x.obj");
    assert_eq!(Surface::read_obj_file(missing).unwrap_err().kind(), ErrorKind::Io);
}

#[test]
fn iges_fixtures_read() {
    let cyl = Surface::read_iges_file(fixture("nurbs_cylinder.igs")).unwrap();
    assert_eq!(cyl.len(), 1);
    assert!(cyl.iter().all(|p| p.is_rational()));
    let text = std::fs::read(fixture("bicubic_knots.igs")).unwrap();
    assert_eq!(Surface::read_iges(text).unwrap().len(), 12);
    let err = Surface::read_iges("too short\n").unwrap_err();
    assert_eq!((err.kind(), err.position()), (ErrorKind::Parse, Some((1, 10))));
}
