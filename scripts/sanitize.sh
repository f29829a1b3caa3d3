#!/usr/bin/env bash
# Sanitizer run: configure a Debug build against deal.II's debug library with
# AddressSanitizer + LeakSanitizer + UBSan (-DDEALVEM_SANITIZE=ON) in
# ./build-sanitize (override with BUILD_DIR), build it
# and run the ctest suite without the labels "long" and "sanitize_slow"
# (tests too slow at -O0 with the sanitizers; they run in the normal suite;
# their programs are not even built here unless -DDEALVEM_SANITIZE_SLOW=ON is
# added to the configure line, see CMakeLists.txt).
# Any sanitizer report makes the test, and so this script, fail.
#   SANITIZE_BUILD_ONLY=1  only configure and build
#   extra arguments are passed to ctest (e.g. -R app/)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build-sanitize}"
JOBS="${JOBS:-$(nproc)}"
mkdir -p "$BUILD_DIR"
# app/downstream installs the Release library of scripts/test.sh (./build, or
# RELEASE_BUILD_DIR) beside this Debug one when it is there, and checks the
# consumers of both variants in one prefix
RELEASE_BUILD_DIR="${RELEASE_BUILD_DIR:-$ROOT/build}"
release_args=(-DDEALVEM_RELEASE_LIBRARY_DIR=)   # none: this variant alone (clears an earlier choice)
if [ -f "$RELEASE_BUILD_DIR/CMakeCache.txt" ] && grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$RELEASE_BUILD_DIR/CMakeCache.txt" \
    && ls "$RELEASE_BUILD_DIR"/libdealvem.so >/dev/null 2>&1; then
  release_args=(-DDEALVEM_RELEASE_LIBRARY_DIR="$RELEASE_BUILD_DIR")
fi
cmake -S "$ROOT" -B "$BUILD_DIR" -DDEALVEM_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
  -DDEALVEM_ENABLE_BENCHMARKS=OFF "${release_args[@]}" > "$BUILD_DIR/configure.log" 2>&1 || {
  cat "$BUILD_DIR/configure.log"; exit 1; }
cmake --build "$BUILD_DIR" -j "$JOBS"
if [ -n "${SANITIZE_BUILD_ONLY:-}" ]; then exit 0; fi

# shellcheck source=scripts/sanitizer-env.sh
source "$ROOT/scripts/sanitizer-env.sh"
cd "$BUILD_DIR"
ctest -LE 'long|sanitize_slow' --output-on-failure -j "$JOBS" --timeout 1500 "$@"
