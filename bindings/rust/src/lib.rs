//! Safe Rust binding to libbezsurf, a C library for rectangular (tensor-product) Bezier surface
//! patches.
//!
//! The raw C API is in [`sys`]; the rest of the crate wraps it safely: owned handles that free
//! themselves ([`Patch`], [`Surface`], [`Mesh`]), failures as [`Error`], slices and strided views
//! ([`Strided`], [`StridedMut`], [`PointsMut`]) for buffers. Patches are evaluated with
//! [`PatchRef::eval`] and its siblings, changed into new patches by the exact operations
//! ([`PatchRef::split`], [`PatchRef::elevate`], ...); surfaces are read and written as `.bpt`
//! text, evaluated, checked for continuity and tessellated into meshes.
//!
//! ```
//! use bezsurf::Patch;
//!
//! // A biquadratic patch in 3-D: 3 x 3 control points, row i along u.
//! let net = [
//!     1.0, 0.0, 2.0,   1.0, 2.0, 4.0,   1.0, 3.0, 2.0,
//!     2.0, 1.0, 0.0,   2.0, 2.0, 2.0,   2.0, 4.0, 0.0,
//!     4.0, 1.0, 0.0,   3.0, 3.0, 2.0,   4.0, 4.0, 2.0,
//! ];
//! let patch = Patch::new(2, 2, 3, &net)?;
//! let mut pos = [0.0; 3];
//! patch.eval(&[0.5], &[0.5], &mut pos)?;
//! assert_eq!(pos, [17.0 / 8.0, 9.0 / 4.0, 13.0 / 8.0]);
//! # Ok::<(), bezsurf::Error>(())
//! ```
//!
//! Threads: patches and meshes are immutable and the library has no mutable global state, so
//! `Patch`, `&PatchRef`, `Surface`, `Mesh` and `Locator` are `Send + Sync` and may be used from any number
//! of threads at once (only `Surface::add` needs `&mut`). Lifetimes: a patch borrowed from a surface is a
//! `&PatchRef` that cannot outlive the surface.

#![deny(missing_docs)]
#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]

pub mod sys;

mod bspline;
mod continuity;
mod error;
mod eval;
mod float32;
mod io;
mod locator;
mod mesh;
mod model;
mod ops;
mod patch;
mod query;
mod strided;
mod surface;
mod surface_eval;

pub use bspline::BSpline;
pub use continuity::{Continuity, EdgeContinuity, OpenEdge, Side};
pub use error::{status_string, Error, ErrorKind, Result};
pub use eval::{NormalKind, Outputs};
pub use float32::GridF32;
pub use io::builtin_names;
pub use locator::{Hit, Locator, Ray};
pub use mesh::{Mesh, MeshFormat, TessFlags, TessMethod, TessOptions, TESS_MAX_RATE};
pub use model::{Face, FaceEval, FaceKind, FaceParams, Model, ModelLocator, PatchParams, Properties, Trim};
pub use ops::{Curve, Dir};
pub use patch::{Patch, PatchRef};
pub use query::{ClosestPoints, Curvature, CurvatureKind};
pub use strided::{PointsMut, Strided, StridedIter, StridedMut};
pub use surface::{Iter, Surface};

use std::ffi::CStr;

/// Largest degree per direction (`BS_MAX_DEGREE`).
pub const MAX_DEGREE: usize = sys::BS_MAX_DEGREE;
/// Largest dimension of a control point (`BS_MAX_DIM`).
pub const MAX_DIM: usize = sys::BS_MAX_DIM;
/// The major version of the C library this crate is written for.
pub const ABI_MAJOR: u32 = 1;

/// Run-time library version number, major*10000 + minor*100 + patch (`bs_version_number`).
pub fn version_number() -> u32 {
    // SAFETY: no arguments, no state.
    unsafe { sys::bs_version_number() }
}

/// Run-time library version as "MAJOR.MINOR.PATCH" (`bs_version_string`).
///
/// ```
/// let (major, minor, patch) = bezsurf::version();
/// assert_eq!(major, bezsurf::ABI_MAJOR);
/// assert_eq!(bezsurf::version_string(), format!("{major}.{minor}.{patch}"));
/// ```
pub fn version_string() -> &'static str {
    // SAFETY: returns a static NUL-terminated ASCII string, never NULL.
    unsafe { CStr::from_ptr(sys::bs_version_string()) }.to_str().unwrap_or("")
}

/// Run-time library version as (major, minor, patch).
pub fn version() -> (u32, u32, u32) {
    let n = version_number();
    (n / 10000, n / 100 % 100, n % 100)
}
