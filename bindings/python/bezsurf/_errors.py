"""Exceptions raised for the library's negative status codes."""

import errno as _errno
import os
from typing import Dict, Optional, Tuple, Type, Union


class BezsurfError(Exception):
    """A libbezsurf call failed.

    Attributes:
        code: the negative ``bs_status`` value returned by the C function.
        message: the library's text for that status (``bs_status_string``).
        function: name of the C function that failed, when known.
        detail: more precise reason given by the library (parse and I/O errors), or None.
    """

    code: int
    message: str
    function: Optional[str]
    detail: Optional[str]

    def __init__(self, code: int, message: str, function: Optional[str] = None,
                 detail: Optional[str] = None) -> None:
        self.code = code
        self.message = message
        self.function = function
        self.detail = detail
        where = f"{function}: " if function else ""
        more = f": {detail}" if detail else ""
        super().__init__(f"{where}{message}{more} (status {code})")
        # the constructor's arguments: ints, strings and None
        self._init: Tuple[Union[int, str, None], ...] = (code, message, function, detail)

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""

    def __reduce__(self) -> Tuple[Type["BezsurfError"], Tuple[Union[int, str, None], ...]]:
        # Rebuilt from the constructor's arguments: exceptions cross process boundaries
        # (multiprocessing) by pickling.
        return (type(self), self._init)


class InvalidArgumentError(BezsurfError, ValueError):
    """BS_ERR_INVALID_ARG: a bad flag, direction or buffer."""


class NoMemoryError(BezsurfError, MemoryError):
    """BS_ERR_NO_MEMORY: the library could not allocate memory."""


class DegreeError(BezsurfError, ValueError):
    """BS_ERR_DEGREE: a degree or derivative order out of range."""


class DimensionError(BezsurfError, ValueError):
    """BS_ERR_DIMENSION: dimension 0 or too large, or normals of a patch that is not 3-D."""


class SizeError(BezsurfError, ValueError):
    """BS_ERR_SIZE: a buffer too small or a count too large."""


class DomainError(BezsurfError, ValueError):
    """BS_ERR_DOMAIN: a parameter outside its allowed range."""


class NonFiniteError(BezsurfError, ValueError):
    """BS_ERR_NONFINITE: NaN or Inf in control points, or a weight that is not finite and > 0."""


class ParseError(BezsurfError, ValueError):
    """BS_ERR_PARSE: malformed input text.

    Attributes:
        line: 1-based line of the error, or None when unknown.
        column: 1-based byte column of the error, or None when unknown.
        filename: the file being read (Surface.load), else None.
    """

    line: Optional[int]
    column: Optional[int]
    filename: Optional[str]

    def __init__(self, code: int, message: str, function: Optional[str] = None,
                 detail: Optional[str] = None, line: Optional[int] = None,
                 column: Optional[int] = None, filename: Optional[str] = None) -> None:
        self.line = line
        self.column = column
        self.filename = filename
        shown = detail
        if line is not None:
            shown = f"line {line}, column {column}" + (f": {detail}" if detail else "")
        super().__init__(code, message, function, shown)
        self.detail = detail
        self._init = (code, message, function, detail, line, column, filename)


class BezsurfIOError(BezsurfError, OSError):
    """BS_ERR_IO: a file could not be opened, read or written.

    Also an OSError with ``errno`` (the C library's errno after the failed call, EIO when it
    left none), ``strerror`` and ``filename``. Raised as the subclass matching the errno where
    Python has one: :class:`BezsurfFileNotFoundError` (a FileNotFoundError),
    :class:`BezsurfPermissionError` (a PermissionError), :class:`BezsurfIsADirectoryError`,
    :class:`BezsurfNotADirectoryError`.
    """

    def __init__(self, code: int, message: str, function: Optional[str] = None,
                 detail: Optional[str] = None, errno: Optional[int] = None,
                 filename: Optional[str] = None) -> None:
        errno = errno or _errno.EIO
        strerror = os.strerror(errno)
        what = f"{detail}: " if detail else ""
        where = f": {filename!r}" if filename is not None else ""
        BezsurfError.__init__(self, code, message, function,
                              f"{what}[Errno {errno}] {strerror}{where}")
        self.detail = detail
        self.errno = errno
        self.strerror = strerror
        self.filename = filename
        self._init = (code, message, function, detail, errno, filename)


class BezsurfFileNotFoundError(BezsurfIOError, FileNotFoundError):
    """BS_ERR_IO with ENOENT."""


class BezsurfPermissionError(BezsurfIOError, PermissionError):
    """BS_ERR_IO with EACCES or EPERM."""


class BezsurfIsADirectoryError(BezsurfIOError, IsADirectoryError):
    """BS_ERR_IO with EISDIR."""


class BezsurfNotADirectoryError(BezsurfIOError, NotADirectoryError):
    """BS_ERR_IO with ENOTDIR."""


_IO_CLASSES: Dict[int, Type[BezsurfIOError]] = {
    _errno.ENOENT: BezsurfFileNotFoundError,
    _errno.EACCES: BezsurfPermissionError,
    _errno.EPERM: BezsurfPermissionError,
    _errno.EISDIR: BezsurfIsADirectoryError,
    _errno.ENOTDIR: BezsurfNotADirectoryError,
}


def with_detail(exc: BezsurfError, detail: str) -> BezsurfError:
    """``exc`` again (same class, status and function) with ``detail`` saying which argument,
    which value and which limit: what the bare status cannot tell."""
    return type(exc)(exc.code, exc.message, exc.function, detail)


def io_error(code: int, message: str, function: Optional[str], detail: Optional[str],
             errno: Optional[int], filename: Optional[str]) -> BezsurfIOError:
    """The BezsurfIOError subclass for errno, carrying errno and filename."""
    cls = _IO_CLASSES.get(errno or 0, BezsurfIOError)
    return cls(code, message, function, detail, errno, filename)


class IncompatibleError(BezsurfError, ValueError):
    """BS_ERR_INCOMPATIBLE: objects that cannot be combined (e.g. patches of different dim)."""


class UnsupportedError(BezsurfError, ValueError):
    """BS_ERR_UNSUPPORTED: the operation is not defined for this input."""


class PrecisionError(BezsurfError, ArithmeticError):
    """BS_ERR_PRECISION: a certified result cannot be given in double precision for this input
    (a weight ratio or a range of magnitudes beyond what the method certifies). Since 1.2."""


ERROR_CLASSES: Dict[int, Type[BezsurfError]] = {
    -1: InvalidArgumentError,
    -2: NoMemoryError,
    -3: DegreeError,
    -4: DimensionError,
    -5: SizeError,
    -6: DomainError,
    -7: NonFiniteError,
    -8: ParseError,
    -9: BezsurfIOError,
    -10: IncompatibleError,
    -11: UnsupportedError,
    -12: PrecisionError,
}
