#!/bin/sh
# The triangle budget of tessellate and render: meshes over it are refused before any work (under
# a memory limit far below what they would take), exactly at it they are made, --max-triangles
# moves it and 0 removes it. Counts are the known ones: the teapot at N x N segments has
# 32 * 2N^2 - 8N triangles (its 8 poles drop N each).
# usage: test_cli_budget.sh TOOL WORK_DIR
tool=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"
limit=60

# 256 MiB of address space: refusing must not come near the gigabytes the meshes would need
# (not where the tool cannot start so capped, as under a sanitizer's shadow memory).
cap='ulimit -v 262144 && exec "$@"'
sh -c "$cap" capped "$tool" --version >/dev/null 2>&1 || cap='exec "$@"'

for cmd in tessellate render; do
    expect 0 "$cmd --help" -- "$tool" $cmd --help
    has out "--max-triangles N" "$cmd help names the budget"
    expect 1 "$cmd bad budget" -- "$tool" $cmd --max-triangles 1e6
    has err "bad triangle count" "$cmd bad budget message"
    expect 1 "$cmd budget without value" -- "$tool" $cmd --max-triangles
done

# tessellate: default 10,000,000; the teapot at 1024 x 1024 has 67,100,672 triangles.
expect 2 "teapot -u 1024 refused" -- sh -c "$cap" capped "$tool" tessellate -u 1024 -o "$work/big.obj"
has err "67100672 triangles, more than the budget of 10000000" "refusal names count and budget"
check "[ ! -e '$work/big.obj' ]" "nothing written when refused"
expect 2 "tolerance 1e-300 refused" -- sh -c "$cap" capped "$tool" tessellate -t 1e-300 -o "$work/big.obj"
has err "67100672 triangles" "adaptive at the rate cap counted"
expect 2 "subdivision at 1e-300 refused" -- sh -c "$cap" capped "$tool" tessellate -m subdivide -t 1e-300 -o "$work/big.obj"
has err "more triangles than the budget of 10000000" "subdivision refused while its trees are small"
# at 8 x 8: 4032 triangles, the budget is inclusive
expect 0 "exactly at the budget" -- "$tool" tessellate -u 8 --max-triangles 4032 -o "$work/t8.obj"
has out "4032 triangles" "mesh at the budget"
expect 2 "one over the budget" -- "$tool" tessellate -u 8 --max-triangles 4031 -o "$work/t8b.obj"
has err "4032 triangles, more than the budget of 4031" "one over"
expect 0 "no budget" -- "$tool" tessellate -u 8 --max-triangles 0 -o "$work/t0.obj"
has out "4032 triangles" "budget 0 is no limit"

# Eight degree-64 patches (a 0.6 MB file) whose nets zigzag by 10 (second differences of 40): at
# the default tolerance every patch reaches the rate cap, 8 * 2 * 1024^2 = 16,777,216 triangles;
# refused at once by default.
awk 'BEGIN {
    print 8
    for (p = 0; p < 8; p++) {
        print "64 64"
        for (i = 0; i <= 64; i++)
            for (j = 0; j <= 64; j++)
                printf "%.5f %.5f %d\n", 3 * p + i / 32, j / 32, 10 * ((i + j) % 2)
    }
}' >"$work/deg64.bpt"
expect 2 "degree-64 file refused" -- sh -c "$cap" capped "$tool" tessellate -o "$work/deg64.obj" "$work/deg64.bpt"
has err "16777216 triangles, more than the budget of 10000000" "degree-64 count"
expect 2 "degree-64 render refused" -- sh -c "$cap" capped "$tool" render -o "$work/deg64.png" "$work/deg64.bpt"
has err "16777216 triangles, more than the budget of 4000000" "degree-64 render count"

# render: default 4,000,000
expect 2 "render tolerance 1e-300 refused" -- sh -c "$cap" capped "$tool" render -r 1e-300 -o "$work/big.png"
has err "67100672 triangles, more than the budget of 4000000" "render refusal"
check "[ ! -e '$work/big.png' ]" "no picture when refused"
expect 2 "render under a small budget" -- "$tool" render --size 32x32 --ss 1 --max-triangles 100 -o "$work/s.png"
expect 0 "render with a budget it fits" -- "$tool" render --size 32x32 --ss 1 -r 0.01 --max-triangles 0 -o "$work/s.png"

# The closest points of render --closest: a point costs (m+1)(n+1)(m+n+2) steps for patches of
# degree m x n, the default budget is 100,000,000 steps. A degree-64 rational patch (150 KB) costs
# 549,250 steps, a third of a second, a point: 100,000 of them (hours) are refused at once, as
# are 183 (one over the budget; 182 would fit).
awk 'BEGIN {
    print 1
    print "64 64 w"
    for (i = 0; i <= 64; i++)
        for (j = 0; j <= 64; j++)
            printf "%.6f %.6f %.6f %.4f\n", i / 32 - 1, j / 32 - 1,
                0.3 * sin(7 * (i / 32 - 1)) * cos(5 * (j / 32 - 1)), 1 + 0.5 * sin(3 * i + 5 * j)
}' >"$work/r64.bpt"
expect 0 "render --help" -- "$tool" render --help
has out "--max-query-work N" "render help names the query budget"
expect 1 "bad query budget" -- "$tool" render --max-query-work 1e8
has err "bad query work" "bad query budget message"
limit=10
expect 2 "100000 closest points on degree 64 refused" -- "$tool" render --closest 100000 -o "$work/q.png" "$work/r64.bpt"
has err "--closest 100000 would take about 54925000000 steps of work (549250 a point on patches of degree 64x64), more than the budget of 100000000 (--max-query-work N raises it, 0 removes it)" \
    "query refusal names the work, the degrees and the flag"
check "[ ! -e '$work/q.png' ] && [ ! -s '$work/out' ]" "nothing written when the queries are refused"
expect 2 "183 closest points on degree 64 refused" -- "$tool" render --closest 183 -o "$work/q.png" "$work/r64.bpt"
has err "about 100512750 steps of work (549250 a point on patches of degree 64x64), more than the budget of 100000000" \
    "one point over the default query budget (the points within it take minutes in the instrumented builds)"
# the teapot (bicubic: 128 steps a point): the budget is inclusive, 0 removes it
expect 2 "one step over a query budget" -- "$tool" render --size 32x32 --ss 1 --closest 1000 --max-query-work 127999 -o "$work/q.png"
has err "about 128000 steps of work (128 a point on patches of degree 3x3), more than the budget of 127999" "teapot's work"
limit=60 # the refusals above are timed (at once); the runs below do their work
expect 0 "exactly at a query budget" -- "$tool" render --size 32x32 --ss 1 --closest 1000 --max-query-work 128000 -o "$work/q.png"
expect 0 "no query budget" -- "$tool" render --size 32x32 --ss 1 -r 0.05 --closest 2 --max-query-work 0 -o "$work/q.png" "$work/r64.bpt"
check "[ -s '$work/q.png' ]" "queries without a budget drawn"

echo "test_cli_budget: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
