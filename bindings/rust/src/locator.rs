//! The locator (`bs_locator`, since 1.1): closest points and ray intersection over a surface.

use std::ptr::{self, NonNull};

use crate::error::{check, Error, Result};
use crate::query::{closest_buffers, closest_views, ClosestPoints};
use crate::surface::Surface;
use crate::sys;

/// An immutable acceleration structure (a bounding-volume hierarchy) over a surface, for
/// certified closest points and watertight ray intersection. It keeps its own copy of what it
/// needs, so the surface may change or be dropped afterwards; it is `Send + Sync` and any number
/// of threads may query it at once.
///
/// ```
/// use bezsurf::{Locator, Ray, Surface};
///
/// let pot = Surface::builtin("teapot")?;
/// let loc = Locator::new(&pot)?;
/// // A ray down the z axis from above meets the lid's knob; one pointing up misses.
/// let hits = loc.intersect(&[Ray::new([0., 0., 10.], [0., 0., -1.]), Ray::new([0., 0., 10.], [0., 0., 1.])])?;
/// assert!(hits[0].patch.is_some() && hits[0].t < 10.0);
/// assert_eq!(hits[1].patch, None);
/// let near = loc.closest_points(&[0.0, 0.0, 10.0])?;
/// assert!(near.dist[0] <= hits[0].t + 1e-9); // the hit is t away from the origin
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug)]
pub struct Locator {
    ptr: NonNull<sys::bs_locator>,
}

// SAFETY: a locator never changes after it is built and the library has no mutable global
// state, so it may be used and dropped from any thread.
unsafe impl Send for Locator {}
// SAFETY: every query takes `const bs_locator *` and only reads it; any number of threads may.
unsafe impl Sync for Locator {}

impl Drop for Locator {
    fn drop(&mut self) {
        // SAFETY: self owns the locator and is dropped once.
        unsafe { sys::bs_locator_destroy(self.ptr.as_ptr()) }
    }
}

/// A ray o + t d, t in [`t_min`, `t_max`], laid out as the library reads it (one strided view
/// per coordinate, no copy).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// Origin o.
    pub origin: [f64; 3],
    /// Direction d, any non-zero length.
    pub dir: [f64; 3],
    /// Smallest t accepted.
    pub t_min: f64,
    /// Largest t accepted: finite, or `f64::INFINITY` for no limit (since 1.2).
    pub t_max: f64,
}

impl Ray {
    /// The ray from `origin` along `dir` with t in [0, +inf) (`t_max` = `f64::INFINITY`: no
    /// limit, since 1.2; a NaN bound, an infinite `t_min` or a `t_max` of -inf makes the ray
    /// invalid, a miss with t NaN).
    pub fn new(origin: [f64; 3], dir: [f64; 3]) -> Ray {
        Ray { origin, dir, t_min: 0.0, t_max: f64::INFINITY }
    }
}

/// The first hit of a ray ([`Locator::intersect`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// The patch hit; `None` on a miss.
    pub patch: Option<u32>,
    /// Parameters of the hit (NaN on a miss).
    pub uv: [f64; 2],
    /// Ray parameter of the hit: +inf on a miss, NaN for an invalid ray (NaN/Inf or d = 0).
    pub t: f64,
    /// Unit normal at the hit (NaN on a miss).
    pub normal: [f64; 3],
}

impl Locator {
    /// Builds a locator over `surface` (`bs_locator_create`).
    pub fn new(surface: &Surface) -> Result<Locator> {
        let mut out = ptr::null_mut();
        // SAFETY: the surface is live; out is valid.
        check(unsafe { sys::bs_locator_create(surface.as_ptr(), &mut out) })?;
        let ptr = NonNull::new(out).expect("bezsurf returned a NULL locator on success");
        Ok(Locator { ptr })
    }

    /// Takes ownership of a locator the library made.
    pub(crate) fn from_raw(out: *mut sys::bs_locator) -> Locator {
        let ptr = NonNull::new(out).expect("bezsurf returned a NULL locator on success");
        Locator { ptr }
    }

    /// The C handle, valid while `self` is borrowed.
    pub fn as_ptr(&self) -> *const sys::bs_locator {
        self.ptr.as_ptr()
    }

    /// Dimension of the surface (0 for an empty one).
    pub fn dim(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_locator_dim(self.as_ptr()) }
    }

    /// The globally closest point of the whole surface to each query point
    /// (`bs_locator_closest_point`), within 1e-9 (D + d) of the exact distance d. `points` holds
    /// n points of [`dim`](Locator::dim) coordinates one after the other.
    pub fn closest_points(&self, points: &[f64]) -> Result<ClosestPoints> {
        self.closest_points_threads(points, 1)
    }

    /// [`Locator::closest_points`] on up to `threads` threads, the calling one included
    /// (`bs_locator_closest_point_mt`, since 1.1; 0: one per online CPU). The answers are the
    /// same bit for bit whatever the number of threads.
    pub fn closest_points_threads(&self, points: &[f64], threads: usize) -> Result<ClosestPoints> {
        let dim = self.dim();
        if dim == 0 {
            return Err(Error::argument_error(sys::BS_ERR_DIMENSION, "self", "the surface is empty"));
        }
        let (q, mut out) = closest_buffers(points, dim)?;
        let n = out.dist.len();
        let mut ids = vec![0u32; n];
        let (uv, dist, pos) = closest_views(&mut out, dim);
        // SAFETY: the locator is live; q views n points of points; ids holds n ids; the output
        // views cover disjoint elements of out's vectors, each holding n entries.
        check(unsafe {
            sys::bs_locator_closest_point_mt(
                self.as_ptr(),
                n,
                q.as_ptr(),
                ids.as_mut_ptr(),
                uv.as_ptr(),
                &dist,
                pos.as_ptr(),
                threads,
            )
        })?;
        out.patch = ids;
        Ok(out)
    }

    /// The first hit of each ray with the surface (`bs_locator_intersect`; 3-D surfaces, else
    /// `Dimension`). No transversal first hit is missed, including rays through shared edges,
    /// corners and poles.
    pub fn intersect(&self, rays: &[Ray]) -> Result<Vec<Hit>> {
        self.intersect_threads(rays, 1)
    }

    /// [`Locator::intersect`] on up to `threads` threads, the calling one included
    /// (`bs_locator_intersect_mt`, since 1.1; 0: one per online CPU). The hits are the same bit
    /// for bit whatever the number of threads.
    pub fn intersect_threads(&self, rays: &[Ray], threads: usize) -> Result<Vec<Hit>> {
        let n = rays.len();
        let stride = std::mem::size_of::<Ray>() as isize;
        let base = rays.as_ptr() as *const f64;
        // Field c of every ray: element c of the first (wrapping_add: never read for n = 0).
        let view = |c: usize| sys::bs_cview { data: base.wrapping_add(c), count: n, stride };
        let org = [view(0), view(1), view(2)];
        let dir = [view(3), view(4), view(5)];
        let range = [view(6), view(7)];
        let mut ids = vec![0u32; n];
        let mut vals = vec![0.0f64; 6 * n];
        let out = vals.as_mut_ptr();
        // Six packed columns of n values: u, v, t, normal x y z.
        let col = |c: usize| sys::bs_view { data: out.wrapping_add(c * n), count: n, stride: 0 };
        let uv = [col(0), col(1)];
        let t = col(2);
        let nrm = [col(3), col(4), col(5)];
        // SAFETY: the locator is live; the input views read the fields of the n rays (Ray is
        // repr(C), eight f64 in a row); ids holds n ids; the output views cover disjoint
        // columns of vals.
        check(unsafe {
            sys::bs_locator_intersect_mt(
                self.as_ptr(),
                n,
                org.as_ptr(),
                dir.as_ptr(),
                range.as_ptr(),
                ids.as_mut_ptr(),
                uv.as_ptr(),
                &t,
                nrm.as_ptr(),
                threads,
            )
        })?;
        Ok((0..n)
            .map(|k| {
                let at = |c: usize| vals[c * n + k];
                Hit {
                    patch: (ids[k] != u32::MAX).then_some(ids[k]),
                    uv: [at(0), at(1)],
                    t: at(2),
                    normal: [at(3), at(4), at(5)],
                }
            })
            .collect())
    }
}
