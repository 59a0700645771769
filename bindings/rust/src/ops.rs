//! Exact operations on patches; every result is a new, independent [`Patch`].

use std::ptr;

use crate::error::{check, values, Error, ErrorKind, Result};
use crate::patch::{Patch, PatchRef};
use crate::sys;

/// A parameter direction (`BS_DIR_U`, `BS_DIR_V`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dir {
    /// Along u (the first index of the net).
    U,
    /// Along v (the second index of the net).
    V,
}

impl From<Dir> for i32 {
    /// The C constant (`BS_DIR_U`, `BS_DIR_V`).
    fn from(d: Dir) -> i32 {
        d.raw()
    }
}

impl TryFrom<i32> for Dir {
    type Error = Error;
    /// The direction for a `BS_DIR_*` value; any other value is `InvalidArg`.
    fn try_from(raw: i32) -> Result<Dir> {
        match raw {
            sys::BS_DIR_U => Ok(Dir::U),
            sys::BS_DIR_V => Ok(Dir::V),
            _ => Err(Error::argument_error(
                sys::BS_ERR_INVALID_ARG,
                "raw",
                format!("is {raw}, not a BS_DIR_ value"),
            )),
        }
    }
}

impl Dir {
    pub(crate) fn raw(self) -> std::os::raw::c_int {
        match self {
            Dir::U => sys::BS_DIR_U,
            Dir::V => sys::BS_DIR_V,
        }
    }
}

/// Runs a C function that returns one new patch through its last argument.
pub(crate) fn new_patch(f: impl FnOnce(*mut *mut sys::bs_patch) -> sys::bs_status) -> Result<Patch> {
    let mut out = ptr::null_mut();
    check(f(&mut out))?;
    // SAFETY: on success the C function returned a new patch that we now own.
    Ok(unsafe { Patch::from_raw(out) })
}

/// A `Size` error for the slice `name` of `len` values where `want` are needed.
fn length_error(name: &'static str, len: usize, want: usize, exact: bool) -> Error {
    let rule = if exact { "exactly" } else { "at least" };
    Error::argument_error(sys::BS_ERR_SIZE, name, format!("has {}, {rule} {want} are needed", values(len)))
}

impl PatchRef {
    /// Splits at `t` along `dir`, 0 < t < 1 (else `Domain`), into the parts over [0, t] and
    /// [t, 1] (`bs_patch_split`).
    ///
    /// ```
    /// use bezsurf::{Dir, Patch};
    ///
    /// let p = Patch::new(2, 1, 1, &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0])?;
    /// let (lo, hi) = p.split(Dir::U, 0.25)?;
    /// // lo(1, v) and hi(0, v) are both p(0.25, v).
    /// assert_eq!(lo.eval_point(1.0, 0.5)?, p.eval_point(0.25, 0.5)?);
    /// assert_eq!(hi.eval_point(0.0, 0.5)?, p.eval_point(0.25, 0.5)?);
    /// assert_eq!(p.split(Dir::U, 1.0).unwrap_err().kind(), bezsurf::ErrorKind::Domain);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn split(&self, dir: Dir, t: f64) -> Result<(Patch, Patch)> {
        let (mut lo, mut hi) = (ptr::null_mut(), ptr::null_mut());
        // SAFETY: self is live; lo and hi are valid.
        check(unsafe { sys::bs_patch_split(self.as_ptr(), dir.raw(), t, &mut lo, &mut hi) })?;
        // SAFETY: on success both are new patches that we now own.
        Ok(unsafe { (Patch::from_raw(lo), Patch::from_raw(hi)) })
    }

    /// Splits at (u, v) into four (`bs_patch_split4`): [u low, v low], [u high, v low],
    /// [u low, v high], [u high, v high].
    pub fn split4(&self, u: f64, v: f64) -> Result<[Patch; 4]> {
        let mut out = [ptr::null_mut(); 4];
        // SAFETY: self is live; out has room for four handles.
        check(unsafe { sys::bs_patch_split4(self.as_ptr(), u, v, out.as_mut_ptr()) })?;
        // SAFETY: on success all four are new patches that we now own.
        Ok(out.map(|p| unsafe { Patch::from_raw(p) }))
    }

    /// The patch over [u0, u1] x [v0, v1]; u0 > u1 (v0 > v1) reverses that direction
    /// (`bs_patch_subpatch`).
    pub fn subpatch(&self, u0: f64, u1: f64, v0: f64, v1: f64) -> Result<Patch> {
        // SAFETY: self is live; out is valid.
        new_patch(|out| unsafe { sys::bs_patch_subpatch(self.as_ptr(), u0, u1, v0, v1, out) })
    }

    /// The same surface with its degrees raised by `raise_u` and `raise_v` (`bs_patch_elevate`).
    pub fn elevate(&self, raise_u: usize, raise_v: usize) -> Result<Patch> {
        // SAFETY: self is live; out is valid.
        new_patch(|out| unsafe { sys::bs_patch_elevate(self.as_ptr(), raise_u, raise_v, out) }).map_err(|e| {
            if e.kind() != crate::ErrorKind::Degree {
                return e;
            }
            let (du, dv) = (self.degree_u(), self.degree_v());
            let (name, raise, d) = if du.saturating_add(raise_u) > sys::BS_MAX_DEGREE {
                ("raise_u", raise_u, du)
            } else {
                ("raise_v", raise_v, dv)
            };
            e.with_argument(
                name,
                format!("is {raise}: degree {d} + {raise} is above the limit {}", sys::BS_MAX_DEGREE),
            )
        })
    }

    /// The hodograph patch of d^(ku+kv) S / du^ku dv^kv (`bs_patch_derivative`); polynomial
    /// patches only (else `Unsupported`).
    pub fn derivative(&self, ku: u32, kv: u32) -> Result<Patch> {
        // SAFETY: self is live; out is valid.
        new_patch(|out| unsafe { sys::bs_patch_derivative(self.as_ptr(), ku, kv, out) })
    }

    /// Number of control points of the iso-curve along `dir`: the curve u = t (`Dir::U`) runs
    /// in v and has deg_v + 1 points; v = t (`Dir::V`) has deg_u + 1.
    pub fn isocurve_len(&self, dir: Dir) -> usize {
        match dir {
            Dir::U => self.degree_v() + 1,
            Dir::V => self.degree_u() + 1,
        }
    }

    /// Control points (packed, `dim` per point) and, if wanted, weights (all 1.0 for a
    /// polynomial patch) of the iso-curve u = t (`Dir::U`) or v = t (`Dir::V`)
    /// (`bs_patch_isocurve`). Any finite t (else `Domain`); `Size` if a slice is too short.
    pub fn isocurve_into(
        &self,
        dir: Dir,
        t: f64,
        ctrl: &mut [f64],
        weights: Option<&mut [f64]>,
    ) -> Result<()> {
        let (wp, wc) = weights.map_or((ptr::null_mut(), 0), |w| (w.as_mut_ptr(), w.len()));
        let cc = ctrl.len();
        // SAFETY: each pointer is NULL or a slice of the capacity passed with it.
        check(unsafe { sys::bs_patch_isocurve(self.as_ptr(), dir.raw(), t, ctrl.as_mut_ptr(), cc, wp, wc) })
            .map_err(|e| {
                let (np, dim) = (self.isocurve_len(dir), self.dim());
                if e.kind() != ErrorKind::Size {
                    e
                } else if cc < np * dim {
                    length_error("ctrl", cc, np * dim, false)
                } else if !wp.is_null() && wc < np {
                    length_error("weights", wc, np, false)
                } else {
                    e
                }
            })
    }

    /// The iso-curve's control points and weights as new vectors (see
    /// [`isocurve_into`](PatchRef::isocurve_into)).
    pub fn isocurve(&self, dir: Dir, t: f64) -> Result<(Vec<f64>, Vec<f64>)> {
        let mut ctrl = vec![0.0; self.isocurve_len(dir) * self.dim()];
        let mut weights = vec![0.0; self.isocurve_len(dir)];
        self.isocurve_into(dir, t, &mut ctrl, Some(&mut weights))?;
        Ok((ctrl, weights))
    }

    /// Bounding box of the control net, which contains the patch (`bs_patch_bounds`): `dim`
    /// values each in `lo` and `hi` (`Size` if either is shorter).
    pub fn bounds_into(&self, lo: &mut [f64], hi: &mut [f64]) -> Result<()> {
        // The C function writes dim values with no capacity argument.
        if lo.len() < self.dim() {
            return Err(length_error("lo", lo.len(), self.dim(), false));
        }
        if hi.len() < self.dim() {
            return Err(length_error("hi", hi.len(), self.dim(), false));
        }
        // SAFETY: lo and hi hold at least dim values.
        check(unsafe { sys::bs_patch_bounds(self.as_ptr(), lo.as_mut_ptr(), hi.as_mut_ptr()) })
    }

    /// Bounding box of the control net as (lo, hi).
    pub fn bounds(&self) -> Result<(Vec<f64>, Vec<f64>)> {
        let (mut lo, mut hi) = (vec![0.0; self.dim()], vec![0.0; self.dim()]);
        self.bounds_into(&mut lo, &mut hi)?;
        Ok((lo, hi))
    }

    /// The patch with x -> A x + b applied to its net (`bs_patch_transform`); `affine` is
    /// dim x (dim + 1), row-major, last column b (`Size` if its length differs).
    pub fn transform(&self, affine: &[f64]) -> Result<Patch> {
        let dim = self.dim();
        // The C function reads dim*(dim+1) values with no capacity argument.
        if affine.len() != dim * (dim + 1) {
            return Err(length_error("affine", affine.len(), dim * (dim + 1), true));
        }
        // SAFETY: affine holds the dim*(dim+1) values read.
        new_patch(|out| unsafe { sys::bs_patch_transform(self.as_ptr(), affine.as_ptr(), out) })
    }
}

impl PatchRef {
    /// The same surface with u and v exchanged, Q(u, v) = P(v, u) (`bs_patch_swap_uv`). The
    /// normal S_u x S_v changes sign.
    pub fn swap_uv(&self) -> Result<Patch> {
        // SAFETY: self is live; out is valid.
        new_patch(|out| unsafe { sys::bs_patch_swap_uv(self.as_ptr(), out) })
    }

    /// The same surface with direction `dir` reversed, e.g. Q(u, v) = P(1 - u, v)
    /// (`bs_patch_reverse`).
    pub fn reverse(&self, dir: Dir) -> Result<Patch> {
        // SAFETY: self is live; out is valid.
        new_patch(|out| unsafe { sys::bs_patch_reverse(self.as_ptr(), dir.raw(), out) })
    }
}

/// A Bezier curve borrowed from slices, for the constructions [`Patch::ruled`] and
/// [`Patch::coons`] (`bs_curve`). Its lengths are checked when it is made.
#[derive(Debug, Clone, Copy)]
pub struct Curve<'a> {
    degree: usize,
    dim: usize,
    ctrl: &'a [f64],
    weights: Option<&'a [f64]>,
}

impl<'a> Curve<'a> {
    /// A polynomial curve of `degree` from (degree + 1)·dim packed coordinates.
    /// Errors: `Degree`, `Dimension` (out of range), `Size` (wrong slice length).
    pub fn new(degree: usize, dim: usize, ctrl: &'a [f64]) -> Result<Curve<'a>> {
        Curve::make(degree, dim, ctrl, None)
    }

    /// A rational curve: as [`Curve::new`] plus degree + 1 weights.
    pub fn new_rational(degree: usize, dim: usize, ctrl: &'a [f64], weights: &'a [f64]) -> Result<Curve<'a>> {
        Curve::make(degree, dim, ctrl, Some(weights))
    }

    fn make(degree: usize, dim: usize, ctrl: &'a [f64], weights: Option<&'a [f64]>) -> Result<Curve<'a>> {
        crate::patch::check_degree("degree", degree)?;
        crate::patch::check_dim(dim)?;
        // The C side reads exactly these lengths, with no capacity argument.
        if ctrl.len() != (degree + 1) * dim {
            return Err(length_error("ctrl", ctrl.len(), (degree + 1) * dim, true));
        }
        if let Some(w) = weights.filter(|w| w.len() != degree + 1) {
            return Err(length_error("weights", w.len(), degree + 1, true));
        }
        Ok(Curve { degree, dim, ctrl, weights })
    }

    /// Degree of the curve.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Dimension of a control point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    fn raw(&self) -> sys::bs_curve {
        sys::bs_curve {
            degree: self.degree,
            dim: self.dim,
            ctrl: self.ctrl.as_ptr(),
            weights: self.weights.map_or(ptr::null(), <[f64]>::as_ptr),
        }
    }
}

impl Patch {
    /// The ruled patch S(u, 0) = c0(u), S(u, 1) = c1(u), straight in v, degree (d, 1) with d the
    /// larger curve degree (`bs_patch_ruled`). `Incompatible` if the dimensions differ.
    ///
    /// ```
    /// use bezsurf::{Curve, Patch};
    ///
    /// let bottom = [0.0, 0.0, 1.0, 0.0]; // a line in 2-D, degree 1
    /// let top = [0.0, 1.0, 0.5, 2.0, 1.0, 1.0]; // a parabola, degree 2
    /// let p = Patch::ruled(&Curve::new(1, 2, &bottom)?, &Curve::new(2, 2, &top)?)?;
    /// assert_eq!((p.degree_u(), p.degree_v()), (2, 1));
    /// assert_eq!(p.eval_point(0.5, 1.0)?, [0.5, 1.5]);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn ruled(c0: &Curve<'_>, c1: &Curve<'_>) -> Result<Patch> {
        let (a, b) = (c0.raw(), c1.raw());
        // SAFETY: both curves point into slices of the lengths their shapes need.
        new_patch(|out| unsafe { sys::bs_patch_ruled(&a, &b, out) })
    }

    /// The bilinearly blended Coons patch with boundaries S(u, 0) = v0(u), S(u, 1) = v1(u),
    /// S(0, v) = u0(v), S(1, v) = u1(v) (`bs_patch_coons`); polynomial curves only
    /// (`Unsupported`), corners must meet (`Incompatible`).
    pub fn coons(v0: &Curve<'_>, v1: &Curve<'_>, u0: &Curve<'_>, u1: &Curve<'_>) -> Result<Patch> {
        let (a, b, c, d) = (v0.raw(), v1.raw(), u0.raw(), u1.raw());
        // SAFETY: every curve points into slices of the lengths its shape needs.
        new_patch(|out| unsafe { sys::bs_patch_coons(&a, &b, &c, &d, out) })
    }
}
