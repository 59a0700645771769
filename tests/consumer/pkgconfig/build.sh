#!/bin/sh
# Builds tests/consumer/consumer.c against an installed libbezsurf with pkg-config only.
# Usage: PKG_CONFIG_PATH=<prefix>/lib/pkgconfig build.sh <output>
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck disable=SC2046
${CC:-cc} -std=c99 -Wall -Wextra -o "$1" "$here/../consumer.c" $(pkg-config --cflags --libs bezsurf)
