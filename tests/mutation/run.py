#!/usr/bin/env python3
"""Mutation check: does the test suite notice small, deliberate bugs in lib/?

Each mutation of tests/mutation/mutations.txt replaces one unique snippet of one file. The tree is
copied once to a scratch folder (default build-mutation/, kept between runs so that builds are
incremental); for each mutation the snippet is replaced there, the library, tool and tests are
rebuilt, the tests of the mutated file's layer run (then, if they all pass, the other unit and
tool tests), and the file is restored. A mutation is killed when the build or a test fails.
Mutations marked equivalent in the list are not counted against the kill rate.

usage: run.py [--scratch DIR] [--part K/N | --rotate N] [--budget SECONDS] [--only ID,...]
              [--check] [--jobs J] [--no-baseline]
  --part K/N     only the mutations whose index mod N is K (0-based index in the list)
  --rotate N     --part D/N with D the day of the year mod N (a different part each day)
  --budget S     start no mutation after S seconds (setup included); the report says how many ran
  --check        only check that every snippet occurs exactly once in its file
Exit status: 0 when the kill rate of the mutations run is at least --min-rate (default 0.9),
1 otherwise or when a snippet is stale, 2 for a bad command line or a failing baseline.
"""
import argparse
import datetime
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LIST = os.path.join(ROOT, "tests", "mutation", "mutations.txt")
FAST = "unit|cli"  # the label set a surviving mutation meets in the end


def parse_list(path):
    """Mutations as dicts: id, file, old, new, equivalent (the reason, or None)."""
    out = []
    with open(path, encoding="utf-8") as f:
        for no, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            fields = line.split("\t")
            if len(fields) not in (4, 5):
                sys.exit(f"{path}:{no}: expected 4 or 5 tab-separated fields, got {len(fields)}")
            eq = fields[4] if len(fields) == 5 else None
            if eq is not None and not eq.startswith("equivalent: "):
                sys.exit(f"{path}:{no}: the fifth field must start with 'equivalent: '")
            nl = lambda x: x.replace("\\n", "\n")  # a line break inside a snippet
            out.append({"id": fields[0], "file": fields[1], "old": nl(fields[2]), "new": nl(fields[3]),
                        "equivalent": eq[len("equivalent: "):] if eq else None})
    return out


def tracked_files():
    try:
        names = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], check=True,
                               capture_output=True).stdout.decode().split("\0")
        return [n for n in names if n and os.path.isfile(os.path.join(ROOT, n))]
    except (OSError, subprocess.CalledProcessError):
        skip = ("build", ".git")
        return [os.path.relpath(os.path.join(d, f), ROOT)
                for d, dirs, files in os.walk(ROOT)
                if not os.path.relpath(d, ROOT).split(os.sep)[0].startswith(skip)
                for f in files]


def sync_tree(src):
    """Copy the tree into src, rewriting only the files whose bytes differ (builds stay incremental)."""
    for name in tracked_files():
        a, b = os.path.join(ROOT, name), os.path.join(src, name)
        with open(a, "rb") as f:
            data = f.read()
        if os.path.exists(b):
            with open(b, "rb") as f:
                if f.read() == data:
                    continue
        os.makedirs(os.path.dirname(b), exist_ok=True)
        shutil.copyfile(a, b)  # a new time stamp, so that make rebuilds what it feeds


def run(cmd, timeout=None):
    try:
        return subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        return 124


def layer_of(path):
    parts = path.split("/")
    return parts[1] if len(parts) > 2 and parts[0] == "lib" else None


def tests_pass(bld, label, jobs, skip=None):
    """ctest on one label set (less the label skip), stopping at the first failure; True when all
    pass. Without its record of test times ctest runs the tests in the order they are declared
    (small, fast ones first) instead of the slowest first, so a failure comes sooner."""
    cost = os.path.join(bld, "Testing", "Temporary", "CTestCostData.txt")
    if os.path.exists(cost):
        os.remove(cost)
    base = ["ctest", "--test-dir", bld, "--stop-on-failure", "--timeout", "60", "-j", str(jobs)]
    return run(base + ["-L", label] + (["-LE", skip] if skip else [])) == 0


def check_snippets(muts, tree):
    stale = []
    for m in muts:
        with open(os.path.join(tree, m["file"]), encoding="utf-8") as f:
            n = f.read().count(m["old"])
        if n != 1:
            stale.append((m["id"], m["file"], n))
    return stale


def say(*args):
    print(*args, flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scratch", default=os.path.join(ROOT, "build-mutation"))
    ap.add_argument("--list", default=LIST)
    ap.add_argument("--part")
    ap.add_argument("--rotate", type=int)
    ap.add_argument("--budget", type=float)
    ap.add_argument("--only")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--min-rate", type=float, default=0.9)
    ap.add_argument("--no-baseline", action="store_true",
                    help="skip the tests of the unmutated tree (when they just passed elsewhere)")
    a = ap.parse_args()
    start = time.monotonic()
    muts = parse_list(a.list)
    total = len(muts)
    if a.check:
        stale = check_snippets(muts, ROOT)
        for s in stale:
            say(f"{s[0]}: the snippet occurs {s[2]} times in {s[1]}, not once")
        say(f"{total} mutations, {total - len(stale)} with a unique snippet")
        return 1 if stale else 0
    index = list(range(total))
    if a.rotate:
        day = datetime.date.today().timetuple().tm_yday
        a.part = f"{day % a.rotate}/{a.rotate}"
    if a.part:
        k, n = (int(x) for x in a.part.split("/"))
        index = [i for i in index if i % n == k]
    if a.only:
        wanted = set(a.only.split(","))
        index = [i for i in index if muts[i]["id"] in wanted]
    src, bld = os.path.join(a.scratch, "src"), os.path.join(a.scratch, "build")
    os.makedirs(src, exist_ok=True)
    sync_tree(src)
    # configured and generated (a configure step that failed leaves a cache but no test files)
    if not os.path.exists(os.path.join(bld, "CTestTestfile.cmake")):
        if run(["cmake", "-S", src, "-B", bld, "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                "-DBS_CPU_DISPATCH=OFF", "-DBS_BUILD_EXAMPLES=OFF", "-DBS_BUILD_BENCH=OFF"]) != 0:
            say("mutation: cannot configure the scratch build")
            return 2
    build = ["cmake", "--build", bld, "-j", str(a.jobs)]
    # Tests and tool load the shared library: a mutation needs only the library rebuilt (the
    # allocation-failure test, which links the sources, then runs the unmutated code).
    rebuild = build + ["--target", "bezsurf"]
    if run(build) != 0 or not (a.no_baseline or tests_pass(bld, FAST, a.jobs)):
        say("mutation: the unmutated tree does not build or pass its tests")
        return 2
    say(f"mutation: setup {time.monotonic() - start:.0f} s; {len(index)} of {total} mutations to run")
    killed, survived, equivalent, stale, ran = [], [], [], [], 0
    for i in index:
        if a.budget is not None and time.monotonic() - start > a.budget:
            break
        m = muts[i]
        path = os.path.join(src, m["file"])
        with open(path, encoding="utf-8") as f:
            original = f.read()
        if original.count(m["old"]) != 1:
            stale.append(m["id"])
            continue
        ran += 1
        t0 = time.monotonic()
        try:
            with open(path, "w", encoding="utf-8") as f:
                f.write(original.replace(m["old"], m["new"]))
            layer = layer_of(m["file"])
            dead = run(rebuild) != 0 or (layer is not None and not tests_pass(bld, layer, a.jobs)) \
                or not tests_pass(bld, FAST, a.jobs, layer)
        finally:
            with open(path, "w", encoding="utf-8") as f:
                f.write(original)
        verdict = "killed" if dead else "equivalent" if m["equivalent"] else "SURVIVED"
        (killed if dead else equivalent if m["equivalent"] else survived).append(m["id"])
        say(f"  {m['id']:<6} {verdict:<10} {time.monotonic() - t0:5.0f} s  {m['file']}")
    run(rebuild)  # leave the scratch library matching the tree
    counted = len(killed) + len(survived)
    rate = len(killed) / counted if counted else 1.0
    say(f"mutation: {ran} run, {len(killed)} killed, {len(survived)} survived, "
          f"{len(equivalent)} equivalent (not counted): kill rate {100 * rate:.1f}% "
          f"in {time.monotonic() - start:.0f} s")
    for s in survived:
        say(f"  survivor {s}")
    for s in stale:
        say(f"  stale snippet {s} (the file changed: update the list)")
    return 0 if rate >= a.min_rate and not stale else 1


if __name__ == "__main__":
    sys.exit(main())
