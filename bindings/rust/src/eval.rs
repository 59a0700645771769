//! Evaluation of patches: positions, partial derivatives, normals, tensor grids.

use std::ptr;

use crate::error::{check, no_room, values, Error, ErrorKind, Result};
use crate::patch::PatchRef;
use crate::strided::{PointsMut, Strided};
use crate::sys;

/// What kind of normal was written for a point (`BS_NORMAL_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NormalKind {
    /// From S_u x S_v (`BS_NORMAL_REGULAR`).
    Regular,
    /// S_u x S_v vanishes; the limit normal along the surface (`BS_NORMAL_LIMIT`).
    Limit,
    /// No normal exists; (0,0,0) was written, or NaN for a NaN parameter
    /// (`BS_NORMAL_UNDEFINED`).
    Undefined,
}

impl NormalKind {
    /// The kind for a byte written by the library, `None` for a value that is no kind.
    pub fn from_byte(b: u8) -> Option<NormalKind> {
        match b {
            sys::BS_NORMAL_REGULAR => Some(NormalKind::Regular),
            sys::BS_NORMAL_LIMIT => Some(NormalKind::Limit),
            sys::BS_NORMAL_UNDEFINED => Some(NormalKind::Undefined),
            _ => None,
        }
    }
}

impl From<NormalKind> for u8 {
    /// The byte the library writes for this kind (`BS_NORMAL_*`).
    fn from(k: NormalKind) -> u8 {
        match k {
            NormalKind::Regular => sys::BS_NORMAL_REGULAR,
            NormalKind::Limit => sys::BS_NORMAL_LIMIT,
            NormalKind::Undefined => sys::BS_NORMAL_UNDEFINED,
        }
    }
}

impl TryFrom<u8> for NormalKind {
    type Error = Error;
    /// The kind for a byte written by the library; any other value is `InvalidArg`.
    fn try_from(b: u8) -> Result<NormalKind> {
        NormalKind::from_byte(b).ok_or_else(|| {
            Error::argument_error(sys::BS_ERR_INVALID_ARG, "byte", format!("is {b}, not a BS_NORMAL_ value"))
        })
    }
}

/// The outputs wanted from an evaluation; anything not set is not computed.
///
/// ```
/// # use bezsurf::{Outputs, Patch};
/// let plane = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0.])?;
/// let (mut pos, mut du) = (vec![0.0; 6], vec![0.0; 6]);
/// plane.eval_with(&[0.25, 1.0], &[0.5, 0.0], Outputs::new().pos(&mut pos).du(&mut du))?;
/// assert_eq!(pos, [0.25, 0.5, 0.0, 1.0, 0.0, 0.0]);
/// assert_eq!(du, [1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug, Default)]
pub struct Outputs<'a> {
    pub(crate) pos: Option<PointsMut<'a>>,
    pub(crate) du: Option<PointsMut<'a>>,
    pub(crate) dv: Option<PointsMut<'a>>,
    pub(crate) nrm: Option<PointsMut<'a>>,
    pub(crate) kind: Option<&'a mut [u8]>,
}

impl<'a> Outputs<'a> {
    /// Nothing wanted yet.
    pub fn new() -> Outputs<'a> {
        Outputs::default()
    }
    /// Positions S(u, v), `dim` coordinates per point.
    pub fn pos(mut self, out: impl Into<PointsMut<'a>>) -> Outputs<'a> {
        self.pos = Some(out.into());
        self
    }
    /// First partial derivatives dS/du.
    pub fn du(mut self, out: impl Into<PointsMut<'a>>) -> Outputs<'a> {
        self.du = Some(out.into());
        self
    }
    /// First partial derivatives dS/dv.
    pub fn dv(mut self, out: impl Into<PointsMut<'a>>) -> Outputs<'a> {
        self.dv = Some(out.into());
        self
    }
    /// Unit normals, 3 coordinates per point (3-D patches only).
    pub fn normal(mut self, out: impl Into<PointsMut<'a>>) -> Outputs<'a> {
        self.nrm = Some(out.into());
        self
    }
    /// One byte per point: the [`NormalKind`] as `sys::BS_NORMAL_*` (see
    /// [`NormalKind::from_byte`]).
    pub fn kind(mut self, out: &'a mut [u8]) -> Outputs<'a> {
        self.kind = Some(out);
        self
    }
}

/// C views for an optional output, holding the array the C call points into.
pub(crate) struct CPoints {
    name: &'static str,
    dim: usize,
    views: Option<[sys::bs_view; sys::BS_MAX_DIM]>,
}

impl CPoints {
    /// The views of output `name` (the argument's name, for errors) for points of `dim`.
    pub(crate) fn new(out: Option<&mut PointsMut<'_>>, dim: usize, name: &'static str) -> Result<CPoints> {
        Ok(CPoints { name, dim, views: out.map(|o| o.c_views(dim, name)).transpose()? })
    }
    pub(crate) fn none() -> CPoints {
        CPoints { name: "", dim: 0, views: None }
    }
    pub(crate) fn as_ptr(&self) -> *const sys::bs_view {
        self.views.as_ref().map_or(ptr::null(), |v| v.as_ptr())
    }
    /// How many points fit, if the output is wanted.
    fn capacity(&self) -> Option<usize> {
        self.views.as_ref().map(|v| v[..self.dim].iter().map(|v| v.count).min().unwrap_or(0))
    }
}

/// Attributes a `Size` error of the library to the first output in `outs` with room for fewer
/// than `n` points (the C API reports only the status). Other errors pass unchanged.
pub(crate) fn name_short_output(e: Error, n: usize, outs: &[&CPoints]) -> Error {
    if e.kind() != ErrorKind::Size || e.argument().is_some() {
        return e;
    }
    let short = outs.iter().find_map(|o| o.capacity().filter(|&cap| cap < n).map(|cap| (o.name, cap)));
    match short {
        Some((name, cap)) => e.with_argument(name, no_room(cap, n, "point")),
        None => e,
    }
}

/// The error for an output that the method does not compute.
pub(crate) fn not_computed(name: &'static str, method: &str, instead: &str) -> Error {
    Error::argument_error(
        sys::BS_ERR_INVALID_ARG,
        name,
        format!("is not an output of {method}; use {instead}"),
    )
}

/// The kind buffer as the C pointer, after checking it holds `n` bytes (the C API has no
/// capacity for it).
pub(crate) fn kind_ptr(kind: Option<&mut [u8]>, n: usize) -> Result<*mut u8> {
    match kind {
        None => Ok(ptr::null_mut()),
        Some(k) if k.len() >= n => Ok(k.as_mut_ptr()),
        Some(k) => Err(Error::argument_error(sys::BS_ERR_SIZE, "kind", no_room(k.len(), n, "byte"))),
    }
}

/// Parameters for scattered evaluation: u and v must have the same length n.
pub(crate) fn scattered<'u, 'v>(
    u: impl Into<Strided<'u>>,
    v: impl Into<Strided<'v>>,
) -> Result<(usize, sys::bs_cview, sys::bs_cview)> {
    let (u, v) = (u.into(), v.into());
    if u.len() != v.len() {
        return Err(Error::argument_error(
            sys::BS_ERR_SIZE,
            "v",
            format!("has {} but `u` has {}; they must have the same length", values(v.len()), u.len()),
        ));
    }
    Ok((u.len(), u.as_cview(), v.as_cview()))
}

/// Surface evaluation's ids: one per point.
pub(crate) fn check_ids(ids: &[u32], n: usize) -> Result<()> {
    if ids.len() != n {
        return Err(Error::argument_error(
            sys::BS_ERR_SIZE,
            "ids",
            format!("has {} but `u` and `v` have {n}; they must have the same length", values(ids.len())),
        ));
    }
    Ok(())
}

impl PatchRef {
    /// Positions at the n points (`u[k]`, `v[k]`) (`bs_patch_eval`). `u` and `v` are slices or
    /// [`Strided`] views of the same length n (else `Size`); `pos` receives n points of
    /// [`dim`](PatchRef::dim) coordinates (interleaved slice or one view per coordinate; too
    /// short is `Size`). Parameters outside [0, 1] extrapolate; a NaN parameter gives NaN.
    pub fn eval<'u, 'v, 'o>(
        &self,
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        pos: impl Into<PointsMut<'o>>,
    ) -> Result<()> {
        self.eval_with(u, v, Outputs::new().pos(pos))
    }

    /// The position at one point, `dim` coordinates.
    pub fn eval_point(&self, u: f64, v: f64) -> Result<Vec<f64>> {
        let mut pos = vec![0.0; self.dim()];
        self.eval(&[u], &[v], &mut pos)?;
        Ok(pos)
    }

    /// Positions and first partial derivatives at n scattered points (`bs_patch_eval`): the
    /// outputs set among `pos`, `du`, `dv`. Asking for normals or kinds here is `InvalidArg`
    /// (use [`eval_normal`](PatchRef::eval_normal)). On error nothing is written.
    pub fn eval_with<'u, 'v>(
        &self,
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        mut out: Outputs<'_>,
    ) -> Result<()> {
        if out.nrm.is_some() {
            return Err(not_computed("normal", "eval_with", "eval_normal"));
        }
        if out.kind.is_some() {
            return Err(not_computed("kind", "eval_with", "eval_normal"));
        }
        let (n, u, v) = scattered(u, v)?;
        let dim = self.dim();
        let pos = CPoints::new(out.pos.as_mut(), dim, "pos")?;
        let du = CPoints::new(out.du.as_mut(), dim, "du")?;
        let dv = CPoints::new(out.dv.as_mut(), dim, "dv")?;
        // SAFETY: every view was built from a borrowed slice it stays inside; the output views
        // come from exclusive borrows, so they do not overlap each other or the inputs.
        check(unsafe { sys::bs_patch_eval(self.as_ptr(), n, &u, &v, pos.as_ptr(), du.as_ptr(), dv.as_ptr()) })
            .map_err(|e| name_short_output(e, n, &[&pos, &du, &dv]))
    }

    /// The mixed partial derivative d^(ku+kv) S / du^ku dv^kv at n scattered points
    /// (`bs_patch_eval_deriv`); (0, 0) gives positions, orders above the degree give zero for
    /// polynomial patches. `Degree` if an order exceeds [`MAX_DEGREE`](crate::MAX_DEGREE).
    pub fn eval_deriv<'u, 'v, 'o>(
        &self,
        ku: u32,
        kv: u32,
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        out: impl Into<PointsMut<'o>>,
    ) -> Result<()> {
        let (n, u, v) = scattered(u, v)?;
        let mut out = out.into();
        let views = CPoints::new(Some(&mut out), self.dim(), "out")?;
        // SAFETY: as in eval_with.
        check(unsafe { sys::bs_patch_eval_deriv(self.as_ptr(), ku, kv, n, &u, &v, views.as_ptr()) })
            .map_err(|e| name_short_output(e, n, &[&views]))
    }

    /// Positions, unit normals and normal kinds at n scattered points of a 3-D patch
    /// (`bs_patch_eval_normal`): the outputs set among `pos`, `normal`, `kind`. Asking for `du` or
    /// `dv` here is `InvalidArg`; a patch that is not 3-D is `Dimension`.
    ///
    /// ```
    /// use bezsurf::{NormalKind, Outputs, Patch};
    ///
    /// let p = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.])?;
    /// let (mut n, mut kind) = ([0.0; 3], [0u8; 1]);
    /// p.eval_normal(&[1.0], &[0.0], Outputs::new().normal(&mut n).kind(&mut kind))?;
    /// let s = 0.5f64.sqrt(); // (-v, -u, 1) = (0, -1, 1), normalised
    /// assert!((n[1] + s).abs() < 1e-15 && (n[2] - s).abs() < 1e-15 && n[0] == 0.0);
    /// assert_eq!(NormalKind::try_from(kind[0])?, NormalKind::Regular);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn eval_normal<'u, 'v>(
        &self,
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        mut out: Outputs<'_>,
    ) -> Result<()> {
        if out.du.is_some() {
            return Err(not_computed("du", "eval_normal", "eval_with"));
        }
        if out.dv.is_some() {
            return Err(not_computed("dv", "eval_normal", "eval_with"));
        }
        let (n, u, v) = scattered(u, v)?;
        let pos = CPoints::new(out.pos.as_mut(), self.dim(), "pos")?;
        let nrm = CPoints::new(out.nrm.as_mut(), 3, "normal")?;
        let kind = kind_ptr(out.kind.take(), n)?;
        // SAFETY: as in eval_with; kind holds at least n bytes.
        check(unsafe {
            sys::bs_patch_eval_normal(self.as_ptr(), n, &u, &v, pos.as_ptr(), nrm.as_ptr(), kind)
        })
        .map_err(|e| name_short_output(e, n, &[&pos, &nrm]))
    }

    /// Every `u[a]` with every `v[b]` (`bs_patch_eval_grid`), point (a, b) written at index
    /// a·nv + b, nu = `u.len()`, nv = `v.len()`. Any of the outputs may be set; `normal` and
    /// `kind` need a 3-D patch (else `Dimension`).
    ///
    /// ```
    /// use bezsurf::{Outputs, Patch};
    ///
    /// // The bilinear patch S(u, v) = (u, v, u v).
    /// let p = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.])?;
    /// let (u, v) = ([0.0, 0.5, 1.0], [0.0, 1.0]);
    /// let mut pos = vec![0.0; 3 * u.len() * v.len()];
    /// let mut normal = vec![0.0; pos.len()];
    /// p.eval_grid(&u, &v, Outputs::new().pos(&mut pos).normal(&mut normal))?;
    /// // Point (a, b) = (2, 1) is S(1, 1), at index 2 * 2 + 1.
    /// assert_eq!(pos[3 * 5..3 * 6], [1.0, 1.0, 1.0]);
    /// // The normal at (0, 0) is (-v, -u, 1) normalised = (0, 0, 1).
    /// assert_eq!(normal[..3], [0.0, 0.0, 1.0]);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn eval_grid<'u, 'v>(
        &self,
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        mut out: Outputs<'_>,
    ) -> Result<()> {
        let (u, v) = (u.into(), v.into());
        let (nu, nv) = (u.len(), v.len());
        let dim = self.dim();
        let pos = CPoints::new(out.pos.as_mut(), dim, "pos")?;
        let du = CPoints::new(out.du.as_mut(), dim, "du")?;
        let dv = CPoints::new(out.dv.as_mut(), dim, "dv")?;
        let nrm = CPoints::new(out.nrm.as_mut(), 3, "normal")?;
        let npts = nu.checked_mul(nv).ok_or_else(|| {
            Error::argument_error(
                sys::BS_ERR_SIZE,
                "v",
                format!("makes {nu} x {nv} grid points, more than usize holds"),
            )
        })?;
        let kind = kind_ptr(out.kind.take(), npts)?;
        let (u, v) = (u.as_cview(), v.as_cview());
        // SAFETY: as in eval_with; kind holds at least nu*nv bytes.
        check(unsafe {
            sys::bs_patch_eval_grid(
                self.as_ptr(),
                nu,
                &u,
                nv,
                &v,
                pos.as_ptr(),
                du.as_ptr(),
                dv.as_ptr(),
                nrm.as_ptr(),
                kind,
            )
        })
        .map_err(|e| name_short_output(e, npts, &[&pos, &du, &dv, &nrm]))
    }
}
