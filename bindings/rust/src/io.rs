//! The .bpt text format, OBJ free-form and IGES surfaces, and the built-in tea set.

use std::ffi::{CStr, CString};
use std::os::raw::c_char;
use std::path::Path;
use std::ptr;

use crate::error::{check, Error, Result};
use crate::surface::Surface;
use crate::sys;

fn empty_parse_error() -> sys::bs_parse_error {
    sys::bs_parse_error { line: 0, column: 0, message: [0; 96] }
}

/// A path as the C string `fopen` receives; a NUL byte inside it is `InvalidArg`.
pub(crate) fn c_path(path: &Path) -> Result<CString> {
    #[cfg(unix)]
    let bytes = {
        use std::os::unix::ffi::OsStrExt;
        path.as_os_str().as_bytes().to_vec()
    };
    #[cfg(not(unix))]
    let bytes = path
        .to_str()
        .ok_or_else(|| Error::argument_error(sys::BS_ERR_INVALID_ARG, "path", "is not valid Unicode"))?
        .as_bytes()
        .to_vec();
    CString::new(bytes).map_err(|e| {
        Error::argument_error(
            sys::BS_ERR_INVALID_ARG,
            "path",
            format!("has a NUL byte at {}", e.nul_position()),
        )
    })
}

/// Runs a reader and turns its status and parse error into a surface or an [`Error`] with
/// [`position`](Error::position) and [`detail`](Error::detail).
fn read_with(
    f: impl FnOnce(*mut sys::bs_parse_error, *mut *mut sys::bs_surface) -> sys::bs_status,
) -> Result<Surface> {
    let mut err = empty_parse_error();
    let mut out = ptr::null_mut();
    let code = f(&mut err, &mut out);
    if code < 0 {
        return Err(match code {
            sys::BS_ERR_PARSE | sys::BS_ERR_IO => Error::with_parse_error(code, &err),
            sys::BS_ERR_UNSUPPORTED if err.line > 0 => Error::with_parse_error(code, &err),
            _ => Error::from_code(code),
        });
    }
    // SAFETY: on success the reader returned a new surface that we now own.
    Ok(unsafe { Surface::from_raw(out) })
}

type TextReader = unsafe extern "C" fn(
    *const c_char,
    usize,
    *mut sys::bs_parse_error,
    *mut *mut sys::bs_surface,
) -> sys::bs_status;
type FileReader = unsafe extern "C" fn(
    *const c_char,
    *mut sys::bs_parse_error,
    *mut *mut sys::bs_surface,
) -> sys::bs_status;
type TextWriter =
    unsafe extern "C" fn(*const sys::bs_surface, *mut c_char, usize, *mut usize) -> sys::bs_status;
type FileWriter = unsafe extern "C" fn(*const sys::bs_surface, *const c_char) -> sys::bs_status;

fn read_text(reader: TextReader, text: &[u8]) -> Result<Surface> {
    // SAFETY: text holds len bytes; err and out are valid.
    read_with(|err, out| unsafe { reader(text.as_ptr() as *const c_char, text.len(), err, out) })
}

fn read_file(reader: FileReader, path: &Path) -> Result<Surface> {
    let cpath = c_path(path)?;
    // SAFETY: cpath is NUL-terminated; err and out are valid.
    read_with(|err, out| unsafe { reader(cpath.as_ptr(), err, out) }).map_err(|e| e.with_path(path))
}

impl Surface {
    fn write_text(&self, writer: TextWriter) -> Result<String> {
        let mut size = 0usize;
        // SAFETY: a NULL buffer asks for the size only.
        check(unsafe { writer(self.as_ptr(), ptr::null_mut(), 0, &mut size) })?;
        let mut buf = vec![0u8; size];
        // SAFETY: buf holds size bytes.
        check(unsafe { writer(self.as_ptr(), buf.as_mut_ptr() as *mut c_char, size, &mut size) })?;
        buf.truncate(size.saturating_sub(1)); // the final NUL
                                              // The writers produce ASCII only.
        Ok(String::from_utf8_lossy(&buf).into_owned())
    }

    fn write_file(&self, writer: FileWriter, path: &Path) -> Result<()> {
        let cpath = c_path(path)?;
        // SAFETY: self is live; cpath is NUL-terminated.
        check(unsafe { writer(self.as_ptr(), cpath.as_ptr()) }).map_err(|e| e.with_path(path))
    }

    /// Parses .bpt text (`bs_surface_read_bpt`) into a surface of 3-D patches. `Parse` errors
    /// carry the line, column and reason.
    ///
    /// ```
    /// use bezsurf::Surface;
    ///
    /// let pot = Surface::builtin("teapot")?;
    /// let text = pot.write_bpt()?;
    /// let back = Surface::read_bpt(&text)?;
    /// assert_eq!(back, pot); // every control point survives bit for bit
    ///
    /// let err = Surface::read_bpt("1\n3 3\n0 0 x\n").unwrap_err();
    /// assert_eq!(err.kind(), bezsurf::ErrorKind::Parse);
    /// assert_eq!(err.position().map(|(line, _)| line), Some(3));
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn read_bpt(text: impl AsRef<[u8]>) -> Result<Surface> {
        read_text(sys::bs_surface_read_bpt, text.as_ref())
    }

    /// Reads a .bpt file (`bs_surface_read_bpt_file`); `Io` if it cannot be read.
    pub fn read_bpt_file(path: impl AsRef<Path>) -> Result<Surface> {
        read_file(sys::bs_surface_read_bpt_file, path.as_ref())
    }

    /// The surface as .bpt text (`bs_surface_write_bpt`); reading it back gives every control
    /// point and weight bit for bit. `Dimension` if the patches are not 3-D.
    pub fn write_bpt(&self) -> Result<String> {
        self.write_text(sys::bs_surface_write_bpt)
    }

    /// Writes the surface as a .bpt file (`bs_surface_write_bpt_file`); `Io` on failure.
    pub fn write_bpt_file(&self, path: impl AsRef<Path>) -> Result<()> {
        self.write_file(sys::bs_surface_write_bpt_file, path.as_ref())
    }

    /// Parses the free-form surfaces of OBJ text (`bs_surface_read_obj`, docs/formats.md):
    /// Bezier and B-spline surfaces, rational or not, as Bezier patches. `Parse` errors carry the
    /// line, column and reason; bmatrix, cardinal and taylor surfaces are `Unsupported`, with the
    /// position too.
    ///
    /// ```
    /// use bezsurf::Surface;
    ///
    /// let cup = Surface::builtin("teacup")?;
    /// let back = Surface::read_obj(cup.write_obj()?)?;
    /// assert_eq!(back, cup); // bit for bit
    /// # Ok::<(), bezsurf::Error>(())
    /// ```
    pub fn read_obj(text: impl AsRef<[u8]>) -> Result<Surface> {
        read_text(sys::bs_surface_read_obj, text.as_ref())
    }

    /// Reads an OBJ file's free-form surfaces (`bs_surface_read_obj_file`); `Io` if it cannot be
    /// read.
    pub fn read_obj_file(path: impl AsRef<Path>) -> Result<Surface> {
        read_file(sys::bs_surface_read_obj_file, path.as_ref())
    }

    /// The surface as OBJ free-form text (`bs_surface_write_obj`), one `cstype [rat] bezier`
    /// surface per patch; reading it back gives every control point and weight bit for bit.
    /// `Dimension` if the patches are not 3-D.
    pub fn write_obj(&self) -> Result<String> {
        self.write_text(sys::bs_surface_write_obj)
    }

    /// Writes the surface as an OBJ file (`bs_surface_write_obj_file`); `Io` on failure.
    pub fn write_obj_file(&self, path: impl AsRef<Path>) -> Result<()> {
        self.write_file(sys::bs_surface_write_obj_file, path.as_ref())
    }

    /// Parses IGES text (`bs_surface_read_iges`, docs/formats.md): every rational B-spline
    /// surface (entity 128), with its transformations (entity 124), restricted to its parameter
    /// range, as Bezier patches. `Parse` errors carry the record's line and the column.
    pub fn read_iges(text: impl AsRef<[u8]>) -> Result<Surface> {
        read_text(sys::bs_surface_read_iges, text.as_ref())
    }

    /// Reads an IGES file (`bs_surface_read_iges_file`); `Io` if it cannot be read.
    pub fn read_iges_file(path: impl AsRef<Path>) -> Result<Surface> {
        read_file(sys::bs_surface_read_iges_file, path.as_ref())
    }

    /// One of the built-in surfaces (`bs_surface_create_builtin`): "teapot", "teacup" or
    /// "teaspoon" (see [`builtin_names`]). An unknown name is `InvalidArg`.
    pub fn builtin(name: &str) -> Result<Surface> {
        let given = name;
        let name = CString::new(name).map_err(|e| {
            Error::argument_error(
                sys::BS_ERR_INVALID_ARG,
                "name",
                format!("has a NUL byte at {}", e.nul_position()),
            )
        })?;
        let mut out = ptr::null_mut();
        // SAFETY: name is NUL-terminated; out is valid.
        check(unsafe { sys::bs_surface_create_builtin(name.as_ptr(), &mut out) }).map_err(|e| {
            if e.kind() != crate::ErrorKind::InvalidArg {
                return e;
            }
            e.with_argument(
                "name",
                format!(
                    "{given:?} is not a built-in surface (names are case-sensitive: {})",
                    builtin_names().join(", ")
                ),
            )
        })?;
        // SAFETY: on success out is a new surface that we now own.
        Ok(unsafe { Surface::from_raw(out) })
    }
}

/// The names of the built-in surfaces (`bs_builtin_name`).
///
/// ```
/// assert_eq!(bezsurf::builtin_names(), ["teapot", "teacup", "teaspoon"]);
/// ```
pub fn builtin_names() -> Vec<&'static str> {
    (0..)
        // SAFETY: any index is allowed; the result is NULL or a static NUL-terminated string.
        .map(|i| unsafe { sys::bs_builtin_name(i) })
        .take_while(|p| !p.is_null())
        // SAFETY: p is a non-NULL (checked above) static NUL-terminated string.
        .map(|p| unsafe { CStr::from_ptr(p) }.to_str().unwrap_or(""))
        .collect()
}
