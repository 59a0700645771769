//! Evaluation of scattered points across a surface: point k on patch `ids[k]` at (u[k], v[k]).

use crate::error::{check, Error, ErrorKind, Result};
use crate::eval::{check_ids, kind_ptr, name_short_output, not_computed, scattered, CPoints, Outputs};
use crate::strided::Strided;
use crate::surface::Surface;

impl Surface {
    /// Positions and first partials at n scattered points (`bs_surface_eval`): point k lies on
    /// patch `ids[k]` at (`u[k]`, `v[k]`). `ids`, `u` and `v` must have the same length n (else
    /// `Size`); an id not below [`len`](Surface::len) is `InvalidArg`. The outputs set among
    /// `pos`, `du`, `dv` receive [`dim`](Surface::dim) coordinates per point; normals and kinds
    /// are asked of [`eval_normal`](Surface::eval_normal) (here they are `InvalidArg`). Sorting
    /// the points by id makes the evaluation faster; the results do not depend on the order.
    pub fn eval<'u, 'v>(
        &self,
        ids: &[u32],
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        out: Outputs<'_>,
    ) -> Result<()> {
        self.eval_threads(ids, u, v, out, 1)
    }

    /// [`Surface::eval`] on up to `threads` threads, the calling one included
    /// (`bs_surface_eval_mt`, since 1.1; 0: one per online CPU). The results are the same bit
    /// for bit whatever the number of threads.
    pub fn eval_threads<'u, 'v>(
        &self,
        ids: &[u32],
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        mut out: Outputs<'_>,
        threads: usize,
    ) -> Result<()> {
        if out.nrm.is_some() {
            return Err(not_computed("normal", "Surface::eval", "Surface::eval_normal"));
        }
        if out.kind.is_some() {
            return Err(not_computed("kind", "Surface::eval", "Surface::eval_normal"));
        }
        let (n, u, v) = scattered(u, v)?;
        // The C function reads n ids with no capacity argument.
        check_ids(ids, n)?;
        // An empty surface has no coordinates to write: its outputs are zero views (the ids are
        // then all out of range, or n is 0).
        let dim = self.dim();
        let (pos, du, dv) = if dim == 0 {
            (CPoints::none(), CPoints::none(), CPoints::none())
        } else {
            (
                CPoints::new(out.pos.as_mut(), dim, "pos")?,
                CPoints::new(out.du.as_mut(), dim, "du")?,
                CPoints::new(out.dv.as_mut(), dim, "dv")?,
            )
        };
        // SAFETY: ids holds n values; every view stays inside the slice it was built from; the
        // output views come from exclusive borrows and do not overlap.
        check(unsafe {
            crate::sys::bs_surface_eval_mt(
                self.as_ptr(),
                n,
                ids.as_ptr(),
                &u,
                &v,
                pos.as_ptr(),
                du.as_ptr(),
                dv.as_ptr(),
                threads,
            )
        })
        .map_err(|e| name_bad_id(name_short_output(e, n, &[&pos, &du, &dv]), ids, self.len()))
    }

    /// Positions, unit normals and normal kinds at n scattered points of a 3-D surface
    /// (`bs_surface_eval_normal`), with the rules of [`Surface::eval`] and of
    /// [`PatchRef::eval_normal`](crate::PatchRef::eval_normal).
    pub fn eval_normal<'u, 'v>(
        &self,
        ids: &[u32],
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        out: Outputs<'_>,
    ) -> Result<()> {
        self.eval_normal_threads(ids, u, v, out, 1)
    }

    /// [`Surface::eval_normal`] on up to `threads` threads, the calling one included
    /// (`bs_surface_eval_normal_mt`, since 1.2; 0: one per online CPU). The positions, normals
    /// and kinds are the same bit for bit whatever the number of threads.
    ///
    /// ```
    /// use bezsurf::{Outputs, Surface};
    ///
    /// let pot = Surface::builtin("teapot")?;
    /// let ids: Vec<u32> = (0..64).map(|k| k % 32).collect();
    /// let t: Vec<f64> = (0..64).map(|k| k as f64 / 63.0).collect();
    /// let (mut one, mut two) = (vec![0.0; 3 * 64], vec![0.0; 3 * 64]);
    /// pot.eval_normal(&ids, &t, &t, Outputs::new().normal(&mut one))?;
    /// pot.eval_normal_threads(&ids, &t, &t, Outputs::new().normal(&mut two), 2)?;
    /// assert_eq!(one, two);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn eval_normal_threads<'u, 'v>(
        &self,
        ids: &[u32],
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        mut out: Outputs<'_>,
        threads: usize,
    ) -> Result<()> {
        if out.du.is_some() {
            return Err(not_computed("du", "Surface::eval_normal", "Surface::eval"));
        }
        if out.dv.is_some() {
            return Err(not_computed("dv", "Surface::eval_normal", "Surface::eval"));
        }
        let (n, u, v) = scattered(u, v)?;
        check_ids(ids, n)?;
        let pos = CPoints::new(out.pos.as_mut(), 3, "pos")?;
        let nrm = CPoints::new(out.nrm.as_mut(), 3, "normal")?;
        let kind = kind_ptr(out.kind.take(), n)?;
        // SAFETY: as in eval; kind holds at least n bytes.
        check(unsafe {
            crate::sys::bs_surface_eval_normal_mt(
                self.as_ptr(),
                n,
                ids.as_ptr(),
                &u,
                &v,
                pos.as_ptr(),
                nrm.as_ptr(),
                kind,
                threads,
            )
        })
        .map_err(|e| name_bad_id(name_short_output(e, n, &[&pos, &nrm]), ids, self.len()))
    }
}

impl Surface {
    /// The same tensor grid of `u` x `v` parameters on every patch (`bs_surface_eval_grid`,
    /// since 1.1), on up to `threads` threads (0: one per online CPU; 1 stays on the calling
    /// thread), with the same bits for every count. Point (`u[a]`, `v[b]`) of patch p is output
    /// point (p * nu + a) * nv + b: `out` needs room for `len() * nu * nv` points (positions,
    /// partials, normals and kinds as for [`PatchRef::eval_grid`](crate::PatchRef::eval_grid)).
    ///
    /// ```
    /// use bezsurf::{Outputs, Surface};
    ///
    /// let cup = Surface::builtin("teacup")?;
    /// let (u, v) = ([0.0, 0.5, 1.0], [0.25, 0.75]);
    /// let mut pos = vec![0.0; cup.len() * 3 * 2 * 3];
    /// cup.eval_grid(&u, &v, Outputs::new().pos(&mut pos), 2)?;
    /// let mut one = [0.0; 3];
    /// cup.eval(&[5], &[0.5], &[0.75], Outputs::new().pos(&mut one))?;
    /// let k = (5 * 3 + 1) * 2 + 1;
    /// assert_eq!(&pos[3 * k..3 * k + 3], &one);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn eval_grid<'u, 'v>(
        &self,
        u: impl Into<Strided<'u>>,
        v: impl Into<Strided<'v>>,
        mut out: Outputs<'_>,
        threads: usize,
    ) -> Result<()> {
        let (u, v) = (u.into(), v.into());
        let (nu, nv) = (u.len(), v.len());
        let dim = self.dim().max(1);
        let pos = CPoints::new(out.pos.as_mut(), dim, "pos")?;
        let du = CPoints::new(out.du.as_mut(), dim, "du")?;
        let dv = CPoints::new(out.dv.as_mut(), dim, "dv")?;
        let nrm = CPoints::new(out.nrm.as_mut(), 3, "normal")?;
        let npts = self.len().checked_mul(nu).and_then(|x| x.checked_mul(nv)).ok_or_else(|| {
            Error::argument_error(
                crate::sys::BS_ERR_SIZE,
                "v",
                format!("makes {} x {nu} x {nv} grid points, more than usize holds", self.len()),
            )
        })?;
        let kind = kind_ptr(out.kind.take(), npts)?;
        let (u, v) = (u.as_cview(), v.as_cview());
        // SAFETY: every view stays inside the slice it was built from; the outputs come from
        // exclusive borrows and do not overlap; kind holds at least npts bytes.
        check(unsafe {
            crate::sys::bs_surface_eval_grid(
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
                threads,
            )
        })
        .map_err(|e| name_short_output(e, npts, &[&pos, &du, &dv, &nrm]))
    }
}

/// An `InvalidArg` of a surface evaluator naming the first id that is not a patch of the surface.
fn name_bad_id(e: Error, ids: &[u32], count: usize) -> Error {
    if e.kind() != ErrorKind::InvalidArg {
        return e;
    }
    match ids.iter().position(|&i| i as usize >= count) {
        Some(k) if count == 0 => {
            e.with_argument("ids", format!("[{k}] is {}, but the surface is empty", ids[k]))
        }
        Some(k) => e.with_argument(
            "ids",
            format!("[{k}] is {}, not a patch of this surface (patch ids 0..={})", ids[k], count - 1),
        ),
        None => e,
    }
}
