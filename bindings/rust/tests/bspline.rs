//! B-spline surfaces through the safe layer: spans, locate, the patches against a direct
//! evaluation of the B-spline, and errors that name the argument.

use bezsurf::{BSpline, ErrorKind, Surface};

/// The B-spline's point at (u, v) by de Boor's algorithm on the span containing it (half-open
/// spans, the last one closed), written independently of the library.
fn de_boor(t: &[f64], p: usize, count: usize, x: f64) -> (usize, Vec<f64>) {
    let mut i = p;
    while i + 1 < count && !(x < t[i + 1] && t[i] < t[i + 1]) {
        i += 1;
    }
    let mut n = vec![0.0; p + 1];
    n[0] = 1.0;
    let (mut left, mut right) = (vec![0.0; p + 1], vec![0.0; p + 1]);
    for j in 1..=p {
        left[j] = x - t[i + 1 - j];
        right[j] = t[i + j] - x;
        let mut saved = 0.0;
        for r in 0..j {
            let tmp = n[r] / (right[r + 1] + left[j - r]);
            n[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        n[j] = saved;
    }
    (i, n)
}

#[test]
fn patches_match_the_bspline() {
    let ku = [0.0, 0.0, 0.0, 0.0, 0.5, 1.5, 1.5, 3.0, 3.0, 3.0, 3.0];
    let kv = [-1.0, -1.0, -1.0, 0.0, 2.0, 2.0, 2.0];
    let (cu, cv, dim) = (7, 4, 3);
    let ctrl: Vec<f64> = (0..cu * cv * dim).map(|k| ((k * 37 % 17) as f64) - 8.0).collect();
    let w: Vec<f64> = (0..cu * cv).map(|k| 0.5 + (k % 4) as f64 * 0.5).collect();
    let b = BSpline::new(3, 2, cu, cv, dim, &ku, &kv, &ctrl).unwrap().with_weights(&w).unwrap();
    assert_eq!(b.span_count().unwrap(), (3, 2));
    let mut s = Surface::new().unwrap();
    let spans = s.add_bspline(&b).unwrap();
    assert_eq!(spans.len(), 6);
    assert_eq!(spans[0], [0.0, 0.5, -1.0, 0.0]);
    assert_eq!(spans[5], [1.5, 3.0, 0.0, 2.0]);
    for k in 0..=20 {
        let (u, v) = (3.0 * k as f64 / 20.0, -1.0 + 3.0 * ((k * 7) % 21) as f64 / 20.0);
        let (index, lu, lv) = b.locate(u, v).unwrap();
        let mut pos = [0.0; 3];
        s[index].eval(&[lu], &[lv], &mut pos).unwrap();
        let (iu, nu) = de_boor(&ku, 3, cu, u);
        let (iv, nv) = de_boor(&kv, 2, cv, v);
        let (mut num, mut den) = ([0.0f64; 3], 0.0);
        for (a, nua) in nu.iter().enumerate() {
            for (c, nvc) in nv.iter().enumerate() {
                let idx = (iu - 3 + a) * cv + (iv - 2 + c);
                let f = nua * nvc * w[idx];
                for d in 0..3 {
                    num[d] += f * ctrl[idx * dim + d];
                }
                den += f;
            }
        }
        for d in 0..3 {
            assert!((pos[d] - num[d] / den).abs() < 1e-12, "u {u} v {v}: {} vs {}", pos[d], num[d] / den);
        }
    }
}

#[test]
fn errors_name_the_argument() {
    let ku = [0.0, 0.0, 1.0, 1.0];
    let kv = [0.0, 0.0, 1.0, 1.0];
    let ctrl = [0.0; 12];
    let e = BSpline::new(1, 1, 2, 2, 3, &ku[..3], &kv, &ctrl).unwrap_err();
    assert_eq!((e.kind(), e.argument()), (ErrorKind::Size, Some("knots_u")));
    let e = BSpline::new(1, 1, 2, 2, 3, &ku, &kv[..2], &ctrl).unwrap_err();
    assert_eq!(e.argument(), Some("knots_v"));
    let e = BSpline::new(1, 1, 2, 2, 3, &ku, &kv, &ctrl[..11]).unwrap_err();
    assert_eq!(e.argument(), Some("ctrl"));
    assert!(e.to_string().contains("ctrl"), "{e}");
    let b = BSpline::new(1, 1, 2, 2, 3, &ku, &kv, &ctrl).unwrap();
    let e = b.with_weights(&[1.0; 3]).unwrap_err();
    assert_eq!(e.argument(), Some("weights"));
    let e = BSpline::new(1, 1, usize::MAX, 2, 3, &ku, &kv, &ctrl).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Size);
    // values are the library's to check: a decreasing knot vector, a zero weight
    let bad = [0.0, 0.0, 1.0, 0.5];
    let b = BSpline::new(1, 1, 2, 2, 3, &bad, &kv, &ctrl).unwrap();
    assert_eq!(b.span_count().unwrap_err().kind(), ErrorKind::Domain);
    let b =
        BSpline::new(1, 1, 2, 2, 3, &ku, &kv, &ctrl).unwrap().with_weights(&[1.0, 0.0, 1.0, 1.0]).unwrap();
    let mut s = Surface::new().unwrap();
    assert_eq!(s.add_bspline(&b).unwrap_err().kind(), ErrorKind::NonFinite);
    assert_eq!(s.len(), 0);
    let b = BSpline::new(1, 1, 2, 2, 3, &ku, &kv, &ctrl).unwrap();
    assert_eq!(b.locate(1.5, 0.5).unwrap_err().kind(), ErrorKind::Domain);
    assert_eq!(b.locate(f64::NAN, 0.5).unwrap_err().kind(), ErrorKind::Domain);
}
