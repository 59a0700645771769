"""Surface evaluation, continuity and meshes on small surfaces with known answers."""

import math
import os
import struct
import tempfile
import unittest

import bezsurf

from .support import PlainTestCase, plain, needs_numpy, numpy as np, requires


def square(x0, y0=0.0):
    """The flat unit square [x0, x0+1] x [y0, y0+1] at z = 0, S(u,v) = (x0+u, y0+v, 0)."""
    return bezsurf.Patch([[[x0, y0, 0], [x0, y0 + 1, 0]], [[x0 + 1, y0, 0], [x0 + 1, y0 + 1, 0]]])


def saddle(x0):
    """S(u,v) = (x0+u, v, uv)."""
    return bezsurf.Patch([[[x0, 0, 0], [x0, 1, 0]], [[x0 + 1, 0, 0], [x0 + 1, 1, 1]]])


@requires("bs_surface_eval", "bs_surface_eval_normal")
class SurfaceEvalTest(PlainTestCase):
    def test_points_on_their_patches(self):
        s = bezsurf.Surface([saddle(0), saddle(10)])
        got = s.eval([1, 0, 1], [0.5, 0.25, 1.0], [0.5, 0.5, 0.75])
        self.assertEqual(got, [(10.5, 0.5, 0.25), (0.25, 0.5, 0.125), (11.0, 0.75, 0.75)])
        self.assertEqual(s.eval(1, 0.5, 0.5), (10.5, 0.5, 0.25))
        self.assertEqual(s.eval(1, [0.0, 1.0], [0.0, 1.0]), [(10.0, 0.0, 0.0), (11.0, 1.0, 1.0)])
        r = s.eval([0], [0.5], [0.25], derivatives=True, normals=True)
        self.assertEqual((r.du, r.dv), ([(1.0, 0.0, 0.25)], [(0.0, 1.0, 0.5)]))
        n = 1 / math.sqrt(1 + 0.25 ** 2 + 0.5 ** 2)
        for a, b in zip(r.normal[0], (-0.25 * n, -0.5 * n, n)):
            self.assertAlmostEqual(a, b, delta=1e-15)
        self.assertEqual(r.kind, [bezsurf.NORMAL_REGULAR])

    def test_errors(self):
        s = bezsurf.Surface([saddle(0)])
        with self.assertRaises(bezsurf.InvalidArgumentError):
            s.eval([1], [0.5], [0.5])              # no patch 1
        with self.assertRaises(ValueError):
            s.eval([-1], [0.5], [0.5])
        with self.assertRaises(ValueError):
            s.eval([0, 0], [0.5], [0.5])
        flat = bezsurf.Surface([bezsurf.Patch([[[0, 0]]])])
        with self.assertRaises(bezsurf.DimensionError):
            flat.eval_normal([0], [0.5], [0.5])

    @needs_numpy
    def test_numpy(self):
        s = bezsurf.Surface([saddle(0), saddle(10)])
        ids = np.array([1, 0, 1], dtype=np.int64)
        out = np.zeros((3, 3), order="F")
        got = s.eval(ids, np.array([0.5, 0.25, 1.0]), [0.5, 0.5, 0.75], out=out)
        self.assertIs(got, out)
        self.assertTrue(np.array_equal(out, [[10.5, 0.5, 0.25], [0.25, 0.5, 0.125],
                                             [11.0, 0.75, 0.75]]))


@requires("bs_surface_continuity")
class ContinuityTest(PlainTestCase):
    def test_two_squares(self):
        c = bezsurf.Surface([square(0), square(1)]).continuity()
        self.assertEqual(len(c.edges), 1)
        e = c.edges[0]
        self.assertEqual((e.patch_a, e.side_a, e.patch_b, e.side_b),
                         (0, bezsurf.SIDE_U1, 1, bezsurf.SIDE_U0))
        self.assertFalse(e.reversed)
        self.assertTrue(e.c1)
        self.assertFalse(e.flipped)
        self.assertEqual((e.c0_gap, e.g1_angle, e.c1_defect), (0.0, 0.0, 0.0))
        self.assertEqual(e.samples, 32)
        self.assertEqual(sorted(c.open_edges),
                         sorted([bezsurf.OpenEdge(0, s) for s in (0, 2, 3)] +
                                [bezsurf.OpenEdge(1, s) for s in (0, 1, 2)]))

    def test_errors(self):
        s = bezsurf.Surface([square(0)])
        with self.assertRaises(bezsurf.DomainError):
            s.continuity(tol=-1.0)
        with self.assertRaises(bezsurf.DomainError):
            s.continuity(samples=0)


@requires("bs_surface_tessellate_uniform", "bs_surface_tessellate_adaptive", "bs_mesh_write",
          "bs_mesh_write_memory", "bs_mesh_copy_strips")
class MeshTest(PlainTestCase):
    def test_uniform_square(self):
        with bezsurf.Surface([square(0)]).tessellate(2) as m:
            self.assertEqual((m.vertex_count, m.triangle_count), (9, 8))
            pos = plain(m.positions())
            self.assertEqual(sorted(pos), sorted((x, y, 0.0) for x in (0, 0.5, 1) for y in (0, 0.5, 1)))
            self.assertEqual(m.normals(), [(0.0, 0.0, 1.0)] * 9)
            self.assertEqual([(x, y) for x, y, _ in pos], m.uv())   # S(u,v) = (u, v, 0)
            self.assertEqual(m.patch_ids(), [0] * 9)
            self.assertEqual(m.triangle_patch_ids(), [0] * 8)
            area = 0.0
            for a, b, c in m.triangles():
                (ax, ay, _), (bx, by, _), (cx, cy, _) = pos[a], pos[b], pos[c]
                cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
                self.assertGreater(cross, 0)              # counter-clockwise seen from +z
                area += cross / 2
            self.assertEqual(area, 1.0)
            corner = m.corner_uv()
            self.assertEqual(len(corner), 24)
            tri = m.triangles()
            self.assertEqual(corner[:3], [m.uv()[i] for i in tri[0]])
        self.assertTrue(m.closed)

    def test_shared_edge_has_shared_vertices(self):
        m = bezsurf.Surface([square(0), square(1)]).tessellate(2, 3)
        self.assertEqual(m.vertex_count, 2 * 12 - 4)
        self.assertEqual(m.triangle_count, 2 * 12)

    def test_strips_cover_triangles(self):
        m = bezsurf.Surface([square(0)]).tessellate(3, strips=True)
        self.assertGreater(m.strip_count, 0)
        tris = set()
        for s in m.strips():
            for i in range(len(s) - 2):
                t = (s[i], s[i + 1], s[i + 2]) if i % 2 == 0 else (s[i + 1], s[i], s[i + 2])
                if len(set(t)) == 3:
                    k = t.index(min(t))
                    tris.add(t[k:] + t[:k])
        want = set()
        for t in plain(m.triangles()):
            k = t.index(min(t))
            want.add(t[k:] + t[:k])
        self.assertEqual(tris, want)

    def test_reverse_faces_the_teapot_outwards(self):
        pot = bezsurf.Surface.builtin("teapot")

        def volume(m):
            p = plain(m.positions())
            v = 0.0
            for a, b, c in plain(m.triangles()):
                (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = p[a], p[b], p[c]
                v += x0 * (y1 * z2 - z1 * y2) - y0 * (x1 * z2 - z1 * x2) + z0 * (x1 * y2 - y1 * x2)
            return v / 6

        for make in (lambda **k: pot.tessellate(4, **k),
                     lambda **k: pot.tessellate_adaptive(0.01, relative=True, subdivide=True, **k)):
            m, r = make(), make(reverse=True)
            self.assertLess(volume(m), -24.0)  # the patches face into the pot
            self.assertGreater(volume(r), 24.0)
            self.assertEqual(plain(r.positions()), plain(m.positions()))
            self.assertEqual(plain(r.triangles()), [(a, c, b) for a, b, c in plain(m.triangles())])
            self.assertEqual(plain(r.normals()),
                             [(-x, -y, -z) for x, y, z in plain(m.normals())])
        self.assertEqual(pot.tessellate_count(3, reverse=True), pot.tessellate_count(3))

    def test_strips_of_a_mesh_made_without_them(self):
        s = bezsurf.Surface([square(0)])
        with self.assertRaisesRegex(ValueError, "without strips"):
            s.tessellate(3).strips()
        with self.assertRaisesRegex(ValueError, "without strips"):
            s.tessellate_adaptive(0.1, threads=2).strips()
        self.assertGreater(len(s.tessellate_adaptive(0.1, strips=True).strips()), 0)

    def test_surface_grid_on_threads(self):
        pot = bezsurf.Surface.builtin("teapot")
        u, v = [0.0, 0.3, 1.0], [0.25, 0.5]
        one = plain(pot.eval_grid(u, v))
        self.assertEqual(len(one), 32 * 3 * 2)
        self.assertEqual(plain(pot.eval_grid(u, v, threads=2)), one)
        for p in (0, 31):
            for a in range(3):
                for b in range(2):
                    self.assertEqual(one[(p * 3 + a) * 2 + b],
                                     plain(pot.eval([p], [u[a]], [v[b]]))[0])
        e = pot.eval_grid(u, v, normals=True, threads=2)
        self.assertEqual(plain(e.position), one)
        self.assertEqual(plain(e.normal)[7], plain(pot.eval_normal([1], [u[0]], [v[1]]).normal)[0])

    def test_scalars_broadcast(self):
        p = saddle(0)
        self.assertEqual(plain(p.eval(0.5, [0.25, 0.75])), plain(p.eval([0.5, 0.5], [0.25, 0.75])))
        self.assertEqual(plain(p.eval([0.25, 0.75], 1.0)), plain(p.eval([0.25, 0.75], [1.0, 1.0])))
        s = bezsurf.Surface([p])
        self.assertEqual(plain(s.eval(0, 0.5, [0.25, 0.75])), plain(p.eval(0.5, [0.25, 0.75])))
        self.assertEqual(plain(p.eval_grid(0.5, 0.5)), plain(p.eval(0.5, 0.5)))  # one point: (3,)
        self.assertEqual(len(plain(p.eval_grid([0.5], 0.5))), 1)

    def test_transform_takes_a_homogeneous_matrix(self):
        p = saddle(0)
        m4 = [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 2, 3], [0, 0, 0, 1]]
        self.assertEqual(p.transform(m4).ctrl, p.transform(m4[:3]).ctrl)
        with self.assertRaisesRegex(ValueError, "last row"):
            p.transform([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]])

    def test_export(self):
        m = bezsurf.Surface([square(0)]).tessellate(1)
        obj = m.to_bytes("obj").decode()
        self.assertEqual(sum(line.startswith("v ") for line in obj.splitlines()), 4)
        self.assertEqual(sum(line.startswith("f ") for line in obj.splitlines()), 2)
        stl = m.to_bytes("stl")
        self.assertEqual(len(stl), 84 + 50 * 2)
        self.assertEqual(struct.unpack_from("<I", stl, 80)[0], 2)
        self.assertTrue(m.to_bytes("ply").startswith(b"ply\nformat binary_little_endian"))
        self.assertTrue(m.to_bytes("ply_ascii").startswith(b"ply\nformat ascii"))
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.stl")
            m.write(path, "stl")
            with open(path, "rb") as f:
                self.assertEqual(f.read(), stl)
            # without a format, the extension's (any case), as `bezsurf tessellate`
            for name, fmt in (("a.ply", "ply"), ("b.PLY", "ply"), ("c.obj", "obj"), ("d.Stl", "stl")):
                m.write(os.path.join(d, name))
                with open(os.path.join(d, name), "rb") as f:
                    self.assertEqual(f.read(), m.to_bytes(fmt), name)
            for name in ("e.txt", "noext", "f.ply.gz"):
                with self.assertRaisesRegex(ValueError, "unknown mesh extension"):
                    m.write(os.path.join(d, name))
                self.assertFalse(os.path.exists(os.path.join(d, name)))
            m.write(os.path.join(d, "g.txt"), "ply_ascii")  # an explicit format wins
            with open(os.path.join(d, "g.txt"), "rb") as f:
                self.assertEqual(f.read(), m.to_bytes("ply_ascii"))
        with self.assertRaises(ValueError):
            m.to_bytes("dxf")
        with self.assertRaises(bezsurf.InvalidArgumentError):
            m.to_bytes(17)
        with self.assertRaises(bezsurf.BezsurfIOError):
            m.write("/nonexistent/dir/m.obj")

    def test_adaptive_teapot_vertices_lie_on_surface(self):
        s = bezsurf.Surface.builtin("teapot")
        m = s.tessellate_adaptive(1e-3, relative=True)
        self.assertGreater(m.triangle_count, 32 * 2)
        ids = m.patch_ids()
        uv = m.uv()
        on = s.eval(ids, [p[0] for p in uv], [p[1] for p in uv])
        for a, b in zip(on, m.positions()):
            self.assertLessEqual(max(abs(x - y) for x, y in zip(a, b)), 1e-12)

    def test_errors(self):
        s = bezsurf.Surface([square(0)])
        with self.assertRaises(bezsurf.DomainError):
            s.tessellate(0)
        with self.assertRaises(bezsurf.DomainError):
            s.tessellate_adaptive(0.0)
        with self.assertRaises(bezsurf.DimensionError):
            bezsurf.Surface([bezsurf.Patch([[[0, 0]]])]).tessellate(2)
        with self.assertRaises(TypeError):
            bezsurf.Mesh()

    @needs_numpy
    def test_numpy_read_back(self):
        m = bezsurf.Surface([square(0), square(1)]).tessellate(4)
        pos = np.full((m.vertex_count, 3), np.nan)
        self.assertIs(m.positions(out=pos), pos)
        self.assertTrue(np.all(np.isfinite(pos)))
        tri = m.triangles()
        self.assertEqual((tri.dtype, tri.shape), (np.uint32, (m.triangle_count, 3)))
        a, b, c = pos[tri[:, 0]], pos[tri[:, 1]], pos[tri[:, 2]]
        self.assertEqual(np.cross(b - a, c - a)[:, 2].sum() / 2, 2.0)   # total area
        self.assertTrue(np.array_equal(m.uv(), np.array(m.uv())))
        self.assertTrue(np.array_equal(m.normals()[:, 2], np.ones(m.vertex_count)))


if __name__ == "__main__":
    unittest.main()
