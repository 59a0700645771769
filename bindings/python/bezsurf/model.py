"""Trimmed B-rep models of 1.2: faces over exact patches, trim loops, edges and shells, read from
STEP, IGES and OBJ files (docs/models.md)."""

import ctypes
import os
from typing import Callable, Dict, List, NamedTuple, Optional, Tuple, Type, Union, cast

from . import _args as A
from . import _buffers as B
from ._buffers import CodeOrCodes, IdOrIds, IdsIn, KindOrKinds, PointOrPoints
from ._errors import BezsurfError, BezsurfIOError, io_error
from ._handle import Handle
from ._lib import BS_ERR_IO, LIB, CFaceInfo, CParseError
from ._enums import TessMethod
from .mesh import Mesh, tess_options
from .patch import Params, _Call
from .query import Locator
from .surface import Surface, _located, _with_file

try:  # numpy is optional
    import numpy as np
except ImportError:  # pragma: no cover - depends on the interpreter
    np = None  # type: ignore[assignment]

#: What a model is made again from: ("surface", a Surface) or (format, the file's bytes).
_Source = Tuple[str, Union[Surface, bytes]]

#: Surface kinds of faces (``Face.kind``), in the order of the C constants BS_FACE_*.
FACE_KINDS = ("bezier", "bspline", "plane", "cylinder", "cone", "sphere", "torus", "revolution",
              "extrusion")

#: Where a point lies with respect to a trimmed face (:meth:`Model.classify`).
TRIM_OUTSIDE = 0
TRIM_INSIDE = 1
TRIM_ON = 2

LIB_IO_TEXT = "input/output error"

#: File formats :meth:`Model.read` knows, by extension.
_FORMATS = {".step": "step", ".stp": "step", ".igs": "iges", ".iges": "iges", ".obj": "obj",
            ".bpt": "bpt"}
_TEXT_READERS = {"step": LIB.bs_model_read_step, "iges": LIB.bs_model_read_iges,
                 "obj": LIB.bs_model_read_obj}


class Face(NamedTuple):
    """One face of a model: its surface kind (one of :data:`FACE_KINDS`), whether its outward side
    is opposite its surface normal, its shell and assembly instance, its patches in
    :attr:`Model.surface` (``first_patch`` .. ``first_patch + patch_count - 1``), its number of
    trim loops (0: untrimmed) and its native parameter box (u0, u1, v0, v1)."""

    kind: str
    reversed: bool
    shell: int
    instance: int
    first_patch: int
    patch_count: int
    loop_count: int
    box: Tuple[float, float, float, float]


class Properties(NamedTuple):
    """Area of the faces, volume enclosed by the closed shells (NaN when none is closed) and the
    centroid of that volume (of the area when no shell is closed), of :meth:`Model.properties`."""

    area: float
    volume: float
    centroid: Tuple[float, float, float]


class FaceEvaluation(NamedTuple):
    """Positions (n, 3) (``position``, as :class:`Evaluation`), outward unit normals (n, 3) and normal kinds (n,) of
    :meth:`Model.face_eval`; for one point the leading n axis is dropped."""

    position: PointOrPoints
    normal: PointOrPoints
    kind: KindOrKinds


def _text_bytes(text: Union[str, bytes]) -> bytes:
    if isinstance(text, str):
        return text.encode("utf-8")
    if isinstance(text, (bytes, bytearray, memoryview)):
        return bytes(text)
    raise TypeError(f"text must be a str or bytes, not {type(text).__name__}")


class Model(Handle):
    """A trimmed B-rep model: faces (pieces of surfaces bounded by trim loops) joined along edges
    into shells. Immutable; any number of threads may use it at once.

    ``Model(surface)`` makes the model of a surface (each patch an untrimmed face, shared sides
    joined as edges); :meth:`read` and :meth:`read_step`, :meth:`read_iges`, :meth:`read_obj`
    read CAD files. A model is a context manager, and can be copied and pickled (a model read
    from a file keeps the file's bytes for that).
    """

    _destroy = LIB.bs_model_destroy

    def __init__(self, surface: Surface) -> None:
        A.instance(surface, Surface, "surface")
        out = ctypes.c_void_p()
        LIB.bs_model_from_surface(surface._ptr, ctypes.byref(out))
        self._adopt(out.value)  # type: ignore[arg-type]
        self._source: _Source = ("surface", surface.clone())

    @classmethod
    def _wrap(cls, handle: Optional[int], source: _Source) -> "Model":
        m = cls.__new__(cls)
        m._adopt(handle)  # type: ignore[arg-type]
        m._source = source
        return m

    @classmethod
    def _read_text(cls, fmt: str, data: bytes, filename: Optional[str] = None) -> "Model":
        err = CParseError()
        out = ctypes.c_void_p()
        try:
            _TEXT_READERS[fmt](data, len(data), ctypes.byref(err), ctypes.byref(out))
        except BezsurfError as exc:
            raise _located(exc, err, filename) from None
        return cls._wrap(out.value, (fmt, data))

    @classmethod
    def read_step(cls, text: Union[str, bytes]) -> "Model":
        """Parse STEP text (ISO 10303-21; AP203, AP214, AP242 geometry). Raises ParseError with
        ``line`` and ``column``, UnsupportedError naming an entity the geometry needs that is not
        read."""
        return cls._read_text("step", _text_bytes(text))

    @classmethod
    def read_iges(cls, text: Union[str, bytes]) -> "Model":
        """Parse IGES 5.3 text: trimmed surfaces (144, 143), B-rep solids (186), B-spline
        surfaces (128). Errors as :meth:`read_step`."""
        return cls._read_text("iges", _text_bytes(text))

    @classmethod
    def read_obj(cls, text: Union[str, bytes]) -> "Model":
        """Parse OBJ free-form text: each ``surf`` a face trimmed by its ``trim`` and ``hole``
        loops. Errors as :meth:`read_step`."""
        return cls._read_text("obj", _text_bytes(text))

    @classmethod
    def read(cls, path: A.PathArg, format: Optional[str] = None) -> "Model":
        """Read a model file; the format is ``format`` ("step", "iges", "obj" or "bpt") or else
        the file's extension (.step/.stp, .igs/.iges, .obj, .bpt). A .bpt file gives the model of
        its surface. Raises BezsurfIOError (an OSError with ``errno`` and ``filename``) when the
        file cannot be read, ParseError with ``line``, ``column`` and ``filename`` when it is
        malformed, ValueError for an unknown format."""
        name = A.path(path)
        if format is None:
            ext = os.path.splitext(os.fsdecode(name))[1].lower()
            if ext not in _FORMATS:
                raise ValueError(f"cannot tell the format of {os.fsdecode(name)!r} from its "
                                 f"extension: pass format= (step, iges, obj, bpt)")
            format = _FORMATS[ext]
        if format not in ("step", "iges", "obj", "bpt"):
            raise ValueError(f"format must be one of step, iges, obj, bpt, not {format!r}")
        if format == "bpt":
            return cls(Surface.load(path))
        try:
            with open(name, "rb") as f:
                data = f.read()
        except OSError as exc:
            raise io_error(BS_ERR_IO, LIB_IO_TEXT, "open", exc.strerror, exc.errno or 0,
                           os.fsdecode(name)) from None
        return cls._read_text(format, data, os.fsdecode(name))

    def __len__(self) -> int:
        """Number of faces."""
        return int(LIB.bs_model_face_count(self._ptr))

    @property
    def edge_count(self) -> int:
        """Number of model edges (3-D edges shared by faces, each counted once)."""
        return int(LIB.bs_model_edge_count(self._ptr))

    @property
    def shells(self) -> List[bool]:
        """For each shell, whether it is closed (bounds a solid)."""
        n = int(LIB.bs_model_shell_count(self._ptr))
        return [LIB.bs_model_shell_closed(self._ptr, k) == 1 for k in range(n)]

    def face(self, index: int) -> Face:
        """The description of face ``index`` (IndexError when out of range)."""
        n = len(self)
        index = A.integer(index, "index", -n, n - 1) if n else A.integer(index, "index", 0, -1)
        if index < 0:
            index += n
        info = CFaceInfo()
        info.size = ctypes.sizeof(CFaceInfo)
        LIB.bs_model_face_info(self._ptr, index, ctypes.byref(info))
        kind = FACE_KINDS[info.kind] if 0 <= info.kind < len(FACE_KINDS) else str(info.kind)
        return Face(kind, bool(info.reversed), int(info.shell), int(info.instance),
                    int(info.first_patch), int(info.patch_count), int(info.loop_count),
                    (info.u0, info.u1, info.v0, info.v1))

    @property
    def faces(self) -> List[Face]:
        """Every face's description, in face order."""
        return [self.face(k) for k in range(len(self))]

    @property
    def surface(self) -> Surface:
        """Every face's patches as one surface, borrowed from the model (it keeps the model
        alive; ``clone()`` it for an independent copy)."""
        handle = LIB.bs_model_surface(self._ptr)
        s = Surface.__new__(Surface)
        s._adopt(handle, self)
        return s

    def _face_ids(self, faces: IdsIn, call: _Call) -> Tuple[object, int]:
        if isinstance(faces, int) and not isinstance(faces, bool) and not call.scalar:
            faces = [faces] * call.n
        keep, addr, n = B.uint32s(faces, "faces")
        if n != call.n:
            raise ValueError(f"faces and u must have the same length ({n} != {call.n})")
        count = len(self)
        ids: Union["B.RealArray", List[int]] = keep if B.is_ndarray(keep) else list(keep)
        if n and max(ids) >= count:
            raise IndexError(f"a face id is out of range: the model has {count} faces")
        return keep, addr

    def face_eval(self, faces: IdsIn, u: Params, v: Params) -> FaceEvaluation:
        """Positions and outward unit normals of faces at native parameters (u, v): point k on
        face ``faces[k]`` (one id for all points). Points outside a face's patches give NaN."""
        call = _Call(u, v, inputs=[("faces", faces)])
        keep, addr = self._face_ids(faces, call)
        pos = call.output(3, None, "pos")
        nrm = call.output(3, None, "normal")
        kinds = call.kinds(None)
        LIB.bs_model_face_eval(self._ptr, call.n, addr, call.u, call.v, pos.views, nrm.views,
                               kinds.address)
        del keep
        kind = kinds.result()
        return FaceEvaluation(call.finish(pos.result()), call.finish(nrm.result()),
                              kind[0] if call.scalar else kind)

    def face_to_patch(self, faces: IdsIn, u: Params, v: Params) -> Tuple[IdOrIds, PointOrPoints]:
        """The patch of :attr:`surface` holding each native (u, v) and the local (s, t) there:
        (patch ids, st of shape (n, 2)); outside a face: patch 4294967295 and NaN."""
        call = _Call(u, v, inputs=[("faces", faces)])
        keep, addr = self._face_ids(faces, call)
        st = call.output(2, None, "st")
        ids = B.UInt32Output(call.n, (call.n,))
        LIB.bs_model_face_to_patch(self._ptr, call.n, addr, call.u, call.v, ids.address,
                                   st.views)
        del keep
        patch = ids.ids()
        return (patch[0] if call.scalar else patch), call.finish(st.result())

    def patch_to_face(self, patches: IdsIn, s: Params, t: Params) -> Tuple[IdOrIds, PointOrPoints]:
        """The inverse of :meth:`face_to_patch`: the face holding each patch of :attr:`surface`
        (one id for all points, or one per point) and the native (u, v) of local (s, t) there:
        (face ids, uv of shape (n, 2)); (s, t) outside [0, 1]: face 4294967295 and NaN."""
        call = _Call(s, t, inputs=[("patches", patches)])
        if isinstance(patches, int) and not isinstance(patches, bool) and not call.scalar:
            patches = [patches] * call.n
        keep, addr, n = B.uint32s(patches, "patches")
        if n != call.n:
            raise ValueError(f"patches and s must have the same length ({n} != {call.n})")
        count = LIB.bs_surface_count(LIB.bs_model_surface(self._ptr))
        ids: Union["B.RealArray", List[int]] = keep if B.is_ndarray(keep) else list(keep)
        if n and max(ids) >= count:
            raise IndexError(f"a patch id is out of range: the model has {count} patches")
        uv = call.output(2, None, "uv")
        faces = B.UInt32Output(call.n, (call.n,))
        LIB.bs_model_patch_to_face(self._ptr, call.n, addr, call.u, call.v, faces.address,
                                   uv.views)
        del keep
        face = faces.ids()
        return (face[0] if call.scalar else face), call.finish(uv.result())

    def classify(self, faces: IdsIn, u: Params, v: Params, tol: float = 0.0) -> CodeOrCodes:
        """Where native (u, v) lies on each face: TRIM_INSIDE, TRIM_OUTSIDE, or TRIM_ON within
        ``tol`` (a 3-D distance >= 0) of the face's boundary. A uint8 array (a list without
        numpy), or one int for one point."""
        tol = A.real(tol, "tol")
        if not (tol >= 0.0) or tol == float("inf"):
            raise ValueError(f"tol must be finite and >= 0, not {tol}")
        call = _Call(u, v, inputs=[("faces", faces)])
        keep, addr = self._face_ids(faces, call)
        where = (ctypes.c_ubyte * max(call.n, 1))()
        LIB.bs_model_classify(self._ptr, call.n, addr, call.u, call.v, tol, where)
        del keep
        values = [int(x) for x in where[: call.n]]
        if call.scalar:
            return values[0]
        if B.have_numpy():
            B.need_numpy()
            codes: CodeOrCodes = np.array(values, dtype=np.uint8)
            return codes
        return values

    def properties(self, rel_tol: float = 1e-10) -> Properties:
        """Area, enclosed volume and centroid on the exact surfaces, within ``rel_tol``
        (1e-12 .. 0.1) of each (Gauss-Kronrod quadrature over the trimmed faces)."""
        rel_tol = A.real(rel_tol, "rel_tol")
        if not (1e-12 <= rel_tol <= 0.1):
            raise ValueError(f"rel_tol must be in [1e-12, 0.1], not {rel_tol}")
        area = ctypes.c_double()
        volume = ctypes.c_double()
        centroid = (ctypes.c_double * 3)()
        LIB.bs_model_properties(self._ptr, rel_tol, ctypes.addressof(area),
                                ctypes.addressof(volume), ctypes.addressof(centroid))
        return Properties(area.value, volume.value, (centroid[0], centroid[1], centroid[2]))

    def tessellate(self, tolerance: float, *, relative: bool = False, max_vertices: int = 0,
                   max_triangles: int = 0, threads: int = 1, reverse: bool = False) -> "Mesh":
        """One watertight mesh of the trimmed faces (since 1.2, bs_model_tessellate): every
        triangle within ``tolerance`` of its face (a distance, or with ``relative`` a fraction
        of the control points' box diagonal), each model edge sampled once and shared, so a
        closed shell gives a closed mesh, wound outward. Triangle ids are face ids, corner
        (u, v) native face parameters. Budgets, ``threads`` and ``reverse`` as for
        :meth:`Surface.tessellate`; the mesh is the same bit for bit whatever ``threads``."""
        args = Surface._tess_args(TessMethod.SUBDIVIDE, 16, 16, tolerance, relative, False,
                                  max_vertices, max_triangles, threads, reverse)
        return Mesh._tessellate(self.clone(), "model", args)

    def tessellate_count(self, tolerance: float, *, relative: bool = False,
                         reverse: bool = False) -> Tuple[int, int]:
        """(vertices, triangles) of the mesh :meth:`tessellate` would make (the faces are
        meshed, the mesh is not built)."""
        args = Surface._tess_args(TessMethod.SUBDIVIDE, 16, 16, tolerance, relative, False, 0, 0,
                                  1, reverse)
        nverts = ctypes.c_size_t()
        ntris = ctypes.c_size_t()
        LIB.bs_model_tessellate_count(self._ptr, ctypes.byref(tess_options(*args)),
                                      ctypes.byref(nverts), ctypes.byref(ntris))
        return int(nverts.value), int(ntris.value)

    def locator(self) -> "ModelLocator":
        """A locator of the model's trimmed faces, for rays and closest points (since 1.2): see
        :class:`ModelLocator`."""
        return ModelLocator(self)

    def to_obj(self) -> str:
        """The model as OBJ free-form text (surfaces with trim and hole loops), read back
        exactly by :meth:`read_obj`."""
        size = ctypes.c_size_t()
        LIB.bs_model_write_obj(self._ptr, None, 0, ctypes.byref(size))
        buf = ctypes.create_string_buffer(size.value + 1)
        LIB.bs_model_write_obj(self._ptr, buf, size.value + 1, ctypes.byref(size))
        return buf.value.decode("ascii")

    def save_obj(self, path: A.PathArg) -> None:
        """Write the model as an OBJ file (replaced only once written completely)."""
        name = A.path(path)
        ctypes.set_errno(0)
        try:
            LIB.bs_model_write_obj_file(self._ptr, name)
        except BezsurfIOError as exc:
            raise _with_file(exc, os.fsdecode(name)) from None

    def clone(self) -> "Model":
        """An independent copy (read again from the same source)."""
        return _rebuild(*self._source)

    __copy__ = clone

    def __deepcopy__(self, memo: Dict[int, object]) -> "Model":
        return self.clone()

    def __reduce__(self) -> Tuple[Callable[[str, Union[Surface, bytes]], "Model"], _Source]:
        return (_rebuild, self._source)

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.Model (closed)>"
        closed = sum(self.shells)
        return (f"<bezsurf.Model: {len(self)} faces, {self.edge_count} edges, "
                f"{len(self.shells)} shells ({closed} closed)>")


def _rebuild(fmt: str, source: Union[Surface, bytes]) -> Model:
    """A model made again from what it was made of (pickling, copies)."""
    if fmt == "surface":
        return Model(cast(Surface, source))
    return Model._read_text(fmt, cast(bytes, source))


__all__ = ["Model", "Face", "FaceEvaluation", "Properties", "FACE_KINDS", "TRIM_OUTSIDE", "TRIM_INSIDE",
           "TRIM_ON"]


class ModelLocator(Locator):
    """Rays and closest points on the trimmed faces of a :class:`Model`
    (``bs_locator_create_model``, since 1.2).

    :meth:`intersect` answers with the first hit inside a trimmed face (hits on a face's surface
    outside its trims are skipped): ``patch`` holds **face** ids, ``uv`` native face parameters
    and ``normal`` the outward normals. A point within 1e-7 of the model's size from a trim
    counts as inside, so that a ray through an edge hits one of its two faces.
    :meth:`closest_point` gives the closest point of the union of the trimmed faces, certified
    within 1e-9 (D + d) as for a surface, with face ids and native parameters (on a trim where
    the surface's own closest point lies outside its face). The locator keeps its model alive;
    copies and pickles rebuild it from the model.
    """

    def __init__(self, model: Model) -> None:  # pylint: disable=super-init-not-called
        A.instance(model, Model, "model")
        out = ctypes.c_void_p()
        LIB.bs_locator_create_model(model._ptr, ctypes.byref(out))
        self._adopt(out.value)  # type: ignore[arg-type]
        self._model = model  # the C locator refers to the model: keep it alive

    def __reduce__(self) -> Tuple[Type["ModelLocator"], Tuple[Model]]:
        self._ptr  # a closed locator is not copied
        return (ModelLocator, (self._model,))

    def __deepcopy__(self, memo: Dict[int, object]) -> "ModelLocator":
        return ModelLocator(self._model)

    def __repr__(self) -> str:
        if self.closed:
            return "<bezsurf.ModelLocator (closed)>"
        return f"<bezsurf.ModelLocator of {len(self._model)} faces>"
