#!/usr/bin/env bash
# The threads tests under ThreadSanitizer: the library and the tests built with -fsanitize=thread in
# their own build tree; any report fails (halt_on_error, exit code 66). test_threads calls the library
# from several threads; the others make the library start threads of its own.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TSAN_BUILD:-build-tsan}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DBS_SANITIZE=thread -DBS_BUILD_EXAMPLES=OFF \
  -DBS_BUILD_BENCH=OFF -DBS_BUILD_TOOLS=OFF >/dev/null
tests="test_threads test_tess_threads test_surface_eval_threads test_locator_threads"
cmake --build "$build" -j2 --target $tests
for t in $tests; do
  TSAN_OPTIONS="halt_on_error=1 exitcode=66 report_signal_unsafe=1" "$build/tests/$t"
done
echo "== ThreadSanitizer: 0 reports"
