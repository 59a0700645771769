"""Geometric queries of 1.1: certified closest points on a patch, and the Locator (closest points
and ray intersection over a whole surface)."""

import ctypes
import math
from typing import TYPE_CHECKING, Any, Dict, List, NamedTuple, Optional, Tuple, Type, Union

from . import _args as A
from . import _buffers as B
from ._buffers import (BoolOrBools, IdOrIds, KindOrKinds, PointOrPoints, PointsArg,
                       RealOrReals, RealOrRealsIn)
from ._handle import Handle
from ._lib import LIB, CView

if TYPE_CHECKING:
    from .model import Model
    from .patch import Patch
    from .surface import Surface

#: The patch id of a miss (UINT32_MAX), in Locator results.
NO_PATCH = 0xFFFFFFFF


class ClosestPoints(NamedTuple):
    """Closest points (:meth:`Patch.closest_point`, :meth:`Locator.closest_point`).

    With numpy: ``uv`` of shape (n, 2), ``dist`` of shape (n,), ``pos`` of shape (n, dim), and
    ``patch`` a uint32 array of shape (n,) (Locator only; None for one patch); else lists. For a
    single query point the leading n axis is dropped.
    """

    patch: Optional[IdOrIds]
    uv: PointOrPoints
    dist: RealOrReals
    pos: PointOrPoints


class RayHits(NamedTuple):
    """First hits of rays (:meth:`Locator.intersect`): ``patch`` ids (NO_PATCH on a miss),
    ``uv`` (n, 2), ``t`` (n,) (+inf on a miss, NaN for an invalid ray) and unit ``normal`` (n, 3).
    For a single ray the leading n axis is dropped."""

    patch: IdOrIds
    uv: PointOrPoints
    t: RealOrReals
    normal: PointOrPoints

    @property
    def hit(self) -> BoolOrBools:
        """Where a ray hit, so that a miss need not be spelled NO_PATCH (4294967295): a bool
        numpy array of shape (n,) with numpy, else a list of bools (one bool for one ray;
        since 1.2). ``hits.patch[hits.hit]`` are the patches hit."""
        patch = self.patch
        if isinstance(patch, (list, tuple)):
            return [p != NO_PATCH for p in patch]
        if B.is_ndarray(patch) and patch.ndim > 0:
            hit: BoolOrBools = patch != NO_PATCH
            return hit
        return bool(patch != NO_PATCH)  # one ray: int or numpy scalar


def _column(points: B.Points) -> Union["B.RealArray", List[float]]:
    """The single column of an (n, 1) result as (n,)."""
    if B.is_ndarray(points):
        return points[:, 0]
    return [row[0] for row in points]


# Any: as patch._squeeze, one item of the result when the query was one point
def _finish(scalar: bool, value: Any) -> Any:
    return value[0] if scalar and value is not None else value


def patch_closest_point(patch: "Patch", points: PointsArg) -> ClosestPoints:
    """The body of :meth:`Patch.closest_point`."""
    q = B.PointsIn(points, patch.dim, "points")
    uv = B.Output(q.n, 2)
    dist = B.Output(q.n, 1)
    pos = B.Output(q.n, patch.dim)
    LIB.bs_patch_closest_point(patch._ptr, q.n, q.views, uv.views, dist.views, pos.views)
    return ClosestPoints(None, _finish(q.scalar, uv.result()),
                         _finish(q.scalar, _column(dist.result())),
                         _finish(q.scalar, pos.result()))


class Locator(Handle):
    """An immutable acceleration structure over a surface for closest points and rays.

    ``Locator(surface)`` copies what it needs, so the surface may change or be closed afterwards.
    Any number of threads may query one locator at once (the library releases no lock: ctypes
    drops the GIL during each call). Points and rays are given as arrays of shape (n, dim) (or
    (dim,) for one) or sequences of tuples; results follow the rules of :class:`Patch`.
    """

    _destroy = LIB.bs_locator_destroy

    def __init__(self, surface: "Surface") -> None:
        from .surface import Surface
        A.instance(surface, Surface, "surface")
        out = ctypes.c_void_p()
        LIB.bs_locator_create(surface._ptr, ctypes.byref(out))
        self._adopt(out.value)  # type: ignore[arg-type]
        # copies and pickles rebuild the locator from the surface it was made from
        self._surface = surface.clone()

    def __reduce__(self) -> Tuple[Type["Locator"], Tuple[Union["Surface", "Model"]]]:
        self._ptr  # a closed locator is not copied
        return (Locator, (self._surface,))

    def __copy__(self) -> "Locator":
        return self  # immutable

    def __deepcopy__(self, memo: Dict[int, object]) -> "Locator":
        return Locator(self._surface)

    @property
    def dim(self) -> int:
        """Dimension of the surface (0 for an empty one)."""
        return int(LIB.bs_locator_dim(self._ptr))

    def closest_point(self, points: PointsArg, *, threads: int = 1) -> ClosestPoints:
        """The globally closest point of the whole surface to each query point, within
        1e-9 (D + d) of the exact distance d (D the diagonal of the control points' box).
        ``threads`` threads answer the queries (0: one per CPU; since 1.1), with the same
        results."""
        threads = A.integer(threads, "threads")
        # an empty surface: every query misses (patch 0xFFFFFFFF, distance inf, NaN elsewhere), as
        # every ray does in intersect(); its queries are read as 3-D points there too
        dim = self.dim or 3
        q = B.PointsIn(points, dim, "points")
        ids = B.UInt32Output(q.n, (q.n,))
        uv = B.Output(q.n, 2)
        dist = B.Output(q.n, 1)
        pos = B.Output(q.n, dim)
        LIB.bs_locator_closest_point_mt(self._ptr, q.n, q.views, ids.address, uv.views,
                                        dist.views, pos.views, threads)
        if self.dim == 0:
            pos.fill(math.nan)  # the library writes no coordinate for a surface of none
        return ClosestPoints(_finish(q.scalar, ids.ids()), _finish(q.scalar, uv.result()),
                             _finish(q.scalar, _column(dist.result())),
                             _finish(q.scalar, pos.result()))

    def intersect(self, origins: PointsArg, directions: PointsArg,
                  t_min: Optional[RealOrRealsIn] = None, t_max: Optional[RealOrRealsIn] = None,
                  *, threads: int = 1) -> RayHits:
        """The first hit of each ray o + t d with t in [t_min, t_max] (default (0, inf); either
        bound may be one number or n numbers; t_min finite, t_max finite or ``inf`` for no
        limit (since 1.2); a NaN or another infinite bound makes the ray invalid, t NaN). 3-D
        surfaces only. ``threads`` threads trace the rays (0: one per CPU; since
        1.1), with the same results."""
        hits, _ = self._trace(origins, directions, t_min, t_max, threads, False)
        return hits

    def intersect_kinds(self, origins: PointsArg, directions: PointsArg,
                        t_min: Optional[RealOrRealsIn] = None,
                        t_max: Optional[RealOrRealsIn] = None) -> Tuple[RayHits, KindOrKinds]:
        """:meth:`intersect` on one thread, with the kind of each hit's normal (NormalKind
        values as for :meth:`Patch.eval_normal`; UNDEFINED for a miss): ``(hits, kinds)``.
        Since 1.2."""
        hits, kinds = self._trace(origins, directions, t_min, t_max, 1, True)
        assert kinds is not None
        return hits, kinds

    def _trace(self, origins: PointsArg, directions: PointsArg, t_min: Optional[RealOrRealsIn],
               t_max: Optional[RealOrRealsIn], threads: int,
               with_kinds: bool) -> Tuple[RayHits, Optional[KindOrKinds]]:
        threads = A.integer(threads, "threads")
        org = B.PointsIn(origins, 3, "origins")
        dirs = B.PointsIn(directions, 3, "directions")
        if org.n != dirs.n:
            raise ValueError(f"origins and directions must have the same length "
                             f"({org.n} != {dirs.n})")
        n = org.n
        trange: Optional["ctypes.Array[CView]"] = None
        keep = []
        if t_min is not None or t_max is not None:
            trange = (CView * 2)()
            # t_max = inf is "no limit" (1.2)
            for i, (bound, default) in enumerate(((t_min, 0.0), (t_max, math.inf))):
                value = default if bound is None else bound
                if B.is_scalar(value):
                    value = [A.real(value, "t_min" if i == 0 else "t_max")] * max(n, 1)
                view = B.doubles(value, "t_min" if i == 0 else "t_max")
                if view.count < n:
                    raise ValueError(f"{'t_min' if i == 0 else 't_max'} must hold {n} values")
                keep.append(view)
                trange[i] = view.cview()
        ids = B.UInt32Output(n, (n,))
        uv = B.Output(n, 2)
        t = B.Output(n, 1)
        nrm = B.Output(n, 3)
        kinds = B.KindOutput(n) if with_kinds else None
        if kinds is not None:
            LIB.bs_locator_intersect_kind(self._ptr, n, org.views, dirs.views, trange, ids.address,
                                          uv.views, t.views, nrm.views, kinds.address)
        else:
            LIB.bs_locator_intersect_mt(self._ptr, n, org.views, dirs.views, trange, ids.address,
                                        uv.views, t.views, nrm.views, threads)
        scalar = org.scalar and dirs.scalar
        hits = RayHits(_finish(scalar, ids.ids()), _finish(scalar, uv.result()),
                       _finish(scalar, _column(t.result())), _finish(scalar, nrm.result()))
        if kinds is None:
            return hits, None
        k = kinds.result()
        return hits, (k[0] if scalar else k)

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Locator (closed)>"
        return f"<bezsurf.Locator dim {self.dim}>"
