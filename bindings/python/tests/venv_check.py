"""Install the package as a new user would and run the README's Python example.

``python3 venv_check.py [SOURCE_DIR]``: makes a fresh virtual environment, installs
``bindings/python`` with a plain ``pip install`` (build isolation on, as the docs say; nothing is
downloaded), then runs
the Python example of README.md with that environment's interpreter from an unrelated directory,
with BEZSURF_LIBRARY, LD_LIBRARY_PATH and PYTHONPATH removed from the environment. Then it checks
that the library came from the installed package, that the wheel's metadata came from
pyproject.toml, and that ``--no-build-isolation`` installs work too.

Exit status 0 on success, 1 on failure, 77 when venv or pip is unavailable (a skip for CTest).
"""

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SKIP = 77
HERE = Path(__file__).resolve().parent
PACKAGE_DIR = HERE.parent
SOURCE_DIR = Path(sys.argv[1]) if len(sys.argv) > 1 else PACKAGE_DIR.parents[1]


def readme_example() -> str:
    text = (SOURCE_DIR / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Python"):]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def clean_env() -> dict:
    env = {k: v for k, v in os.environ.items()
           if k not in ("BEZSURF_LIBRARY", "LD_LIBRARY_PATH", "PYTHONPATH", "PYTHONHOME",
                        "BEZSURF_BUNDLE", "PIP_CONFIG_FILE")}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return env


def run(cmd, **kw):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       env=clean_env(), **kw)
    return r


def fail(what: str, r=None) -> int:
    print(f"FAIL: {what}")
    if r is not None:
        print(r.stdout)
    return 1


def main() -> int:
    with tempfile.TemporaryDirectory(prefix="bezsurf-venv-") as tmp:
        venv = Path(tmp) / "venv"
        r = run([sys.executable, "-m", "venv", str(venv)])
        if r.returncode != 0:
            print(f"SKIP: cannot make a virtual environment with pip:\n{r.stdout}")
            return SKIP
        py = str(venv / "bin" / "python")
        if run([py, "-m", "pip", "--version"]).returncode != 0:
            print("SKIP: the virtual environment has no pip")
            return SKIP
        pip = [py, "-m", "pip", "install", "--no-cache-dir"]
        elsewhere = Path(tmp) / "elsewhere"
        elsewhere.mkdir()

        # exactly as the README says (no index needed: nothing to download)
        r = run(pip + [str(PACKAGE_DIR)], cwd=elsewhere)
        if r.returncode != 0:
            return fail("pip install", r)

        r = run([py, "-c", readme_example()], cwd=elsewhere)
        print(r.stdout, end="")
        if r.returncode != 0 or r.stdout.split() != ["2.125", "2.25", "1.625"]:
            return fail("the README example", r)

        probe = ("import bezsurf, importlib.metadata as m; print(bezsurf.library_path()); "
                 "print(bezsurf.__file__); print(m.distribution('bezsurf').read_text('METADATA'))")
        r = run([py, "-c", probe], cwd=elsewhere)
        if r.returncode != 0:
            return fail("import", r)
        lib, module, meta = r.stdout.split("\n", 2)
        if Path(lib).parent != Path(module).parent or not lib.endswith("libbezsurf.so.1"):
            return fail(f"the library was not the package's own: {lib}")
        for field in ("License: MIT", "Classifier: Typing :: Typed", "Requires-Python: >=3.8",
                      "Description-Content-Type: text/markdown", "# bezsurf (Python)"):
            if field not in meta:
                return fail(f"metadata lacks {field!r}", r)

        r = run(pip + ["--no-index", "--no-build-isolation", "--force-reinstall", str(PACKAGE_DIR)],
                cwd=elsewhere)
        if r.returncode != 0:
            return fail("pip install --no-build-isolation", r)
        r = run([py, "-c", readme_example()], cwd=elsewhere)
        if r.returncode != 0 or r.stdout.split() != ["2.125", "2.25", "1.625"]:
            return fail("the README example after --no-build-isolation", r)
    print("OK: pip install into a fresh venv, README example without environment variables")
    return 0


if __name__ == "__main__":
    sys.exit(main())
