#!/bin/sh
# `bezsurf closest X Y Z [FILE]`: a point of the teapot (from `bezsurf eval`) is found again at
# distance ~0 (the locator's bound is 1e-9 (D + d), D about 8 here); for points away from it the
# distance agrees with brute force over the vertices of a uniform tessellation (-u 64: a point of a
# bicubic patch is within (|S_u| + |S_v|)/128 of a vertex, |S_u| and |S_v| at most 3 times the
# longest control-net edge, 1.64 for the teapot: within 0.077; so the true distance is at most the
# vertices' minimum and at least that minimum less 0.1); the printed point is what `eval` gives at the printed patch and
# (u,v), and lies at the printed distance. Bad command lines exit 1, bad input 2.
# usage: test_cli_closest.sh TOOL WORK_DIR
tool=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

# A point on patch 5 of the teapot.
expect 0 "eval a teapot point" -- "$tool" eval --point 5 0.3 0.6
set -- $(cat "$work/out")
x=$4 y=$5 z=$6
expect 0 "closest to a point on the teapot" -- "$tool" closest "$x" "$y" "$z"
check "awk '{ exit !(NF == 7 && \$7 >= 0 && \$7 < 1e-8) }' '$work/out'" "distance ~0 ($(cat "$work/out"))"

# The vertices of a fine tessellation, for brute force.
expect 0 "tessellate for brute force" -- "$tool" tessellate -u 64 -o "$work/t.obj"
for q in "10 -7 12" "-6 2 -3" "0 0 1.5" "1 1 0.5"; do
    expect 0 "closest to $q" -- "$tool" closest $q
    cp "$work/out" "$work/answer"
    set -- $(cat "$work/answer")
    patch=$1 u=$2 v=$3 px=$4 py=$5 pz=$6 d=$7
    brute=$(awk -v q="$q" 'BEGIN { split(q, c, " "); best = -1 }
        $1 == "v" { s = ($2 - c[1])^2 + ($3 - c[2])^2 + ($4 - c[3])^2; if (best < 0 || s < best) best = s }
        END { printf "%.17g", sqrt(best) }' "$work/t.obj")
    check "awk -v d=$d -v b=$brute 'BEGIN { exit !(d <= b + 1e-9 && d >= b - 0.1) }'" \
        "closest to $q: distance $d against brute force $brute"
    check "awk -v q='$q' -v p='$px $py $pz' -v d=$d 'BEGIN { split(q, a, \" \"); split(p, b, \" \");
        s = sqrt((a[1]-b[1])^2 + (a[2]-b[2])^2 + (a[3]-b[3])^2); exit !(s - d <= 1e-12 * (1 + d) && d - s <= 1e-12 * (1 + d)) }'" \
        "closest to $q: the point lies at the distance"
    expect 0 "eval at the answer to $q" -- "$tool" eval --point "$patch" "$u" "$v"
    check "[ \"\$(cat '$work/out')\" = '$patch $u $v $px $py $pz' ]" "closest to $q: the point is eval's"
done

expect 0 "closest on the teacup" -- "$tool" closest -b teacup 0 1 0
check "awk '{ exit !(NF == 7 && \$7 > 0) }' '$work/out'" "teacup answer"
expect 0 "teaspoon to a file" -- "$tool" convert -b teaspoon "$work/s.bpt"
expect 0 "closest from standard input" -- sh -c "'$tool' closest 0.5 0 0 - <'$work/s.bpt'"
check "awk '{ exit !(NF == 7) }' '$work/out'" "answer for standard input"

expect 1 "two coordinates" -- "$tool" closest 1 2
check "grep -q 'three coordinates' '$work/err'" "two coordinates: message"
expect 1 "a word for a coordinate" -- "$tool" closest 1 2 x3
expect 1 "not finite" -- "$tool" closest 1 2 1e999
check "grep -q 'Z is not a finite number: 1e999' '$work/err'" "not finite: which coordinate, not 'three are needed'"
for bad in "1 2 nan" "1e400 0 0" "0 -inf 0"; do
    expect 1 "closest $bad" -- "$tool" closest $bad
    check "grep -q 'is not a finite number' '$work/err' && ! grep -q 'three coordinates' '$work/err'" "closest $bad: message"
done
# "--" ends the options: a file whose name starts with '-', coordinates after it
"$tool" convert -b teacup "$work/cup.bpt" >/dev/null && mv "$work/cup.bpt" "$work/-cup.bpt"
expect 0 "closest --" -- sh -c "cd '$work' && '$tool' closest -- 0.5 2 0.1 -cup.bpt"
expect 0 "closest -- without file" -- "$tool" closest -- -1 2 3
expect 1 "unknown option" -- "$tool" closest --bogus 1 2 3
expect 2 "missing file" -- "$tool" closest 1 2 3 "$work/missing.bpt"
expect 2 "unknown built-in" -- "$tool" closest -b kettle 1 2 3
expect 0 "help" -- "$tool" closest --help
check "grep -q 'PATCH U V x y z DISTANCE' '$work/out'" "help names the columns"

echo "test_cli_closest: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
