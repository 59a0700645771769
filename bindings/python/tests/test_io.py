"""The .bpt format and the built-in tea set, checked against the data files' own text."""

import os
import tempfile
import unittest

import bezsurf

from .support import PlainTestCase, plain, DATA_DIR, requires

SADDLE_BPT = "1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n"


def first_patch_from_text(path):
    """Control points of the first patch of a .bpt file, read with str.split."""
    words = open(path).read().split()
    du, dv = int(words[1]), int(words[2])
    nums = [float(w) for w in words[3:3 + 3 * (du + 1) * (dv + 1)]]
    pts = [tuple(nums[3 * k:3 * k + 3]) for k in range((du + 1) * (dv + 1))]
    return int(words[0]), [pts[i * (dv + 1):(i + 1) * (dv + 1)] for i in range(du + 1)]


@requires("bs_surface_read_bpt", "bs_surface_read_bpt_file", "bs_surface_write_bpt",
          "bs_surface_write_bpt_file", "bs_surface_create_builtin", "bs_builtin_name")
class BptTest(PlainTestCase):
    def test_builtin_names_and_teapot(self):
        self.assertEqual(bezsurf.builtin_names()[:3], ["teapot", "teacup", "teaspoon"])
        with bezsurf.Surface.builtin("teapot") as s:
            self.assertEqual((len(s), s.dim), (32, 3))
            self.assertTrue(all(p.degree == (3, 3) for p in s))
            count, first = first_patch_from_text(DATA_DIR / "teapot.bpt")
            self.assertEqual(count, 32)
            self.assertEqual(s[0].ctrl, first)
        with self.assertRaises(bezsurf.InvalidArgumentError):
            bezsurf.Surface.builtin("teakettle")

    def test_files_match_builtins(self):
        for name, count in (("teapot", 32), ("teacup", 26), ("teaspoon", 16)):
            loaded = bezsurf.Surface.load(DATA_DIR / f"{name}.bpt")
            built = bezsurf.Surface.builtin(name)
            self.assertEqual(len(loaded), count)
            self.assertEqual([p.ctrl for p in loaded], [p.ctrl for p in built])

    def test_text_round_trip_bit_for_bit(self):
        s = bezsurf.Surface.builtin("teacup")
        again = bezsurf.Surface.from_bpt(s.to_bpt())
        self.assertEqual([p.ctrl for p in again], [p.ctrl for p in s])
        odd = bezsurf.Surface([bezsurf.Patch([[[0.1, 1 / 3, 2 ** -1074]]], [[0.7]])])
        back = bezsurf.Surface.from_bpt(odd.to_bpt().encode())
        self.assertEqual((back[0].ctrl, back[0].weights), (odd[0].ctrl, odd[0].weights))

    def test_file_round_trip(self):
        s = bezsurf.Surface.from_bpt(SADDLE_BPT)
        self.assertEqual(s[0].ctrl, [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)],
                                     [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]])
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "saddle.bpt")
            s.save(path)
            self.assertEqual(bezsurf.Surface.load(path)[0].ctrl, s[0].ctrl)

    def test_load_and_save_by_extension(self):
        # as the tool: .obj and .igs/.iges by their readers, any other name .bpt; format= wins
        pot = bezsurf.Surface.builtin("teapot")
        iges = DATA_DIR.parent / "tests" / "io" / "data" / "iges" / "nurbs_cylinder.igs"
        self.assertEqual(len(bezsurf.Surface.load(iges)), len(bezsurf.Surface.load_iges(iges)))
        with tempfile.TemporaryDirectory() as d:
            for name, text in (("p.obj", pot.to_obj()), ("p.OBJ", pot.to_obj()),
                               ("p.bpt", pot.to_bpt()), ("p.txt", pot.to_bpt())):
                path = os.path.join(d, name)
                pot.save(path)
                with open(path) as f:
                    self.assertEqual(f.read(), text, name)
                self.assertEqual(bezsurf.Surface.load(path).to_bpt(), pot.to_bpt(), name)
            path = os.path.join(d, "p.dat")
            pot.save(path, format="obj")
            with open(path) as f:
                self.assertEqual(f.read(), pot.to_obj())
            self.assertEqual(bezsurf.Surface.load(path, format="obj").to_bpt(), pot.to_bpt())
            with self.assertRaises(bezsurf.ParseError):
                bezsurf.Surface.load(path)  # .dat: read as .bpt
            with self.assertRaisesRegex(ValueError, "IGES is read, not written"):
                pot.save(os.path.join(d, "p.igs"))
            with self.assertRaisesRegex(ValueError, "format must be one of"):
                bezsurf.Surface.load(path, format="step")

    def test_parse_error_location(self):
        with self.assertRaises(bezsurf.ParseError) as cm:
            bezsurf.Surface.from_bpt("1\n1 1\n0 0 0\n0 x 0\n1 0 0\n1 1 1\n")
        e = cm.exception
        self.assertEqual((e.line, e.column), (4, 3))
        self.assertEqual(e.code, -8)
        self.assertTrue(e.detail)
        self.assertIn("line 4, column 3", str(e))
        self.assertIsInstance(e, ValueError)

    def test_io_errors(self):
        with self.assertRaises(bezsurf.BezsurfIOError) as cm:
            bezsurf.Surface.load("/nonexistent/dir/x.bpt")
        self.assertIsInstance(cm.exception, OSError)
        with self.assertRaises(bezsurf.BezsurfIOError):
            bezsurf.Surface.from_bpt(SADDLE_BPT).save("/nonexistent/dir/x.bpt")
        with self.assertRaises(bezsurf.DimensionError):
            bezsurf.Surface([bezsurf.Patch([[[0, 0]]])]).to_bpt()


if __name__ == "__main__":
    unittest.main()
