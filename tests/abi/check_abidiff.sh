#!/bin/sh
# Compare the built library with the committed ABI baseline (abi/libbezsurf-RELEASE.abi) using abidiff.
# Fails when an existing function or variable was removed or changed, or when a symbol was added to
# a version node that the baseline already has; symbols in a new version node are fine.
# Exit 77 (skipped) when abidiff is not installed.
#   check_abidiff.sh LIBRARY BASELINE INCLUDE_DIR...
set -u
lib=$1
base=$2
shift 2
command -v abidiff >/dev/null 2>&1 || { echo "abidiff not installed: skipped"; exit 77; }
# abidiff exits 0 on an unreadable baseline: check it first
if command -v abilint >/dev/null 2>&1 && ! abilint "$base" >/dev/null; then
  echo "baseline $base cannot be read"
  exit 1
fi
headers=""
for d in "$@"; do headers="$headers --headers-dir2 $d"; done
# shellcheck disable=SC2086
report=$(abidiff --no-show-locs $headers "$base" "$lib")
status=$?
echo "$report"
if [ $((status & 3)) -ne 0 ]; then
  echo "abidiff failed to run (status $status)"
  exit 1
fi
fail=0
if echo "$report" | grep -Eq '(Functions|Variables) changes summary: ([1-9][0-9]* Removed|[0-9]+ Removed, [1-9])'; then
  echo "ABI break: an existing function or variable was removed or changed"
  fail=1
fi
if echo "$report" | grep -Eq 'Function symbols changes summary: [1-9][0-9]* Removed|Variable symbols changes summary: [1-9][0-9]* Removed'; then
  echo "ABI break: a symbol was removed"
  fail=1
fi
# versions the baseline already defines may not grow
for v in $(grep -o 'version=.LIBBEZSURF_[0-9.]*' "$base" | sed 's/.*=.//' | sort -u); do
  if echo "$report" | grep -A 1000 -E 'Added (function|variable)' | grep -q "@@$v}"; then
    echo "symbols added to the existing version node $v: add them to a new node, or (before release)"
    echo "regenerate the baseline with .ci/abi-baseline.sh"
    fail=1
  fi
done
[ $fail -eq 0 ] && echo "ABI compatible with the baseline"
exit $fail
