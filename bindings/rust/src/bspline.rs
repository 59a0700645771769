//! B-spline and NURBS surfaces cut into Bezier patches (`bezsurf/bspline.h`, since 1.1).

use crate::error::{check, count, values, Error, Result};
use crate::surface::Surface;
use crate::sys;

/// A B-spline or NURBS surface borrowed from the caller's slices: one Bezier patch per knot span
/// when added to a [`Surface`] with [`Surface::add_bspline`].
///
/// Point (i, j) of the control net (i along u) has its `dim` coordinates at
/// `ctrl[(i * count_v + j) * dim ..]`; each knot vector has `count + degree + 1` values. The slice
/// lengths are checked here, the values (degrees, finite non-decreasing knots, finite points,
/// positive weights) by the library.
///
/// ```
/// use bezsurf::{BSpline, Surface};
///
/// // Quadratic along u with an interior knot at 1 (two spans), linear along v (one span).
/// let ku = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
/// let kv = [0.0, 0.0, 1.0, 1.0];
/// let ctrl: Vec<f64> = (0..4 * 2 * 3).map(|k| k as f64).collect();
/// let b = BSpline::new(2, 1, 4, 2, 3, &ku, &kv, &ctrl)?;
/// assert_eq!(b.span_count()?, (2, 1));
///
/// let mut s = Surface::new()?;
/// let spans = s.add_bspline(&b)?;
/// assert_eq!(s.len(), 2);
/// assert_eq!(spans, vec![[0.0, 1.0, 0.0, 1.0], [1.0, 2.0, 0.0, 1.0]]);
/// // Parameter (1.5, 0.25) lies on patch 1 at local (0.5, 0.25).
/// assert_eq!(b.locate(1.5, 0.25)?, (1, 0.5, 0.25));
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct BSpline<'a> {
    raw: sys::bs_bspline,
    _data: std::marker::PhantomData<&'a [f64]>,
}

/// The error for a slice of the wrong length.
fn wrong_len(name: &'static str, got: usize, want: usize) -> Error {
    Error::argument_error(
        sys::BS_ERR_SIZE,
        name,
        format!("has {} but {} are needed", values(got), count(want, "value")),
    )
}

impl<'a> BSpline<'a> {
    /// A polynomial B-spline surface of degrees (`deg_u`, `deg_v`) with `count_u` x `count_v`
    /// control points of dimension `dim`. `Size` naming the slice when a slice's length is not
    /// what the counts say.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        deg_u: usize,
        deg_v: usize,
        count_u: usize,
        count_v: usize,
        dim: usize,
        knots_u: &'a [f64],
        knots_v: &'a [f64],
        ctrl: &'a [f64],
    ) -> Result<BSpline<'a>> {
        let need_ku = count_u.checked_add(deg_u).and_then(|n| n.checked_add(1));
        let need_kv = count_v.checked_add(deg_v).and_then(|n| n.checked_add(1));
        let need_ctrl = count_u.checked_mul(count_v).and_then(|n| n.checked_mul(dim));
        match need_ku {
            Some(n) if n == knots_u.len() => {}
            _ => return Err(wrong_len("knots_u", knots_u.len(), need_ku.unwrap_or(usize::MAX))),
        }
        match need_kv {
            Some(n) if n == knots_v.len() => {}
            _ => return Err(wrong_len("knots_v", knots_v.len(), need_kv.unwrap_or(usize::MAX))),
        }
        match need_ctrl {
            Some(n) if n == ctrl.len() => {}
            _ => return Err(wrong_len("ctrl", ctrl.len(), need_ctrl.unwrap_or(usize::MAX))),
        }
        Ok(BSpline {
            raw: sys::bs_bspline {
                deg_u,
                deg_v,
                count_u,
                count_v,
                dim,
                knots_u: knots_u.as_ptr(),
                knots_v: knots_v.as_ptr(),
                ctrl: ctrl.as_ptr(),
                weights: std::ptr::null(),
            },
            _data: std::marker::PhantomData,
        })
    }

    /// The same surface as a NURBS with `count_u * count_v` weights, one per control point.
    pub fn with_weights(mut self, weights: &'a [f64]) -> Result<BSpline<'a>> {
        let n = self.raw.count_u * self.raw.count_v;
        if weights.len() != n {
            return Err(wrong_len("weights", weights.len(), n));
        }
        self.raw.weights = weights.as_ptr();
        Ok(self)
    }

    /// The raw description, pointing into the borrowed slices.
    pub fn as_raw(&self) -> &sys::bs_bspline {
        &self.raw
    }

    /// Knot spans along u and v: [`Surface::add_bspline`] adds `spans_u * spans_v` patches
    /// (`bs_bspline_span_count`).
    pub fn span_count(&self) -> Result<(usize, usize)> {
        let (mut nu, mut nv) = (0usize, 0usize);
        // SAFETY: raw points into slices of the lengths the counts require (checked in new), which
        // live for 'a; nu and nv are valid.
        check(unsafe { sys::bs_bspline_span_count(&self.raw, &mut nu, &mut nv) })?;
        Ok((nu, nv))
    }

    /// The patch index (counted from the first patch [`Surface::add_bspline`] added) and the local
    /// (u, v) of B-spline parameter (u, v) (`bs_bspline_locate`). `Domain` outside the domain or
    /// for NaN.
    pub fn locate(&self, u: f64, v: f64) -> Result<(usize, f64, f64)> {
        let (mut index, mut lu, mut lv) = (0usize, 0.0f64, 0.0f64);
        // SAFETY: as in span_count; index, lu and lv are valid.
        check(unsafe { sys::bs_bspline_locate(&self.raw, u, v, &mut index, &mut lu, &mut lv) })?;
        Ok((index, lu, lv))
    }
}

impl Surface {
    /// Appends `b` as one Bezier patch per knot span, span (a, b) at index
    /// `len_before + a * spans_v + b`, and returns each added patch's span `[u0, u1, v0, v1]`
    /// (`bs_surface_add_bspline`). On failure the surface is unchanged.
    pub fn add_bspline(&mut self, b: &BSpline<'_>) -> Result<Vec<[f64; 4]>> {
        let (nu, nv) = b.span_count()?;
        let n = nu.checked_mul(nv).ok_or_else(|| Error::from_code(sys::BS_ERR_SIZE))?;
        let mut spans = vec![[0.0f64; 4]; n];
        let mut added = 0usize;
        // SAFETY: self is live and exclusively borrowed; b's pointers are valid for 'a (see
        // span_count); spans has room for 4 * n doubles, the capacity passed; added is valid.
        check(unsafe {
            sys::bs_surface_add_bspline(
                self.as_mut_ptr(),
                b.as_raw(),
                spans.as_mut_ptr().cast(),
                4 * n,
                &mut added,
            )
        })?;
        spans.truncate(added);
        Ok(spans)
    }
}
