//! The standard traits: iteration and indexing of surfaces, collecting patches into surfaces,
//! equality of patches and surfaces, shared clones of meshes, conversions to and from the C
//! constants.

use std::borrow::Cow;

use bezsurf::{
    Dir, ErrorKind, MeshFormat, NormalKind, Patch, PatchRef, Side, Strided, StridedMut, Surface, TessFlags,
};

fn line(x0: f64, x1: f64) -> Patch {
    Patch::new(1, 0, 1, &[x0, x1]).unwrap()
}

#[test]
fn surfaces_iterate_by_reference_both_ways() {
    let pot = Surface::builtin("teapot").unwrap();
    let mut n = 0;
    for (i, p) in (&pot).into_iter().enumerate() {
        assert_eq!(p.as_ptr(), pot.get(i).unwrap().as_ptr());
        n += 1;
    }
    assert_eq!(n, pot.len());
    let it = pot.iter();
    assert_eq!(it.len(), pot.len());
    let back: Vec<_> = pot.iter().rev().map(PatchRef::as_ptr).collect();
    let mut fwd: Vec<_> = pot.iter().map(PatchRef::as_ptr).collect();
    fwd.reverse();
    assert_eq!(back, fwd);
    let mut it = pot.iter();
    let first = it.next().unwrap().as_ptr();
    let last = it.next_back().unwrap().as_ptr();
    assert_eq!((first, last), (pot[0].as_ptr(), pot[pot.len() - 1].as_ptr()));
    assert_eq!(it.len(), pot.len() - 2);
    assert_eq!(Surface::default().iter().next(), None);
}

#[test]
#[should_panic(expected = "patch index 1 out of range for a surface of 1")]
fn indexing_past_the_end_panics() {
    let s: Surface = [line(0.0, 1.0)].into_iter().collect();
    let _ = &s[1];
}

#[test]
fn collecting_and_extending_copy_patches() {
    let parts = [line(0.0, 1.0), line(1.0, 3.0)];
    let mut s: Surface = parts.iter().map(|p| &**p).collect();
    assert_eq!((s.len(), s.dim()), (2, 1));
    assert_eq!(s[1], parts[1]);
    s.extend([line(3.0, 4.0)]);
    s.extend(parts.iter());
    assert_eq!(s.len(), 5);
    assert_eq!(s[4].ctrl(), [1.0, 3.0]);
    let mut t = Surface::default();
    assert!(t.is_empty() && t.dim() == 0);
    t.try_extend(&parts).unwrap();
    assert_eq!(t.len(), 2);
    // Fallible forms: a 3-D patch after 1-D ones is Incompatible; the earlier ones stay.
    let plane = Patch::new(1, 1, 3, &[0.0; 12]).unwrap();
    let e = t.try_extend([line(0.0, 2.0), plane.clone()]).unwrap_err();
    assert_eq!((e.kind(), t.len()), (ErrorKind::Incompatible, 3));
    let e = Surface::try_from_patches([&*parts[0], &*plane]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Incompatible);
    // Collecting results stops at the first error.
    let r: Result<Surface, _> = [0.5, 2.0].iter().map(|&t| parts[0].subpatch(0.0, t, 0.0, 1.0)).collect();
    assert_eq!(r.unwrap().len(), 2);
    let r: Result<Surface, _> = [0.5, 2.0].iter().map(|&t| parts[0].split(Dir::U, t).map(|s| s.0)).collect();
    assert_eq!(r.unwrap_err().kind(), ErrorKind::Domain);
}

#[test]
#[should_panic(expected = "Surface::extend")]
fn extending_with_an_incompatible_patch_panics() {
    let mut s: Surface = [line(0.0, 1.0)].into_iter().collect();
    s.extend([Patch::new(0, 0, 2, &[1.0, 2.0]).unwrap()]);
}

#[test]
fn patches_compare_by_shape_and_net() {
    let p = line(0.0, 1.0);
    assert_eq!(p, p.clone());
    assert_eq!(p, line(-0.0, 1.0));
    assert_ne!(p, line(0.0, 2.0));
    assert_ne!(p, p.elevate(1, 0).unwrap());
    assert_ne!(p, Patch::new(0, 1, 1, &[0.0, 1.0]).unwrap());
    let rational = Patch::new_rational(1, 0, 1, &[0.0, 1.0], &[1.0, 1.0]).unwrap();
    assert_ne!(p, rational, "same points, but one is rational");
    let heavier = Patch::new_rational(1, 0, 1, &[0.0, 1.0], &[1.0, 2.0]).unwrap();
    assert_ne!(rational, heavier);
    let s: Surface = [p.clone()].into_iter().collect();
    assert!(s[0] == p);
    assert!(p == s[0]);
    let owned: Patch = s[0].to_owned();
    assert_eq!(owned, p);
    assert_ne!(owned.as_ptr(), s[0].as_ptr());
    let copy = Patch::try_from(&s[0]).unwrap();
    assert_eq!(copy, p);
    let cow: Cow<'_, PatchRef> = Cow::Borrowed(&s[0]);
    assert_eq!(cow.into_owned(), p);
}

#[test]
fn surfaces_compare_patch_by_patch() {
    let pot = Surface::builtin("teapot").unwrap();
    assert_eq!(pot, pot.clone());
    assert_ne!(pot, Surface::builtin("teacup").unwrap());
    let mut longer = pot.clone();
    longer.add(&pot[0]).unwrap();
    assert_ne!(pot, longer);
    let moved: Surface = pot
        .iter()
        .map(|p| p.transform(&[1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 1e-9]).unwrap())
        .collect();
    assert_ne!(pot, moved);
    assert_eq!(Surface::default(), Surface::new().unwrap());
}

#[test]
fn mesh_clones_share_one_immutable_mesh() {
    let cup = Surface::builtin("teacup").unwrap();
    let mesh = cup.tessellate_uniform(3, 2, TessFlags::STRIPS).unwrap();
    let copy = mesh.clone();
    assert_eq!(copy.as_ptr(), mesh.as_ptr());
    drop(mesh);
    // The clone keeps the mesh alive after the original is gone.
    assert_eq!(copy.triangle_count(), cup.len() * 3 * 2 * 2);
    let bytes = copy.to_bytes(MeshFormat::Stl).unwrap();
    assert_eq!(bytes.len(), 84 + 50 * copy.triangle_count());
    let t = std::thread::spawn({
        let m = copy.clone();
        move || m.positions()
    });
    assert_eq!(t.join().unwrap(), copy.positions());
}

#[test]
fn constants_convert_both_ways() {
    for k in [NormalKind::Regular, NormalKind::Limit, NormalKind::Undefined] {
        assert_eq!(NormalKind::try_from(u8::from(k)).unwrap(), k);
    }
    assert_eq!(u8::from(NormalKind::Limit), bezsurf::sys::BS_NORMAL_LIMIT);
    let e = NormalKind::try_from(7u8).unwrap_err();
    assert_eq!((e.kind(), e.argument()), (ErrorKind::InvalidArg, Some("byte")));
    for s in [Side::V0, Side::U1, Side::V1, Side::U0] {
        assert_eq!(Side::try_from(i32::from(s)).unwrap(), s);
    }
    assert_eq!(i32::from(Side::U0), bezsurf::sys::BS_SIDE_U0);
    assert!(Side::try_from(4).is_err());
    assert_eq!(Dir::try_from(i32::from(Dir::V)).unwrap(), Dir::V);
    assert_eq!(i32::from(Dir::U), bezsurf::sys::BS_DIR_U);
    assert_eq!(Dir::try_from(-1).unwrap_err().argument(), Some("raw"));
    assert_eq!(i32::from(MeshFormat::PlyAscii), bezsurf::sys::BS_MESH_PLY_ASCII);
    let mut f = TessFlags::NONE;
    f |= TessFlags::STRIPS;
    assert_eq!(
        i32::from(f | TessFlags::RELATIVE),
        bezsurf::sys::BS_TESS_STRIPS | bezsurf::sys::BS_TESS_RELATIVE
    );
    assert_eq!(TessFlags::default(), TessFlags::NONE);
}

#[test]
fn views_convert_from_owned_buffers_and_index() {
    let mut v = vec![1.0, 2.0, 3.0];
    let mut a = [4.0, 5.0];
    {
        let mut sv = StridedMut::from(&mut v);
        sv[2] = 30.0;
        let sa = StridedMut::from(&mut a);
        let ro = Strided::from(&sa);
        assert_eq!((ro.len(), ro[1]), (2, 5.0));
        assert_eq!(sv.len(), 3);
    }
    assert_eq!(v, [1.0, 2.0, 30.0]);
    let points: bezsurf::PointsMut<'_> = [StridedMut::from(&mut v)].into_iter().collect();
    line(0.0, 2.0).eval(&[0.25], &[0.0], points).unwrap();
    assert_eq!(v, [0.5, 2.0, 30.0]);
}
