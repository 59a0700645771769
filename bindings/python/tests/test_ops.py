"""Exact operations against hand-computed nets (dyadic values, so exact) and their properties."""

import math
import unittest

import bezsurf

from .support import PlainTestCase, plain, NET, bilinear, needs_numpy, numpy as np, requires

SADDLE = [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]]


@requires("bs_patch_split", "bs_patch_split4", "bs_patch_subpatch")
class SubdivisionTest(PlainTestCase):
    def test_split_u(self):
        lo, hi = bilinear().split("u", 0.5)
        self.assertEqual(lo.ctrl, [SADDLE[0], [(0.5, 0.0, 0.0), (0.5, 1.0, 0.5)]])
        self.assertEqual(hi.ctrl, [[(0.5, 0.0, 0.0), (0.5, 1.0, 0.5)], SADDLE[1]])

    def test_split_v_matches_parent(self):
        p = bezsurf.Patch(NET)
        lo, hi = p.split(bezsurf.DIR_V, 0.25)
        s = [0.0, 0.5, 1.0]
        self.assertEqual(lo.eval(s, s), p.eval(s, [x * 0.25 for x in s]))
        self.assertEqual(hi.eval([1.0], [0.0]), p.eval([1.0], [0.25]))

    def test_split4_order(self):
        parts = bilinear().split4(0.5, 0.5)
        self.assertEqual(len(parts), 4)
        # corner (0,0) of each part: (0,0), (.5,0), (0,.5), (.5,.5)
        self.assertEqual([q.ctrl[0][0] for q in parts],
                         [(0.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.0, 0.5, 0.0), (0.5, 0.5, 0.25)])

    def test_subpatch_reverses(self):
        q = bilinear().subpatch(1.0, 0.0, 0.0, 1.0)
        self.assertEqual(q.ctrl, [SADDLE[1], SADDLE[0]])

    def test_errors(self):
        p = bilinear()
        with self.assertRaises(bezsurf.DomainError):
            p.split("u", 0.0)
        with self.assertRaises(bezsurf.DomainError):
            p.split4(0.5, math.nan)
        with self.assertRaises(bezsurf.InvalidArgumentError):
            p.split(7, 0.5)
        with self.assertRaises(ValueError):
            p.split("w", 0.5)
        with self.assertRaises(bezsurf.DomainError):
            p.subpatch(0.5, 0.5, 0, 1)


@requires("bs_patch_elevate", "bs_patch_derivative", "bs_patch_isocurve", "bs_patch_bounds",
          "bs_patch_transform")
class OperationsTest(PlainTestCase):
    def test_elevate(self):
        q = bilinear().elevate(1, 1)
        self.assertEqual(q.degree, (2, 2))
        self.assertEqual(q.ctrl[1][1], (0.5, 0.5, 0.25))
        self.assertEqual(q.ctrl[2][2], (1.0, 1.0, 1.0))
        with self.assertRaises(bezsurf.DegreeError):
            bilinear().elevate(bezsurf.MAX_DEGREE, 0)

    def test_derivative(self):
        d = bilinear().derivative(1, 0)
        self.assertEqual(d.degree, (0, 1))
        self.assertEqual(d.ctrl, [[(1.0, 0.0, 0.0), (1.0, 0.0, 1.0)]])
        # NET along u: x rows 1 -> 2 -> 4 at j = 0; second difference 4 - 2*2 + 1 = 1, times 2!
        self.assertEqual(bezsurf.Patch(NET).derivative(2, 0).ctrl[0][0][0], 2.0)
        with self.assertRaises(bezsurf.UnsupportedError):
            bezsurf.Patch(NET, [[1, 2, 1]] * 3).derivative(1, 0)

    def test_isocurve(self):
        c = bilinear().isocurve("u", 0.5)
        self.assertIsInstance(c, bezsurf.Curve)
        self.assertEqual(c.points, [(0.5, 0.0, 0.0), (0.5, 1.0, 0.5)])
        self.assertIsNone(c.weights)
        pts, w = bezsurf.Patch(NET, [[1, 2, 1]] * 3).isocurve("v", 0.0)
        self.assertEqual(pts, [(1.0, 0.0, 2.0), (2.0, 1.0, 0.0), (4.0, 1.0, 0.0)])
        self.assertEqual(list(w), [1.0, 1.0, 1.0])
        with self.assertRaises(bezsurf.DomainError):
            bilinear().isocurve("u", math.inf)

    def test_bounds(self):
        self.assertEqual(bezsurf.Patch(NET).bounds(), ((1.0, 0.0, 0.0), (4.0, 4.0, 4.0)))

    def test_transform(self):
        affine = [[2, 0, 0, 1], [0, 1, 0, -1], [0, 0, 1, 0.5]]
        q = bilinear().transform(affine)
        self.assertEqual(q.ctrl[1][1], (3.0, 0.0, 1.5))
        with self.assertRaises(ValueError):
            bilinear().transform([[1, 0, 0]])
        with self.assertRaises(bezsurf.NonFiniteError):
            bilinear().transform([[math.nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]])

    @needs_numpy
    def test_numpy_variants(self):
        q = bilinear().transform(np.eye(3, 4))
        self.assertEqual(q.ctrl, SADDLE)
        pts, w = bilinear().isocurve("v", 1.0)
        self.assertTrue(np.array_equal(pts, [[0, 1, 0], [1, 1, 1]]))
        self.assertIsNone(w)


@requires("bs_patch_swap_uv", "bs_patch_reverse", "bs_patch_ruled", "bs_patch_coons")
class OrientationAndConstructionTest(PlainTestCase):
    def test_swap_and_reverse(self):
        p = bezsurf.Patch(NET)
        self.assertEqual(p.swap_uv().ctrl, [list(col) for col in zip(*p.ctrl)])
        self.assertEqual(p.reverse("u").ctrl, p.ctrl[::-1])
        self.assertEqual(p.reverse("v").ctrl, [row[::-1] for row in p.ctrl])

    def test_ruled_reproduces_saddle(self):
        q = bezsurf.Patch.ruled([(0, 0, 0), (1, 0, 0)], bezsurf.Curve([(0, 1, 0), (1, 1, 1)]))
        self.assertEqual(q.ctrl, [[SADDLE[0][0], SADDLE[0][1]], [SADDLE[1][0], SADDLE[1][1]]])

    def test_coons_of_saddle_boundaries(self):
        v0 = [(0, 0, 0), (1, 0, 0)]
        v1 = [(0, 1, 0), (1, 1, 1)]
        u0 = [(0, 0, 0), (0, 1, 0)]
        u1 = [(1, 0, 0), (1, 1, 1)]
        q = bezsurf.Patch.coons(v0, v1, u0, u1)
        self.assertEqual(q.eval([0.5, 0.25], [0.5, 0.75]), [(0.5, 0.5, 0.25), (0.25, 0.75, 0.1875)])
        with self.assertRaises(bezsurf.IncompatibleError):
            bezsurf.Patch.coons(v0, v1, u0, [(2, 0, 0), (1, 1, 1)])
        with self.assertRaises(bezsurf.UnsupportedError):
            bezsurf.Patch.coons(bezsurf.Curve(v0, [1, 2]), v1, u0, u1)


if __name__ == "__main__":
    unittest.main()
