"""The Surface class: an ordered set of patches of one dimension (a quilt such as the teapot)."""

import ctypes
import os
import numbers
from typing import Any, Iterable, Iterator, List, NamedTuple, Optional, Union

from . import _buffers as B
from ._errors import BezsurfError, BezsurfIOError, ParseError
from ._handle import Handle
from ._lib import LIB, CEdgeContinuity, COpenEdge, CParseError
from .mesh import Mesh
from .patch import Evaluation, Patch, _Call, _check_requested

#: Sides of a patch's unit square (BS_SIDE_*), counter-clockwise.
SIDE_V0 = 0
SIDE_U1 = 1
SIDE_V1 = 2
SIDE_U0 = 3


class EdgeContinuity(NamedTuple):
    """How two patches meet along one shared edge (see :meth:`Surface.continuity`)."""

    patch_a: int
    patch_b: int
    side_a: int
    side_b: int
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
    side: int


class Continuity(NamedTuple):
    """Shared edges with their continuity measures, and open edges."""

    edges: List[EdgeContinuity]
    open_edges: List[OpenEdge]

PathLike = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]


def builtin_names() -> List[str]:
    """Names of the built-in surfaces ("teapot", "teacup", "teaspoon", ...)."""
    names = []
    while True:
        name = LIB.bs_builtin_name(len(names))
        if name is None:
            return names
        names.append(name.decode("ascii"))


def _located(exc: BezsurfError, err: CParseError) -> BezsurfError:
    """The parse or I/O error with the library's position and reason attached."""
    reason = err.message.decode("utf-8", "replace") or None
    if isinstance(exc, ParseError):
        return ParseError(exc.code, exc.message, exc.function, reason,
                          err.line or None, err.column or None)
    if isinstance(exc, BezsurfIOError):
        return BezsurfIOError(exc.code, exc.message, exc.function, reason)
    return exc


class Surface(Handle):
    """An ordered, growable set of patches of one dimension (degrees and rationality may differ).

    ``Surface(patches=())`` creates a surface holding copies of the given patches. Indexing gives
    a patch borrowed from the surface: it keeps the surface alive and cannot be used once the
    surface is closed (``clone()`` it for an independent copy). A surface is a context manager.
    """

    _destroy = LIB.bs_surface_destroy

    def __init__(self, patches: Iterable[Patch] = ()) -> None:
        handle = ctypes.c_void_p()
        LIB.bs_surface_create(ctypes.byref(handle))
        self._adopt(handle.value)  # type: ignore[arg-type]
        for p in patches:
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
        out = ctypes.c_void_p()
        LIB.bs_surface_create_builtin(name.encode("utf-8"), ctypes.byref(out))
        return cls._wrap(out.value)

    @classmethod
    def from_bpt(cls, text: Union[str, bytes]) -> "Surface":
        """Parse .bpt text (str or bytes) into a new surface of 3-D patches.
        Raises ParseError with ``line``, ``column`` and ``detail`` when the text is malformed."""
        data = text.encode("utf-8") if isinstance(text, str) else bytes(text)
        err = CParseError()
        out = ctypes.c_void_p()
        try:
            LIB.bs_surface_read_bpt(data, len(data), ctypes.byref(err), ctypes.byref(out))
        except BezsurfError as exc:
            raise _located(exc, err) from None
        return cls._wrap(out.value)

    @classmethod
    def load(cls, path: PathLike) -> "Surface":
        """Read a .bpt file. Raises BezsurfIOError (an OSError) when it cannot be read and
        ParseError (with line and column) when it is malformed."""
        err = CParseError()
        out = ctypes.c_void_p()
        try:
            LIB.bs_surface_read_bpt_file(os.fsencode(path), ctypes.byref(err), ctypes.byref(out))
        except BezsurfError as exc:
            raise _located(exc, err) from None
        return cls._wrap(out.value)

    def to_bpt(self) -> str:
        """The surface as .bpt text; numbers read back bit for bit (3-D patches only)."""
        size = ctypes.c_size_t()
        LIB.bs_surface_write_bpt(self._ptr, None, 0, ctypes.byref(size))
        buf = ctypes.create_string_buffer(size.value)
        LIB.bs_surface_write_bpt(self._ptr, buf, size.value, ctypes.byref(size))
        return buf.value.decode("ascii")

    def save(self, path: PathLike) -> None:
        """Write the surface as a .bpt file (created or truncated)."""
        LIB.bs_surface_write_bpt_file(self._ptr, os.fsencode(path))

    def add(self, patch: Patch) -> int:
        """Append a copy of ``patch``; returns its index (patch id). Raises IncompatibleError if
        its dimension differs from the surface's."""
        index = ctypes.c_size_t()
        LIB.bs_surface_add(self._ptr, patch._ptr, ctypes.byref(index))
        return index.value

    def clone(self) -> "Surface":
        """An independent copy of the surface and its patches."""
        out = ctypes.c_void_p()
        LIB.bs_surface_clone(self._ptr, ctypes.byref(out))
        return Surface._wrap(out.value)

    __copy__ = clone

    def __deepcopy__(self, memo: Any) -> "Surface":
        return self.clone()

    @property
    def dim(self) -> int:
        """Dimension of the patches; 0 while the surface is empty."""
        return int(LIB.bs_surface_dim(self._ptr))

    def __len__(self) -> int:
        return int(LIB.bs_surface_count(self._ptr))

    def __getitem__(self, index: int) -> Patch:
        n = len(self)
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
    def eval(self, ids: Any, u: Any, v: Any, *, derivatives: bool = False, normals: bool = False,
             out: Any = None, du_out: Any = None, dv_out: Any = None, normal_out: Any = None,
             kind_out: Any = None) -> Any:
        """Evaluate at n scattered points: point k lies on patch ids[k] at (u[k], v[k]).

        ``ids`` is a sequence or numpy array of patch indices, or one index for every point.
        Results and keyword arguments as :meth:`Patch.eval`; sorting points by id is fastest.
        """
        _check_requested(derivatives, normals, du_out, dv_out, normal_out, kind_out)
        call = _Call(u, v, (out, du_out, dv_out, normal_out, kind_out, ids))
        if isinstance(ids, numbers.Integral) and not call.scalar:
            ids = [int(ids)] * call.n
        keep, id_addr, nid, _ = B.uint32s(ids, "ids")
        if nid != call.n:
            raise ValueError(f"ids and u must have the same length ({nid} != {call.n})")
        dim = self.dim
        pos = call.output(dim, out, "out")
        dus = dvs = nrm = kinds = None
        if derivatives:
            dus = call.output(dim, du_out, "du_out")
            dvs = call.output(dim, dv_out, "dv_out")
        if normals:  # first, so that a failure leaves every output untouched
            nrm = call.output(3, normal_out, "normal_out")
            kinds = B.KindOutput(call.n, call.numpy, kind_out)
            LIB.bs_surface_eval_normal(self._ptr, call.n, id_addr, call.u, call.v,
                                       None if derivatives else pos.views, nrm.views,
                                       kinds.address)
        if derivatives or not normals:
            LIB.bs_surface_eval(self._ptr, call.n, id_addr, call.u, call.v, pos.views,
                                dus.views if dus else None, dvs.views if dvs else None)
        del keep
        if not derivatives and not normals:
            return call.finish(pos.result())
        return Evaluation(*(call.finish(x.result() if x is not None else None)
                            for x in (pos, dus, dvs, nrm, kinds)))

    def eval_normal(self, ids: Any, u: Any, v: Any, **outputs: Any) -> Evaluation:
        """Positions, unit normals and kinds at scattered points of a 3-D surface
        (``eval(ids, u, v, normals=True)``)."""
        return self.eval(ids, u, v, normals=True, **outputs)  # type: ignore[no-any-return]

    def continuity(self, tol: float = 1e-9, samples: int = 32) -> Continuity:
        """Shared and open edges of a 3-D surface and the continuity across each shared edge.

        ``tol`` (absolute, per coordinate) matches sides and bounds the C1 test; ``samples``
        (1..4096) normals per edge measure the G1 angle. Returns a :class:`Continuity` of
        :class:`EdgeContinuity` and :class:`OpenEdge` lists.
        """
        n_edges, n_open = ctypes.c_size_t(), ctypes.c_size_t()
        LIB.bs_surface_continuity(self._ptr, tol, samples, None, 0, ctypes.byref(n_edges),
                                  None, 0, ctypes.byref(n_open))
        edges = (CEdgeContinuity * max(n_edges.value, 1))()
        opens = (COpenEdge * max(n_open.value, 1))()
        LIB.bs_surface_continuity(self._ptr, tol, samples, edges, n_edges.value,
                                  ctypes.byref(n_edges), opens, n_open.value, ctypes.byref(n_open))
        return Continuity(
            [EdgeContinuity(e.patch_a, e.patch_b, e.side_a, e.side_b, bool(e.reversed), bool(e.c1),
                            bool(e.flipped), e.samples, e.c0_gap, e.g1_angle, e.c1_defect)
             for e in edges[: n_edges.value]],
            [OpenEdge(o.patch, o.side) for o in opens[: n_open.value]])

    # ---- tessellation --------------------------------------------------------------------------
    def tessellate(self, nu: int, nv: Optional[int] = None, *, strips: bool = False) -> Mesh:
        """A crack-free triangle mesh with nu x nv segments per patch (nv defaults to nu);
        ``strips`` also builds triangle strips."""
        out = ctypes.c_void_p()
        LIB.bs_surface_tessellate_uniform(self._ptr, nu, nu if nv is None else nv,
                                          2 if strips else 0, ctypes.byref(out))
        return Mesh._wrap(out.value)

    def tessellate_adaptive(self, tolerance: float, *, relative: bool = False,
                            strips: bool = False) -> Mesh:
        """A crack-free mesh whose triangles lie within ``tolerance`` of the surface (a distance,
        or with ``relative`` a fraction of the control points' bounding-box diagonal)."""
        out = ctypes.c_void_p()
        flags = (1 if relative else 0) | (2 if strips else 0)
        LIB.bs_surface_tessellate_adaptive(self._ptr, tolerance, flags, ctypes.byref(out))
        return Mesh._wrap(out.value)

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Surface (closed)>"
        return f"<bezsurf.Surface {len(self)} patches dim {self.dim}>"
