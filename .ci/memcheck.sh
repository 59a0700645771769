#!/usr/bin/env bash
# The unit test suite under valgrind memcheck: every test command of label "unit" (in the build
# tree given, default ./build) runs under valgrind, following into programs that scripts start;
# any memory error or leak fails.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ -f "$build/CTestTestfile.cmake" ] || cmake --workflow --preset test >/dev/null
ctest --test-dir "$build" -L unit --show-only=json-v1 > "$build/memcheck-tests.json"
python3 - "$build" <<'PY'
import json, os, subprocess, sys, time
build = sys.argv[1]
tests = json.load(open(os.path.join(build, "memcheck-tests.json")))["tests"]
vg = ["valgrind", "--quiet", "--error-exitcode=99", "--leak-check=full", "--show-leak-kinds=definite,indirect,possible",
      "--errors-for-leak-kinds=definite,indirect,possible", "--trace-children=yes",
      "--trace-children-skip=/bin/*,/usr/bin/*,/usr/local/bin/*,*/localedef"]
failed, t0 = [], time.time()


def run_one(t):
    """One test under valgrind: (name, ok, seconds, note, output)."""
    props = {p["name"]: p["value"] for p in t.get("properties", [])}
    env = dict(os.environ)
    env["BS_TEST_QUICK"] = "1"  # the slowest tests check a smaller sample (tests/support/harness.h)
    for kv in props.get("ENVIRONMENT", []):
        k, _, v = kv.partition("=")
        env[k] = v
    cwd = props.get("WORKING_DIRECTORY", os.path.dirname(t["command"][0]) if os.path.isabs(t["command"][0]) else build)
    start = time.time()
    r = subprocess.run(vg + t["command"], cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    skip = props.get("SKIP_RETURN_CODE")
    # valgrind exits 99 on a memory error or leak. A test's own failed checks are not memcheck's
    # verdict (valgrind runs long double at double precision, which accuracy tests notice); the
    # ordinary test run judges those.
    ok = r.returncode != 99
    note = "" if r.returncode == 0 or (skip is not None and r.returncode == int(skip)) else \
        f" (test exit {r.returncode} under valgrind: no memory error)"
    return t["name"], ok, time.time() - start, note, r.stdout


# valgrind runs one thread of its own per process: the tests run two at a time, one per core
from concurrent.futures import ThreadPoolExecutor
with ThreadPoolExecutor(max_workers=int(os.environ.get("MEMCHECK_JOBS", "2"))) as pool:
    for name, ok, secs, note, out in pool.map(run_one, tests):
        print(f"{'ok  ' if ok else 'FAIL'} {name:<28} {secs:6.1f}s{note}", flush=True)
        if not ok:
            failed.append(name)
            print(out[-4000:])
print(f"memcheck: {len(tests) - len(failed)}/{len(tests)} unit tests with 0 errors and 0 leaks "
      f"({time.time() - t0:.0f}s)")
sys.exit(1 if failed else 0)
PY
