"""The library's integer constants as IntEnum classes (they compare equal to the C values)."""

from enum import IntEnum


class Direction(IntEnum):
    """A parameter direction (BS_DIR_*): split(), isocurve() and reverse() also take "u"/"v"."""

    U = 0
    V = 1


class NormalKind(IntEnum):
    """How a normal was obtained (BS_NORMAL_*)."""

    REGULAR = 0     #: from S_u x S_v
    LIMIT = 1       #: S_u x S_v vanishes; the limit normal along the surface
    UNDEFINED = 2   #: no normal exists; (0, 0, 0) is written


class CurvatureKind(IntEnum):
    """How a curvature was obtained (BS_CURV_*, since 1.1)."""

    REGULAR = 0     #: from the fundamental forms at the point
    LIMIT = 1       #: the limit along the line towards (1/2, 1/2) (collapsed edges, poles)
    UNDEFINED = 2   #: no finite curvature (a cone's apex); NaN is written


class Format(IntEnum):
    """Mesh export formats (BS_MESH_*): Mesh.write() and to_bytes() also take their names."""

    OBJ = 0         #: Wavefront OBJ (text)
    PLY = 1         #: binary little-endian PLY
    PLY_ASCII = 2   #: ASCII PLY
    STL = 3         #: binary STL


class TessMethod(IntEnum):
    """Tessellation methods of bs_tess_options (BS_TESS_UNIFORM ..., since 1.1)."""

    UNIFORM = 0     #: nu x nv segments per patch
    PER_PATCH = 1   #: one segment count per patch and direction from a curvature bound
    SUBDIVIDE = 2   #: a quadtree of sub-patches, refined where the surface curves


class Side(IntEnum):
    """The sides of a patch's unit square (BS_SIDE_*), counter-clockwise."""

    V0 = 0          #: v = 0, running along u
    U1 = 1          #: u = 1, running along v
    V1 = 2          #: v = 1, running along u
    U0 = 3          #: u = 0, running along v


#: NormalKind members indexed by their value (turns the library's bytes into members quickly).
NORMAL_KINDS = tuple(NormalKind)
SIDES = tuple(Side)
