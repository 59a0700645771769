"""Python-level behaviour: copies and pickles of every object (also across processes), argument
errors naming the argument, I/O errors as OSError subclasses, slicing, overlapping outputs,
enums, and the one rule for result types."""

import copy
import errno
import multiprocessing
import os
import pickle
import tempfile
import unittest

import bezsurf

from .support import (NET, HAVE_NUMPY, PlainTestCase, bilinear, needs_numpy, numpy as np, plain,
                      requires)


def square(z):
    return bezsurf.Patch([[[0, 0, z], [0, 1, z]], [[1, 0, z], [1, 1, z]]])


def mesh_arrays(m):
    return (plain(m.positions()), plain(m.normals()), plain(m.uv()), plain(m.triangles()),
            plain(m.patch_ids()), m.to_bytes("ply"))


def _work(obj):
    """Runs in a spawned worker: the object arrived by pickle; results go back as plain data,
    and the object itself goes back too."""
    if isinstance(obj, bezsurf.Mesh):
        return mesh_arrays(obj), obj
    if isinstance(obj, bezsurf.Surface):
        return plain(obj.eval(list(range(len(obj))), [0.25] * len(obj), [0.5] * len(obj))), obj
    return plain(obj.eval([0.25, 0.5], [0.75, 0.5])), obj


class CopyPickleTest(PlainTestCase):
    def check_copies(self, obj, same):
        for dup in (copy.copy(obj), copy.deepcopy(obj), pickle.loads(pickle.dumps(obj)),
                    pickle.loads(pickle.dumps(obj, protocol=0))):
            self.assertIsInstance(dup, type(obj))
            self.assertIsNot(dup, obj)
            self.assertNotEqual(dup._handle, obj._handle)   # a handle of its own
            self.assertEqual(same(dup), same(obj))
            dup.close()                                      # closing the copy ...
        self.assertFalse(obj.closed)                         # ... leaves the original alone
        self.assertEqual(same(obj), same(obj))

    def test_patch(self):
        rational = bezsurf.Patch(NET, [[1, 2, 1], [1, 3, 1], [2, 1, 1]])
        self.check_copies(rational, lambda p: (p.ctrl, p.weights))
        self.check_copies(bezsurf.Patch(NET), lambda p: (p.ctrl, p.weights))

    def test_borrowed_patch_copies_own_their_handle(self):
        s = bezsurf.Surface([bezsurf.Patch(NET)])
        for dup in (copy.copy(s[0]), copy.deepcopy(s[0]), pickle.loads(pickle.dumps(s[0]))):
            self.assertIsNone(dup._parent)
            self.assertEqual(dup.ctrl, s[0].ctrl)
        s.close()
        self.assertEqual(dup.ctrl, bezsurf.Patch(NET).ctrl)

    def test_surface(self):
        teapot = bezsurf.Surface.builtin("teapot")
        self.check_copies(teapot, lambda s: s.to_bpt())
        mixed = bezsurf.Surface([bezsurf.Patch(NET, [[1, 2, 1]] * 3), bilinear()])
        self.check_copies(mixed, lambda s: [(p.ctrl, p.weights) for p in s])
        self.check_copies(bezsurf.Surface(), len)
        flat = bezsurf.Surface([bezsurf.Patch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])])
        self.check_copies(flat, lambda s: (s.dim, s[0].ctrl))   # 2-D: no .bpt needed

    @requires("bs_surface_tessellate_uniform", "bs_surface_tessellate_adaptive")
    def test_mesh(self):
        s = bezsurf.Surface([square(0), square(1)])
        uniform = s.tessellate(3, 2, strips=True)
        s.add(square(2))                     # later changes of the surface do not matter
        self.check_copies(uniform, lambda m: mesh_arrays(m) + (m.strips(),))
        self.assertEqual(uniform.vertex_count, 2 * 12)
        adaptive = bezsurf.Surface.builtin("teacup").tessellate_adaptive(0.01, relative=True)
        self.check_copies(adaptive, mesh_arrays)

    def test_closed_objects_are_not_copied(self):
        for obj in (bilinear(), bezsurf.Surface([bilinear()]),
                    bezsurf.Surface([bilinear()]).tessellate(1)):
            obj.close()
            for op in (copy.copy, copy.deepcopy, pickle.dumps):
                with self.assertRaises(ValueError):
                    op(obj)

    def test_errors_pickle(self):
        errors = []
        for call in (lambda: bezsurf.Surface.from_bpt("1\n3 3\n"),
                     lambda: bezsurf.Surface.load("/nonexistent/dir/x.bpt"),
                     lambda: bilinear().split("u", 2.0)):
            with self.assertRaises(bezsurf.BezsurfError) as cm:
                call()
            errors.append(cm.exception)
        for e in errors:
            back = pickle.loads(pickle.dumps(e))
            self.assertIs(type(back), type(e))
            self.assertEqual(str(back), str(e))
            self.assertEqual((back.code, back.function, back.detail),
                             (e.code, e.function, e.detail))
        self.assertEqual((errors[0].line, errors[1].errno, errors[1].filename),
                         (pickle.loads(pickle.dumps(errors[0])).line,
                          pickle.loads(pickle.dumps(errors[1])).errno,
                          pickle.loads(pickle.dumps(errors[1])).filename))

    @requires("bs_surface_tessellate_uniform")
    def test_spawned_pool(self):
        patch = bilinear()
        surface = bezsurf.Surface.builtin("teaspoon")
        mesh = bezsurf.Surface([square(0)]).tessellate(2)
        ctx = multiprocessing.get_context("spawn")
        with ctx.Pool(2) as pool:
            results = pool.map_async(_work, [patch, surface, mesh]).get(timeout=120)
        (p_vals, p_back), (s_vals, s_back), (m_vals, m_back) = results
        self.assertEqual(p_vals, [(0.25, 0.75, 0.1875), (0.5, 0.5, 0.25)])
        self.assertEqual(p_back.ctrl, patch.ctrl)
        n = len(surface)
        self.assertEqual(s_vals, plain(surface.eval(list(range(n)), [0.25] * n, [0.5] * n)))
        self.assertEqual(s_back.to_bpt(), surface.to_bpt())
        self.assertEqual(m_vals, mesh_arrays(mesh))
        self.assertEqual(mesh_arrays(m_back), mesh_arrays(mesh))


class ArgumentErrorTest(unittest.TestCase):
    def assertNamed(self, exc_type, name, call):
        with self.assertRaises(exc_type) as cm:
            call()
        self.assertNotIsInstance(cm.exception, bezsurf.BezsurfError)
        self.assertIn(name, str(cm.exception))

    def test_wrong_scalar_types_are_type_errors_naming_the_argument(self):
        p = bilinear()
        s = bezsurf.Surface([square(0)])
        m = s.tessellate(1)
        cases = [
            ("t", lambda: p.split("u", "0.5")), ("direction", lambda: p.split(None, 0.5)),
            ("direction", lambda: p.split(0.5, 0.5)), ("u", lambda: p.split4("a", 0.5)),
            ("v", lambda: p.split4(0.5, None)), ("u1", lambda: p.subpatch(0, "1", 0, 1)),
            ("v1", lambda: p.subpatch(0, 1, 0, [1])), ("raise_u", lambda: p.elevate(1.5, 0)),
            ("raise_v", lambda: p.elevate(1, "2")), ("ku", lambda: p.derivative(None, 0)),
            ("kv", lambda: p.eval_deriv(0, 1.0, [0.5], [0.5])),
            ("t", lambda: p.isocurve("u", "x")), ("direction", lambda: p.reverse(b"u")),
            ("nu", lambda: s.tessellate(2.0)), ("nv", lambda: s.tessellate(2, "3")),
            ("tolerance", lambda: s.tessellate_adaptive("0.1")),
            ("tol", lambda: s.continuity(tol="1")), ("samples", lambda: s.continuity(samples=3.0)),
            ("patch", lambda: s.add(NET)), ("name", lambda: bezsurf.Surface.builtin(3)),
            ("text", lambda: bezsurf.Surface.from_bpt(3)), ("path", lambda: s.save(3)),
            ("path", lambda: bezsurf.Surface.load(None)), ("path", lambda: m.write(1.5)),
            ("format", lambda: m.to_bytes(1.5)), ("format", lambda: m.write("x.obj", 1.5)),
            ("u", lambda: p.eval("abc", [0.5])), ("v", lambda: p.eval([0.5], [None])),
            ("u", lambda: p.eval_grid({"a": 1}, [0.5])), ("ids", lambda: s.eval("0", 0.5, 0.5)),
            ("ids", lambda: s.eval([0.5], [0.5], [0.5])), ("code", lambda: bezsurf.status_string("x")),
            ("surface indices", lambda: s["0"]), ("surface indices", lambda: s[0.0]),
            ("patches", lambda: bezsurf.Surface(3)),
            ("patches[1]", lambda: bezsurf.Surface([p, NET])),
        ]
        for name, call in cases:
            with self.subTest(name=name):
                self.assertNamed(TypeError, name, call)

    def test_bad_values_are_value_errors_naming_the_argument(self):
        p = bilinear()
        self.assertNamed(ValueError, "direction", lambda: p.split("w", 0.5))
        self.assertNamed(ValueError, "raise_u", lambda: p.elevate(-1, 0))
        self.assertNamed(ValueError, "nu", lambda: bezsurf.Surface([p]).tessellate(-2))
        self.assertNamed(ValueError, "format", lambda: p.swap_uv() and
                         bezsurf.Surface([square(0)]).tessellate(1).to_bytes("gltf"))
        self.assertNamed(ValueError, "ids", lambda: bezsurf.Surface([p]).eval([-1], [0.5], [0.5]))

    def test_malformed_nets_name_the_element(self):
        cases = [
            (TypeError, "net must be a sequence, not int", 3),
            (TypeError, "net[0] must be a sequence, not int", [1, 2, 3]),
            (TypeError, "net[0][0] must be a sequence of real numbers, not int", [[1, 2]]),
            (TypeError, "net[0][1][2] must be a real number, not str", [[[0, 0, 0], [0, 0, "z"]]]),
            (TypeError, "net[1] must be a sequence, not str", [[[0, 0, 0]], "ab"]),
            (ValueError, "net[2] has 1 entries", NET[:2] + [[[0, 0, 0]]]),
            (ValueError, "net[0][1] has 2 entries", [[[0, 0, 0], [0, 0]]]),
        ]
        for exc, text, net in cases:
            with self.subTest(text=text):
                with self.assertRaises(exc) as cm:
                    bezsurf.Patch(net)
                self.assertIn(text, str(cm.exception))
        with self.assertRaises(ValueError) as cm:
            bezsurf.Patch(NET, [[1, 1, 1], [1, 1]])
        self.assertIn("weights", str(cm.exception))
        with self.assertRaises(TypeError) as cm:
            bezsurf.Patch(NET, [[1, 1, 1], [1, 1, 1], [1, "w", 1]])
        self.assertIn("weights[2][1]", str(cm.exception))
        with self.assertRaises(TypeError) as cm:
            bilinear().transform(["abcd", "efgh", "ijkl"])
        self.assertIn("affine[0]", str(cm.exception))
        with self.assertRaises(TypeError) as cm:
            bezsurf.Patch.ruled([[0, 0, 0], 5], [[0, 1, 0], [1, 1, 0]])
        self.assertIn("c0[1]", str(cm.exception))
        with self.assertRaises(ValueError) as cm:
            bezsurf.Patch.ruled(bezsurf.Curve([[0, 0, 0], [1, 0, 0]], [1]), [[0, 1, 0], [1, 1, 0]])
        self.assertIn("c0.weights", str(cm.exception))


class LibraryErrorDetailTest(unittest.TestCase):
    """Errors of the library's calls name the argument, its value and the limit it broke."""

    def test_unknown_builtin_lists_the_names(self):
        with self.assertRaises(bezsurf.InvalidArgumentError) as cm:
            bezsurf.Surface.builtin("kettle")
        self.assertIn("'kettle' is not a built-in surface", str(cm.exception))
        self.assertIn("teapot, teacup, teaspoon", str(cm.exception))

    def test_patch_id_out_of_range(self):
        pot = bezsurf.Surface.builtin("teapot")
        for call in (lambda: pot.eval([0, 32], [0.5, 0.5], [0.5, 0.5]),
                     lambda: pot.eval([32], [0.5], [0.5], normals=True),
                     lambda: pot.eval_normal([1, 2, 40], [0.5] * 3, [0.5] * 3)):
            with self.assertRaises(bezsurf.InvalidArgumentError) as cm:
                call()
            self.assertRegex(str(cm.exception), r"ids\[\d\] = (32|40) is not a patch of this "
                                                r"surface \(patch ids 0\.\.31\)")

    def test_rates_tolerances_and_budgets(self):
        pot = bezsurf.Surface.builtin("teapot")
        for call, text in ((lambda: pot.tessellate(0), "nu = 0 segments per patch is outside 1..1024"),
                           (lambda: pot.tessellate(4, 2000, strips=True), "nv = 2000"),
                           (lambda: pot.tessellate(4, 2000, threads=2), "nv = 2000"),
                           (lambda: pot.tessellate_count(1025), "nu = 1025"),
                           (lambda: pot.tessellate_adaptive(-1.0), "tolerance = -1.0 must be")):
            with self.assertRaises(bezsurf.DomainError) as cm:
                call()
            self.assertIn(text, str(cm.exception))
        with self.assertRaises(bezsurf.SizeError) as cm:
            pot.tessellate(16, max_triangles=1000)
        self.assertIn("the mesh would have 8258 vertices and 16256 triangles, over "
                      "max_triangles = 1000", str(cm.exception))

    def test_degree_limit(self):
        net = [[[i, j, 0.0] for j in range(2)] for i in range(66)]
        with self.assertRaises(bezsurf.DegreeError) as cm:
            bezsurf.Patch(net)
        self.assertIn("degrees 65 x 1, above the limit 64", str(cm.exception))
        p = bezsurf.Patch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
        with self.assertRaises(bezsurf.DegreeError) as cm:
            p.elevate(64, 0)
        self.assertIn("degrees 1 + 64 x 1 + 0 would be above the limit 64", str(cm.exception))


class IOErrorTest(unittest.TestCase):
    def test_missing_file(self):
        path = os.path.join(tempfile.gettempdir(), "no-such-dir-bezsurf", "x.bpt")
        with self.assertRaises(FileNotFoundError) as cm:
            bezsurf.Surface.load(path)
        e = cm.exception
        self.assertIsInstance(e, bezsurf.BezsurfIOError)
        self.assertIsInstance(e, bezsurf.BezsurfFileNotFoundError)
        self.assertEqual((e.errno, e.filename, e.strerror),
                         (errno.ENOENT, path, os.strerror(errno.ENOENT)))
        self.assertEqual(e.code, -9)
        self.assertIn(path, str(e))
        with self.assertRaises(FileNotFoundError) as cm:
            bezsurf.Surface([square(0)]).save(path)
        self.assertEqual(cm.exception.filename, path)

    @requires("bs_mesh_write")
    def test_directory_and_path_kinds(self):
        m = bezsurf.Surface([square(0)]).tessellate(1)
        with tempfile.TemporaryDirectory() as d:
            with self.assertRaises(IsADirectoryError) as cm:
                m.write(d, bezsurf.Format.STL)
            self.assertEqual((cm.exception.errno, cm.exception.filename), (errno.EISDIR, d))
            blocker = os.path.join(d, "file")
            open(blocker, "w").close()
            with self.assertRaises(NotADirectoryError) as cm:
                bezsurf.Surface([square(0)]).save(os.path.join(blocker, "x.bpt"))
            self.assertEqual(cm.exception.errno, errno.ENOTDIR)
            ok = os.path.join(d, "ok.bpt")
            bezsurf.Surface([square(0)]).save(bytes(ok, "utf-8"))   # bytes paths work too
            self.assertEqual(len(bezsurf.Surface.load(ok)), 1)

    @requires("bs_mesh_write")
    def test_nul_in_paths(self):
        # refused as open() refuses it, nothing written under the name cut at the NUL
        m = bezsurf.Surface([square(0)]).tessellate(1)
        with tempfile.TemporaryDirectory() as d:
            cut = os.path.join(d, "a")
            surface = bezsurf.Surface([square(0)])
            for save in (surface.save, m.write, bezsurf.Surface.load,
                         lambda p: surface.save(bytes(p, "utf-8"))):
                with self.assertRaisesRegex(ValueError, "null byte"):
                    save(cut + "\0b.bpt")
                self.assertFalse(os.path.exists(cut))

    @unittest.skipIf(os.geteuid() == 0, "root reads and writes anything")
    def test_permission(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "locked.bpt")
            bezsurf.Surface([square(0)]).save(path)
            os.chmod(path, 0)
            with self.assertRaises(PermissionError) as cm:
                bezsurf.Surface.load(path)
            self.assertEqual((cm.exception.errno, cm.exception.filename), (errno.EACCES, path))

    def test_parse_error_names_the_file(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "bad.bpt")
            with open(path, "w") as f:
                f.write("1\n3 3\n0 0 0\n")
            with self.assertRaises(bezsurf.ParseError) as cm:
                bezsurf.Surface.load(path)
            self.assertEqual(cm.exception.filename, path)
            self.assertIsNotNone(cm.exception.line)


class SliceTest(PlainTestCase):
    def test_slices_are_new_surfaces_of_copies(self):
        teapot = bezsurf.Surface.builtin("teapot")
        n = len(teapot)
        for sl in (slice(0, 2), slice(None, None, -1), slice(5, None, 7), slice(-3, None),
                   slice(40, 50), slice(None)):
            with self.subTest(sl=sl):
                part = teapot[sl]
                self.assertIsInstance(part, bezsurf.Surface)
                idx = range(n)[sl]
                self.assertEqual(len(part), len(idx))
                self.assertEqual([p.ctrl for p in part], [teapot[i].ctrl for i in idx])
        first = teapot[0:2]
        teapot.close()
        self.assertEqual(len(first), 2)          # independent of the surface it came from
        self.assertEqual(first[1].degree, (3, 3))
        with self.assertRaises(IndexError):
            first[2]
        self.assertEqual(first[-1].ctrl, first[1].ctrl)


class EnumTest(PlainTestCase):
    def test_values_match_the_library(self):
        self.assertEqual([int(d) for d in bezsurf.Direction], [0, 1])
        self.assertEqual([(k.name, int(k)) for k in bezsurf.NormalKind],
                         [("REGULAR", 0), ("LIMIT", 1), ("UNDEFINED", 2)])
        self.assertEqual([(f.name, int(f)) for f in bezsurf.Format],
                         [("OBJ", 0), ("PLY", 1), ("PLY_ASCII", 2), ("STL", 3)])
        self.assertEqual([(s.name, int(s)) for s in bezsurf.Side],
                         [("V0", 0), ("U1", 1), ("V1", 2), ("U0", 3)])
        self.assertIs(bezsurf.DIR_V, bezsurf.Direction.V)
        self.assertIs(bezsurf.NORMAL_LIMIT, bezsurf.NormalKind.LIMIT)
        self.assertIs(bezsurf.SIDE_U0, bezsurf.Side.U0)

    def test_enums_are_accepted_and_returned(self):
        p = bezsurf.Patch(NET)
        for d, name in ((bezsurf.Direction.U, "u"), (bezsurf.Direction.V, "V")):
            a = p.split(d, 0.5)
            b = p.split(name, 0.5)
            self.assertEqual([q.ctrl for q in a], [q.ctrl for q in b])
        m = bezsurf.Surface([square(0)]).tessellate(1)
        self.assertEqual(m.to_bytes(bezsurf.Format.PLY_ASCII), m.to_bytes("ply_ascii"))
        self.assertEqual(m.to_bytes(bezsurf.Format.STL), m.to_bytes(3))
        fan = bezsurf.Patch([[[0, 0, 0], [0, 0, 0]], [[1, 0, 0], [1, 1, 0]]])
        kinds = fan.eval_normal([0.0, 0.5], [0.5, 0.5]).kind
        self.assertEqual(list(kinds), [bezsurf.NormalKind.LIMIT, bezsurf.NormalKind.REGULAR])
        if not HAVE_NUMPY:
            self.assertIs(kinds[0], bezsurf.NormalKind.LIMIT)
        edges = bezsurf.Surface.builtin("teapot").continuity()
        self.assertTrue(all(isinstance(e.side_a, bezsurf.Side) for e in edges.edges))
        self.assertTrue(all(isinstance(o.side, bezsurf.Side) for o in edges.open_edges))


class ResultTypeTest(unittest.TestCase):
    """One rule: numpy arrays whenever numpy is importable, plain lists otherwise, whatever the
    type of the inputs."""

    def results(self):
        p = bilinear()
        s = bezsurf.Surface([p])
        m = s.tessellate(2)
        ev = p.eval([0.5], [0.5], derivatives=True, normals=True)
        return [p.eval([0.5], [0.5]), p.eval((0.5,), (0.5,)), p.eval_grid([0.5], [0.5]),
                p.eval_deriv(1, 0, [0.5], [0.5]), ev.position, ev.du, ev.normal, ev.kind,
                s.eval([0], [0.5], [0.5]), p.isocurve("u", 0.5).points, m.positions(),
                m.normals(), m.uv(), m.corner_uv(), m.triangles(), m.patch_ids(),
                m.triangle_patch_ids()]

    def test_rule(self):
        want = np.ndarray if HAVE_NUMPY else list
        self.assertEqual(bezsurf.have_numpy(), HAVE_NUMPY)
        for r in self.results():
            self.assertIsInstance(r, want)

    @needs_numpy
    def test_float_results_are_fortran_ordered(self):
        for i, r in enumerate(self.results()):
            if r.dtype == np.float64 and i != 9:    # (isocurve points are a packed net)
                self.assertTrue(r.flags.f_contiguous, r.flags)
                self.assertEqual(r.strides[0], 8)        # each coordinate packed
        g = bilinear().eval_grid(np.linspace(0, 1, 5), np.linspace(0, 1, 3))
        view = g.reshape(5, 3, 3)
        self.assertTrue(np.shares_memory(view, g))           # the grid reshape is still a view
        self.assertEqual(tuple(view[4, 2]), (1.0, 1.0, 1.0))


@needs_numpy
class OverlapTest(unittest.TestCase):
    def test_overlapping_outputs_are_rejected(self):
        p = bilinear()
        u = np.array([0.25, 0.5, 0.75])
        v = np.array([0.5, 0.5, 0.5])
        buf = np.full((3, 9), -1.0)
        with self.assertRaises(ValueError) as cm:
            p.eval(u, v, derivatives=True, out=buf[:, 0:3], du_out=buf[:, 2:5],
                   dv_out=buf[:, 6:9])
        self.assertIn("out overlaps du_out", str(cm.exception))
        self.assertTrue(np.all(buf == -1.0))                  # nothing written
        with self.assertRaises(ValueError):
            p.eval(u, v, normals=True, out=buf[:, 0:3], normal_out=buf[:, 0:3])
        grid = np.zeros((9, 3))
        with self.assertRaises(ValueError):
            p.eval_grid(u, v, derivatives=True, du_out=grid, dv_out=grid)
        with self.assertRaises(ValueError):
            p.eval_normal(u, v, normal_out=buf[:, 0:3], kind_out=buf[:, 0:3].view(np.uint8)[:, 0])
        uv = np.zeros((3, 4))
        uv[:, 0], uv[:, 1] = u, v
        with self.assertRaises(ValueError) as cm:               # an output over an input
            p.eval(uv[:, 0], uv[:, 1], out=uv[:, 1:4])
        self.assertIn("out overlaps v", str(cm.exception))
        out = np.zeros((3, 3))
        # interleaved but disjoint columns of one buffer are fine
        r = p.eval(u, v, derivatives=True, out=buf[:, 0:3], du_out=buf[:, 3:6],
                   dv_out=buf[:, 6:9])
        self.assertTrue(np.array_equal(buf[:, 0:3], r.position))
        self.assertTrue(np.array_equal(buf[:, 3], [1.0, 1.0, 1.0]))
        kinds = np.zeros(3, np.uint8)
        p.eval_normal(u, v, out=out, normal_out=buf[:, 0:3], kind_out=kinds)
        self.assertTrue(np.all(kinds == bezsurf.NormalKind.REGULAR))


if __name__ == "__main__":
    unittest.main()
