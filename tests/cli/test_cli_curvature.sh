#!/bin/sh
# `bezsurf render --curvature` on surfaces whose curvature is known exactly (rational quadratic
# circles are exact): a cylinder of radius 2 has H = -1/4 with its normals outwards (S_u x S_v,
# and the sign rule of bs_patch_eval_curvature: a sphere with outward normals has k = -1/r),
# H = +1/4 with them inwards, and K = 0; a unit hemisphere with inward normals has H = K = 1; a
# cone's apex has no curvature. Checked: the printed colour range, the colours of the middle of
# the picture (png_check --colors counts red, blue and grey pixels), the legend in the strip on
# the right (red at the top of the bar, blue at its bottom, grey in the middle, dark text), bad
# values; models far too small or large for their curvatures (tests/hostile/) coloured as the unit
# one.
# usage: test_cli_curvature.sh TOOL PNG_CHECK HOSTILE_DIR WORK_DIR
tool=$1 pngcheck=$2 hostile=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"

# count KIND FILE X0 Y0 X1 Y1: the number of pixels of that kind in the rectangle
count() {
    "$pngcheck" --colors "$2" "$3" "$4" "$5" "$6" | awk -v k="$1" '{ for (i = 1; i < NF; i += 2) if ($i == k) print $(i + 1) }'
}

# Four quarter cylinders around z, radius 2, height 4: u around the axis (counter-clockwise seen
# from +z), v up, so S_u x S_v points outwards; cyl_in.bpt swaps u and v.
awk 'BEGIN {
    w = 0.70710678118654757; split("2 0  2 2  0 2  -2 2  -2 0  -2 -2  0 -2  2 -2  2 0", p, " +")
    print 4 >"'"$work"'/cyl_out.bpt"; print 4 >"'"$work"'/cyl_in.bpt"
    for (q = 0; q < 4; q++) {
        print "2 1 w" >"'"$work"'/cyl_out.bpt"; print "1 2 w" >"'"$work"'/cyl_in.bpt"
        for (i = 0; i < 3; i++) for (z = 0; z <= 4; z += 4)
            print p[4*q+2*i+1], p[4*q+2*i+2], z, (i == 1 ? w : 1) >"'"$work"'/cyl_out.bpt"
        for (z = 0; z <= 4; z += 4) for (i = 0; i < 3; i++)
            print p[4*q+2*i+1], p[4*q+2*i+2], z, (i == 1 ? w : 1) >"'"$work"'/cyl_in.bpt"
    }
}'
# A unit hemisphere: the profile (1,0) (1,1) (0,1) (radius, height) turned by quarter circles; u
# climbs to the pole, v goes round, so S_u x S_v points inwards. A cone: apex (0,0,2) over the
# unit circle at z = 0.
awk 'BEGIN {
    w = 0.70710678118654757; split("1 0  1 1  0 1  -1 1  -1 0  -1 -1  0 -1  1 -1  1 0", c, " +")
    split("1 0 1  1 1 " w "  0 1 1", r, " +")
    print 4 >"'"$work"'/sphere.bpt"; print 4 >"'"$work"'/cone.bpt"
    for (q = 0; q < 4; q++) {
        print "2 2 w" >"'"$work"'/sphere.bpt"; print "1 2 w" >"'"$work"'/cone.bpt"
        for (i = 0; i < 3; i++) for (j = 0; j < 3; j++)
            print r[3*i+1] * c[4*q+2*j+1], r[3*i+1] * c[4*q+2*j+2], r[3*i+2], r[3*i+3] * (j == 1 ? w : 1) \
                >"'"$work"'/sphere.bpt"
        for (i = 0; i < 2; i++) for (j = 0; j < 3; j++)
            print i * c[4*q+2*j+1], i * c[4*q+2*j+2], 2 - 2 * i, (j == 1 ? w : 1) >"'"$work"'/cone.bpt"
    }
}'

# 400x300 seen from +x: the legend strip is the right 77 columns (its bar from row 45 to 255), the
# cylinder fills the middle of the rest (270 pixels square around (161, 150)).
mid="100 90 220 210" all=$((121 * 121)) most=$((121 * 121 * 9 / 10))
expect 0 "outward cylinder, mean" -- "$tool" render --curvature mean --size 400x300 -a 0 -e 0 -o "$work/out-h.png" "$work/cyl_out.bpt"
has out "mean curvature: colours over -0.25..0.25; at the vertices from -0.25 to -0.25, 0 undefined" "H = -1/(2r)"
check "[ \$(count blue '$work/out-h.png' $mid) -ge $most ]" "outward cylinder: blue (H < 0)"
check "[ \$(count red '$work/out-h.png' $mid) -eq 0 ]" "outward cylinder: no red"
# the legend: red at the top of the bar, grey in the middle, blue at the bottom, and the labels
check "[ \$(count red '$work/out-h.png' 323 46 399 60) -ge 60 ]" "legend: red at the top"
check "[ \$(count neutral '$work/out-h.png' 323 146 399 154) -ge 40 ]" "legend: grey in the middle"
check "[ \$(count blue '$work/out-h.png' 323 240 399 254) -ge 60 ]" "legend: blue at the bottom"
check "[ \$(count dark '$work/out-h.png' 323 0 399 299) -ge 60 ]" "legend: labels"
check "[ \$(count dark '$work/out-h.png' 0 0 300 299) -eq 0 ]" "no text over the surface"

expect 0 "inward cylinder, mean" -- "$tool" render --curvature mean --size 400x300 -a 0 -e 0 -o "$work/in-h.png" "$work/cyl_in.bpt"
has out "at the vertices from 0.25 to 0.25" "H = +1/(2r)"
check "[ \$(count red '$work/in-h.png' $mid) -ge $most ]" "inward cylinder: red (H > 0)"
check "[ \$(count blue '$work/in-h.png' $mid) -eq 0 ]" "inward cylinder: no blue"

expect 0 "cylinder, Gaussian" -- "$tool" render --curvature gauss --size 400x300 -a 0 -e 0 -o "$work/k.png" "$work/cyl_out.bpt"
has out "Gaussian curvature: colours over" "K reported"
check "[ \$(count neutral '$work/k.png' $mid) -ge $most ]" "cylinder: grey (K = 0)"
check "[ \$(count red '$work/k.png' $mid) -eq 0 ] && [ \$(count blue '$work/k.png' $mid) -eq 0 ]" "cylinder: K not coloured"

# The hemisphere from above (elevation 90): a disc of 270 pixels around (161, 150).
mid="121 110 201 190" most=$((81 * 81 * 9 / 10))
for c in mean gauss; do
    expect 0 "sphere, $c" -- "$tool" render --curvature $c --size 400x300 -e 90 -o "$work/s-$c.png" "$work/sphere.bpt"
    has out "colours over -1..1" "sphere, $c: range 1/r or 1/r^2"
    check "[ \$(count red '$work/s-$c.png' $mid) -ge $most ]" "sphere, $c: red (> 0)"
done

expect 0 "cone" -- "$tool" render --curvature gauss --size 400x300 -o "$work/cone.png" "$work/cone.bpt"
check "grep -Eq ', [1-9][0-9]* undefined' '$work/out'" "cone: its apex undefined"

# The unit box scaled to 1e-308, 1e-320 and 1e308: curvatures up to 1e616 (no longer a double)
# and down to 1e-617, the same picture (too small for a legend, whose values would differ).
for c in mean gauss; do
    expect 0 "unit box, $c" -- "$tool" render --curvature $c --size 200x150 -o "$work/unit-$c.png" "$hostile/unit_box.bpt"
    for f in tiny_box subnormal_box huge_box; do
        expect 0 "$f, $c" -- "$tool" render --curvature $c --size 200x150 -o "$work/$f-$c.png" "$hostile/$f.bpt"
        check "cmp -s '$work/unit-$c.png' '$work/$f-$c.png'" "$f, $c: the unit box's picture"
    done
done

# Too small for a legend: still a picture.
expect 0 "small picture" -- "$tool" render --curvature mean --size 64x48 -o "$work/small.png"
expect 1 "bad curvature" -- "$tool" render --curvature gaussian -o "$work/x.png"
check "grep -q 'bad curvature' '$work/err'" "bad curvature message"
expect 1 "curvature without value" -- "$tool" render --curvature
check "[ ! -e '$work/x.png' ]" "nothing written on a bad command line"

echo "test_cli_curvature: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
