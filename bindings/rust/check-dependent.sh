#!/bin/sh
# Follows docs/rust.md's "Using the crate" as a user would: a new crate made with `cargo new`,
# this crate added as a path dependency with `cargo add --path`, the documentation's example as
# its main.rs, then `cargo run`, whose output must equal the documented output. The library is
# found the way the environment says (pkg-config for an installed library).
# Usage: check-dependent.sh CARGO CRATE_DIR DOC WORK_DIR
set -eu
cargo=$1
crate_dir=$2
doc=$3
work=$4

# The first ```rust block after the "## Using the crate" heading, and the ```text block after it.
block() {
  awk -v lang="$1" '
    /^## / { in_section = ($0 == "## Using the crate") }
    in_section && !on && $0 == "```" lang { on = 1; next }
    on && /^```/ { exit }
    on { print }
  ' "$doc"
}

rm -rf "$work/app"
mkdir -p "$work"
cd "$work"
"$cargo" new --quiet --vcs none --name app app
cd app
"$cargo" add --quiet --offline --path "$crate_dir"
block rust > src/main.rs
block text > expected.txt
if [ ! -s src/main.rs ] || [ ! -s expected.txt ]; then
  echo "no rust/text example under '## Using the crate' in $doc" >&2
  exit 1
fi
"$cargo" run --quiet --offline > actual.txt
diff -u expected.txt actual.txt
echo "the documented example builds, links and prints the documented output"
