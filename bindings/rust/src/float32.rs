//! Float outputs (since 1.1): the grid evaluator and the mesh read-back, each value the double
//! result correctly rounded to `f32`, for callers that upload to a GPU.

use crate::error::{check, Error, Result};
use crate::mesh::Mesh;
use crate::patch::PatchRef;
use crate::sys;

/// `dim` float views of `n` points stored interleaved in `data` (point k coordinate c at
/// `data[k * dim + c]`); `Size` naming `what` when `data` is too short.
fn interleaved(data: &mut [f32], dim: usize, n: usize, what: &'static str) -> Result<Vec<sys::bs_fview>> {
    let need =
        n.checked_mul(dim).ok_or_else(|| Error::argument_error(sys::BS_ERR_SIZE, what, "too many points"))?;
    if data.len() < need {
        return Err(Error::argument_error(
            sys::BS_ERR_SIZE,
            what,
            format!("holds {} values but {need} are needed ({n} points of {dim})", data.len()),
        ));
    }
    let stride = (dim * std::mem::size_of::<f32>()) as isize;
    let base = data.as_mut_ptr();
    // Column c starts at element c (wrapping_add: never read when n = 0).
    Ok((0..dim).map(|c| sys::bs_fview { data: base.wrapping_add(c), count: n, stride }).collect())
}

/// The outputs of [`PatchRef::eval_grid_f32`], each `None` (not wanted) or an interleaved
/// slice with room for nu·nv points (`kind`: nu·nv bytes).
#[derive(Debug, Default)]
pub struct GridF32<'a> {
    /// Positions, `dim` per point.
    pub pos: Option<&'a mut [f32]>,
    /// dS/du, `dim` per point.
    pub du: Option<&'a mut [f32]>,
    /// dS/dv, `dim` per point.
    pub dv: Option<&'a mut [f32]>,
    /// Unit normals, 3 per point (3-D patches).
    pub normal: Option<&'a mut [f32]>,
    /// Normal kinds (`BS_NORMAL_*`), one byte per point.
    pub kind: Option<&'a mut [u8]>,
}

impl PatchRef {
    /// Every `u[a]` with every `v[b]` (`bs_patch_eval_grid_f32`), point (a, b) at index a·nv + b,
    /// each float the double result of [`eval_grid`](PatchRef::eval_grid) correctly rounded.
    ///
    /// ```
    /// use bezsurf::{GridF32, Patch};
    ///
    /// let p = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.])?;
    /// let mut pos = [0f32; 3 * 4];
    /// p.eval_grid_f32(&[0.0, 0.1], &[0.0, 0.3], GridF32 { pos: Some(&mut pos), ..Default::default() })?;
    /// assert_eq!(pos[9..12], [0.1f32, 0.3, (0.1f64 * 0.3) as f32]);
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn eval_grid_f32(&self, u: &[f64], v: &[f64], out: GridF32<'_>) -> Result<()> {
        let (nu, nv) = (u.len(), v.len());
        let n = nu
            .checked_mul(nv)
            .ok_or_else(|| Error::argument_error(sys::BS_ERR_SIZE, "v", "nu * nv overflows"))?;
        let dim = self.dim();
        let views = |d: Option<&mut [f32]>, k: usize, what| d.map(|d| interleaved(d, k, n, what)).transpose();
        let pos = views(out.pos, dim, "pos")?;
        let du = views(out.du, dim, "du")?;
        let dv = views(out.dv, dim, "dv")?;
        let nrm = views(out.normal, 3, "normal")?;
        let kind = match out.kind {
            Some(k) if k.len() < n => {
                return Err(Error::argument_error(
                    sys::BS_ERR_SIZE,
                    "kind",
                    format!("holds {} bytes, {n} needed", k.len()),
                ))
            }
            Some(k) => k.as_mut_ptr(),
            None => std::ptr::null_mut(),
        };
        let ptr = |v: &Option<Vec<sys::bs_fview>>| v.as_ref().map_or(std::ptr::null(), |v| v.as_ptr());
        let cu = sys::bs_cview { data: u.as_ptr(), count: nu, stride: 0 };
        let cv = sys::bs_cview { data: v.as_ptr(), count: nv, stride: 0 };
        // SAFETY: the patch is live; u and v hold nu and nv values; every view covers n points
        // of its own slice (checked above); kind holds n bytes or is NULL.
        check(unsafe {
            sys::bs_patch_eval_grid_f32(
                self.as_ptr(),
                nu,
                &cu,
                nv,
                &cv,
                ptr(&pos),
                ptr(&du),
                ptr(&dv),
                ptr(&nrm),
                kind,
            )
        })
    }
}

impl Mesh {
    fn copy_f32(
        &self,
        k: usize,
        f: unsafe extern "C" fn(*const sys::bs_mesh, *const sys::bs_fview) -> sys::bs_status,
    ) -> Vec<f32> {
        let n = self.vertex_count();
        let mut out = vec![0f32; k * n];
        let views = interleaved(&mut out, k, n, "out").expect("sized for the mesh");
        // SAFETY: the mesh is live; the views cover the n points of out.
        check(unsafe { f(self.as_ptr(), views.as_ptr()) }).expect("float read-back of a live mesh");
        out
    }

    /// Positions as floats, 3 per vertex (`bs_mesh_copy_positions_f32`), each the double rounded.
    pub fn positions_f32(&self) -> Vec<f32> {
        self.copy_f32(3, sys::bs_mesh_copy_positions_f32)
    }

    /// Unit normals as floats, 3 per vertex (`bs_mesh_copy_normals_f32`).
    pub fn normals_f32(&self) -> Vec<f32> {
        self.copy_f32(3, sys::bs_mesh_copy_normals_f32)
    }

    /// Vertex (u, v) as floats, 2 per vertex (`bs_mesh_copy_uv_f32`).
    pub fn uv_f32(&self) -> Vec<f32> {
        self.copy_f32(2, sys::bs_mesh_copy_uv_f32)
    }
}
