//! Triangle meshes made by tessellating a surface, their read-back and export.

use std::ffi::c_void;
use std::ops::BitOr;
use std::path::Path;
use std::ptr::{self, NonNull};
use std::sync::Arc;

use crate::error::{check, Error, ErrorKind, Result};
use crate::io::c_path;
use crate::strided::PointsMut;
use crate::surface::Surface;
use crate::sys;

/// Tessellation flags (`BS_TESS_*`), combined with `|`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct TessFlags(i32);

impl TessFlags {
    /// No flag.
    pub const NONE: TessFlags = TessFlags(0);
    /// The adaptive tolerance is a fraction of the control-net bounding-box diagonal
    /// (`BS_TESS_RELATIVE`).
    pub const RELATIVE: TessFlags = TessFlags(sys::BS_TESS_RELATIVE);
    /// Also build triangle strips (`BS_TESS_STRIPS`).
    pub const STRIPS: TessFlags = TessFlags(sys::BS_TESS_STRIPS);
    /// Face the mesh the other way: every triangle's winding reversed and every normal negated
    /// (`BS_TESS_REVERSE`, since 1.2). The built-in teapot's patches face into the pot; with
    /// this flag its mesh faces outwards.
    pub const REVERSE: TessFlags = TessFlags(sys::BS_TESS_REVERSE);

    /// The C flag bits.
    pub fn bits(self) -> i32 {
        self.0
    }
}

impl From<TessFlags> for i32 {
    /// The C flag bits, as [`TessFlags::bits`].
    fn from(f: TessFlags) -> i32 {
        f.0
    }
}

impl std::ops::BitOrAssign for TessFlags {
    fn bitor_assign(&mut self, rhs: TessFlags) {
        self.0 |= rhs.0;
    }
}

impl BitOr for TessFlags {
    type Output = TessFlags;
    fn bitor(self, rhs: TessFlags) -> TessFlags {
        TessFlags(self.0 | rhs.0)
    }
}

/// How [`Surface::tessellate`] meshes each patch (`BS_TESS_*` methods, since 1.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TessMethod {
    /// `nu` x `nv` segments per patch, as [`Surface::tessellate_uniform`].
    Uniform {
        /// Segments along u per patch.
        nu: usize,
        /// Segments along v per patch.
        nv: usize,
    },
    /// One segment count per patch and direction from a curvature bound, as
    /// [`Surface::tessellate_adaptive`], within the options' tolerance.
    PerPatch,
    /// A quadtree of sub-patches per patch, refined only where the surface curves, within the
    /// options' tolerance.
    Subdivide,
}

/// Options of [`Surface::tessellate`] and [`Surface::tessellate_count`] (`bs_tess_options`).
///
/// ```
/// use bezsurf::{Surface, TessMethod, TessOptions};
///
/// let pot = Surface::builtin("teapot")?;
/// let opts = TessOptions::new(TessMethod::Uniform { nu: 8, nv: 8 });
/// let (vertices, triangles) = pot.tessellate_count(&opts)?;
/// let mesh = pot.tessellate(&opts.max_vertices(vertices))?;
/// assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (vertices, triangles));
/// assert!(pot.tessellate(&opts.max_vertices(vertices - 1)).is_err());
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TessOptions {
    method: TessMethod,
    flags: TessFlags,
    tolerance: f64,
    max_vertices: usize,
    max_triangles: usize,
    threads: usize,
}

impl TessOptions {
    /// Options for `method` with no flags, tolerance 1e-3 and no budget.
    pub fn new(method: TessMethod) -> TessOptions {
        TessOptions {
            method,
            flags: TessFlags::NONE,
            tolerance: 1e-3,
            max_vertices: 0,
            max_triangles: 0,
            threads: 1,
        }
    }

    /// The tolerance of the adaptive methods (with [`TessFlags::RELATIVE`], a fraction of the
    /// control points' bounding-box diagonal).
    pub fn tolerance(mut self, tolerance: f64) -> TessOptions {
        self.tolerance = tolerance;
        self
    }

    /// [`TessFlags::RELATIVE`], [`TessFlags::STRIPS`] and/or [`TessFlags::REVERSE`].
    pub fn flags(mut self, flags: TessFlags) -> TessOptions {
        self.flags = flags;
        self
    }

    /// A budget: a mesh with more vertices is `Size`, refused before anything large is
    /// allocated (0: only the 32-bit index limit).
    pub fn max_vertices(mut self, n: usize) -> TessOptions {
        self.max_vertices = n;
        self
    }

    /// A budget on triangles, as [`TessOptions::max_vertices`].
    pub fn max_triangles(mut self, n: usize) -> TessOptions {
        self.max_triangles = n;
        self
    }

    /// Threads sampling the vertices, the calling one included (default 1, none started; 0: one
    /// per online CPU). The mesh is the same bit for bit whatever their number.
    pub fn threads(mut self, n: usize) -> TessOptions {
        self.threads = n;
        self
    }

    pub(crate) fn raw(&self) -> sys::bs_tess_options {
        let mut o = std::mem::MaybeUninit::<sys::bs_tess_options>::uninit();
        // SAFETY: the library fills every field of the struct it is given.
        let mut o = unsafe {
            sys::bs_tess_options_init(o.as_mut_ptr());
            o.assume_init()
        };
        match self.method {
            TessMethod::Uniform { nu, nv } => {
                o.method = sys::BS_TESS_UNIFORM;
                o.nu = nu;
                o.nv = nv;
            }
            TessMethod::PerPatch => o.method = sys::BS_TESS_PER_PATCH,
            TessMethod::Subdivide => o.method = sys::BS_TESS_SUBDIVIDE,
        }
        o.flags = self.flags.0;
        o.tolerance = self.tolerance;
        o.max_vertices = self.max_vertices;
        o.max_triangles = self.max_triangles;
        o.threads = self.threads;
        o
    }
}

/// Largest number of segments per patch and direction (`BS_TESS_MAX_RATE`).
pub const TESS_MAX_RATE: usize = sys::BS_TESS_MAX_RATE;

/// A mesh file format (`BS_MESH_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// Wavefront OBJ with positions, parameters and normals (`BS_MESH_OBJ`).
    Obj,
    /// Binary little-endian PLY (`BS_MESH_PLY`).
    Ply,
    /// ASCII PLY (`BS_MESH_PLY_ASCII`).
    PlyAscii,
    /// Binary STL (`BS_MESH_STL`).
    Stl,
}

impl From<MeshFormat> for i32 {
    /// The C constant (`BS_MESH_*`).
    fn from(f: MeshFormat) -> i32 {
        f.raw()
    }
}

impl MeshFormat {
    /// The format a file name's extension names, as `bezsurf tessellate` reads it: `.obj`,
    /// `.ply` (binary) or `.stl`, in any case. Another extension, or none, is an `InvalidArg`
    /// error naming the path.
    ///
    /// ```
    /// use bezsurf::MeshFormat;
    ///
    /// assert_eq!(MeshFormat::from_path("pot.PLY")?, MeshFormat::Ply);
    /// assert!(MeshFormat::from_path("pot.txt").is_err());
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn from_path(path: impl AsRef<Path>) -> Result<MeshFormat> {
        let path = path.as_ref();
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("obj") => Ok(MeshFormat::Obj),
            Some("ply") => Ok(MeshFormat::Ply),
            Some("stl") => Ok(MeshFormat::Stl),
            _ => Err(Error::argument_error(
                sys::BS_ERR_INVALID_ARG,
                "path",
                format!(
                    "{}: unknown mesh extension {}; use .obj, .ply or .stl, or Mesh::write with a MeshFormat",
                    path.display(),
                    ext.map_or_else(|| "(none)".to_string(), |e| format!(".{e}"))
                ),
            )),
        }
    }

    fn raw(self) -> i32 {
        match self {
            MeshFormat::Obj => sys::BS_MESH_OBJ,
            MeshFormat::Ply => sys::BS_MESH_PLY,
            MeshFormat::PlyAscii => sys::BS_MESH_PLY_ASCII,
            MeshFormat::Stl => sys::BS_MESH_STL,
        }
    }
}

/// An immutable triangle mesh (`bs_mesh *`), released with `bs_mesh_destroy` when its last
/// clone is dropped. It is independent of the surface it was made from.
///
/// A mesh never changes after it is made, so `Clone` shares it (a reference count, no copy):
/// a clone is indistinguishable from a copy.
///
/// ```
/// use bezsurf::{Surface, TessFlags};
///
/// let cup = Surface::builtin("teacup")?;
/// let mesh = cup.tessellate_uniform(4, 4, TessFlags::NONE)?;
/// assert_eq!(mesh.triangle_count(), cup.len() * 4 * 4 * 2);
/// let tris = mesh.triangles();
/// assert!(tris.iter().all(|&i| (i as usize) < mesh.vertex_count()));
/// let shared = mesh.clone();
/// assert_eq!(shared.positions(), mesh.positions());
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Clone)]
pub struct Mesh {
    handle: Arc<MeshHandle>,
}

/// The owned C handle behind every clone of a [`Mesh`].
struct MeshHandle {
    ptr: NonNull<sys::bs_mesh>,
}

// SAFETY: a mesh never changes after it is made (every accessor takes `const bs_mesh *`) and the
// library has no mutable global state, so the handle may be used and destroyed from any thread.
unsafe impl Send for MeshHandle {}
// SAFETY: as for Send: every use through a shared reference only reads the mesh, which any
// number of threads may do at once.
unsafe impl Sync for MeshHandle {}

impl Drop for MeshHandle {
    fn drop(&mut self) {
        // SAFETY: the handle owns the mesh and is dropped once, after the last Mesh sharing it.
        unsafe { sys::bs_mesh_destroy(self.ptr.as_ptr()) }
    }
}

impl std::fmt::Debug for Mesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Mesh")
            .field("vertices", &self.vertex_count())
            .field("triangles", &self.triangle_count())
            .field("strips", &self.strip_count())
            .finish()
    }
}

pub(crate) fn new_mesh(f: impl FnOnce(*mut *mut sys::bs_mesh) -> sys::bs_status) -> Result<Mesh> {
    let mut out = ptr::null_mut();
    check(f(&mut out))?;
    let ptr = NonNull::new(out).expect("bezsurf returned a NULL mesh on success");
    Ok(Mesh { handle: Arc::new(MeshHandle { ptr }) })
}

impl Surface {
    /// Tessellates a 3-D surface with `nu` x `nv` segments per patch
    /// (`bs_surface_tessellate_uniform`), crack-free across shared sides. `flags` may hold
    /// [`TessFlags::STRIPS`]. Errors: `Domain` (a rate 0 or above [`TESS_MAX_RATE`]),
    /// `Dimension` (not 3-D), `InvalidArg` (unknown flags).
    pub fn tessellate_uniform(&self, nu: usize, nv: usize, flags: TessFlags) -> Result<Mesh> {
        // SAFETY: self is live; out is valid.
        new_mesh(|out| unsafe { sys::bs_surface_tessellate_uniform(self.as_ptr(), nu, nv, flags.0, out) })
            .map_err(|e| self.explain_tess(e, &TessOptions::new(TessMethod::Uniform { nu, nv }).flags(flags)))
    }

    /// Tessellates a 3-D surface so that every triangle lies within `tolerance` of the surface
    /// (`bs_surface_tessellate_adaptive`); with [`TessFlags::RELATIVE`] the tolerance is a
    /// fraction of the control-net bounding-box diagonal. `Domain` if the tolerance is not finite
    /// and positive.
    ///
    /// ```
    /// use bezsurf::{MeshFormat, Surface, TessFlags};
    ///
    /// let spoon = Surface::builtin("teaspoon")?;
    /// let coarse = spoon.tessellate_adaptive(0.01, TessFlags::RELATIVE)?;
    /// let fine = spoon.tessellate_adaptive(0.001, TessFlags::RELATIVE)?;
    /// assert!(fine.triangle_count() > coarse.triangle_count());
    /// let stl = fine.to_bytes(MeshFormat::Stl)?;
    /// assert_eq!(stl.len(), 84 + 50 * fine.triangle_count());
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn tessellate_adaptive(&self, tolerance: f64, flags: TessFlags) -> Result<Mesh> {
        // SAFETY: self is live; out is valid.
        new_mesh(|out| unsafe { sys::bs_surface_tessellate_adaptive(self.as_ptr(), tolerance, flags.0, out) })
            .map_err(|e| {
                self.explain_tess(
                    e,
                    &TessOptions::new(TessMethod::PerPatch).tolerance(tolerance).flags(flags),
                )
            })
    }

    /// A tessellator's error naming the argument, its value and the limit it broke.
    fn explain_tess(&self, e: Error, o: &TessOptions) -> Error {
        match (e.kind(), o.method) {
            (ErrorKind::Domain, TessMethod::Uniform { nu, nv }) => {
                match [("nu", nu), ("nv", nv)].into_iter().find(|&(_, r)| r == 0 || r > TESS_MAX_RATE) {
                    Some((name, rate)) => e.with_argument(
                        name,
                        format!(
                            "is {rate} segments per patch, outside 1..={TESS_MAX_RATE} (BS_TESS_MAX_RATE)"
                        ),
                    ),
                    None => e,
                }
            }
            (ErrorKind::Domain, _) => {
                e.with_argument("tolerance", format!("is {}; it must be finite and > 0", o.tolerance))
            }
            (ErrorKind::Size, _) => {
                let unlimited = TessOptions { max_vertices: 0, max_triangles: 0, ..*o };
                let Ok((nv, nt)) = self.tessellate_count(&unlimited) else { return e };
                let (name, over) = if o.max_vertices != 0 && nv > o.max_vertices {
                    ("max_vertices", format!("the budget of {} vertices", o.max_vertices))
                } else if o.max_triangles != 0 && nt > o.max_triangles {
                    ("max_triangles", format!("the budget of {} triangles", o.max_triangles))
                } else {
                    (
                        "options",
                        "the 32-bit index limit (4294967294 vertices, 1431655765 triangles)".to_string(),
                    )
                };
                e.with_argument(
                    name,
                    format!("is exceeded: the mesh would have {nv} vertices and {nt} triangles, over {over}"),
                )
            }
            _ => e,
        }
    }
}

impl Surface {
    /// Tessellates a 3-D surface as `options` say (`bs_surface_tessellate`, since 1.1). Errors as
    /// the other tessellators, and `Size` when the mesh would exceed a budget of the options.
    pub fn tessellate(&self, options: &TessOptions) -> Result<Mesh> {
        let o = options.raw();
        // SAFETY: self is live; o is a filled options struct; out is valid.
        new_mesh(|out| unsafe { sys::bs_surface_tessellate(self.as_ptr(), &o, out) })
            .map_err(|e| self.explain_tess(e, options))
    }

    /// The (vertices, triangles) [`Surface::tessellate`] would give with `options`, computed
    /// without building the mesh (`bs_surface_tessellate_count`; budgets give no error, but with
    /// the subdivision method counting stops past one and the counts are then lower bounds over it).
    pub fn tessellate_count(&self, options: &TessOptions) -> Result<(usize, usize)> {
        let o = options.raw();
        let (mut nv, mut nt) = (0usize, 0usize);
        // SAFETY: self is live; o is a filled options struct; both outputs are valid.
        check(unsafe { sys::bs_surface_tessellate_count(self.as_ptr(), &o, &mut nv, &mut nt) })
            .map_err(|e| if e.kind() == ErrorKind::Domain { self.explain_tess(e, options) } else { e })?;
        Ok((nv, nt))
    }
}

impl Mesh {
    /// The C handle, valid while `self` is borrowed.
    pub fn as_ptr(&self) -> *const sys::bs_mesh {
        self.handle.ptr.as_ptr()
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_mesh_vertex_count(self.as_ptr()) }
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_mesh_triangle_count(self.as_ptr()) }
    }

    /// Number of triangle strips (0 unless made with [`TessFlags::STRIPS`]).
    pub fn strip_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_mesh_strip_count(self.as_ptr()) }
    }

    /// Total number of indices in all strips.
    pub fn strip_index_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_mesh_strip_index_count(self.as_ptr()) }
    }

    fn copy_views(
        &self,
        out: PointsMut<'_>,
        dim: usize,
        needed: usize,
        f: unsafe extern "C" fn(*const sys::bs_mesh, *const sys::bs_view) -> sys::bs_status,
    ) -> Result<()> {
        let mut out = out;
        let views = out.c_views(dim, "out")?;
        // SAFETY: the views stay inside the slices they were built from and do not overlap.
        check(unsafe { f(self.as_ptr(), views.as_ptr()) }).map_err(|e| {
            let cap = out.capacity(dim);
            if e.kind() == ErrorKind::Size && cap < needed {
                e.with_argument("out", crate::error::no_room(cap, needed, "point"))
            } else {
                e
            }
        })
    }

    /// Copies the vertex positions (3 coordinates per vertex) (`bs_mesh_copy_positions`).
    pub fn copy_positions<'a>(&self, out: impl Into<PointsMut<'a>>) -> Result<()> {
        self.copy_views(out.into(), 3, self.vertex_count(), sys::bs_mesh_copy_positions)
    }

    /// Copies the unit vertex normals (3 per vertex) (`bs_mesh_copy_normals`).
    pub fn copy_normals<'a>(&self, out: impl Into<PointsMut<'a>>) -> Result<()> {
        self.copy_views(out.into(), 3, self.vertex_count(), sys::bs_mesh_copy_normals)
    }

    /// Copies the vertex (u, v) parameters (2 per vertex) (`bs_mesh_copy_uv`).
    pub fn copy_uv<'a>(&self, out: impl Into<PointsMut<'a>>) -> Result<()> {
        self.copy_views(out.into(), 2, self.vertex_count(), sys::bs_mesh_copy_uv)
    }

    /// Copies the (u, v) of every triangle corner on the triangle's own patch (2 per corner, 3
    /// corners per triangle) (`bs_mesh_copy_corner_uv`).
    pub fn copy_corner_uv<'a>(&self, out: impl Into<PointsMut<'a>>) -> Result<()> {
        self.copy_views(out.into(), 2, 3 * self.triangle_count(), sys::bs_mesh_copy_corner_uv)
    }

    /// Positions as a new interleaved vector, x y z per vertex.
    pub fn positions(&self) -> Vec<f64> {
        let mut v = vec![0.0; 3 * self.vertex_count()];
        self.copy_positions(&mut v).expect("bs_mesh_copy_positions");
        v
    }

    /// Unit normals as a new interleaved vector, 3 per vertex.
    pub fn normals(&self) -> Vec<f64> {
        let mut v = vec![0.0; 3 * self.vertex_count()];
        self.copy_normals(&mut v).expect("bs_mesh_copy_normals");
        v
    }

    /// Vertex parameters as a new interleaved vector, u v per vertex.
    pub fn uv(&self) -> Vec<f64> {
        let mut v = vec![0.0; 2 * self.vertex_count()];
        self.copy_uv(&mut v).expect("bs_mesh_copy_uv");
        v
    }

    /// Corner parameters as a new interleaved vector, u v per corner.
    pub fn corner_uv(&self) -> Vec<f64> {
        let mut v = vec![0.0; 6 * self.triangle_count()];
        self.copy_corner_uv(&mut v).expect("bs_mesh_copy_corner_uv");
        v
    }

    /// Copies the per-vertex patch ids (`bs_mesh_copy_patch_ids`); `Size` if `ids` is shorter
    /// than the vertex count.
    pub fn copy_patch_ids(&self, ids: &mut [u32]) -> Result<()> {
        // SAFETY: ids holds ids.len() values.
        check(unsafe { sys::bs_mesh_copy_patch_ids(self.as_ptr(), ids.as_mut_ptr(), ids.len()) })
    }

    /// Copies the triangles, 3 vertex indices each, counter-clockwise seen from the normals'
    /// side (`bs_mesh_copy_triangles`).
    pub fn copy_triangles(&self, idx: &mut [u32]) -> Result<()> {
        // SAFETY: idx holds idx.len() values.
        check(unsafe { sys::bs_mesh_copy_triangles(self.as_ptr(), idx.as_mut_ptr(), idx.len()) })
    }

    /// Copies the per-triangle patch ids (`bs_mesh_copy_triangle_patch_ids`).
    pub fn copy_triangle_patch_ids(&self, ids: &mut [u32]) -> Result<()> {
        // SAFETY: ids holds ids.len() values.
        check(unsafe { sys::bs_mesh_copy_triangle_patch_ids(self.as_ptr(), ids.as_mut_ptr(), ids.len()) })
    }

    /// Per-vertex patch ids as a new vector.
    pub fn patch_ids(&self) -> Vec<u32> {
        let mut v = vec![0; self.vertex_count()];
        self.copy_patch_ids(&mut v).expect("bs_mesh_copy_patch_ids");
        v
    }

    /// Triangle indices as a new vector, 3 per triangle.
    pub fn triangles(&self) -> Vec<u32> {
        let mut v = vec![0; 3 * self.triangle_count()];
        self.copy_triangles(&mut v).expect("bs_mesh_copy_triangles");
        v
    }

    /// Per-triangle patch ids as a new vector.
    pub fn triangle_patch_ids(&self) -> Vec<u32> {
        let mut v = vec![0; self.triangle_count()];
        self.copy_triangle_patch_ids(&mut v).expect("bs_mesh_copy_triangle_patch_ids");
        v
    }

    /// Copies the triangle strips (`bs_mesh_copy_strips`): strip k is
    /// `idx[start[k] as usize..start[k + 1] as usize]`, its triangle i being (`s[i]`, `s[i+1]`, `s[i+2]`)
    /// for even i and (`s[i+1]`, `s[i]`, `s[i+2]`) for odd i; triangles with a repeated index are
    /// degenerate (at poles) and to be dropped.
    pub fn copy_strips(&self, idx: &mut [u32], start: &mut [u32]) -> Result<()> {
        // SAFETY: each slice holds the capacity passed with it.
        check(unsafe {
            sys::bs_mesh_copy_strips(
                self.as_ptr(),
                idx.as_mut_ptr(),
                idx.len(),
                start.as_mut_ptr(),
                start.len(),
            )
        })
    }

    /// The strips as new vectors (indices, starts); see [`copy_strips`](Mesh::copy_strips).
    pub fn strips(&self) -> (Vec<u32>, Vec<u32>) {
        let mut idx = vec![0; self.strip_index_count()];
        let mut start = vec![0; self.strip_count() + 1];
        self.copy_strips(&mut idx, &mut start).expect("bs_mesh_copy_strips");
        (idx, start)
    }

    /// Writes the mesh to a file (`bs_mesh_write`); `Io` on failure.
    pub fn write(&self, format: MeshFormat, path: impl AsRef<Path>) -> Result<()> {
        let path = path.as_ref();
        let cpath = c_path(path)?;
        // SAFETY: cpath is NUL-terminated.
        check(unsafe { sys::bs_mesh_write(self.as_ptr(), format.raw(), cpath.as_ptr()) })
            .map_err(|e| e.with_path(path))
    }

    /// Writes the mesh to a file in the format its extension names ([`MeshFormat::from_path`]:
    /// `.obj`, `.ply`, `.stl`); an unknown extension is `InvalidArg` and nothing is written.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<()> {
        let format = MeshFormat::from_path(path.as_ref())?;
        self.write(format, path)
    }

    /// The bytes [`write`](Mesh::write) would put in a file (`bs_mesh_write_memory`).
    pub fn to_bytes(&self, format: MeshFormat) -> Result<Vec<u8>> {
        let mut size = 0usize;
        // SAFETY: a NULL buffer asks for the size only.
        check(unsafe {
            sys::bs_mesh_write_memory(self.as_ptr(), format.raw(), ptr::null_mut(), 0, &mut size)
        })?;
        let mut buf = vec![0u8; size];
        // SAFETY: buf holds size bytes.
        check(unsafe {
            sys::bs_mesh_write_memory(
                self.as_ptr(),
                format.raw(),
                buf.as_mut_ptr() as *mut c_void,
                size,
                &mut size,
            )
        })?;
        if size > buf.len() {
            return Err(Error::from_code(sys::BS_ERR_SIZE));
        }
        buf.truncate(size);
        Ok(buf)
    }
}
