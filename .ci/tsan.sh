#!/usr/bin/env bash
# The threads test under ThreadSanitizer: the library and the test built with -fsanitize=thread in
# their own build tree; any report fails (halt_on_error, exit code 66).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TSAN_BUILD:-build-tsan}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DBS_SANITIZE=thread -DBS_BUILD_EXAMPLES=OFF \
  -DBS_BUILD_BENCH=OFF -DBS_BUILD_TOOLS=OFF >/dev/null
cmake --build "$build" -j2 --target test_threads
TSAN_OPTIONS="halt_on_error=1 exitcode=66 report_signal_unsafe=1" "$build/tests/test_threads"
echo "== ThreadSanitizer: 0 reports"
