#!/bin/sh
# Two separate runs of the determinism test print the same digest of all their results.
set -eu
a=$("$1" | grep '^result digest')
b=$("$1" | grep '^result digest')
echo "run 1: $a"
echo "run 2: $b"
[ -n "$a" ] && [ "$a" = "$b" ]
