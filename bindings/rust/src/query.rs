//! Geometric queries on a patch (`bezsurf/query.h`, since 1.1): curvature.

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
