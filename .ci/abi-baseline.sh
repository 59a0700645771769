#!/usr/bin/env bash
# Write the ABI baseline of this release, abi/libbezsurf-MAJOR.MINOR.abi, from a fresh default
# build. Run it once a release's version node is complete (before the release, again when a symbol
# joins its node), never to hide a change: the baselines of earlier releases are never rewritten,
# and the build is compared with every committed baseline (tests/abi/check_abidiff.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build build -j2 --target bezsurf
version=$(sed -n 's/^#define BS_VERSION_STRING "\([0-9]*\.[0-9]*\)\..*"/\1/p' build/include/bezsurf/version.h)
out=abi/libbezsurf-$version.abi
abidw --no-corpus-path --no-show-locs --headers-dir include --headers-dir build/include \
  --out-file "$out" build/lib/libbezsurf.so.1
echo "$out: $(grep -c '<elf-symbol ' "$out") ELF symbols"
