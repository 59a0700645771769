#!/bin/sh
# What `cmake --install` puts in a prefix, as Debian policy wants it where that costs nothing:
# the licence as share/doc/bezsurf/copyright, the man page gzipped (no name or time in its header),
# and the CPack configuration strips the binaries of the packages.
# usage: check_install.sh BUILD_DIR WORK_DIR
build=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
fails=0
fail() { echo "FAIL: $1"; fails=$((fails + 1)); }
cmake --install "$build" --prefix "$work/p" >"$work/log" 2>&1 || { cat "$work/log"; fail "cmake --install"; }
[ -f "$work/p/share/doc/bezsurf/copyright" ] || fail "no share/doc/bezsurf/copyright"
man=$work/p/share/man/man1/bezsurf.1
if command -v gzip >/dev/null; then
    [ -f "$man.gz" ] && [ ! -e "$man" ] || fail "man page not gzipped"
    gzip -dc "$man.gz" | grep -q '^\.TH BEZSURF' || fail "bezsurf.1.gz is not the man page"
    # bytes 4..7 of a gzip header: flags (no FNAME) and mtime (0)
    [ "$(od -An -tx1 -j3 -N5 "$man.gz" | tr -d ' \n')" = "0000000000" ] || fail "gzip header has a name or a time"
fi
grep -q 'set(CPACK_STRIP_FILES "ON")' "$build/CPackConfig.cmake" || fail "packages not stripped"
echo "check_install: $fails failures"
[ "$fails" -eq 0 ]
