#!/usr/bin/env bash
# Install dealvem into PREFIX in both variants, as deal.II installs
# libdeal.ii.so and libdeal.ii.g.so side by side:
#   Release: libdealvem.so, the program bin/dealvem, headers, CMake package
#            (built in BUILD_DIR, default ./build; only the library and the
#            program are built there for the install)
#   Debug:   libdealvem.g.so, library only (built in DEBUG_BUILD_DIR,
#            default ./build-debug, without tests, examples, benchmarks)
# A project using find_package(dealvem) then gets the one matching its
# CMAKE_BUILD_TYPE (README, "Using dealvem from your own CMake project").
#   usage: scripts/install.sh PREFIX
#   JOBS=n  parallel compile jobs (default: all cores)
set -euo pipefail
if [ $# -ne 1 ]; then
  echo "usage: $0 PREFIX" >&2
  exit 2
fi
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PREFIX="$1"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
DEBUG_BUILD_DIR="${DEBUG_BUILD_DIR:-$ROOT/build-debug}"
JOBS="${JOBS:-$(nproc)}"

mkdir -p "$BUILD_DIR" "$DEBUG_BUILD_DIR"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release > "$BUILD_DIR/configure.log" 2>&1 || {
  cat "$BUILD_DIR/configure.log"; exit 1; }
if grep -q '^DEALVEM_SANITIZE:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
  echo "$BUILD_DIR is a sanitizer build; set BUILD_DIR to a Release build directory" >&2
  exit 1
fi
cmake --build "$BUILD_DIR" -j "$JOBS" --target dealvem dealvem_app
cmake --install "$BUILD_DIR" --prefix "$PREFIX"

# the same CGAL choice as the Release build: both variants share the
# installed dealvem/config.h and dealvemConfig.cmake
with_cgal="$(sed -n 's/^DEALVEM_WITH_CGAL:BOOL=//p' "$BUILD_DIR/CMakeCache.txt")"
cmake -S "$ROOT" -B "$DEBUG_BUILD_DIR" -DCMAKE_BUILD_TYPE=Debug -DDEALVEM_WITH_CGAL="${with_cgal:-OFF}" \
  -DDEALVEM_ENABLE_PROGRAM=OFF -DDEALVEM_ENABLE_TESTS=OFF -DDEALVEM_ENABLE_EXAMPLES=OFF \
  -DDEALVEM_ENABLE_BENCHMARKS=OFF -DDEALVEM_ENABLE_DOC=OFF > "$DEBUG_BUILD_DIR/configure.log" 2>&1 || {
  cat "$DEBUG_BUILD_DIR/configure.log"; exit 1; }
cmake --build "$DEBUG_BUILD_DIR" -j "$JOBS"
cmake --install "$DEBUG_BUILD_DIR" --prefix "$PREFIX"
echo "dealvem installed in $PREFIX:"; find "$PREFIX" -name 'libdealvem*.so' -print
echo "use it with -Ddealvem_DIR=$(cd "$PREFIX" && ls -d "$PWD"/lib*/cmake/dealvem)"
