#!/bin/sh
# The bezsurf tool: exit codes, one-line errors with file positions, and a few known outputs.
# usage: test_cli.sh TOOL DATA_DIR WORK_DIR
tool=$1 data=$2 work=$3
mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

expect 1 "no command" -- "$tool"
has err "usage: bezsurf" "usage on stderr"
expect 0 "--help" -- "$tool" --help
has out "continuity" "command list"
expect 0 "--version" -- "$tool" --version
expect 1 "unknown command" -- "$tool" frobnicate
has err "unknown command 'frobnicate'" "unknown command message"
for cmd in info eval continuity; do
    expect 0 "$cmd --help" -- "$tool" $cmd --help
    has out "usage: bezsurf $cmd" "$cmd help text"
    expect 1 "$cmd bad option" -- "$tool" $cmd --bogus
    point=""
    [ "$cmd" = eval ] && point="--point 0 0 0"
    expect 2 "$cmd missing file" -- "$tool" $cmd $point "$work/no-such-file.bpt"
    has err "no-such-file.bpt" "missing file named"
done

expect 0 "info on the built-in teapot" -- "$tool" info
has out "patches: 32" "teapot patch count"
has out "degrees: 3x3 (32)" "teapot degrees"
has out "bounds: x -3 .. 3.525, y -2 .. 2, z 0 .. 3.15" "teapot bounds"
expect 0 "info --builtin teacup" -- "$tool" info --builtin teacup
has out "patches: 26" "teacup patch count"
expect 2 "unknown built-in" -- "$tool" info --builtin kettle
expect 1 "--builtin without a name" -- "$tool" info --builtin
expect 0 "info on a file" -- "$tool" info "$data/teaspoon.bpt"
has out "patches: 16" "teaspoon patch count"
expect 0 "info on standard input" -- sh -c "\"$tool\" info - < \"$data/teacup.bpt\""
has out "patches: 26" "stdin patch count"
expect 1 "two files" -- "$tool" info "$data/teacup.bpt" "$data/teapot.bpt"

# Parse errors: exit 2 and FILE:LINE:COLUMN on one line.
printf '1\n3 3\n1 2 oops\n' >"$work/bad.bpt"
expect 2 "parse error" -- "$tool" info "$work/bad.bpt"
has err "bad.bpt:3:5: expected z coordinate" "error position"
checks=$((checks + 1))
[ "$(wc -l <"$work/err")" -eq 1 ] || { fails=$((fails + 1)); echo "FAIL: error is not one line"; }
printf '2\n0 0\n1 2 3\n' >"$work/short.bpt"
expect 2 "truncated file" -- "$tool" continuity "$work/short.bpt"
has err "short.bpt:4:1: unexpected end of input" "truncation position"
printf '1\n0 0\n1 2 3\n4\n' >"$work/trail.bpt"
expect 2 "trailing garbage" -- "$tool" eval --point 0 0 0 "$work/trail.bpt"
has err "trail.bpt:4:1:" "garbage position"

# eval: corners interpolate the net; the teapot's first point is (1.4, 0, 2.4).
expect 0 "eval a corner" -- "$tool" eval --point 0 0 0 --point 0 1 1
has out "0 0 0 1.4 0 2.4" "corner point"
expect 0 "eval with normals" -- "$tool" eval --normals --point 5 0.5 0.5
checks=$((checks + 1))
awk 'NF != 10 || ($7*$7 + $8*$8 + $9*$9 - 1)^2 > 1e-20 { exit 1 }' "$work/out" ||
    { fails=$((fails + 1)); echo "FAIL: normal line"; cat "$work/out"; }
# a zero coordinate prints as 0, never -0 (patch 1 at (0.5, 0) has the normal (-0, -0, -1))
expect 0 "eval without -0" -- "$tool" eval --normals --point 1 0.5 0
check "[ \"\$(cat '$work/out')\" = '1 0.5 0 0 -1.403125 2.4984374999999996 0 0 -1 0' ]" "no -0: \$(cat '$work/out')"
expect 2 "eval patch id out of range" -- "$tool" eval --point 32 0 0
has err "patch id 32" "id message"
expect 1 "eval without points" -- "$tool" eval
expect 1 "eval bad number" -- "$tool" eval --point 0 x 0

# continuity: the teapot's seams close exactly.
expect 0 "continuity" -- "$tool" continuity --samples 8
has out "max C0 gap: 0" "teapot C0 gap"
expect 1 "continuity bad samples" -- "$tool" continuity --samples 0
expect 1 "continuity bad tol" -- "$tool" continuity --tol -1

# Output errors.
if [ -w /dev/full ]; then
    expect 3 "output to a full device" -- sh -c "\"$tool\" info > /dev/full"
fi

echo "test_cli: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
