"""The Mesh class: an immutable indexed triangle mesh made by tessellating a surface."""

import ctypes
import os
from typing import Any, List, Optional, Tuple, Union

from . import _buffers as B
from ._handle import Handle
from ._lib import LIB

#: Export formats of :meth:`Mesh.write` (the names may be given as strings too).
FORMATS = {"obj": 0, "ply": 1, "ply_ascii": 2, "stl": 3}

Format = Union[int, str]


def _format(f: Format) -> int:
    if isinstance(f, str):
        try:
            return FORMATS[f.lower()]
        except KeyError:
            raise ValueError(f"format must be one of {sorted(FORMATS)}, not {f!r}") from None
    return int(f)


class Mesh(Handle):
    """An immutable triangle mesh (from :meth:`Surface.tessellate` or
    :meth:`Surface.tessellate_adaptive`).

    Vertices carry a position, a unit normal, a (u, v) pair and the id of the patch they were
    evaluated on; triangles are counter-clockwise index triples seen from the side the normals
    point to. The read-back methods return lists of tuples, or numpy arrays written in place by
    the library when ``numpy=True`` (or an ``out=`` array, where offered, is given). A mesh is a
    context manager; ``close()`` releases it at once.
    """

    _destroy = LIB.bs_mesh_destroy

    def __init__(self) -> None:
        raise TypeError("meshes are made by Surface.tessellate() and Surface.tessellate_adaptive()")

    @classmethod
    def _wrap(cls, handle: Optional[int]) -> "Mesh":
        m = cls.__new__(cls)
        m._adopt(handle)  # type: ignore[arg-type]
        return m

    @property
    def vertex_count(self) -> int:
        """Number of vertices."""
        return int(LIB.bs_mesh_vertex_count(self._ptr))

    @property
    def triangle_count(self) -> int:
        """Number of triangles."""
        return int(LIB.bs_mesh_triangle_count(self._ptr))

    @property
    def strip_count(self) -> int:
        """Number of triangle strips (0 unless tessellated with ``strips=True``)."""
        return int(LIB.bs_mesh_strip_count(self._ptr))

    def _views(self, fn: Any, n: int, k: int, numpy: bool, out: Any) -> Any:
        res = B.Output(n, k, numpy, out)
        fn(self._ptr, res.views)
        return res.result()

    def positions(self, *, numpy: bool = False, out: Any = None) -> Any:
        """Vertex positions, (vertex_count, 3)."""
        return self._views(LIB.bs_mesh_copy_positions, self.vertex_count, 3, numpy, out)

    def normals(self, *, numpy: bool = False, out: Any = None) -> Any:
        """Unit vertex normals, (vertex_count, 3); never NaN."""
        return self._views(LIB.bs_mesh_copy_normals, self.vertex_count, 3, numpy, out)

    def uv(self, *, numpy: bool = False, out: Any = None) -> Any:
        """Vertex (u, v) parameters on the patch each vertex was evaluated on, (vertex_count, 2)."""
        return self._views(LIB.bs_mesh_copy_uv, self.vertex_count, 2, numpy, out)

    def corner_uv(self, *, numpy: bool = False, out: Any = None) -> Any:
        """(u, v) of every triangle corner on the triangle's own patch, (3 * triangle_count, 2)."""
        return self._views(LIB.bs_mesh_copy_corner_uv, 3 * self.triangle_count, 2, numpy, out)

    def _ids(self, fn: Any, count: int, shape: Tuple[int, ...], numpy: bool) -> Any:
        res = B.UInt32Output(count, numpy, shape)
        fn(self._ptr, res.address, count)
        return res.result()

    def patch_ids(self, *, numpy: bool = False) -> Any:
        """Per vertex, the id of the patch it was evaluated on (uint32)."""
        n = self.vertex_count
        return self._ids(LIB.bs_mesh_copy_patch_ids, n, (n,), numpy)

    def triangles(self, *, numpy: bool = False) -> Any:
        """Vertex index triples, (triangle_count, 3) (uint32)."""
        n = self.triangle_count
        return self._ids(LIB.bs_mesh_copy_triangles, 3 * n, (n, 3), numpy)

    def triangle_patch_ids(self, *, numpy: bool = False) -> Any:
        """Per triangle, the id of the patch it tessellates (uint32)."""
        n = self.triangle_count
        return self._ids(LIB.bs_mesh_copy_triangle_patch_ids, n, (n,), numpy)

    def strips(self) -> List[List[int]]:
        """The triangle strips as lists of vertex indices. Triangle i of a strip s is
        (s[i], s[i+1], s[i+2]) for even i and (s[i+1], s[i], s[i+2]) for odd i; triangles with
        a repeated index (at poles) are degenerate and to be dropped."""
        nidx = int(LIB.bs_mesh_strip_index_count(self._ptr))
        nstart = self.strip_count + 1
        idx = B.UInt32Output(nidx, False, (nidx,))
        start = B.UInt32Output(nstart, False, (nstart,))
        LIB.bs_mesh_copy_strips(self._ptr, idx.address, nidx, start.address, nstart)
        flat, offsets = idx.result(), start.result()
        return [flat[offsets[k]:offsets[k + 1]] for k in range(nstart - 1)]

    def write(self, path: "Union[str, bytes, os.PathLike[str]]", format: Format = "obj") -> None:
        """Write the mesh to a file: "obj" (Wavefront OBJ), "ply" (binary little-endian),
        "ply_ascii" or "stl" (binary)."""
        LIB.bs_mesh_write(self._ptr, _format(format), os.fsencode(path))

    def to_bytes(self, format: Format = "obj") -> bytes:
        """The bytes :meth:`write` would put in a file."""
        fmt = _format(format)
        size = ctypes.c_size_t()
        LIB.bs_mesh_write_memory(self._ptr, fmt, None, 0, ctypes.byref(size))
        buf = ctypes.create_string_buffer(max(size.value, 1))
        LIB.bs_mesh_write_memory(self._ptr, fmt, buf, size.value, ctypes.byref(size))
        return buf.raw[: size.value]

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Mesh (closed)>"
        return f"<bezsurf.Mesh {self.vertex_count} vertices {self.triangle_count} triangles>"
