"""Loading libbezsurf and declaring its C functions.

The library is ``$BEZSURF_LIBRARY`` when that is set, else the first ``libbezsurf.so.1`` of
``search_path()``: the package directory, the install prefixes, then the dynamic loader's own
search. Always the SONAME: the unversioned development symlink is never used, so a library of
another major version cannot be picked up by accident; the major version is checked as well. Every C function is
declared once, in ``FUNCTIONS`` below, and the declarations are applied when the module loads.
"""

import ctypes
import os
import sys
import sysconfig
from ctypes import (POINTER, c_char_p, c_double, c_int, c_size_t, c_ssize_t, c_ubyte, c_uint,
                    c_uint32, c_void_p)
from typing import Any, Callable, Dict, List, NoReturn, Sequence, Tuple, Type, Union

from ._errors import ERROR_CLASSES, BezsurfError, BezsurfIOError, io_error

BS_ERR_IO = -9

#: Major version of the C ABI this binding speaks.
ABI_MAJOR = 1

if sys.platform == "darwin":
    SONAME = "libbezsurf.1.dylib"
elif sys.platform == "win32":
    SONAME = "bezsurf.dll"
else:
    SONAME = "libbezsurf.so.1"


class View(ctypes.Structure):
    """``bs_view``: a strided output buffer of doubles (stride in bytes, 0 = packed)."""

    _fields_ = [("data", c_void_p), ("count", c_size_t), ("stride", c_ssize_t)]


class FView(ctypes.Structure):
    """``bs_fview``: a strided output buffer of floats (since 1.1)."""

    _fields_ = [("data", c_void_p), ("count", c_size_t), ("stride", c_ssize_t)]


class CView(ctypes.Structure):
    """``bs_cview``: a strided input buffer of doubles."""

    _fields_ = [("data", c_void_p), ("count", c_size_t), ("stride", c_ssize_t)]


class CCurve(ctypes.Structure):
    """``bs_curve``: a Bezier curve given to the ruled and Coons constructions."""

    _fields_ = [("degree", c_size_t), ("dim", c_size_t), ("ctrl", c_void_p), ("weights", c_void_p)]


class CParseError(ctypes.Structure):
    """``bs_parse_error``: where and why parsing failed."""

    _fields_ = [("line", c_size_t), ("column", c_size_t), ("message", ctypes.c_char * 96)]


class CBSpline(ctypes.Structure):
    """``bs_bspline``: a B-spline or NURBS surface pointing into packed arrays (since 1.1)."""

    _fields_ = [("deg_u", c_size_t), ("deg_v", c_size_t), ("count_u", c_size_t),
                ("count_v", c_size_t), ("dim", c_size_t), ("knots_u", c_void_p),
                ("knots_v", c_void_p), ("ctrl", c_void_p), ("weights", c_void_p)]


class CEdgeContinuity(ctypes.Structure):
    """``bs_edge_continuity``: how two patches meet along one shared edge."""

    _fields_ = [("patch_a", c_uint32), ("patch_b", c_uint32), ("side_a", c_int),
                ("side_b", c_int), ("reversed", c_int), ("c1", c_int), ("flipped", c_int),
                ("samples", c_int), ("c0_gap", c_double), ("g1_angle", c_double),
                ("c1_defect", c_double)]


class COpenEdge(ctypes.Structure):
    """``bs_open_edge``: a patch side no other patch shares."""

    _fields_ = [("patch", c_uint32), ("side", c_int)]


class CTessOptions(ctypes.Structure):
    """``bs_tess_options``: how bs_surface_tessellate() meshes (since 1.1; first field its size)."""

    _fields_ = [("size", c_size_t), ("method", c_int), ("flags", c_int), ("nu", c_size_t),
                ("nv", c_size_t), ("tolerance", c_double), ("max_vertices", c_size_t),
                ("max_triangles", c_size_t), ("threads", c_size_t)]


class _Status:
    """Marks a function returning ``bs_status``: negative results raise through errcheck."""


STATUS = _Status()

class CFaceInfo(ctypes.Structure):
    """``bs_face_info``: one face of a model (since 1.2); ``size`` is set before the call."""

    _fields_ = [("size", c_size_t), ("kind", c_int), ("reversed", c_int), ("shell", c_size_t),
                ("instance", c_size_t), ("first_patch", c_size_t), ("patch_count", c_size_t),
                ("loop_count", c_size_t), ("u0", c_double), ("u1", c_double), ("v0", c_double),
                ("v1", c_double)]


# Handles are opaque pointers; wrapper objects pass themselves through ``_as_parameter_``.
HANDLE = c_void_p
HANDLE_OUT = POINTER(c_void_p)
VIEWS = POINTER(View)
FVIEWS = POINTER(FView)
CVIEW = POINTER(CView)
DOUBLES = c_void_p      # a double * (input or output), passed as an address
BYTES = c_void_p        # an unsigned char * output
SIZE_OUT = POINTER(c_size_t)
CURVE = POINTER(CCurve)
PARSE_ERROR = POINTER(CParseError)
IDS = c_void_p          # a uint32_t * (input or output)

# (name, argtypes, restype): the one declaration of every C function the binding uses.
_CType = Type["ctypes._CData"]  # a ctypes type: c_int, POINTER(View), a Structure, ...
FUNCTIONS: Sequence[Tuple[str, Sequence[_CType], Union[_CType, _Status, None]]] = (
    # core.h: version and status
    ("bs_version_number", (), c_uint),
    ("bs_version_string", (), c_char_p),
    ("bs_status_string", (c_int,), c_char_p),
    # core.h: patches
    ("bs_patch_create", (c_size_t, c_size_t, c_size_t, DOUBLES, DOUBLES, HANDLE_OUT), STATUS),
    ("bs_patch_destroy", (HANDLE,), None),
    ("bs_patch_clone", (HANDLE, HANDLE_OUT), STATUS),
    ("bs_patch_degree_u", (HANDLE,), c_size_t),
    ("bs_patch_degree_v", (HANDLE,), c_size_t),
    ("bs_patch_dim", (HANDLE,), c_size_t),
    ("bs_patch_is_rational", (HANDLE,), c_int),
    ("bs_patch_get_ctrl", (HANDLE, DOUBLES, c_size_t, DOUBLES, c_size_t), STATUS),
    # core.h: evaluation
    ("bs_patch_eval", (HANDLE, c_size_t, CVIEW, CVIEW, VIEWS, VIEWS, VIEWS), STATUS),
    ("bs_patch_eval_deriv", (HANDLE, c_uint, c_uint, c_size_t, CVIEW, CVIEW, VIEWS), STATUS),
    ("bs_patch_eval_normal", (HANDLE, c_size_t, CVIEW, CVIEW, VIEWS, VIEWS, BYTES), STATUS),
    ("bs_patch_eval_grid", (HANDLE, c_size_t, CVIEW, c_size_t, CVIEW, VIEWS, VIEWS, VIEWS, VIEWS,
                            BYTES), STATUS),
    ("bs_patch_eval_grid_f32", (HANDLE, c_size_t, CVIEW, c_size_t, CVIEW, FVIEWS, FVIEWS, FVIEWS,
                                FVIEWS, BYTES), STATUS),
    # ops.h: exact operations
    ("bs_patch_split", (HANDLE, c_int, c_double, HANDLE_OUT, HANDLE_OUT), STATUS),
    ("bs_patch_split4", (HANDLE, c_double, c_double, HANDLE_OUT), STATUS),
    ("bs_patch_subpatch", (HANDLE, c_double, c_double, c_double, c_double, HANDLE_OUT), STATUS),
    ("bs_patch_elevate", (HANDLE, c_size_t, c_size_t, HANDLE_OUT), STATUS),
    ("bs_patch_derivative", (HANDLE, c_uint, c_uint, HANDLE_OUT), STATUS),
    ("bs_patch_isocurve", (HANDLE, c_int, c_double, DOUBLES, c_size_t, DOUBLES, c_size_t), STATUS),
    ("bs_patch_bounds", (HANDLE, DOUBLES, DOUBLES), STATUS),
    ("bs_patch_transform", (HANDLE, DOUBLES, HANDLE_OUT), STATUS),
    ("bs_patch_swap_uv", (HANDLE, HANDLE_OUT), STATUS),
    ("bs_patch_reverse", (HANDLE, c_int, HANDLE_OUT), STATUS),
    ("bs_patch_ruled", (CURVE, CURVE, HANDLE_OUT), STATUS),
    ("bs_patch_coons", (CURVE, CURVE, CURVE, CURVE, HANDLE_OUT), STATUS),
    # surface.h: sets of patches
    ("bs_surface_create", (HANDLE_OUT,), STATUS),
    ("bs_surface_destroy", (HANDLE,), None),
    ("bs_surface_clone", (HANDLE, HANDLE_OUT), STATUS),
    ("bs_surface_add", (HANDLE, HANDLE, SIZE_OUT), STATUS),
    ("bs_surface_count", (HANDLE,), c_size_t),
    ("bs_surface_dim", (HANDLE,), c_size_t),
    ("bs_surface_get", (HANDLE, c_size_t), HANDLE),
    ("bs_surface_eval", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, VIEWS, VIEWS, VIEWS), STATUS),
    ("bs_surface_eval_normal", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, VIEWS, VIEWS, BYTES), STATUS),
    # bspline.h (1.1): B-spline and NURBS surfaces
    ("bs_bspline_span_count", (POINTER(CBSpline), SIZE_OUT, SIZE_OUT), STATUS),
    ("bs_surface_add_bspline", (HANDLE, POINTER(CBSpline), DOUBLES, c_size_t, SIZE_OUT), STATUS),
    ("bs_bspline_locate", (POINTER(CBSpline), c_double, c_double, SIZE_OUT, POINTER(c_double),
                           POINTER(c_double)), STATUS),
    # query.h (1.1): curvature
    ("bs_patch_eval_curvature", (HANDLE, c_size_t, CVIEW, CVIEW, VIEWS, VIEWS, VIEWS, BYTES), STATUS),
    # query.h (1.1): closest points and the locator
    ("bs_patch_closest_point", (HANDLE, c_size_t, CVIEW, VIEWS, VIEWS, VIEWS), STATUS),
    ("bs_locator_create", (HANDLE, HANDLE_OUT), STATUS),
    ("bs_locator_destroy", (HANDLE,), None),
    ("bs_locator_dim", (HANDLE,), c_size_t),
    ("bs_locator_closest_point", (HANDLE, c_size_t, CVIEW, IDS, VIEWS, VIEWS, VIEWS), STATUS),
    ("bs_surface_eval_mt", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, VIEWS, VIEWS, VIEWS, c_size_t), STATUS),
    ("bs_surface_eval_grid", (HANDLE, c_size_t, CVIEW, c_size_t, CVIEW, VIEWS, VIEWS, VIEWS, VIEWS, BYTES,
                              c_size_t), STATUS),
    ("bs_surface_eval_normal_mt", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, VIEWS, VIEWS, BYTES,
                                   c_size_t), STATUS),  # since 1.2
    ("bs_locator_intersect", (HANDLE, c_size_t, CVIEW, CVIEW, CVIEW, IDS, VIEWS, VIEWS, VIEWS),
     STATUS),
    ("bs_locator_closest_point_mt", (HANDLE, c_size_t, CVIEW, IDS, VIEWS, VIEWS, VIEWS, c_size_t),
     STATUS),
    ("bs_locator_intersect_mt", (HANDLE, c_size_t, CVIEW, CVIEW, CVIEW, IDS, VIEWS, VIEWS, VIEWS,
                                 c_size_t), STATUS),
    ("bs_locator_intersect_kind", (HANDLE, c_size_t, CVIEW, CVIEW, CVIEW, IDS, VIEWS, VIEWS, VIEWS,
                                   BYTES), STATUS),
    # continuity.h
    ("bs_surface_continuity", (HANDLE, c_double, c_size_t, POINTER(CEdgeContinuity), c_size_t,
                               SIZE_OUT, POINTER(COpenEdge), c_size_t, SIZE_OUT), STATUS),
    # mesh.h: tessellation, mesh read-back and export
    ("bs_surface_tessellate_uniform", (HANDLE, c_size_t, c_size_t, c_int, HANDLE_OUT), STATUS),
    ("bs_surface_tessellate_adaptive", (HANDLE, c_double, c_int, HANDLE_OUT), STATUS),
    ("bs_tess_options_init", (POINTER(CTessOptions),), None),
    ("bs_surface_tessellate", (HANDLE, POINTER(CTessOptions), HANDLE_OUT), STATUS),
    ("bs_surface_tessellate_count", (HANDLE, POINTER(CTessOptions), SIZE_OUT, SIZE_OUT), STATUS),
    ("bs_mesh_destroy", (HANDLE,), None),
    ("bs_mesh_vertex_count", (HANDLE,), c_size_t),
    ("bs_mesh_triangle_count", (HANDLE,), c_size_t),
    ("bs_mesh_strip_count", (HANDLE,), c_size_t),
    ("bs_mesh_strip_index_count", (HANDLE,), c_size_t),
    ("bs_mesh_copy_positions", (HANDLE, VIEWS), STATUS),
    ("bs_mesh_copy_normals", (HANDLE, VIEWS), STATUS),
    ("bs_mesh_copy_uv", (HANDLE, VIEWS), STATUS),
    ("bs_mesh_copy_patch_ids", (HANDLE, IDS, c_size_t), STATUS),
    ("bs_mesh_copy_triangles", (HANDLE, IDS, c_size_t), STATUS),
    ("bs_mesh_copy_triangle_patch_ids", (HANDLE, IDS, c_size_t), STATUS),
    ("bs_mesh_copy_corner_uv", (HANDLE, VIEWS), STATUS),
    ("bs_mesh_copy_positions_f32", (HANDLE, FVIEWS), STATUS),
    ("bs_mesh_copy_normals_f32", (HANDLE, FVIEWS), STATUS),
    ("bs_mesh_copy_uv_f32", (HANDLE, FVIEWS), STATUS),
    ("bs_mesh_copy_strips", (HANDLE, IDS, c_size_t, IDS, c_size_t), STATUS),
    ("bs_mesh_write", (HANDLE, c_int, c_char_p), STATUS),
    ("bs_mesh_write_memory", (HANDLE, c_int, c_void_p, c_size_t, SIZE_OUT), STATUS),
    # io.h: the .bpt format, OBJ free-form and IGES surfaces, the built-in tea set
    ("bs_surface_read_bpt", (c_char_p, c_size_t, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_surface_read_bpt_file", (c_char_p, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_surface_write_bpt", (HANDLE, c_void_p, c_size_t, SIZE_OUT), STATUS),
    ("bs_surface_write_bpt_file", (HANDLE, c_char_p), STATUS),
    ("bs_surface_read_obj", (c_char_p, c_size_t, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_surface_read_obj_file", (c_char_p, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_surface_write_obj", (HANDLE, c_void_p, c_size_t, SIZE_OUT), STATUS),
    ("bs_surface_write_obj_file", (HANDLE, c_char_p), STATUS),
    ("bs_surface_read_iges", (c_char_p, c_size_t, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_surface_read_iges_file", (c_char_p, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_surface_create_builtin", (c_char_p, HANDLE_OUT), STATUS),
    ("bs_builtin_name", (c_size_t,), c_char_p),
    # model.h: trimmed models (since 1.2)
    ("bs_model_read_step", (c_char_p, c_size_t, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_model_read_step_file", (c_char_p, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_model_read_iges", (c_char_p, c_size_t, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_model_read_iges_file", (c_char_p, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_model_read_obj", (c_char_p, c_size_t, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_model_read_obj_file", (c_char_p, PARSE_ERROR, HANDLE_OUT), STATUS),
    ("bs_model_from_surface", (HANDLE, HANDLE_OUT), STATUS),
    ("bs_model_destroy", (HANDLE,), None),
    ("bs_model_write_obj", (HANDLE, c_void_p, c_size_t, SIZE_OUT), STATUS),
    ("bs_model_write_obj_file", (HANDLE, c_char_p), STATUS),
    ("bs_model_face_count", (HANDLE,), c_size_t),
    ("bs_model_edge_count", (HANDLE,), c_size_t),
    ("bs_model_shell_count", (HANDLE,), c_size_t),
    ("bs_model_shell_closed", (HANDLE, c_size_t), c_int),
    ("bs_model_face_info", (HANDLE, c_size_t, POINTER(CFaceInfo)), STATUS),
    ("bs_model_surface", (HANDLE,), c_void_p),
    ("bs_model_face_eval", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, VIEWS, VIEWS, BYTES), STATUS),
    ("bs_model_face_to_patch", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, IDS, VIEWS), STATUS),
    ("bs_model_patch_to_face", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, IDS, VIEWS), STATUS),
    ("bs_model_classify", (HANDLE, c_size_t, IDS, CVIEW, CVIEW, c_double, BYTES), STATUS),
    ("bs_model_properties", (HANDLE, c_double, DOUBLES, DOUBLES, DOUBLES), STATUS),
    ("bs_locator_create_model", (HANDLE, HANDLE_OUT), STATUS),
    ("bs_model_tessellate", (HANDLE, POINTER(CTessOptions), HANDLE_OUT), STATUS),
    ("bs_model_tessellate_count", (HANDLE, POINTER(CTessOptions), SIZE_OUT, SIZE_OUT), STATUS),
)

#: C functions of the library deliberately left without a binding, with the reason.
NOT_BOUND: Dict[str, str] = {}


def status_text(dll: ctypes.CDLL, code: int) -> str:
    text: bytes = dll.bs_status_string(code)
    return text.decode("utf-8", "replace")


def error_for(dll: ctypes.CDLL, code: int, function: str = "", errno: int = 0) -> BezsurfError:
    cls = ERROR_CLASSES.get(code, BezsurfError)
    if issubclass(cls, BezsurfIOError):
        return io_error(code, status_text(dll, code), function or None, None, errno, None)
    return cls(code, status_text(dll, code), function or None)


class Library:
    """The loaded shared library with every function of ``FUNCTIONS`` declared on it.

    A function the loaded library does not export (an older 1.x library) is replaced by a stub
    raising NotImplementedError when called; ``missing`` lists those names.
    """

    def __init__(self, dll: ctypes.CDLL, path: str) -> None:
        self.dll = dll
        self.path = path
        self.missing: List[str] = []
        for name, argtypes, restype in FUNCTIONS:
            try:
                fn = getattr(dll, name)
            except AttributeError:
                self.missing.append(name)
                setattr(self, name, _missing_stub(name))
                continue
            fn.argtypes = list(argtypes)
            if restype is STATUS:
                fn.restype = c_int
                fn.errcheck = self._check
            else:
                fn.restype = restype
            setattr(self, name, fn)

    def _check(self, result: int, func: object, args: Tuple[object, ...]) -> int:
        if result < 0:
            # errno as the failed call left it (the library is loaded with use_errno; callers
            # of I/O functions clear it first), read before anything else can change it
            errno = ctypes.get_errno() if result == BS_ERR_IO else 0
            raise error_for(self.dll, result, getattr(func, "__name__", ""), errno)
        return result

    # Any: a foreign function returns what its restype makes of the C result (int, bytes, None, ...)
    def __getattr__(self, name: str) -> Callable[..., Any]:
        # Only reached for names outside FUNCTIONS: a programming error in the binding.
        raise AttributeError(f"{name} is not declared in bezsurf._lib.FUNCTIONS")


def _missing_stub(name: str) -> Callable[..., NoReturn]:
    def stub(*args: object) -> NoReturn:
        raise NotImplementedError(f"the loaded libbezsurf does not export {name}")
    stub.__name__ = name
    return stub


def search_path() -> List[str]:
    """Where the library is looked for, in order (see docs/python.md, "How the library is found").

    1. ``$BEZSURF_LIBRARY`` when set (and then nothing else);
    2. the package's own directory (the library a wheel built from the sources carries);
    3. the install prefixes: ``lib``, ``lib/<multiarch>`` and ``lib64`` under ``sys.prefix``
       (a virtual environment), ``sys.base_prefix`` and ``/usr/local`` (CMake's default prefix,
       whose libraries the dynamic loader finds only after ``ldconfig``);
    4. the bare SONAME, resolved by the dynamic loader (``LD_LIBRARY_PATH``, ``ld.so.cache``,
       the system directories).
    """
    explicit = os.environ.get("BEZSURF_LIBRARY")
    if explicit:
        return [explicit]
    paths = [os.path.join(os.path.dirname(os.path.abspath(__file__)), SONAME)]
    multiarch = sysconfig.get_config_var("MULTIARCH")
    for prefix in (sys.prefix, sys.base_prefix, "/usr/local"):
        for libdir in ("lib", f"lib/{multiarch}" if multiarch else None, "lib64"):
            if libdir:
                path = os.path.join(prefix, libdir, SONAME)
                if path not in paths:
                    paths.append(path)
    paths.append(SONAME)
    return paths


def _open(path: str) -> ctypes.CDLL:
    """Load one candidate and check that it is libbezsurf of major version ABI_MAJOR."""
    dll = ctypes.CDLL(path, use_errno=True)
    try:
        fn = dll.bs_version_number
    except AttributeError:
        raise OSError(f"{path!r} is not libbezsurf (no bs_version_number)") from None
    fn.argtypes = []
    fn.restype = c_uint
    number = int(fn())
    if number // 10000 != ABI_MAJOR:
        raise OSError(f"{path!r} is libbezsurf major version {number // 10000}; this binding "
                      f"needs major version {ABI_MAJOR}")
    return dll


def load() -> Library:
    """Find and load the library, check its major version and declare its functions."""
    candidates = search_path()
    tried: List[str] = []
    for path in candidates:
        if len(candidates) > 1 and os.sep in path and not os.path.exists(path):
            continue
        try:
            return Library(_open(path), path)
        except OSError as exc:
            tried.append(str(exc))
    where = "; ".join(tried) if tried else "not found"
    raise ImportError(
        f"cannot load libbezsurf {ABI_MAJOR}.x ({where}); searched {', '.join(candidates)}. "
        f"Install libbezsurf (cmake --install) or the wheel built from its sources, or set "
        f"BEZSURF_LIBRARY to the library file")


LIB = load()

__all__ = ["ABI_MAJOR", "SONAME", "View", "FView", "CView", "CCurve", "CParseError", "CEdgeContinuity", "COpenEdge", "CTessOptions", "CFaceInfo", "FUNCTIONS", "NOT_BOUND", "Library", "LIB",
           "error_for", "c_double", "c_ubyte", "c_uint32"]
