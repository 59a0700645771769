"""Curvature through the binding: a sphere with a pole, a cylinder, undefined points."""

import math
import unittest

import bezsurf

from .support import PlainTestCase, numpy as np, plain, requires

R = 2.5
H = math.sqrt(0.5)


def sphere_octant():
    """The octant of a sphere of radius R (rational biquadratic), its pole the side u = 0."""
    q, wq = [(0, R), (R, R), (R, 0)], [1, H, 1]
    a, wa = [(1, 0), (1, 1), (0, 1)], [1, H, 1]
    net = [[[q[i][0] * a[j][0], q[i][0] * a[j][1], q[i][1]] for j in range(3)] for i in range(3)]
    w = [[wq[i] * wa[j] for j in range(3)] for i in range(3)]
    return bezsurf.Patch(net, w)


@requires("bs_patch_eval_curvature")
class CurvatureTest(PlainTestCase):
    def test_sphere(self):
        p = sphere_octant()
        c = p.eval_curvature([0.3, 0.0, 0.8], [0.6, 0.5, 1.0])
        kinds = plain(c.kind)
        self.assertEqual([int(k) for k in kinds], [0, 1, 0])
        if np is None:
            self.assertIsInstance(kinds[1], bezsurf.CurvatureKind)
        for i in range(3):
            tol = 1e-6 if i == 1 else 1e-9
            self.assertAlmostEqual(plain(c.gaussian)[i], 1 / R ** 2, delta=tol)
            self.assertAlmostEqual(abs(plain(c.mean)[i]), 1 / R, delta=tol)
            self.assertAlmostEqual(plain(c.k_min)[i], plain(c.k_max)[i], delta=tol)
        one = p.eval_curvature(0.3, 0.6)                      # scalars: one point
        self.assertAlmostEqual(one.gaussian, 1 / R ** 2, delta=1e-12)
        self.assertEqual(len(plain(one.d_min)), 3)

    def test_cylinder_and_undefined(self):
        a, wa = [(1, 0), (1, 1), (0, 1)], [1, H, 1]
        net = [[[R * a[j][0], R * a[j][1], 4.0 * i] for j in range(3)] for i in range(2)]
        p = bezsurf.Patch(net, [wa, wa])
        c = p.eval_curvature(0.5, 0.5)
        ks = sorted([c.k_min, c.k_max], key=abs)
        self.assertAlmostEqual(ks[0], 0.0, delta=1e-12)
        self.assertAlmostEqual(abs(ks[1]), 1 / R, delta=1e-12)
        bad = p.eval_curvature([math.nan], [0.5])
        self.assertTrue(math.isnan(plain(bad.gaussian)[0]))
        self.assertEqual(int(plain(bad.kind)[0]), bezsurf.CurvatureKind.UNDEFINED)
        flat = bezsurf.Patch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
        with self.assertRaises(bezsurf.DimensionError):
            flat.eval_curvature(0.5, 0.5)
        with self.assertRaises(ValueError):
            p.eval_curvature([0.1, 0.2], [0.3])


if __name__ == "__main__":
    unittest.main()
