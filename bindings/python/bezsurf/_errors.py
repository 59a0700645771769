"""Exceptions raised for the library's negative status codes."""

from typing import Dict, Optional, Type


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
    """

    line: Optional[int]
    column: Optional[int]

    def __init__(self, code: int, message: str, function: Optional[str] = None,
                 detail: Optional[str] = None, line: Optional[int] = None,
                 column: Optional[int] = None) -> None:
        self.line = line
        self.column = column
        if line is not None:
            detail = f"line {line}, column {column}" + (f": {detail}" if detail else "")
        super().__init__(code, message, function, detail)


class BezsurfIOError(BezsurfError, OSError):
    """BS_ERR_IO: a file could not be opened, read or written."""


class IncompatibleError(BezsurfError, ValueError):
    """BS_ERR_INCOMPATIBLE: objects that cannot be combined (e.g. patches of different dim)."""


class UnsupportedError(BezsurfError, ValueError):
    """BS_ERR_UNSUPPORTED: the operation is not defined for this input."""


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
}
