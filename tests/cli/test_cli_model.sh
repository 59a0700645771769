#!/bin/sh
# Models in the tool: info on the CAD parts of data/cad/ (the face counts, area and volume of their
# .ref files, one closed shell), STEP converted to OBJ and read back, render --faces and trims
# pictures, watertight meshes by tessellate, errors.
# usage: test_cli_model.sh TOOL PNG_CHECK CAD_DIR WORK_DIR
tool=$1 png_check=$2 cad=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

faces_of() { sed -n 's/^faces \([0-9]*\)$/\1/p' "$cad/$1.ref"; }
ref_of() { sed -n "s/^$2 //p" "$cad/$1.ref"; }
# 1 when the value printed on line "KEY: value" of the last output is within 1e-7 (relative) of
# the .ref's (the kernel's own area and volume are good to about 1e-8 on the duct and the bell)
near_ref() {
    awk -v a="$(sed -n "s/^$2: //p" "$work/out")" -v b="$(ref_of "$1" "$2")" \
        'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= 1e-7 * b) }'
}

# every file of every part: the kernel's face count, one closed shell (the files of trimmed
# surfaces without topology sewn into one: block.igs's hole within the loose tolerance of closed
# trims, docs/models.md) and the kernel's volume and area
for f in "$cad"/*.step "$cad"/*.igs; do
    name=$(basename "$f")
    part=${name%%.*}
    part=${part%-3d-edges}
    part=${part%-brep}
    n=$(faces_of "$part")
    expect 0 "info $name" -- "$tool" info "$f"
    has out "faces: $n (" "$name: $n faces"
    has out "shells: 1 (1 closed, 0 open)" "$name: one closed shell"
    check 'near_ref "$part" volume' "$name: volume $(sed -n 's/^volume: //p' "$work/out"), the kernel's $(ref_of "$part" volume)"
    check 'near_ref "$part" area' "$name: area $(sed -n 's/^area: //p' "$work/out"), the kernel's $(ref_of "$part" area)"
done

# an assembly (tests/model/data/step/assembly.step: two parts placed five times): its instances
expect 0 "info assembly.step" -- "$tool" info "$(dirname "$0")/../model/data/step/assembly.step"
has out "faces: 19 (" "assembly.step: 19 faces"
has out "shells: 5 (5 closed, 0 open)" "assembly.step: five closed shells"
has out "instances: 5" "assembly.step: five instances"

# STEP -> OBJ -> the same faces and patches (the parts whose trims OBJ holds exactly:
# bs_model_write_obj). info describes an OBJ file by its patches; trims reads it as a model.
for part in bottle duct sphere torus wedge; do
    n=$(faces_of "$part")
    expect 0 "info $part.step" -- "$tool" info "$cad/$part.step"
    patches=$(sed -n 's/^patches: //p' "$work/out")
    expect 0 "convert $part.step" -- "$tool" convert "$cad/$part.step" "$work/$part.obj"
    expect 0 "info $part.obj" -- "$tool" info "$work/$part.obj"
    has out "patches: $patches" "$part.obj: the $patches patches of $part.step"
    expect 0 "trims $part.obj" -- "$tool" trims --size 128 -o "$work/$part-trims.png" "$work/$part.obj"
    has out " of $n (" "$part.obj: $n faces"
done

# pictures: render --faces (trimmed faces, a legend) and trims
expect 0 "render --faces" -- "$tool" render --faces --size 320x200 --ss 1 --max-triangles 20000 \
    -o "$work/block.png" "$cad/block.step"
has out "320x200" "render's report"
expect 0 "block.png" -- "$png_check" "$work/block.png" 320 200
expect 0 "render of a model without --faces" -- "$tool" render --size 160x120 --ss 1 --max-triangles 20000 \
    -o "$work/wedge.png" "$cad/wedge-brep.igs"
expect 0 "wedge.png" -- "$png_check" "$work/wedge.png" 160 120
expect 0 "render --faces of a .bpt surface" -- "$tool" render --faces -b teacup --size 160x120 --ss 1 \
    --max-triangles 20000 -o "$work/cup.png"
expect 0 "cup.png" -- "$png_check" "$work/cup.png" 160 120
# render --rays of a model hits its trimmed faces only: the bell's planes are discs cut by the
# revolution's 300 degrees, far smaller than their square patches (fewer hits than those give)
expect 0 "render --rays of a model" -- "$tool" render --rays --size 160x120 --ss 1 -o "$work/bell-rays.png" "$cad/bell.step"
trimmed_hits=$(sed -n 's/.* rays, \([0-9]*\) hits$/\1/p' "$work/out")
expect 0 "bell-rays.png" -- "$png_check" "$work/bell-rays.png" 160 120
expect 0 "convert bell.step bell.bpt (its patches, untrimmed)" -- "$tool" convert "$cad/bell.step" "$work/bell.bpt"
expect 0 "render --rays of its patches" -- "$tool" render --rays --size 160x120 --ss 1 -o "$work/bell-patches.png" "$work/bell.bpt"
whole_hits=$(sed -n 's/.* rays, \([0-9]*\) hits$/\1/p' "$work/out")
check '[ "$trimmed_hits" -gt 1000 ] && [ "$trimmed_hits" -lt $((whole_hits * 3 / 4)) ]' \
    "render --rays of the bell: $trimmed_hits hits on its trimmed faces, $whole_hits on its patches"
expect 0 "trims" -- "$tool" trims --size 200 -o "$work/trims.png" "$cad/block.step"
has out "face 8 of 28 (plane), 3 loops" "the block's face with two holes is the default"
expect 0 "trims.png" -- "$png_check" "$work/trims.png" 200 200
expect 0 "trims --face" -- "$tool" trims --face 1 --size 128 -o "$work/bell.png" "$cad/bell.step"
has out "face 1 of 7 (revolution), 2 loops" "the bell's face 1"
expect 0 "bell.png" -- "$png_check" "$work/bell.png" 128 128

# tessellate: a watertight mesh of each part's STEP file, the report says it is closed; an STL
# of it has the triangles reported; -u is refused for models
for part in bottle block sphere torus cone wedge bell duct; do
    expect 0 "tessellate $part.step" -- "$tool" tessellate -r 1e-3 -o "$work/$part.stl" "$cad/$part.step"
    has out ", closed" "$part.step: a closed mesh"
    n=$(sed -n 's/.* \([0-9]*\) triangles.*/\1/p' "$work/out")
    check '[ "$(wc -c < "$work/$part.stl")" -eq $((84 + 50 * n)) ]' "$part.stl holds the $n triangles reported"
done
expect 0 "tessellate block-brep.igs" -- "$tool" tessellate -o "$work/bb.obj" "$cad/block-brep.igs"
has out ", closed" "block-brep.igs: closed (its hole's trims written 0.03 apart share the edge's vertices)"
expect 0 "tessellate block.igs" -- "$tool" tessellate -o "$work/bi.obj" "$cad/block.igs"
has out ", closed" "block.igs: closed (sewn, its hole's trims 0.03 apart)"
expect 0 "tessellate an open box" -- "$tool" tessellate -o "$work/ob.obj" "$(dirname "$0")/../model/data/faces/open-box-brep.igs"
has out ", not closed" "open-box-brep.igs: its open shell reported"
expect 1 "tessellate a model with -u" -- "$tool" tessellate -u 4 -o "$work/u.obj" "$cad/cone.step"
check "[ ! -e '$work/u.obj' ]" "nothing written after -u on a model"

# render --wire of a model: its watertight mesh drawn (the triangle count of tessellate)
expect 0 "render --wire of the cone" -- "$tool" render --wire -r 1e-3 --size 200x150 -o "$work/cone-wire.png" "$cad/cone.step"
expect 0 "tessellate the cone at the same tolerance" -- "$tool" tessellate -r 1e-3 -o "$work/cone-wire.obj" "$cad/cone.step"
n=$(sed -n 's/.* \([0-9]*\) triangles.*/\1/p' "$work/out")
expect 0 "render --wire again" -- "$tool" render --wire -r 1e-3 --size 200x150 -o "$work/cone-wire.png" "$cad/cone.step"
has out ", $n triangles" "render --wire draws the $n triangles of the model's mesh"

# closest: on the trimmed faces of a model (face id, native uv, point, distance); the block's
# first .ref point lies beside a hole, where the kernel's distance is 1.495303296449455
expect 0 "closest on the cone" -- "$tool" closest 0 0 100 "$cad/cone.step"
has out "1 -2.220446049250313e-16 -2.220446049250313e-16 " "the top disc (face 1) at its centre"
has out " 7 93" "z = 7, 93 away"
read -r q1 q2 q3 kd <<EOF_REF
$(sed -n 's/^closest \([^ ]*\) \([^ ]*\) \([^ ]*\) dist \(.*\)/\1 \2 \3 \4/p' "$cad/block.ref" | head -1)
EOF_REF
expect 0 "closest on the block" -- "$tool" closest -- "$q1" "$q2" "$q3" "$cad/block.step"
d=$(awk '{print $7}' "$work/out")
check "awk -v d='$d' -v k='$kd' 'BEGIN { exit !(d <= k + 1e-7 * 50) }'" "no farther than the kernel's $kd ($d)"
expect 0 "closest on the block's patches (.bpt: untrimmed)" -- "$tool" convert "$cad/block.step" "$work/block.bpt"
expect 0 "closest on the untrimmed patches" -- "$tool" closest -- "$q1" "$q2" "$q3" "$work/block.bpt"
du=$(awk '{print $7}' "$work/out")
check "awk -v d='$d' -v u='$du' 'BEGIN { exit !(u <= d) }'" "the untrimmed surface is no farther ($du <= $d)"

# errors
printf 'ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=CARTESIAN_POINT(%s,(0.,0.,0.);\nENDSEC;\nEND-ISO-10303-21;\n' "''" \
    > "$work/bad.step"
expect 2 "a STEP syntax error" -- "$tool" info "$work/bad.step"
has err "bad.step:5:" "the error's line and column"
expect 2 "trims of a bad file" -- "$tool" trims -o "$work/x.png" "$work/bad.step"
expect 2 "render of a bad file" -- "$tool" render --faces -o "$work/x.png" "$work/bad.step"
expect 2 "no such face" -- "$tool" trims --face 99 -o "$work/x.png" "$cad/cone.step"
has err "no face 99 (the model has 3)" "the face count in the message"
expect 1 "bad trims size" -- "$tool" trims --size 12 "$cad/cone.step"
expect 1 "bad face id" -- "$tool" trims --face x "$cad/cone.step"
expect 1 "unknown trims option" -- "$tool" trims --bogus 1 "$cad/cone.step"
expect 1 "--faces with --rays" -- "$tool" render --faces --rays -o "$work/x.png" "$cad/cone.step"
check "[ ! -e '$work/x.png' ]" "nothing written after errors"
expect 0 "trims --help" -- "$tool" trims --help
has out "usage: bezsurf trims" "trims' usage"

echo "test_cli_model: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
