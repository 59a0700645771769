//! Geometric queries on a patch (`bezsurf/query.h`, since 1.1): curvature and closest points.

use crate::error::{check, Error, Result};
use crate::patch::PatchRef;
use crate::sys;

/// How a curvature was obtained (`BS_CURV_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CurvatureKind {
    /// From the fundamental forms at the point (`BS_CURV_REGULAR`).
    Regular,
    /// The limit along the line towards (1/2, 1/2): collapsed edges and poles (`BS_CURV_LIMIT`).
    Limit,
    /// No finite curvature exists (a cone's apex); every value is NaN (`BS_CURV_UNDEFINED`).
    Undefined,
}

/// Curvatures and principal directions at one point ([`PatchRef::eval_curvature`]).
///
/// Signs follow the normal of [`PatchRef::eval_normal`]: a sphere with outward normals has
/// k = -1/r. `gaussian = k_min * k_max`, `mean = (k_min + k_max) / 2`, `k_min <= k_max`, and
/// (`d_min`, `d_max`, normal) is a right-handed frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curvature {
    /// Gaussian curvature K.
    pub gaussian: f64,
    /// Mean curvature H.
    pub mean: f64,
    /// Smaller principal curvature.
    pub k_min: f64,
    /// Larger principal curvature.
    pub k_max: f64,
    /// Unit direction of `k_min`.
    pub d_min: [f64; 3],
    /// Unit direction of `k_max`.
    pub d_max: [f64; 3],
    /// How the values were obtained.
    pub kind: CurvatureKind,
}

impl PatchRef {
    /// Curvatures and principal directions at the points (`u[k]`, `v[k]`) of a 3-D patch
    /// (`bs_patch_eval_curvature`). `Dimension` for another dimension; `Size` naming `v` when the
    /// slices differ in length.
    ///
    /// ```
    /// use bezsurf::{CurvatureKind, Patch};
    ///
    /// // The saddle S(u, v) = (u, v, u v): at the origin K = -1 and H = 0.
    /// let p = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.])?;
    /// let c = p.eval_curvature(&[0.0], &[0.0])?[0];
    /// assert_eq!(c.kind, CurvatureKind::Regular);
    /// assert!((c.gaussian + 1.0).abs() < 1e-15 && c.mean.abs() < 1e-15);
    /// assert!((c.k_min + 1.0).abs() < 1e-15 && (c.k_max - 1.0).abs() < 1e-15);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn eval_curvature(&self, u: &[f64], v: &[f64]) -> Result<Vec<Curvature>> {
        let n = u.len();
        if v.len() != n {
            return Err(Error::argument_error(
                sys::BS_ERR_SIZE,
                "v",
                format!("has {} values but `u` has {n}; they must have the same length", v.len()),
            ));
        }
        let mut vals = vec![0.0f64; 10 * n];
        let mut kind = vec![0u8; n];
        let cu = sys::bs_cview { data: u.as_ptr(), count: n, stride: 0 };
        let cv = sys::bs_cview { data: v.as_ptr(), count: n, stride: 0 };
        // Ten packed columns of n values: K, H, k_min, k_max, d_min x y z, d_max x y z.
        let base = vals.as_mut_ptr();
        let views: Vec<sys::bs_view> = (0..10)
            // SAFETY: c < 10, so c * n is within the 10 * n elements of vals (one past the end
            // when n = 0, which the library does not read).
            .map(|c| sys::bs_view { data: unsafe { base.add(c * n) }, count: n, stride: 0 })
            .collect();
        // SAFETY: the patch is live; u, v hold n values; the views cover disjoint columns of
        // vals, each n values long; kind holds n bytes.
        check(unsafe {
            sys::bs_patch_eval_curvature(
                self.as_ptr(),
                n,
                &cu,
                &cv,
                views.as_ptr(),
                views[4..].as_ptr(),
                views[7..].as_ptr(),
                kind.as_mut_ptr(),
            )
        })?;
        Ok((0..n)
            .map(|k| {
                let at = |c: usize| vals[c * n + k];
                Curvature {
                    gaussian: at(0),
                    mean: at(1),
                    k_min: at(2),
                    k_max: at(3),
                    d_min: [at(4), at(5), at(6)],
                    d_max: [at(7), at(8), at(9)],
                    kind: match kind[k] {
                        sys::BS_CURV_REGULAR => CurvatureKind::Regular,
                        sys::BS_CURV_LIMIT => CurvatureKind::Limit,
                        _ => CurvatureKind::Undefined,
                    },
                }
            })
            .collect())
    }
}

/// Closest points of a patch or a surface to n query points ([`PatchRef::closest_points`],
/// [`Locator::closest_points`](crate::Locator::closest_points)): one entry per query in each field.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ClosestPoints {
    /// Patch id of each answer ([`Locator`](crate::Locator) only; empty for one patch; `u32::MAX` where there is
    /// none).
    pub patch: Vec<u32>,
    /// Parameters (u, v) of each closest point.
    pub uv: Vec<[f64; 2]>,
    /// Distance of each closest point to its query.
    pub dist: Vec<f64>,
    /// The closest points, `dim` coordinates each, one point after the other.
    pub pos: Vec<f64>,
}

impl ClosestPoints {
    /// The patch of answer `k` as [`Hit::patch`](crate::Hit::patch) gives one: `None` where
    /// there is none (the `u32::MAX` of [`patch`](ClosestPoints::patch)), past the end, and for
    /// the closest points of one patch (since 1.2).
    ///
    /// ```
    /// use bezsurf::{Locator, Surface};
    ///
    /// let pot = Surface::builtin("teapot")?;
    /// let found = Locator::new(&pot)?.closest_points(&[4.0, 1.0, 2.0])?;
    /// assert!(found.patch_of(0).is_some_and(|p| (p as usize) < pot.len()));
    /// assert_eq!(found.patch_of(1), None);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn patch_of(&self, k: usize) -> Option<u32> {
        self.patch.get(k).copied().filter(|&p| p != u32::MAX)
    }
}

/// Splits `points` (n points of `dim` coordinates, one after the other) into `dim` strided
/// views, and makes room for the results.
pub(crate) fn closest_buffers(points: &[f64], dim: usize) -> Result<(Vec<sys::bs_cview>, ClosestPoints)> {
    if dim == 0 || points.len() % dim != 0 {
        return Err(Error::argument_error(
            sys::BS_ERR_SIZE,
            "points",
            format!("has {} values, not a multiple of the dimension {dim}", points.len()),
        ));
    }
    let n = points.len() / dim;
    let stride = (dim * std::mem::size_of::<f64>()) as isize;
    let q =
        (0..dim).map(|c| sys::bs_cview { data: points.as_ptr().wrapping_add(c), count: n, stride }).collect();
    let out = ClosestPoints {
        patch: Vec::new(),
        uv: vec![[0.0; 2]; n],
        dist: vec![0.0; n],
        pos: vec![0.0; n * dim],
    };
    Ok((q, out))
}

/// Views of the uv and pos outputs of [`ClosestPoints`] (interleaved, so strided).
pub(crate) fn closest_views(
    out: &mut ClosestPoints,
    dim: usize,
) -> (Vec<sys::bs_view>, sys::bs_view, Vec<sys::bs_view>) {
    let n = out.dist.len();
    let uv_base = out.uv.as_mut_ptr() as *mut f64;
    let pos_base = out.pos.as_mut_ptr();
    let uv_stride = (2 * std::mem::size_of::<f64>()) as isize;
    let pos_stride = (dim * std::mem::size_of::<f64>()) as isize;
    // Column c starts at element c of the first point (wrapping_add: for n = 0 the pointer is
    // never read).
    let uv =
        (0..2).map(|c| sys::bs_view { data: uv_base.wrapping_add(c), count: n, stride: uv_stride }).collect();
    let pos = (0..dim)
        .map(|c| sys::bs_view { data: pos_base.wrapping_add(c), count: n, stride: pos_stride })
        .collect();
    let dist = sys::bs_view { data: out.dist.as_mut_ptr(), count: n, stride: 0 };
    (uv, dist, pos)
}

impl PatchRef {
    /// The globally closest point of the patch to each query point (`bs_patch_closest_point`):
    /// within 1e-9 (D + d) of the exact distance d, boundary included. `points` holds n points
    /// of [`dim`](PatchRef::dim) coordinates one after the other (`Size` otherwise); NaN
    /// results where a query coordinate is not finite.
    ///
    /// ```
    /// use bezsurf::Patch;
    ///
    /// // The unit square in the plane z = 0; a point above it and one beyond a corner.
    /// let p = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0.])?;
    /// let c = p.closest_points(&[0.25, 0.5, 2.0, 3.0, 5.0, 0.0])?;
    /// assert!((c.dist[0] - 2.0).abs() < 1e-9 && (c.uv[0][0] - 0.25).abs() < 1e-9);
    /// assert!((c.dist[1] - 20f64.sqrt()).abs() < 1e-9 && (c.uv[1][0] - 1.0).abs() < 1e-9);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn closest_points(&self, points: &[f64]) -> Result<ClosestPoints> {
        let dim = self.dim();
        let (q, mut out) = closest_buffers(points, dim)?;
        let n = out.dist.len();
        let (uv, dist, pos) = closest_views(&mut out, dim);
        // SAFETY: the patch is live; q views n points of points; the output views cover
        // disjoint elements of out's vectors, each holding n entries.
        check(unsafe {
            sys::bs_patch_closest_point(self.as_ptr(), n, q.as_ptr(), uv.as_ptr(), &dist, pos.as_ptr())
        })?;
        Ok(out)
    }
}
