//! Tessellation, mesh read-back and export, checked on a unit square whose mesh is known exactly
//! and on the teapot for properties the library documents.

use bezsurf::{ErrorKind, MeshFormat, Patch, StridedMut, Surface, TessFlags};

/// The unit square in z = 0 with S(u, v) = (u, v, 0) and normal +z.
fn unit_square() -> Surface {
    let mut s = Surface::new().unwrap();
    s.add(&Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0.]).unwrap()).unwrap();
    s
}

#[test]
fn uniform_grid_of_the_unit_square() {
    let mesh = unit_square().tessellate_uniform(2, 3, TessFlags::NONE).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (12, 12));
    let pos = mesh.positions();
    let uv = mesh.uv();
    let nrm = mesh.normals();
    let mut grid_points: Vec<(f64, f64)> = Vec::new();
    for k in 0..12 {
        let p = &pos[3 * k..3 * k + 3];
        // S(u, v) = (u, v, 0), so each vertex's parameters are its x and y.
        assert_eq!((p[0], p[1], p[2]), (uv[2 * k], uv[2 * k + 1], 0.0));
        assert_eq!(nrm[3 * k..3 * k + 3], [0., 0., 1.]);
        grid_points.push((p[0] * 2.0, p[1] * 3.0));
    }
    // The vertices are exactly the 3 x 4 grid points (u = a/2, v = b/3).
    for a in 0..3 {
        for b in 0..4 {
            let hits = grid_points
                .iter()
                .filter(|&&(x, y)| (x - a as f64).abs() < 1e-12 && (y - b as f64).abs() < 1e-12)
                .count();
            assert_eq!(hits, 1, "grid point ({a}, {b})");
        }
    }
    let tri = mesh.triangles();
    let mut area = 0.0;
    for t in tri.chunks(3) {
        assert!(t.iter().all(|&i| (i as usize) < 12));
        let (a, b, c) = (t[0] as usize, t[1] as usize, t[2] as usize);
        // Signed area in the xy-plane: positive means counter-clockwise seen from +z.
        let cross = (pos[3 * b] - pos[3 * a]) * (pos[3 * c + 1] - pos[3 * a + 1])
            - (pos[3 * b + 1] - pos[3 * a + 1]) * (pos[3 * c] - pos[3 * a]);
        assert!(cross > 0.0);
        area += cross / 2.0;
    }
    assert!((area - 1.0).abs() < 1e-12);
    assert_eq!(mesh.patch_ids(), vec![0; 12]);
    assert_eq!(mesh.triangle_patch_ids(), vec![0; 12]);
    let corner = mesh.corner_uv();
    for (k, &i) in tri.iter().enumerate() {
        assert_eq!(corner[2 * k..2 * k + 2], uv[2 * i as usize..2 * i as usize + 2]);
    }
    assert_eq!(mesh.strip_count(), 0);
}

#[test]
fn strided_read_back() {
    let mesh = unit_square().tessellate_uniform(1, 1, TessFlags::NONE).unwrap();
    let (mut x, mut y, mut z) = ([0.0; 4], [0.0; 4], [9.0; 4]);
    mesh.copy_positions([StridedMut::from(&mut x[..]), (&mut y[..]).into(), (&mut z[..]).into()]).unwrap();
    let mut xs: Vec<(f64, f64)> = x.iter().zip(y.iter()).map(|(&a, &b)| (a, b)).collect();
    xs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(xs, [(0., 0.), (0., 1.), (1., 0.), (1., 1.)]);
    assert_eq!(z, [0.0; 4]);
    let mut short = [7.0; 11];
    assert_eq!(mesh.copy_positions(&mut short).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!(short, [7.0; 11]);
    let mut ids = [7u32; 3];
    assert_eq!(mesh.copy_patch_ids(&mut ids).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!(mesh.copy_triangles(&mut ids).unwrap_err().kind(), ErrorKind::Size);
    assert_eq!(ids, [7; 3]);
}

#[test]
fn adaptive_flat_patch_needs_one_cell() {
    // A plane has no second derivatives: one segment per direction meets any tolerance.
    let mesh = unit_square().tessellate_adaptive(1e-6, TessFlags::NONE).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (4, 2));
    let s = unit_square();
    assert_eq!(s.tessellate_adaptive(0.0, TessFlags::NONE).unwrap_err().kind(), ErrorKind::Domain);
    assert_eq!(s.tessellate_adaptive(f64::NAN, TessFlags::RELATIVE).unwrap_err().kind(), ErrorKind::Domain);
}

#[test]
fn teapot_strips_hold_exactly_the_triangles() {
    let teapot = Surface::builtin("teapot").unwrap();
    let mesh = teapot.tessellate_uniform(4, 4, TessFlags::STRIPS).unwrap();
    // Shared sides and poles merge vertices: fewer than 32 separate 5 x 5 grids.
    assert!(mesh.vertex_count() < 32 * 25);
    assert!(mesh.strip_count() > 0);
    let (idx, start) = mesh.strips();
    assert_eq!(start.len(), mesh.strip_count() + 1);
    assert_eq!(*start.last().unwrap() as usize, idx.len());
    let mut from_strips = Vec::new();
    for k in 0..mesh.strip_count() {
        let s = &idx[start[k] as usize..start[k + 1] as usize];
        for i in 0..s.len().saturating_sub(2) {
            let t = if i % 2 == 0 { [s[i], s[i + 1], s[i + 2]] } else { [s[i + 1], s[i], s[i + 2]] };
            if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
                from_strips.push(t);
            }
        }
    }
    let mut from_list: Vec<[u32; 3]> = mesh.triangles().chunks(3).map(|t| [t[0], t[1], t[2]]).collect();
    // Compare as sets of triangles, each kept in its winding (rotated to start at its least index).
    let norm = |t: &[u32; 3]| {
        let m = (0..3).min_by_key(|&i| t[i]).unwrap();
        [t[m], t[(m + 1) % 3], t[(m + 2) % 3]]
    };
    let mut a: Vec<_> = from_strips.iter().map(norm).collect();
    from_list = from_list.iter().map(norm).collect();
    a.sort();
    from_list.sort();
    assert_eq!(a, from_list);
}

#[test]
fn export_formats() {
    let mesh = unit_square().tessellate_uniform(2, 2, TessFlags::NONE).unwrap();
    let (nv, nt) = (mesh.vertex_count(), mesh.triangle_count());
    let obj = String::from_utf8(mesh.to_bytes(MeshFormat::Obj).unwrap()).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), nv);
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), nt);
    // Binary STL: 80-byte header, triangle count, 50 bytes per triangle.
    let stl = mesh.to_bytes(MeshFormat::Stl).unwrap();
    assert_eq!(stl.len(), 84 + 50 * nt);
    assert_eq!(u32::from_le_bytes([stl[80], stl[81], stl[82], stl[83]]) as usize, nt);
    let ply = mesh.to_bytes(MeshFormat::Ply).unwrap();
    assert!(ply.starts_with(b"ply\nformat binary_little_endian 1.0\n"));
    let ascii = String::from_utf8(mesh.to_bytes(MeshFormat::PlyAscii).unwrap()).unwrap();
    assert!(ascii.contains(&format!("element vertex {nv}")));
    assert!(ascii.contains(&format!("element face {nt}")));
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("square.stl");
    mesh.write(MeshFormat::Stl, &path).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), stl);
    let _ = std::fs::remove_file(&path);
    let bad = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("no-such-dir/x.obj");
    assert_eq!(mesh.write(MeshFormat::Obj, &bad).unwrap_err().kind(), ErrorKind::Io);
    // save: the format from the extension, any case, as `bezsurf tessellate`; others refused
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    for (name, format) in [("s.ply", MeshFormat::Ply), ("s.OBJ", MeshFormat::Obj), ("s.Stl", MeshFormat::Stl)]
    {
        mesh.save(dir.join(name)).unwrap();
        assert_eq!(std::fs::read(dir.join(name)).unwrap(), mesh.to_bytes(format).unwrap(), "{name}");
        let _ = std::fs::remove_file(dir.join(name));
    }
    for name in ["s.txt", "noext"] {
        let err = mesh.save(dir.join(name)).unwrap_err();
        assert_eq!((err.kind(), err.argument()), (ErrorKind::InvalidArg, Some("path")));
        assert!(err.to_string().contains("unknown mesh extension"), "{err}");
        assert!(!dir.join(name).exists());
    }
}

#[test]
fn tessellation_errors() {
    let s = unit_square();
    assert_eq!(s.tessellate_uniform(0, 1, TessFlags::NONE).unwrap_err().kind(), ErrorKind::Domain);
    assert_eq!(s.tessellate_uniform(1, 1025, TessFlags::NONE).unwrap_err().kind(), ErrorKind::Domain);
    let mut flat = Surface::new().unwrap();
    flat.add(&Patch::new(0, 0, 2, &[1., 2.]).unwrap()).unwrap();
    assert_eq!(flat.tessellate_uniform(1, 1, TessFlags::NONE).unwrap_err().kind(), ErrorKind::Dimension);
    let empty = Surface::new().unwrap().tessellate_uniform(3, 3, TessFlags::NONE).unwrap();
    assert_eq!((empty.vertex_count(), empty.triangle_count()), (0, 0));
}

#[test]
fn meshes_are_send_and_sync() {
    fn check<T: Send + Sync>() {}
    check::<bezsurf::Mesh>();
}

#[test]
fn float_read_back_is_the_doubles_rounded() {
    let cup = bezsurf::Surface::builtin("teacup").unwrap();
    let m = cup.tessellate_uniform(3, 3, bezsurf::TessFlags::NONE).unwrap();
    let round = |v: Vec<f64>| v.into_iter().map(|x| x as f32).collect::<Vec<f32>>();
    assert_eq!(m.positions_f32(), round(m.positions()));
    assert_eq!(m.normals_f32(), round(m.normals()));
    assert_eq!(m.uv_f32(), round(m.uv()));
}

#[test]
fn reverse_faces_the_teapot_outwards() {
    let teapot = Surface::builtin("teapot").unwrap();
    let volume = |m: &bezsurf::Mesh| {
        let p = m.positions();
        let v = |i: u32, c: usize| p[3 * i as usize + c];
        m.triangles()
            .chunks(3)
            .map(|t| {
                let (a, b, c) = (t[0], t[1], t[2]);
                v(a, 0) * (v(b, 1) * v(c, 2) - v(b, 2) * v(c, 1))
                    - v(a, 1) * (v(b, 0) * v(c, 2) - v(b, 2) * v(c, 0))
                    + v(a, 2) * (v(b, 0) * v(c, 1) - v(b, 1) * v(c, 0))
            })
            .sum::<f64>()
            / 6.0
    };
    let plain = teapot.tessellate_uniform(4, 4, TessFlags::NONE).unwrap();
    let rev = teapot.tessellate_uniform(4, 4, TessFlags::REVERSE).unwrap();
    // The patches face into the pot: the plain mesh encloses a negative volume.
    assert!(volume(&plain) < -24.0 && volume(&rev) > 24.0);
    assert_eq!(plain.positions(), rev.positions());
    let swapped: Vec<u32> = plain.triangles().chunks(3).flat_map(|t| [t[0], t[2], t[1]]).collect();
    assert_eq!(rev.triangles(), swapped);
    let negated: Vec<f64> = plain.normals().iter().map(|x| -x).collect();
    assert_eq!(rev.normals(), negated);
}
