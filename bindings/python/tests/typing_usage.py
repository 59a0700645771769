"""Typical uses of the binding, for the type checker (tests/typecheck.py), not for running.

``assert_type`` fails the check when an overload resolves to another type than documented.
"""

from typing import List, Optional, Tuple

from typing_extensions import assert_type

import bezsurf
from bezsurf._buffers import (BoolOrBools, CodeOrCodes, Grid, Ids, IdOrIds, IdRows, KindOrKinds, Point,
                              PointOrPoints, Points, RealOrReals, Reals)


def uses(path: str) -> None:
    p = bezsurf.Patch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], weights=None)
    assert_type(p.eval(0.5, 0.5), Point)
    assert_type(p.eval([0.5], [0.5]), Points)
    assert_type(p.eval(0.5, [0.5, 0.25]), Points)
    assert_type(p.eval([0.5], [0.5], derivatives=True), bezsurf.Evaluation)
    assert_type(p.eval([0.5], [0.5], normals=True), bezsurf.Evaluation)
    assert_type(p.eval_grid([0.0, 1.0], [0.0, 1.0]), Points)
    assert_type(p.eval_deriv(1, 0, 0.5, 0.5), Point)
    ev = p.eval_normal([0.5], [0.5])
    assert_type(ev.position, PointOrPoints)
    lo, hi = p.split(bezsurf.Direction.U, 0.5)
    assert_type(lo, bezsurf.Patch)
    assert_type(p.split4(0.5, 0.5)[3], bezsurf.Patch)
    assert_type(p.degree, Tuple[int, int])
    assert_type(p.weights, Optional[List[List[float]]])
    c = p.isocurve("u", 0.5)
    assert_type(c.points, Grid)
    assert_type(c.weights, Optional[Reals])
    assert_type(bezsurf.Patch.ruled(c, [[0, 0, 1], [1, 0, 1]]), bezsurf.Patch)

    s = bezsurf.Surface.load(path)
    assert_type(s[0], bezsurf.Patch)
    assert_type(s[1:], bezsurf.Surface)
    assert_type(s.eval([0, 1], [0.5, 0.5], [0.5, 0.5]), Points)
    assert_type(s.eval(0, 0.5, 0.5), Point)
    assert_type(s.continuity().edges[0].side_a, bezsurf.Side)
    assert_type(s.eval_normal([0, 1], [0.5, 0.5], [0.5, 0.5], threads=2), bezsurf.Evaluation)
    assert_type(s.eval([0, 1], [0.5, 0.5], [0.5, 0.5], normals=True, threads=0), bezsurf.Evaluation)
    assert_type(s.eval_grid([0.0, 1.0], [0.5]), Points)
    assert_type(s.eval_grid([0.0, 1.0], [0.5], normals=True, threads=2), bezsurf.Evaluation)
    assert_type(p.eval_curvature(0.5, 0.5).mean, RealOrReals)
    with s.locator() as loc:
        near = loc.closest_point([(0.0, 0.0, 1.0)], threads=2)
        assert_type(near.dist, RealOrReals)
        assert_type(near.patch, Optional[IdOrIds])
        hits = loc.intersect([(0.0, 0.0, 5.0)], [(0.0, 0.0, -1.0)], t_max=10.0)
        assert_type(hits.hit, BoolOrBools)
        assert_type(loc.intersect_kinds((0.0, 0.0, 5.0), (0.0, 0.0, -1.0))[1], KindOrKinds)
    model = bezsurf.Model(s)
    assert_type(model.face_eval(0, [0.5], [0.5]).normal, PointOrPoints)
    assert_type(model.classify([0], [0.5], [0.5]), CodeOrCodes)
    assert_type(model.face_to_patch(0, 0.5, 0.5)[0], IdOrIds)
    with s.tessellate(8, strips=True) as m:
        assert_type(m.positions(), Points)
        assert_type(m.triangles(), IdRows)
        assert_type(m.patch_ids(), Ids)
        assert_type(m.strips(), List[List[int]])
        m.write(path + ".ply", bezsurf.Format.PLY)
        assert_type(m.to_bytes("stl"), bytes)
    try:
        bezsurf.Surface.load(path)
    except FileNotFoundError as e:
        assert_type(e.errno, int)
    assert_type(bezsurf.version(), str)
