//! How the patches of a surface meet: shared and open edges, continuity across shared ones.

use std::ptr;

use crate::error::{check, Result};
use crate::surface::Surface;
use crate::sys;

/// A side of a patch's unit square (`BS_SIDE_*`), counter-clockwise from v = 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// v = 0; the edge parameter runs along u.
    V0,
    /// u = 1; the edge parameter runs along v.
    U1,
    /// v = 1; the edge parameter runs along u.
    V1,
    /// u = 0; the edge parameter runs along v.
    U0,
}

impl Side {
    /// The side for a `BS_SIDE_*` value, `None` for any other value.
    pub fn from_raw(raw: i32) -> Option<Side> {
        match raw {
            sys::BS_SIDE_V0 => Some(Side::V0),
            sys::BS_SIDE_U1 => Some(Side::U1),
            sys::BS_SIDE_V1 => Some(Side::V1),
            sys::BS_SIDE_U0 => Some(Side::U0),
            _ => None,
        }
    }

    fn from_library(raw: i32) -> Side {
        Side::from_raw(raw).unwrap_or_else(|| panic!("bs_surface_continuity reported side {raw}"))
    }
}

impl From<Side> for i32 {
    /// The C constant (`BS_SIDE_*`).
    fn from(side: Side) -> i32 {
        match side {
            Side::V0 => sys::BS_SIDE_V0,
            Side::U1 => sys::BS_SIDE_U1,
            Side::V1 => sys::BS_SIDE_V1,
            Side::U0 => sys::BS_SIDE_U0,
        }
    }
}

impl TryFrom<i32> for Side {
    type Error = crate::Error;
    /// The side for a `BS_SIDE_*` value; any other value is `InvalidArg`.
    fn try_from(raw: i32) -> Result<Side> {
        Side::from_raw(raw).ok_or_else(|| {
            crate::Error::argument_error(
                sys::BS_ERR_INVALID_ARG,
                "raw",
                format!("is {raw}, not a BS_SIDE_ value"),
            )
        })
    }
}

/// How two patches meet along one shared edge (`bs_edge_continuity`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeContinuity {
    /// The patch with the lower id (or the same patch, lower side).
    pub patch_a: u32,
    /// The neighbour.
    pub patch_b: u32,
    /// The shared side of `patch_a`.
    pub side_a: Side,
    /// The shared side of `patch_b`.
    pub side_b: Side,
    /// True if the edge parameter on `side_b` runs opposite to the one on `side_a`.
    pub reversed: bool,
    /// True if the cross-boundary derivatives are equal and opposite within the tolerance
    /// (always false when either patch is rational).
    pub c1: bool,
    /// True if the two patches' normals point to opposite sides (at most samples).
    pub flipped: bool,
    /// Number of samples at which both normals exist.
    pub samples: usize,
    /// Largest distance between corresponding boundary control points.
    pub c0_gap: f64,
    /// Largest angle in radians between the two tangent planes, sampled.
    pub g1_angle: f64,
    /// Largest |D_a + D_b| over the edge's cross-boundary derivative nets; NaN for rational
    /// patches.
    pub c1_defect: f64,
}

/// A side of a patch that no other patch shares (`bs_open_edge`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct OpenEdge {
    /// The patch id.
    pub patch: u32,
    /// Its unshared side.
    pub side: Side,
}

/// The continuity report of a surface: every shared edge and every open edge.
#[derive(Debug, Clone, PartialEq)]
pub struct Continuity {
    /// Shared edges in order of (patch_a, side_a).
    pub edges: Vec<EdgeContinuity>,
    /// Open edges in patch and side order.
    pub open: Vec<OpenEdge>,
}

impl Surface {
    /// Finds the shared and open edges of a 3-D surface and measures the continuity across each
    /// shared edge (`bs_surface_continuity`). `tol` (finite, >= 0) is the absolute tolerance for
    /// matching sides and for C1; `samples` (1..=4096) normal samples per edge measure G1.
    /// Errors: `Dimension` (not 3-D), `Domain` (tol or samples out of range).
    ///
    /// ```
    /// let cup = bezsurf::Surface::builtin("teacup")?;
    /// let report = cup.continuity(1e-6, 16)?;
    /// assert!(!report.edges.is_empty());
    /// assert!(report.edges.iter().all(|e| e.c0_gap <= 1e-6 && e.patch_a <= e.patch_b));
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn continuity(&self, tol: f64, samples: usize) -> Result<Continuity> {
        let (mut n_edges, mut n_open) = (0usize, 0usize);
        // SAFETY: NULL arrays ask for the counts only.
        check(unsafe {
            sys::bs_surface_continuity(
                self.as_ptr(),
                tol,
                samples,
                ptr::null_mut(),
                0,
                &mut n_edges,
                ptr::null_mut(),
                0,
                &mut n_open,
            )
        })?;
        let blank_edge = sys::bs_edge_continuity {
            patch_a: 0,
            patch_b: 0,
            side_a: 0,
            side_b: 0,
            reversed: 0,
            c1: 0,
            flipped: 0,
            samples: 0,
            c0_gap: 0.0,
            g1_angle: 0.0,
            c1_defect: 0.0,
        };
        let mut edges = vec![blank_edge; n_edges];
        let mut open = vec![sys::bs_open_edge { patch: 0, side: 0 }; n_open];
        // SAFETY: the arrays hold the capacities passed with them; `&self` keeps the surface
        // unchanged between the two calls, so the counts still hold.
        check(unsafe {
            sys::bs_surface_continuity(
                self.as_ptr(),
                tol,
                samples,
                edges.as_mut_ptr(),
                edges.len(),
                &mut n_edges,
                open.as_mut_ptr(),
                open.len(),
                &mut n_open,
            )
        })?;
        edges.truncate(n_edges);
        open.truncate(n_open);
        Ok(Continuity {
            edges: edges
                .iter()
                .map(|e| EdgeContinuity {
                    patch_a: e.patch_a,
                    patch_b: e.patch_b,
                    side_a: Side::from_library(e.side_a),
                    side_b: Side::from_library(e.side_b),
                    reversed: e.reversed != 0,
                    c1: e.c1 != 0,
                    flipped: e.flipped != 0,
                    samples: usize::try_from(e.samples).unwrap_or(0),
                    c0_gap: e.c0_gap,
                    g1_angle: e.g1_angle,
                    c1_defect: e.c1_defect,
                })
                .collect(),
            open: open
                .iter()
                .map(|o| OpenEdge { patch: o.patch, side: Side::from_library(o.side) })
                .collect(),
        })
    }
}
