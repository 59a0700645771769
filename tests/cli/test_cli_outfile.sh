#!/bin/sh
# Output files of tessellate and render (docs/cli.md, "Output files"): a signal (INT, TERM, HUP)
# during the job removes the temporary file and leaves the old file whole, the exit status showing
# the signal; a symbolic link is written through and stays a link; a file the user may not write,
# an empty name, a directory and a missing directory are refused before any work (status 3, one
# line naming the file, no report, nothing written).
# usage: test_cli_outfile.sh TOOL WORK_DIR
tool=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
. "$(dirname "$0")/assert.sh"
limit=60

# temporary files in directory $1 matching $2 (default: any of the tool's or the library's)
tmps() { ls -A "$1" | grep "^\.bezsurf-${2:-}"; }

# wait_tmp DIR PATTERN PID: until such a temporary file shows in DIR (0), or PID has ended or 30 s
# have passed (1)
wait_tmp() {
    n=0
    while [ $n -lt 600 ]; do
        [ -n "$(tmps "$1" "$2")" ] && return 0
        kill -0 "$3" 2>/dev/null || return 1
        sleep 0.05
        n=$((n + 1))
    done
    return 1
}

# SIGINT is ignored in the background jobs of a script: give it back its default action, where
# env can (the tool keeps an ignored signal ignored, as nohup expects)
run_int=""
if env --default-signal=INT true 2>/dev/null; then
    run_int="env --default-signal=INT"
fi

# signalled NAME NUMBER PATTERN OUT -- command...: run it in the background, send signal NAME once
# a temporary file matching PATTERN shows beside OUT (in a directory of its own), then check the
# exit status 128 + NUMBER, no temporary file left and OUT's old content
signalled() {
    sig=$1 num=$2 pattern=$3 out=$4
    shift 5
    dir=$(dirname "$out")
    rm -rf "$dir" && mkdir -p "$dir" || exit 1
    echo "old $sig" >"$out"
    $run "$@" >"$work/out" 2>"$work/err" &
    pid=$!
    wait_tmp "$dir" "$pattern" $pid
    seen=$?
    kill -s "$sig" $pid 2>/dev/null
    wait $pid
    status=$?
    checks=$((checks + 1))
    if [ $seen -ne 0 ]; then
        fails=$((fails + 1))
        echo "FAIL: $*: no temporary file '$pattern' while it ran (exit $status)"
    fi
    check "[ $status -eq $((128 + num)) ]" "$*: exit $status, not killed by SIG$sig"
    check "[ -z \"\$(tmps '$dir')\" ]" "$*: SIG$sig left a temporary file: $(tmps "$dir")"
    check "[ \"\$(cat '$out')\" = 'old $sig' ]" "$*: SIG$sig changed the old file"
}

# Signals while the tool computes: the teapot at 128 x 128 (1 M triangles, 140 MB of OBJ) and
# 100,000 closest points drawn on it (a few seconds each).
for s in "INT 2" "TERM 15" "HUP 1"; do
    set -- $s
    run=""
    if [ $1 = INT ]; then
        run=$run_int
        [ -n "$run" ] || { echo "skip: SIGINT (env has no --default-signal)"; continue; }
    fi
    signalled $1 $2 "" "$work/sig_mesh_$1/mesh.obj" -- "$tool" tessellate -u 128 -o "$work/sig_mesh_$1/mesh.obj"
    signalled $1 $2 "" "$work/sig_pic_$1/pic.png" -- \
        "$tool" render --size 64x64 --ss 1 --closest 100000 -o "$work/sig_pic_$1/pic.png"
done
# While the library writes the mesh through a temporary file of its own (.bezsurf-*.tmp) beside
# the tool's: the signal waits for that write, then the tool's file is removed too.
run=""
signalled TERM 15 '.*\.tmp$' "$work/sig_write/mesh.obj" -- "$tool" tessellate -u 128 -o "$work/sig_write/mesh.obj"

# A symbolic link is written through: its final target is replaced, the link stays.
mkdir -p "$work/real" "$work/links" || exit 1
echo old >"$work/real/mesh.obj"
echo old >"$work/real/pic.png"
ln -s ../real/mesh.obj "$work/links/mesh.obj"
ln -s "$work/links/mesh.obj" "$work/links/chain.obj" # a link to a link
ln -s ../real/pic.png "$work/links/pic.png"
expect 0 "tessellate through a link" -- "$tool" tessellate -u 2 -o "$work/links/mesh.obj"
check "[ -L '$work/links/mesh.obj' ] && grep -q '^v ' '$work/real/mesh.obj'" "link kept, its target written"
has out "links/mesh.obj: " "the report names the link"
echo old >"$work/real/mesh.obj"
expect 0 "tessellate through a chain of links" -- "$tool" tessellate -u 2 -o "$work/links/chain.obj"
check "[ -L '$work/links/chain.obj' ] && [ -L '$work/links/mesh.obj' ] && grep -q '^v ' '$work/real/mesh.obj'" \
    "chain kept, its final target written"
expect 0 "render through a link" -- "$tool" render --size 32x32 --ss 1 -o "$work/links/pic.png"
check "[ -L '$work/links/pic.png' ] && [ \"\$(head -c 4 '$work/real/pic.png' | tail -c 3)\" = PNG ]" \
    "link kept, the picture in its target"
check "[ -z \"\$(tmps '$work/real')\" ] && [ -z \"\$(tmps '$work/links')\" ]" "no temporary file beside link or target"
# a link to a missing file is not written through (as cp does not): nothing is created
ln -s ../real/missing.obj "$work/links/dangling.obj"
expect 3 "tessellate to a dangling link" -- "$tool" tessellate -u 2 -o "$work/links/dangling.obj"
has err "cannot write $work/links/dangling.obj: a symbolic link to a missing file" "dangling link message"
check "[ -L '$work/links/dangling.obj' ] && [ ! -e '$work/real/missing.obj' ] && [ ! -s '$work/out' ]" \
    "dangling link kept, nothing written"

# Refused before any work: one line naming the file, no report, nothing written. The job would
# be long (1 M triangles, or 100,000 closest points), so the limit catches a check made after it.
limit=5
long_mesh='tessellate -u 128'
long_pic='render --closest 100000 --size 64x64 --ss 1'
refused() {
    case_name=$1 target=$2 msg=$3 # (expect sets $what)
    for job in "$long_mesh" "$long_pic"; do
        expect 3 "$case_name: $job" -- "$tool" $job -o "$target"
        has err "$msg" "$case_name: $job: message"
        check "[ ! -s '$work/out' ] && [ \$(wc -l <'$work/err') -eq 1 ]" "$case_name: $job: one line, no report"
    done
}
refused "empty name" "" "cannot write '': the file name is empty"
check "[ -z \"\$(tmps .)\" ]" "empty name: no temporary file here"
mkdir -p "$work/dir.obj"
refused "a directory" "$work/dir.obj" "cannot write $work/dir.obj: Is a directory"
refused "a missing directory" "$work/no/such/x.obj" "cannot write $work/no/such/x.obj: No such file or directory"

# A file the user may not write is refused, as cp refuses it (root may write any file, as with
# cp: the check runs as nobody where the test runs as root).
as_user=""
if [ "$(id -u)" -eq 0 ]; then
    as_user="setpriv --reuid=nobody --regid=nogroup --clear-groups"
    $as_user true 2>/dev/null && $as_user test -x "$tool" || as_user=none
fi
if [ "$as_user" = none ]; then
    echo "skip: read-only file (root, and no setpriv to run as nobody)"
else
    mkdir -p "$work/ro" && chmod 777 "$work/ro" || exit 1
    echo old >"$work/ro/mesh.obj"
    chmod 444 "$work/ro/mesh.obj"
    for job in "$long_mesh" "$long_pic"; do
        expect 3 "read-only file: $job" -- $as_user "$tool" $job -o "$work/ro/mesh.obj"
        has err "cannot write $work/ro/mesh.obj: Permission denied" "read-only file: $job: message"
        check "[ ! -s '$work/out' ] && [ \"\$(cat '$work/ro/mesh.obj')\" = old ] && [ -z \"\$(tmps '$work/ro')\" ]" \
            "read-only file: $job: kept, nothing written"
    done
    # the same file with its write bit: replaced, with its permissions
    chmod 644 "$work/ro/mesh.obj"
    chown nobody "$work/ro/mesh.obj" 2>/dev/null
    expect 0 "writable file" -- $as_user "$tool" tessellate -u 2 -o "$work/ro/mesh.obj"
    check "grep -q '^v ' '$work/ro/mesh.obj'" "writable file replaced"
fi

limit=60

echo "test_cli_outfile: $checks checks, $fails failures"
[ "$fails" -eq 0 ]
