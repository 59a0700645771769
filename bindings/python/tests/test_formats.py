"""OBJ free-form and IGES surfaces: round trips, errors with their position, the IGES fixtures."""

import os
import tempfile

import bezsurf

from .support import PlainTestCase, SOURCE_DIR, requires

IGES_DIR = SOURCE_DIR / "tests" / "io" / "data" / "iges"

TWO_SEGMENTS = """v 0 0 0
v 1 0 0
v 2 0 0
v 0 1 0 2
v 1 1 1
v 2 1 0
cstype rat bezier
deg 1 1
surf 0 2 0 1 -6 -5 -4 \\
  -3 -2 -1
parm u 0 1 2
parm v 0 1
end
"""


@requires("bs_surface_read_obj", "bs_surface_read_obj_file", "bs_surface_write_obj",
          "bs_surface_write_obj_file")
class ObjTest(PlainTestCase):
    def test_segments_and_round_trip(self):
        s = bezsurf.Surface.read_obj(TWO_SEGMENTS)
        self.assertEqual(len(s), 2)
        self.assertEqual(s[0].ctrl, [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]])
        self.assertEqual(s[0].weights, [[1.0, 2.0], [1.0, 1.0]])
        text = s.to_obj()
        self.assertIn("cstype rat bezier", text)
        back = bezsurf.Surface.read_obj(text.encode("ascii"))
        self.assertEqual(back.to_obj(), text)
        self.assertEqual([p.ctrl for p in back], [p.ctrl for p in s])

    def test_teapot_file_round_trip(self):
        teapot = bezsurf.Surface.builtin("teapot")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "teapot.obj")
            teapot.save_obj(path)
            back = bezsurf.Surface.load_obj(path)
        self.assertEqual(back.to_bpt(), teapot.to_bpt())

    def test_errors(self):
        with self.assertRaises(bezsurf.ParseError) as cm:
            bezsurf.Surface.read_obj("v 0 0 0\nv 1 x 0\n")
        self.assertEqual((cm.exception.line, cm.exception.column), (2, 5))
        with self.assertRaises(bezsurf.UnsupportedError) as cm:
            bezsurf.Surface.read_obj("v 0 0 0\ncstype taylor\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n")
        self.assertIn("line 4", str(cm.exception))
        with self.assertRaises(FileNotFoundError):
            bezsurf.Surface.load_obj("/nonexistent-directory/x.obj")
        with self.assertRaises(TypeError):
            bezsurf.Surface.read_obj(3)


@requires("bs_surface_read_iges", "bs_surface_read_iges_file")
class IgesTest(PlainTestCase):
    def test_fixtures(self):
        cyl = bezsurf.Surface.load_iges(IGES_DIR / "nurbs_cylinder.igs")
        self.assertEqual(len(cyl), 1)
        for u in (0.0, 0.3, 0.5, 1.0):
            x, y, _ = cyl[0].eval(u, 0.5)
            self.assertAlmostEqual((x * x + y * y) ** 0.5, 2.0, places=8)
        text = (IGES_DIR / "bicubic_knots.igs").read_text()
        self.assertEqual(len(bezsurf.Surface.read_iges(text)), 12)

    def test_errors(self):
        with self.assertRaises(bezsurf.ParseError) as cm:
            bezsurf.Surface.read_iges("too short\n")
        self.assertEqual((cm.exception.line, cm.exception.column), (1, 10))
        with self.assertRaises(FileNotFoundError):
            bezsurf.Surface.load_iges("/nonexistent-directory/x.igs")
