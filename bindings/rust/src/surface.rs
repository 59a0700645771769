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
unsafe impl Sync for Surface {}

impl Surface {
    /// An empty surface; its dimension is fixed by the first patch added.
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
        (!p.is_null()).then(|| unsafe { PatchRef::from_ptr(p) })
    }

    /// The patches in order.
    pub fn iter(&self) -> impl Iterator<Item = &PatchRef> + '_ {
        (0..self.len()).filter_map(move |i| self.get(i))
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
