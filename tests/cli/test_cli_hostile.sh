#!/bin/sh
# The tool against hostile input and hostile outputs: surfaces far too small or too large for
# their numbers (tests/hostile/), FIFOs and directories where files are expected, writes that fail
# half-way (a file-size limit), the largest input read, and command lines that used to be
# misread. Every run is under a time limit: a hang is a failure.
# usage: test_cli_hostile.sh TOOL PNG_CHECK HOSTILE_DIR WORK_DIR
tool=$1 pngcheck=$2 hostile=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"
limit=60

# no temporary file left in the work directory
no_tmp() { check "[ -z \"\$(ls -A '$work' | grep '^\.bezsurf-')\" ]" "$1: temporary file left behind"; }

# Rendering: tiny (down to subnormal) and huge boxes give the unit box's picture, nets included.
expect 0 "render the unit box" -- "$tool" render --nets --size 64x48 --ss 1 -o "$work/unit.png" "$hostile/unit_box.bpt"
for f in tiny_box subnormal_box huge_box; do
    expect 0 "render $f" -- "$tool" render --nets --size 64x48 --ss 1 -o "$work/$f.png" "$hostile/$f.bpt"
    check "cmp -s '$work/unit.png' '$work/$f.png'" "$f: not the unit box's picture"
done
for f in one_point line; do
    expect 0 "render $f" -- "$tool" render --nets --split --size 40x30 --ss 2 -o "$work/$f.png" "$hostile/$f.bpt"
    check "'$pngcheck' '$work/$f.png' 40 30" "$f: PNG not valid"
done
# Not split: the adaptive rate of a patch with weights 1e-300 .. 1e300 saturates at the maximum
# (1024 x 1024), four times over when split (4 M triangles, half a minute on a loaded machine).
expect 0 "render wild_weights" -- "$tool" render --nets --size 40x30 --ss 1 -o "$work/wild_weights.png" "$hostile/wild_weights.bpt"
check "'$pngcheck' '$work/wild_weights.png' 40 30" "wild_weights: PNG not valid"
expect 2 "render an empty surface" -- "$tool" render --size 64x48 -o "$work/empty.png" "$hostile/empty.bpt"
check "grep -q 'no patches' '$work/err' && ! grep -q '3-D' '$work/err'" "empty surface message"
check "[ ! -e '$work/empty.png' ]" "no picture of an empty surface"

# Not regular files: refused at once, with the reason.
mkfifo "$work/fifo" || exit 1
expect 2 "FIFO without a writer as input" -- "$tool" info "$work/fifo"
check "grep -q 'fifo: not a regular file' '$work/err'" "FIFO message"
expect 2 "directory as input" -- "$tool" info "$work"
check "grep -q 'not a regular file (a directory)' '$work/err'" "directory message"
expect 3 "FIFO as output" -- "$tool" tessellate -u 2 -o "$work/fifo"
check "[ -p '$work/fifo' ] && grep -q 'cannot write .*fifo: not a regular file' '$work/err'" "FIFO kept, message"
mkdir "$work/dir.obj"
expect 3 "directory as output" -- "$tool" tessellate -u 2 -o "$work/dir.obj"
check "[ -d '$work/dir.obj' ] && grep -q 'Is a directory' '$work/err'" "directory kept, message"

# Outputs: checked before the work (an unwritable output wins over a missing input), with the
# path and the system's reason.
expect 3 "tessellate to a missing directory" -- "$tool" tessellate -u 2 -o "$work/no/such/x.obj" "$work/missing.bpt"
check "grep -q 'cannot write $work/no/such/x.obj: No such file or directory' '$work/err'" "tessellate output message"
expect 3 "render to a missing directory" -- "$tool" render -o "$work/no/such/x.png" "$work/missing.bpt"
check "grep -q 'cannot write $work/no/such/x.png: No such file or directory' '$work/err'" "render output message"

# A write that fails half-way (file-size limit of 4 KiB): the old file is untouched, no temporary
# file remains, the message names the path and the reason. SIGXFSZ is ignored, so that the
# write fails with EFBIG instead of killing the tool.
for out in old.obj old.ply old.stl old.png; do
    echo "previous content" >"$work/$out"
    cmd="tessellate -u 4"
    [ "$out" = old.png ] && cmd="render --size 320x240 --ss 1" # about 17 KiB compressed
    expect 3 "$cmd to $out past the file-size limit" -- sh -c \
        "trap '' XFSZ; ulimit -f 8; exec '$tool' $cmd -o '$work/$out' -b teacup"
    check "[ \"\$(cat '$work/$out')\" = 'previous content' ]" "$out: old content lost"
    check "grep -q 'cannot write $work/$out: File too large' '$work/err'" "$out: message"
    no_tmp "$out"
done
expect 0 "tessellate over an old file" -- "$tool" tessellate -u 2 -o "$work/old.obj"
check "grep -q '^v ' '$work/old.obj'" "old.obj replaced"
no_tmp "a successful write"

# The largest input read is 256 MiB (sparse files of NUL bytes: a parse error at 1:1 when read).
dd if=/dev/zero of="$work/max.bpt" bs=1 count=0 seek=268435456 2>/dev/null
dd if=/dev/zero of="$work/over.bpt" bs=1 count=0 seek=268435457 2>/dev/null
expect 2 "a file of exactly 256 MiB" -- "$tool" info "$work/max.bpt"
check "grep -q 'max.bpt:1:1:' '$work/err'" "256 MiB file read and parsed"
expect 2 "256 MiB on standard input" -- sh -c "exec '$tool' info - <'$work/max.bpt'"
check "grep -q '<stdin>:1:1:' '$work/err'" "256 MiB of standard input read and parsed"
expect 2 "a file of 256 MiB + 1" -- "$tool" info "$work/over.bpt"
check "grep -q 'larger than 256 MiB' '$work/err'" "over-large file refused"
expect 2 "256 MiB + 1 on standard input" -- sh -c "exec '$tool' info - <'$work/over.bpt'"
check "grep -q 'more than 256 MiB' '$work/err'" "over-large standard input refused"
rm -f "$work/max.bpt" "$work/over.bpt"

# Command lines: rates out of range are usage errors naming the option; values are never cut;
# a FILE and --builtin together are refused; points where the surface overflows are errors.
expect 1 "-u 0" -- "$tool" tessellate -u 0 -o "$work/z.obj"
check "grep -q -- '-u 0: segments out of range' '$work/err'" "-u 0 message"
expect 1 "--uniform 2x1025" -- "$tool" tessellate --uniform 2x1025 -o "$work/z.obj"
check "grep -q -- '--uniform 2x1025' '$work/err'" "--uniform message"
# zeros: N zeros
zeros() { printf "%0${1}d" 0; }
# values whose first 63 (127) bytes are valid on their own
expect 1 "-u with a value over 63 bytes" -- "$tool" tessellate -u "$(zeros 62)5junk" -o "$work/z.obj"
check "grep -q 'value of -u too long' '$work/err'" "long value message"
check "[ ! -e '$work/z.obj' ]" "no mesh from a bad command line"
expect 1 "--size with a value over 63 bytes" -- "$tool" render --size "64x$(zeros 58)64junk" -o "$work/z.png"
expect 1 "--color with a value over 127 bytes" -- "$tool" render --color "1,1,$(zeros 122)1junk" -o "$work/z.png"
check "[ ! -e '$work/z.png' ]" "no picture from a bad command line"
expect 1 "-b NAME FILE" -- "$tool" info -b teacup "$hostile/unit_box.bpt"
check "grep -q 'more than one input' '$work/err'" "-b NAME FILE message"
expect 1 "FILE -b NAME" -- "$tool" info "$hostile/unit_box.bpt" --builtin teacup
expect 1 "-b twice" -- "$tool" info -b teacup -b teaspoon
expect 2 "eval at u = 1e308" -- "$tool" eval --point 0 1e308 0
check "! grep -q nan '$work/out' && grep -q 'overflows' '$work/err'" "eval overflow message"
expect 2 "eval normals at u = -1e200" -- "$tool" eval --normals --point 3 -1e200 0.5

echo "test_cli_hostile: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
