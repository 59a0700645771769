#!/bin/sh
# Checks that build.rs explains how to point the build at the library instead of leaving a bare
# linker error: a BEZSURF_LIB_DIR without the library is an error naming the variable, and with
# nothing configured (pkg-config not knowing bezsurf) the script prints the ways to fix it.
# Usage: check-build-hints.sh CARGO MANIFEST   (CARGO_TARGET_DIR in the environment)
set -u
cargo=$1
manifest=$2
status=0

out=$(BEZSURF_LIB_DIR=/nonexistent/bezsurf "$cargo" check --offline --lib --manifest-path "$manifest" 2>&1)
if [ $? -eq 0 ]; then
  echo "FAIL: a BEZSURF_LIB_DIR without the library was accepted" >&2
  status=1
fi
case $out in
  *"BEZSURF_LIB_DIR is set to \`/nonexistent/bezsurf\`, which has no \`libbezsurf.so\`"*) ;;
  *) echo "FAIL: no explanation for a wrong BEZSURF_LIB_DIR:" >&2; echo "$out" >&2; status=1 ;;
esac

# Nothing configured. Skipped when the library is on the compiler's default path (installed).
found=$(${CC:-cc} -print-file-name=libbezsurf.so 2>/dev/null || true)
case $found in
  /*) if [ -e "$found" ]; then echo "libbezsurf is installed ($found): the not-found hint is not checked"; exit $status; fi ;;
esac
out=$(env -u BEZSURF_LIB_DIR PKG_CONFIG_PATH= PKG_CONFIG_LIBDIR=/nonexistent \
  "$cargo" check --offline --lib --manifest-path "$manifest" 2>&1)
for want in "libbezsurf not found" "pkg-config does not know \`bezsurf\`" "PKG_CONFIG_PATH" "BEZSURF_LIB_DIR" \
  "cmake --install build"; do
  case $out in
    *"$want"*) ;;
    *) echo "FAIL: the not-found hint lacks '$want':" >&2; echo "$out" >&2; status=1 ;;
  esac
done
[ $status -eq 0 ] && echo "build.rs explains a missing or misplaced library"
exit $status
