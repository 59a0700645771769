#!/usr/bin/env bash
# Regenerate the committed ABI baseline abi/libbezsurf.abi from a fresh default build. Run it when a
# release adds symbols (after the version script has its new node), never to hide a change.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build build -j2 --target bezsurf
abidw --no-corpus-path --no-show-locs --headers-dir include --headers-dir build/include \
  --out-file abi/libbezsurf.abi build/lib/libbezsurf.so.1
echo "abi/libbezsurf.abi: $(grep -c '<elf-symbol ' abi/libbezsurf.abi) ELF symbols"
