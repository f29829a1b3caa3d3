#!/usr/bin/env bash
# Where the build time goes: configure a fresh Release build in
# ./build-profile (override with BUILD_DIR) with every compile and link run
# through scripts/timed.sh (user CPU seconds per command), build everything
# the test suite needs, and print the CPU time of the library's compiles,
# the programs' compiles, the links and the slowest commands. CPU seconds do
# not depend on what else the machine runs; wall time on 2 idle cores is
# about half the total.
#   extra arguments go to the configure line, e.g.
#   bash scripts/build-profile.sh -DDEALVEM_PRECOMPILED_HEADERS=OFF
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build-profile}"
JOBS="${JOBS:-$(nproc)}"
[ -x /usr/bin/time ] || { echo "build-profile: needs /usr/bin/time (apt-get install time)" >&2; exit 1; }
rm -rf "$BUILD_DIR"
mkdir -p "$BUILD_DIR"
export DEALVEM_TIMED_LOG="$BUILD_DIR/times.log"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER_LAUNCHER="$ROOT/scripts/timed.sh" \
  -DCMAKE_CXX_LINKER_LAUNCHER="$ROOT/scripts/timed.sh" "$@" > "$BUILD_DIR/configure.log"
start=$SECONDS
cmake --build "$BUILD_DIR" -j "$JOBS" > "$BUILD_DIR/build.log"
wall=$((SECONDS - start))
awk -v wall="$wall" '
  { t = $1 + $2; name = $4 }
  name ~ /CMakeFiles\/dealvem\.dir\// { lib += t; nlib++ }
  name ~ /\.o$/ && name !~ /CMakeFiles\/dealvem\.dir\// { prog += t; nprog++ }
  name ~ /\.gch$/ { pch += t }
  name !~ /\.(o|gch)$/ { link += t; nlink++ }
  { print t, name > "/dev/stderr" }
  END {
    printf "build wall time: %d s (%s jobs)\n", wall, ENVIRON["JOBS"]
    printf "library compiles: %d files, %.0f s CPU\n", nlib, lib
    printf "precompiled header: %.0f s CPU\n", pch
    printf "program compiles: %d files, %.0f s CPU\n", nprog, prog
    printf "links: %d, %.0f s CPU\n", nlink, link
    printf "total: %.0f s CPU\n", lib + pch + prog + link
  }' "$DEALVEM_TIMED_LOG" 2> "$BUILD_DIR/per-command.txt"
echo "slowest commands (CPU s):"
sort -rn "$BUILD_DIR/per-command.txt" | head -15 | sed "s|$BUILD_DIR/||"
