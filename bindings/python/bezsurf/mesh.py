"""The Mesh class: an immutable indexed triangle mesh made by tessellating a surface."""

import ctypes
import os
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Optional, Tuple, Union, cast

from . import _args as A
from . import _buffers as B
from ._buffers import IdRows, Ids, Points
from ._enums import Format
from ._errors import BezsurfError, BezsurfIOError, DomainError, SizeError, io_error, with_detail
from ._handle import Handle
from ._lib import LIB, CTessOptions

if TYPE_CHECKING:
    from .model import Model
    from .surface import Surface

#: Export formats of :meth:`Mesh.write` by name (Format members and their names work too).
FORMATS = {f.name.lower(): f for f in Format}

FormatArg = Union[Format, int, str]

#: Formats of :meth:`Mesh.write` by file extension (lower case), as ``bezsurf tessellate``.
EXTENSIONS = {".obj": Format.OBJ, ".ply": Format.PLY, ".stl": Format.STL}


def format_of_path(path: A.PathArg) -> Format:
    """The mesh format a file name's extension names (:data:`EXTENSIONS`); ValueError for
    another one."""
    ext = os.path.splitext(os.fsdecode(path))[1].lower()
    try:
        return EXTENSIONS[ext]
    except KeyError:
        known = ", ".join(EXTENSIONS)
        raise ValueError(f"path {os.fsdecode(path)!r}: unknown mesh extension {ext or '(none)'!r}; "
                         f"use one of {known} or pass format=") from None


OutArray = B.OutArray

#: The fields of a bs_tess_options, in the order tess_options() takes them.
TessOptionsArgs = Tuple[int, int, int, int, float, int, int, int]
#: Tessellation arguments as a mesh keeps them: (nu, nv, flags) for "uniform", (tolerance, flags)
#: for "adaptive", else TessOptionsArgs; ints but for the tolerance.
TessArgs = Tuple[Union[int, float], ...]


def tess_options(method: int, flags: int, nu: int, nv: int, tolerance: float,
                 max_vertices: int, max_triangles: int, threads: int = 1) -> CTessOptions:
    """A ``bs_tess_options`` filled by the library's defaults, then with these values."""
    o = CTessOptions()
    LIB.bs_tess_options_init(ctypes.byref(o))
    o.method, o.flags, o.nu, o.nv = method, flags, nu, nv
    o.tolerance, o.max_vertices, o.max_triangles = tolerance, max_vertices, max_triangles
    o.threads = threads
    return o


#: The tessellators' largest rate per patch and direction (BS_TESS_MAX_RATE).
TESS_MAX_RATE = 1024


def explain_tessellation(exc: BezsurfError, surface: "Surface", method: str, args: "TessArgs") -> BezsurfError:
    """A tessellator's error with the argument, its value and the limit it broke."""
    if method == "uniform":
        args = (0, args[2], args[0], args[1], 1e-3, 0, 0)
    elif method == "adaptive":
        args = (1, args[1], 16, 16, args[0], 0, 0)
    kind, flags, nu, nv, tol, max_v, max_t = args[:7]
    if isinstance(exc, DomainError):
        for name, rate in (("nu", nu), ("nv", nv)):
            if kind == 0 and not 1 <= rate <= TESS_MAX_RATE:
                return with_detail(exc, f"{name} = {rate} segments per patch is outside "
                                        f"1..{TESS_MAX_RATE} (BS_TESS_MAX_RATE)")
        if kind != 0:
            return with_detail(exc, f"tolerance = {tol!r} must be finite and > 0")
    if isinstance(exc, SizeError):
        nverts, ntris = ctypes.c_size_t(), ctypes.c_size_t()
        try:
            LIB.bs_surface_tessellate_count(surface._ptr, ctypes.byref(
                tess_options(*cast(TessOptionsArgs, (kind, flags, nu, nv, tol, 0, 0, 1)))),
                ctypes.byref(nverts),
                ctypes.byref(ntris))
        except BezsurfError:
            return exc
        over = [f"{n} = {limit}" for n, limit, have in (("max_vertices", max_v, nverts.value),
                                                        ("max_triangles", max_t, ntris.value))
                if limit and have > limit]
        return with_detail(exc, f"the mesh would have {nverts.value} vertices and {ntris.value} "
                                f"triangles, over " + (" and ".join(over) if over else
                                "the 32-bit index limit (4294967294 vertices, 1431655765 "
                                "triangles)"))
    return exc


class Mesh(Handle):
    """An immutable triangle mesh (from :meth:`Surface.tessellate` or
    :meth:`Surface.tessellate_adaptive`).

    Vertices carry a position, a unit normal, a (u, v) pair and the id of the patch they were
    evaluated on; triangles are counter-clockwise index triples seen from the side the normals
    point to. The read-back methods return numpy arrays written in place by the library whenever
    numpy is importable (float arrays in Fortran order; ``out=`` takes any float64 array of the
    shape), else lists of tuples. A mesh is a context manager; ``close()`` releases it at once.

    A mesh remembers how it was made (a copy of the surface and the tessellation parameters):
    ``copy.copy``, ``copy.deepcopy`` and pickling rebuild it from that, and tessellation is
    deterministic, so the copy has the same vertices and triangles bit for bit.
    """

    _destroy = LIB.bs_mesh_destroy
    _recipe: Tuple[Union["Surface", "Model"], str, "TessArgs"]

    def __init__(self) -> None:
        raise TypeError("meshes are made by Surface.tessellate() and Surface.tessellate_adaptive()")

    @classmethod
    def _tessellate(cls, surface: Union["Surface", "Model"], method: str,
                    args: "TessArgs") -> "Mesh":
        """Tessellate ``surface`` (a copy the mesh keeps as its recipe): a Surface, or a Model
        for method "model"."""
        out = ctypes.c_void_p()
        try:
            if method == "uniform":
                LIB.bs_surface_tessellate_uniform(surface._ptr, *args, ctypes.byref(out))
            elif method == "adaptive":
                LIB.bs_surface_tessellate_adaptive(surface._ptr, *args, ctypes.byref(out))
            elif method == "model":
                LIB.bs_model_tessellate(surface._ptr, ctypes.byref(tess_options(*cast(TessOptionsArgs, args))),
                                        ctypes.byref(out))
            elif method == "options":
                LIB.bs_surface_tessellate(surface._ptr, ctypes.byref(tess_options(*cast(TessOptionsArgs, args))),
                                          ctypes.byref(out))
            else:
                raise ValueError(f"unknown tessellation method {method!r}")
        except (DomainError, SizeError) as exc:
            if method == "model":
                raise
            raise explain_tessellation(exc, cast("Surface", surface), method, args) from None
        m = cls.__new__(cls)
        m._adopt(out.value)  # type: ignore[arg-type]
        m._recipe = (surface, method, args)
        return m

    def _remake(self) -> "Mesh":
        self._ptr  # a closed mesh is not copied
        surface, method, args = self._recipe
        return Mesh._tessellate(surface.clone(), method, args)

    def __copy__(self) -> "Mesh":
        return self._remake()

    def __deepcopy__(self, memo: Dict[int, object]) -> "Mesh":
        return self._remake()

    def __reduce__(self) -> Tuple[Callable[[Union["Surface", "Model"], str, "TessArgs"], "Mesh"],
                                  Tuple[Union["Surface", "Model"], str, "TessArgs"]]:
        self._ptr  # a closed mesh is not pickled
        return (Mesh._tessellate, self._recipe)

    @property
    def vertex_count(self) -> int:
        """Number of vertices."""
        return int(LIB.bs_mesh_vertex_count(self._ptr))

    @property
    def triangle_count(self) -> int:
        """Number of triangles."""
        return int(LIB.bs_mesh_triangle_count(self._ptr))

    @property
    def strip_count(self) -> int:
        """Number of triangle strips (0 unless tessellated with ``strips=True``)."""
        return int(LIB.bs_mesh_strip_count(self._ptr))

    def _views(self, fn: Callable[..., object], n: int, k: int, out: OutArray,
               float32: bool = False) -> Points:
        res = B.Output(n, k, out, "out", float32)
        fn(self._ptr, res.views)
        return res.result()

    def positions(self, *, out: OutArray = None, float32: bool = False) -> Points:
        """Vertex positions, (vertex_count, 3); with ``float32`` as float32, each value the
        double correctly rounded (since 1.1)."""
        fn = LIB.bs_mesh_copy_positions_f32 if float32 else LIB.bs_mesh_copy_positions
        return self._views(fn, self.vertex_count, 3, out, float32)

    def normals(self, *, out: OutArray = None, float32: bool = False) -> Points:
        """Unit vertex normals, (vertex_count, 3); never NaN. ``float32`` as for positions()."""
        fn = LIB.bs_mesh_copy_normals_f32 if float32 else LIB.bs_mesh_copy_normals
        return self._views(fn, self.vertex_count, 3, out, float32)

    def uv(self, *, out: OutArray = None, float32: bool = False) -> Points:
        """Vertex (u, v) parameters on the patch each vertex was evaluated on, (vertex_count, 2).
        ``float32`` as for positions()."""
        fn = LIB.bs_mesh_copy_uv_f32 if float32 else LIB.bs_mesh_copy_uv
        return self._views(fn, self.vertex_count, 2, out, float32)

    def corner_uv(self, *, out: OutArray = None) -> Points:
        """(u, v) of every triangle corner on the triangle's own patch, (3 * triangle_count, 2)."""
        return self._views(LIB.bs_mesh_copy_corner_uv, 3 * self.triangle_count, 2, out)

    def _ids(self, fn: Callable[..., object], count: int, shape: Tuple[int, ...]) -> B.UInt32Output:
        res = B.UInt32Output(count, shape)
        fn(self._ptr, res.address, count)
        return res

    def patch_ids(self) -> Ids:
        """Per vertex, the id of the patch it was evaluated on (uint32)."""
        n = self.vertex_count
        return self._ids(LIB.bs_mesh_copy_patch_ids, n, (n,)).ids()

    def triangles(self) -> IdRows:
        """Vertex index triples, (triangle_count, 3) (uint32)."""
        n = self.triangle_count
        return self._ids(LIB.bs_mesh_copy_triangles, 3 * n, (n, 3)).rows()

    def triangle_patch_ids(self) -> Ids:
        """Per triangle, the id of the patch it tessellates (uint32)."""
        n = self.triangle_count
        return self._ids(LIB.bs_mesh_copy_triangle_patch_ids, n, (n,)).ids()

    def strips(self) -> List[List[int]]:
        """The triangle strips as lists of vertex indices. Triangle i of a strip s is
        (s[i], s[i+1], s[i+2]) for even i and (s[i+1], s[i], s[i+2]) for odd i; triangles with
        a repeated index (at poles) are degenerate and to be dropped. A mesh made without
        ``strips=True`` has none: ValueError (1.2; 1.1 returned [])."""
        _, method, args = self._recipe
        flags = cast(int, args[2] if method == "uniform" else args[1])  # the flags are an int
        if not flags & 2:  # BS_TESS_STRIPS
            raise ValueError("the mesh was made without strips: tessellate with strips=True")
        nidx = int(LIB.bs_mesh_strip_index_count(self._ptr))
        nstart = self.strip_count + 1
        idx = B.UInt32Output(nidx, (nidx,), lists=True)
        start = B.UInt32Output(nstart, (nstart,), lists=True)
        LIB.bs_mesh_copy_strips(self._ptr, idx.address, nidx, start.address, nstart)
        flat, offsets = idx.values(), start.values()
        return [flat[offsets[k]:offsets[k + 1]] for k in range(nstart - 1)]

    def write(self, path: A.PathArg, format: Optional[FormatArg] = None) -> None:
        """Write the mesh to a file: Format.OBJ ("obj", Wavefront OBJ), Format.PLY ("ply",
        binary little-endian), Format.PLY_ASCII ("ply_ascii") or Format.STL ("stl", binary).
        Without ``format``, the format follows the file's extension as ``bezsurf tessellate``
        does: .obj, .ply (binary) or .stl, in any case; another extension raises ValueError
        (1.2: 1.1 wrote OBJ whatever the name). Raises BezsurfIOError (an OSError with
        ``errno`` and ``filename``) on failure."""
        name = A.path(path)
        fmt = format_of_path(name) if format is None else A.mesh_format(format)
        ctypes.set_errno(0)
        try:
            LIB.bs_mesh_write(self._ptr, fmt, name)
        except BezsurfIOError as exc:
            raise io_error(exc.code, exc.message, exc.function, exc.detail, exc.errno,
                           os.fsdecode(name)) from None

    def to_bytes(self, format: FormatArg = Format.OBJ) -> bytes:
        """The bytes :meth:`write` would put in a file."""
        fmt = A.mesh_format(format)
        size = ctypes.c_size_t()
        LIB.bs_mesh_write_memory(self._ptr, fmt, None, 0, ctypes.byref(size))
        buf = ctypes.create_string_buffer(max(size.value, 1))
        LIB.bs_mesh_write_memory(self._ptr, fmt, buf, size.value, ctypes.byref(size))
        return buf.raw[: size.value]

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Mesh (closed)>"
        return f"<bezsurf.Mesh {self.vertex_count} vertices {self.triangle_count} triangles>"
