"""Closest points, the locator and rays through the binding, checked against geometry known in
closed form (planes, a sphere octant, the teapot's own points)."""

import array
import copy
import math
import pickle
import threading
import unittest

import bezsurf

from .support import PlainTestCase, bilinear, numpy as np, plain, requires
from .test_curvature import R, sphere_octant


def flat_square():
    """The square [0,2] x [0,2] in the plane z = 1, as a degree (2,1) patch (m != n)."""
    return bezsurf.Patch([[[0, 0, 1], [0, 2, 1]], [[1, 0, 1], [1, 2, 1]], [[2, 0, 1], [2, 2, 1]]])


@requires("bs_patch_closest_point")
class PatchClosestTest(PlainTestCase):
    def test_plane_inside_and_beyond(self):
        p = flat_square()
        r = p.closest_point([(0.5, 1.5, 4.0), (3.0, -1.0, 1.0)])
        uv, dist, pos = plain(r.uv), plain(r.dist), plain(r.pos)
        self.assertIsNone(r.patch)
        self.assertAlmostEqual(uv[0][0], 0.25, delta=1e-9)
        self.assertAlmostEqual(uv[0][1], 0.75, delta=1e-9)
        self.assertAlmostEqual(dist[0], 3.0, delta=1e-8)
        self.assertAlmostEqual(dist[1], math.sqrt(2.0), delta=1e-8)   # the corner (2, 0, 1)
        self.assertEqual(tuple(round(c, 9) for c in pos[1]), (2.0, 0.0, 1.0))
        one = p.closest_point((1.0, 1.0, 1.0))                    # one point: no n axis
        self.assertAlmostEqual(one.dist, 0.0, delta=1e-9)
        self.assertEqual(len(plain(one.uv)), 2)

    def test_sphere_octant_radial(self):
        p = sphere_octant()
        d = (1.0, 2.0, 2.0)                                        # |d| = 3
        q = [tuple(2.0 * c for c in d)]                            # |q| = 6, on a radius
        r = p.closest_point(q)
        self.assertAlmostEqual(plain(r.dist)[0], 6.0 - R, delta=1e-8)
        x = plain(r.pos)[0]
        for a, b in zip(x, d):
            self.assertAlmostEqual(a, R * b / 3.0, delta=1e-8)

    def test_nan_and_errors(self):
        p = bilinear()
        r = p.closest_point([(math.nan, 0.0, 0.0)])
        self.assertTrue(math.isnan(plain(r.dist)[0]))
        with self.assertRaises(ValueError):
            p.closest_point([(1.0, 2.0)])                          # 2 coordinates, dim 3
        with self.assertRaises(TypeError):
            p.closest_point("points")
        empty = p.closest_point([])
        self.assertEqual(len(plain(empty.dist)), 0)

    @unittest.skipIf(np is None, "numpy is not available")
    def test_numpy_strided_input(self):
        p = flat_square()
        q = np.zeros((4, 6))
        q[:, ::2] = [[0.5, 0.5, 2.0]] * 4                           # (n, 3) view, stride 48
        r = p.closest_point(q[:, ::2])
        self.assertEqual(r.pos.shape, (4, 3))
        self.assertTrue(np.allclose(r.dist, 1.0, atol=1e-9))


@requires("bs_locator_create", "bs_locator_intersect", "bs_locator_closest_point")
class LocatorTest(PlainTestCase):
    def setUp(self):
        self.teapot = bezsurf.Surface.builtin("teapot")
        self.loc = bezsurf.Locator(self.teapot)

    def tearDown(self):
        self.loc.close()

    def test_rays_hit_known_points(self):
        # Aim at surface points from outside along the normal: the hit is that point or earlier.
        ids, us, vs = [0, 5, 12, 20], [0.3, 0.5, 0.7, 0.1], [0.4, 0.5, 0.2, 0.9]
        ev = self.teapot.eval_normal(ids, us, vs)
        pts, nrm = plain(ev.position), plain(ev.normal)
        org = [tuple(p[c] + 5.0 * n[c] for c in range(3)) for p, n in zip(pts, nrm)]
        dirs = [tuple(-n[c] for c in range(3)) for n in nrm]
        hits = self.loc.intersect(org, dirs)
        t, hit_ids, uv = plain(hits.t), plain(hits.patch), plain(hits.uv)
        for k in range(4):
            self.assertNotEqual(hit_ids[k], bezsurf.NO_PATCH)
            self.assertLessEqual(t[k], 5.0 + 1e-7)
            # the hit is a point of the surface on the ray (the target or one before it)
            at = plain(self.teapot.eval(hit_ids[k], uv[k][0], uv[k][1]))
            for c in range(3):
                self.assertAlmostEqual(at[c], org[k][c] + t[k] * dirs[k][c], delta=1e-7)

    def test_miss_range_and_invalid(self):
        hits = self.loc.intersect([(0, 0, 100.0), (0, 0, 100.0), (0, 0, 100.0)],
                                  [(0, 0, 1.0), (0, 0, -1.0), (0, 0, 0.0)])
        self.assertEqual(plain(hits.patch)[0], bezsurf.NO_PATCH)
        self.assertEqual(plain(hits.t)[0], math.inf)
        self.assertNotEqual(plain(hits.patch)[1], bezsurf.NO_PATCH)
        self.assertTrue(math.isnan(plain(hits.t)[2]))
        short = self.loc.intersect((0, 0, 100.0), (0, 0, -1.0), t_max=1.0)   # one ray
        self.assertEqual(short.patch, bezsurf.NO_PATCH)
        self.assertEqual(plain(hits.hit), [False, True, False])   # the mask of the hits
        self.assertIs(short.hit, False)
        # t_max = inf is "no limit" (1.2): the hit of the default range, not an invalid ray
        free = self.loc.intersect((0, 0, 100.0), (0, 0, -1.0))
        self.assertIs(free.hit, True)
        for t_min, t_max in ((None, math.inf), (0.0, math.inf), (1.0, [math.inf])):
            hit = self.loc.intersect([(0, 0, 100.0)], [(0, 0, -1.0)], t_min=t_min, t_max=t_max)
            self.assertEqual(plain(hit.patch)[0], free.patch)
            self.assertEqual(plain(hit.t)[0], free.t)
        bad = self.loc.intersect((0, 0, 100.0), (0, 0, -1.0), t_min=-math.inf, t_max=math.inf)
        self.assertTrue(math.isnan(bad.t))
        with self.assertRaises(ValueError):
            self.loc.intersect([(0, 0, 1.0)], [(0, 0, 1.0), (0, 0, 1.0)])

    def test_empty_surface_misses_alike(self):
        # rays and closest points on an empty surface both answer with misses (1.2: closest_point
        # raised ValueError where intersect missed)
        empty = bezsurf.Surface([]).locator()
        near = empty.closest_point([(0, 0, 0.0), (1, 2, 3.0)])
        self.assertEqual(plain(near.patch), [bezsurf.NO_PATCH] * 2)
        self.assertEqual(list(plain(near.dist)), [math.inf] * 2)
        self.assertTrue(all(math.isnan(x) for p in plain(near.pos) for x in p))
        self.assertTrue(all(math.isnan(x) for p in plain(near.uv) for x in p))
        ray = empty.intersect([(0, 0, 0.0)], [(0, 0, 1.0)])
        self.assertEqual((list(plain(ray.patch)), list(plain(ray.t))), ([bezsurf.NO_PATCH], [math.inf]))
        one = empty.closest_point((0, 0, 0.0))
        self.assertEqual((one.patch, one.dist), (bezsurf.NO_PATCH, math.inf))

    def test_ray_normal_kinds(self):
        # down onto the lid's pole (a limit normal), and a miss (since 1.2)
        hits, kinds = self.loc.intersect_kinds([(0, 0, 10.0), (0, 0, -10.0)],
                                               [(0, 0, -1.0), (0, 0, -1.0)])
        kinds = [int(k) for k in plain(kinds)]
        self.assertEqual(kinds, [int(bezsurf.NormalKind.LIMIT), int(bezsurf.NormalKind.UNDEFINED)])
        self.assertEqual(plain(hits.patch), plain(self.loc.intersect([(0, 0, 10.0), (0, 0, -10.0)],
                                                                     [(0, 0, -1.0), (0, 0, -1.0)]).patch))
        one, kind = self.loc.intersect_kinds((0, 0, 10.0), (0, 0, -1.0))
        self.assertEqual(int(kind), int(bezsurf.NormalKind.LIMIT))

    def test_closest_agrees_with_patches(self):
        q = [(4.0, 1.0, 2.0), (0.0, 0.0, 5.0)]
        r = self.loc.closest_point(q)
        best = [min(plain(p.closest_point([x]).dist)[0] for p in self.teapot) for x in q]
        for k in range(2):
            self.assertAlmostEqual(plain(r.dist)[k], best[k], delta=1e-8 * (10 + best[k]))
            self.assertLess(plain(r.patch)[k], len(self.teapot))

    def test_queries_on_threads(self):
        # batches cut into pieces for the threads: the same answers as one thread
        q = [(0.1 * k - 4.0, 0.05 * k - 2.0, 0.03 * k) for k in range(150)]
        one = self.loc.closest_point(q)
        for n in (2, 0):
            many = self.loc.closest_point(q, threads=n)
            self.assertEqual(plain(many.patch), plain(one.patch))
            self.assertEqual(plain(many.dist), plain(one.dist))
            self.assertEqual(plain(many.uv), plain(one.uv))
        org = [(8.0, (k % 34) / 8.5 - 2.0, (k // 34) / 10.0) for k in range(1100)]  # a 34 x 33 grid
        dirs = [(-1.0, 0.0, 0.0)] * len(org)
        one_hits = self.loc.intersect(org, dirs)
        self.assertGreater(sum(i != bezsurf.NO_PATCH for i in plain(one_hits.patch)), 100)
        hits = self.loc.intersect(org, dirs, threads=2)
        self.assertEqual(plain(hits.patch), plain(one_hits.patch))
        self.assertEqual(plain(hits.t), plain(one_hits.t))
        with self.assertRaises(TypeError):
            self.loc.closest_point(q, threads=1.5)
        with self.assertRaises(ValueError):
            self.loc.intersect(org, dirs, threads=-1)

    def test_copy_pickle_threads(self):
        q = [(1.0, 2.0, 3.0)]
        ref = plain(self.loc.closest_point(q).dist)
        for other in (copy.copy(self.loc), copy.deepcopy(self.loc),
                      pickle.loads(pickle.dumps(self.loc))):
            self.assertEqual(plain(other.closest_point(q).dist), ref)
        results = []

        def work():
            results.append(plain(self.loc.closest_point(q).dist))
        threads = [threading.Thread(target=work) for _ in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(results, [ref] * 4)
        self.assertEqual(self.loc.dim, 3)
        self.assertIn("Locator", repr(self.loc))


@requires("bs_surface_tessellate", "bs_surface_tessellate_count")
class TessOptionsTest(PlainTestCase):
    def test_counts_and_budgets(self):
        s = bezsurf.Surface.builtin("teapot")
        nv, nt = s.tessellate_count(8, 6)
        m = s.tessellate(8, 6)
        self.assertEqual((m.vertex_count, m.triangle_count), (nv, nt))
        self.assertEqual(s.tessellate(8, 6, max_vertices=nv).vertex_count, nv)
        with self.assertRaises(bezsurf.SizeError):
            s.tessellate(8, 6, max_vertices=nv - 1)
        with self.assertRaises(bezsurf.SizeError):
            s.tessellate_adaptive(1e-3, relative=True, max_triangles=10)
        av, at = s.tessellate_count(tolerance=1e-3, relative=True)
        ad = s.tessellate_adaptive(1e-3, relative=True)
        self.assertEqual((ad.vertex_count, ad.triangle_count), (av, at))
        with self.assertRaises(ValueError):
            s.tessellate_count()

    def test_subdivide(self):
        s = bezsurf.Surface.builtin("teapot")
        sv, st = s.tessellate_count(tolerance=1e-3, relative=True, subdivide=True)
        m = s.tessellate_adaptive(1e-3, relative=True, subdivide=True)
        self.assertEqual((m.vertex_count, m.triangle_count), (sv, st))
        self.assertEqual(copy.copy(m).triangle_count, st)          # the recipe remakes it


@requires("bs_surface_tessellate", "bs_surface_eval_mt")
class ThreadsTest(PlainTestCase):
    """threads= gives the results of one thread, bit for bit."""

    def test_tessellate(self):
        s = bezsurf.Surface.builtin("teapot")
        one = s.tessellate(12, 7)
        for n in (2, 0):
            m = s.tessellate(12, 7, threads=n)
            self.assertEqual(plain(m.positions()), plain(one.positions()))
            self.assertEqual(plain(m.triangles()), plain(one.triangles()))
        sub = s.tessellate_adaptive(1e-3, relative=True, subdivide=True, threads=2)
        ref = s.tessellate_adaptive(1e-3, relative=True, subdivide=True)
        self.assertEqual(plain(sub.normals()), plain(ref.normals()))
        with self.assertRaises((TypeError, ValueError)):
            s.tessellate(4, threads=-1)

    def test_eval(self):
        s = bezsurf.Surface.builtin("teapot")
        n = 9000
        ids = [k % 32 for k in range(n)]
        u = [(k % 97) / 96 for k in range(n)]
        v = [(k % 89) / 88 for k in range(n)]
        one = s.eval(ids, u, v, derivatives=True)
        two = s.eval(ids, u, v, derivatives=True, threads=2)
        self.assertEqual(plain(one.position), plain(two.position))
        self.assertEqual(plain(one.du), plain(two.du))

    @requires("bs_surface_eval_normal_mt")
    def test_eval_normal(self):
        # positions, normals and kinds on 2, 3, 7 and one per CPU thread: the bits of one thread
        # (NaN included), with lists, with array.array and (numpy) with strided arrays
        s = bezsurf.Surface.builtin("teapot")
        n = 9000
        ids = [(k // 3) % 32 for k in range(n)]
        u = [(k % 97) / 96 for k in range(n)]
        v = [(k % 89) / 88 for k in range(n)]
        u[7] = float("nan")
        one = s.eval_normal(ids, u, v)
        self.assertEqual(plain(one.kind)[7], bezsurf.NormalKind.UNDEFINED)
        ref = [repr(plain(x)) for x in one]
        for threads in (2, 3, 7, 0):
            many = s.eval_normal(ids, array.array("d", u), v, threads=threads)
            self.assertEqual([repr(plain(x)) for x in many], ref)
            both = s.eval(ids, u, v, normals=True, derivatives=True, threads=threads)
            self.assertEqual(repr(plain(both.normal)), ref[3])
        with self.assertRaises(bezsurf.InvalidArgumentError):
            s.eval_normal([0, 32], [0.5, 0.5], [0.5, 0.5], threads=2)
        with self.assertRaises((TypeError, ValueError)):
            s.eval_normal(ids, u, v, threads=-1)
        if np is not None:
            uu = np.repeat(np.asarray(u), 2)[::-2]   # strided, reversed
            vv = np.asarray(v)[::-1]
            rid = np.asarray(ids, dtype=np.uint32)[::-1]
            a = s.eval_normal(rid, uu, vv)
            b = s.eval_normal(rid, uu, vv, threads=3)
            for x, y in zip((a.position, a.normal, a.kind), (b.position, b.normal, b.kind)):
                self.assertEqual(x.tobytes(), y.tobytes())
            out = np.empty((n, 3), order="F")
            c = s.eval_normal(rid, uu, vv, normal_out=out, threads=2)
            self.assertIs(c.normal, out)
            self.assertEqual(out.tobytes(), a.normal.tobytes())


if __name__ == "__main__":
    unittest.main()
