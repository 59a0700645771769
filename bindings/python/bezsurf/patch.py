"""The Patch class: one rectangular tensor-product Bezier patch."""

import array
import ctypes
from typing import (TYPE_CHECKING, Any, Dict, List, Literal, NamedTuple, Optional, Sequence,
                    SupportsFloat, Tuple, Type, Union, cast, overload)

from . import _args as A
from . import _buffers as B
from ._buffers import KindOrKinds, Point, PointOrPoints, Points
from ._enums import CurvatureKind, Direction, NormalKind
from ._errors import DegreeError, DimensionError, with_detail
from ._handle import Handle
from ._lib import LIB, CCurve

try:  # numpy is optional
    import numpy as np
except ImportError:  # pragma: no cover - depends on the interpreter
    np = None  # type: ignore[assignment]

if TYPE_CHECKING:
    from .query import ClosestPoints

#: Directions for split(), isocurve() and reverse(); 'u' and 'v' are accepted as well.
DIR_U = Direction.U
DIR_V = Direction.V

#: Normal kinds written by the normal evaluators.
NORMAL_REGULAR = NormalKind.REGULAR
NORMAL_LIMIT = NormalKind.LIMIT
NORMAL_UNDEFINED = NormalKind.UNDEFINED

#: A direction: Direction.U / Direction.V, 0 / 1, or "u" / "v".
DirectionArg = Union[Direction, int, str]
#: Evaluation parameters: a real number, a sequence of them, array.array('d'), memoryview or
#: numpy array (any real dtype, any stride).
ParamSeq = B.RealsIn
Params = Union[float, ParamSeq]
#: A control net (deg_u+1, deg_v+1, dim), a weight grid, a curve's points or a matrix: nested
#: sequences of real numbers or a numpy array.
Nested = B.Nested
#: An ``out=`` array: a numpy array of the result's dtype (float64, float32 or uint8) and shape.
OutArray = B.OutArray

class Curve(NamedTuple):
    """A Bezier curve: its control points and, when rational, its weights (else None).

    ``points`` is a list of tuples (or any nested sequence or numpy array of shape
    (degree+1, dim)); ``weights`` None or degree+1 positive numbers. Returned by
    :meth:`Patch.isocurve` and accepted by :meth:`Patch.ruled` and :meth:`Patch.coons`, which
    also take a bare sequence of points for a polynomial curve.
    """

    points: B.Grid
    weights: Optional[B.Reals] = None


class Evaluation(NamedTuple):
    """Results of an evaluation; fields that were not asked for are None.

    With numpy each field is a numpy array (``position``, ``du``, ``dv``: float64 of shape
    (n, dim); ``normal``: (n, 3); ``kind``: uint8 of shape (n,)), else a list of n tuples
    (``kind``: a list of :class:`NormalKind`). For scalar u and v the leading n axis is dropped.
    """

    position: PointOrPoints
    du: Optional[PointOrPoints] = None
    dv: Optional[PointOrPoints] = None
    normal: Optional[PointOrPoints] = None
    kind: Optional[KindOrKinds] = None


def _check_requested(derivatives: bool, normals: bool, du_out: object, dv_out: object,
                     normal_out: object, kind_out: object) -> None:
    """An output array given for a result that was not asked for is a mistake, not a no-op."""
    if not derivatives and (du_out is not None or dv_out is not None):
        raise ValueError("du_out and dv_out need derivatives=True")
    if not normals and (normal_out is not None or kind_out is not None):
        raise ValueError("normal_out and kind_out need normals=True")


#: CurvatureKind members indexed by their value.
CURVATURE_KINDS = tuple(CurvatureKind)


class Curvature(NamedTuple):
    """Curvatures and principal directions (:meth:`Patch.eval_curvature`).

    With numpy: ``gaussian``, ``mean``, ``k_min``, ``k_max`` float64 arrays of shape (n,),
    ``d_min``, ``d_max`` of shape (n, 3), ``kind`` uint8 of shape (n,); else lists (``kind``: of
    :class:`CurvatureKind`). For scalar u and v the leading n axis is dropped.
    """

    gaussian: B.RealOrReals
    mean: B.RealOrReals
    k_min: B.RealOrReals
    k_max: B.RealOrReals
    d_min: PointOrPoints
    d_max: PointOrPoints
    kind: Union["B.UInt8Array", List[CurvatureKind], CurvatureKind, "np.uint8"]


# Any: the result is one point, kind or number of a result when u and v were scalars, which is
# known at run time only; the public overloads state the precise types.
def _squeeze(value: Any) -> Any:
    """The single point of a one-point result (scalar parameters)."""
    if value is None:
        return None
    return value[0]


_MAX_DEGREE = 64  # BS_MAX_DEGREE
_MAX_DIM = 8      # BS_MAX_DIM


class Patch(Handle):
    """A rectangular tensor-product Bezier patch (immutable).

    ``Patch(net, weights=None)`` builds a patch from its control net: any nested sequence or
    array of shape (deg_u+1, deg_v+1, dim), row i along u, column j along v, so that
    S(u, v) = sum_ij B_i(u) B_j(v) P_ij. ``weights`` (shape (deg_u+1, deg_v+1), all finite and
    positive) makes the patch rational; control points are Cartesian, not pre-multiplied.
    The library copies both.

    Parameters of the evaluators (u, v) may be real numbers, lists, tuples, ``array.array('d')``,
    memoryviews of doubles or numpy arrays. Results are numpy arrays of shape (n, dim) written in
    place by the library whenever numpy is importable (Fortran order: each coordinate contiguous,
    the library's fastest layout; pass ``out=`` to reuse an array of any layout), otherwise lists
    of n tuples. u and v outside [0, 1] extrapolate.

    Errors from the library raise :class:`bezsurf.BezsurfError` subclasses. A patch is a context
    manager; ``close()`` releases it at once.

    Example::

        >>> p = Patch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
        >>> x, y, z = p.eval(0.5, 0.5)
        >>> print(x, y, z)
        0.5 0.5 0.25
    """

    _destroy = LIB.bs_patch_destroy

    def __init__(self, net: Nested, weights: Optional[Nested] = None) -> None:
        rows, cols, dim, keep, ctrl, w = B.flat_net(net, weights)
        handle = ctypes.c_void_p()
        try:
            LIB.bs_patch_create(rows - 1, cols - 1, dim, ctrl, w, ctypes.byref(handle))
        except DegreeError as exc:
            raise with_detail(exc, f"a net of {rows} x {cols} points has degrees {rows - 1} x "
                                   f"{cols - 1}, above the limit {_MAX_DEGREE} (BS_MAX_DEGREE)") from None
        except DimensionError as exc:
            raise with_detail(exc, f"points of dimension {dim}, outside 1..{_MAX_DIM} "
                                   f"(BS_MAX_DIM)") from None
        del keep
        self._adopt(handle.value)  # type: ignore[arg-type]

    @classmethod
    def _wrap(cls, handle: Optional[int], parent: Optional[Handle] = None) -> "Patch":
        p = cls.__new__(cls)
        p._adopt(handle, parent)  # type: ignore[arg-type]
        return p

    # ---- properties -----------------------------------------------------------------------
    @property
    def degree_u(self) -> int:
        """Degree along u (rows of the net minus one)."""
        return int(LIB.bs_patch_degree_u(self._ptr))

    @property
    def degree_v(self) -> int:
        """Degree along v (columns of the net minus one)."""
        return int(LIB.bs_patch_degree_v(self._ptr))

    @property
    def degree(self) -> Tuple[int, int]:
        """(degree_u, degree_v)."""
        return self.degree_u, self.degree_v

    @property
    def dim(self) -> int:
        """Dimension of a control point."""
        return int(LIB.bs_patch_dim(self._ptr))

    @property
    def rational(self) -> bool:
        """True if the patch has weights."""
        return bool(LIB.bs_patch_is_rational(self._ptr))

    @property
    def shape(self) -> Tuple[int, int, int]:
        """Shape of the control net: (degree_u+1, degree_v+1, dim)."""
        return self.degree_u + 1, self.degree_v + 1, self.dim

    @property
    def ctrl(self) -> List[List[Tuple[float, ...]]]:
        """The control net as nested lists: ``ctrl[i][j]`` is the point tuple P_ij."""
        shape = self.shape
        buf = array.array("d", bytes(8 * shape[0] * shape[1] * shape[2]))
        LIB.bs_patch_get_ctrl(self._ptr, buf.buffer_info()[0], len(buf), None, 0)
        net: List[List[Tuple[float, ...]]] = B.nested(buf, shape)
        return net

    @property
    def weights(self) -> Optional[List[List[float]]]:
        """The weights as nested lists ``weights[i][j]``, or None for a polynomial patch."""
        if not self.rational:
            return None
        rows, cols, _ = self.shape
        buf = array.array("d", bytes(8 * rows * cols))
        LIB.bs_patch_get_ctrl(self._ptr, None, 0, buf.buffer_info()[0], len(buf))
        return [list(buf[i * cols:(i + 1) * cols]) for i in range(rows)]

    def ctrl_array(self, out: OutArray = None) -> "B.FloatArray":
        """The control net as a numpy array of shape (deg_u+1, deg_v+1, dim), written by the
        library into ``out`` (a C-contiguous float64 array of that shape) or a new array."""
        B.need_numpy()
        # the dtype of out is checked by _check_packed
        arr = cast("B.FloatArray", out) if out is not None else np.empty(self.shape)
        _check_packed(arr, self.shape, "out")
        LIB.bs_patch_get_ctrl(self._ptr, arr.ctypes.data, arr.size, None, 0)
        return arr

    def weights_array(self, out: OutArray = None) -> "B.FloatArray":
        """The weights as a numpy array of shape (deg_u+1, deg_v+1); all ones when polynomial."""
        B.need_numpy()
        shape = self.shape[:2]
        arr = cast("B.FloatArray", out) if out is not None else np.empty(shape)
        _check_packed(arr, shape, "out")
        LIB.bs_patch_get_ctrl(self._ptr, None, 0, arr.ctypes.data, arr.size)
        return arr

    def clone(self) -> "Patch":
        """An independent copy (bs_patch_clone)."""
        out = ctypes.c_void_p()
        LIB.bs_patch_clone(self._ptr, ctypes.byref(out))
        return Patch._wrap(out.value)

    __copy__ = clone

    def __deepcopy__(self, memo: Dict[int, object]) -> "Patch":
        return self.clone()

    def __reduce__(self) -> Tuple[Type["Patch"], Tuple[List[List[Tuple[float, ...]]],
                                                       Optional[List[List[float]]]]]:
        # The control data, rebuilt by Patch(net, weights) on load (also for borrowed patches).
        return (Patch, (self.ctrl, self.weights))

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Patch (closed)>"
        kind = "rational" if self.rational else "polynomial"
        return f"<bezsurf.Patch degree ({self.degree_u}, {self.degree_v}) dim {self.dim} {kind}>"

    # ---- evaluation -----------------------------------------------------------------------
    @overload
    def eval(self, u: float, v: float, *, derivatives: Literal[False] = ...,
             normals: Literal[False] = ..., out: OutArray = ...) -> Point: ...

    @overload
    def eval(self, u: ParamSeq, v: Params, *, derivatives: Literal[False] = ...,
             normals: Literal[False] = ..., out: OutArray = ...) -> Points: ...

    @overload
    def eval(self, u: Params, v: ParamSeq, *, derivatives: Literal[False] = ...,
             normals: Literal[False] = ..., out: OutArray = ...) -> Points: ...

    @overload
    def eval(self, u: Params, v: Params, *, derivatives: Literal[True], normals: bool = ...,
             out: OutArray = ..., du_out: OutArray = ..., dv_out: OutArray = ...,
             normal_out: OutArray = ..., kind_out: OutArray = ...) -> Evaluation: ...

    @overload
    def eval(self, u: Params, v: Params, *, derivatives: bool = ..., normals: Literal[True],
             out: OutArray = ..., du_out: OutArray = ..., dv_out: OutArray = ...,
             normal_out: OutArray = ..., kind_out: OutArray = ...) -> Evaluation: ...

    @overload
    def eval(self, u: Params, v: Params, *, derivatives: bool = ..., normals: bool = ...,
             out: OutArray = ..., du_out: OutArray = ..., dv_out: OutArray = ...,
             normal_out: OutArray = ...,
             kind_out: OutArray = ...) -> Union[PointOrPoints, Evaluation]: ...

    def eval(self, u: Params, v: Params, *, derivatives: bool = False, normals: bool = False,
             out: OutArray = None, du_out: OutArray = None, dv_out: OutArray = None,
             normal_out: OutArray = None, kind_out: OutArray = None) -> object:
        """Evaluate the patch at the n points (u[k], v[k]).

        Returns the positions S(u, v), shape (n, dim), unless ``derivatives`` or ``normals`` is
        set; then an :class:`Evaluation` with ``position`` and, on request, the first partial
        derivatives ``du``, ``dv`` and the unit ``normal`` with its ``kind`` (a
        :class:`NormalKind`; 3-D patches only). Scalar u and v give one point.
        ``out``, ``du_out``, ``dv_out`` (float64, shape (n, dim)), ``normal_out`` (n, 3) and
        ``kind_out`` (uint8, n) are numpy arrays written in place instead of new results; they
        must not overlap each other or the inputs.
        """
        _check_requested(derivatives, normals, du_out, dv_out, normal_out, kind_out)
        call = _Call(u, v)
        pos = call.output(self.dim, out, "out")
        dus = dvs = nrm = kinds = None
        if derivatives:
            dus = call.output(self.dim, du_out, "du_out")
            dvs = call.output(self.dim, dv_out, "dv_out")
        if normals:
            nrm = call.output(3, normal_out, "normal_out")
            kinds = call.kinds(kind_out)
        call.check_disjoint()
        # Normals first: their call fails (dimension) before anything is written, so a failure
        # leaves every output untouched, as a single C call would.
        if normals:
            assert nrm is not None and kinds is not None
            LIB.bs_patch_eval_normal(self._ptr, call.n, call.u, call.v,
                                     None if derivatives else pos.views, nrm.views, kinds.address)
        if derivatives or not normals:
            LIB.bs_patch_eval(self._ptr, call.n, call.u, call.v, pos.views,
                              dus.views if dus else None, dvs.views if dvs else None)
        if not derivatives and not normals:
            return call.finish(pos.result())
        return Evaluation(*(call.finish(x.result() if x is not None else None)
                            for x in (pos, dus, dvs, nrm, kinds)))

    @overload
    def eval_deriv(self, ku: int, kv: int, u: float, v: float, *,
                   out: OutArray = ...) -> Point: ...

    @overload
    def eval_deriv(self, ku: int, kv: int, u: ParamSeq, v: Params, *,
                   out: OutArray = ...) -> Points: ...

    @overload
    def eval_deriv(self, ku: int, kv: int, u: Params, v: ParamSeq, *,
                   out: OutArray = ...) -> Points: ...

    def eval_deriv(self, ku: int, kv: int, u: Params, v: Params, *,
                   out: OutArray = None) -> object:
        """The mixed partial derivative d^(ku+kv) S / du^ku dv^kv at the n points (u[k], v[k]).

        Orders beyond the degree give zero (polynomial patches); (0, 0) gives positions. Result
        shape (n, dim), like :meth:`eval`.
        """
        ku = A.integer(ku, "ku", 0, A.UINT_MAX)
        kv = A.integer(kv, "kv", 0, A.UINT_MAX)
        call = _Call(u, v)
        res = call.output(self.dim, out, "out")
        call.check_disjoint()
        LIB.bs_patch_eval_deriv(self._ptr, ku, kv, call.n, call.u, call.v, res.views)
        return call.finish(res.result())

    def eval_normal(self, u: Params, v: Params, *, out: OutArray = None,
                    normal_out: OutArray = None, kind_out: OutArray = None) -> Evaluation:
        """Positions, unit normals and normal kinds at the n points of a 3-D patch.

        Returns an :class:`Evaluation` (position, normal, kind set). Where S_u x S_v vanishes
        the limit normal is given (kind NormalKind.LIMIT); where no normal exists, (0, 0, 0) with
        kind NormalKind.UNDEFINED.
        """
        call = _Call(u, v)
        pos = call.output(self.dim, out, "out")
        nrm = call.output(3, normal_out, "normal_out")
        kinds = call.kinds(kind_out)
        call.check_disjoint()
        LIB.bs_patch_eval_normal(self._ptr, call.n, call.u, call.v, pos.views, nrm.views,
                                 kinds.address)
        return Evaluation(call.finish(pos.result()), None, None, call.finish(nrm.result()),
                          call.finish(kinds.result()))

    def eval_curvature(self, u: Params, v: Params) -> Curvature:
        """Gaussian and mean curvature, principal curvatures k_min <= k_max and their unit
        directions at the n points of a 3-D patch (bs_patch_eval_curvature, since 1.1).

        Signs follow the normal of :meth:`eval_normal` (outward normals give a sphere k = -1/r);
        (d_min, d_max, normal) is right-handed. At collapsed edges and poles the values are the
        limits towards (1/2, 1/2) (kind CurvatureKind.LIMIT); where no finite limit exists, NaN
        with kind CurvatureKind.UNDEFINED. See docs/queries.md for the accuracy.
        """
        call = _Call(u, v)
        curv = call.output(4, None, "curv")
        dmin = call.output(3, None, "d_min")
        dmax = call.output(3, None, "d_max")
        kinds = call.kinds(None)
        LIB.bs_patch_eval_curvature(self._ptr, call.n, call.u, call.v, curv.views, dmin.views,
                                    dmax.views, kinds.address)
        k = curv.result()
        cols: List[Union["B.RealArray", List[float]]]
        kind: Union["B.UInt8Array", List[CurvatureKind]]
        if B.is_ndarray(k):
            cols = [k[:, i] for i in range(4)]
            kind = cast("B.UInt8Array", kinds.result())  # an array, as k is
        else:
            cols = [[row[i] for row in k] for i in range(4)]
            kind = [CURVATURE_KINDS[int(x)] for x in kinds.result()]
        gauss, mean, k_min, k_max = (call.finish(c) for c in cols)
        return Curvature(gauss, mean, k_min, k_max, call.finish(dmin.result()),
                         call.finish(dmax.result()), call.finish(kind))

    def closest_point(self, points: B.PointsArg) -> "ClosestPoints":
        """The globally closest point of the patch to each query point (bs_patch_closest_point,
        since 1.1): certified within 1e-9 (D + d) of the exact distance d, boundary included.

        ``points``: an array of shape (n, dim) or (dim,), or a sequence of points. Returns
        :class:`ClosestPoints` (``patch`` is None); NaN where a query coordinate is not finite.
        """
        from .query import patch_closest_point
        return patch_closest_point(self, points)

    @overload
    def eval_grid(self, u: Params, v: Params, *, derivatives: Literal[False] = ...,
                  normals: Literal[False] = ..., out: OutArray = ...,
                  float32: bool = ...) -> Points: ...

    @overload
    def eval_grid(self, u: Params, v: Params, *, derivatives: Literal[True], normals: bool = ...,
                  out: OutArray = ..., du_out: OutArray = ..., dv_out: OutArray = ...,
                  normal_out: OutArray = ..., kind_out: OutArray = ...,
                  float32: bool = ...) -> Evaluation: ...

    @overload
    def eval_grid(self, u: Params, v: Params, *, derivatives: bool = ..., normals: Literal[True],
                  out: OutArray = ..., du_out: OutArray = ..., dv_out: OutArray = ...,
                  normal_out: OutArray = ..., kind_out: OutArray = ...,
                  float32: bool = ...) -> Evaluation: ...

    @overload
    def eval_grid(self, u: Params, v: Params, *, derivatives: bool = ..., normals: bool = ...,
                  out: OutArray = ..., du_out: OutArray = ..., dv_out: OutArray = ...,
                  normal_out: OutArray = ...,
                  kind_out: OutArray = ..., float32: bool = ...) -> Union[Points, Evaluation]: ...

    def eval_grid(self, u: Params, v: Params, *, derivatives: bool = False,
                  normals: bool = False, out: OutArray = None, du_out: OutArray = None,
                  dv_out: OutArray = None, normal_out: OutArray = None,
                  kind_out: OutArray = None, float32: bool = False) -> object:
        """Evaluate on the tensor grid of every u[a] with every v[b].

        Point (a, b) is row a*len(v) + b of results of shape (len(u)*len(v), dim) (for numpy,
        ``result.reshape(len(u), len(v), dim)`` is a view). Returns positions, or an
        :class:`Evaluation` when ``derivatives`` or ``normals`` is set, as :meth:`eval` does.
        With ``float32`` the results are float32 (numpy) arrays, each value the double result
        correctly rounded (bs_patch_eval_grid_f32, since 1.1); ``out=`` arrays are then float32.
        """
        _check_requested(derivatives, normals, du_out, dv_out, normal_out, kind_out)
        call = _Call(u, v, grid=True)
        pos = call.output(self.dim, out, "out", float32)
        dus = dvs = nrm = kinds = None
        if derivatives:
            dus = call.output(self.dim, du_out, "du_out", float32)
            dvs = call.output(self.dim, dv_out, "dv_out", float32)
        if normals:
            nrm = call.output(3, normal_out, "normal_out", float32)
            kinds = call.kinds(kind_out)
        call.check_disjoint()
        grid = LIB.bs_patch_eval_grid_f32 if float32 else LIB.bs_patch_eval_grid
        grid(self._ptr, call.nu, call.u, call.nv, call.v, pos.views,
             dus.views if dus else None, dvs.views if dvs else None,
             nrm.views if nrm else None, kinds.address if kinds else None)
        if not derivatives and not normals:
            return call.finish(pos.result())
        return Evaluation(*(call.finish(x.result()) if x is not None else None
                            for x in (pos, dus, dvs, nrm, kinds)))

    # ---- exact operations -----------------------------------------------------------------
    def split(self, direction: DirectionArg, t: float) -> Tuple["Patch", "Patch"]:
        """Split at t (0 < t < 1) along ``direction`` ('u' or 'v') into the parts over [0, t]
        and [t, 1]."""
        d = A.direction(direction)
        t = A.real(t, "t")
        lo, hi = ctypes.c_void_p(), ctypes.c_void_p()
        LIB.bs_patch_split(self._ptr, d, t, ctypes.byref(lo), ctypes.byref(hi))
        return Patch._wrap(lo.value), Patch._wrap(hi.value)

    def split4(self, u: float, v: float) -> Tuple["Patch", "Patch", "Patch", "Patch"]:
        """Split at (u, v) into four patches: [u low, v low], [u high, v low], [u low, v high],
        [u high, v high]."""
        u, v = A.real(u, "u"), A.real(v, "v")
        out = (ctypes.c_void_p * 4)()
        LIB.bs_patch_split4(self._ptr, u, v, out)
        a, b, c, d = (Patch._wrap(h) for h in out)
        return a, b, c, d

    def subpatch(self, u0: float, u1: float, v0: float, v1: float) -> "Patch":
        """The patch over [u0, u1] x [v0, v1]; u0 > u1 (v0 > v1) reverses that direction."""
        args = [A.real(x, name) for x, name in ((u0, "u0"), (u1, "u1"), (v0, "v0"), (v1, "v1"))]
        out = ctypes.c_void_p()
        LIB.bs_patch_subpatch(self._ptr, *args, ctypes.byref(out))
        return Patch._wrap(out.value)

    def elevate(self, raise_u: int, raise_v: int) -> "Patch":
        """The same surface with its degrees raised by raise_u and raise_v."""
        ru = A.integer(raise_u, "raise_u")
        rv = A.integer(raise_v, "raise_v")
        out = ctypes.c_void_p()
        try:
            LIB.bs_patch_elevate(self._ptr, ru, rv, ctypes.byref(out))
        except DegreeError as exc:
            raise with_detail(exc, f"degrees {self.degree_u} + {ru} x {self.degree_v} + {rv} would "
                                   f"be above the limit {_MAX_DEGREE} (BS_MAX_DEGREE)") from None
        return Patch._wrap(out.value)

    def derivative(self, ku: int, kv: int) -> "Patch":
        """The hodograph patch of d^(ku+kv) S / du^ku dv^kv (polynomial patches only)."""
        ku = A.integer(ku, "ku", 0, A.UINT_MAX)
        kv = A.integer(kv, "kv", 0, A.UINT_MAX)
        out = ctypes.c_void_p()
        LIB.bs_patch_derivative(self._ptr, ku, kv, ctypes.byref(out))
        return Patch._wrap(out.value)

    def isocurve(self, direction: DirectionArg, t: float) -> Curve:
        """Control points and weights of an iso-parameter curve.

        Direction 'u': the curve u = t, a Bezier curve in v of degree degree_v; 'v': v = t, in u.
        Returns a :class:`Curve` (points, weights): with numpy, points a float64 array of shape
        (degree+1, dim) and weights an array; else a list of tuples and a list. Weights are None
        when the patch is polynomial.
        """
        d = A.direction(direction)
        t = A.real(t, "t")
        npts = (self.degree_v if d == DIR_U else self.degree_u) + 1
        dim = self.dim
        rational = self.rational
        if B.have_numpy():
            pts = np.empty((npts, dim))
            w = np.empty(npts) if rational else None
            paddr, waddr = pts.ctypes.data, (w.ctypes.data if w is not None else None)
            LIB.bs_patch_isocurve(self._ptr, d, t, paddr, npts * dim, waddr, npts if rational else 0)
            return Curve(pts, w)
        flat = array.array("d", bytes(8 * npts * dim))
        wflat = array.array("d", bytes(8 * npts)) if rational else None
        paddr, waddr = flat.buffer_info()[0], (wflat.buffer_info()[0] if wflat is not None else None)
        LIB.bs_patch_isocurve(self._ptr, d, t, paddr, npts * dim, waddr, npts if rational else 0)
        return Curve(B.nested(flat, (npts, dim)), list(wflat) if wflat is not None else None)

    def bounds(self) -> Tuple[Tuple[float, ...], Tuple[float, ...]]:
        """(lo, hi): the bounding box of the control net, which contains the patch."""
        dim = self.dim
        lo = array.array("d", bytes(8 * dim))
        hi = array.array("d", bytes(8 * dim))
        LIB.bs_patch_bounds(self._ptr, lo.buffer_info()[0], hi.buffer_info()[0])
        return tuple(lo), tuple(hi)

    def transform(self, affine: Nested) -> "Patch":
        """The patch with x -> A x + b applied to its net. ``affine`` is dim rows of dim+1
        numbers, [A | b] (nested sequence or numpy array of shape (dim, dim+1)), or the
        homogeneous (dim+1) x (dim+1) matrix whose last row is 0 ... 0 1 (a 4 x 4 matrix for a
        3-D patch, since 1.2); another last row is a ValueError (a projective map)."""
        dim = self.dim
        # rows of real numbers, checked below and by packed_doubles
        rows: Union["B.RealArray", List[B.Reals]] = \
            affine if B.is_ndarray(affine) else list(cast("Sequence[B.Reals]", affine))
        if len(rows) == dim + 1:
            last = [float(x) for x in rows[dim]]
            if last != [0.0] * dim + [1.0]:
                raise ValueError(f"affine: the last row of a {dim + 1} x {dim + 1} matrix must be "
                                 f"{[0.0] * dim + [1.0]}, not {last}")
            affine = rows[:dim]
        keep, address = B.packed_doubles(affine, (dim, dim + 1), "affine")
        out = ctypes.c_void_p()
        LIB.bs_patch_transform(self._ptr, address, ctypes.byref(out))
        del keep
        return Patch._wrap(out.value)

    def swap_uv(self) -> "Patch":
        """The same surface with u and v exchanged: Q(u, v) = P(v, u), Q[j][i] = P[i][j].
        The normal S_u x S_v changes sign."""
        out = ctypes.c_void_p()
        LIB.bs_patch_swap_uv(self._ptr, ctypes.byref(out))
        return Patch._wrap(out.value)

    def reverse(self, direction: DirectionArg) -> "Patch":
        """The same surface with one direction reversed: 'u' gives Q(u, v) = P(1-u, v),
        'v' gives Q(u, v) = P(u, 1-v)."""
        d = A.direction(direction)
        out = ctypes.c_void_p()
        LIB.bs_patch_reverse(self._ptr, d, ctypes.byref(out))
        return Patch._wrap(out.value)

    @classmethod
    def ruled(cls, c0: Union[Curve, Nested], c1: Union[Curve, Nested]) -> "Patch":
        """The ruled patch joining curve c0 (at v = 0) to curve c1 (at v = 1) by straight
        segments: degree (d, 1), d the larger curve degree. Curves are :class:`Curve` values or
        bare point sequences; rational curves give a rational patch."""
        curves = [_CurveArg(c, name) for c, name in ((c0, "c0"), (c1, "c1"))]
        out = ctypes.c_void_p()
        LIB.bs_patch_ruled(ctypes.byref(curves[0].c), ctypes.byref(curves[1].c), ctypes.byref(out))
        return cls._wrap(out.value)

    @classmethod
    def coons(cls, v0: Union[Curve, Nested], v1: Union[Curve, Nested], u0: Union[Curve, Nested],
              u1: Union[Curve, Nested]) -> "Patch":
        """The bilinearly blended Coons patch of four polynomial boundary curves:
        S(u, 0) = v0(u), S(u, 1) = v1(u), S(0, v) = u0(v), S(1, v) = u1(v). The corners must
        meet (IncompatibleError otherwise); rational curves raise UnsupportedError."""
        curves = [_CurveArg(c, name)
                  for c, name in ((v0, "v0"), (v1, "v1"), (u0, "u0"), (u1, "u1"))]
        out = ctypes.c_void_p()
        LIB.bs_patch_coons(*(ctypes.byref(c.c) for c in curves), ctypes.byref(out))
        return cls._wrap(out.value)


class _CurveArg:
    """A bs_curve built from a Curve or a bare point sequence, with its buffers kept alive."""

    def __init__(self, curve: Union[Curve, Nested], what: str) -> None:
        points: Nested
        if isinstance(curve, Curve):
            points, weights = curve.points, curve.weights
            pname = f"{what}.points"
        else:
            points, weights = curve, None
            pname = what
        (npts, dim), ctrl = B.nested_doubles(points, 2, pname)
        if npts == 0:
            raise ValueError(f"{pname} needs at least one point")
        w_addr = None
        keep: List["array.array[float]"] = [ctrl]
        if weights is not None:
            (nw,), w = B.nested_doubles(weights, 1, f"{what}.weights")
            if nw != npts:
                raise ValueError(f"{what}.weights must hold {npts} numbers, got {nw}")
            keep.append(w)
            w_addr = w.buffer_info()[0]
        self.keep = keep
        self.c = CCurve(npts - 1, dim, ctrl.buffer_info()[0], w_addr)


def _check_packed(arr: object, shape: Sequence[int], what: str) -> None:
    B.need_numpy()
    if not isinstance(arr, np.ndarray):
        raise TypeError(f"{what} must be a numpy array, not {type(arr).__name__}")
    if arr.dtype != np.float64 or arr.shape != tuple(shape) \
            or not arr.flags.c_contiguous or not arr.flags.writeable:
        raise ValueError(f"{what} must be a writable C-contiguous float64 array of shape "
                         f"{tuple(shape)}")


class _Call:
    """The parameter views of one evaluation call, its outputs and how its results are shaped."""

    def __init__(self, u: Params, v: Params, grid: bool = False,
                 inputs: Sequence[Tuple[str, object]] = ()) -> None:
        self.scalar = B.is_scalar(u) and B.is_scalar(v)
        if not grid and B.is_scalar(u) != B.is_scalar(v):  # a scalar pairs with every value
            n = B.doubles(v if B.is_scalar(u) else u, "v" if B.is_scalar(u) else "u").count
            scalar = cast(SupportsFloat, u if B.is_scalar(u) else v)  # a number, checked above
            if B.is_scalar(u):
                u = [float(scalar)] * n
            else:
                v = [float(scalar)] * n
        du = B.doubles(u, "u")
        dv = B.doubles(v, "v")
        self.inputs: List[Tuple[str, object]] = [("u", du.keep), ("v", dv.keep)] + list(inputs)
        self.given: List[Tuple[str, object]] = []
        self.u = du.cview()
        self.v = dv.cview()
        self.nu = self.nv = 0
        if grid:
            self.nu, self.nv = du.count, dv.count
            self.n = self.nu * self.nv
        else:
            if du.count != dv.count:
                raise ValueError(f"u and v must have the same length ({du.count} != {dv.count})")
            self.n = du.count

    def output(self, k: int, out: object, what: str, float32: bool = False) -> B.Output:
        res = B.Output(self.n, k, out, what, float32)
        if out is not None:
            self.given.append((what, out))
        return res

    def kinds(self, out: object) -> B.KindOutput:
        res = B.KindOutput(self.n, out)
        if out is not None:
            self.given.append(("kind_out", out))
        return res

    def check_disjoint(self) -> None:
        if self.given:
            B.check_disjoint(self.given, self.inputs)

    def finish(self, value: Any) -> Any:  # Any: as _squeeze
        return _squeeze(value) if self.scalar else value
