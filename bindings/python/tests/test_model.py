"""Models through the binding: the model of a surface (faces, edges, shells), face evaluation
against the surface's own evaluation, the CAD parts of data/cad/ read from STEP and IGES with
the face counts their .ref files give, pickling, and the argument rules."""

import copy
import math
import pickle
import unittest

import bezsurf

from .support import DATA_DIR, PlainTestCase, plain, requires

CAD_DIR = DATA_DIR / "cad"
PARTS = ("bottle", "block", "sphere", "torus", "cone", "wedge", "bell", "duct")


def ref_faces(part):
    for line in (CAD_DIR / f"{part}.ref").read_text().splitlines():
        if line.startswith("faces "):
            return int(line.split()[1])
    raise AssertionError(f"{part}.ref has no face count")


def ref_values(part):
    """The kernel's area and volume of a part (its .ref file)."""
    out = {}
    for line in (CAD_DIR / f"{part}.ref").read_text().splitlines():
        key, _, value = line.partition(" ")
        if key in ("area", "volume"):
            out[key] = float(value)
    return out


def reference_tolerance(part, name):
    """How closely a file's area and volume can match the kernel's: 1e-9, except where the file
    holds fewer digits (the 144 files write about 10 significant digits) and where the kernel's
    own value is off (docs/models.md: the duct's area and the bell's volume, ours stable to 1e-15
    from rel_tol 1e-8 to 1e-12 and the same from every file)."""
    rel = {"area": 1e-9, "volume": 1e-9}
    if name.endswith(".igs") and "brep" not in name:
        rel = {"area": 1e-7, "volume": 1e-7}
    if part == "duct":  # and its files' B-spline trims agree only to 3e-9 with each other
        rel = {"area": 1e-7, "volume": 1e-7}
    if part == "bell":
        rel["volume"] = 1e-7
    return rel


def cube():
    """A unit cube of six bilinear patches."""
    c = [[[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0]], [[0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]],
         [[0, 0, 0], [1, 0, 0], [0, 0, 1], [1, 0, 1]], [[0, 1, 0], [0, 1, 1], [1, 1, 0], [1, 1, 1]],
         [[0, 0, 0], [0, 0, 1], [0, 1, 0], [0, 1, 1]], [[1, 0, 0], [1, 1, 0], [1, 0, 1], [1, 1, 1]]]
    return bezsurf.Surface([bezsurf.Patch([f[0:2], f[2:4]]) for f in c])


@requires("bs_model_from_surface")
class ModelOfSurfaceTest(PlainTestCase):
    def test_cube_is_one_closed_shell(self):
        m = bezsurf.Model(cube())
        self.assertEqual(len(m), 6)
        self.assertEqual(m.edge_count, 12)
        self.assertEqual(m.shells, [True])
        f = m.face(5)
        self.assertEqual(f.kind, "bezier")
        self.assertEqual((f.first_patch, f.patch_count, f.loop_count), (5, 1, 1))
        self.assertEqual(f.box, (0.0, 1.0, 0.0, 1.0))
        self.assertEqual(m.face(-1), f)
        with self.assertRaises((IndexError, ValueError)):
            m.face(6)

    def test_face_eval_is_the_patch_evaluation(self):
        s = bezsurf.Surface.builtin("teapot")
        m = bezsurf.Model(s)
        faces, u, v = [0, 9, 20], [0.25, 0.5, 1.0], [0.75, 0.0, 0.5]
        ev = m.face_eval(faces, u, v)
        ref = s.eval(faces, u, v, normals=True)
        self.assertEqual(plain(ev.position), plain(ref.position))
        self.assertEqual(plain(ev.normal), plain(ref.normal))
        patch, st = m.face_to_patch(faces, u, v)
        self.assertEqual(list(plain(patch)), faces)
        self.assertEqual([tuple(x) for x in plain(st)], list(zip(u, v)))
        face, uv = m.patch_to_face(faces, u, v)  # each patch its own face on (0,1)^2
        self.assertEqual(list(plain(face)), faces)
        self.assertEqual([tuple(x) for x in plain(uv)], list(zip(u, v)))
        face, uv = m.patch_to_face(3, 1.5, 0.5)
        self.assertEqual(face, 4294967295)
        self.assertTrue(math.isnan(plain(uv)[0]))
        with self.assertRaises(IndexError):
            m.patch_to_face(32, 0.5, 0.5)
        one = m.face_eval(3, 0.5, 0.5)
        self.assertEqual(len(plain(one.position)), 3)
        self.assertEqual(len(m.surface), 32)

    def test_properties_of_the_cube(self):
        # the cube's patches face inwards (S_u x S_v into the cube): its volume is -1
        p = bezsurf.Model(cube()).properties()
        self.assertAlmostEqual(p.area, 6.0, delta=1e-12)
        self.assertAlmostEqual(p.volume, -1.0, delta=1e-12)
        for c in p.centroid:
            self.assertAlmostEqual(c, 0.5, delta=1e-12)
        open_model = bezsurf.Model(bezsurf.Surface.builtin("teapot"))
        self.assertTrue(math.isnan(open_model.properties(1e-6).volume))
        with self.assertRaises(ValueError):
            open_model.properties(0.5)

    def test_copy_and_pickle(self):
        m = bezsurf.Model(cube())
        for other in (copy.copy(m), copy.deepcopy(m), pickle.loads(pickle.dumps(m))):
            self.assertEqual(other.faces, m.faces)
            self.assertEqual(other.edge_count, 12)

    def test_arguments(self):
        m = bezsurf.Model(cube())
        with self.assertRaises(IndexError):
            m.face_eval([6], [0.5], [0.5])
        with self.assertRaises(ValueError):
            m.face_eval([0, 1], [0.5], [0.5])
        with self.assertRaises(ValueError):
            m.classify([0], [0.5], [0.5], tol=-1.0)
        with self.assertRaises(TypeError):
            bezsurf.Model("teapot")
        with self.assertRaises(ValueError):
            bezsurf.Model.read(str(CAD_DIR / "README.md"))
        with self.assertRaises(bezsurf.BezsurfIOError) as cm:
            bezsurf.Model.read("/nonexistent-directory/part.step")
        self.assertEqual(cm.exception.filename, "/nonexistent-directory/part.step")
        with self.assertRaises(bezsurf.ParseError):
            bezsurf.Model.read_step("ISO-10303-21;\nHEADER;\nENDSEC;\n")
        m.close()
        with self.assertRaises(ValueError):
            len(m)


@requires("bs_model_read_step")
class CadPartsTest(PlainTestCase):
    def test_parts_read_from_step_and_iges(self):
        for part in PARTS:
            for name in (f"{part}.step", f"{part}.igs", f"{part}-brep.igs"):
                with self.subTest(file=name):
                    m = bezsurf.Model.read(CAD_DIR / name)
                    self.assertEqual(len(m), ref_faces(part))
                    if not name.endswith(".igs") or "brep" in name:
                        self.assertTrue(all(m.shells), m.shells)
                    ref = ref_values(part)
                    p = m.properties(1e-10)
                    rel = reference_tolerance(part, name)
                    self.assertAlmostEqual(p.area, ref["area"], delta=rel["area"] * ref["area"])
                    if all(m.shells):
                        self.assertAlmostEqual(p.volume, ref["volume"],
                                               delta=rel["volume"] * ref["volume"])

    def test_points_of_a_sphere(self):
        m = bezsurf.Model.read(CAD_DIR / "sphere.step")
        f = m.face(0)
        self.assertEqual(f.kind, "sphere")
        u0, u1, v0, v1 = f.box
        us = [u0 + (u1 - u0) * k / 7 for k in range(8)]
        vs = [v0 + (v1 - v0) * (k + 0.5) / 8 for k in range(8)]
        ev = m.face_eval(0, us, vs)
        # the sphere of data/cad/sphere.ref's box: centre (1, 2, 3), radius 5
        for p in plain(ev.position):
            self.assertAlmostEqual(math.dist(p, (1.0, 2.0, 3.0)), 5.0, delta=1e-12 * 5.0)
        where = m.classify(0, us, vs, 1e-9)
        self.assertTrue(all(w == bezsurf.TRIM_INSIDE for w in plain(where)))
        # native -> (patch, s, t) -> native again, along the sphere's angular directions
        patch, st = m.face_to_patch(0, us[1:-1], vs[1:-1])
        face, uv = m.patch_to_face(patch, [p[0] for p in plain(st)], [p[1] for p in plain(st)])
        self.assertEqual(list(plain(face)), [0] * 6)
        for (u, v), (ub, vb) in zip(zip(us[1:-1], vs[1:-1]), plain(uv)):
            self.assertAlmostEqual(u, ub, delta=1e-13)
            self.assertAlmostEqual(v, vb, delta=1e-13)


def ref_rays(part):
    """The kernel's rays of a part: (origin, direction, t or None for a miss)."""
    out = []
    for line in (CAD_DIR / f"{part}.ref").read_text().splitlines():
        w = line.split()
        if w and w[0] == "ray":
            out.append((tuple(map(float, w[1:4])), tuple(map(float, w[4:7])),
                        float(w[8]) if w[7] == "hit" else None))
    return out


@requires("bs_locator_create_model")
class ModelLocatorTest(PlainTestCase):
    def test_rays_of_the_block_as_the_kernel(self):
        m = bezsurf.Model.read(CAD_DIR / "block.step")
        loc = m.locator()
        rays = ref_rays("block")[:80]
        hits = loc.intersect([r[0] for r in rays], [r[1] for r in rays])
        diag = 50.0  # the block is about 40 x 30 x 20
        for (o, d, t), face, tt in zip(rays, plain(hits.patch), plain(hits.t)):
            if t is None:
                self.assertEqual(face, bezsurf.NO_PATCH)
            else:
                self.assertLess(face, len(m))
                self.assertAlmostEqual(tt, t, delta=1e-6 * diag)

    def test_face_uv_and_outward_normal(self):
        m = bezsurf.Model.read(CAD_DIR / "sphere.step")  # centre (1, 2, 3), radius 5
        hit = m.locator().intersect((1.0, 2.0, 20.0), (0.0, 0.0, -1.0))
        self.assertEqual(hit.patch, 0)
        self.assertAlmostEqual(hit.t, 12.0, delta=1e-9)
        self.assertAlmostEqual(plain(hit.normal)[2], 1.0, delta=1e-12)  # outward: +z at the top
        ev = m.face_eval(0, [plain(hit.uv)[0]], [plain(hit.uv)[1]])
        self.assertAlmostEqual(plain(ev.position)[0][2], 8.0, delta=1e-9)

    def test_closest_points_copies_and_pickles(self):
        m = bezsurf.Model.read(CAD_DIR / "cone.step")  # a truncated cone, its top disc at z = 7
        loc = m.locator()
        c = loc.closest_point((0.0, 0.0, 100.0))
        self.assertEqual(c.patch, 1)  # the face id
        self.assertAlmostEqual(c.dist, 93.0, delta=1e-12)
        self.assertAlmostEqual(plain(c.pos)[2], 7.0, delta=1e-12)
        # the kernel's distances (BRepExtrema_DistShapeShape), never beaten by more than its
        # tolerance
        diag = 0.0
        for line in (CAD_DIR / "cone.ref").read_text().splitlines():
            w = line.split()
            if w[0] == "box":
                b = [float(x) for x in w[1:7]]
                diag = sum((b[k + 3] - b[k]) ** 2 for k in range(3)) ** 0.5
            if w[0] == "closest":
                got = loc.closest_point(tuple(float(x) for x in w[1:4]))
                self.assertLessEqual(got.dist, float(w[5]) + 1e-7 * diag)
        for other in (copy.deepcopy(loc), pickle.loads(pickle.dumps(loc))):
            a = loc.intersect((0.0, 0.0, 100.0), (0.0, 0.0, -1.0))
            b = other.intersect((0.0, 0.0, 100.0), (0.0, 0.0, -1.0))
            self.assertEqual(plain(a.t), plain(b.t))
        self.assertIn("ModelLocator", repr(loc))
        with self.assertRaises(TypeError):
            bezsurf.ModelLocator(cube())


if __name__ == "__main__":
    unittest.main()


class ModelTessellateTest(PlainTestCase):
    def test_closed_outward_mesh_of_the_cone(self):
        m = bezsurf.Model.read(CAD_DIR / "cone.step")
        mesh = m.tessellate(1e-3, relative=True)
        tris = [tuple(t) for t in plain(mesh.triangles())]
        self.assertEqual(len(tris), mesh.triangle_count)
        edges = {}
        for a, b, c in tris:
            for e in ((a, b), (b, c), (c, a)):
                edges[e] = edges.get(e, 0) + 1
        # closed: every directed edge once, and its reverse once
        self.assertTrue(all(n == 1 and edges.get((e[1], e[0])) == 1 for e, n in edges.items()))
        self.assertTrue(all(f < len(m) for f in plain(mesh.triangle_patch_ids())))
        self.assertEqual(m.tessellate_count(1e-3, relative=True),
                         (mesh.vertex_count, mesh.triangle_count))
        two = m.tessellate(1e-3, relative=True, threads=2)
        self.assertEqual(plain(two.triangles()), plain(mesh.triangles()))
        again = pickle.loads(pickle.dumps(mesh))
        self.assertEqual(again.triangle_count, mesh.triangle_count)

    def test_tolerance_and_budget_errors(self):
        m = bezsurf.Model.read(CAD_DIR / "wedge.step")
        with self.assertRaises(ValueError):
            m.tessellate(0.0)
        with self.assertRaises(bezsurf.SizeError):
            m.tessellate(1e-3, relative=True, max_triangles=10)
