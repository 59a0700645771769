#!/bin/sh
# The evaluation loops are compiled for AVX-512, AVX2 and SSE2 and one is picked at load time
# (lib/core/kernels.h, BSI_HOT). Every version must give the same bits: compare the digest of all
# results that tests/test_determinism prints
#   - from the test build as this CPU runs it (its widest instruction set),
#   - from the same binary under valgrind, which hides AVX-512 (so the AVX2 versions run),
#   - from a build with -DBS_CPU_DISPATCH=OFF (SSE2 only),
#   - from the Debug build of the asan preset (no vectorisation at all), when it exists.
#   .ci/isa.sh [build]
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
base=build-baseline
cmake -S . -B "$base" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBS_CPU_DISPATCH=OFF \
  -DBS_BUILD_EXAMPLES=OFF -DBS_BUILD_TOOLS=OFF -DBS_BUILD_BENCH=OFF >/dev/null
cmake --build "$base" -j2 --target test_determinism >/dev/null
digest() { "$@" | grep '^result digest'; }
ref=$(digest "$build/tests/test_determinism")
isa=SSE2
grep -qw avx2 /proc/cpuinfo && isa=AVX2
grep -qw avx512f /proc/cpuinfo && isa=AVX-512
echo "dispatched (this CPU: $isa): $ref"
fail=0
check() {
  got=$(digest "$@")
  echo "$label: $got"
  [ "$got" = "$ref" ] || fail=1
}
label="no dispatch (SSE2)" check "$base/tests/test_determinism"
label="valgrind (AVX2 at most)" check valgrind -q --error-exitcode=3 "$build/tests/test_determinism"
if [ -x build-asan/tests/test_determinism ]; then
  label="asan preset (Debug)" check build-asan/tests/test_determinism
fi
[ "$fail" = 0 ] || { echo "results differ between instruction sets" >&2; exit 1; }
echo "same bits on every instruction set"
