"""Ownership of C handles: deterministic release and parents kept alive by their children."""

import ctypes
from typing import Callable, Optional, TypeVar

_H = TypeVar("_H", bound="Handle")


class Handle:
    """Base of the wrapper objects: owns (or borrows) one C handle.

    The handle is released by ``close()``, by leaving a ``with`` block, or when the object is
    garbage-collected, whichever comes first; closing twice is harmless. An object borrowed from a
    parent (a patch of a surface) holds a reference to the parent, so the parent outlives it, and
    it never releases the handle itself; it becomes unusable once the parent is closed.
    """

    _destroy: Optional[Callable[[int], None]] = None

    def __init__(self) -> None:  # pragma: no cover - subclasses build through _adopt
        raise TypeError("use a subclass")

    def _adopt(self, handle: int, parent: "Optional[Handle]" = None) -> None:
        self._handle: Optional[int] = handle
        self._parent = parent

    @property
    def closed(self) -> bool:
        """True once the handle (or the parent it was borrowed from) has been closed."""
        h = getattr(self, "_handle", None)
        return h is None or (self._parent is not None and self._parent.closed)

    @property
    def _ptr(self) -> ctypes.c_void_p:
        """The C handle; ValueError once closed (checked before every call)."""
        if self.closed:
            raise ValueError(f"operation on a closed {type(self).__name__}")
        return ctypes.c_void_p(self._handle)

    # Lets the object itself be passed to a C function. The public methods check their
    # arguments first, so that a wrong type is a TypeError naming the argument.
    _as_parameter_ = _ptr

    def close(self) -> None:
        """Release the C object now. Further use raises ValueError; closing again does nothing."""
        h = getattr(self, "_handle", None)
        self._handle = None
        if h is not None and self._parent is None and self._destroy is not None:
            type(self)._destroy(h)  # type: ignore[misc]

    def __enter__(self: _H) -> _H:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:  # interpreter shutdown: the library may already be gone
            pass
