#!/bin/sh
# Builds tests/consumer/consumer.c against an installed libbezsurf with pkg-config only.
# Usage: PKG_CONFIG_PATH=<prefix>/lib/pkgconfig build.sh <output>
# The program records the library folder as its RUNPATH, as a program linked against a library
# outside the loader's search path must (docs/building.md), so it runs without LD_LIBRARY_PATH.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
libdir=$(pkg-config --variable=libdir bezsurf)
# shellcheck disable=SC2046
${CC:-cc} -std=c99 -Wall -Wextra -o "$1" "$here/../consumer.c" $(pkg-config --cflags --libs bezsurf) \
  -Wl,-rpath,"$libdir"
