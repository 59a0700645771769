"""examples/python/eval_demo.py runs and prints what the C example examples/eval_demo.c prints."""

import os
import subprocess
import sys
import unittest
from pathlib import Path

import bezsurf

from .support import SOURCE_DIR

DEMO = SOURCE_DIR / "examples" / "python" / "eval_demo.py"
C_DEMO = os.environ.get("BEZSURF_C_EVAL_DEMO")


class ExampleTest(unittest.TestCase):
    def run_demo(self):
        env = dict(os.environ, PYTHONPATH=str(Path(bezsurf.__file__).resolve().parents[1]))
        r = subprocess.run([sys.executable, str(DEMO)], capture_output=True, text=True, env=env)
        self.assertEqual(r.returncode, 0, r.stderr)
        return r.stdout

    def test_demo_output(self):
        out = self.run_demo().splitlines()
        self.assertEqual(len(out), 11)
        # the apex rows take the limit rule, with the normal (0, 0, 1)
        self.assertTrue(out[2].endswith(" 0.00000  0.00000  1.00000  limit"), out[2])
        self.assertEqual(out[8].split(), ["limit"] * 3)

    @unittest.skipUnless(C_DEMO and os.path.exists(C_DEMO), "C example not built")
    def test_same_output_as_c_example(self):
        c = subprocess.run([C_DEMO], capture_output=True, text=True, check=True).stdout
        self.assertEqual(self.run_demo(), c)


if __name__ == "__main__":
    unittest.main()
