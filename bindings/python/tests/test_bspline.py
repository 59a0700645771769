"""B-spline and NURBS surfaces: the patches against a direct evaluation of the B-spline, spans,
locate, errors that name the argument, copies and pickles."""

import math
import pickle
import unittest

import bezsurf

from .support import PlainTestCase, numpy as np, plain, requires


def basis(t, p, i, x):
    """Basis functions N[i-p..i] of degree p at x on span i (the triangular Cox-de Boor scheme)."""
    n, left, right = [1.0] + [0.0] * p, [0.0] * (p + 1), [0.0] * (p + 1)
    for j in range(1, p + 1):
        left[j], right[j] = x - t[i + 1 - j], t[i + j] - x
        saved = 0.0
        for r in range(j):
            tmp = n[r] / (right[r + 1] + left[j - r])
            n[r] = saved + right[r + 1] * tmp
            saved = left[j - r] * tmp
        n[j] = saved
    return n


def span(t, p, count, x):
    """Knot index of the half-open span holding x (the last span closed)."""
    i = p
    while i + 1 < count and not (t[i] < t[i + 1] and x < t[i + 1]):
        i += 1
    return i


def point(ctrl, w, ku, kv, pu, pv, u, v):
    cu, cv = len(ctrl), len(ctrl[0])
    iu, iv = span(ku, pu, cu, u), span(kv, pv, cv, v)
    nu, nv = basis(ku, pu, iu, u), basis(kv, pv, iv, v)
    num, den = [0.0] * len(ctrl[0][0]), 0.0
    for a in range(pu + 1):
        for b in range(pv + 1):
            i, j = iu - pu + a, iv - pv + b
            f = nu[a] * nv[b] * (w[i][j] if w else 1.0)
            num = [x + f * c for x, c in zip(num, ctrl[i][j])]
            den += f
    return [x / den for x in num]


KU = [0, 0, 0, 0, 0.5, 1.5, 1.5, 3, 3, 3, 3]        # cubic, 7 points, a double knot: 3 spans
KV = [-1, -1, -1, 0, 2, 2, 2]                        # quadratic, 4 points: 2 spans
CTRL = [[[((i * 4 + j) * 37 % 17) - 8.0, float(i), float(j * j)] for j in range(4)]
        for i in range(7)]
W = [[0.5 + ((i * 4 + j) % 4) * 0.5 for j in range(4)] for i in range(7)]


@requires("bs_surface_add_bspline", "bs_bspline_locate", "bs_bspline_span_count")
class BSplineTest(PlainTestCase):
    def test_patches_match_the_bspline(self):
        b = bezsurf.BSpline(CTRL, KU, KV, W)
        self.assertEqual((b.degree, b.count, b.dim, b.rational), ((3, 2), (7, 4), 3, True))
        self.assertEqual(b.span_count(), (3, 2))
        s = bezsurf.Surface()
        spans = plain(s.add_bspline(b))
        self.assertEqual(len(s), 6)
        self.assertEqual(spans[0], (0.0, 0.5, -1.0, 0.0))
        self.assertEqual(spans[5], (1.5, 3.0, 0.0, 2.0))
        for k in range(41):
            u, v = 3.0 * k / 40, -1.0 + 3.0 * ((k * 7) % 41) / 40
            index, lu, lv = b.locate(u, v)
            got = plain(s.eval(index, lu, lv))
            want = point(CTRL, W, KU, KV, 3, 2, u, v)
            for g, x in zip(got, want):
                self.assertLess(abs(g - x), 1e-12, (u, v, got, want))

    def test_from_bspline_and_numpy_inputs(self):
        s = bezsurf.Surface.from_bspline(CTRL, KU, KV)
        self.assertEqual((len(s), s.dim, s[0].rational), (6, 3, False))
        if np is not None:
            s2 = bezsurf.Surface.from_bspline(np.array(CTRL), np.array(KU, dtype=float),
                                              np.array(KV, dtype=float))
            self.assertEqual([p.ctrl for p in s2], [p.ctrl for p in s])
            spans = bezsurf.Surface().add_bspline(bezsurf.BSpline(CTRL, KU, KV))
            self.assertEqual((type(spans), spans.shape), (np.ndarray, (6, 4)))

    def test_locate(self):
        b = bezsurf.BSpline(CTRL, KU, KV)
        self.assertEqual(b.locate(0.5, 0.0), (1 * 2 + 1, 0.0, 0.0))   # knots: the later span
        self.assertEqual(b.locate(3.0, 2.0), (2 * 2 + 1, 1.0, 1.0))   # the domain's end
        for bad in ((3.5, 0.0), (0.0, -1.5), (math.nan, 0.0)):
            with self.assertRaises(bezsurf.DomainError):
                b.locate(*bad)
        with self.assertRaises(TypeError):
            b.locate("0", 0.0)

    def test_errors(self):
        with self.assertRaisesRegex(ValueError, "knots_u"):
            bezsurf.BSpline(CTRL, KU[:7], KV)               # degree 0 implied
        with self.assertRaisesRegex(ValueError, "weights"):
            bezsurf.BSpline(CTRL, KU, KV, [[1.0] * 4] * 6)
        with self.assertRaisesRegex(TypeError, r"ctrl\[0\]\[1\]\[2\]"):
            bezsurf.BSpline([[[0, 0, 0], [0, 0, "x"]]] * 2, [0, 0, 1, 1], [0, 0, 1, 1])
        s = bezsurf.Surface.from_bspline(CTRL, KU, KV)
        bad_knots = list(KU)
        bad_knots[5] = 0.1                                     # decreasing
        with self.assertRaises(bezsurf.DomainError):
            s.add_bspline(bezsurf.BSpline(CTRL, bad_knots, KV))
        zero_w = [row[:] for row in W]
        zero_w[2][1] = 0.0
        with self.assertRaises(bezsurf.NonFiniteError):
            s.add_bspline(bezsurf.BSpline(CTRL, KU, KV, zero_w))
        flat = [[[x, y] for x, y, z in row] for row in CTRL]
        with self.assertRaises(bezsurf.IncompatibleError):
            s.add_bspline(bezsurf.BSpline(flat, KU, KV))
        self.assertEqual(len(s), 6)                            # unchanged by every failure
        with self.assertRaises(TypeError):
            s.add_bspline(CTRL)

    def test_pickle_and_repr(self):
        b = bezsurf.BSpline(CTRL, KU, KV, W)
        b2 = pickle.loads(pickle.dumps(b))
        self.assertEqual((b2.degree, b2.count, b2.span_count()), (b.degree, b.count, b.span_count()))
        self.assertIn("NURBS", repr(b2))


if __name__ == "__main__":
    unittest.main()
