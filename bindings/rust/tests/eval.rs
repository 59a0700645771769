//! Evaluation against values known independently: MATH.md's worked points and a patch whose
//! surface is known in closed form, S(u, v) = (u, v, u^2 v).

use bezsurf::{ErrorKind, NormalKind, Outputs, Patch, PointsMut, Strided, StridedMut};

/// MATH.md's first net; S(1/2, 1/2) = (17/8, 9/4, 13/8).
const NET1: [f64; 27] = [
    1., 0., 2., 1., 2., 4., 1., 3., 2., //
    2., 1., 0., 2., 2., 2., 2., 4., 0., //
    4., 1., 0., 3., 3., 2., 4., 4., 2.,
];
/// MATH.md's second net; S(1/4, 1/4) = (1, 1, 173/64).
const NET2: [f64; 27] = [
    0., 0., 4., 0., 2., 4., 0., 4., 0., //
    2., 0., 0., 2., 2., 4., 2., 4., 0., //
    4., 0., 0., 4., 2., 0., 4., 4., 8.,
];

/// S(u, v) = (u, v, u^2 v): x and y are linear (net i/2, j/2), z has the Bernstein ordinates
/// of u^2 ([0, 0, 1]) times those of v ([0, 1/2, 1]).
fn graph() -> Patch {
    let mut net = Vec::new();
    for i in 0..3 {
        for j in 0..3 {
            let z = [0., 0., 1.][i] * [0., 0.5, 1.][j];
            net.extend([i as f64 / 2.0, j as f64 / 2.0, z]);
        }
    }
    Patch::new(2, 2, 3, &net).unwrap()
}

fn s(u: f64, v: f64) -> [f64; 3] {
    [u, v, u * u * v]
}
fn s_u(u: f64, v: f64) -> [f64; 3] {
    [1., 0., 2. * u * v]
}
fn s_v(u: f64, _v: f64) -> [f64; 3] {
    [0., 1., u * u]
}
fn unit_normal(u: f64, v: f64) -> [f64; 3] {
    // S_u x S_v = (-2uv, -u^2, 1).
    let n = [-2. * u * v, -u * u, 1.];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    [n[0] / len, n[1] / len, n[2] / len]
}

fn close(a: &[f64], b: &[f64]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= 1e-14 * (1.0 + y.abs()), "{a:?} vs {b:?}");
    }
}

const US: [f64; 5] = [0.0, 0.25, 0.5, 0.75, 1.0];
const VS: [f64; 5] = [0.5, 1.0, 0.125, 0.0, 0.625];

#[test]
fn math_md_worked_points() {
    let p = Patch::new(2, 2, 3, &NET1).unwrap();
    assert_eq!(p.eval_point(0.5, 0.5).unwrap(), [17. / 8., 9. / 4., 13. / 8.]);
    let q = Patch::new(2, 2, 3, &NET2).unwrap();
    close(&q.eval_point(0.25, 0.25).unwrap(), &[1., 1., 173. / 64.]);
}

#[test]
fn positions_and_first_partials() {
    let p = graph();
    let (mut pos, mut du, mut dv) = (vec![0.0; 15], vec![0.0; 15], vec![0.0; 15]);
    p.eval_with(&US, &VS, Outputs::new().pos(&mut pos).du(&mut du).dv(&mut dv)).unwrap();
    for k in 0..5 {
        let r = 3 * k..3 * k + 3;
        close(&pos[r.clone()], &s(US[k], VS[k]));
        close(&du[r.clone()], &s_u(US[k], VS[k]));
        close(&dv[r], &s_v(US[k], VS[k]));
    }
}

#[test]
fn higher_derivatives() {
    let p = graph();
    let u = [0.5, 0.25];
    let v = [0.25, 1.0];
    let mut out = [0.0; 6];
    p.eval_deriv(1, 1, &u, &v, &mut out).unwrap(); // S_uv = (0, 0, 2u)
    close(&out, &[0., 0., 1., 0., 0., 0.5]);
    p.eval_deriv(2, 0, &u, &v, &mut out).unwrap(); // S_uu = (0, 0, 2v)
    close(&out, &[0., 0., 0.5, 0., 0., 2.]);
    p.eval_deriv(2, 1, &u, &v, &mut out).unwrap(); // S_uuv = (0, 0, 2)
    close(&out, &[0., 0., 2., 0., 0., 2.]);
    p.eval_deriv(3, 0, &u, &v, &mut out).unwrap(); // beyond the degree
    assert_eq!(out, [0.0; 6]);
    p.eval_deriv(0, 0, &u, &v, &mut out).unwrap(); // positions
    close(&out, &[0.5, 0.25, 0.0625, 0.25, 1., 0.0625]);
    let e = p.eval_deriv(65, 0, &u, &v, &mut out).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Degree);
}

#[test]
fn regular_normals() {
    let p = graph();
    let (mut pos, mut nrm, mut kind) = (vec![0.0; 15], vec![0.0; 15], vec![9u8; 5]);
    p.eval_normal(&US, &VS, Outputs::new().pos(&mut pos).normal(&mut nrm).kind(&mut kind)).unwrap();
    for k in 0..5 {
        close(&pos[3 * k..3 * k + 3], &s(US[k], VS[k]));
        close(&nrm[3 * k..3 * k + 3], &unit_normal(US[k], VS[k]));
        assert_eq!(NormalKind::from_byte(kind[k]), Some(NormalKind::Regular));
    }
}

#[test]
fn limit_and_undefined_normals() {
    // S = (u(1-v), uv, 0): the edge u = 0 is collapsed; S_u x S_v = (0, 0, u).
    let fan = Patch::new(1, 1, 3, &[0., 0., 0., 0., 0., 0., 1., 0., 0., 0., 1., 0.]).unwrap();
    let (mut nrm, mut kind) = ([0.0; 6], [9u8; 2]);
    fan.eval_normal(&[0.0, 0.5], &[0.5, 0.5], Outputs::new().normal(&mut nrm).kind(&mut kind)).unwrap();
    close(&nrm, &[0., 0., 1., 0., 0., 1.]);
    assert_eq!(kind, [bezsurf::sys::BS_NORMAL_LIMIT, bezsurf::sys::BS_NORMAL_REGULAR]);
    // A net on a line has no normal anywhere.
    let line = Patch::new(1, 1, 3, &[0., 0., 0., 1., 0., 0., 2., 0., 0., 3., 0., 0.]).unwrap();
    let (mut nrm, mut kind) = ([7.0; 3], [9u8; 1]);
    line.eval_normal(&[0.5], &[0.5], Outputs::new().normal(&mut nrm).kind(&mut kind)).unwrap();
    assert_eq!((nrm, NormalKind::from_byte(kind[0])), ([0.0; 3], Some(NormalKind::Undefined)));
    // Normals of a 2-D patch do not exist.
    let flat = Patch::new(0, 0, 2, &[1., 2.]).unwrap();
    let e = flat.eval_normal(&[0.5], &[0.5], Outputs::new().normal(&mut nrm)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Dimension);
}

#[test]
fn grid_layout_is_a_times_nv_plus_b() {
    let p = graph();
    let u = [0.0, 0.5, 1.0];
    let v = [0.25, 0.75];
    let n = u.len() * v.len();
    let (mut pos, mut du, mut dv) = (vec![0.0; 3 * n], vec![0.0; 3 * n], vec![0.0; 3 * n]);
    let (mut nrm, mut kind) = (vec![0.0; 3 * n], vec![9u8; n]);
    let out = Outputs::new().pos(&mut pos).du(&mut du).dv(&mut dv).normal(&mut nrm).kind(&mut kind);
    p.eval_grid(&u, &v, out).unwrap();
    for (a, &ua) in u.iter().enumerate() {
        for (b, &vb) in v.iter().enumerate() {
            let k = a * v.len() + b;
            let r = 3 * k..3 * k + 3;
            close(&pos[r.clone()], &s(ua, vb));
            close(&du[r.clone()], &s_u(ua, vb));
            close(&dv[r.clone()], &s_v(ua, vb));
            close(&nrm[r], &unit_normal(ua, vb));
            assert_eq!(kind[k], bezsurf::sys::BS_NORMAL_REGULAR);
        }
    }
}

#[test]
fn strided_inputs_and_outputs() {
    let p = graph();
    // Parameters interleaved as (u, v) pairs; outputs as three separate coordinate arrays, and
    // the v parameters read backwards through a negative stride.
    let uv = [0.5, 0.25, 1.0, 0.5, 0.25, 1.0];
    let u = Strided::new(&uv, 2);
    let v = Strided::new(&uv[1..], 2);
    let (mut x, mut y, mut z) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    let views = [StridedMut::from(&mut x[..]), StridedMut::from(&mut y[..]), (&mut z[..]).into()];
    p.eval(u, v, views).unwrap();
    for k in 0..3 {
        close(&[x[k], y[k], z[k]], &s(uv[2 * k], uv[2 * k + 1]));
    }
    let mut xyz = [0.0; 9];
    p.eval(u, v.rev(), PointsMut::views(StridedMut::split_interleaved::<3>(&mut xyz))).unwrap();
    for k in 0..3 {
        close(&xyz[3 * k..3 * k + 3], &s(uv[2 * k], uv[2 * (2 - k) + 1]));
    }
    // Only the y coordinates of interleaved xyz, written through StridedMut::new.
    let mut buf = [-1.0; 9];
    let mut only_y = StridedMut::new(&mut buf[1..], 3);
    assert_eq!(only_y.len(), 3);
    let out = [StridedMut::from(&mut x[..]), only_y.reborrow(), (&mut z[..]).into()];
    p.eval(u, v, out).unwrap();
    assert_eq!([buf[1], buf[4], buf[7]], [0.25, 0.5, 1.0]);
    assert_eq!([buf[0], buf[2], buf[3]], [-1.0; 3]);
}

#[test]
fn nan_parameter_spoils_only_its_point() {
    let p = graph();
    let mut pos = [0.0; 6];
    p.eval(&[f64::NAN, 0.5], &[0.5, 0.5], &mut pos).unwrap();
    assert!(pos[..3].iter().all(|x| x.is_nan()));
    close(&pos[3..], &s(0.5, 0.5));
}

#[test]
fn errors_write_nothing() {
    let p = graph();
    let mut pos = [7.0; 5];
    let e = p.eval(&[0.5, 0.5], &[0.5, 0.5], &mut pos).unwrap_err(); // room for one point
    assert_eq!((e.kind(), pos), (ErrorKind::Size, [7.0; 5]));
    let mut pos = [7.0; 6];
    assert_eq!(p.eval(&[0.5, 0.5], &[0.5], &mut pos).unwrap_err().kind(), ErrorKind::Size);
    let mut other = [0.0; 3];
    let two = [StridedMut::from(&mut pos[..3]), StridedMut::from(&mut other[..])];
    assert_eq!(p.eval(&[0.5], &[0.5], two).unwrap_err().kind(), ErrorKind::Dimension);
    let mut kind = [9u8; 1];
    let e = p.eval_normal(&[0.5, 0.5], &[0.5, 0.5], Outputs::new().kind(&mut kind)).unwrap_err();
    assert_eq!((e.kind(), kind), (ErrorKind::Size, [9]));
    let mut nrm = [0.0; 3];
    let e = p.eval_with(&[0.5], &[0.5], Outputs::new().normal(&mut nrm)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidArg);
    let mut du = [0.0; 3];
    let e = p.eval_normal(&[0.5], &[0.5], Outputs::new().du(&mut du)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidArg);
    let mut grid = [7.0; 17];
    let e = p.eval_grid(&[0., 1.], &[0., 0.5, 1.], Outputs::new().pos(&mut grid)).unwrap_err();
    assert_eq!((e.kind(), grid), (ErrorKind::Size, [7.0; 17]));
    // No points: nothing to do, buffers unread.
    p.eval(&[], &[], &mut []).unwrap();
}

#[test]
fn rational_quarter_circle() {
    // (1,0), (1,1), (0,1) with weights 1, sqrt(2)/2, 1: the unit quarter circle, swept along v.
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let ctrl = [1., 0., 1., 0., 1., 1., 1., 1., 0., 1., 0., 1.];
    let p = Patch::new_rational(2, 1, 2, &ctrl, &[1., 1., w, w, 1., 1.]).unwrap();
    for (u, angle) in [(0.0, 0.0), (0.5, std::f64::consts::FRAC_PI_4), (1.0, std::f64::consts::FRAC_PI_2)] {
        close(&p.eval_point(u, 0.3).unwrap(), &[angle.cos(), angle.sin()]);
    }
    // Every point lies on the circle.
    let u: Vec<f64> = (0..=16).map(|k| k as f64 / 16.0).collect();
    let mut pos = vec![0.0; 2 * u.len()];
    p.eval(&u, &vec![0.5; u.len()], &mut pos).unwrap();
    for xy in pos.chunks(2) {
        assert!((xy[0].hypot(xy[1]) - 1.0).abs() < 1e-15);
    }
    // The tangent at u = 0 points along +y with length 2 * w (the quotient rule: 2 w1/w0 (P1 - P0)).
    let mut du = [0.0; 2];
    p.eval_deriv(1, 0, &[0.0], &[0.5], &mut du).unwrap();
    close(&du, &[0.0, 2.0 * w]);
}

#[test]
fn float_grid_is_the_double_grid_rounded() {
    let pot = bezsurf::Surface::builtin("teapot").unwrap();
    let lid = pot.get(20).unwrap(); // a patch with a pole: limit normals
    let (u, v) = ([0.0, 0.25, 0.5, 1.0], [0.0, 0.1, 0.9]);
    let n = u.len() * v.len();
    let (mut pos, mut nrm, mut kind) = (vec![0.0; 3 * n], vec![0.0; 3 * n], vec![0u8; n]);
    lid.eval_grid(&u[..], &v[..], bezsurf::Outputs::new().pos(&mut pos).normal(&mut nrm).kind(&mut kind))
        .unwrap();
    let (mut pf, mut nf, mut kf) = (vec![0f32; 3 * n], vec![0f32; 3 * n], vec![0u8; n]);
    let out = bezsurf::GridF32 {
        pos: Some(&mut pf),
        normal: Some(&mut nf),
        kind: Some(&mut kf),
        ..Default::default()
    };
    lid.eval_grid_f32(&u, &v, out).unwrap();
    let round = |x: &[f64]| x.iter().map(|&a| a as f32).collect::<Vec<f32>>();
    assert_eq!(pf, round(&pos));
    assert_eq!(nf, round(&nrm));
    assert_eq!(kf, kind);
    let mut short = vec![0f32; 3 * n - 1];
    let e = lid
        .eval_grid_f32(&u, &v, bezsurf::GridF32 { pos: Some(&mut short), ..Default::default() })
        .unwrap_err();
    assert_eq!(e.kind(), bezsurf::ErrorKind::Size);
}
