//! Surfaces: adding, borrowing and copying patches.

use bezsurf::{ErrorKind, Patch, Surface};

fn flat(z: f64) -> Patch {
    Patch::new(1, 1, 3, &[0., 0., z, 0., 1., z, 1., 0., z, 1., 1., z]).unwrap()
}

#[test]
fn add_get_iterate() {
    let mut s = Surface::new().unwrap();
    assert!(s.is_empty());
    assert_eq!(s.dim(), 0);
    assert!(s.get(0).is_none());
    assert_eq!(s.add(&flat(0.0)).unwrap(), 0);
    assert_eq!(s.add(&flat(1.0)).unwrap(), 1);
    assert_eq!((s.len(), s.dim()), (2, 3));
    assert_eq!(s.get(1).unwrap().ctrl()[2], 1.0);
    assert!(s.get(2).is_none());
    let zs: Vec<f64> = s.iter().map(|p| p.ctrl()[11]).collect();
    assert_eq!(zs, [0.0, 1.0]);
}

#[test]
fn added_patch_is_a_copy() {
    let mut s = Surface::new().unwrap();
    let p = flat(2.0);
    s.add(&p).unwrap();
    assert_ne!(s.get(0).unwrap().as_ptr(), p.as_ptr());
    drop(p);
    assert_eq!(s.get(0).unwrap().ctrl()[2], 2.0);
}

#[test]
fn borrowed_patch_can_be_owned_beyond_the_surface() {
    let mut s = Surface::new().unwrap();
    s.add(&flat(3.0)).unwrap();
    let owned = s.get(0).unwrap().to_patch().unwrap();
    drop(s);
    assert_eq!(owned.ctrl()[2], 3.0);
}

#[test]
fn dimension_mismatch_is_incompatible() {
    let mut s = Surface::new().unwrap();
    s.add(&flat(0.0)).unwrap();
    let p2 = Patch::new(0, 0, 2, &[1.0, 2.0]).unwrap();
    assert_eq!(s.add(&p2).unwrap_err().kind(), ErrorKind::Incompatible);
    assert_eq!(s.len(), 1);
}

#[test]
fn clone_is_independent() {
    let mut s = Surface::new().unwrap();
    s.add(&flat(0.0)).unwrap();
    let mut t = s.clone();
    t.add(&flat(5.0)).unwrap();
    assert_eq!((s.len(), t.len()), (1, 2));
    drop(s);
    assert_eq!(t.get(1).unwrap().ctrl()[2], 5.0);
}
