#!/bin/sh
# bezsurf convert, and OBJ and IGES inputs to every subcommand: exact round trips between .bpt and
# OBJ, formats by extension or --from/--to, IGES files written by OpenCASCADE, and the errors.
# usage: test_cli_convert.sh TOOL IGES_DIR WORK_DIR
tool=$1 iges=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

# .bpt -> OBJ -> .bpt is exact, for every built-in surface.
for b in teapot teacup teaspoon; do
    expect 0 "$b to .bpt" -- "$tool" convert --builtin "$b" "$work/$b.bpt"
    expect 0 "$b to OBJ" -- "$tool" convert -b "$b" "$work/$b.obj"
    expect 0 "$b OBJ back to .bpt" -- "$tool" convert "$work/$b.obj" "$work/$b.back.bpt"
    check "cmp -s '$work/$b.bpt' '$work/$b.back.bpt'" "$b: .bpt -> OBJ -> .bpt not exact"
done
check "grep -q '^cstype bezier' '$work/teapot.obj' && grep -q '^surf ' '$work/teapot.obj'" "OBJ free-form text"
# formats named on the command line; standard input
expect 0 "--to obj whatever the name" -- "$tool" convert --builtin teacup --to obj "$work/cup.txt"
check "grep -q '^cstype' '$work/cup.txt'" "--to obj wrote OBJ"
expect 0 "--from obj" -- "$tool" convert --from obj "$work/cup.txt" "$work/cup.bpt"
check "cmp -s '$work/cup.bpt' '$work/teacup.bpt'" "--from obj round trip"
expect 0 "OBJ on standard input" -- sh -c "\"$tool\" convert --from obj - \"$work/stdin.bpt\" < \"$work/teapot.obj\""
check "cmp -s '$work/stdin.bpt' '$work/teapot.bpt'" "OBJ from standard input"
expect 0 "an uppercase extension" -- cp "$work/teapot.obj" "$work/POT.OBJ"
expect 0 "info on POT.OBJ" -- "$tool" info "$work/POT.OBJ"
check "grep -q 'patches: 32' '$work/out'" "info reads OBJ by its extension"

# IGES written by OpenCASCADE: read by every subcommand, converted to OBJ and .bpt
for f in nurbs_cylinder bicubic_knots transformed subrange trimmed_face; do
    expect 0 "info $f.igs" -- "$tool" info "$iges/$f.igs"
    expect 0 "convert $f.igs" -- "$tool" convert "$iges/$f.igs" "$work/$f.bpt"
done
# a closed NURBS (the vase): its seam and knot lines shared, only the two rims open
expect 0 "info vase.igs" -- "$tool" info "$iges/vase.igs"
check "grep -q 'patches: 15' '$work/out' && grep -q 'shared edges: 27' '$work/out' && grep -q 'open edges: 6' '$work/out'" "the vase's patches and edges"
expect 0 "eval on IGES" -- "$tool" eval --point 0 0 0 "$iges/nurbs_cylinder.igs"
check "grep -q '^0 0 0 2 0 0' '$work/out'" "the cylinder's corner is (2, 0, 0)"
expect 0 "tessellate IGES" -- "$tool" tessellate -u 4 -o "$work/cyl.stl" "$iges/nurbs_cylinder.igs"
expect 0 "--from iges" -- "$tool" info --from iges "$iges/bicubic_knots.igs"

# errors
expect 1 "IGES is read only" -- "$tool" convert --builtin teapot "$work/out.igs"
check "grep -q 'read, not written' '$work/err'" "IGES output message"
expect 1 "unknown output extension" -- "$tool" convert --builtin teapot "$work/out.xyz"
check "grep -q 'use --to' '$work/err'" "unknown extension message"
expect 1 "unknown --to" -- "$tool" convert --builtin teapot --to step "$work/out.step"
expect 1 "unknown --from" -- "$tool" info --from dxf "$work/teapot.obj"
expect 1 "convert without OUT" -- "$tool" convert "$work/teapot.obj"
expect 1 "convert with IN and --builtin" -- "$tool" convert -b teapot "$work/teapot.obj" "$work/x.bpt"
printf 'v 0 0 0\ncstype taylor\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n' > "$work/taylor.obj"
expect 2 "unsupported OBJ surface type" -- "$tool" info "$work/taylor.obj"
check "grep -q 'taylor.obj:4:.*taylor' '$work/err'" "the line of the unsupported surface and its type"
printf 'v 0 0 0\nsurf 0 1 0 1 1 2\n' > "$work/broken.obj"
expect 2 "broken OBJ" -- "$tool" info "$work/broken.obj"
check "grep -q 'broken.obj:2:' '$work/err'" "the line of the OBJ error"
# a polygon mesh: refused, saying what it holds (it read as 0 patches, then closest said
# "the surface is not 3-D")
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\n' >"$work/polygons.obj"
for cmd in info "closest 1 2 3"; do
    expect 2 "polygon OBJ, $cmd" -- "$tool" $cmd "$work/polygons.obj"
    has err "polygons.obj:4:1: no surface (surf) to read, only 2 faces (f)" "polygon OBJ, $cmd: what it holds"
done
expect 2 "a .bpt read as IGES" -- "$tool" info --from iges "$work/teapot.bpt"

echo "test_cli_convert: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
