//! Surfaces: ordered sets of patches of one dimension (a quilt such as the Utah teapot).

use std::ptr::{self, NonNull};

use crate::error::{check, Result};
use crate::patch::PatchRef;
use crate::sys;

/// An owned surface (`bs_surface *`), released with `bs_surface_destroy` on drop, which also
/// releases its patches. Patches borrowed from it ([`Surface::get`], [`Surface::iter`]) are
/// `&PatchRef` tied to the borrow of the surface, so they cannot outlive it, and
/// [`Surface::add`] (which takes `&mut self`) cannot run while one is held.
///
/// ```
/// let teapot = bezsurf::Surface::builtin("teapot")?;
/// let rim = teapot.get(0).unwrap(); // &PatchRef borrowed from `teapot`
/// assert_eq!((rim.degree_u(), rim.degree_v()), (3, 3));
/// let owned = rim.to_patch()?; // an independent copy may outlive the surface
/// drop(teapot);
/// assert_eq!(owned.dim(), 3);
/// # Ok::<(), bezsurf::Error>(())
/// ```
///
/// A borrowed patch cannot outlive its surface:
///
/// ```compile_fail,E0597
/// let rim;
/// {
///     let teapot = bezsurf::Surface::builtin("teapot").unwrap();
///     rim = teapot.get(0).unwrap();
/// } // `teapot` dropped here while still borrowed
/// rim.degree_u();
/// ```
///
/// nor be held while the surface grows:
///
/// ```compile_fail,E0502
/// let mut teapot = bezsurf::Surface::builtin("teapot").unwrap();
/// let rim = teapot.get(0).unwrap();
/// teapot.add(rim).unwrap(); // needs `&mut teapot` while `rim` borrows it
/// ```
pub struct Surface {
    ptr: NonNull<sys::bs_surface>,
}

// SAFETY: the only C function that changes a surface, bs_surface_add, is behind `&mut self`, so
// Rust's borrow rules already forbid it while another thread reads; reading functions take
// `const bs_surface *` and the library documents them as safe from any number of threads; the
// library has no mutable global state.
unsafe impl Send for Surface {}
// SAFETY: through `&Surface` only the reading functions are reachable, which the library allows
// from any number of threads at once; `add` needs `&mut Surface`.
unsafe impl Sync for Surface {}

impl Surface {
    /// An empty surface; its dimension is fixed by the first patch added.
    ///
    /// ```
    /// use bezsurf::{ErrorKind, Patch, Surface};
    ///
    /// let mut s = Surface::new()?;
    /// let square = Patch::new(1, 1, 2, &[0., 0., 0., 1., 1., 0., 1., 1.])?;
    /// assert_eq!(s.add(&square)?, 0);
    /// assert_eq!(s.dim(), 2);
    /// let other = Patch::new(0, 0, 3, &[0., 0., 0.])?;
    /// assert_eq!(s.add(&other).unwrap_err().kind(), ErrorKind::Incompatible);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn new() -> Result<Surface> {
        let mut out = ptr::null_mut();
        // SAFETY: out is valid.
        check(unsafe { sys::bs_surface_create(&mut out) })?;
        // SAFETY: on success out is a new surface that we now own.
        Ok(unsafe { Surface::from_raw(out) })
    }

    /// Takes ownership of a raw surface pointer (it will be destroyed on drop).
    ///
    /// # Safety
    /// `ptr` must be a live surface from this library that nothing else owns or destroys.
    ///
    /// # Panics
    /// If `ptr` is NULL.
    pub unsafe fn from_raw(ptr: *mut sys::bs_surface) -> Surface {
        Surface { ptr: NonNull::new(ptr).expect("bezsurf returned a NULL surface on success") }
    }

    /// Gives up ownership: the caller must release the pointer with `bs_surface_destroy`.
    pub fn into_raw(self) -> *mut sys::bs_surface {
        let ptr = self.ptr.as_ptr();
        std::mem::forget(self);
        ptr
    }

    /// The C handle, valid while `self` is borrowed.
    pub fn as_ptr(&self) -> *const sys::bs_surface {
        self.ptr.as_ptr()
    }

    /// The raw handle for a call that changes the surface; `&mut self` keeps it exclusive.
    pub(crate) fn as_mut_ptr(&mut self) -> *mut sys::bs_surface {
        self.ptr.as_ptr()
    }

    /// An independent copy (`bs_surface_clone`).
    pub fn try_clone(&self) -> Result<Surface> {
        let mut out = ptr::null_mut();
        // SAFETY: self is live; out is valid.
        check(unsafe { sys::bs_surface_clone(self.as_ptr(), &mut out) })?;
        // SAFETY: on success out is a new surface that we now own.
        Ok(unsafe { Surface::from_raw(out) })
    }

    /// Appends a copy of `patch` and returns its index (`bs_surface_add`). `Incompatible` if its
    /// dimension differs from the surface's.
    pub fn add(&mut self, patch: &PatchRef) -> Result<usize> {
        let mut index = 0usize;
        // SAFETY: self is live and exclusively borrowed; patch is live; index is valid.
        check(unsafe { sys::bs_surface_add(self.ptr.as_ptr(), patch.as_ptr(), &mut index) })?;
        Ok(index)
    }

    /// Number of patches.
    pub fn len(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_surface_count(self.as_ptr()) }
    }

    /// True if the surface holds no patch.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Dimension of the patches; 0 while empty.
    pub fn dim(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_surface_dim(self.as_ptr()) }
    }

    /// Borrows patch `i`, or `None` if `i >= len()`.
    pub fn get(&self, i: usize) -> Option<&PatchRef> {
        // SAFETY: self is live; the returned pointer stays valid until the surface is destroyed,
        // and the borrow of self keeps it alive and unchanged.
        let p = unsafe { sys::bs_surface_get(self.as_ptr(), i) };
        // SAFETY: p is NULL (checked) or a live patch owned by the surface, which the returned
        // borrow of self keeps alive and unchanged.
        (!p.is_null()).then(|| unsafe { PatchRef::from_ptr(p) })
    }

    /// The patches in order; `for patch in &surface` does the same.
    ///
    /// ```
    /// let cup = bezsurf::Surface::builtin("teacup")?;
    /// let bicubic = cup.iter().filter(|p| p.degree_u() == 3 && p.degree_v() == 3).count();
    /// assert_eq!(bicubic, cup.len());
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn iter(&self) -> Iter<'_> {
        Iter { surface: self, front: 0, back: self.len() }
    }

    /// Appends a copy of every patch, stopping at the first error (patches appended before it
    /// stay). The fallible form of [`Extend`].
    pub fn try_extend<P: AsRef<PatchRef>>(&mut self, patches: impl IntoIterator<Item = P>) -> Result<()> {
        for p in patches {
            self.add(p.as_ref())?;
        }
        Ok(())
    }

    /// A new surface holding copies of the patches; the fallible form of [`FromIterator`].
    ///
    /// ```
    /// use bezsurf::{Dir, Surface};
    ///
    /// let pot = Surface::builtin("teapot")?;
    /// let (lo, hi) = pot[0].split(Dir::U, 0.5)?;
    /// let halves = Surface::try_from_patches([lo, hi])?;
    /// assert_eq!(halves.len(), 2);
    /// let (a, b) = (halves[1].eval_point(0.0, 0.25)?, pot[0].eval_point(0.5, 0.25)?);
    /// assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12));
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn try_from_patches<P: AsRef<PatchRef>>(patches: impl IntoIterator<Item = P>) -> Result<Surface> {
        let mut s = Surface::new()?;
        s.try_extend(patches)?;
        Ok(s)
    }
}

/// Iterator over the patches of a [`Surface`] in order ([`Surface::iter`]).
#[derive(Debug, Clone)]
pub struct Iter<'a> {
    surface: &'a Surface,
    front: usize,
    back: usize,
}

impl<'a> Iterator for Iter<'a> {
    type Item = &'a PatchRef;
    fn next(&mut self) -> Option<&'a PatchRef> {
        if self.front == self.back {
            return None;
        }
        self.front += 1;
        self.surface.get(self.front - 1)
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.back - self.front, Some(self.back - self.front))
    }
}

impl<'a> DoubleEndedIterator for Iter<'a> {
    fn next_back(&mut self) -> Option<&'a PatchRef> {
        if self.front == self.back {
            return None;
        }
        self.back -= 1;
        self.surface.get(self.back)
    }
}

impl ExactSizeIterator for Iter<'_> {}
impl std::iter::FusedIterator for Iter<'_> {}

impl<'a> IntoIterator for &'a Surface {
    type Item = &'a PatchRef;
    type IntoIter = Iter<'a>;
    fn into_iter(self) -> Iter<'a> {
        self.iter()
    }
}

impl std::ops::Index<usize> for Surface {
    type Output = PatchRef;
    /// Patch `i`, borrowed (see [`Surface::get`] for the non-panicking form).
    ///
    /// # Panics
    /// If `i >= len()`.
    fn index(&self, i: usize) -> &PatchRef {
        self.get(i).unwrap_or_else(|| panic!("patch index {i} out of range for a surface of {}", self.len()))
    }
}

impl Default for Surface {
    /// An empty surface, as [`Surface::new`].
    ///
    /// # Panics
    /// If the library runs out of memory.
    fn default() -> Surface {
        Surface::new().unwrap_or_else(|e| panic!("bs_surface_create failed: {e}"))
    }
}

impl<P: AsRef<PatchRef>> Extend<P> for Surface {
    /// Appends a copy of every patch, as [`Surface::add`].
    ///
    /// # Panics
    /// If a patch's dimension differs from the surface's, or the library runs out of memory;
    /// [`Surface::try_extend`] returns the error instead.
    fn extend<I: IntoIterator<Item = P>>(&mut self, patches: I) {
        if let Err(e) = self.try_extend(patches) {
            panic!("Surface::extend: {e}");
        }
    }
}

impl<P: AsRef<PatchRef>> FromIterator<P> for Surface {
    /// A surface of copies of the patches (owned [`Patch`](crate::Patch)es or `&PatchRef`s).
    ///
    /// ```
    /// use bezsurf::{Dir, Surface};
    ///
    /// let pot = Surface::builtin("teapot")?;
    /// let reversed: Surface = pot.iter().map(|p| p.reverse(Dir::V)).collect::<Result<_, _>>()?;
    /// assert_eq!(reversed.len(), pot.len());
    /// let copy: Surface = pot.iter().collect();
    /// assert_eq!(copy, pot);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    ///
    /// # Panics
    /// As [`Extend`]; [`Surface::try_from_patches`] returns the error instead.
    fn from_iter<I: IntoIterator<Item = P>>(patches: I) -> Surface {
        let mut s = Surface::default();
        s.extend(patches);
        s
    }
}

impl PartialEq for Surface {
    /// Equal if both hold equal patches in the same order (see `PartialEq for PatchRef`).
    fn eq(&self, other: &Surface) -> bool {
        self.len() == other.len() && self.iter().eq(other.iter())
    }
}

impl Drop for Surface {
    fn drop(&mut self) {
        // SAFETY: we own the surface; no borrow of it or its patches outlives self.
        unsafe { sys::bs_surface_destroy(self.ptr.as_ptr()) }
    }
}

impl Clone for Surface {
    fn clone(&self) -> Surface {
        self.try_clone().unwrap_or_else(|e| panic!("bs_surface_clone failed: {e}"))
    }
}

impl std::fmt::Debug for Surface {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Surface").field("len", &self.len()).field("dim", &self.dim()).finish()
    }
}
