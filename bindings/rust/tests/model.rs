//! Models through the Rust binding: the model of a surface, face evaluation against the
//! surface's own evaluation, the CAD parts of data/cad/ with the face counts of their .ref files.

use std::path::PathBuf;

use bezsurf::{
    ErrorKind, FaceKind, Model, NormalKind, Outputs, Ray, Surface, TessFlags, TessMethod, TessOptions, Trim,
};

fn cad_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data/cad")
}

fn ref_faces(part: &str) -> usize {
    let text = std::fs::read_to_string(cad_dir().join(format!("{part}.ref"))).unwrap();
    let line = text.lines().find(|l| l.starts_with("faces ")).unwrap();
    line[6..].trim().parse().unwrap()
}

fn ref_measures(part: &str) -> (f64, f64) {
    let text = std::fs::read_to_string(cad_dir().join(format!("{part}.ref"))).unwrap();
    let value = |key: &str| -> f64 {
        let line = text.lines().find(|l| l.starts_with(key)).unwrap();
        line[key.len()..].trim().parse().unwrap()
    };
    (value("area "), value("volume "))
}

#[test]
fn teapot_model_evaluates_as_its_patches() {
    let pot = Surface::builtin("teapot").unwrap();
    let m = Model::from_surface(&pot).unwrap();
    assert_eq!(m.face_count(), 32);
    assert!(m.shell_count() >= 4);
    assert_eq!(m.shell_closed(m.shell_count()), None);
    let f = m.face(3).unwrap();
    assert_eq!((f.kind, f.first_patch, f.patch_count, f.loop_count), (FaceKind::Bezier, 3, 1, 1));
    assert_eq!(m.face(32).unwrap_err().kind(), ErrorKind::Domain);

    let (ids, u, v) = ([0u32, 9, 20], [0.25, 0.5, 1.0], [0.75, 0.0, 0.5]);
    let ev = m.face_eval(&ids, &u, &v).unwrap();
    let mut pos = [0.0; 9];
    let mut nrm = [0.0; 9];
    let mut kind = [0u8; 3];
    pot.eval_normal(&ids, &u[..], &v[..], Outputs::new().pos(&mut pos).normal(&mut nrm).kind(&mut kind))
        .unwrap();
    for k in 0..3 {
        assert_eq!(ev.pos[k], [pos[3 * k], pos[3 * k + 1], pos[3 * k + 2]]);
        assert_eq!(ev.normal[k], [nrm[3 * k], nrm[3 * k + 1], nrm[3 * k + 2]]);
        assert_eq!(ev.kind[k], NormalKind::from_byte(kind[k]).unwrap());
    }
    let (patch, st) = m.face_to_patch(&ids, &u, &v).unwrap();
    assert_eq!(patch, vec![Some(0), Some(9), Some(20)]);
    assert_eq!(st[1], [0.5, 0.0]);
    let (outside, _) = m.face_to_patch(&[0], &[1.5], &[0.5]).unwrap();
    assert_eq!(outside, vec![None]);
    // back from the patches: each patch its own face on (0,1)^2
    let (face, uv) = m.patch_to_face(&ids, &u, &v).unwrap();
    assert_eq!(face, vec![Some(0), Some(9), Some(20)]);
    assert_eq!(uv[1], [0.5, 0.0]);
    let (outside, uv) = m.patch_to_face(&[0], &[1.5], &[0.5]).unwrap();
    assert!(outside == vec![None] && uv[0][0].is_nan());
    assert_eq!(m.patch_to_face(&[32], &[0.5], &[0.5]).unwrap_err().kind(), ErrorKind::InvalidArg);
    assert_eq!(m.patch_to_face(&[0, 1], &[0.5], &[0.5]).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!(m.classify(&[0], &[0.5], &[0.5], 1e-9).unwrap(), vec![Trim::Inside]);
    assert_eq!(m.classify(&[0], &[0.5], &[0.5], -1.0).unwrap_err().kind(), ErrorKind::Domain);
    assert_eq!(m.face_eval(&[0, 1], &[0.5], &[0.5]).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!(m.face_eval(&[32], &[0.5], &[0.5]).unwrap_err().kind(), ErrorKind::InvalidArg);
    assert_eq!(m.surface().unwrap().len(), 32);
    let p = m.properties(1e-6).unwrap();
    assert!(p.area > 0.0 && p.volume.is_nan());
    assert_eq!(m.properties(0.5).unwrap_err().kind(), ErrorKind::Domain);
}

#[test]
fn cad_parts_read_with_their_face_counts() {
    for part in ["bottle", "block", "sphere", "torus", "cone", "wedge", "bell", "duct"] {
        for file in [format!("{part}.step"), format!("{part}.igs"), format!("{part}-brep.igs")] {
            let m = Model::read_file(cad_dir().join(&file)).unwrap_or_else(|e| panic!("{file}: {e}"));
            assert_eq!(m.face_count(), ref_faces(part), "{file}");
            let (area, volume) = ref_measures(part);
            let p = m.properties(1e-10).unwrap();
            // 1e-9 but where the file holds fewer digits (144 files) or the kernel's value is off
            // (the duct's area, the bell's volume: docs/models.md)
            let coarse = file.ends_with(".igs") && !file.contains("brep");
            let rel_area = if coarse || part == "duct" { 1e-7 } else { 1e-9 };
            let rel_volume = if coarse || part == "bell" || part == "duct" { 1e-7 } else { 1e-9 };
            assert!((p.area - area).abs() <= rel_area * area, "{file}: area {} against {area}", p.area);
            let closed = (0..m.shell_count()).all(|s| m.shell_closed(s) == Some(true));
            if closed {
                assert!(
                    (p.volume - volume).abs() <= rel_volume * volume,
                    "{file}: volume {} against {volume}",
                    p.volume
                );
            }
        }
    }
}

#[test]
fn unknown_extension_and_missing_file() {
    let e = Model::read_file("part.xyz").unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidArg);
    let e = Model::read_file("/nonexistent-directory/part.step").unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Io);
}

#[test]
fn model_locator_hits_as_the_kernel() {
    // the first rays of the block's .ref (OpenCASCADE's IntCurvesFace_ShapeIntersector)
    let text = std::fs::read_to_string(cad_dir().join("block.ref")).unwrap();
    let part = Model::read_file(cad_dir().join("block.step")).unwrap();
    let loc = part.locator().unwrap();
    let mut rays = Vec::new();
    let mut want = Vec::new();
    for line in text.lines().filter(|l| l.starts_with("ray ")).take(80) {
        let w: Vec<&str> = line.split_whitespace().collect();
        let num = |k: usize| w[k].parse::<f64>().unwrap();
        rays.push(Ray::new([num(1), num(2), num(3)], [num(4), num(5), num(6)]));
        want.push(if w[7] == "hit" { Some(num(8)) } else { None });
    }
    let hits = loc.intersect(&rays).unwrap();
    for (h, t) in hits.iter().zip(&want) {
        match t {
            None => assert_eq!(h.patch, None),
            Some(t) => {
                assert!((h.patch.unwrap() as usize) < part.face_count());
                assert!((h.t - t).abs() <= 1e-6 * 50.0, "t {} against the kernel's {}", h.t, t);
            }
        }
    }
    // closest points: never farther than the kernel's (BRepExtrema_DistShapeShape) beyond its
    // tolerance, reported as face ids
    let mut points = Vec::new();
    let mut dists = Vec::new();
    for line in text.lines().filter(|l| l.starts_with("closest ")).take(40) {
        let w: Vec<&str> = line.split_whitespace().collect();
        let num = |k: usize| w[k].parse::<f64>().unwrap();
        points.extend_from_slice(&[num(1), num(2), num(3)]);
        dists.push(num(5));
    }
    let near = loc.closest_points(&points).unwrap();
    for (k, d) in dists.iter().enumerate() {
        assert!(near.dist[k] <= d + 1e-7 * 50.0, "{} against the kernel's {}", near.dist[k], d);
        assert!((near.patch[k] as usize) < part.face_count());
    }
}

#[test]
fn cone_meshes_closed_and_outward() {
    let m = Model::read_step_file(cad_dir().join("cone.step")).unwrap();
    let opts = TessOptions::new(TessMethod::Subdivide).tolerance(1e-3).flags(TessFlags::RELATIVE);
    let mesh = m.tessellate(&opts).unwrap();
    let tri = mesh.triangles();
    let mut edges = std::collections::HashMap::new();
    for t in tri.chunks(3) {
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    // closed: every directed edge once and its reverse once
    assert!(edges.iter().all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1)));
    assert!(mesh.triangle_patch_ids().iter().all(|&f| (f as usize) < m.face_count()));
    assert_eq!(m.tessellate_count(&opts).unwrap(), (mesh.vertex_count(), mesh.triangle_count()));
    let uniform = TessOptions::new(TessMethod::Uniform { nu: 4, nv: 4 });
    assert_eq!(m.tessellate(&uniform).unwrap_err().kind(), ErrorKind::Unsupported);
    let bad = TessOptions::new(TessMethod::Subdivide).tolerance(-1.0);
    assert_eq!(m.tessellate(&bad).unwrap_err().kind(), ErrorKind::Domain);
}
