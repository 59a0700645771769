//! Patches: creation, accessors, control-net round trips, copies, errors, version and statuses.

use bezsurf::{sys, ErrorKind, Patch};

/// MATH.md's biquadratic net (rows i = 0..2 along u).
const NET: [f64; 27] = [
    1., 0., 2., 1., 2., 4., 1., 3., 2., //
    2., 1., 0., 2., 2., 2., 2., 4., 0., //
    4., 1., 0., 3., 3., 2., 4., 4., 2.,
];

#[test]
fn create_and_read_back() {
    let p = Patch::new(2, 2, 3, &NET).unwrap();
    assert_eq!((p.degree_u(), p.degree_v(), p.dim()), (2, 2, 3));
    assert!(!p.is_rational());
    assert_eq!(p.num_ctrl(), 9);
    assert_eq!(p.ctrl(), NET);
    assert_eq!(p.weights(), vec![1.0; 9]);
}

#[test]
fn rational_patch_keeps_its_weights() {
    let ctrl = [0., 0., 1., 0., 0., 1., 1., 1.];
    let w = [1., 2., 0.5, 3.];
    let p = Patch::new_rational(1, 1, 2, &ctrl, &w).unwrap();
    assert!(p.is_rational());
    assert_eq!(p.ctrl(), ctrl);
    assert_eq!(p.weights(), w);
}

#[test]
fn get_ctrl_reports_short_buffers_and_writes_nothing() {
    let p = Patch::new(2, 2, 3, &NET).unwrap();
    let mut short = [-7.0; 26];
    let e = p.get_ctrl(Some(&mut short), None).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Size);
    assert_eq!(e.code(), sys::BS_ERR_SIZE);
    assert!(short.iter().all(|&x| x == -7.0));
    let mut w = [0.0; 9];
    p.get_ctrl(None, Some(&mut w)).unwrap();
    assert_eq!(w, [1.0; 9]);
}

#[test]
fn clones_are_independent_and_equal() {
    let p = Patch::new(2, 2, 3, &NET).unwrap();
    let q = p.clone();
    assert_ne!(p.as_ptr(), q.as_ptr());
    drop(p);
    assert_eq!(q.ctrl(), NET);
    let r = q.try_clone().unwrap();
    assert_eq!(r.ctrl(), NET);
}

#[test]
fn creation_errors() {
    let kind = |r: bezsurf::Result<Patch>| r.unwrap_err().kind();
    assert_eq!(kind(Patch::new(65, 0, 1, &[0.0; 66])), ErrorKind::Degree);
    assert_eq!(kind(Patch::new(0, 65, 1, &[0.0; 66])), ErrorKind::Degree);
    assert_eq!(kind(Patch::new(0, 0, 0, &[])), ErrorKind::Dimension);
    assert_eq!(kind(Patch::new(0, 0, 9, &[0.0; 9])), ErrorKind::Dimension);
    assert_eq!(kind(Patch::new(2, 2, 3, &NET[..26])), ErrorKind::Size);
    assert_eq!(kind(Patch::new(1, 1, 1, &[0.0, 1.0, f64::NAN, 2.0])), ErrorKind::NonFinite);
    assert_eq!(kind(Patch::new(1, 1, 1, &[0.0, 1.0, f64::INFINITY, 2.0])), ErrorKind::NonFinite);
    let c = [0.0; 4];
    assert_eq!(kind(Patch::new_rational(1, 1, 1, &c, &[1., 1., 0., 1.])), ErrorKind::NonFinite);
    assert_eq!(kind(Patch::new_rational(1, 1, 1, &c, &[1., 1., -2., 1.])), ErrorKind::NonFinite);
    assert_eq!(kind(Patch::new_rational(1, 1, 1, &c, &[1., 1., 1.])), ErrorKind::Size);
    // The largest shape is accepted.
    let big = vec![0.5; 65 * 65 * 8];
    let p = Patch::new(64, 64, 8, &big).unwrap();
    assert_eq!((p.degree_u(), p.degree_v(), p.dim()), (64, 64, 8));
}

#[test]
fn raw_round_trip() {
    let p = Patch::new(0, 0, 1, &[3.0]).unwrap();
    let raw = p.into_raw();
    // SAFETY: raw came from into_raw and is owned by nobody else.
    let q = unsafe { Patch::from_raw(raw) };
    assert_eq!(q.ctrl(), [3.0]);
}

#[test]
fn errors_carry_code_and_library_text() {
    let e = Patch::new(0, 0, 0, &[]).unwrap_err();
    assert_eq!(e.code(), -4);
    assert_eq!(e.message(), "dimension out of range");
    assert_eq!(e.argument(), Some("dim"));
    assert_eq!(
        e.to_string(),
        "dimension out of range: argument `dim` is 0, 1 to 8 are possible (bezsurf status -4)"
    );
    let e = bezsurf::Error::from_code(-4);
    assert_eq!((e.argument(), e.detail()), (None, None));
    assert_eq!(e.to_string(), "dimension out of range (bezsurf status -4)");
    let boxed: Box<dyn std::error::Error> = Box::new(e);
    assert!(boxed.to_string().contains("dimension"));
    assert_eq!(bezsurf::status_string(0), "success");
    assert_eq!(bezsurf::status_string(12345), "unknown status");
    assert_eq!(bezsurf::Error::from_code(-999).kind(), ErrorKind::Unknown);
}

#[test]
fn version_matches_the_crate() {
    let (major, minor, patch) = bezsurf::version();
    assert_eq!(major, bezsurf::ABI_MAJOR);
    assert_eq!(bezsurf::version_string(), format!("{major}.{minor}.{patch}"));
    assert_eq!(bezsurf::version_string(), env!("CARGO_PKG_VERSION"));
}
