# Checks shared by the tool's test scripts (sourced; they set $work and count checks and fails).
#   expect CODE DESCRIPTION -- command...  run it (under `timeout $limit` when limit is set), keep
#                                          stdout/stderr in $work/out and $work/err, compare the exit code
#   has FILE TEXT DESCRIPTION              $work/FILE contains the fixed string TEXT
#   check SHELL-TEST DESCRIPTION           the test (eval'd) succeeds
checks=0 fails=0

expect() {
    code=$1 what=$2
    shift 3
    if [ -n "${limit:-}" ]; then
        timeout "$limit" "$@" >"$work/out" 2>"$work/err"
    else
        "$@" >"$work/out" 2>"$work/err"
    fi
    got=$?
    checks=$((checks + 1))
    if [ "$got" -ne "$code" ]; then
        fails=$((fails + 1))
        echo "FAIL: $what: exit $got, expected $code"; cat "$work/err"
    fi
}

has() {
    checks=$((checks + 1))
    if ! grep -qF -- "$2" "$work/$1"; then
        fails=$((fails + 1))
        echo "FAIL: $3: '$2' not in $1:"; cat "$work/$1"
    fi
}

check() {
    checks=$((checks + 1))
    if ! eval "$1"; then
        fails=$((fails + 1))
        echo "FAIL: $2"; cat "$work/err"
    fi
}
