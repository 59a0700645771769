"""The BSpline class: a B-spline or NURBS surface, cut into Bezier patches by a Surface."""

import ctypes
from typing import List, Optional, Tuple, Type

from . import _args as A
from . import _buffers as B
from ._lib import LIB, CBSpline
from .patch import Nested


def _degree(nknots: int, count: int, what: str) -> int:
    degree = nknots - count - 1
    if degree < 1:
        raise ValueError(f"{what} must hold count + degree + 1 values with degree >= 1: got "
                         f"{nknots} knots for {count} control points")
    return degree


class BSpline:
    """A B-spline or NURBS surface.

    ``BSpline(ctrl, knots_u, knots_v, weights=None)``: ``ctrl`` of shape (count_u, count_v, dim)
    (row i along u), one knot vector per direction with count + degree + 1 non-decreasing values
    (the degrees follow from the lengths), ``weights`` None or of shape (count_u, count_v) for a
    NURBS. Numpy arrays or nested sequences; packed copies are kept. The values are checked by
    the library when the B-spline is used (DomainError for bad knots, NonFiniteError for bad
    points or weights, ...). :meth:`Surface.add_bspline` appends one Bezier patch per knot span.

    >>> b = BSpline([[[0, 0, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]]],
    ...             [0, 0, 1, 2, 2], [0, 0, 1, 1])
    >>> b.degree, b.span_count()
    ((1, 1), (2, 1))
    >>> b.locate(1.5, 0.25)
    (1, 0.5, 0.25)
    """

    __slots__ = ("_raw", "_keep", "_args")

    def __init__(self, ctrl: Nested, knots_u: B.RealsIn, knots_v: B.RealsIn,
                 weights: Optional[Nested] = None) -> None:
        count_u, count_v, dim, keep, ctrl_addr, w_addr = B.flat_net(ctrl, weights, "ctrl")
        (nku,), ku = B.nested_doubles(knots_u, 1, "knots_u")
        (nkv,), kv = B.nested_doubles(knots_v, 1, "knots_v")
        deg_u = _degree(nku, count_u, "knots_u")
        deg_v = _degree(nkv, count_v, "knots_v")
        self._raw = CBSpline(deg_u, deg_v, count_u, count_v, dim, ku.buffer_info()[0],
                             kv.buffer_info()[0], ctrl_addr, w_addr)
        self._keep = (keep, ku, kv)
        self._args = (ctrl, knots_u, knots_v, weights)

    @property
    def degree(self) -> Tuple[int, int]:
        """(degree along u, degree along v)."""
        return int(self._raw.deg_u), int(self._raw.deg_v)

    @property
    def count(self) -> Tuple[int, int]:
        """Control points along u and along v."""
        return int(self._raw.count_u), int(self._raw.count_v)

    @property
    def dim(self) -> int:
        """Dimension of a control point."""
        return int(self._raw.dim)

    @property
    def rational(self) -> bool:
        """True for a NURBS (weights given)."""
        return bool(self._raw.weights)

    def span_count(self) -> Tuple[int, int]:
        """Knot spans along u and v: :meth:`Surface.add_bspline` adds their product of patches."""
        nu, nv = ctypes.c_size_t(), ctypes.c_size_t()
        LIB.bs_bspline_span_count(ctypes.byref(self._raw), ctypes.byref(nu), ctypes.byref(nv))
        return nu.value, nv.value

    def locate(self, u: float, v: float) -> Tuple[int, float, float]:
        """(index, local u, local v) of B-spline parameter (u, v): the index counts from the first
        patch :meth:`Surface.add_bspline` added. Spans are half-open, the last one closed.
        Raises DomainError outside the domain or for NaN."""
        u = A.real(u, "u")
        v = A.real(v, "v")
        index = ctypes.c_size_t()
        lu, lv = ctypes.c_double(), ctypes.c_double()
        LIB.bs_bspline_locate(ctypes.byref(self._raw), u, v, ctypes.byref(index),
                              ctypes.byref(lu), ctypes.byref(lv))
        return index.value, lu.value, lv.value

    def _add_to(self, surface_ptr: ctypes.c_void_p) -> B.Points:
        nu, nv = self.span_count()
        res = B.Output(nu * nv, 4, what="spans")
        # The library writes u0 u1 v0 v1 per patch packed; read through a packed scratch copy.
        packed = (ctypes.c_double * max(4 * nu * nv, 1))()
        added = ctypes.c_size_t()
        LIB.bs_surface_add_bspline(surface_ptr, ctypes.byref(self._raw), ctypes.addressof(packed),
                                   4 * nu * nv, ctypes.byref(added))
        rows: List[Tuple[float, ...]] = [tuple(packed[4 * k: 4 * k + 4])
                                         for k in range(added.value)]
        if res.array is not None:
            for k, row in enumerate(rows):
                res.array[k, :] = row
            result: B.Points = res.array
            return result
        return rows

    def __reduce__(self) -> Tuple[Type["BSpline"], Tuple[Nested, B.RealsIn, B.RealsIn, Optional[Nested]]]:
        return (BSpline, self._args)

    def __repr__(self) -> str:
        kind = "NURBS" if self.rational else "B-spline"
        return (f"<bezsurf.BSpline {kind} degree {self.degree}, {self.count[0]}x{self.count[1]} "
                f"points, dim {self.dim}>")
