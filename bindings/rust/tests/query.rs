//! Curvature through the safe layer: a cylinder's principal curvatures, undefined points, errors.

use bezsurf::{CurvatureKind, ErrorKind, Patch};

#[test]
fn cylinder_and_errors() {
    let (r, h) = (2.5, 0.5f64.sqrt());
    let a = [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    let mut ctrl = Vec::new();
    for i in 0..2 {
        for (x, y) in a {
            ctrl.extend_from_slice(&[r * x, r * y, 4.0 * i as f64]);
        }
    }
    let p = Patch::new_rational(1, 2, 3, &ctrl, &[1.0, h, 1.0, 1.0, h, 1.0]).unwrap();
    let c = p.eval_curvature(&[0.25, f64::NAN], &[0.5, 0.5]).unwrap();
    assert_eq!(c[0].kind, CurvatureKind::Regular);
    let (small, big) =
        if c[0].k_min.abs() < c[0].k_max.abs() { (c[0].k_min, c[0].k_max) } else { (c[0].k_max, c[0].k_min) };
    assert!(small.abs() < 1e-12 && (big.abs() - 1.0 / r).abs() < 1e-12, "{:?}", c[0]);
    assert_eq!(c[1].kind, CurvatureKind::Undefined);
    assert!(c[1].gaussian.is_nan() && c[1].d_max[2].is_nan());
    let e = p.eval_curvature(&[0.1, 0.2], &[0.3]).unwrap_err();
    assert_eq!((e.kind(), e.argument()), (ErrorKind::Size, Some("v")));
    let flat = Patch::new(1, 1, 2, &[0., 0., 0., 1., 1., 0., 1., 1.]).unwrap();
    assert_eq!(flat.eval_curvature(&[0.5], &[0.5]).unwrap_err().kind(), ErrorKind::Dimension);
    assert!(p.eval_curvature(&[], &[]).unwrap().is_empty());
}
