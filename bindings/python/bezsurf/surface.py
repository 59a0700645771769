"""The Surface class: an ordered set of patches of one dimension (a quilt such as the teapot)."""

import ctypes
import numbers
import os
from typing import (Any, Callable, Dict, Iterable, Iterator, List, Literal, NamedTuple, Optional, Tuple,
                    Type, Union, overload)

from . import _args as A
from . import _buffers as B
from ._buffers import Point, PointOrPoints, Points
from ._enums import SIDES, Side, TessMethod
from ._errors import (BezsurfError, BezsurfIOError, DomainError, InvalidArgumentError,
                      ParseError, UnsupportedError, io_error, with_detail)
from ._handle import Handle
from ._lib import LIB, CEdgeContinuity, COpenEdge, CParseError
from .bspline import BSpline
from .mesh import Mesh, TessOptionsArgs, explain_tessellation, tess_options
from .query import Locator
from .patch import (Evaluation, Nested, OutArray, Params, ParamSeq, Patch, _Call,
                    _check_requested)

#: Sides of a patch's unit square (BS_SIDE_*), counter-clockwise.
SIDE_V0 = Side.V0
SIDE_U1 = Side.U1
SIDE_V1 = Side.V1
SIDE_U0 = Side.U0

#: Patch ids of a scattered evaluation: one id for all points, a sequence or a numpy array.
Ids = B.IdsIn


class EdgeContinuity(NamedTuple):
    """How two patches meet along one shared edge (see :meth:`Surface.continuity`)."""

    patch_a: int
    patch_b: int
    side_a: Side
    side_b: Side
    reversed: bool
    c1: bool
    flipped: bool
    samples: int
    c0_gap: float
    g1_angle: float
    c1_defect: float


class OpenEdge(NamedTuple):
    """A patch side that no other patch shares."""

    patch: int
    side: Side


class Continuity(NamedTuple):
    """Shared edges with their continuity measures, and open edges."""

    edges: List[EdgeContinuity]
    open_edges: List[OpenEdge]


def builtin_names() -> List[str]:
    """Names of the built-in surfaces ("teapot", "teacup", "teaspoon", ...)."""
    names: List[str] = []
    while True:
        name = LIB.bs_builtin_name(len(names))
        if name is None:
            return names
        names.append(name.decode("ascii"))


#: Surface file formats by extension (lower case), as the ``bezsurf`` tool reads them.
_SURFACE_EXTENSIONS = {".bpt": "bpt", ".obj": "obj", ".igs": "iges", ".iges": "iges"}


def _surface_format(path: A.PathArg, format: Optional[str], default: str) -> str:
    """The format named by ``format`` ("bpt", "obj", "iges", "igs"), else by the extension of
    ``path``, else ``default``."""
    if format is None:
        try:
            ext = os.path.splitext(os.fsdecode(path))[1].lower()
        except TypeError:
            raise TypeError(f"path must be a str, bytes or os.PathLike, not "
                            f"{type(path).__name__}") from None
        return _SURFACE_EXTENSIONS.get(ext, default)
    if not isinstance(format, str) or format.lower() not in ("bpt", "obj", "iges", "igs"):
        raise ValueError(f"format must be one of 'bpt', 'obj', 'iges', not {format!r}")
    return "iges" if format.lower() == "igs" else format.lower()


def _located(exc: BezsurfError, err: CParseError, filename: Optional[str] = None) -> BezsurfError:
    """The parse or I/O error with the library's position and reason, and the file, attached."""
    reason = err.message.decode("utf-8", "replace") or None
    if isinstance(exc, ParseError):
        return ParseError(exc.code, exc.message, exc.function, reason,
                          err.line or None, err.column or None, filename)
    if isinstance(exc, BezsurfIOError):
        return io_error(exc.code, exc.message, exc.function, reason, exc.errno, filename)
    if isinstance(exc, UnsupportedError) and err.line:
        return UnsupportedError(exc.code, exc.message, exc.function,
                                f"line {err.line}, column {err.column}: {reason}")
    return exc


def _with_file(exc: BezsurfIOError, filename: str) -> BezsurfIOError:
    return io_error(exc.code, exc.message, exc.function, exc.detail, exc.errno, filename)


class Surface(Handle):
    """An ordered, growable set of patches of one dimension (degrees and rationality may differ).

    ``Surface(patches=())`` creates a surface holding copies of the given patches. Indexing gives
    a patch borrowed from the surface: it keeps the surface alive and cannot be used once the
    surface is closed (``clone()`` it for an independent copy). A surface is a context manager.
    """

    _destroy = LIB.bs_surface_destroy

    def __init__(self, patches: Iterable[Patch] = ()) -> None:
        if not isinstance(patches, Iterable):
            raise TypeError(f"patches must be an iterable of bezsurf.Patch, not "
                            f"{type(patches).__name__}")
        items = list(patches)
        for i, p in enumerate(items):
            A.instance(p, Patch, f"patches[{i}]")
        handle = ctypes.c_void_p()
        LIB.bs_surface_create(ctypes.byref(handle))
        self._adopt(handle.value)  # type: ignore[arg-type]
        for p in items:
            self.add(p)

    @classmethod
    def _wrap(cls, handle: Optional[int]) -> "Surface":
        s = cls.__new__(cls)
        s._adopt(handle)  # type: ignore[arg-type]
        return s

    @classmethod
    def builtin(cls, name: str) -> "Surface":
        """A new copy of a built-in surface: "teapot" (32 bicubic patches, Z up), "teacup"
        (26, Y up) or "teaspoon" (16, Y up), Newell's tea set. See :func:`builtin_names`."""
        if not isinstance(name, str):
            raise TypeError(f"name must be a str, not {type(name).__name__}")
        out = ctypes.c_void_p()
        try:
            LIB.bs_surface_create_builtin(name.encode("utf-8"), ctypes.byref(out))
        except InvalidArgumentError as exc:
            names = ", ".join(builtin_names())
            raise with_detail(exc, f"name {name!r} is not a built-in surface (names are "
                                   f"case-sensitive: {names})") from None
        return cls._wrap(out.value)

    @classmethod
    def _read_text(cls, reader: Callable[..., object], text: Union[str, bytes]) -> "Surface":
        """A new surface from text through a C reader of (text, len, err, out)."""
        if isinstance(text, str):
            data = text.encode("utf-8")
        elif isinstance(text, (bytes, bytearray, memoryview)):
            data = bytes(text)
        else:
            raise TypeError(f"text must be a str or bytes, not {type(text).__name__}")
        err = CParseError()
        out = ctypes.c_void_p()
        try:
            reader(data, len(data), ctypes.byref(err), ctypes.byref(out))
        except BezsurfError as exc:
            raise _located(exc, err) from None
        return cls._wrap(out.value)

    @classmethod
    def _read_file(cls, reader: Callable[..., object], path: A.PathArg) -> "Surface":
        """A new surface from a file through a C reader of (path, err, out)."""
        name = A.path(path)
        err = CParseError()
        out = ctypes.c_void_p()
        ctypes.set_errno(0)
        try:
            reader(name, ctypes.byref(err), ctypes.byref(out))
        except BezsurfError as exc:
            raise _located(exc, err, os.fsdecode(name)) from None
        return cls._wrap(out.value)

    def _write_text(self, writer: Callable[..., object]) -> str:
        """The text a C writer of (surface, buf, cap, size) produces."""
        size = ctypes.c_size_t()
        writer(self._ptr, None, 0, ctypes.byref(size))
        buf = ctypes.create_string_buffer(size.value)
        writer(self._ptr, buf, size.value, ctypes.byref(size))
        return buf.value.decode("ascii")

    def _write_file(self, writer: Callable[..., object], path: A.PathArg) -> None:
        """Write a file through a C writer of (surface, path)."""
        name = A.path(path)
        ctypes.set_errno(0)
        try:
            writer(self._ptr, name)
        except BezsurfIOError as exc:
            raise _with_file(exc, os.fsdecode(name)) from None

    @classmethod
    def from_bpt(cls, text: Union[str, bytes]) -> "Surface":
        """Parse .bpt text (str or bytes) into a new surface of 3-D patches.
        Raises ParseError with ``line``, ``column`` and ``detail`` when the text is malformed."""
        return cls._read_text(LIB.bs_surface_read_bpt, text)

    @classmethod
    def load(cls, path: A.PathArg, format: Optional[str] = None) -> "Surface":
        """Read a surface file in the format its extension names, as the ``bezsurf`` tool does:
        .obj (:meth:`load_obj`), .igs or .iges (:meth:`load_iges`), any other .bpt; ``format``
        ("bpt", "obj", "iges" or "igs") overrides the extension (1.2: 1.1 read .bpt whatever
        the name). Raises BezsurfIOError (an OSError with ``errno`` and ``filename``, e.g. a
        FileNotFoundError) when it cannot be read and ParseError (with line, column and
        filename) when it is malformed."""
        fmt = _surface_format(path, format, "bpt")
        reader = {"bpt": LIB.bs_surface_read_bpt_file, "obj": LIB.bs_surface_read_obj_file,
                  "iges": LIB.bs_surface_read_iges_file}[fmt]
        return cls._read_file(reader, path)

    def to_bpt(self) -> str:
        """The surface as .bpt text; numbers read back bit for bit (3-D patches only)."""
        return self._write_text(LIB.bs_surface_write_bpt)

    def save(self, path: A.PathArg, format: Optional[str] = None) -> None:
        """Write the surface file (created or truncated) in the format its extension names, as
        the ``bezsurf`` tool does: .obj (:meth:`save_obj`), any other .bpt; ``format`` ("bpt"
        or "obj") overrides it; IGES is read only (ValueError). 1.1 wrote .bpt whatever the
        name. Raises BezsurfIOError (an OSError with ``errno`` and ``filename``) when the file
        cannot be written."""
        fmt = _surface_format(path, format, "bpt")
        if fmt == "iges":
            raise ValueError(f"path {os.fsdecode(path)!r}: IGES is read, not written; "
                             f"use format='bpt' or 'obj'")
        self._write_file(LIB.bs_surface_write_obj_file if fmt == "obj"
                         else LIB.bs_surface_write_bpt_file, path)

    @classmethod
    def read_obj(cls, text: Union[str, bytes]) -> "Surface":
        """Parse the free-form surfaces of Wavefront OBJ text (Bezier and B-spline, rational or
        not; a B-spline over its ``surf`` range) into Bezier patches (docs/formats.md). Raises
        ParseError with ``line`` and ``column`` when the text is malformed, UnsupportedError (its
        ``detail`` naming the line) for bmatrix, cardinal and taylor surfaces."""
        return cls._read_text(LIB.bs_surface_read_obj, text)

    @classmethod
    def load_obj(cls, path: A.PathArg) -> "Surface":
        """Read an OBJ file's free-form surfaces (as :meth:`read_obj`). Raises BezsurfIOError
        when it cannot be read."""
        return cls._read_file(LIB.bs_surface_read_obj_file, path)

    def to_obj(self) -> str:
        """The surface as OBJ free-form text, one ``cstype [rat] bezier`` surface per patch;
        reads back bit for bit (3-D patches only)."""
        return self._write_text(LIB.bs_surface_write_obj)

    def save_obj(self, path: A.PathArg) -> None:
        """Write the surface as an OBJ file (created or truncated). Raises BezsurfIOError when
        the file cannot be written."""
        self._write_file(LIB.bs_surface_write_obj_file, path)

    @classmethod
    def read_iges(cls, text: Union[str, bytes]) -> "Surface":
        """Parse IGES 5.3 text: every rational B-spline surface (entity 128), with its
        transformations (entity 124), restricted to its parameter range, as Bezier patches
        (docs/formats.md). Raises ParseError with ``line`` (the record's line) and ``column``."""
        return cls._read_text(LIB.bs_surface_read_iges, text)

    @classmethod
    def load_iges(cls, path: A.PathArg) -> "Surface":
        """Read an IGES file (as :meth:`read_iges`). Raises BezsurfIOError when it cannot be
        read."""
        return cls._read_file(LIB.bs_surface_read_iges_file, path)

    def add(self, patch: Patch) -> int:
        """Append a copy of ``patch``; returns its index (patch id). Raises IncompatibleError if
        its dimension differs from the surface's."""
        A.instance(patch, Patch, "patch")
        index = ctypes.c_size_t()
        LIB.bs_surface_add(self._ptr, patch._ptr, ctypes.byref(index))
        return index.value

    def add_bspline(self, bspline: BSpline) -> Points:
        """Append a B-spline or NURBS surface as one Bezier patch per knot span: span (a, b) becomes
        patch ``len(self) + a * spans_v + b`` (len before the call). Returns each added patch's
        span (u0, u1, v0, v1), shape (patches, 4). On any error the surface is unchanged."""
        A.instance(bspline, BSpline, "bspline")
        return bspline._add_to(self._ptr)

    @classmethod
    def from_bspline(cls, ctrl: Nested, knots_u: ParamSeq, knots_v: ParamSeq,
                     weights: Optional[Nested] = None) -> "Surface":
        """A new surface of the Bezier patches of a B-spline or NURBS surface; the arguments are
        those of :class:`BSpline`."""
        s = cls()
        s.add_bspline(BSpline(ctrl, knots_u, knots_v, weights))
        return s

    def clone(self) -> "Surface":
        """An independent copy of the surface and its patches."""
        out = ctypes.c_void_p()
        LIB.bs_surface_clone(self._ptr, ctypes.byref(out))
        return Surface._wrap(out.value)

    __copy__ = clone

    def __deepcopy__(self, memo: Dict[int, object]) -> "Surface":
        return self.clone()

    def __reduce__(self) -> Tuple[Type["Surface"], Tuple[List[Patch]]]:
        # The patches' control data, rebuilt by Surface(patches) on load.
        return (Surface, (list(self),))

    @property
    def dim(self) -> int:
        """Dimension of the patches; 0 while the surface is empty."""
        return int(LIB.bs_surface_dim(self._ptr))

    def __len__(self) -> int:
        return int(LIB.bs_surface_count(self._ptr))

    @overload
    def __getitem__(self, index: int) -> Patch: ...

    @overload
    def __getitem__(self, index: slice) -> "Surface": ...

    def __getitem__(self, index: Union[int, slice]) -> Union[Patch, "Surface"]:
        """``surface[i]``: patch i, borrowed from the surface (negative i counts from the end).
        ``surface[a:b:c]``: a new surface holding copies of those patches, renumbered from 0."""
        n = len(self)
        if isinstance(index, slice):
            return Surface([self[i] for i in range(*index.indices(n))])
        if isinstance(index, bool) or not isinstance(index, numbers.Integral) and \
                not hasattr(index, "__index__"):
            raise TypeError(f"surface indices must be integers or slices, not "
                            f"{type(index).__name__}")
        i = index.__index__()
        if i < 0:
            i += n
        if not 0 <= i < n:
            raise IndexError(f"patch index {index} out of range for a surface of {n} patches")
        handle = LIB.bs_surface_get(self._ptr, i)
        return Patch._wrap(handle, parent=self)

    def __iter__(self) -> Iterator[Patch]:
        for i in range(len(self)):
            yield self[i]

    # ---- evaluation --------------------------------------------------------------------------
    @overload
    def eval(self, ids: int, u: float, v: float, *, derivatives: Literal[False] = ...,
             normals: Literal[False] = ..., out: OutArray = ..., threads: int = ...) -> Point: ...

    @overload
    def eval(self, ids: Ids, u: ParamSeq, v: Params, *, derivatives: Literal[False] = ...,
             normals: Literal[False] = ..., out: OutArray = ..., threads: int = ...) -> Points: ...

    @overload
    def eval(self, ids: Ids, u: Params, v: ParamSeq, *, derivatives: Literal[False] = ...,
             normals: Literal[False] = ..., out: OutArray = ..., threads: int = ...) -> Points: ...

    @overload
    def eval(self, ids: Ids, u: Params, v: Params, *, derivatives: Literal[True],
             normals: bool = ..., out: OutArray = ..., du_out: OutArray = ...,
             dv_out: OutArray = ..., normal_out: OutArray = ...,
             kind_out: OutArray = ..., threads: int = ...) -> Evaluation: ...

    @overload
    def eval(self, ids: Ids, u: Params, v: Params, *, derivatives: bool = ...,
             normals: Literal[True], out: OutArray = ..., du_out: OutArray = ...,
             dv_out: OutArray = ..., normal_out: OutArray = ...,
             kind_out: OutArray = ..., threads: int = ...) -> Evaluation: ...

    @overload
    def eval(self, ids: Ids, u: Params, v: Params, *, derivatives: bool = ...,
             normals: bool = ..., out: OutArray = ..., du_out: OutArray = ...,
             dv_out: OutArray = ..., normal_out: OutArray = ...,
             kind_out: OutArray = ..., threads: int = ...) -> Union[PointOrPoints, Evaluation]: ...

    def eval(self, ids: Ids, u: Params, v: Params, *, derivatives: bool = False,
             normals: bool = False, out: OutArray = None, du_out: OutArray = None,
             dv_out: OutArray = None, normal_out: OutArray = None,
             kind_out: OutArray = None, threads: int = 1) -> object:
        """Evaluate at n scattered points: point k lies on patch ids[k] at (u[k], v[k]).

        ``ids`` is a sequence or numpy array of patch indices, or one index for every point.
        Results and keyword arguments as :meth:`Patch.eval` (positions of shape (n, dim), or an
        :class:`Evaluation`); sorting points by id is fastest. ``threads`` threads evaluate the
        positions and partials (0: one per CPU; since 1.1) and the normals (since 1.2:
        bs_surface_eval_normal_mt), with the same results bit for bit.
        """
        threads = A.integer(threads, "threads")
        _check_requested(derivatives, normals, du_out, dv_out, normal_out, kind_out)
        call = _Call(u, v, inputs=[("ids", ids)])
        if isinstance(ids, numbers.Integral) and not isinstance(ids, bool) and not call.scalar:
            ids = [int(ids)] * call.n
        keep, id_addr, nid = B.uint32s(ids, "ids")
        if nid != call.n:
            raise ValueError(f"ids and u must have the same length ({nid} != {call.n})")
        dim = self.dim
        pos = call.output(dim, out, "out")
        dus = dvs = nrm = kinds = None
        if derivatives:
            dus = call.output(dim, du_out, "du_out")
            dvs = call.output(dim, dv_out, "dv_out")
        if normals:
            nrm = call.output(3, normal_out, "normal_out")
            kinds = call.kinds(kind_out)
        call.check_disjoint()
        try:
            if normals:  # first, so that a failure leaves every output untouched
                assert nrm is not None and kinds is not None
                # one thread: the 1.0 function, so that a 1.0 or 1.1 library serves too
                normal_args = (self._ptr, call.n, id_addr, call.u, call.v,
                               None if derivatives else pos.views, nrm.views, kinds.address)
                if threads == 1:
                    LIB.bs_surface_eval_normal(*normal_args)
                else:
                    LIB.bs_surface_eval_normal_mt(*normal_args, threads)
            if derivatives or not normals:
                LIB.bs_surface_eval_mt(self._ptr, call.n, id_addr, call.u, call.v, pos.views,
                                       dus.views if dus else None, dvs.views if dvs else None,
                                       threads)
        except InvalidArgumentError as exc:
            raise self._bad_id(exc, id_addr, nid) from None
        del keep
        if not derivatives and not normals:
            return call.finish(pos.result())
        return Evaluation(*(call.finish(x.result() if x is not None else None)
                            for x in (pos, dus, dvs, nrm, kinds)))

    def _bad_id(self, exc: InvalidArgumentError, id_addr: int, nid: int) -> BezsurfError:
        """``exc`` naming the first id that is not a patch of this surface, if one is not."""
        count = len(self)
        ids: List[int] = list((ctypes.c_uint32 * nid).from_address(id_addr)) if nid else []
        for k, i in enumerate(ids):
            if i >= count:
                limit = f"0..{count - 1}" if count else "none: the surface is empty"
                return with_detail(exc, f"ids[{k}] = {i} is not a patch of this surface "
                                        f"(patch ids {limit})")
        return exc

    def eval_normal(self, ids: Ids, u: Params, v: Params, *, out: OutArray = None,
                    normal_out: OutArray = None, kind_out: OutArray = None,
                    threads: int = 1) -> Evaluation:
        """Positions, unit normals and kinds at scattered points of a 3-D surface
        (``eval(ids, u, v, normals=True)``), on ``threads`` threads (0: one per CPU; since 1.2,
        bs_surface_eval_normal_mt) with the same results bit for bit as one thread."""
        return self.eval(ids, u, v, normals=True, out=out, normal_out=normal_out,
                         kind_out=kind_out, threads=threads)

    @overload
    def eval_grid(self, u: Params, v: Params, *, normals: Literal[False] = ...,
                  threads: int = ...) -> Points: ...

    @overload
    def eval_grid(self, u: Params, v: Params, *, normals: Literal[True],
                  threads: int = ...) -> Evaluation: ...

    @overload
    def eval_grid(self, u: Params, v: Params, *, normals: bool = ...,
                  threads: int = ...) -> Union[Points, Evaluation]: ...

    def eval_grid(self, u: Params, v: Params, *, normals: bool = False,
                  threads: int = 1) -> Union[Points, Evaluation]:
        """Positions (or with ``normals`` an :class:`Evaluation` of positions, normals and
        kinds) on the tensor grid u x v of every patch, through bs_surface_eval_grid (1.1) on
        ``threads`` threads (0: one per CPU; the same bits for every count). Point (u[a], v[b])
        of patch p is row (p * len(u) + a) * len(v) + b: with numpy an array of shape
        (count * nu * nv, dim), reshape it to (count, nu, nv, dim)."""
        threads = A.integer(threads, "threads")
        call = _Call(u, v, grid=True)
        n = len(self) * call.n
        pos = B.Output(n, self.dim)
        nrm = B.Output(n, 3) if normals else None
        kinds = B.KindOutput(n, None) if normals else None
        LIB.bs_surface_eval_grid(self._ptr, call.nu, call.u, call.nv, call.v, pos.views, None,
                                 None, nrm.views if nrm else None,
                                 kinds.address if kinds else None, threads)
        positions: Points = pos.result()
        if not normals:
            return positions
        assert nrm is not None and kinds is not None
        return Evaluation(positions, None, None, nrm.result(), kinds.result())

    def continuity(self, tol: float = 1e-9, samples: int = 32) -> Continuity:
        """Shared and open edges of a 3-D surface and the continuity across each shared edge.

        ``tol`` (absolute, per coordinate) matches sides and bounds the C1 test; ``samples``
        (1..4096) normals per edge measure the G1 angle. Returns a :class:`Continuity` of
        :class:`EdgeContinuity` and :class:`OpenEdge` lists.
        """
        tol = A.real(tol, "tol")
        samples = A.integer(samples, "samples")
        n_edges, n_open = ctypes.c_size_t(), ctypes.c_size_t()
        LIB.bs_surface_continuity(self._ptr, tol, samples, None, 0, ctypes.byref(n_edges),
                                  None, 0, ctypes.byref(n_open))
        edges = (CEdgeContinuity * max(n_edges.value, 1))()
        opens = (COpenEdge * max(n_open.value, 1))()
        LIB.bs_surface_continuity(self._ptr, tol, samples, edges, n_edges.value,
                                  ctypes.byref(n_edges), opens, n_open.value, ctypes.byref(n_open))
        return Continuity(
            [EdgeContinuity(e.patch_a, e.patch_b, SIDES[e.side_a], SIDES[e.side_b],
                            bool(e.reversed), bool(e.c1), bool(e.flipped), e.samples, e.c0_gap,
                            e.g1_angle, e.c1_defect)
             for e in edges[: n_edges.value]],
            [OpenEdge(o.patch, SIDES[o.side]) for o in opens[: n_open.value]])

    # ---- tessellation --------------------------------------------------------------------------
    def tessellate(self, nu: int, nv: Optional[int] = None, *, strips: bool = False,
                   max_vertices: int = 0, max_triangles: int = 0, threads: int = 1,
                   reverse: bool = False) -> Mesh:
        """A crack-free triangle mesh with nu x nv segments per patch (nv defaults to nu);
        ``strips`` also builds triangle strips. ``max_vertices`` and ``max_triangles`` (0: no
        limit) are budgets: a larger mesh raises SizeError before anything large is allocated.
        ``threads`` threads sample the vertices (0: one per CPU; since 1.1); the mesh is the same
        bit for bit whatever their number. ``reverse`` (since 1.2, BS_TESS_REVERSE) reverses the
        triangles' winding and negates the normals: the built-in teapot's patches face into the
        pot, ``reverse=True`` makes its mesh face outwards."""
        args = self._tess_args(TessMethod.UNIFORM, nu, nv, 1e-3, False, strips, max_vertices,
                               max_triangles, threads, reverse)
        if not (max_vertices or max_triangles) and args[7] == 1:
            return Mesh._tessellate(self.clone(), "uniform", (args[2], args[3], args[1]))
        return Mesh._tessellate(self.clone(), "options", args)

    def tessellate_adaptive(self, tolerance: float, *, relative: bool = False,
                            strips: bool = False, subdivide: bool = False,
                            max_vertices: int = 0, max_triangles: int = 0,
                            threads: int = 1, reverse: bool = False) -> Mesh:
        """A crack-free mesh whose triangles lie within ``tolerance`` of the surface (a distance,
        or with ``relative`` a fraction of the control points' bounding-box diagonal). One
        segment count per patch, or with ``subdivide`` a quadtree of sub-patches refined only
        where the surface curves (since 1.1). Budgets, threads and ``reverse`` as in
        :meth:`tessellate`."""
        method = TessMethod.SUBDIVIDE if subdivide else TessMethod.PER_PATCH
        args = self._tess_args(method, 16, 16, tolerance, relative, strips, max_vertices,
                               max_triangles, threads, reverse)
        if method == TessMethod.PER_PATCH and not (max_vertices or max_triangles) and args[7] == 1:
            return Mesh._tessellate(self.clone(), "adaptive", (args[4], args[1]))
        return Mesh._tessellate(self.clone(), "options", args)

    def tessellate_count(self, nu: Optional[int] = None, nv: Optional[int] = None, *,
                         tolerance: Optional[float] = None, relative: bool = False,
                         strips: bool = False, subdivide: bool = False,
                         reverse: bool = False) -> Tuple[int, int]:
        """(vertices, triangles) of the mesh :meth:`tessellate` (nu, nv) or
        :meth:`tessellate_adaptive` (tolerance) would make, computed without building it."""
        if (nu is None) == (tolerance is None):
            raise ValueError("give either nu (uniform) or tolerance (adaptive)")
        if nu is not None:
            args = self._tess_args(TessMethod.UNIFORM, nu, nv, 1e-3, False, strips, 0, 0, 1,
                                   reverse)
        else:
            method = TessMethod.SUBDIVIDE if subdivide else TessMethod.PER_PATCH
            args = self._tess_args(method, 16, 16, tolerance, relative, strips, 0, 0, 1, reverse)
        nverts = ctypes.c_size_t()
        ntris = ctypes.c_size_t()
        try:
            LIB.bs_surface_tessellate_count(self._ptr, ctypes.byref(tess_options(*args)),
                                            ctypes.byref(nverts), ctypes.byref(ntris))
        except DomainError as exc:
            raise explain_tessellation(exc, self, "options", args) from None
        return int(nverts.value), int(ntris.value)

    @staticmethod
    def _tess_args(method: int, nu: object, nv: object, tolerance: object, relative: bool,
                   strips: bool, max_vertices: object, max_triangles: object, threads: object = 1,
                   reverse: bool = False) -> TessOptionsArgs:
        """The checked fields of a bs_tess_options, in the order tess_options() takes them."""
        nu = A.integer(nu, "nu")
        nv = nu if nv is None else A.integer(nv, "nv")
        flags = (1 if relative else 0) | (2 if strips else 0) | (4 if reverse else 0)
        return (int(method), flags, nu, nv, A.real(tolerance, "tolerance"),
                A.integer(max_vertices, "max_vertices"), A.integer(max_triangles, "max_triangles"),
                A.integer(threads, "threads"))

    def locator(self) -> "Locator":
        """A :class:`Locator` for closest points and rays on this surface (since 1.1)."""
        return Locator(self)

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Surface (closed)>"
        return f"<bezsurf.Surface {len(self)} patches dim {self.dim}>"
