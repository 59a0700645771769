#!/bin/sh
# `bezsurf render --rays` against the tessellated picture with the same camera, lights and colour:
# drawn in the base colour 1,0,0 without supersampling, so that surface and background pixels are
# told apart exactly (png_check --compare), the two pictures of each view must agree but for the
# pixels where a tessellation's chords and interpolated normals differ from the exact surface:
#   - pixels that are surface in one picture and background in the other (silhouettes): at most
#     0.1% of the picture (77 of 320x240);
#   - pixels with a channel differing by more than 16 of 255: at most 0.5% (384);
# and both pictures must show the surface (at least 3% of the pixels red: the thin teaspoon has
# 4%). Also: --rays with --nets, --patch and --split, and with --curvature refused; models of
# 1e-308, 1e-320 and 1e308 (tests/hostile/) drawn as the unit one, bit for bit. And the
# point cloud of --closest joined to its closest points.
# usage: test_cli_rays.sh TOOL PNG_CHECK HOSTILE_DIR WORK_DIR
tool=$1 pngcheck=$2 hostile=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

# field NAME: the number after NAME in $work/out
field() { awk -v k="$1" '{ for (i = 1; i < NF; i += 2) if ($i == k) print $(i + 1) }' "$work/out"; }

pic="--ss 1 --color 1,0,0 --size 320x240"
n=0
for view in "-b teapot" "-b teacup" "-b teaspoon -a -120 -e 35" "-b teapot -e 90" "-b teapot -e -40 -a 30"; do
    n=$((n + 1))
    expect 0 "tessellated $view" -- "$tool" render $view $pic -o "$work/mesh$n.png"
    expect 0 "rays $view" -- "$tool" render --rays $view $pic -o "$work/rays$n.png"
    has out "76800 rays" "rays $view: one ray per pixel"
    for f in mesh rays; do
        expect 0 "$f $view: colours" -- "$pngcheck" --colors "$work/$f$n.png" 0 0 319 239
        check "[ \$(field red) -ge 2304 ]" "$f $view: the surface is drawn"
    done
    expect 0 "compare $view" -- "$pngcheck" --compare "$work/mesh$n.png" "$work/rays$n.png" 16
    check "[ \$(field silhouette) -le 77 ]" "$view: silhouettes agree ($(cat "$work/out"))"
    check "[ \$(field differ) -le 384 ]" "$view: colours agree ($(cat "$work/out"))"
done

expect 0 "rays with nets" -- "$tool" render --rays --nets --size 200x150 -o "$work/nets.png"
expect 0 "rays with nets: valid picture" -- "$pngcheck" "$work/nets.png" 200 150
expect 0 "rays on a split patch" -- "$tool" render --rays --patch 4 --split --nets --size 200x150 -o "$work/split.png"
expect 0 "rays on a split patch: valid picture" -- "$pngcheck" "$work/split.png" 200 150
expect 0 "rays on the unit box" -- "$tool" render --rays --size 64x48 -o "$work/unit.png" "$hostile/unit_box.bpt"
for f in tiny_box subnormal_box huge_box; do
    expect 0 "rays on $f" -- "$tool" render --rays --size 64x48 -o "$work/$f.png" "$hostile/$f.bpt"
    check "cmp -s '$work/unit.png' '$work/$f.png'" "rays on $f: the unit box's picture"
done
expect 1 "rays with curvature" -- "$tool" render --rays --curvature mean -o "$work/no.png"
check "grep -q 'do not go together' '$work/err'" "rays with curvature: message"

# --closest N: the projections of a point cloud, their feet drawn red over a surface of the base
# colour's blue (no red before); a count past 100000 refused.
for n in 0 60; do
    expect 0 "closest cloud of $n" -- "$tool" render --patch 4 --closest $n --color 0.2,0.3,0.9 --ss 1 \
        --size 320x240 -o "$work/cloud$n.png"
    expect 0 "closest cloud of $n: colours" -- "$pngcheck" --colors "$work/cloud$n.png" 0 0 319 239
    eval "red$n=\$(field red)"
done
check "[ $red0 -eq 0 ] && [ $red60 -gt 60 ]" "the cloud's feet are drawn: red $red0 without, $red60 with"
expect 1 "closest cloud too large" -- "$tool" render --closest 100001 -o "$work/no.png"

echo "test_cli_rays: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
