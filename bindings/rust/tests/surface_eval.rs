//! Scattered evaluation across a surface and its continuity report, against closed forms.

use bezsurf::{ErrorKind, Outputs, Patch, Side, Surface};

/// S(u, v) = (u, v, u^2 v) (see tests/eval.rs).
fn graph() -> Patch {
    let mut net = Vec::new();
    for i in 0..3 {
        for j in 0..3 {
            net.extend([i as f64 / 2.0, j as f64 / 2.0, [0., 0., 1.][i] * [0., 0.5, 1.][j]]);
        }
    }
    Patch::new(2, 2, 3, &net).unwrap()
}

/// The plane z = 0 over [x0, x0 + 1] x [0, 1]: S(u, v) = (x0 + u, v, 0).
fn square(x0: f64) -> Patch {
    Patch::new(1, 1, 3, &[x0, 0., 0., x0, 1., 0., x0 + 1., 0., 0., x0 + 1., 1., 0.]).unwrap()
}

#[test]
fn points_go_to_their_patches() {
    let mut s = Surface::new().unwrap();
    s.add(&graph()).unwrap();
    s.add(&square(5.0)).unwrap();
    let ids = [1, 0, 1, 0];
    let u = [0.5, 0.5, 0.25, 1.0];
    let v = [0.5, 0.5, 1.0, 0.25];
    let (mut pos, mut du, mut dv) = ([0.0; 12], [0.0; 12], [0.0; 12]);
    s.eval(&ids, &u, &v, Outputs::new().pos(&mut pos).du(&mut du).dv(&mut dv)).unwrap();
    assert_eq!(pos, [5.5, 0.5, 0., 0.5, 0.5, 0.125, 5.25, 1., 0., 1., 0.25, 0.25]);
    assert_eq!(du, [1., 0., 0., 1., 0., 0.5, 1., 0., 0., 1., 0., 0.5]);
    assert_eq!(dv, [0., 1., 0., 0., 1., 0.25, 0., 1., 0., 0., 1., 1.]);
    let (mut nrm, mut kind) = ([0.0; 12], [9u8; 4]);
    s.eval_normal(&ids, &u, &v, Outputs::new().normal(&mut nrm).kind(&mut kind)).unwrap();
    assert_eq!(nrm[..3], [0., 0., 1.]);
    // Graph normal at (1/2, 1/2): (-2uv, -u^2, 1) / |.| = (-0.5, -0.25, 1) / sqrt(1.3125).
    let len = 1.3125f64.sqrt();
    for (x, y) in nrm[3..6].iter().zip([-0.5 / len, -0.25 / len, 1. / len]) {
        assert!((x - y).abs() < 1e-15);
    }
    assert_eq!(kind, [0; 4]);
}

#[test]
fn surface_eval_errors() {
    let mut s = Surface::new().unwrap();
    s.add(&square(0.0)).unwrap();
    let mut pos = [7.0; 6];
    let e = s.eval(&[0, 1], &[0.5, 0.5], &[0.5, 0.5], Outputs::new().pos(&mut pos)).unwrap_err();
    assert_eq!((e.kind(), pos), (ErrorKind::InvalidArg, [7.0; 6]));
    let e = s.eval(&[0], &[0.5, 0.5], &[0.5, 0.5], Outputs::new().pos(&mut pos)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Size);
    let mut flat = Surface::new().unwrap();
    flat.add(&Patch::new(0, 0, 2, &[1., 2.]).unwrap()).unwrap();
    let e = flat.eval_normal(&[0], &[0.5], &[0.5], Outputs::new().normal(&mut pos)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Dimension);
    let mut two = [0.0; 2];
    flat.eval(&[0], &[0.5], &[0.5], Outputs::new().pos(&mut two)).unwrap();
    assert_eq!(two, [1., 2.]);
    // No points: nothing to do, even on an empty surface.
    Surface::new().unwrap().eval(&[], &[], &[], Outputs::new().pos(&mut two)).unwrap();
}

#[test]
fn continuity_of_two_squares_side_by_side() {
    let mut s = Surface::new().unwrap();
    s.add(&square(0.0)).unwrap();
    s.add(&square(1.0)).unwrap();
    let report = s.continuity(1e-12, 8).unwrap();
    assert_eq!(report.edges.len(), 1);
    let e = report.edges[0];
    assert_eq!((e.patch_a, e.side_a, e.patch_b, e.side_b), (0, Side::U1, 1, Side::U0));
    assert!(!e.reversed && !e.flipped && e.c1);
    assert_eq!((e.c0_gap, e.g1_angle, e.c1_defect), (0.0, 0.0, 0.0));
    assert_eq!(e.samples, 8);
    let open: Vec<(u32, Side)> = report.open.iter().map(|o| (o.patch, o.side)).collect();
    assert_eq!(
        open,
        [(0, Side::V0), (0, Side::V1), (0, Side::U0), (1, Side::V0), (1, Side::U1), (1, Side::V1)]
    );
    assert_eq!(s.continuity(-1.0, 8).unwrap_err().kind(), ErrorKind::Domain);
    assert_eq!(s.continuity(0.0, 0).unwrap_err().kind(), ErrorKind::Domain);
}

#[test]
fn teapot_edges_meet() {
    let teapot = Surface::builtin("teapot").unwrap();
    let report = teapot.continuity(1e-9, 16).unwrap();
    assert!(!report.edges.is_empty());
    // Shared sides are found by matching control points, so they coincide.
    assert!(report.edges.iter().all(|e| e.c0_gap <= 1e-9 && e.patch_a <= e.patch_b));
    assert!(report.open.iter().all(|o| (o.patch as usize) < teapot.len()));
}
