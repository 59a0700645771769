"""Type-check the package with ``mypy --strict``: ``python3 typecheck.py``.

Checks the package and tests/typing_usage.py (typical calls whose result types are asserted).
Exit status 0 when clean, 1 with mypy's report otherwise, 77 (a skip for CTest) when mypy is not
installed for this interpreter (Debian: ``apt-get install python3-mypy``).
"""

import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE_DIR = os.path.dirname(HERE)


def main() -> int:
    try:
        from mypy import api
    except ImportError:
        print("SKIP: mypy is not installed for this interpreter")
        return 77
    with tempfile.TemporaryDirectory() as cache:
        out, err, status = api.run(["--strict", "--cache-dir", cache, "--no-error-summary",
                                    os.path.join(PACKAGE_DIR, "bezsurf"),
                                    os.path.join(HERE, "typing_usage.py")])
    print(out + err, end="")
    if status == 0:
        print("mypy --strict: no issues")
    return 0 if status == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
