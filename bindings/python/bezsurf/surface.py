"""The Surface class: an ordered set of patches of one dimension (a quilt such as the teapot)."""

import ctypes
from typing import Any, Iterable, Iterator, Optional

from ._handle import Handle
from ._lib import LIB
from .patch import Patch


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
