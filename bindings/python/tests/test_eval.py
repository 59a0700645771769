"""Evaluation against exact values: the acceptance point, the hyperbolic paraboloid
S(u,v) = (u, v, uv) (all values dyadic, so exact), a rational circle, degenerate normals."""

import array
import math
import unittest

import bezsurf

from .support import PlainTestCase, plain, NET, bilinear, needs_numpy, numpy as np, requires

PARAMS = [(0.0, 0.0), (1.0, 0.0), (0.25, 0.75), (0.5, 0.5), (1.0, 1.0), (-0.5, 2.0)]
U = [p[0] for p in PARAMS]
V = [p[1] for p in PARAMS]


def saddle(u, v):
    return (u, v, u * v)


def saddle_normal(u, v):
    n = math.sqrt(1 + u * u + v * v)
    return (-v / n, -u / n, 1 / n)


@requires("bs_patch_eval")
class AcceptanceTest(PlainTestCase):
    def test_acceptance_point_exact(self):
        p = bezsurf.Patch([[[1, 0, 2], [1, 2, 4], [1, 3, 2]], [[2, 1, 0], [2, 2, 2], [2, 4, 0]],
                           [[4, 1, 0], [3, 3, 2], [4, 4, 2]]])
        self.assertEqual(p.eval([0.5], [0.5]), [(17 / 8, 9 / 4, 13 / 8)])

    def test_corners_interpolate_net(self):
        p = bezsurf.Patch(NET)
        got = p.eval([0, 1, 0, 1], [0, 0, 1, 1])
        self.assertEqual(got, [tuple(map(float, NET[i][j])) for i, j in
                               ((0, 0), (2, 0), (0, 2), (2, 2))])


@requires("bs_patch_eval", "bs_patch_eval_deriv", "bs_patch_eval_normal")
class ListEvalTest(PlainTestCase):
    def test_positions(self):
        self.assertEqual(bilinear().eval(U, V), [saddle(u, v) for u, v in PARAMS])

    def test_input_kinds(self):
        p = bilinear()
        want = [saddle(u, v) for u, v in PARAMS]
        self.assertEqual(p.eval(tuple(U), tuple(V)), want)
        self.assertEqual(p.eval(array.array("d", U), array.array("d", V)), want)
        self.assertEqual(p.eval(memoryview(array.array("d", U)), memoryview(array.array("d", V))),
                         want)
        # a strided memoryview, and a read-only one
        big = array.array("d", [x for u in U for x in (u, 99.0)])
        ro = memoryview(bytes(array.array("d", V))).cast("d")
        self.assertEqual(p.eval(memoryview(big)[::2], ro), want)
        self.assertEqual(p.eval([0, 1], [1, 0]), [(0.0, 1.0, 0.0), (1.0, 0.0, 0.0)])  # ints

    def test_scalar_parameters(self):
        p = bilinear()
        self.assertEqual(p.eval(0.5, 0.25), (0.5, 0.25, 0.125))
        r = p.eval(0.5, 0.25, derivatives=True, normals=True)
        self.assertEqual(r.du, (1.0, 0.0, 0.25))
        self.assertEqual(r.kind, bezsurf.NORMAL_REGULAR)

    def test_derivatives_and_normals(self):
        p = bilinear()
        r = p.eval(U, V, derivatives=True, normals=True)
        self.assertIsInstance(r, bezsurf.Evaluation)
        self.assertEqual(r.position, [saddle(u, v) for u, v in PARAMS])
        self.assertEqual(r.du, [(1.0, 0.0, v) for u, v in PARAMS])
        self.assertEqual(r.dv, [(0.0, 1.0, u) for u, v in PARAMS])
        for got, (u, v) in zip(r.normal, PARAMS):
            for a, b in zip(got, saddle_normal(u, v)):
                self.assertAlmostEqual(a, b, delta=1e-15)
        self.assertEqual(r.kind, [bezsurf.NORMAL_REGULAR] * len(PARAMS))
        only_d = p.eval(U, V, derivatives=True)
        self.assertIsNone(only_d.normal)
        self.assertEqual(only_d.du, r.du)

    def test_eval_normal(self):
        r = bilinear().eval_normal([0.5], [0.0])
        self.assertEqual(r.position, [(0.5, 0.0, 0.0)])
        n = 1 / math.sqrt(1.25)
        for a, b in zip(r.normal[0], (0.0, -0.5 * n, n)):
            self.assertAlmostEqual(a, b, delta=1e-15)
        self.assertIsNone(r.du)

    def test_eval_deriv(self):
        p = bilinear()
        self.assertEqual(p.eval_deriv(1, 1, U, V), [(0.0, 0.0, 1.0)] * len(U))
        self.assertEqual(p.eval_deriv(2, 0, U, V), [(0.0, 0.0, 0.0)] * len(U))
        self.assertEqual(p.eval_deriv(0, 0, U, V), p.eval(U, V))
        q = bezsurf.Patch(NET)   # x along u: rows 1, 2, (4,3,4): d2x/du2 at v = 0 is 2*(4-2*2+1)
        self.assertEqual(p.eval_deriv(0, 1, [0.5], [0.5]), [(0.0, 1.0, 0.5)])
        self.assertEqual(q.eval_deriv(2, 0, [0.3], [0.0])[0][0], 2.0)

    def test_limit_and_undefined_normals(self):
        # S(u,v) = (u, uv, 0): the row u = 0 collapses to a point; S_v = 0 there.
        fan = bezsurf.Patch([[[0, 0, 0], [0, 0, 0]], [[1, 0, 0], [1, 1, 0]]])
        r = fan.eval_normal([0.0, 0.5], [0.5, 0.5])
        self.assertEqual(r.kind, [bezsurf.NORMAL_LIMIT, bezsurf.NORMAL_REGULAR])
        self.assertEqual(r.normal, [(0.0, 0.0, 1.0), (0.0, 0.0, 1.0)])
        line = bezsurf.Patch([[[0, 0, 0], [1, 0, 0]], [[2, 0, 0], [3, 0, 0]]])
        r = line.eval_normal([0.5], [0.5])
        self.assertEqual((r.normal, r.kind), ([(0.0, 0.0, 0.0)], [bezsurf.NORMAL_UNDEFINED]))

    def test_nonfinite_parameter_affects_its_point_only(self):
        got = bilinear().eval([math.nan, 0.5], [0.5, 0.5])
        self.assertTrue(all(math.isnan(x) for x in got[0]))
        self.assertEqual(got[1], (0.5, 0.5, 0.25))

    def test_rational_quarter_circle(self):
        h = math.sqrt(0.5)
        arc = bezsurf.Patch([[[1, 0]], [[1, 1]], [[0, 1]]], [[1], [h], [1]])
        ts = [k / 16 for k in range(17)]
        for x, y in arc.eval(ts, [0.0] * len(ts)):
            self.assertAlmostEqual(math.hypot(x, y), 1.0, delta=4e-16)
        self.assertEqual(arc.eval([0.5], [0.0])[0][0], arc.eval([0.5], [0.0])[0][1])

    def test_errors(self):
        p = bilinear()
        with self.assertRaises(ValueError):
            p.eval([0.5, 0.5], [0.5])
        with self.assertRaises(bezsurf.DegreeError):
            p.eval_deriv(bezsurf.MAX_DEGREE + 1, 0, [0.5], [0.5])
        flat = bezsurf.Patch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
        with self.assertRaises(bezsurf.DimensionError):
            flat.eval_normal([0.5], [0.5])
        with self.assertRaises(bezsurf.DimensionError):
            flat.eval([0.5], [0.5], normals=True)
        with self.assertRaises(TypeError):
            p.eval(["a"], [0.5])
        with self.assertRaises(TypeError):     # out= needs numpy or is rejected
            p.eval([0.5], [0.5], out=[[0, 0, 0]])
        self.assertEqual(p.eval([], []), [])


@requires("bs_patch_eval_grid")
class GridTest(PlainTestCase):
    def test_grid_order_and_values(self):
        us, vs = [0.0, 0.5, 1.0], [0.25, 0.75]
        got = bilinear().eval_grid(us, vs, derivatives=True, normals=True)
        pairs = [(u, v) for u in us for v in vs]
        self.assertEqual(got.position, [saddle(u, v) for u, v in pairs])
        self.assertEqual(got.du, [(1.0, 0.0, v) for u, v in pairs])
        self.assertEqual(got.dv, [(0.0, 1.0, u) for u, v in pairs])
        self.assertEqual(got.kind, [bezsurf.NORMAL_REGULAR] * 6)
        for n, (u, v) in zip(got.normal, pairs):
            for a, b in zip(n, saddle_normal(u, v)):
                self.assertAlmostEqual(a, b, delta=1e-15)
        self.assertEqual(bilinear().eval_grid(us, vs), got.position)
        self.assertEqual(bilinear().eval_grid(us, []), [])


@needs_numpy
@requires("bs_patch_eval", "bs_patch_eval_grid", "bs_patch_eval_normal", "bs_patch_eval_deriv")
class NumpyEvalTest(PlainTestCase):
    def setUp(self):
        self.p = bilinear()
        self.u = np.array(U)
        self.v = np.array(V)
        self.want = np.array([saddle(u, v) for u, v in PARAMS])

    def test_numpy_result_is_written_in_place(self):
        got = self.p.eval(self.u, self.v)
        self.assertIsInstance(got, np.ndarray)
        self.assertEqual(got.shape, (len(U), 3))
        self.assertTrue(got.flags.owndata)      # the array the library wrote, not a copy of it
        self.assertTrue(np.array_equal(got, self.want))

    def test_out_is_written_zero_copy_through_strides(self):
        # Fortran order, negative row stride, and a column stride skipping sentinels.
        buf = np.full((2 * len(U), 7), -7.0)
        out = buf[::-2, ::3]
        self.assertEqual(out.shape, (len(U), 3))
        res = self.p.eval(self.u, self.v, out=out)
        self.assertIs(res, out)
        self.assertEqual(res.ctypes.data, out.ctypes.data)
        self.assertTrue(np.array_equal(buf[::-2, ::3], self.want))
        mask = np.ones(buf.shape, bool)
        mask[::-2, ::3] = False
        self.assertTrue(np.all(buf[mask] == -7.0))     # nothing written outside the view
        f = np.zeros((len(U), 3), order="F")
        self.assertIs(self.p.eval(self.u, self.v, out=f), f)
        self.assertTrue(np.array_equal(f, self.want))

    def test_numpy_inputs_pass_by_address(self):
        from bezsurf import _buffers
        a = np.arange(12.0)[::-3]
        d = _buffers.doubles(a, "u")
        self.assertEqual((d.address, d.count, d.stride), (a.ctypes.data, 4, -24))
        f = np.asfortranarray(np.ones((3, 4)))[1]
        d = _buffers.doubles(f, "u")
        self.assertEqual((d.address, d.stride), (f.ctypes.data, 24))

    def test_strided_and_converted_inputs(self):
        big = np.zeros(3 * len(U))
        big[::3] = U
        rev = np.array(V[::-1])[::-1]                   # negative stride
        self.assertLess(rev.strides[0], 0)
        self.assertTrue(np.array_equal(self.p.eval(big[::3], rev), self.want))
        f32 = self.p.eval(np.array(U, dtype=np.float32), np.array(V, dtype=np.float32))
        self.assertTrue(np.array_equal(f32, self.want))  # all parameters exact in float32
        mixed = self.p.eval(U, self.v)                   # one numpy input gives numpy results
        self.assertIsInstance(mixed, np.ndarray)
        bc = self.p.eval(np.broadcast_to(0.5, (4,)), np.array([0.0, 0.25, 0.5, 1.0]))
        self.assertTrue(np.array_equal(bc[:, 0], [0.5] * 4))

    def test_all_outputs(self):
        r = self.p.eval(self.u, self.v, derivatives=True, normals=True)
        self.assertTrue(np.array_equal(r.du[:, 2], self.v))
        self.assertTrue(np.array_equal(r.dv[:, 2], self.u))
        self.assertEqual(r.kind.dtype, np.uint8)
        n = np.stack([-self.v, -self.u, np.ones_like(self.u)], axis=1)
        n /= np.linalg.norm(n, axis=1)[:, None]
        self.assertTrue(np.allclose(r.normal, n, rtol=0, atol=1e-15))
        kind = np.full(len(U), 9, dtype=np.uint8)
        nrm = np.zeros((len(U), 3))
        e = self.p.eval_normal(self.u, self.v, normal_out=nrm, kind_out=kind)
        self.assertIs(e.normal, nrm)
        self.assertIs(e.kind, kind)
        self.assertTrue(np.all(kind == bezsurf.NORMAL_REGULAR))
        d = self.p.eval_deriv(1, 1, self.u, self.v)
        self.assertTrue(np.array_equal(d, np.tile([0.0, 0.0, 1.0], (len(U), 1))))

    def test_grid(self):
        us, vs = np.linspace(0, 1, 5), np.linspace(0, 1, 3)
        g = self.p.eval_grid(us, vs)
        uu, vv = np.meshgrid(us, vs, indexing="ij")
        want = np.stack([uu, vv, uu * vv], axis=-1)
        self.assertTrue(np.array_equal(g.reshape(5, 3, 3), want))
        out = np.empty((15, 3))
        self.assertIs(self.p.eval_grid(us, vs, out=out), out)

    def test_out_errors(self):
        with self.assertRaises(ValueError):
            self.p.eval(self.u, self.v, out=np.zeros((len(U), 2)))
        with self.assertRaises(TypeError):
            self.p.eval(self.u, self.v, out=np.zeros((len(U), 3), dtype=np.float32))
        with self.assertRaises(ValueError):     # an output for a result not asked for
            self.p.eval(self.u, self.v, normal_out=np.zeros((len(U), 3)))
        with self.assertRaises(ValueError):
            self.p.eval_grid(self.u, self.v, du_out=np.zeros((len(U) ** 2, 3)))
        flat = bezsurf.Patch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
        out = np.full((len(U), 2), -1.0)
        with self.assertRaises(bezsurf.DimensionError):
            flat.eval(self.u, self.v, derivatives=True, normals=True, out=out)
        self.assertTrue(np.all(out == -1.0))    # nothing written on failure
        ro = np.zeros((len(U), 3))
        ro.flags.writeable = False
        with self.assertRaises(ValueError):
            self.p.eval(self.u, self.v, out=ro)
        with self.assertRaises(ValueError):
            self.p.eval(np.zeros((2, 2)), np.zeros((2, 2)))


if __name__ == "__main__":
    unittest.main()
