"""Shared helpers of the binding tests."""

import os
import unittest
from pathlib import Path

import bezsurf
from bezsurf import _lib

try:
    import numpy
except ImportError:
    numpy = None

HAVE_NUMPY = numpy is not None
needs_numpy = unittest.skipUnless(HAVE_NUMPY, "numpy is not available to this interpreter")

SOURCE_DIR = Path(os.environ.get("BEZSURF_SOURCE_DIR", Path(__file__).resolve().parents[3]))
DATA_DIR = SOURCE_DIR / "data"


def requires(*names):
    """Skip a test whose C functions the loaded library does not export (a partial 1.x build)."""
    missing = [n for n in names if n in _lib.LIB.missing]
    return unittest.skipIf(bool(missing), f"library does not export {', '.join(missing)}")


# The patch of the acceptance check: a biquadratic 3-D net.
NET = [[[1, 0, 2], [1, 2, 4], [1, 3, 2]],
       [[2, 1, 0], [2, 2, 2], [2, 4, 0]],
       [[4, 1, 0], [3, 3, 2], [4, 4, 2]]]


def bilinear():
    """S(u,v) = (u, v, u*v): the hyperbolic paraboloid as a degree (1,1) patch."""
    return bezsurf.Patch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])


def plain(x):
    """A result as plain Python values: numpy arrays become what the binding returns without
    numpy (2-D: a list of tuples; 1-D floats: a tuple; 1-D integers: a list), recursively."""
    if numpy is not None:
        if isinstance(x, numpy.ndarray):
            if x.ndim == 2:
                return [tuple(r) for r in x.tolist()]
            if x.ndim == 1:
                return tuple(x.tolist()) if x.dtype.kind == "f" else x.tolist()
            return x.tolist()
        if isinstance(x, numpy.generic):
            return x.item()
    if isinstance(x, list):
        return [plain(e) for e in x]
    if isinstance(x, tuple):
        return type(x)(*(plain(e) for e in x)) if hasattr(x, "_fields") else \
            tuple(plain(e) for e in x)
    return x


class PlainTestCase(unittest.TestCase):
    """assertEqual compares results as plain Python values, so that one test checks the same
    values whether the binding returns numpy arrays (numpy importable) or lists."""

    def assertEqual(self, first, second, msg=None):
        super().assertEqual(plain(first), plain(second), msg)
