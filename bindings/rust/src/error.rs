//! The error type: a negative `bs_status` and the library's text for it.

use std::ffi::CStr;
use std::fmt;
use std::path::{Path, PathBuf};

use crate::sys;

/// What went wrong, one variant per `BS_ERR_` code of the C library.
///
/// New codes may be appended by later library versions; they arrive as `Unknown`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// `BS_ERR_INVALID_ARG`: a missing or misaligned buffer, a bad flag or direction.
    InvalidArg,
    /// `BS_ERR_NO_MEMORY`: an allocation failed.
    NoMemory,
    /// `BS_ERR_DEGREE`: a degree above `MAX_DEGREE` or a derivative order out of range.
    Degree,
    /// `BS_ERR_DIMENSION`: a dimension of 0 or above `MAX_DIM`, normals of a patch that is not
    /// 3-D, or (checked by this crate) output points whose dimension differs from the patch's.
    Dimension,
    /// `BS_ERR_SIZE`: a buffer too small for the result, or inputs of different lengths.
    Size,
    /// `BS_ERR_DOMAIN`: a parameter outside its allowed range.
    Domain,
    /// `BS_ERR_NONFINITE`: NaN or infinity in control points, or a weight that is not positive.
    NonFinite,
    /// `BS_ERR_PARSE`: malformed input text.
    Parse,
    /// `BS_ERR_IO`: a file could not be opened, read or written.
    Io,
    /// `BS_ERR_INCOMPATIBLE`: objects that cannot be combined.
    Incompatible,
    /// `BS_ERR_UNSUPPORTED`: an operation not defined for this input.
    Unsupported,
    /// A status this crate does not know.
    Unknown,
}

/// A failed call: the C status code and the library's description of it, plus, where known, the
/// argument that was rejected ([`argument`](Error::argument)), where a reader stopped
/// ([`position`](Error::position)) and why ([`detail`](Error::detail)).
///
/// ```
/// use bezsurf::{ErrorKind, Patch};
///
/// let plane = Patch::new(1, 1, 3, &[0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0.])?;
/// let mut pos = [0.0; 6];
/// let err = plane.eval(&[0.0, 1.0], &[0.5], &mut pos).unwrap_err();
/// assert_eq!(err.kind(), ErrorKind::Size);
/// assert_eq!(err.argument(), Some("v"));
/// assert_eq!(
///     err.to_string(),
///     "buffer or view too small: argument `v` has 1 value but `u` has 2; \
///      they must have the same length (bezsurf status -5)"
/// );
/// # Ok::<(), bezsurf::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Error {
    code: sys::bs_status,
    message: &'static str,
    argument: Option<&'static str>,
    position: Option<(usize, usize)>,
    detail: Option<String>,
    path: Option<PathBuf>,
}

impl Error {
    /// The error for a status code, with its text from `bs_status_string`.
    pub fn from_code(code: i32) -> Error {
        Error { code, message: status_string(code), argument: None, position: None, detail: None, path: None }
    }

    /// The error for a status code caused by the argument `name`, with an explanation.
    pub(crate) fn argument_error(code: i32, name: &'static str, detail: impl Into<String>) -> Error {
        Error::from_code(code).with_argument(name, detail)
    }

    /// This error, attributed to the argument `name` with an explanation.
    pub(crate) fn with_argument(mut self, name: &'static str, detail: impl Into<String>) -> Error {
        self.argument = Some(name);
        self.detail = Some(detail.into());
        self
    }

    /// This error, about the file `path` (readers and writers of files).
    pub(crate) fn with_path(mut self, path: &Path) -> Error {
        self.path = Some(path.to_path_buf());
        self
    }

    /// The error for a status code with what a reader reported in its `bs_parse_error`.
    pub(crate) fn with_parse_error(code: i32, err: &sys::bs_parse_error) -> Error {
        let mut e = Error::from_code(code);
        if err.line > 0 {
            e.position = Some((err.line, err.column));
        }
        let bytes: Vec<u8> = err.message.iter().take_while(|&&c| c != 0).map(|&c| c as u8).collect();
        if !bytes.is_empty() {
            e.detail = Some(String::from_utf8_lossy(&bytes).into_owned());
        }
        e
    }

    /// The file a reader or writer of files failed on (since 1.2).
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// For parse errors: the 1-based line and byte column of the first error.
    pub fn position(&self) -> Option<(usize, usize)> {
        self.position
    }

    /// The name of the argument that was rejected, as it is spelled in the method's signature
    /// (`"u"`, `"v"`, `"pos"`, `"ctrl"`, `"stride"`, ...), when the crate knows it.
    pub fn argument(&self) -> Option<&'static str> {
        self.argument
    }

    /// What is wrong, in words: for the readers' parse and I/O errors the library's account,
    /// for an [`argument`](Error::argument) error the crate's (e.g. which lengths differ).
    pub fn detail(&self) -> Option<&str> {
        self.detail.as_deref()
    }

    /// The C status code (negative; one of the `sys::BS_ERR_` constants).
    pub fn code(&self) -> i32 {
        self.code
    }

    /// The library's text for the code (`bs_status_string`).
    pub fn message(&self) -> &'static str {
        self.message
    }

    /// The kind of failure.
    pub fn kind(&self) -> ErrorKind {
        match self.code {
            sys::BS_ERR_INVALID_ARG => ErrorKind::InvalidArg,
            sys::BS_ERR_NO_MEMORY => ErrorKind::NoMemory,
            sys::BS_ERR_DEGREE => ErrorKind::Degree,
            sys::BS_ERR_DIMENSION => ErrorKind::Dimension,
            sys::BS_ERR_SIZE => ErrorKind::Size,
            sys::BS_ERR_DOMAIN => ErrorKind::Domain,
            sys::BS_ERR_NONFINITE => ErrorKind::NonFinite,
            sys::BS_ERR_PARSE => ErrorKind::Parse,
            sys::BS_ERR_IO => ErrorKind::Io,
            sys::BS_ERR_INCOMPATIBLE => ErrorKind::Incompatible,
            sys::BS_ERR_UNSUPPORTED => ErrorKind::Unsupported,
            _ => ErrorKind::Unknown,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.message)?;
        if let Some(path) = &self.path {
            write!(f, ": {}", path.display())?;
        }
        if let Some(name) = self.argument {
            write!(f, ": argument `{name}`")?;
            if let Some(detail) = &self.detail {
                write!(f, " {detail}")?;
            }
            return write!(f, " (bezsurf status {})", self.code);
        }
        if let Some((line, column)) = self.position {
            write!(f, " at line {line}, column {column}")?;
        }
        if let Some(detail) = &self.detail {
            write!(f, ": {detail}")?;
        }
        write!(f, " (bezsurf status {})", self.code)
    }
}

impl std::error::Error for Error {}

impl From<Error> for std::io::Error {
    /// Wraps the error for code that reports `std::io::Error`: `Io` becomes
    /// [`Other`](std::io::ErrorKind::Other), argument, size, domain and parse errors
    /// [`InvalidInput`](std::io::ErrorKind::InvalidInput) or
    /// [`InvalidData`](std::io::ErrorKind::InvalidData), `NoMemory`
    /// [`OutOfMemory`](std::io::ErrorKind::OutOfMemory); the original is the source.
    fn from(e: Error) -> std::io::Error {
        use std::io::ErrorKind as Io;
        let kind = match e.kind() {
            ErrorKind::Parse => Io::InvalidData,
            ErrorKind::NoMemory => Io::OutOfMemory,
            ErrorKind::Io | ErrorKind::Unknown => Io::Other,
            _ => Io::InvalidInput,
        };
        std::io::Error::new(kind, e)
    }
}

/// "1 value", "2 values": a count of `f64`s for an error's detail.
pub(crate) fn values(n: usize) -> String {
    count(n, "value")
}

/// "1 point", "0 points", ...: `n` things for an error's detail.
pub(crate) fn count(n: usize, thing: &str) -> String {
    if n == 1 {
        format!("1 {thing}")
    } else {
        format!("{n} {thing}s")
    }
}

/// The detail of an output with room for `cap` things where `need` are written.
pub(crate) fn no_room(cap: usize, need: usize, thing: &str) -> String {
    format!("has room for {}, but {} must be written", count(cap, thing), count(need, thing))
}

/// `Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// The library's static text for any status value (`bs_status_string`).
pub fn status_string(code: i32) -> &'static str {
    // SAFETY: bs_status_string accepts any value and returns a static NUL-terminated string,
    // never NULL; the texts are ASCII.
    unsafe { CStr::from_ptr(sys::bs_status_string(code)) }.to_str().unwrap_or("unknown status")
}

/// Turns a C status into a `Result`: success for `BS_OK` and (defensively) any positive value.
pub(crate) fn check(code: sys::bs_status) -> Result<()> {
    if code < 0 {
        Err(Error::from_code(code))
    } else {
        Ok(())
    }
}
