#!/usr/bin/env bash
# Build the libFuzzer targets with clang in their own build tree, replay the committed seed corpora,
# then fuzz each target for N seconds (default 120; the OBJ and IGES readers' targets for at most
# 60 seconds each) and print its execution count.
#   .ci/fuzz.sh [seconds]        FUZZ_BUILD=dir to choose the build tree (default build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=${1:-120}
build=${FUZZ_BUILD:-$root/build-fuzz}
CC=clang cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DBS_BUILD_EXAMPLES=OFF -DBS_BUILD_BENCH=OFF \
  -DBS_BUILD_TOOLS=OFF >/dev/null
cmake --build "$build" -j2 --target fuzz_bpt fuzz_api fuzz_obj fuzz_iges fuzz_locator
for target in fuzz_bpt fuzz_api fuzz_obj fuzz_iges fuzz_locator; do
  budget=$seconds
  case $target in fuzz_obj | fuzz_iges) if [ "$budget" -gt 60 ]; then budget=60; fi ;; esac
  seeds=$root/tests/fuzz/corpus/$target
  work=$build/corpus-$target
  mkdir -p "$work" "$build/artifacts"
  echo "== $target: replay $(ls "$seeds" | wc -l) seeds"
  "$build/tests/$target" -runs=0 "$seeds" 2>&1 | tail -n 1
  echo "== $target: fuzz ${budget}s"
  log=$build/$target.log
  # a locator input runs several certified searches on rational patches with wide weights: up to
  # some seconds under the sanitizers
  timeout=10
  case $target in fuzz_locator) timeout=30 ;; esac
  if ! "$build/tests/$target" -max_total_time="$budget" -max_len=4096 -timeout="$timeout" -rss_limit_mb=1024 \
       -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" "$work" "$seeds" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "== $target: FAILED (the input is saved in $build/artifacts)"
    exit 1
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1)
  echo "== $target: $execs executions in ${budget}s, $cov, corpus $(ls "$work" | wc -l) files"
done
