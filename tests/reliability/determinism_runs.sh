#!/bin/sh
# Two separate runs of the determinism test print the same digest of all their results, and it is
# the committed one: every build (instruction set, compiler, optimisation) computes the same bits.
# A change of arithmetic on purpose updates the value below, and says so in its commit.
set -eu
expected="result digest 158785c3dd2e8c44"
a=$("$1" | grep '^result digest')
b=$("$1" | grep '^result digest')
echo "run 1: $a"
echo "run 2: $b"
echo "committed: $expected"
[ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" = "$expected" ]
