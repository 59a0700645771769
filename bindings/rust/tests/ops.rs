//! Exact operations, checked against nets worked out by hand (de Casteljau, the elevation
//! formula, forward differences and the definitions of ruled and Coons patches).

use bezsurf::{Curve, Dir, ErrorKind, Patch};

/// f(u, v) = 2u + v as a bilinear scalar patch: P00 = 0, P01 = 1, P10 = 2, P11 = 3.
fn bilinear() -> Patch {
    Patch::new(1, 1, 1, &[0., 1., 2., 3.]).unwrap()
}

#[test]
fn split_along_u_and_v() {
    let p = Patch::new(2, 0, 1, &[0., 4., 0.]).unwrap();
    let (lo, hi) = p.split(Dir::U, 0.5).unwrap();
    assert_eq!(lo.ctrl(), [0., 2., 2.]);
    assert_eq!(hi.ctrl(), [2., 2., 0.]);
    let q = Patch::new(0, 2, 1, &[0., 4., 0.]).unwrap();
    let (lo, hi) = q.split(Dir::V, 0.25).unwrap();
    // Level 1: [1, 3]; level 2: [0.75 * 1 + 0.25 * 3] = [1.5].
    assert_eq!(lo.ctrl(), [0., 1., 1.5]);
    assert_eq!(hi.ctrl(), [1.5, 3., 0.]);
    assert_eq!((lo.degree_u(), lo.degree_v()), (0, 2));
}

#[test]
fn split_rejects_parameters_outside_the_open_interval() {
    let p = bilinear();
    for t in [0.0, 1.0, -0.5, 2.0, f64::NAN, f64::INFINITY] {
        assert_eq!(p.split(Dir::U, t).unwrap_err().kind(), ErrorKind::Domain, "t = {t}");
    }
    assert_eq!(p.split4(0.5, 1.0).unwrap_err().kind(), ErrorKind::Domain);
}

#[test]
fn split4_gives_the_four_quarters_in_documented_order() {
    let [a, b, c, d] = bilinear().split4(0.5, 0.5).unwrap();
    // Nets are the corner values of f over each quarter (a bilinear patch is its own net).
    assert_eq!(a.ctrl(), [0., 0.5, 1., 1.5]); // [0,.5] x [0,.5]
    assert_eq!(b.ctrl(), [1., 1.5, 2., 2.5]); // [.5,1] x [0,.5]
    assert_eq!(c.ctrl(), [0.5, 1., 1.5, 2.]); // [0,.5] x [.5,1]
    assert_eq!(d.ctrl(), [1.5, 2., 2.5, 3.]); // [.5,1] x [.5,1]
}

#[test]
fn subpatch_with_a_reversed_direction() {
    // Q(s, r) = f(0.25 + 0.5 s, 1 - r).
    let q = bilinear().subpatch(0.25, 0.75, 1.0, 0.0).unwrap();
    assert_eq!(q.ctrl(), [1.5, 0.5, 2.5, 1.5]);
    assert_eq!(bilinear().subpatch(0.5, 0.5, 0., 1.).unwrap_err().kind(), ErrorKind::Domain);
}

#[test]
fn elevation_keeps_the_surface() {
    let p = Patch::new(1, 0, 1, &[0., 3.]).unwrap();
    let q = p.elevate(2, 0).unwrap();
    assert_eq!((q.degree_u(), q.degree_v()), (3, 0));
    assert_eq!(q.ctrl(), [0., 1., 2., 3.]);
    let c = Patch::new(0, 0, 2, &[5., -1.]).unwrap().elevate(1, 1).unwrap();
    assert_eq!(c.ctrl(), [5., -1., 5., -1., 5., -1., 5., -1.]);
    assert_eq!(p.elevate(64, 0).unwrap_err().kind(), ErrorKind::Degree);
}

#[test]
fn hodographs_are_scaled_differences() {
    let p = Patch::new(2, 0, 1, &[0., 4., 0.]).unwrap();
    let d1 = p.derivative(1, 0).unwrap();
    assert_eq!((d1.degree_u(), d1.ctrl()), (1, vec![8., -8.]));
    let d2 = p.derivative(2, 0).unwrap();
    assert_eq!((d2.degree_u(), d2.ctrl()), (0, vec![-16.]));
    let d3 = p.derivative(3, 0).unwrap();
    assert_eq!((d3.degree_u(), d3.degree_v(), d3.ctrl()), (0, 0, vec![0.]));
    let mixed = bilinear().derivative(1, 1).unwrap();
    assert_eq!(mixed.ctrl(), [0.]); // f = 2u + v has no uv term
    let r = Patch::new_rational(1, 0, 1, &[0., 1.], &[1., 2.]).unwrap();
    assert_eq!(r.derivative(1, 0).unwrap_err().kind(), ErrorKind::Unsupported);
    assert_eq!(p.derivative(65, 0).unwrap_err().kind(), ErrorKind::Degree);
}

#[test]
fn isocurves_of_the_bilinear_patch() {
    let p = bilinear();
    assert_eq!(p.isocurve(Dir::U, 0.5).unwrap(), (vec![1., 2.], vec![1., 1.]));
    assert_eq!(p.isocurve(Dir::V, 0.25).unwrap(), (vec![0.25, 2.25], vec![1., 1.]));
    let mut short = [9.0; 1];
    let e = p.isocurve_into(Dir::U, 0.5, &mut short, None).unwrap_err();
    assert_eq!((e.kind(), short), (ErrorKind::Size, [9.0]));
    assert_eq!(p.isocurve(Dir::U, f64::NAN).unwrap_err().kind(), ErrorKind::Domain);
    let r = Patch::new_rational(1, 0, 1, &[0., 1.], &[1., 3.]).unwrap();
    // v = t of a patch constant in v: the whole u-curve, weights kept.
    assert_eq!(r.isocurve(Dir::V, 0.7).unwrap(), (vec![0., 1.], vec![1., 3.]));
}

#[test]
fn bounds_of_the_net() {
    let net = [
        1., 0., 2., 1., 2., 4., 1., 3., 2., 2., 1., 0., 2., 2., 2., 2., 4., 0., 4., 1., 0., 3., 3., 2., 4.,
        4., 2.,
    ];
    let p = Patch::new(2, 2, 3, &net).unwrap();
    assert_eq!(p.bounds().unwrap(), (vec![1., 0., 0.], vec![4., 4., 4.]));
    let (mut lo, mut hi) = ([7.0; 2], [7.0; 3]);
    assert_eq!(p.bounds_into(&mut lo, &mut hi).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!((lo, hi), ([7.0; 2], [7.0; 3]));
}

#[test]
fn affine_transform_of_the_net() {
    let p = Patch::new(1, 0, 2, &[0., 0., 1., 2.]).unwrap();
    // x' = 2x + 1, y' = y - 1.
    let q = p.transform(&[2., 0., 1., 0., 1., -1.]).unwrap();
    assert_eq!(q.ctrl(), [1., -1., 3., 1.]);
    assert_eq!(p.transform(&[1., 0., 0., 0., 1.]).unwrap_err().kind(), ErrorKind::Size);
    let bad = p.transform(&[f64::NAN, 0., 0., 0., 1., 0.]).unwrap_err();
    assert_eq!(bad.kind(), ErrorKind::NonFinite);
}

#[test]
fn swap_and_reverse_reindex_the_net() {
    // Degree (1, 2): rows i = 0, 1 of three values each.
    let p = Patch::new(1, 2, 1, &[0., 1., 2., 10., 11., 12.]).unwrap();
    let s = p.swap_uv().unwrap();
    assert_eq!((s.degree_u(), s.degree_v()), (2, 1));
    assert_eq!(s.ctrl(), [0., 10., 1., 11., 2., 12.]);
    assert_eq!(p.reverse(Dir::U).unwrap().ctrl(), [10., 11., 12., 0., 1., 2.]);
    assert_eq!(p.reverse(Dir::V).unwrap().ctrl(), [2., 1., 0., 12., 11., 10.]);
}

#[test]
fn ruled_patch_between_a_line_and_a_parabola() {
    let line = [0., 0., 0., 1., 0., 0.];
    let arc = [0., 1., 0., 0.5, 1., 1., 1., 1., 0.];
    let c0 = Curve::new(1, 3, &line).unwrap();
    let c1 = Curve::new(2, 3, &arc).unwrap();
    let p = Patch::ruled(&c0, &c1).unwrap();
    assert_eq!((p.degree_u(), p.degree_v()), (2, 1));
    // The line elevated to degree 2 is (0,0,0), (0.5,0,0), (1,0,0).
    assert_eq!(p.ctrl(), [0., 0., 0., 0., 1., 0., 0.5, 0., 0., 0.5, 1., 1., 1., 0., 0., 1., 1., 0.]);
    let flat = Curve::new(1, 2, &[0., 0., 1., 0.]).unwrap();
    assert_eq!(Patch::ruled(&c0, &flat).unwrap_err().kind(), ErrorKind::Incompatible);
}

#[test]
fn coons_patch_of_one_curved_side() {
    let bump = [0., 1., 0.];
    let zero = [0., 0.];
    let v0 = Curve::new(2, 1, &bump).unwrap();
    let z = Curve::new(1, 1, &zero).unwrap();
    // Boundaries: S(u,0) = bump(u), the other three 0, so S = (1 - v) bump(u).
    let p = Patch::coons(&v0, &z, &z, &z).unwrap();
    assert_eq!((p.degree_u(), p.degree_v()), (2, 1));
    assert_eq!(p.ctrl(), [0., 0., 1., 0., 0., 0.]);
    let off = [1., 0.];
    let bad = Curve::new(1, 1, &off).unwrap();
    assert_eq!(Patch::coons(&v0, &z, &bad, &z).unwrap_err().kind(), ErrorKind::Incompatible);
    let w = [1., 2., 1.];
    let rational = Curve::new_rational(2, 1, &bump, &w).unwrap();
    assert_eq!(Patch::coons(&rational, &z, &z, &z).unwrap_err().kind(), ErrorKind::Unsupported);
}

#[test]
fn curves_check_their_slices() {
    assert_eq!(Curve::new(1, 3, &[0.; 5]).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!(Curve::new(65, 1, &[0.; 66]).unwrap_err().kind(), ErrorKind::Degree);
    assert_eq!(Curve::new(1, 0, &[]).unwrap_err().kind(), ErrorKind::Dimension);
    assert_eq!(Curve::new_rational(1, 1, &[0., 1.], &[1.]).unwrap_err().kind(), ErrorKind::Size);
    let c = Curve::new(2, 1, &[0., 1., 2.]).unwrap();
    assert_eq!((c.degree(), c.dim()), (2, 1));
}
