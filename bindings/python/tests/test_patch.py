"""Patch creation, accessors, control-net round trips, copies and lifetime."""

import array
import copy
import gc
import math
import pickle
import unittest

import bezsurf

from .support import PlainTestCase, plain, NET, HAVE_NUMPY, needs_numpy, numpy as np


class CreateTest(PlainTestCase):
    def test_accessors(self):
        with bezsurf.Patch([[[0, 0], [1, 0], [2, 1], [3, 0]], [[0, 1], [1, 1], [2, 2], [3, 3]]]) as p:
            self.assertEqual((p.degree_u, p.degree_v, p.dim), (1, 3, 2))
            self.assertEqual(p.degree, (1, 3))
            self.assertEqual(p.shape, (2, 4, 2))
            self.assertFalse(p.rational)
            self.assertIsNone(p.weights)

    def test_ctrl_round_trip_exact(self):
        p = bezsurf.Patch(NET)
        self.assertEqual(p.ctrl, [[tuple(float(c) for c in pt) for pt in row] for row in NET])

    def test_rational_weights(self):
        w = [[1, 0.5, 2], [3, 1, 0.25], [1, 1, 1]]
        p = bezsurf.Patch(NET, w)
        self.assertTrue(p.rational)
        self.assertEqual(p.weights, [[float(x) for x in row] for row in w])
        self.assertEqual(p.ctrl[1][2], (2.0, 4.0, 0.0))  # Cartesian, not pre-multiplied

    def test_degree_zero_and_tuples_and_arrays(self):
        p = bezsurf.Patch(((array.array("d", [1, 2]), (3.5, 4)),))
        self.assertEqual((p.degree_u, p.degree_v, p.dim), (0, 1, 2))
        self.assertEqual(p.ctrl, [[(1.0, 2.0), (3.5, 4.0)]])

    def test_memoryview_net(self):
        mv = memoryview(array.array("d", range(12))).cast("B").cast("d", (2, 2, 3))
        p = bezsurf.Patch(mv)
        self.assertEqual(p.ctrl[1][1], (9.0, 10.0, 11.0))

    def test_errors(self):
        with self.assertRaises(bezsurf.DimensionError):
            bezsurf.Patch([[[]]])
        with self.assertRaises(bezsurf.DimensionError):
            bezsurf.Patch([[[0.0] * 9]])
        with self.assertRaises(bezsurf.DegreeError):
            bezsurf.Patch([[[0.0]]] * 66)
        with self.assertRaises(bezsurf.NonFiniteError):
            bezsurf.Patch([[[math.nan, 0, 0]]])
        with self.assertRaises(bezsurf.NonFiniteError):
            bezsurf.Patch([[[0, 0, 0]]], [[-1.0]])
        with self.assertRaises(bezsurf.NonFiniteError):
            bezsurf.Patch([[[0, 0, 0]]], [[math.inf]])
        with self.assertRaises(ValueError):      # ragged rows
            bezsurf.Patch([[[0, 0]], [[0, 0], [1, 1]]])
        with self.assertRaises(ValueError):      # points of different dimension
            bezsurf.Patch([[[0, 0], [1, 1, 1]]])
        with self.assertRaises(ValueError):      # weights of the wrong shape
            bezsurf.Patch(NET, [[1, 1, 1]])
        with self.assertRaises(ValueError):
            bezsurf.Patch([])
        with self.assertRaises(TypeError):
            bezsurf.Patch([[["a", 0]]])

    def test_max_degree_accepted(self):
        p = bezsurf.Patch([[[float(i)]] for i in range(bezsurf.MAX_DEGREE + 1)])
        self.assertEqual(p.degree_u, bezsurf.MAX_DEGREE)


class CopyAndLifetimeTest(PlainTestCase):
    def test_clone_is_independent(self):
        p = bezsurf.Patch(NET, [[1, 2, 1]] * 3)
        q = p.clone()
        p.close()
        self.assertTrue(p.closed)
        self.assertEqual(q.weights, [[1.0, 2.0, 1.0]] * 3)
        self.assertEqual(copy.copy(q).ctrl, q.ctrl)
        self.assertEqual(copy.deepcopy(q).ctrl, q.ctrl)

    def test_handles_are_destroyed_exactly_once(self):
        destroyed = []
        real = bezsurf.Patch._destroy

        def counting(handle):
            destroyed.append(handle)
            real(handle)

        bezsurf.Patch._destroy = counting
        try:
            p = bezsurf.Patch(NET)
            h = p._handle
            p.close()
            p.close()
            self.assertEqual(destroyed, [h])
            with bezsurf.Patch(NET) as q:
                h = q._handle
            self.assertEqual(destroyed[-1], h)
            r = bezsurf.Patch(NET)
            h = r._handle
            del r                                   # released when the last reference goes
            self.assertEqual(destroyed[-1], h)
            s = bezsurf.Surface([bezsurf.Patch(NET)])
            n = len(destroyed)                      # the temporary patch above is gone by now
            borrowed = s[0]
            borrowed.close()
            del borrowed
            self.assertEqual(len(destroyed), n)     # a borrowed patch never frees its handle
            s.close()
        finally:
            bezsurf.Patch._destroy = real

    def test_pickle(self):
        p = bezsurf.Patch(NET, [[1, 2, 1]] * 3)
        q = pickle.loads(pickle.dumps(p))
        self.assertEqual((q.ctrl, q.weights), (p.ctrl, p.weights))

    def test_closed_patch_raises(self):
        with bezsurf.Patch(NET) as p:
            pass
        self.assertTrue(p.closed)
        with self.assertRaises(ValueError):
            p.dim
        p.close()  # closing twice is harmless
        self.assertIn("closed", repr(p))

    def test_patch_borrowed_from_surface_keeps_it_alive(self):
        s = bezsurf.Surface([bezsurf.Patch(NET)])
        borrowed = s[0]
        del s
        gc.collect()
        self.assertEqual(borrowed.ctrl[2][2], (4.0, 4.0, 2.0))
        self.assertIsNotNone(borrowed._parent)

    def test_borrowed_patch_unusable_after_surface_close(self):
        s = bezsurf.Surface([bezsurf.Patch(NET)])
        borrowed = s[0]
        s.close()
        self.assertTrue(borrowed.closed)
        with self.assertRaises(ValueError):
            borrowed.degree_u
        borrowed.close()  # never frees what it does not own


@needs_numpy
class NumpyCtrlTest(PlainTestCase):
    def test_numpy_net_any_layout_and_dtype(self):
        a = np.array(NET, dtype=np.int32)
        p = bezsurf.Patch(np.asfortranarray(a)[:, ::-1, :])
        self.assertEqual(p.ctrl[0][0], (1.0, 3.0, 2.0))
        out = np.zeros((3, 3, 3))
        got = p.ctrl_array(out=out)
        self.assertIs(got, out)
        self.assertTrue(np.array_equal(out, a[:, ::-1, :]))
        self.assertTrue(np.array_equal(p.weights_array(), np.ones((3, 3))))

    def test_numpy_weights(self):
        w = np.array([[1, 2, 3], [4, 5, 6], [7, 8, 9]], dtype=np.float32)
        p = bezsurf.Patch(np.array(NET, dtype=float), w)
        self.assertTrue(np.array_equal(p.weights_array(), w))

    def test_ctrl_array_rejects_bad_out(self):
        p = bezsurf.Patch(NET)
        with self.assertRaises(ValueError):
            p.ctrl_array(out=np.zeros((3, 3, 3), order="F"))
        with self.assertRaises(ValueError):
            p.ctrl_array(out=np.zeros((3, 3, 2)))


class SurfaceTest(PlainTestCase):
    def test_add_count_get(self):
        with bezsurf.Surface() as s:
            self.assertEqual((len(s), s.dim), (0, 0))
            self.assertEqual(s.add(bezsurf.Patch(NET)), 0)
            self.assertEqual(s.add(bezsurf.Patch([[[0, 0, 0]]])), 1)
            self.assertEqual((len(s), s.dim), (2, 3))
            self.assertEqual(s[-1].ctrl, [[(0.0, 0.0, 0.0)]])
            self.assertEqual([p.degree_u for p in s], [2, 0])
            with self.assertRaises(IndexError):
                s[2]
            with self.assertRaises(bezsurf.IncompatibleError):
                s.add(bezsurf.Patch([[[0, 0]]]))
            c = s.clone()
        self.assertTrue(s.closed)
        self.assertEqual(len(c), 2)
        self.assertEqual(c[0].ctrl, bezsurf.Patch(NET).ctrl)


if __name__ == "__main__":
    unittest.main()
