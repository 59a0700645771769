"""Float outputs through the binding: every float is the double result rounded to float."""

import array
import unittest

import bezsurf

from .support import NET, PlainTestCase, numpy as np, plain, requires


def rounded(rows):
    """Each value of a list of tuples (or an array) rounded to float through array('f')."""
    return [tuple(array.array("f", [float(x) for x in row])) for row in plain(rows)]


@requires("bs_patch_eval_grid_f32", "bs_mesh_copy_positions_f32")
class Float32Test(PlainTestCase):
    def test_grid_equals_rounded_doubles(self):
        p = bezsurf.Patch(NET)
        u, v = [0.0, 0.1, 0.37, 1.0], [0.0, 0.5, 0.9]
        dbl = p.eval_grid(u, v, derivatives=True, normals=True)
        flt = p.eval_grid(u, v, derivatives=True, normals=True, float32=True)
        for name in ("position", "du", "dv", "normal"):
            self.assertEqual(rounded(getattr(flt, name)), rounded(getattr(dbl, name)), name)
        self.assertEqual(plain(flt.kind), plain(dbl.kind))
        if np is not None:
            self.assertEqual(flt.position.dtype, np.float32)
            out = np.zeros((12, 3), dtype=np.float32)
            p.eval_grid(u, v, out=out, float32=True)
            self.assertTrue(np.array_equal(out, dbl.position.astype(np.float32)))
            with self.assertRaises(TypeError):
                p.eval_grid(u, v, out=np.zeros((12, 3)), float32=True)

    def test_mesh_read_back(self):
        m = bezsurf.Surface.builtin("teacup").tessellate(3)
        for name in ("positions", "normals", "uv"):
            dbl = getattr(m, name)()
            flt = getattr(m, name)(float32=True)
            self.assertEqual(rounded(flt), rounded(dbl), name)


if __name__ == "__main__":
    unittest.main()
