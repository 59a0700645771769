#!/bin/sh
# Instructions per evaluated point, counted by callgrind (stable on a loaded machine, unlike seconds).
# Only the instructions inside the measured function (and what it calls) are counted.
# Usage: bench/callgrind.sh [build dir] [G]
set -eu
build=${1:-build}
g=${2:-64}
bench="$build/bench/bench_eval"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
points=$((32 * g * g))
printf '%-10s %-11s %12s\n' method workload "instr/point"
for w in pos pos+du+dv pos+normal; do
  for m in store naive grid scattered store32 grid32; do
    case "$m" in
      store) fn="store_only.*" ;; # the clone the CPU dispatch picked
      store32) fn="store_only_f32*" ;;
      grid32) fn=bs_patch_eval_grid_f32 ;;
      naive) fn=naive_grid ;;
      grid) fn=bs_patch_eval_grid ;;
      scattered) if [ "$w" = pos+normal ]; then fn=bs_patch_eval_normal; else fn=bs_patch_eval; fi ;;
    esac
    valgrind --tool=callgrind --callgrind-out-file="$tmp/out" --toggle-collect="$fn" \
      "$bench" --once "$m" "$w" "$g" >/dev/null 2>"$tmp/log"
    ir=$(sed -n 's/^totals: *\([0-9]*\).*/\1/p' "$tmp/out")
    [ -n "$ir" ] || ir=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p' "$tmp/out")
    awk -v m="$m" -v w="$w" -v ir="$ir" -v n="$points" 'BEGIN { printf "%-10s %-11s %12.1f\n", m, w, ir / n }'
  done
done
