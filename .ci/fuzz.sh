#!/usr/bin/env bash
# Build the libFuzzer targets with clang in their own build tree, replay the committed seed corpora,
# then fuzz each target for N seconds (default 90; the readers' targets for at most
# READER_SECONDS, default 30, each) and print its execution count. fuzz_locator runs from a fixed
# seed (LOCATOR_SEED, default 20261204): its oracles are numerical (rays that must hit, closest
# points that must be global), and a failure must replay as it happened.
#   .ci/fuzz.sh [seconds]        FUZZ_BUILD=dir to choose the build tree (default build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=${1:-90}
build=${FUZZ_BUILD:-$root/build-fuzz}
readers="fuzz_obj fuzz_iges fuzz_iges_model fuzz_obj_model fuzz_step"
targets="fuzz_bpt fuzz_api $readers fuzz_locator"
CC=clang cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DBS_BUILD_EXAMPLES=OFF -DBS_BUILD_BENCH=OFF \
  -DBS_BUILD_TOOLS=OFF >/dev/null
# shellcheck disable=SC2086
cmake --build "$build" -j2 --target $targets
for target in $targets; do
  budget=$seconds
  cap=${READER_SECONDS:-30}
  case " $readers " in *" $target "*) if [ "$budget" -gt "$cap" ]; then budget=$cap; fi ;; esac
  max_len=4096
  case $target in fuzz_iges_model | fuzz_step) max_len=8192 ;; esac # the seeds are whole CAD parts
  # a locator input runs several certified searches on rational patches with wide weights: up to
  # some seconds under the sanitizers
  timeout=10
  case $target in fuzz_locator) timeout=30 ;; esac
  seeds=$root/tests/fuzz/corpus/$target
  work=$build/corpus-$target
  mkdir -p "$work" "$build/artifacts"
  echo "== $target: replay $(ls "$seeds" | wc -l) seeds"
  "$build/tests/$target" -runs=0 -timeout="$timeout" "$seeds" 2>&1 | tail -n 1
  seed=()
  if [ "$target" = fuzz_locator ]; then
    seed=(-seed="${LOCATOR_SEED:-20261204}")
  fi
  echo "== $target: fuzz ${budget}s"
  log=$build/$target.log
  if ! "$build/tests/$target" "${seed[@]}" -max_total_time="$budget" -max_len="$max_len" -timeout="$timeout" \
       -rss_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" "$work" "$seeds" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "== $target: FAILED (the input is saved in $build/artifacts)"
    exit 1
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1)
  echo "== $target: $execs executions in ${budget}s, $cov, corpus $(ls "$work" | wc -l) files"
done
