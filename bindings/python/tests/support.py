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
