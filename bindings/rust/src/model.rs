//! Trimmed B-rep models (`bs_model`, since 1.2): faces over exact patches bounded by trim loops,
//! joined along edges into shells, read from STEP, IGES and OBJ files.

use std::mem::size_of;
use std::os::raw::c_char;
use std::path::Path;
use std::ptr::{self, NonNull};

use crate::error::{check, Error, Result};
use crate::eval::NormalKind;
use crate::io::c_path;
use crate::locator::Locator;
use crate::mesh::{new_mesh, Mesh, TessOptions};
use crate::surface::Surface;
use crate::sys;

/// The surface a face lies on (`BS_FACE_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FaceKind {
    /// Bezier patches of the library.
    Bezier,
    /// A B-spline or NURBS surface.
    BSpline,
    /// A plane.
    Plane,
    /// A circular cylinder.
    Cylinder,
    /// A circular cone.
    Cone,
    /// A sphere.
    Sphere,
    /// A torus.
    Torus,
    /// A curve revolved about an axis.
    Revolution,
    /// A curve swept along a vector.
    Extrusion,
}

impl FaceKind {
    fn from_c(kind: i32) -> Option<FaceKind> {
        const KINDS: [FaceKind; 9] = [
            FaceKind::Bezier,
            FaceKind::BSpline,
            FaceKind::Plane,
            FaceKind::Cylinder,
            FaceKind::Cone,
            FaceKind::Sphere,
            FaceKind::Torus,
            FaceKind::Revolution,
            FaceKind::Extrusion,
        ];
        usize::try_from(kind).ok().and_then(|k| KINDS.get(k).copied())
    }
}

/// One face of a model ([`Model::face`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Face {
    /// Its surface's kind.
    pub kind: FaceKind,
    /// Its outward side is opposite its surface normal.
    pub reversed: bool,
    /// Its shell.
    pub shell: usize,
    /// Its assembly placement (0 without assemblies).
    pub instance: usize,
    /// Its patches in [`Model::surface`]: `first_patch .. first_patch + patch_count`.
    pub first_patch: usize,
    /// Number of its patches.
    pub patch_count: usize,
    /// Trim loops, the outer first (0: untrimmed).
    pub loop_count: usize,
    /// Native parameter box (u0, u1, v0, v1).
    pub bounds: [f64; 4],
}

/// Where a point lies with respect to a trimmed face ([`Model::classify`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Trim {
    /// Outside the face (`BS_TRIM_OUTSIDE`).
    Outside,
    /// Inside, farther than the tolerance from the boundary (`BS_TRIM_INSIDE`).
    Inside,
    /// Within the tolerance of the boundary (`BS_TRIM_ON`).
    On,
}

/// Area, enclosed volume and centroid of [`Model::properties`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Properties {
    /// Total area of the faces.
    pub area: f64,
    /// Volume enclosed by the closed shells (NaN when no shell is closed).
    pub volume: f64,
    /// Centroid of that volume (of the area when no shell is closed).
    pub centroid: [f64; 3],
}

/// Positions, outward unit normals and normal kinds of [`Model::face_eval`], one per point.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceEval {
    /// Positions (NaN outside a face's patches).
    pub pos: Vec<[f64; 3]>,
    /// Outward unit normals.
    pub normal: Vec<[f64; 3]>,
    /// The kind of each normal.
    pub kind: Vec<NormalKind>,
}

/// Patch ids (`None` outside a face) and local (s, t) of [`Model::face_to_patch`].
pub type PatchParams = (Vec<Option<u32>>, Vec<[f64; 2]>);

/// Face ids (`None` for (s, t) outside [0, 1]) and native (u, v) of [`Model::patch_to_face`].
pub type FaceParams = (Vec<Option<u32>>, Vec<[f64; 2]>);

/// A trimmed B-rep model: faces joined along edges into shells. Immutable, `Send + Sync`.
///
/// ```
/// use bezsurf::{Model, Surface};
///
/// let pot = Surface::builtin("teapot")?;
/// let model = Model::from_surface(&pot)?;
/// assert_eq!(model.face_count(), 32);
/// let face = model.face(0)?;
/// assert_eq!(face.bounds, [0.0, 1.0, 0.0, 1.0]);
/// let ev = model.face_eval(&[0], &[0.5], &[0.5])?;
/// assert!(ev.pos[0][2] > 0.0);
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug)]
pub struct Model {
    ptr: NonNull<sys::bs_model>,
}

// SAFETY: a model never changes after it is made and the library has no mutable global state.
unsafe impl Send for Model {}
// SAFETY: every function taking a model reads it through `const bs_model *` only.
unsafe impl Sync for Model {}

impl Drop for Model {
    fn drop(&mut self) {
        // SAFETY: self owns the model and is dropped once.
        unsafe { sys::bs_model_destroy(self.ptr.as_ptr()) }
    }
}

type TextReader = unsafe extern "C" fn(
    *const c_char,
    usize,
    *mut sys::bs_parse_error,
    *mut *mut sys::bs_model,
) -> sys::bs_status;
type FileReader =
    unsafe extern "C" fn(*const c_char, *mut sys::bs_parse_error, *mut *mut sys::bs_model) -> sys::bs_status;

fn read_with(
    f: impl FnOnce(*mut sys::bs_parse_error, *mut *mut sys::bs_model) -> sys::bs_status,
) -> Result<Model> {
    let mut err = sys::bs_parse_error { line: 0, column: 0, message: [0; 96] };
    let mut out = ptr::null_mut();
    let code = f(&mut err, &mut out);
    if code < 0 {
        return Err(match code {
            sys::BS_ERR_PARSE | sys::BS_ERR_IO | sys::BS_ERR_UNSUPPORTED | sys::BS_ERR_SIZE => {
                Error::with_parse_error(code, &err)
            }
            _ => Error::from_code(code),
        });
    }
    let ptr = NonNull::new(out).expect("bezsurf returned a NULL model on success");
    Ok(Model { ptr })
}

fn read_text(reader: TextReader, text: &[u8]) -> Result<Model> {
    // SAFETY: text holds len bytes; err and out are valid.
    read_with(|err, out| unsafe { reader(text.as_ptr() as *const c_char, text.len(), err, out) })
}

fn read_file(reader: FileReader, path: &Path) -> Result<Model> {
    let path = c_path(path)?;
    // SAFETY: path is NUL-terminated; err and out are valid.
    read_with(|err, out| unsafe { reader(path.as_ptr(), err, out) })
}

/// The views of n packed points of k coordinates.
fn packed_views(data: &mut [f64], k: usize) -> Vec<sys::bs_view> {
    let n = data.len() / k;
    let stride = (k * size_of::<f64>()) as isize;
    (0..k).map(|c| sys::bs_view { data: data[c..].as_mut_ptr(), count: n, stride }).collect()
}

fn scattered_inputs(faces: &[u32], u: &[f64], v: &[f64]) -> Result<(sys::bs_cview, sys::bs_cview)> {
    if u.len() != faces.len() || v.len() != faces.len() {
        return Err(Error::argument_error(
            sys::BS_ERR_SIZE,
            "u, v",
            format!("must hold one value per face id ({} ids, {} u, {} v)", faces.len(), u.len(), v.len()),
        ));
    }
    let cu = sys::bs_cview { data: u.as_ptr(), count: u.len(), stride: 0 };
    let cv = sys::bs_cview { data: v.as_ptr(), count: v.len(), stride: 0 };
    Ok((cu, cv))
}

impl Model {
    /// Parses STEP text (`bs_model_read_step`; ISO 10303-21, AP203/AP214/AP242 geometry).
    /// `Parse` and `Unsupported` errors carry the line, column and reason.
    pub fn read_step(text: impl AsRef<[u8]>) -> Result<Model> {
        read_text(sys::bs_model_read_step, text.as_ref())
    }

    /// Reads a STEP file (`bs_model_read_step_file`); `Io` if it cannot be read.
    pub fn read_step_file(path: impl AsRef<Path>) -> Result<Model> {
        read_file(sys::bs_model_read_step_file, path.as_ref())
    }

    /// Parses IGES text as a model (`bs_model_read_iges`): trimmed surfaces, B-rep solids,
    /// B-spline surfaces.
    pub fn read_iges(text: impl AsRef<[u8]>) -> Result<Model> {
        read_text(sys::bs_model_read_iges, text.as_ref())
    }

    /// Reads an IGES file as a model (`bs_model_read_iges_file`).
    pub fn read_iges_file(path: impl AsRef<Path>) -> Result<Model> {
        read_file(sys::bs_model_read_iges_file, path.as_ref())
    }

    /// Parses OBJ free-form text as a model (`bs_model_read_obj`): surfaces with their trim and
    /// hole loops.
    pub fn read_obj(text: impl AsRef<[u8]>) -> Result<Model> {
        read_text(sys::bs_model_read_obj, text.as_ref())
    }

    /// Reads an OBJ file as a model (`bs_model_read_obj_file`).
    pub fn read_obj_file(path: impl AsRef<Path>) -> Result<Model> {
        read_file(sys::bs_model_read_obj_file, path.as_ref())
    }

    /// Reads a model file, the format chosen by the extension: `.step`/`.stp`, `.igs`/`.iges`,
    /// `.obj`, or `.bpt` (the model of its surface). Another extension is `InvalidArg`.
    pub fn read_file(path: impl AsRef<Path>) -> Result<Model> {
        let path = path.as_ref();
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        match ext.as_str() {
            "step" | "stp" => Model::read_step_file(path),
            "igs" | "iges" => Model::read_iges_file(path),
            "obj" => Model::read_obj_file(path),
            "bpt" => Model::from_surface(&Surface::read_bpt_file(path)?),
            _ => Err(Error::argument_error(
                sys::BS_ERR_INVALID_ARG,
                "path",
                format!(
                    "{}: no model format for this extension (step, stp, igs, iges, obj, bpt)",
                    path.display()
                ),
            )),
        }
    }

    /// The model of a surface (`bs_model_from_surface`): each patch an untrimmed face, shared
    /// sides joined as edges, one shell per connected set of patches.
    pub fn from_surface(surface: &Surface) -> Result<Model> {
        let mut out = ptr::null_mut();
        // SAFETY: the surface is live; out is valid.
        check(unsafe { sys::bs_model_from_surface(surface.as_ptr(), &mut out) })?;
        let ptr = NonNull::new(out).expect("bezsurf returned a NULL model on success");
        Ok(Model { ptr })
    }

    /// The C handle, valid while `self` is borrowed.
    pub fn as_ptr(&self) -> *const sys::bs_model {
        self.ptr.as_ptr()
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_model_face_count(self.as_ptr()) }
    }

    /// Number of edges (3-D edges shared by faces, each counted once).
    pub fn edge_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_model_edge_count(self.as_ptr()) }
    }

    /// Number of shells.
    pub fn shell_count(&self) -> usize {
        // SAFETY: self is live.
        unsafe { sys::bs_model_shell_count(self.as_ptr()) }
    }

    /// Whether shell `shell` is closed (bounds a solid); `None` for an id out of range.
    pub fn shell_closed(&self, shell: usize) -> Option<bool> {
        // SAFETY: self is live; any id is allowed.
        match unsafe { sys::bs_model_shell_closed(self.as_ptr(), shell) } {
            1 => Some(true),
            0 => Some(false),
            _ => None,
        }
    }

    /// The description of face `index` (`bs_model_face_info`); `Domain` when out of range.
    pub fn face(&self, index: usize) -> Result<Face> {
        let mut info = sys::bs_face_info { size: size_of::<sys::bs_face_info>(), ..Default::default() };
        // SAFETY: self is live; info is a valid struct of the size it declares.
        check(unsafe { sys::bs_model_face_info(self.as_ptr(), index, &mut info) })?;
        Ok(Face {
            kind: FaceKind::from_c(info.kind).unwrap_or(FaceKind::Bezier),
            reversed: info.reversed != 0,
            shell: info.shell,
            instance: info.instance,
            first_patch: info.first_patch,
            patch_count: info.patch_count,
            loop_count: info.loop_count,
            bounds: [info.u0, info.u1, info.v0, info.v1],
        })
    }

    /// Every face's description, in face order.
    pub fn faces(&self) -> Result<Vec<Face>> {
        (0..self.face_count()).map(|k| self.face(k)).collect()
    }

    /// A copy of the surface holding every face's patches (`bs_model_surface`).
    pub fn surface(&self) -> Result<Surface> {
        let mut out = ptr::null_mut();
        // SAFETY: the model's surface lives as long as self; out is valid.
        check(unsafe { sys::bs_surface_clone(sys::bs_model_surface(self.as_ptr()), &mut out) })?;
        // SAFETY: on success out is a new surface that we now own.
        Ok(unsafe { Surface::from_raw(out) })
    }

    /// Positions and outward unit normals at native parameters (`bs_model_face_eval`): point k
    /// on face `faces[k]` at (`u[k]`, `v[k]`). Lengths must agree (`Size`); a face id out of
    /// range is `InvalidArg`.
    pub fn face_eval(&self, faces: &[u32], u: &[f64], v: &[f64]) -> Result<FaceEval> {
        let (cu, cv) = scattered_inputs(faces, u, v)?;
        let n = faces.len();
        let mut pos = vec![0.0; 3 * n];
        let mut nrm = vec![0.0; 3 * n];
        let mut kind = vec![0u8; n];
        if n > 0 {
            let pv = packed_views(&mut pos, 3);
            let nv = packed_views(&mut nrm, 3);
            // SAFETY: faces, u, v hold n values; the views cover disjoint elements of pos and
            // nrm (3n each); kind holds n bytes.
            check(unsafe {
                sys::bs_model_face_eval(
                    self.as_ptr(),
                    n,
                    faces.as_ptr(),
                    &cu,
                    &cv,
                    pv.as_ptr(),
                    nv.as_ptr(),
                    kind.as_mut_ptr(),
                )
            })?;
        }
        Ok(FaceEval {
            pos: pos.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect(),
            normal: nrm.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect(),
            kind: kind.iter().map(|&b| NormalKind::from_byte(b).unwrap_or(NormalKind::Undefined)).collect(),
        })
    }

    /// The patch of [`surface`](Model::surface) holding each native (u, v), and the local (s, t)
    /// there (`bs_model_face_to_patch`); `None` and NaN outside a face's patches.
    pub fn face_to_patch(&self, faces: &[u32], u: &[f64], v: &[f64]) -> Result<PatchParams> {
        let (cu, cv) = scattered_inputs(faces, u, v)?;
        let n = faces.len();
        let mut ids = vec![0u32; n];
        let mut st = vec![0.0; 2 * n];
        if n > 0 {
            let sv = packed_views(&mut st, 2);
            // SAFETY: as in face_eval; ids holds n values.
            check(unsafe {
                sys::bs_model_face_to_patch(
                    self.as_ptr(),
                    n,
                    faces.as_ptr(),
                    &cu,
                    &cv,
                    ids.as_mut_ptr(),
                    sv.as_ptr(),
                )
            })?;
        }
        Ok((
            ids.iter().map(|&p| if p == u32::MAX { None } else { Some(p) }).collect(),
            st.chunks_exact(2).map(|p| [p[0], p[1]]).collect(),
        ))
    }

    /// The inverse of [`face_to_patch`](Model::face_to_patch) (`bs_model_patch_to_face`): the
    /// face holding each patch of [`surface`](Model::surface) and the native (u, v) of local
    /// (s, t) there; `None` and NaN for (s, t) outside [0, 1]. A patch id out of range is
    /// `InvalidArg`.
    pub fn patch_to_face(&self, patches: &[u32], s: &[f64], t: &[f64]) -> Result<FaceParams> {
        let (cs, ct) = scattered_inputs(patches, s, t)?;
        let n = patches.len();
        let mut ids = vec![0u32; n];
        let mut uv = vec![0.0; 2 * n];
        if n > 0 {
            let views = packed_views(&mut uv, 2);
            // SAFETY: as in face_eval; ids holds n values, views address uv's 2 n doubles.
            check(unsafe {
                sys::bs_model_patch_to_face(
                    self.as_ptr(),
                    n,
                    patches.as_ptr(),
                    &cs,
                    &ct,
                    ids.as_mut_ptr(),
                    views.as_ptr(),
                )
            })?;
        }
        Ok((
            ids.iter().map(|&f| if f == u32::MAX { None } else { Some(f) }).collect(),
            uv.chunks_exact(2).map(|p| [p[0], p[1]]).collect(),
        ))
    }

    /// Where each native (u, v) lies on its face (`bs_model_classify`): inside, outside, or on
    /// the boundary within `tol` (a finite 3-D distance >= 0, else `Domain`).
    pub fn classify(&self, faces: &[u32], u: &[f64], v: &[f64], tol: f64) -> Result<Vec<Trim>> {
        let (cu, cv) = scattered_inputs(faces, u, v)?;
        let n = faces.len();
        let mut out = vec![0u8; n];
        if n > 0 {
            // SAFETY: as in face_eval; out holds n bytes.
            check(unsafe {
                sys::bs_model_classify(self.as_ptr(), n, faces.as_ptr(), &cu, &cv, tol, out.as_mut_ptr())
            })?;
        } else if !(tol.is_finite() && tol >= 0.0) {
            return Err(Error::argument_error(
                sys::BS_ERR_DOMAIN,
                "tol",
                format!("{tol} is not finite and >= 0"),
            ));
        }
        Ok(out
            .iter()
            .map(|&b| match b {
                sys::BS_TRIM_INSIDE => Trim::Inside,
                sys::BS_TRIM_ON => Trim::On,
                _ => Trim::Outside,
            })
            .collect())
    }

    /// Area, enclosed volume and centroid on the exact surfaces, within `rel_tol` (1e-12 ..
    /// 0.1, else `Domain`) of each (`bs_model_properties`).
    pub fn properties(&self, rel_tol: f64) -> Result<Properties> {
        let (mut area, mut volume, mut centroid) = (0.0, 0.0, [0.0; 3]);
        // SAFETY: self is live; the outputs are valid for 1, 1 and 3 doubles.
        check(unsafe {
            sys::bs_model_properties(self.as_ptr(), rel_tol, &mut area, &mut volume, centroid.as_mut_ptr())
        })?;
        Ok(Properties { area, volume, centroid })
    }

    /// The model as OBJ free-form text with trim and hole loops (`bs_model_write_obj`).
    pub fn write_obj(&self) -> Result<String> {
        let mut size = 0usize;
        // SAFETY: a NULL buffer asks for the size only.
        check(unsafe { sys::bs_model_write_obj(self.as_ptr(), ptr::null_mut(), 0, &mut size) })?;
        let mut buf = vec![0u8; size + 1];
        // SAFETY: buf holds size + 1 bytes.
        check(unsafe {
            sys::bs_model_write_obj(self.as_ptr(), buf.as_mut_ptr() as *mut c_char, size + 1, &mut size)
        })?;
        buf.truncate(size);
        Ok(String::from_utf8_lossy(&buf).into_owned())
    }

    /// Writes the model as an OBJ file (`bs_model_write_obj_file`); `Io` on failure.
    pub fn write_obj_file(&self, path: impl AsRef<Path>) -> Result<()> {
        let path = c_path(path.as_ref())?;
        // SAFETY: self is live; path is NUL-terminated.
        check(unsafe { sys::bs_model_write_obj_file(self.as_ptr(), path.as_ptr()) })
    }
}

/// Rays and closest points on the trimmed faces of a [`Model`] (`bs_locator_create_model`,
/// since 1.2), borrowed from the model it was made of. Derefs to [`Locator`]:
/// [`Locator::intersect`] answers with the first hit inside a trimmed face (hits outside a
/// face's trims are skipped), `patch` holding the **face** id, `uv` native face parameters and
/// `normal` the outward normal; a point within 1e-7 of the model's size from a trim counts as
/// inside, so a ray through an edge hits one of its faces. [`Locator::closest_points`] gives the
/// closest point of the union of the trimmed faces (certified within 1e-9 (D + d) as on a
/// surface; on a trim where the surface's own closest point lies outside its face), `patch`
/// again holding face ids and `uv` native face parameters.
///
/// ```no_run
/// use bezsurf::{Model, Ray};
///
/// let part = Model::read_file("part.step")?;
/// let loc = part.locator()?;
/// let hits = loc.intersect(&[Ray::new([0., 0., 100.], [0., 0., -1.])])?;
/// if let Some(face) = hits[0].patch {
///     println!("face {face} at t = {}", hits[0].t);
/// }
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug)]
pub struct ModelLocator<'m> {
    locator: Locator,
    _model: std::marker::PhantomData<&'m Model>,
}

impl std::ops::Deref for ModelLocator<'_> {
    type Target = Locator;
    fn deref(&self) -> &Locator {
        &self.locator
    }
}

impl Model {
    /// One watertight mesh of the trimmed faces (`bs_model_tessellate`, since 1.2): each model
    /// edge sampled once and shared by the faces on both sides, so a closed shell gives a closed
    /// mesh wound outward; every triangle within the options' tolerance of its face. Triangle
    /// ids are face ids, corner (u, v) native face parameters. `Unsupported` for
    /// [`TessMethod::Uniform`] and [`TessFlags::STRIPS`] (and faces without trims: tessellate
    /// [`Model::surface`] instead); `Domain` for a tolerance that is not finite and positive;
    /// `Size` over a budget.
    ///
    /// [`TessMethod::Uniform`]: crate::TessMethod::Uniform
    /// [`TessFlags::STRIPS`]: crate::TessFlags::STRIPS
    pub fn tessellate(&self, options: &TessOptions) -> Result<Mesh> {
        let o = options.raw();
        // SAFETY: self is live; o is a filled options struct; out is valid.
        new_mesh(|out| unsafe { sys::bs_model_tessellate(self.as_ptr(), &o, out) })
    }

    /// The (vertices, triangles) [`Model::tessellate`] would give (`bs_model_tessellate_count`).
    pub fn tessellate_count(&self, options: &TessOptions) -> Result<(usize, usize)> {
        let o = options.raw();
        let (mut nv, mut nt) = (0usize, 0usize);
        // SAFETY: self is live; o is a filled options struct; both outputs are valid.
        check(unsafe { sys::bs_model_tessellate_count(self.as_ptr(), &o, &mut nv, &mut nt) })?;
        Ok((nv, nt))
    }

    /// A locator of the model's trimmed faces, for rays and closest points ([`ModelLocator`]).
    pub fn locator(&self) -> Result<ModelLocator<'_>> {
        let mut out = std::ptr::null_mut();
        // SAFETY: the model is live and outlives the locator (the borrow); out is valid.
        check(unsafe { sys::bs_locator_create_model(self.as_ptr(), &mut out) })?;
        Ok(ModelLocator { locator: Locator::from_raw(out), _model: std::marker::PhantomData })
    }
}
