"""Checking scalar arguments before they reach ctypes.

ctypes would report a wrong type as ``ctypes.ArgumentError`` naming an argument position; these
helpers raise TypeError (wrong type) or ValueError (right type, value out of range) naming the
Python argument instead.
"""

import ctypes
import numbers
import operator
import os
from typing import SupportsFloat, SupportsIndex, Union, cast

from ._enums import Direction, Format

SIZE_MAX = 2 ** (8 * ctypes.sizeof(ctypes.c_size_t)) - 1
UINT_MAX = 2 ** 32 - 1

PathArg = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]


def _name(x: object) -> str:
    return type(x).__name__


def real(x: object, name: str) -> float:
    """A real number (int, float, numpy scalar, 0-d array) as a float."""
    if isinstance(x, numbers.Real) and not isinstance(x, bool):
        return float(x)
    if getattr(x, "ndim", None) == 0 and getattr(getattr(x, "dtype", None), "kind", "") in "iuf":
        return float(cast(SupportsFloat, x))  # a 0-d array of a real dtype
    raise TypeError(f"{name} must be a real number, not {_name(x)}")


def integer(x: object, name: str, lo: int = 0, hi: int = SIZE_MAX) -> int:
    """An integer in [lo, hi] (anything with __index__, not bool)."""
    if isinstance(x, bool):
        raise TypeError(f"{name} must be an integer, not bool")
    try:
        i = operator.index(cast(SupportsIndex, x))  # operator.index checks it
    except TypeError:
        raise TypeError(f"{name} must be an integer, not {_name(x)}") from None
    if not lo <= i <= hi:
        raise ValueError(f"{name} must be in {lo}..{hi}, got {i}")
    return i


def direction(d: object, name: str = "direction") -> int:
    """'u', 'v' (any case), Direction.U/V, or 0/1."""
    if isinstance(d, str):
        try:
            return Direction[d.upper()]
        except KeyError:
            raise ValueError(f"{name} must be 'u' or 'v', not {d!r}") from None
    i = integer(d, name, -2 ** 31, 2 ** 31 - 1)
    # an int that is no member goes to the library, which reports it (InvalidArgumentError)
    return Direction(i) if i in Direction._value2member_map_ else i


def mesh_format(f: object, name: str = "format") -> int:
    """A Format member or value, or its name ("obj", "ply", "ply_ascii", "stl")."""
    if isinstance(f, str):
        try:
            return Format[f.upper()]
        except KeyError:
            names = ", ".join(m.name.lower() for m in Format)
            raise ValueError(f"{name} must be one of {names}, not {f!r}") from None
    i = integer(f, name, -2 ** 31, 2 ** 31 - 1)
    return Format(i) if i in Format._value2member_map_ else i


def path(p: object, name: str = "path") -> bytes:
    """A file name for the C library (str, bytes or os.PathLike); a NUL byte in it is refused as
    open() refuses it (the C library would read the name only up to it)."""
    try:
        b = os.fsencode(cast(PathArg, p))  # os.fsencode checks it
    except TypeError:
        raise TypeError(f"{name} must be a str, bytes or os.PathLike, not {_name(p)}") from None
    if b"\0" in b:
        raise ValueError(f"{name} must not contain a NUL byte (embedded null byte): {p!r}")
    return b


def instance(x: object, cls: type, name: str) -> None:
    if not isinstance(x, cls):
        raise TypeError(f"{name} must be a bezsurf.{cls.__name__}, not {_name(x)}")
