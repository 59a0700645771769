#!/bin/sh
# The library exports exactly the names the version script lists, each bound to a version node.
# Usage: check_exports.sh <libbezsurf.so> <libbezsurf.map>
set -eu
lib=$1 map=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Names listed in the script: lines "name;" inside global sections, without comments.
sed -e 's:/\*.*\*/::g' "$map" | grep -E '^[[:space:]]*bs_[A-Za-z0-9_]+;' | tr -d ' \t;' | sort >"$tmp/listed"
# Defined dynamic symbols of the library (the version node names themselves excluded).
nm -D --defined-only "$lib" | awk '$2 != "A" {print $3}' >"$tmp/raw"
if grep -v '@' "$tmp/raw" >"$tmp/unversioned"; then
  echo "exported without a version:"; cat "$tmp/unversioned"; exit 1
fi
sed 's/@.*//' "$tmp/raw" | sort >"$tmp/exported"
if ! diff -u "$tmp/listed" "$tmp/exported"; then
  echo "exports differ from $map ('-' listed only, '+' exported only)"; exit 1
fi
if grep -v -E '^bs_' "$tmp/exported"; then echo "exports outside the bs_ namespace"; exit 1; fi
echo "$(wc -l <"$tmp/exported") exports, all listed and versioned"
