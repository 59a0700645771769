#!/bin/sh
# The tessellate and render commands: exit codes, outputs whose counts match what the tool
# reports, valid PNG files (checked by png_check), the default teapot.png.
# usage: test_cli_mesh.sh TOOL PNG_CHECK DATA_DIR WORK_DIR
tool=$1 pngcheck=$2 data=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

for cmd in tessellate render; do
    expect 0 "$cmd --help" -- "$tool" $cmd --help
    check "grep -q 'usage: bezsurf $cmd' '$work/out'" "$cmd help text"
    check "grep -q 'Exit status' '$work/out'" "$cmd help lists exit codes"
    expect 1 "$cmd bad option" -- "$tool" $cmd --bogus
    check "grep -q '^bezsurf $cmd: ' '$work/err'" "$cmd one-line error"
    expect 2 "$cmd missing file" -- "$tool" $cmd "$work/missing.bpt"
    expect 2 "$cmd unknown builtin" -- "$tool" $cmd -b kettle
    expect 1 "$cmd builtin without name" -- "$tool" $cmd -b
    expect 1 "$cmd two inputs" -- "$tool" $cmd "$data/teapot.bpt" "$data/teacup.bpt"
    printf '1\n3 3\n0 0\n' >"$work/bad.bpt"
    expect 2 "$cmd malformed file" -- "$tool" $cmd "$work/bad.bpt"
    check "grep -q 'bad.bpt:' '$work/err'" "$cmd parse error position"
done

# tessellate: formats by extension and by flag, counts as reported.
expect 0 "tessellate obj" -- "$tool" tessellate -u 8 -o "$work/t.obj" "$data/teapot.bpt"
check "grep -q '2082 vertices, 4032 triangles' '$work/out'" "uniform 8 counts"
check "[ \$(grep -c '^v ' '$work/t.obj') -eq 2082 ] && [ \$(grep -c '^f ' '$work/t.obj') -eq 4032 ]" "OBJ lines"
check "[ \$(grep -c '^vn ' '$work/t.obj') -eq 2082 ] && [ \$(grep -c '^vt ' '$work/t.obj') -eq 2082 ]" "OBJ vn/vt"
# --reverse: the teapot's patches face into the pot (negative signed volume); reversed, its mesh
# faces outwards: each face's last two corners swapped, each normal negated, the volume positive.
vol() {
    awk '/^v /{n++; x[n]=$2; y[n]=$3; z[n]=$4}
         /^f /{split($2,a,"/"); split($3,b,"/"); split($4,c,"/"); i=a[1]; j=b[1]; k=c[1]
               s+=x[i]*(y[j]*z[k]-z[j]*y[k])-y[i]*(x[j]*z[k]-z[j]*x[k])+z[i]*(x[j]*y[k]-y[j]*x[k])}
         END{printf "%.3f\n", s/6}' "$1"
}
expect 0 "tessellate reverse" -- "$tool" tessellate -u 8 --reverse -o "$work/r.obj" "$data/teapot.bpt"
check "grep -q '2082 vertices, 4032 triangles' '$work/out'" "reversed counts"
vt=$(vol "$work/t.obj") vr=$(vol "$work/r.obj")
check "[ \"$vt\" = \"-$vr\" ] && [ \"${vr#-}\" = \"$vr\" ]" "signed volumes $vt plain, $vr reversed"
awk '/^f /{print $1, $2, $4, $3}' "$work/t.obj" >"$work/faces.want"
awk '/^vn /{print -$2, -$3, -$4}' "$work/t.obj" >"$work/vn.want"
check "grep '^f ' '$work/r.obj' | cmp -s - '$work/faces.want'" "reversed faces"
check "awk '/^vn /{print \$2+0, \$3+0, \$4+0}' '$work/r.obj' | cmp -s - '$work/vn.want'" "negated normals"
# -o -: the mesh (or picture) to standard output, the report to stderr, no file named '-'
expect 0 "tessellate -o -" -- sh -c "cd '$work' && '$tool' tessellate -u 8 -o - '$data/teapot.bpt'"
check "cmp -s '$work/out' '$work/t.obj'" "tessellate -o -: the OBJ bytes of -o t.obj"
check "grep -q '^<stdout>: 2082 vertices, 4032 triangles' '$work/err'" "tessellate -o -: counts on stderr"
check "[ ! -e '$work/-' ]" "tessellate -o -: no file named -"
expect 0 "tessellate -o - -f stl" -- "$tool" tessellate -u 8 -f stl -o - "$data/teapot.bpt"
check "[ \$(wc -c <'$work/out') -eq \$((84 + 50 * 4032)) ]" "STL to stdout"
expect 0 "render -o -" -- sh -c "cd '$work' && '$tool' render --size 48x32 --ss 1 -o -"
check "head -c 4 '$work/out' | od -c | grep -q 'P   N   G'" "render -o -: a PNG on stdout"
check "grep -q '^<stdout>: 48x32' '$work/err' && [ ! -e '$work/-' ]" "render -o -: report on stderr"
# "--" ends the options: an input whose name starts with '-'
cp "$data/teacup.bpt" "$work/-cup.bpt"
expect 0 "tessellate --" -- sh -c "cd '$work' && '$tool' tessellate -u 2 -o cup2.obj -- -cup.bpt"
check "grep -q '^cup2.obj: ' '$work/out'" "tessellate -- -cup.bpt"
expect 0 "tessellate stl" -- "$tool" tessellate -u 8 -o "$work/t.stl"
check "[ \$(wc -c <'$work/t.stl') -eq \$((84 + 50 * 4032)) ]" "STL size"
expect 0 "tessellate ply" -- "$tool" tessellate -u 4x6 -o "$work/t.ply" -b teacup
check "head -c 40 '$work/t.ply' | grep -q 'binary_little_endian'" "PLY binary by extension"
expect 0 "tessellate ply-ascii flag" -- "$tool" tessellate -f ply-ascii -t 0.05 -o "$work/a.out" -b teaspoon
check "head -c 40 '$work/a.out' | grep -q 'format ascii'" "PLY ASCII by flag"
expect 0 "tessellate stdin" -- sh -c "'$tool' tessellate -r 0.01 -s -o '$work/s.obj' - <'$data/teacup.bpt'"
check "grep -q 'strips' '$work/out'" "strip count reported"
expect 1 "tessellate bad rate" -- "$tool" tessellate -u 8y
expect 1 "tessellate bad format" -- "$tool" tessellate -f dxf
expect 1 "tessellate bad tolerance" -- "$tool" tessellate -t -1
expect 1 "tessellate rate out of range" -- "$tool" tessellate -u 0 -o "$work/z.obj"
expect 3 "tessellate unwritable" -- "$tool" tessellate -u 2 -o "$work/no/such/dir/x.obj"
# --method: subdivision reports what it writes, and needs fewer triangles than one rate per patch.
expect 0 "tessellate subdivide" -- "$tool" tessellate -m subdivide -t 0.01 -o "$work/q.obj"
nq=$(sed -n 's/.* \([0-9]*\) triangles.*/\1/p' "$work/out")
check "[ \$(grep -c '^f ' '$work/q.obj') -eq $nq ]" "subdivide OBJ faces as reported"
expect 0 "tessellate per-patch" -- "$tool" tessellate --method per-patch -t 0.01 -o "$work/p.obj"
np=$(sed -n 's/.* \([0-9]*\) triangles.*/\1/p' "$work/out")
check "[ $nq -lt $np ]" "subdivide $nq triangles, per-patch $np"
expect 1 "tessellate bad method" -- "$tool" tessellate -m quadtree
check "grep -q 'unknown method: quadtree' '$work/err'" "bad method message"
(cd "$work" && "$tool" tessellate -u 2 >/dev/null 2>&1)
check "[ -s '$work/teapot.obj' ]" "default output teapot.obj"

# render: default teapot.png in the working directory, sizes, options, valid PNGs.
(cd "$work" && "$tool" render --size 96x64 --ss 1 >"$work/out" 2>"$work/err")
rc=$?
check "[ $rc -eq 0 ]" "render with no input"
check "'$pngcheck' '$work/teapot.png' 96 64" "teapot.png valid"
expect 0 "render teacup nets" -- "$tool" render -b teacup --nets --size 80x60 -a 30 -e 40 --up y -r 0.01 \
    --color 1,0.5,0.25 -o "$work/cup.png"
check "'$pngcheck' '$work/cup.png' 80 60" "cup.png valid"
expect 0 "render file" -- "$tool" render --size 400x300 --ss 1 -o "$work/spoon.png" "$data/teaspoon.bpt"
check "'$pngcheck' '$work/spoon.png' 400 300" "spoon.png valid (several deflate blocks)"
expect 0 "render split patch" -- "$tool" render --patch 4 --split --nets --size 64x48 -o "$work/split.png"
check "'$pngcheck' '$work/split.png' 64 48" "split.png valid"
check "grep -q '64x48' '$work/out'" "render reports its size"
expect 0 "render subdivided wireframe" -- "$tool" render -m subdivide --wire -r 0.005 --size 64x48 -o "$work/wire.png"
check "'$pngcheck' '$work/wire.png' 64 48" "wire.png valid"
expect 1 "render bad method" -- "$tool" render --method uniform
expect 2 "render no such patch" -- "$tool" render --patch 32 -o "$work/none.png"
expect 1 "render bad patch id" -- "$tool" render --patch x
expect 1 "render bad size" -- "$tool" render --size 10x10
expect 1 "render bad size text" -- "$tool" render --size 100
expect 1 "render bad elevation" -- "$tool" render -e 91
expect 1 "render bad up" -- "$tool" render --up x
expect 1 "render bad colour" -- "$tool" render --color 1,2
expect 1 "render bad ss" -- "$tool" render --ss 9
expect 1 "render over 2^26 samples" -- "$tool" render --size 8192x4097 --ss 2 -o "$work/huge.png"
expect 1 "render one sample over" -- "$tool" render --size 8192x8192 --ss 1 --ss 2 -o "$work/huge.png"
expect 3 "render unwritable" -- "$tool" render --size 32x32 -o "$work/no/such/dir/x.png"

echo "test_cli_mesh: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
