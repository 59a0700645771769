#!/bin/sh
# The man page made from the tool's --help texts: one section per command the tool lists, every
# line of each command's --help in it, and groff reads it without a warning.
#   test_man_page.sh TOOL MAN_PAGE
set -eu
tool=$1
page=$2
[ -s "$page" ] || { echo "no man page at $page"; exit 1; }
commands=$("$tool" --help | sed -n '/^commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z]*\) .*/\1/p')
[ -n "$commands" ] || { echo "no command list in $tool --help"; exit 1; }
# The page as text, without roff's escapes, to compare with --help line by line.
text=$(sed -e 's/\\-/-/g' -e 's/\\e/\\/g' -e 's/^\\&//' "$page")
fail=0
for c in $commands; do
  printf '%s\n' "$text" | grep -qx ".SS $c" || { echo "no section for command $c"; fail=1; }
  "$tool" "$c" --help | while IFS= read -r line; do
    printf '%s\n' "$text" | grep -qxF -- "$line" || { echo "$c: line missing: $line"; exit 1; }
  done || fail=1
done
warnings=$(groff -man -Tutf8 -ww -z "$page" 2>&1 || true)
[ -z "$warnings" ] || { echo "groff: $warnings"; fail=1; }
[ "$fail" = 0 ] && echo "man page: $(echo $commands | wc -w) commands, groff clean"
