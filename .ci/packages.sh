#!/usr/bin/env bash
# The packages as a user gets them (docs/building.md): a Debian package and a tarball made by CPack
# from a build configured for /usr. The tarball's tool runs from wherever it is unpacked. The .deb
# is installed on this machine with dpkg, then the tool, its man page and both consumers are used
# with no environment variables, as after `apt install ./bezsurf_*.deb`, and so is the Rust crate
# as a path dependency; the package is removed again at the end, whatever happens.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${PKG_BUILD:-build-pkg}
rm -rf "$build"
cmake -S . -B "$build" -DCMAKE_INSTALL_PREFIX=/usr -DBUILD_TESTING=OFF -DBS_BUILD_BENCH=OFF \
  -DBS_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j2 >/dev/null
(cd "$build" && cpack -G "DEB;TGZ" >/dev/null)
deb=$(ls "$build"/bezsurf_*.deb)
tgz=$(ls "$build"/bezsurf-*.tar.gz)
echo "built $(basename "$deb") and $(basename "$tgz")"

# What the .deb holds: library, headers, pkg-config file, CMake package, tool, man page.
contents=$(dpkg-deb --contents "$deb")
for want in 'usr/lib/.*/libbezsurf\.so\.1 ' 'usr/lib/.*/libbezsurf\.so ' 'usr/include/bezsurf\.h' \
    'usr/include/bezsurf/core\.h' 'usr/lib/.*/pkgconfig/bezsurf\.pc' \
    'usr/lib/.*/cmake/bezsurf/bezsurfConfig\.cmake' 'usr/bin/bezsurf' 'usr/share/man/man1/bezsurf\.1\.gz' \
    'usr/share/doc/bezsurf/copyright'; do
  echo "$contents" | grep -q "$want" || { echo "the .deb has no $want" >&2; exit 1; }
done

scratch=$(mktemp -d)
installed=0
cleanup() {
  [ "$installed" = 1 ] && dpkg --purge bezsurf >/dev/null
  rm -rf "$scratch"
}
trap cleanup EXIT
unset LD_LIBRARY_PATH PKG_CONFIG_PATH CMAKE_PREFIX_PATH BEZSURF_LIBRARY BEZSURF_LIB_DIR

# The tarball, unpacked anywhere.
tar xzf "$tgz" -C "$scratch"
"$scratch"/bezsurf-*/bin/bezsurf info >/dev/null
echo "tarball: the unpacked tool runs"

# The .deb, installed.
if dpkg-query -W -f '${Status}' bezsurf 2>/dev/null | grep -q "ok installed"; then
  echo "a bezsurf package is already installed here; not replacing it" >&2
  exit 1
fi
dpkg -i "$deb" >/dev/null
installed=1
bezsurf --version
bezsurf info >/dev/null
man -w bezsurf >/dev/null
"$root/tests/consumer/pkgconfig/build.sh" "$scratch/consumer-pc"
"$scratch/consumer-pc"
cmake -S "$root/tests/consumer/cmake" -B "$scratch/consumer-cmake" >/dev/null
cmake --build "$scratch/consumer-cmake" >/dev/null
"$scratch/consumer-cmake/consumer"
echo "deb: tool, man page, pkg-config and CMake consumers work with no environment variables"
# The Rust crate as a path dependency of a new crate, finding the installed library through
# pkg-config alone (docs/rust.md, "Using the crate").
if command -v cargo >/dev/null 2>&1; then
  CARGO_TARGET_DIR="$scratch/rust-target" sh "$root/bindings/rust/check-dependent.sh" cargo \
    "$root/bindings/rust" "$root/docs/rust.md" "$scratch/rust"
fi
