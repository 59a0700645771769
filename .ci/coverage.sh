#!/usr/bin/env bash
# Line and branch coverage of lib/ by the unit tests (gcc --coverage, gcovr), printed as a summary
# and written to build-cov/coverage.txt. Optional thresholds: COV_MIN_LINES, COV_MIN_BRANCHES (percent).
# Only the library's sources are instrumented and unoptimised (BS_COVERAGE); the tests are
# optimised, so that the long sweeps of the suite run at their usual speed.
# Built without CPU dispatch: the copies of the evaluation loops for instruction sets this CPU does
# not pick would count as untested branches (.ci/isa.sh checks that every copy gives the same bits).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${COV_BUILD:-build-cov}
rm -rf "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBS_COVERAGE=ON \
  -DBS_CPU_DISPATCH=OFF -DBS_BUILD_EXAMPLES=OFF -DBS_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j2 >/dev/null
ctest --test-dir "$build" -L 'unit|cli' -j2 --output-on-failure >/dev/null
gcovr --root . --filter 'lib/' --exclude-unreachable-branches "$build" --txt "$build/coverage.txt" \
  --print-summary | tee "$build/coverage-summary.txt"
lines=$(sed -n 's/^lines: *\([0-9.]*\)%.*/\1/p' "$build/coverage-summary.txt")
branches=$(sed -n 's/^branches: *\([0-9.]*\)%.*/\1/p' "$build/coverage-summary.txt")
awk -v l="$lines" -v b="$branches" -v ml="${COV_MIN_LINES:-0}" -v mb="${COV_MIN_BRANCHES:-0}" 'BEGIN {
  if (l + 0 < ml + 0 || b + 0 < mb + 0) { printf "coverage below the floor (%s%% lines, %s%% branches)\n", ml, mb; exit 1 } }'
