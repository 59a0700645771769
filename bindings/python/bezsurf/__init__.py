"""Python binding of libbezsurf: rectangular (tensor-product) Bezier surface patches.

The binding is a thin ctypes layer over the C library ``libbezsurf.so.1``: every computation
happens in C. The library is loaded from ``$BEZSURF_LIBRARY`` when set, else by its SONAME from
the system library search path, and must be of major version 1.

Main classes: :class:`Patch` (one patch: evaluation, subdivision, elevation, hodographs, ...),
:class:`Surface` (an ordered set of patches: evaluation, .bpt files, the built-in tea set,
continuity, tessellation), :class:`Mesh` (a triangle mesh: read-back, OBJ/PLY/STL export) and
:class:`BSpline` (a B-spline or NURBS surface, cut into Bezier patches by
:meth:`Surface.add_bspline`), :class:`Locator` (closest points and rays on a surface) and
:class:`Model` (trimmed B-rep models read from STEP, IGES and OBJ files; since 1.2).
Errors are :class:`BezsurfError` subclasses; wrong argument types raise TypeError and bad
values ValueError, naming the argument. numpy is optional: whenever it is importable, results
are numpy arrays written in place by the library (float arrays in Fortran order, the library's
fastest layout), otherwise lists of tuples. Every object can be copied and pickled.
"""

from ._errors import (BezsurfError, BezsurfFileNotFoundError, BezsurfIOError,
                      BezsurfIsADirectoryError, BezsurfNotADirectoryError, BezsurfPermissionError,
                      DegreeError, DimensionError, DomainError, IncompatibleError,
                      InvalidArgumentError, NoMemoryError, NonFiniteError, ParseError, SizeError,
                      UnsupportedError, PrecisionError)
from ._enums import CurvatureKind, Direction, Format, NormalKind, Side, TessMethod
from ._lib import LIB as _LIB
from ._buffers import have_numpy
from .patch import (DIR_U, DIR_V, NORMAL_LIMIT, NORMAL_REGULAR, NORMAL_UNDEFINED, Curvature,
                    Curve, Evaluation, Patch)
from .mesh import Mesh
from .bspline import BSpline
from .query import NO_PATCH, ClosestPoints, Locator, RayHits
from .model import (FACE_KINDS, TRIM_INSIDE, TRIM_ON, TRIM_OUTSIDE, Face, FaceEvaluation,
                    Model, ModelLocator, Properties)
from .surface import (SIDE_U0, SIDE_U1, SIDE_V0, SIDE_V1, Continuity, EdgeContinuity, OpenEdge,
                      Surface, builtin_names)

__version__ = "1.2.0"

#: Largest degree per direction and largest dimension (BS_MAX_DEGREE, BS_MAX_DIM).
MAX_DEGREE = 64
MAX_DIM = 8


def version() -> str:
    """Version string of the loaded C library, "MAJOR.MINOR.PATCH"."""
    text: bytes = _LIB.bs_version_string()
    return text.decode("ascii")


def version_number() -> int:
    """Version of the loaded C library as MAJOR*10000 + MINOR*100 + PATCH."""
    return int(_LIB.bs_version_number())


def status_string(code: int) -> str:
    """The library's text for a status code (any integer; "unknown status" for non-codes)."""
    from ._args import integer
    code = integer(code, "code", -2 ** 31, 2 ** 31 - 1)
    text: bytes = _LIB.bs_status_string(code)
    return text.decode("utf-8", "replace")


def library_path() -> str:
    """The name or path the C library was loaded from."""
    path: str = _LIB.path
    return path


__all__ = [
    "Patch", "Surface", "Mesh", "BSpline", "Locator", "ClosestPoints", "RayHits", "NO_PATCH",
    "TessMethod", "Evaluation", "Curve", "Continuity", "EdgeContinuity", "OpenEdge",
    "Direction", "NormalKind", "Format", "Side", "CurvatureKind", "Curvature",
    "SIDE_V0", "SIDE_U1", "SIDE_V1", "SIDE_U0",
    "BezsurfError", "InvalidArgumentError", "NoMemoryError", "DegreeError", "DimensionError",
    "SizeError", "DomainError", "NonFiniteError", "ParseError", "BezsurfIOError",
    "BezsurfFileNotFoundError", "BezsurfPermissionError", "BezsurfIsADirectoryError",
    "BezsurfNotADirectoryError", "IncompatibleError", "UnsupportedError", "PrecisionError",
    "DIR_U", "DIR_V", "NORMAL_REGULAR", "NORMAL_LIMIT", "NORMAL_UNDEFINED", "MAX_DEGREE",
    "MAX_DIM", "builtin_names", "version", "version_number", "status_string", "library_path",
    "have_numpy", "Model", "ModelLocator", "Face", "FaceEvaluation", "Properties", "FACE_KINDS", "TRIM_OUTSIDE",
    "TRIM_INSIDE", "TRIM_ON",
]
