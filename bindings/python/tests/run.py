"""Run the binding tests: ``python run.py [--no-numpy]``.

``--no-numpy`` hides numpy from the binding and the tests, so that the pure-Python paths are
exercised even by an interpreter that has numpy installed.
"""

import os
import sys
import unittest

if __name__ == "__main__":
    if "--no-numpy" in sys.argv:
        sys.argv.remove("--no-numpy")
        sys.modules["numpy"] = None  # type: ignore[assignment]  # makes `import numpy` fail
    here = os.path.dirname(os.path.abspath(__file__))
    top = os.path.dirname(here)
    sys.path.insert(0, top)
    suite = unittest.defaultTestLoader.discover(here, top_level_dir=top)
    result = unittest.TextTestRunner(verbosity=2).run(suite)
    sys.exit(0 if result.wasSuccessful() else 1)
