//! One patch (and one surface) read by several threads at once gives exactly the serial results.

use std::sync::Arc;
use std::thread;

use bezsurf::{Outputs, Patch, Surface};

fn bicubic() -> Patch {
    // A wavy 4 x 4 net with distinct values everywhere.
    let mut net = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let (x, y) = (i as f64, j as f64);
            net.extend([x, y, ((x * 1.7 + y * 0.9).sin() * 2.0).round() / 2.0 + 0.25 * x * y]);
        }
    }
    Patch::new(3, 3, 3, &net).unwrap()
}

/// Positions, derivatives, normals and kinds on an n x n grid, as raw bits.
fn grid(p: &bezsurf::PatchRef, n: usize) -> (Vec<u64>, Vec<u8>) {
    let t: Vec<f64> = (0..n).map(|k| k as f64 / (n - 1) as f64).collect();
    let m = n * n * 3;
    let (mut pos, mut du, mut dv, mut nrm) = (vec![0.0; m], vec![0.0; m], vec![0.0; m], vec![0.0; m]);
    let mut kind = vec![0u8; n * n];
    let out = Outputs::new().pos(&mut pos).du(&mut du).dv(&mut dv).normal(&mut nrm).kind(&mut kind);
    p.eval_grid(&t, &t, out).unwrap();
    let bits = [pos, du, dv, nrm].concat().into_iter().map(f64::to_bits).collect();
    (bits, kind)
}

#[test]
fn arc_shared_patch_matches_serial() {
    let patch = Arc::new(bicubic());
    let serial = grid(&patch, 61);
    let handles: Vec<_> = (0..4)
        .map(|_| {
            let p = Arc::clone(&patch);
            thread::spawn(move || (0..5).map(|_| grid(&p, 61)).collect::<Vec<_>>())
        })
        .collect();
    for h in handles {
        for result in h.join().unwrap() {
            assert!(result == serial);
        }
    }
}

#[test]
fn scoped_threads_share_a_surface_and_its_borrowed_patches() {
    let mut surface = Surface::new().unwrap();
    let base = bicubic();
    surface.add(&base).unwrap();
    surface.add(&base.swap_uv().unwrap()).unwrap();
    let serial: Vec<_> = surface.iter().map(|p| grid(p, 33)).collect();
    let surface = &surface;
    thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .map(|k| {
                let patch = surface.get(k % 2).unwrap();
                scope.spawn(move || grid(patch, 33))
            })
            .collect();
        for (k, h) in handles.into_iter().enumerate() {
            assert!(h.join().unwrap() == serial[k % 2]);
        }
    });
    // The two patches really differ, so the comparison above can tell them apart.
    assert!(serial[0] != serial[1]);
}

#[test]
fn patches_and_surfaces_are_send_and_sync() {
    fn check<T: Send + Sync>() {}
    check::<Patch>();
    check::<Surface>();
    check::<&bezsurf::PatchRef>();
    check::<bezsurf::Locator>();
}

/// Positions and normals of a mesh as raw bits, and its triangles.
fn snapshot(m: &bezsurf::Mesh) -> (Vec<u64>, Vec<u32>) {
    let bits: Vec<u64> = [m.positions(), m.normals()].concat().into_iter().map(f64::to_bits).collect();
    (bits, m.triangles())
}

#[test]
fn tessellating_one_surface_from_several_threads_matches_serial() {
    let teapot = Surface::builtin("teapot").unwrap();
    let serial = snapshot(&teapot.tessellate_adaptive(1e-3, bezsurf::TessFlags::RELATIVE).unwrap());
    let teapot = &teapot;
    thread::scope(|scope| {
        let handles: Vec<_> = (0..3)
            .map(|_| scope.spawn(|| teapot.tessellate_adaptive(1e-3, bezsurf::TessFlags::RELATIVE).unwrap()))
            .collect();
        for h in handles {
            assert!(snapshot(&h.join().unwrap()) == serial);
        }
    });
}

#[test]
fn thread_counts_give_the_mesh_and_points_of_one_thread() {
    use bezsurf::{TessMethod, TessOptions};
    let teapot = Surface::builtin("teapot").unwrap();
    for method in [TessMethod::Uniform { nu: 11, nv: 6 }, TessMethod::PerPatch, TessMethod::Subdivide] {
        let opts = TessOptions::new(method).flags(bezsurf::TessFlags::RELATIVE);
        let one = snapshot(&teapot.tessellate(&opts).unwrap());
        for n in [2, 0] {
            assert!(snapshot(&teapot.tessellate(&opts.threads(n)).unwrap()) == one);
        }
    }
    let n = 9000;
    let ids: Vec<u32> = (0..n).map(|k| (k % 32) as u32).collect();
    let u: Vec<f64> = (0..n).map(|k| (k % 97) as f64 / 96.0).collect();
    let v: Vec<f64> = (0..n).map(|k| (k % 89) as f64 / 88.0).collect();
    let (mut a, mut b) = (vec![0.0; 3 * n], vec![0.0; 3 * n]);
    teapot.eval(&ids, &u[..], &v[..], Outputs::new().pos(&mut a)).unwrap();
    teapot.eval_threads(&ids, &u[..], &v[..], Outputs::new().pos(&mut b), 2).unwrap();
    assert!(a.iter().map(|x| x.to_bits()).eq(b.iter().map(|x| x.to_bits())));
}

#[test]
fn thread_counts_give_the_normals_of_one_thread() {
    let teapot = Surface::builtin("teapot").unwrap();
    let n = 3 * 4096 + 29;
    let ids: Vec<u32> = (0..n).map(|k| ((k / 7) % 32) as u32).collect();
    let mut u: Vec<f64> = (0..n).map(|k| (k % 97) as f64 / 96.0).collect();
    let v: Vec<f64> = (0..n).map(|k| (k % 89) as f64 / 88.0).collect();
    u[4100] = f64::NAN;
    let bits = |x: &[f64]| x.iter().map(|y| y.to_bits()).collect::<Vec<u64>>();
    let (mut pos, mut nrm, mut kind) = (vec![0.0; 3 * n], vec![0.0; 3 * n], vec![9u8; n]);
    let out = Outputs::new().pos(&mut pos).normal(&mut nrm).kind(&mut kind);
    teapot.eval_normal(&ids, &u[..], &v[..], out).unwrap();
    assert_eq!(kind[4100], u8::from(bezsurf::NormalKind::Undefined));
    assert!(kind.iter().any(|&k| k == u8::from(bezsurf::NormalKind::Limit)));
    for threads in [1, 2, 3, 7, 0] {
        let (mut p2, mut n2, mut k2) = (vec![0.0; 3 * n], vec![0.0; 3 * n], vec![9u8; n]);
        let out = Outputs::new().pos(&mut p2).normal(&mut n2).kind(&mut k2);
        teapot.eval_normal_threads(&ids, &u[..], &v[..], out, threads).unwrap();
        assert!(bits(&p2) == bits(&pos) && bits(&n2) == bits(&nrm) && k2 == kind, "{threads} threads");
    }
    // The checks of one thread, nothing written: an id out of range, a short output, du asked.
    let mut bad = ids.clone();
    bad[n - 1] = 32;
    let mut n2 = vec![7.0; 3 * n];
    let e = teapot.eval_normal_threads(&bad, &u[..], &v[..], Outputs::new().normal(&mut n2), 3).unwrap_err();
    assert_eq!(e.kind(), bezsurf::ErrorKind::InvalidArg);
    let e =
        teapot.eval_normal_threads(&ids, &u[..], &v[..], Outputs::new().normal(&mut n2[1..]), 3).unwrap_err();
    assert_eq!(e.kind(), bezsurf::ErrorKind::Size);
    let mut du = vec![7.0; 3 * n];
    let e = teapot.eval_normal_threads(&ids, &u[..], &v[..], Outputs::new().du(&mut du), 2).unwrap_err();
    assert_eq!(e.kind(), bezsurf::ErrorKind::InvalidArg);
    assert!(n2.iter().chain(&du).all(|&x| x == 7.0));
}
