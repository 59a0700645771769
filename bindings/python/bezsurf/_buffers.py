"""Passing caller buffers to the library as strided views, without copies where possible.

Inputs: numpy arrays pass as they are (any stride, including negative ones; other dtypes are
converted to float64 once); ``array.array('d')`` and writable contiguous memoryviews of doubles pass
by address; lists, tuples and other buffers are copied once into an ``array.array('d')``.

Outputs follow one rule: numpy arrays whenever numpy is importable, plain lists otherwise. With
numpy, one array of shape (n, k) in Fortran order (each column contiguous, the library's packed
fast path) is allocated, or the caller's ``out=`` array used, and its k columns are handed to the
library as k views, so the library writes the final array directly. Without numpy, the library
writes k packed ``array.array('d')`` columns that are zipped into a list of n tuples.
"""

import array
import ctypes
import numbers
import sys
from typing import TYPE_CHECKING, Iterable, List, Optional, Sequence, Tuple, Type, Union, cast, overload

from ._enums import NORMAL_KINDS, NormalKind
from ._lib import CView, FView, View

try:  # numpy is optional
    import numpy as np
except ImportError:  # pragma: no cover - depends on the interpreter
    np = None  # type: ignore[assignment]

if TYPE_CHECKING:
    import numpy.typing as npt
    from typing import TypeGuard  # Python 3.10+, for annotations only

    from _typeshed import ReadableBuffer

    FloatArray = npt.NDArray[np.float64]
    Float32Array = npt.NDArray[np.float32]
    UInt8Array = npt.NDArray[np.uint8]
    UInt32Array = npt.NDArray[np.uint32]
    BoolArray = npt.NDArray[np.bool_]
    _FloatType = Union[Type[np.float64], Type[np.float32]]
    #: An input array of any dtype (a real one is converted to float64 once, others are refused
    #: at run time).
    RealArray = npt.NDArray[np.generic]

#: Results of n points: a float64 array of shape (n, k) with numpy, else a list of n tuples.
Points = Union["FloatArray", List[Tuple[float, ...]]]
#: One point: a float64 array of shape (k,) with numpy, else a tuple.
Point = Union["FloatArray", Tuple[float, ...]]
#: Normal kinds: a uint8 array with numpy, else a list of NormalKind.
Kinds = Union["UInt8Array", List[NormalKind]]
#: A result of n points or, for scalar parameters, of one point.
PointOrPoints = Union["FloatArray", List[Tuple[float, ...]], Tuple[float, ...]]
#: Normal kinds of n points or, for scalar parameters, of one point.
KindOrKinds = Union["UInt8Array", List[NormalKind], NormalKind, "np.uint8"]
#: uint32 results (ids, indices): an array with numpy, else a list of ints or of int tuples.
Ids = Union["UInt32Array", List[int]]
IdRows = Union["UInt32Array", List[Tuple[int, ...]]]
#: Real results of n points (a distance, a parameter t): a float64 array of shape (n,) with
#: numpy, else a list; for one point one float.
RealOrReals = Union["FloatArray", List[float], float]
#: uint32 ids of n points, or one id for one point.
IdOrIds = Union["UInt32Array", List[int], int, "np.uint32"]
#: uint8 codes of n points (TRIM_* values), or one code for one point.
CodeOrCodes = Union["UInt8Array", List[int], int]
#: Booleans of n points, or one bool for one point.
BoolOrBools = Union["BoolArray", List[bool], bool]

#: Input real numbers: a sequence, ``array.array('d')``, a memoryview of doubles or a numpy array
#: (any real dtype, any stride).
RealsIn = Union[Sequence[float], "array.array[float]", memoryview, "RealArray"]
#: One real number for every point, or one per point.
RealOrRealsIn = Union[float, RealsIn]
#: Input points: one point of shape (k,) or n points of shape (n, k), as nested sequences of real
#: numbers or a numpy array.
PointsArg = Union[Sequence[float], Sequence[Sequence[float]], "RealArray"]
#: Input ids (patches, faces): one id for every point, a sequence or a numpy array.
IdsIn = Union[int, Iterable[int], "UInt32Array"]
#: A rectangular nested input of real numbers, one to three levels deep (a control net, a weight
#: grid, a curve's points, a matrix, knots): sequences, numpy arrays at any level, memoryviews.
Reals = Union[Sequence[float], "RealArray", memoryview]
Grid = Union[Sequence[Reals], "RealArray", memoryview]
Net = Union[Sequence[Grid], "RealArray", memoryview]
Nested = Union[Reals, Grid, Net]
#: An array the library writes (``out=``); its dtype, shape and flags are checked at run time.
OutArray = Optional["RealArray"]
#: Nested lists of floats made by nested(): tuples at the innermost level.
NestedLists = Union[Tuple[float, ...], List["NestedLists"]]

# numpy >= 1.25 keeps its exceptions in numpy.exceptions
_TOO_HARD: Type[BaseException] = getattr(getattr(np, "exceptions", np), "TooHardError", Exception)
_DOUBLE = ctypes.sizeof(ctypes.c_double)
_DOUBLE_FORMATS = {"d", "@d", "=d", "<d" if sys.byteorder == "little" else ">d"}


def have_numpy() -> bool:
    """True when results are numpy arrays (numpy importable), False when they are lists."""
    return np is not None


def is_ndarray(x: object) -> "TypeGuard[RealArray]":
    return np is not None and isinstance(x, np.ndarray)


def is_scalar(x: object) -> bool:
    """A single real number (Python or numpy scalar, or a 0-d array)."""
    if isinstance(x, numbers.Real):
        return True
    return is_ndarray(x) and bool(x.ndim == 0)


def need_numpy() -> None:
    """ImportError unless numpy is importable (callers then use ``np``)."""
    if np is None:
        raise ImportError("this call needs numpy, which is not installed")


def type_name(x: object) -> str:
    return type(x).__name__


class Doubles:
    """A 1-D run of doubles the library may read (or write): address, count, byte stride.

    ``keep`` holds the Python object owning the memory for as long as the view is in use.
    """

    __slots__ = ("address", "count", "stride", "keep")

    def __init__(self, address: int, count: int, stride: int, keep: object) -> None:
        self.address = address
        self.count = count
        self.stride = stride
        self.keep = keep

    def cview(self) -> CView:
        return CView(self.address, self.count, self.stride)


def _ndarray_1d(x: "RealArray", what: str) -> Doubles:
    try:
        a = np.asarray(x, dtype=np.float64)      # converts other dtypes once, never float64
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{what} must hold real numbers, not {x.dtype}") from exc
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1:
        raise ValueError(f"{what} must be one-dimensional, got shape {a.shape}")
    # A zero stride means "packed" to the library, so broadcast arrays are made real; unaligned
    # data (views into byte buffers) is copied since the library requires aligned doubles.
    if (a.strides[0] == 0 and a.shape[0] > 1) or not a.flags.aligned:
        a = np.array(a, dtype=np.float64, copy=True)
    return Doubles(int(a.ctypes.data), int(a.shape[0]), int(a.strides[0]), a)


def _packed(values: object, what: str) -> Doubles:
    if isinstance(values, (str, bytes)):
        raise TypeError(f"{what} must be a real number or a sequence of them, not "
                        f"{type_name(values)}")
    try:
        arr = array.array("d", cast("Iterable[float]", values))  # array.array checks the items
    except TypeError as exc:
        raise TypeError(f"{what} must be a real number or a sequence of real numbers "
                        f"({exc})") from None
    address, count = arr.buffer_info()
    return Doubles(address, count, _DOUBLE, arr)


def doubles(x: object, what: str) -> Doubles:
    """A 1-D double input from a numpy array, array.array, memoryview, sequence or scalar."""
    if is_ndarray(x):
        return _ndarray_1d(x, what)
    if isinstance(x, numbers.Real):
        return _packed((float(x),), what)
    if isinstance(x, array.array) and x.typecode == "d":
        address, count = x.buffer_info()
        return Doubles(address, count, _DOUBLE, x)
    if isinstance(x, (memoryview, bytearray)) or hasattr(x, "__buffer__"):
        mv = memoryview(cast("ReadableBuffer", x))  # a memoryview, bytearray or __buffer__ object
        if mv.format in _DOUBLE_FORMATS and mv.ndim == 1:
            if mv.c_contiguous and not mv.readonly and mv.nbytes:
                raw = (ctypes.c_double * len(mv)).from_buffer(mv)
                return Doubles(ctypes.addressof(raw), len(mv), _DOUBLE, (mv, raw))
            return _packed(mv.tolist(), what)
        if mv.format not in _DOUBLE_FORMATS:
            raise TypeError(f"{what}: a buffer of doubles is needed, got format {mv.format!r}")
        raise ValueError(f"{what} must be one-dimensional")
    return _packed(x, what)


class PointsIn:
    """n input points of k coordinates as k strided views (zero-copy for numpy arrays).

    Accepts an array of shape (n, k) or (k,) (one point: ``scalar``), or a sequence of n
    sequences of k real numbers (copied once, packed by coordinate).
    """

    __slots__ = ("n", "views", "keep", "scalar")

    def __init__(self, x: object, k: int, what: str) -> None:
        views = (CView * k)()
        if is_ndarray(x):
            try:
                a = np.asarray(x, dtype=np.float64)
            except (TypeError, ValueError) as exc:
                raise TypeError(f"{what} must hold real numbers, not {x.dtype}") from exc
            self.scalar = a.ndim == 1
            if self.scalar:
                a = a.reshape(1, -1)
            if a.ndim != 2 or a.shape[1] != k:
                raise ValueError(f"{what} must have shape (n, {k}) or ({k},), got {np.shape(x)}")
            # Zero strides mean "packed" to the library, and the library needs aligned doubles.
            if (a.strides[0] == 0 and a.shape[0] > 1) or (a.strides[1] == 0 and k > 1) \
                    or not a.flags.aligned:
                a = np.array(a, dtype=np.float64, copy=True)
            base = int(a.ctypes.data)
            for c in range(k):
                views[c] = CView(base + c * a.strides[1], a.shape[0], a.strides[0])
            self.n = int(a.shape[0])
            self.keep: object = a
        else:
            if isinstance(x, (str, bytes)) or not isinstance(x, Iterable):
                raise TypeError(f"{what} must be a sequence of points, not {type_name(x)}")
            rows = list(x)
            self.scalar = bool(rows) and all(isinstance(c, numbers.Real) for c in rows)
            if self.scalar:
                rows = [rows]
            for row in rows:
                if isinstance(row, (str, bytes)) or not isinstance(row, Sequence):
                    raise TypeError(f"{what} must be a sequence of points, not of "
                                    f"{type_name(row)}")
                if len(row) != k:
                    raise ValueError(f"{what} must hold points of {k} coordinates, got {len(row)}")
            cols: List["array.array[float]"] = []
            for c in range(k):
                try:
                    col = array.array("d", (float(r[c]) for r in rows))
                except (TypeError, IndexError) as exc:
                    raise TypeError(f"{what} must be a sequence of points of {k} real numbers "
                                    f"({exc})") from None
                cols.append(col if col else array.array("d", [0.0]))
            for c in range(k):
                views[c] = CView(cols[c].buffer_info()[0], len(rows), _DOUBLE)
            self.n = len(rows)
            self.keep = cols
        self.views = views


class Output:
    """An (n, k) double (or, with ``float32``, float) result the library writes through k views."""

    __slots__ = ("n", "k", "array", "columns", "views", "given")

    def __init__(self, n: int, k: int, out: object = None, what: str = "out",
                 float32: bool = False) -> None:
        self.n = n
        self.k = k
        # float32 data when float32 is set: typed as the float64 arrays the public aliases name
        self.array: Optional["FloatArray"] = None
        self.columns: List["array.array[float]"] = []
        self.given = out is not None
        view: Union[Type[View], Type[FView]] = FView if float32 else View
        views = (view * k)()
        if out is not None or np is not None:
            dtype: Optional[_FloatType] = None if np is None else np.float32 if float32 else np.float64
            arr = _check_out(out, (n, k), what, dtype) if out is not None else \
                np.empty((n, k), dtype=dtype, order="F")
            base = int(arr.ctypes.data)
            for c in range(k):
                views[c] = view(base + c * arr.strides[1], n, arr.strides[0])
            self.array = arr
        else:
            # k packed columns (the library's fast path), zipped into n tuples at C speed.
            code, size = ("f", 4) if float32 else ("d", _DOUBLE)
            for c in range(k):
                col = array.array(code, bytes(size * max(n, 1)))
                views[c] = view(col.buffer_info()[0], n, size)
                self.columns.append(col)
        self.views = views

    def fill(self, x: float) -> None:
        """Every value set to x (for results the library leaves unwritten)."""
        if self.array is not None:
            self.array[...] = x
        for col in self.columns:
            for i in range(len(col)):
                col[i] = x

    def result(self) -> "Points":
        if self.array is not None:
            return self.array
        if self.n == 0:
            return []
        return list(zip(*(col[: self.n] for col in self.columns)))


def _check_out(out: object, shape: Tuple[int, ...], what: str,
               dtype: "Optional[_FloatType]" = None) -> "FloatArray":
    if not is_ndarray(out):
        raise TypeError(f"{what} must be a numpy array, not {type_name(out)}")
    want = np.dtype(np.float64 if dtype is None else dtype)
    if out.dtype != want:
        raise TypeError(f"{what} must have dtype {want}, not {out.dtype}")
    if out.shape != shape:
        raise ValueError(f"{what} must have shape {shape}, not {out.shape}")
    if not out.flags.writeable:
        raise ValueError(f"{what} is read-only")
    if not out.flags.aligned:
        raise ValueError(f"{what} is not aligned for {want}")
    # Zero strides would alias elements (and 0 means "packed" to the library).
    for axis, size in enumerate(shape):
        if size > 1 and out.strides[axis] == 0:
            raise ValueError(f"{what} has a zero stride on axis {axis}")
    return cast("FloatArray", out)  # float64, or float32 for the float32 results


class KindOutput:
    """n bytes of normal kinds (uint8 numpy array, or a list of NormalKind)."""

    __slots__ = ("n", "array", "buffer", "address", "given")

    def __init__(self, n: int, out: object = None) -> None:
        self.n = n
        self.array: Optional["UInt8Array"] = None
        self.buffer: Optional["ctypes.Array[ctypes.c_ubyte]"] = None
        self.given = out is not None
        if out is not None:
            if not is_ndarray(out):
                raise TypeError(f"kind_out must be a numpy array, not {type_name(out)}")
            if out.dtype != np.uint8 or out.shape != (n,) or not out.flags.c_contiguous \
                    or not out.flags.writeable:
                raise ValueError(f"kind_out must be a writable contiguous uint8 array of shape "
                                 f"({n},)")
            self.array = cast("UInt8Array", out)  # the dtype was checked above
        elif np is not None:
            self.array = np.empty(n, dtype=np.uint8)
        if self.array is not None:
            self.address = int(self.array.ctypes.data)
        else:
            self.buffer = (ctypes.c_ubyte * max(n, 1))()
            self.address = ctypes.addressof(self.buffer)

    def result(self) -> "Kinds":
        if self.array is not None:
            return self.array
        assert self.buffer is not None
        return [NORMAL_KINDS[k] for k in self.buffer[: self.n]]


def check_disjoint(outputs: Sequence[Tuple[str, object]], inputs: Sequence[Tuple[str, object]]) -> None:
    """ValueError if two output arrays, or an output and an input, share memory.

    The library writes outputs while reading inputs; overlapping buffers would give results that
    depend on the order of the writes. Only arrays the caller passed can overlap.
    """
    arrays = [(name, a) for name, a in outputs if is_ndarray(a)]
    others = [(name, a) for name, a in inputs if is_ndarray(a)]
    for i, (name, a) in enumerate(arrays):
        for other, b in arrays[i + 1:] + others:
            try:
                shared = np.shares_memory(a, b, max_work=100000)
            except _TOO_HARD:
                shared = np.may_share_memory(a, b)
            if shared:
                raise ValueError(f"{name} overlaps {other}: outputs must not share memory with "
                                 f"each other or with the inputs")


_U32 = "I" if array.array("I").itemsize == 4 else "L"


def uint32s(x: object, what: str) -> Tuple[Union["UInt32Array", "array.array[int]"], int, int]:
    """(keep, address, count) of a packed uint32 copy (or view) of ids."""
    if is_ndarray(x):
        a = np.asarray(x)
        if a.ndim == 0:
            a = a.reshape(1)
        if a.ndim != 1:
            raise ValueError(f"{what} must be one-dimensional")
        if a.dtype != np.uint32:
            if a.size and not np.issubdtype(a.dtype, np.integer):
                raise TypeError(f"{what} must hold integers, not {a.dtype}")
            if a.size and (a.min() < 0 or a.max() > 0xFFFFFFFF):
                raise ValueError(f"{what} must hold integers in 0..2**32-1")
            a = a.astype(np.uint32)
        ids = cast("UInt32Array", np.ascontiguousarray(a))  # uint32 by the checks above
        return ids, int(ids.ctypes.data), int(ids.shape[0])
    if isinstance(x, numbers.Integral):
        x = (x,)
    if isinstance(x, (str, bytes)) or not isinstance(x, Iterable):
        raise TypeError(f"{what} must be an integer or a sequence of integers, not {type_name(x)}")
    try:
        arr = array.array(_U32, x)
    except TypeError as exc:
        raise TypeError(f"{what} must be an integer or a sequence of integers ({exc})") from None
    except OverflowError as exc:
        raise ValueError(f"{what} must hold integers in 0..2**32-1") from exc
    if not arr:
        arr.append(0)  # a valid pointer; the count passed stays 0
        return arr, arr.buffer_info()[0], 0
    return arr, arr.buffer_info()[0], len(arr)



class UInt32Output:
    """count uint32 values, shaped (rows, k) or flat, as a numpy array or a list."""

    def __init__(self, count: int, shape: Tuple[int, ...], lists: bool = False) -> None:
        self.count = count
        self.shape = shape
        self.array: Optional["UInt32Array"] = None
        self.buf: Optional["array.array[int]"] = None
        if np is not None and not lists:
            self.array = np.empty(shape, dtype=np.uint32)
            self.address = int(self.array.ctypes.data)
        else:
            self.buf = array.array(_U32, bytes(4 * max(count, 1)))
            self.address = self.buf.buffer_info()[0]

    def values(self) -> List[int]:
        """The values as a flat list (made with ``lists``)."""
        assert self.buf is not None
        return list(self.buf[: self.count])

    def ids(self) -> "Ids":
        """A flat result: an array, or a list of ints."""
        if self.array is not None:
            return self.array
        return self.values()

    def rows(self) -> "IdRows":
        """A result of shape (rows, k): an array, or a list of k-tuples."""
        if self.array is not None:
            return self.array
        assert self.buf is not None
        values = self.buf[: self.count]
        k = self.shape[1]
        return list(zip(*(values[c::k] for c in range(k))))


def nested_doubles(x: object, depth: int, what: str) -> Tuple[Tuple[int, ...], "array.array[float]"]:
    """(shape, packed doubles) of a rectangular nested sequence of real numbers, depth levels deep.

    Errors name the offending element: ``net[1][2] must be a sequence of real numbers, not int``,
    ``net must be rectangular: net[1] has 2 entries, net[0] has 3``.
    """
    if isinstance(x, memoryview):
        x = x.tolist()
    flat: "array.array[float]" = array.array("d")
    lengths: List[Optional[Tuple[int, str]]] = [None] * depth

    def walk(obj: object, level: int, label: str) -> None:
        if is_ndarray(obj) and obj.ndim == depth - level:
            try:
                a = np.ascontiguousarray(obj, dtype=np.float64)
            except (TypeError, ValueError):
                raise TypeError(f"{label} must hold real numbers, not {obj.dtype}") from None
            for lv, size in enumerate(a.shape):
                expect(lv + level, size, label + "[0]" * lv)
            flat.extend(a.reshape(-1).tolist())
            return
        if isinstance(obj, (str, bytes)) or not isinstance(obj, Iterable):
            kind = "a sequence of real numbers" if level == depth - 1 else "a sequence"
            raise TypeError(f"{label} must be {kind}, not {type_name(obj)}")
        items = obj if isinstance(obj, (list, tuple)) else list(obj)
        expect(level, len(items), label)
        if level == depth - 1:
            try:
                flat.extend(array.array("d", items))
            except TypeError:
                for i, item in enumerate(items):
                    if not isinstance(item, numbers.Real):
                        raise TypeError(f"{label}[{i}] must be a real number, not "
                                        f"{type_name(item)}") from None
                raise
            return
        for i, item in enumerate(items):
            walk(item, level + 1, f"{label}[{i}]")

    def expect(level: int, size: int, label: str) -> None:
        seen = lengths[level]
        if seen is None:
            lengths[level] = (size, label)
        elif seen[0] != size:
            raise ValueError(f"{what} must be rectangular: {label} has {size} entries, "
                             f"{seen[1]} has {seen[0]}")

    walk(x, 0, what)
    shape = tuple(seen[0] if seen is not None else 0 for seen in lengths)
    return shape, flat


def flat_net(net: object, weights: object, what: str = "net",
             wname: str = "weights") -> Tuple[int, int, int, object, int, Optional[int]]:
    """(rows, cols, dim, keep, ctrl address, weights address) from a control net.

    The net is a numpy array or nested sequence of shape (deg_u+1, deg_v+1, dim); weights None or
    of shape (deg_u+1, deg_v+1). The library copies both, so one packed copy is made here.
    """
    if is_ndarray(net):
        if net.ndim != 3:
            raise ValueError(f"{what} must have shape (deg_u+1, deg_v+1, dim), got {net.shape}")
        try:
            a = np.ascontiguousarray(net, dtype=np.float64)
        except (TypeError, ValueError):
            raise TypeError(f"{what} must hold real numbers, not {net.dtype}") from None
        rows, cols, dim = (int(s) for s in a.shape)
        ctrl_keep: object = a
        ctrl_addr = int(a.ctypes.data)
    else:
        (rows, cols, dim), flat = nested_doubles(net, 3, what)
        if not flat:  # keep the pointer valid so that the library reports the real problem
            flat.append(0.0)
        ctrl_keep = flat
        ctrl_addr = flat.buffer_info()[0]
    if rows == 0 or cols == 0:
        raise ValueError(f"{what} needs at least one row and one column")
    w_keep: object = None
    w_addr = None
    if weights is not None:
        wshape, w = nested_doubles(weights, 2, wname)
        if wshape != (rows, cols):
            raise ValueError(f"{wname} must have shape {(rows, cols)}, got {wshape}")
        w_keep, w_addr = w, w.buffer_info()[0]
    return rows, cols, dim, (ctrl_keep, w_keep), ctrl_addr, w_addr


def packed_doubles(values: object, shape: Tuple[int, ...], what: str) -> Tuple["array.array[float]", int]:
    """A packed C copy of a small nested sequence or array of the given shape."""
    got, flat = nested_doubles(values, len(shape), what)
    if got != shape:
        raise ValueError(f"{what} must have shape {shape}, got {got}")
    return flat, flat.buffer_info()[0]


@overload
def nested(flat: Sequence[float], shape: Tuple[int, int]) -> List[Tuple[float, ...]]: ...


@overload
def nested(flat: Sequence[float], shape: Tuple[int, int, int]) -> List[List[Tuple[float, ...]]]: ...


def nested(flat: Sequence[float], shape: Tuple[int, ...]
           ) -> Union[List[Tuple[float, ...]], List[List[Tuple[float, ...]]]]:
    # the length of shape fixes the depth of the result
    return cast("Union[List[Tuple[float, ...]], List[List[Tuple[float, ...]]]]", _nested(flat, shape))


def _nested(flat: Sequence[float], shape: Sequence[int]) -> NestedLists:
    """Split a flat sequence into nested lists; the innermost level becomes tuples."""
    if len(shape) == 1:
        return tuple(flat)
    step = 1
    for s in shape[1:]:
        step *= s
    return [_nested(flat[i * step:(i + 1) * step], shape[1:]) for i in range(shape[0])]
