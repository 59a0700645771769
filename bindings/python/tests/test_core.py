"""Loading rules, version checks, status strings and the declaration table."""

import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import bezsurf
from bezsurf import _lib

from .support import SOURCE_DIR

PACKAGE_DIR = str(Path(bezsurf.__file__).resolve().parents[1])
LIBRARY = os.environ.get("BEZSURF_LIBRARY", "")


def run_import(env_changes, code="import bezsurf; print(bezsurf.version())"):
    env = {k: v for k, v in os.environ.items() if k not in ("BEZSURF_LIBRARY", "LD_LIBRARY_PATH")}
    env["PYTHONPATH"] = PACKAGE_DIR
    env.update(env_changes)
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          cwd=tempfile.gettempdir())


class VersionTest(unittest.TestCase):
    def test_version_matches_number(self):
        n = bezsurf.version_number()
        self.assertEqual(n // 10000, 1)
        self.assertEqual(bezsurf.version(), f"{n // 10000}.{n // 100 % 100}.{n % 100}")

    def test_status_strings(self):
        self.assertEqual(bezsurf.status_string(0), "success")
        self.assertEqual(bezsurf.status_string(-4), "dimension out of range")
        self.assertEqual(bezsurf.status_string(12345), "unknown status")

    def test_error_carries_code_and_library_text(self):
        with self.assertRaises(bezsurf.DimensionError) as cm:
            bezsurf.Patch([[[]]])
        e = cm.exception
        self.assertEqual(e.code, -4)
        self.assertEqual(e.message, bezsurf.status_string(-4))
        self.assertEqual(e.function, "bs_patch_create")
        self.assertIsInstance(e, ValueError)
        self.assertIsInstance(e, bezsurf.BezsurfError)

    def test_error_classes(self):
        self.assertTrue(issubclass(bezsurf.NoMemoryError, MemoryError))
        self.assertTrue(issubclass(bezsurf.BezsurfIOError, OSError))
        for cls in (bezsurf.InvalidArgumentError, bezsurf.DegreeError, bezsurf.DimensionError,
                    bezsurf.SizeError, bezsurf.DomainError, bezsurf.NonFiniteError,
                    bezsurf.ParseError):
            self.assertTrue(issubclass(cls, ValueError), cls)
        e = bezsurf.ParseError(-8, "malformed input", "f", line=3, column=7)
        self.assertEqual((e.line, e.column), (3, 7))
        self.assertIn("line 3, column 7", str(e))


class TableTest(unittest.TestCase):
    """Every export of the version script has a binding, and every binding resolves."""

    def exports(self):
        text = (SOURCE_DIR / "lib" / "libbezsurf.map").read_text()
        text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
        return set(re.findall(r"\b(bs_\w+)\s*;", text))

    def test_every_export_is_bound(self):
        bound = {name for name, _, _ in _lib.FUNCTIONS} | set(_lib.NOT_BOUND)
        self.assertEqual(sorted(self.exports() - bound), [])

    def test_every_exported_binding_resolves(self):
        exports = self.exports()
        self.assertEqual([n for n in _lib.LIB.missing if n in exports], [])

    def test_table_names_unique(self):
        names = [name for name, _, _ in _lib.FUNCTIONS]
        self.assertEqual(len(names), len(set(names)))


@unittest.skipUnless(LIBRARY and sys.platform.startswith("linux"), "needs BEZSURF_LIBRARY on Linux")
class LoaderTest(unittest.TestCase):
    def test_explicit_path(self):
        r = run_import({"BEZSURF_LIBRARY": LIBRARY})
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.strip(), bezsurf.version())

    def test_soname_from_search_path(self):
        with tempfile.TemporaryDirectory() as d:
            shutil.copy(LIBRARY, os.path.join(d, "libbezsurf.so.1"))
            r = run_import({"LD_LIBRARY_PATH": d}, "import bezsurf; print(bezsurf.library_path())")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.strip(), "libbezsurf.so.1")

    def test_unversioned_name_is_not_used(self):
        with tempfile.TemporaryDirectory() as d:
            shutil.copy(LIBRARY, os.path.join(d, "libbezsurf.so"))
            r = run_import({"LD_LIBRARY_PATH": d})
        if r.returncode == 0:  # a libbezsurf.so.1 installed on the system was found instead
            self.skipTest("a system libbezsurf.so.1 is installed")
        self.assertIn("ImportError", r.stderr)
        self.assertIn("libbezsurf.so.1", r.stderr)

    def test_package_directory_before_search_path(self):
        with tempfile.TemporaryDirectory() as d:
            shutil.copytree(os.path.join(PACKAGE_DIR, "bezsurf"), os.path.join(d, "bezsurf"))
            bundled = os.path.join(d, "bezsurf", "libbezsurf.so.1")
            shutil.copy(LIBRARY, bundled)
            r = run_import({"PYTHONPATH": d, "LD_LIBRARY_PATH": os.path.dirname(LIBRARY)},
                           "import bezsurf; print(bezsurf.library_path())")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.strip(), bundled)

    def test_search_order(self):
        saved = os.environ.pop("BEZSURF_LIBRARY", None), sys.prefix
        try:
            sys.prefix = "/opt/venv"
            paths = _lib.search_path()
            os.environ["BEZSURF_LIBRARY"] = "/x/libother.so"
            self.assertEqual(_lib.search_path(), ["/x/libother.so"])
        finally:
            os.environ.pop("BEZSURF_LIBRARY", None)
            if saved[0] is not None:
                os.environ["BEZSURF_LIBRARY"] = saved[0]
            sys.prefix = saved[1]
        package = os.path.dirname(os.path.abspath(bezsurf.__file__))
        self.assertEqual(paths[0], os.path.join(package, "libbezsurf.so.1"))
        self.assertEqual(paths[1], "/opt/venv/lib/libbezsurf.so.1")
        self.assertLess(paths.index("/opt/venv/lib/libbezsurf.so.1"),
                        paths.index("/usr/local/lib/libbezsurf.so.1"))
        self.assertEqual(paths[-1], "libbezsurf.so.1")
        self.assertTrue(all(p.endswith("libbezsurf.so.1") for p in paths), paths)

    def test_missing_library(self):
        r = run_import({"BEZSURF_LIBRARY": "/nonexistent/libbezsurf.so.1"})
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("ImportError", r.stderr)

    def test_other_major_version_is_refused(self):
        cc = shutil.which("cc") or shutil.which("gcc")
        if not cc:
            self.skipTest("no C compiler to build a stand-in library")
        with tempfile.TemporaryDirectory() as d:
            src = os.path.join(d, "fake.c")
            lib = os.path.join(d, "libfake.so.2")
            with open(src, "w") as f:
                f.write("unsigned bs_version_number(void) { return 20003; }\n")
            subprocess.run([cc, "-shared", "-fPIC", "-o", lib, src], check=True)
            r = run_import({"BEZSURF_LIBRARY": lib})
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("major version 2", r.stderr)


class BackendTest(unittest.TestCase):
    """The in-tree build backend takes the metadata from pyproject.toml."""

    @classmethod
    def setUpClass(cls):
        import importlib.util
        spec = importlib.util.spec_from_file_location(
            "bezsurf_build_under_test", os.path.join(PACKAGE_DIR, "_build", "bezsurf_build.py"))
        cls.backend = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(cls.backend)
        with open(os.path.join(PACKAGE_DIR, "pyproject.toml"), encoding="utf-8") as f:
            cls.pyproject = f.read()

    def test_fallback_toml_parser_agrees_with_tomllib(self):
        try:
            import tomllib
        except ImportError:
            self.skipTest("tomllib needs Python 3.11")
        self.assertEqual(self.backend.parse_toml(self.pyproject), tomllib.loads(self.pyproject))

    def test_metadata_from_pyproject(self):
        project = self.backend.parse_toml(self.pyproject)["project"]
        meta = self.backend.metadata_text()
        head, _, body = meta.partition("\n\n")
        lines = head.splitlines()
        self.assertIn(f"Version: {bezsurf.__version__}", lines)
        self.assertIn(f"Summary: {project['description']}", lines)
        self.assertIn(f"Requires-Python: {project['requires-python']}", lines)
        self.assertIn(f"License: {project['license']['text']}", lines)
        self.assertEqual([ln[len("Classifier: "):] for ln in lines if ln.startswith("Classifier: ")],
                         project["classifiers"])
        self.assertIn('Requires-Dist: numpy; extra == "numpy"', lines)
        with open(os.path.join(PACKAGE_DIR, project["readme"]), encoding="utf-8") as f:
            self.assertEqual(body, f.read())

    def test_bundle_setting(self):
        self.assertEqual(self.backend._bundle_mode({"bundle": "no"}), "no")
        with self.assertRaises(ValueError):
            self.backend._bundle_mode({"bundle": "maybe"})
        self.assertIsNone(self.backend.build_library("no"))


class InstallTest(unittest.TestCase):
    """The package installs offline with the interpreter's own pip (in-tree stdlib backend)."""

    def test_pip_install_no_build_isolation(self):
        try:
            import pip  # noqa: F401
        except ImportError:
            self.skipTest("pip is not available to this interpreter")
        with tempfile.TemporaryDirectory() as d:
            # the pure-Python wheel (bundling the library is python_install's job)
            r = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation",
                                "--no-index", "--no-cache-dir", "--disable-pip-version-check",
                                "--target", d, PACKAGE_DIR], capture_output=True, text=True,
                               env=dict(os.environ, BEZSURF_BUNDLE="no"))
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertTrue(os.path.exists(os.path.join(d, "bezsurf", "py.typed")))
            r = run_import({"PYTHONPATH": d, "BEZSURF_LIBRARY": LIBRARY},
                           "import bezsurf; print(bezsurf.__file__)")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertTrue(r.stdout.startswith(d), r.stdout)
            dist = [n for n in os.listdir(d) if n.endswith(".dist-info")]
            self.assertEqual(dist, [f"bezsurf-{bezsurf.__version__}.dist-info"])


if __name__ == "__main__":
    unittest.main()
