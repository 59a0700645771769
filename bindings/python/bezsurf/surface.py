"""The Surface class: an ordered set of patches of one dimension (a quilt such as the teapot)."""

import ctypes
import os
from typing import Any, Iterable, Iterator, List, Optional, Union

from ._errors import BezsurfError, BezsurfIOError, ParseError
from ._handle import Handle
from ._lib import LIB, CParseError
from .patch import Patch

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

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Surface (closed)>"
        return f"<bezsurf.Surface {len(self)} patches dim {self.dim}>"
