#!/bin/sh
# Runs this crate's test programs against a libbezsurf built with -fsanitize=address. The ASan
# runtime must be the first library loaded, so cargo builds the programs normally and each one
# then runs with the runtime preloaded. Doc tests are not run this way.
# Usage: run-sanitized-tests.sh CARGO MANIFEST   (with BEZSURF_LIB_DIR etc. in the environment)
set -eu
cargo=$1
manifest=$2
runtime=$(${CC:-cc} -print-file-name=libasan.so)
if [ ! -e "$runtime" ]; then
  echo "no ASan runtime found by ${CC:-cc}" >&2
  exit 1
fi
exes=$("$cargo" test --offline --no-run --message-format=json --manifest-path "$manifest" |
  sed -n 's/.*"executable":"\([^"]*\)".*/\1/p')
if [ -z "$exes" ]; then
  echo "cargo built no test programs" >&2
  exit 1
fi
for exe in $exes; do
  echo "== $exe"
  LD_PRELOAD=$runtime "$exe" --quiet
done
