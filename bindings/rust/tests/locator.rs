//! Closest points, the locator, rays and tessellation options, checked against geometry known in
//! closed form and against the library's own evaluation of the points aimed at.

use bezsurf::{ErrorKind, Locator, Outputs, Patch, Ray, Surface, TessFlags, TessMethod, TessOptions};

/// The square [0,2] x [0,2] in the plane z = 1 as a degree (2,1) patch.
fn flat_square() -> Patch {
    let net = [0., 0., 1., 0., 2., 1., 1., 0., 1., 1., 2., 1., 2., 0., 1., 2., 2., 1.];
    Patch::new(2, 1, 3, &net).unwrap()
}

#[test]
fn closest_points_on_a_plane_inside_and_beyond_the_boundary() {
    let p = flat_square();
    let c = p.closest_points(&[0.5, 1.5, 4.0, 3.0, -1.0, 1.0]).unwrap();
    assert!(c.patch.is_empty());
    assert!((c.uv[0][0] - 0.25).abs() < 1e-9 && (c.uv[0][1] - 0.75).abs() < 1e-9);
    assert!((c.dist[0] - 3.0).abs() < 1e-8);
    assert!((c.dist[1] - 2f64.sqrt()).abs() < 1e-8);
    let corner = &c.pos[3..6];
    assert!((corner[0] - 2.0).abs() < 1e-9 && corner[1].abs() < 1e-9 && (corner[2] - 1.0).abs() < 1e-12);
    let e = p.closest_points(&[1.0, 2.0]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Size);
    let nan = p.closest_points(&[f64::NAN, 0.0, 0.0]).unwrap();
    assert!(nan.dist[0].is_nan() && nan.uv[0][0].is_nan());
    assert!(p.closest_points(&[]).unwrap().dist.is_empty());
}

#[test]
fn rays_aimed_at_teapot_points_hit_them_or_something_earlier() {
    let pot = Surface::builtin("teapot").unwrap();
    let loc = Locator::new(&pot).unwrap();
    let targets = [(0usize, 0.3, 0.4), (5, 0.5, 0.5), (12, 0.7, 0.2), (20, 0.1, 0.9)];
    for &(id, u, v) in &targets {
        let mut pos = [0.0; 3];
        let mut nrm = [0.0; 3];
        let patch = pot.get(id).unwrap();
        patch.eval_normal(&[u], &[v], Outputs::new().pos(&mut pos).normal(&mut nrm)).unwrap();
        let origin = [pos[0] + 5.0 * nrm[0], pos[1] + 5.0 * nrm[1], pos[2] + 5.0 * nrm[2]];
        let hit = loc.intersect(&[Ray::new(origin, [-nrm[0], -nrm[1], -nrm[2]])]).unwrap()[0];
        let hit_patch = hit.patch.expect("a ray aimed at the surface must hit it");
        assert!(hit.t <= 5.0 + 1e-7, "patch {id}: hit at t = {} beyond the target", hit.t);
        // The hit is a point of the surface on the ray: the target or one before it.
        let mut at = [0.0; 3];
        pot.get(hit_patch as usize).unwrap().eval(&[hit.uv[0]], &[hit.uv[1]], &mut at).unwrap();
        for c in 0..3 {
            assert!((at[c] - (origin[c] - hit.t * nrm[c])).abs() < 1e-7, "patch {id}: hit off the ray");
        }
        let len = (hit.normal.iter().map(|x| x * x).sum::<f64>()).sqrt();
        assert!((len - 1.0).abs() < 1e-12);
    }
}

#[test]
fn misses_ranges_and_invalid_rays() {
    let pot = Surface::builtin("teapot").unwrap();
    let loc = Locator::new(&pot).unwrap();
    assert_eq!(loc.dim(), 3);
    let mut short = Ray::new([0., 0., 100.], [0., 0., -1.]);
    short.t_max = 1.0;
    let hits = loc
        .intersect(&[Ray::new([0., 0., 100.], [0., 0., 1.]), short, Ray::new([0., 0., 100.], [0., 0., 0.])])
        .unwrap();
    assert_eq!(hits[0].patch, None);
    assert_eq!(hits[0].t, f64::INFINITY);
    assert!(hits[0].uv[0].is_nan() && hits[0].normal[0].is_nan());
    assert_eq!(hits[1].patch, None);
    assert_eq!(hits[2].patch, None);
    assert!(hits[2].t.is_nan());
    assert!(loc.intersect(&[]).unwrap().is_empty());
    // t_max = +inf is "no limit" (1.2), also set by hand after a finite range
    let free = loc.intersect(&[Ray::new([0., 0., 100.], [0., 0., -1.])]).unwrap()[0];
    assert!(free.patch.is_some() && free.t.is_finite());
    let mut unlimited = short;
    unlimited.t_max = f64::INFINITY;
    assert_eq!(loc.intersect(&[unlimited]).unwrap()[0], free);
    unlimited.t_min = f64::NEG_INFINITY;
    assert!(loc.intersect(&[unlimited]).unwrap()[0].t.is_nan());
}

#[test]
fn batches_on_threads_give_the_answers_of_one_thread() {
    let pot = Surface::builtin("teapot").unwrap();
    let loc = Locator::new(&pot).unwrap();
    // 150 points and 1,100 rays: several pieces per thread
    let q: Vec<f64> =
        (0..150).flat_map(|k| [0.1 * k as f64 - 4.0, 0.05 * k as f64 - 2.0, 0.03 * k as f64]).collect();
    let one = loc.closest_points(&q).unwrap();
    // a 34 x 33 grid of rays along -x over the teapot's side
    let at = |k: usize| [8.0, (k % 34) as f64 / 8.5 - 2.0, (k / 34) as f64 / 10.0];
    let rays: Vec<Ray> = (0..1100).map(|k| Ray::new(at(k), [-1.0, 0.0, 0.0])).collect();
    let one_hits = loc.intersect(&rays).unwrap();
    assert!(one_hits.iter().filter(|h| h.patch.is_some()).count() > 100);
    let bits = |h: &[bezsurf::Hit]| -> Vec<u64> {
        h.iter().flat_map(|h| [h.t.to_bits(), h.uv[0].to_bits()]).collect()
    };
    for threads in [2, 0] {
        assert_eq!(loc.closest_points_threads(&q, threads).unwrap(), one);
        let hits = loc.intersect_threads(&rays, threads).unwrap();
        assert_eq!(bits(&hits), bits(&one_hits));
    }
}

#[test]
fn locator_closest_agrees_with_the_best_patch_and_threads_agree() {
    let pot = Surface::builtin("teapot").unwrap();
    let loc = Locator::new(&pot).unwrap();
    let q = [4.0, 1.0, 2.0, 0.0, 0.0, 5.0];
    let all = loc.closest_points(&q).unwrap();
    for k in 0..2 {
        let best = (0..pot.len())
            .map(|i| pot.get(i).unwrap().closest_points(&q[3 * k..3 * k + 3]).unwrap().dist[0])
            .fold(f64::INFINITY, f64::min);
        assert!((all.dist[k] - best).abs() <= 1e-8 * (10.0 + best));
        assert!((all.patch[k] as usize) < pot.len());
    }
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..3).map(|_| s.spawn(|| loc.closest_points(&q).unwrap())).collect();
        for h in handles {
            assert_eq!(h.join().unwrap(), all);
        }
    });
}

#[test]
fn tessellation_options_counts_and_budgets() {
    let pot = Surface::builtin("teapot").unwrap();
    let uniform = TessOptions::new(TessMethod::Uniform { nu: 8, nv: 6 });
    let (nv, nt) = pot.tessellate_count(&uniform).unwrap();
    let m = pot.tessellate(&uniform).unwrap();
    assert_eq!((m.vertex_count(), m.triangle_count()), (nv, nt));
    assert_eq!(m.positions(), pot.tessellate_uniform(8, 6, TessFlags::NONE).unwrap().positions());
    assert_eq!(pot.tessellate(&uniform.max_triangles(nt - 1)).unwrap_err().kind(), ErrorKind::Size);
    for method in [TessMethod::PerPatch, TessMethod::Subdivide] {
        let o = TessOptions::new(method).tolerance(1e-3).flags(TessFlags::RELATIVE);
        let (av, at) = pot.tessellate_count(&o).unwrap();
        let a = pot.tessellate(&o).unwrap();
        assert_eq!((a.vertex_count(), a.triangle_count()), (av, at));
        assert_eq!(pot.tessellate(&o.max_vertices(av - 1)).unwrap_err().kind(), ErrorKind::Size);
    }
}
