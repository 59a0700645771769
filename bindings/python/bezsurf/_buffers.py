"""Passing caller buffers to the library as strided views, without copies where possible.

Inputs: numpy arrays pass as they are (any stride, including negative ones; other dtypes are
converted to float64 once); ``array.array('d')`` and writable contiguous memoryviews of doubles pass
by address; lists, tuples and other buffers are copied once into an ``array.array('d')``.

Outputs: with numpy, one array of shape (n, k) is allocated (or the caller's ``out=`` array used)
and its k columns are handed to the library as k strided views, so the library writes the final
array directly. Without numpy, the library writes one interleaved ``array.array('d')`` (k views
of stride k doubles) that is grouped into a list of n tuples.
"""

import array
import ctypes
import numbers
import sys
from typing import Any, List, Optional, Sequence, Tuple

from ._lib import CView, View

try:  # numpy is optional
    import numpy as np
except ImportError:  # pragma: no cover - depends on the interpreter
    np = None  # type: ignore[assignment]

_DOUBLE = ctypes.sizeof(ctypes.c_double)
_DOUBLE_FORMATS = {"d", "@d", "=d", "<d" if sys.byteorder == "little" else ">d"}


def is_ndarray(x: Any) -> bool:
    return np is not None and isinstance(x, np.ndarray)


def is_scalar(x: Any) -> bool:
    """A single real number (Python or numpy scalar, or a 0-d array)."""
    if isinstance(x, numbers.Real):
        return True
    return is_ndarray(x) and x.ndim == 0


def need_numpy() -> Any:
    if np is None:
        raise ImportError("this call needs numpy, which is not installed")
    return np


class Doubles:
    """A 1-D run of doubles the library may read (or write): address, count, byte stride.

    ``keep`` holds the Python object owning the memory for as long as the view is in use.
    """

    __slots__ = ("address", "count", "stride", "keep", "numpy")

    def __init__(self, address: int, count: int, stride: int, keep: Any, numpy: bool) -> None:
        self.address = address
        self.count = count
        self.stride = stride
        self.keep = keep
        self.numpy = numpy

    def cview(self) -> CView:
        return CView(self.address, self.count, self.stride)


def _ndarray_1d(a: Any, what: str) -> Doubles:
    a = np.asarray(a, dtype=np.float64)          # converts other dtypes once, never float64
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1:
        raise ValueError(f"{what} must be one-dimensional, got shape {a.shape}")
    # A zero stride means "packed" to the library, so broadcast arrays are made real; unaligned
    # data (views into byte buffers) is copied since the library requires aligned doubles.
    if (a.strides[0] == 0 and a.shape[0] > 1) or not a.flags.aligned:
        a = np.array(a, dtype=np.float64, copy=True)
    return Doubles(a.ctypes.data, a.shape[0], a.strides[0], a, True)


def _packed(values: Any, what: str) -> Doubles:
    try:
        arr = array.array("d", values)
    except TypeError as exc:
        raise TypeError(f"{what} must be a sequence of real numbers") from exc
    address, count = arr.buffer_info()
    return Doubles(address, count, _DOUBLE, arr, False)


def doubles(x: Any, what: str) -> Doubles:
    """A 1-D double input from a numpy array, array.array, memoryview, sequence or scalar."""
    if is_ndarray(x):
        return _ndarray_1d(x, what)
    if isinstance(x, numbers.Real):
        return _packed((float(x),), what)
    if isinstance(x, array.array) and x.typecode == "d":
        address, count = x.buffer_info()
        return Doubles(address, count, _DOUBLE, x, False)
    if isinstance(x, (memoryview, bytes, bytearray)) or hasattr(x, "__buffer__"):
        mv = memoryview(x)
        if mv.format in _DOUBLE_FORMATS and mv.ndim == 1:
            if mv.c_contiguous and not mv.readonly and mv.nbytes:
                raw = (ctypes.c_double * len(mv)).from_buffer(mv)
                return Doubles(ctypes.addressof(raw), len(mv), _DOUBLE, (mv, raw), False)
            return _packed(mv.tolist(), what)
        if mv.format not in _DOUBLE_FORMATS:
            raise TypeError(f"{what}: a buffer of doubles is needed, got format {mv.format!r}")
        raise ValueError(f"{what} must be one-dimensional")
    return _packed(x, what)


class Output:
    """An (n, k) double result the library writes through k strided views."""

    __slots__ = ("n", "k", "array", "columns", "views")

    def __init__(self, n: int, k: int, use_numpy: bool, out: Any = None, what: str = "out") -> None:
        self.n = n
        self.k = k
        self.array = None
        self.columns: List[array.array] = []
        views = (View * k)()
        if out is not None or use_numpy:
            arr = _check_out(out, (n, k), what) if out is not None else \
                need_numpy().empty((n, k), dtype=np.float64)
            base = arr.ctypes.data
            for c in range(k):
                views[c] = View(base + c * arr.strides[1], n, arr.strides[0])
            self.array = arr
        else:
            # One interleaved buffer (point-major, stride k doubles), read back as n tuples.
            buf = array.array("d", bytes(_DOUBLE * max(n * k, 1)))
            base = buf.buffer_info()[0]
            for c in range(k):
                views[c] = View(base + c * _DOUBLE, n, k * _DOUBLE)
            self.columns.append(buf)
        self.views = views

    def result(self) -> Any:
        if self.array is not None:
            return self.array
        values = iter(self.columns[0][: self.n * self.k])
        return list(zip(*[values] * self.k))


def _check_out(out: Any, shape: Tuple[int, ...], what: str) -> Any:
    if not is_ndarray(out):
        raise TypeError(f"{what} must be a numpy array")
    if out.dtype != np.float64:
        raise TypeError(f"{what} must have dtype float64, not {out.dtype}")
    if out.shape != shape:
        raise ValueError(f"{what} must have shape {shape}, not {out.shape}")
    if not out.flags.writeable:
        raise ValueError(f"{what} is read-only")
    if not out.flags.aligned:
        raise ValueError(f"{what} is not aligned for doubles")
    # Zero strides would alias elements (and 0 means "packed" to the library).
    for axis, size in enumerate(shape):
        if size > 1 and out.strides[axis] == 0:
            raise ValueError(f"{what} has a zero stride on axis {axis}")
    return out


class KindOutput:
    """n bytes of normal kinds (uint8 numpy array, or a list of ints)."""

    __slots__ = ("n", "array", "buffer", "address")

    def __init__(self, n: int, use_numpy: bool, out: Any = None) -> None:
        self.n = n
        self.array = None
        if out is not None:
            if not is_ndarray(out) or out.dtype != np.uint8 or out.shape != (n,) \
                    or not out.flags.c_contiguous or not out.flags.writeable:
                raise ValueError(f"kind_out must be a writable contiguous uint8 array of shape ({n},)")
            self.array = out
        elif use_numpy:
            self.array = need_numpy().empty(n, dtype=np.uint8)
        if self.array is not None:
            self.buffer = None
            self.address = self.array.ctypes.data
        else:
            self.buffer = (ctypes.c_ubyte * max(n, 1))()
            self.address = ctypes.addressof(self.buffer)

    def result(self) -> Any:
        if self.array is not None:
            return self.array
        return list(self.buffer[: self.n])


_U32 = "I" if array.array("I").itemsize == 4 else "L"


def uint32s(x: Any, what: str) -> Tuple[Any, int, int, bool]:
    """(keep, address, count, is_numpy) of a packed uint32 copy (or view) of ids."""
    if is_ndarray(x):
        a = np.asarray(x)
        if a.ndim == 0:
            a = a.reshape(1)
        if a.ndim != 1:
            raise ValueError(f"{what} must be one-dimensional")
        if a.dtype != np.uint32:
            if a.size and (not np.issubdtype(a.dtype, np.integer) or a.min() < 0
                           or a.max() > 0xFFFFFFFF):
                raise ValueError(f"{what} must hold integers in 0..2**32-1")
            a = a.astype(np.uint32)
        a = np.ascontiguousarray(a)
        return a, a.ctypes.data, a.shape[0], True
    if isinstance(x, numbers.Integral):
        x = (x,)
    try:
        arr = array.array(_U32, x)
    except (TypeError, OverflowError) as exc:
        raise ValueError(f"{what} must hold integers in 0..2**32-1") from exc
    if not arr:
        arr.append(0)  # a valid pointer; the count passed stays 0
        return arr, arr.buffer_info()[0], 0, False
    return arr, arr.buffer_info()[0], len(arr), False


class UInt32Output:
    """count uint32 values, shaped (rows, k) or flat, as a numpy array or a list."""

    def __init__(self, count: int, use_numpy: bool, shape: Tuple[int, ...]) -> None:
        self.count = count
        self.shape = shape
        if use_numpy:
            self.array = need_numpy().empty(shape, dtype=np.uint32)
            self.buf = None
            self.address = self.array.ctypes.data
        else:
            self.array = None
            self.buf = array.array(_U32, bytes(4 * max(count, 1)))
            self.address = self.buf.buffer_info()[0]

    def result(self) -> Any:
        if self.array is not None:
            return self.array
        values = self.buf[: self.count]
        if len(self.shape) == 1:
            return list(values)
        k = self.shape[1]
        return list(zip(*(values[c::k] for c in range(k))))


def flat_net(net: Any, weights: Any) -> Tuple[int, int, int, Any, Any, Any]:
    """(rows, cols, dim, ctrl keep, ctrl address, weights address) from a control net.

    The net is a numpy array or nested sequence of shape (deg_u+1, deg_v+1, dim); weights None or
    of shape (deg_u+1, deg_v+1). The library copies both, so one packed copy is made here.
    """
    if is_ndarray(net):
        a = np.ascontiguousarray(net, dtype=np.float64)
        if a.ndim != 3:
            raise ValueError(f"the control net must have shape (deg_u+1, deg_v+1, dim), got {a.shape}")
        rows, cols, dim = a.shape
        ctrl_keep: Any = a
        ctrl_addr = a.ctypes.data
    else:
        if isinstance(net, memoryview):
            net = net.tolist()
        rows_list = [list(r) for r in net]
        rows = len(rows_list)
        cols = len(rows_list[0]) if rows else 0
        points = [p for r in rows_list for p in r]
        dim = len(points[0]) if points else 0
        if any(len(r) != cols for r in rows_list) or any(len(p) != dim for p in points):
            raise ValueError("the control net must be rectangular: every row the same length, "
                             "every point the same dimension")
        flat = array.array("d")
        for p in points:
            flat.extend(p if isinstance(p, array.array) else array.array("d", p))
        if not flat:  # keep the pointer valid so that the library reports the real problem
            flat.append(0.0)
        ctrl_keep = flat
        ctrl_addr = flat.buffer_info()[0]
    if rows == 0 or cols == 0:
        raise ValueError("the control net needs at least one row and one column")
    w_keep: Any = None
    w_addr = None
    if weights is not None:
        if is_ndarray(weights):
            w = np.ascontiguousarray(weights, dtype=np.float64)
            if w.shape != (rows, cols):
                raise ValueError(f"weights must have shape {(rows, cols)}, got {w.shape}")
            w_keep, w_addr = w, w.ctypes.data
        else:
            wrows = [list(r) for r in weights]
            if len(wrows) != rows or any(len(r) != cols for r in wrows):
                raise ValueError(f"weights must have shape {(rows, cols)}")
            w_keep = array.array("d", [float(x) for r in wrows for x in r])
            w_addr = w_keep.buffer_info()[0]
    return rows, cols, dim, (ctrl_keep, w_keep), ctrl_addr, w_addr


def packed_doubles(values: Any, count: int, what: str) -> Tuple[Any, int]:
    """A packed C copy of count doubles from a nested sequence or array (for small inputs)."""
    if is_ndarray(values):
        a = np.ascontiguousarray(values, dtype=np.float64).reshape(-1)
    else:
        a = array.array("d", _flatten(values))
    if len(a) != count:
        raise ValueError(f"{what} must hold {count} numbers, got {len(a)}")
    address = a.ctypes.data if is_ndarray(a) else a.buffer_info()[0]
    return a, address


def _flatten(x: Any) -> List[float]:
    if isinstance(x, numbers.Real):
        return [float(x)]
    out: List[float] = []
    for item in x:
        out.extend(_flatten(item))
    return out


def nested(flat: Sequence[float], shape: Sequence[int]) -> Any:
    """Split a flat sequence into nested lists; the innermost level becomes tuples."""
    if len(shape) == 1:
        return tuple(flat)
    step = 1
    for s in shape[1:]:
        step *= s
    return [nested(flat[i * step:(i + 1) * step], shape[1:]) for i in range(shape[0])]
