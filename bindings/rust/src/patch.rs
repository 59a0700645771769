//! Patches: the owned [`Patch`] and the borrowed [`PatchRef`] that carries every read method.

use std::marker::PhantomData;
use std::ops::Deref;
use std::ptr::{self, NonNull};

use crate::error::{check, values, Error, Result};
use crate::sys;

/// A patch borrowed from its owner: a [`Patch`] (through `Deref`) or a
/// [`Surface`](crate::Surface). Only ever seen as `&PatchRef`, whose lifetime keeps the owner
/// alive. All reading and evaluating methods live here.
pub struct PatchRef {
    _opaque: [u8; 0],
    // Not Send/Sync automatically; see the explicit impls below.
    _not_auto: PhantomData<*mut u8>,
}

// SAFETY: a patch never changes after creation (the C API only ever takes `const bs_patch *`
// after bs_patch_create) and the library has no mutable global state and no lazy caches, so any
// number of threads may read the same patch at once, and a patch may be read from any thread.
unsafe impl Send for PatchRef {}
// SAFETY: as for Send: every method takes `&self` and only reads the immutable patch.
unsafe impl Sync for PatchRef {}

/// An owned Bezier patch (`bs_patch *`), released with `bs_patch_destroy` on drop.
///
/// Derefs to [`PatchRef`], which has the reading and evaluating methods.
pub struct Patch {
    ptr: NonNull<sys::bs_patch>,
}

// SAFETY: as for PatchRef: nothing takes `&mut self` on a Patch except Drop, which owns it, and
// the library lets any thread use or destroy a patch.
unsafe impl Send for Patch {}
// SAFETY: a shared `&Patch` only reaches `&PatchRef`, which is Sync (see above).
unsafe impl Sync for Patch {}

/// Number of control points of a (deg_u, deg_v) net, when the degrees are in range.
fn net_points(deg_u: usize, deg_v: usize) -> usize {
    (deg_u + 1) * (deg_v + 1)
}

/// `Degree` naming `name` if `degree` is above `BS_MAX_DEGREE`.
pub(crate) fn check_degree(name: &'static str, degree: usize) -> Result<()> {
    if degree > sys::BS_MAX_DEGREE {
        return Err(Error::argument_error(
            sys::BS_ERR_DEGREE,
            name,
            format!("is {degree}, at most {} is possible", sys::BS_MAX_DEGREE),
        ));
    }
    Ok(())
}

/// `Dimension` naming `dim` if it is 0 or above `BS_MAX_DIM`.
pub(crate) fn check_dim(dim: usize) -> Result<()> {
    if dim == 0 || dim > sys::BS_MAX_DIM {
        return Err(Error::argument_error(
            sys::BS_ERR_DIMENSION,
            "dim",
            format!("is {dim}, 1 to {} are possible", sys::BS_MAX_DIM),
        ));
    }
    Ok(())
}

/// Checks the shape as `bs_patch_create` does, so the slice lengths can be checked after it.
fn check_shape(deg_u: usize, deg_v: usize, dim: usize) -> Result<()> {
    check_degree("deg_u", deg_u)?;
    check_degree("deg_v", deg_v)?;
    check_dim(dim)
}

impl Patch {
    /// A polynomial patch of degree (`deg_u`, `deg_v`) from its packed control net:
    /// point (i, j) coordinate c at `ctrl[(i * (deg_v + 1) + j) * dim + c]`, i along u.
    ///
    /// Errors: `Degree` (a degree above [`MAX_DEGREE`](crate::MAX_DEGREE)), `Dimension` (dim 0 or
    /// above [`MAX_DIM`](crate::MAX_DIM)), `Size` (`ctrl.len()` is not
    /// (deg_u+1)(deg_v+1)·dim), `NonFinite` (NaN or infinity in the net).
    pub fn new(deg_u: usize, deg_v: usize, dim: usize, ctrl: &[f64]) -> Result<Patch> {
        Patch::create(deg_u, deg_v, dim, ctrl, None)
    }

    /// A rational patch: as [`Patch::new`] plus (deg_u+1)(deg_v+1) weights in the same order,
    /// finite and positive (else `NonFinite`; a wrong length is `Size`). Control points are
    /// Cartesian, not multiplied by their weights.
    pub fn new_rational(
        deg_u: usize,
        deg_v: usize,
        dim: usize,
        ctrl: &[f64],
        weights: &[f64],
    ) -> Result<Patch> {
        Patch::create(deg_u, deg_v, dim, ctrl, Some(weights))
    }

    fn create(
        deg_u: usize,
        deg_v: usize,
        dim: usize,
        ctrl: &[f64],
        weights: Option<&[f64]>,
    ) -> Result<Patch> {
        check_shape(deg_u, deg_v, dim)?;
        // The C function reads exactly these many values; shorter slices must never reach it.
        let npts = net_points(deg_u, deg_v);
        if ctrl.len() != npts * dim {
            return Err(Error::argument_error(
                sys::BS_ERR_SIZE,
                "ctrl",
                format!(
                    "has {}; a degree ({deg_u}, {deg_v}) net of dimension {dim} needs exactly {}",
                    values(ctrl.len()),
                    npts * dim
                ),
            ));
        }
        if let Some(w) = weights.filter(|w| w.len() != npts) {
            return Err(Error::argument_error(
                sys::BS_ERR_SIZE,
                "weights",
                format!("has {}; a degree ({deg_u}, {deg_v}) net needs exactly {npts}", values(w.len())),
            ));
        }
        let wptr = weights.map_or(ptr::null(), <[f64]>::as_ptr);
        let mut out = ptr::null_mut();
        // SAFETY: ctrl and weights hold the number of values the shape needs; out is valid.
        check(unsafe { sys::bs_patch_create(deg_u, deg_v, dim, ctrl.as_ptr(), wptr, &mut out) })?;
        // SAFETY: on success out is a new patch that we now own.
        Ok(unsafe { Patch::from_raw(out) })
    }

    /// Takes ownership of a raw patch pointer (it will be destroyed on drop).
    ///
    /// # Safety
    /// `ptr` must be a live patch from this library that nothing else owns or destroys.
    ///
    /// # Panics
    /// If `ptr` is NULL.
    pub unsafe fn from_raw(ptr: *mut sys::bs_patch) -> Patch {
        Patch { ptr: NonNull::new(ptr).expect("bezsurf returned a NULL patch on success") }
    }

    /// Gives up ownership: the caller must release the pointer with `bs_patch_destroy`.
    pub fn into_raw(self) -> *mut sys::bs_patch {
        let ptr = self.ptr.as_ptr();
        std::mem::forget(self);
        ptr
    }

    /// An independent copy (`bs_patch_clone`); `Clone` does the same but panics when out of
    /// memory.
    pub fn try_clone(&self) -> Result<Patch> {
        self.deref().to_patch()
    }
}

impl Drop for Patch {
    fn drop(&mut self) {
        // SAFETY: we own the patch; no borrow of it outlives self.
        unsafe { sys::bs_patch_destroy(self.ptr.as_ptr()) }
    }
}

impl Clone for Patch {
    fn clone(&self) -> Patch {
        self.try_clone().unwrap_or_else(|e| panic!("bs_patch_clone failed: {e}"))
    }
}

impl Deref for Patch {
    type Target = PatchRef;
    fn deref(&self) -> &PatchRef {
        // SAFETY: the pointer is a live patch for as long as self is borrowed.
        unsafe { PatchRef::from_ptr(self.ptr.as_ptr()) }
    }
}

impl AsRef<PatchRef> for Patch {
    fn as_ref(&self) -> &PatchRef {
        self
    }
}

impl AsRef<PatchRef> for PatchRef {
    fn as_ref(&self) -> &PatchRef {
        self
    }
}

impl std::borrow::Borrow<PatchRef> for Patch {
    fn borrow(&self) -> &PatchRef {
        self
    }
}

impl ToOwned for PatchRef {
    type Owned = Patch;
    /// An owned copy, as [`PatchRef::to_patch`].
    ///
    /// # Panics
    /// If the library runs out of memory.
    fn to_owned(&self) -> Patch {
        self.to_patch().unwrap_or_else(|e| panic!("bs_patch_clone failed: {e}"))
    }
}

impl PartialEq for PatchRef {
    /// Equal if the patches have the same degrees, dimension and rationality and equal control
    /// points and weights (compared as numbers, so 0.0 equals -0.0).
    ///
    /// ```
    /// use bezsurf::{Dir, Patch};
    ///
    /// let p = Patch::new(1, 1, 1, &[0.0, 1.0, 2.0, 3.0])?;
    /// assert_eq!(p.reverse(Dir::U)?.reverse(Dir::U)?, p);
    /// assert_ne!(p.reverse(Dir::U)?, p);
    /// assert_ne!(p.elevate(1, 0)?, p); // the same surface, but another net
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    fn eq(&self, other: &PatchRef) -> bool {
        std::ptr::eq(self, other)
            || (self.degree_u() == other.degree_u()
                && self.degree_v() == other.degree_v()
                && self.dim() == other.dim()
                && self.is_rational() == other.is_rational()
                && self.ctrl() == other.ctrl()
                && self.weights() == other.weights())
    }
}

impl PartialEq for Patch {
    fn eq(&self, other: &Patch) -> bool {
        **self == **other
    }
}

impl PartialEq<PatchRef> for Patch {
    fn eq(&self, other: &PatchRef) -> bool {
        **self == *other
    }
}

impl PartialEq<Patch> for PatchRef {
    fn eq(&self, other: &Patch) -> bool {
        *self == **other
    }
}

impl TryFrom<&PatchRef> for Patch {
    type Error = Error;
    /// An owned copy, as [`PatchRef::to_patch`].
    fn try_from(p: &PatchRef) -> Result<Patch> {
        p.to_patch()
    }
}

impl std::fmt::Debug for PatchRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Patch")
            .field("degree_u", &self.degree_u())
            .field("degree_v", &self.degree_v())
            .field("dim", &self.dim())
            .field("rational", &self.is_rational())
            .finish()
    }
}

impl std::fmt::Debug for Patch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.deref().fmt(f)
    }
}

impl PatchRef {
    /// Borrows a patch pointer for a caller-chosen lifetime.
    ///
    /// # Safety
    /// `ptr` must be a live, non-NULL patch for all of `'a`.
    pub unsafe fn from_ptr<'a>(ptr: *const sys::bs_patch) -> &'a PatchRef {
        debug_assert!(!ptr.is_null());
        // SAFETY: the caller guarantees a live patch for 'a; PatchRef is a zero-sized stand-in
        // for the opaque struct, so the reference only carries the address.
        unsafe { &*(ptr as *const PatchRef) }
    }

    /// The C handle, valid while `self` is borrowed.
    pub fn as_ptr(&self) -> *const sys::bs_patch {
        self as *const PatchRef as *const sys::bs_patch
    }

    /// An independent owned copy (`bs_patch_clone`).
    pub fn to_patch(&self) -> Result<Patch> {
        let mut out = ptr::null_mut();
        // SAFETY: self is a live patch; out is valid.
        check(unsafe { sys::bs_patch_clone(self.as_ptr(), &mut out) })?;
        // SAFETY: on success out is a new patch that we now own.
        Ok(unsafe { Patch::from_raw(out) })
    }

    /// Degree along u.
    pub fn degree_u(&self) -> usize {
        // SAFETY: self is a live patch.
        unsafe { sys::bs_patch_degree_u(self.as_ptr()) }
    }

    /// Degree along v.
    pub fn degree_v(&self) -> usize {
        // SAFETY: self is a live patch.
        unsafe { sys::bs_patch_degree_v(self.as_ptr()) }
    }

    /// Dimension of a control point.
    pub fn dim(&self) -> usize {
        // SAFETY: self is a live patch.
        unsafe { sys::bs_patch_dim(self.as_ptr()) }
    }

    /// True if the patch has weights.
    pub fn is_rational(&self) -> bool {
        // SAFETY: self is a live patch.
        unsafe { sys::bs_patch_is_rational(self.as_ptr()) != 0 }
    }

    /// Number of control points, (deg_u+1)(deg_v+1).
    pub fn num_ctrl(&self) -> usize {
        net_points(self.degree_u(), self.degree_v())
    }

    /// Copies the packed control net and/or the weights (all 1.0 for a polynomial patch) into
    /// the given slices (`bs_patch_get_ctrl`). `Size` if a slice is too short; nothing is
    /// written then.
    pub fn get_ctrl(&self, ctrl: Option<&mut [f64]>, weights: Option<&mut [f64]>) -> Result<()> {
        let (cp, cc) = ctrl.map_or((ptr::null_mut(), 0), |c| (c.as_mut_ptr(), c.len()));
        let (wp, wc) = weights.map_or((ptr::null_mut(), 0), |w| (w.as_mut_ptr(), w.len()));
        // SAFETY: each pointer is NULL or a slice of the capacity passed with it.
        check(unsafe { sys::bs_patch_get_ctrl(self.as_ptr(), cp, cc, wp, wc) }).map_err(|e| {
            let (np, dim) = (self.num_ctrl(), self.dim());
            let short = |name, len: usize, want: usize| {
                e.clone().with_argument(name, format!("has {}, at least {want} are needed", values(len)))
            };
            if e.kind() != crate::ErrorKind::Size {
                e
            } else if !cp.is_null() && cc < np * dim {
                short("ctrl", cc, np * dim)
            } else if !wp.is_null() && wc < np {
                short("weights", wc, np)
            } else {
                e
            }
        })
    }

    /// The packed control net as a new vector.
    pub fn ctrl(&self) -> Vec<f64> {
        let mut ctrl = vec![0.0; self.num_ctrl() * self.dim()];
        // Cannot fail: the patch is live and the vector has exactly the needed size.
        self.get_ctrl(Some(&mut ctrl), None).expect("bs_patch_get_ctrl");
        ctrl
    }

    /// The weights as a new vector (all 1.0 for a polynomial patch).
    pub fn weights(&self) -> Vec<f64> {
        let mut w = vec![0.0; self.num_ctrl()];
        self.get_ctrl(None, Some(&mut w)).expect("bs_patch_get_ctrl");
        w
    }
}
