#!/usr/bin/env bash
# Cook's membrane at finite strain: builds benchmark_cook_membrane in the
# dealvem build (BUILD_DIR, default <repo>/build; one core), runs it (one
# thread) and writes a Markdown report: the machine notes, then the
# program's tables (FE_Q(2) reference with its Richardson extrapolation,
# VEM k = 1, 2 on mapped quads and Voronoi meshes, the tangent assembly
# timing). Arguments are passed to the program (see the header of
# cook_membrane.cc: --fe-max, --vem-max, --voronoi-max, --timing-n, --steps).
#
# Environment:
#   BUILD_DIR  the dealvem build directory (default: <repo>/build)
#   OUT        the report (default: $BUILD_DIR/benchmarks/cook_membrane.md)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
OUT="${OUT:-$BUILD/benchmarks/cook_membrane.md}"
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

[ -f "$BUILD/CMakeCache.txt" ] || BUILD_DIR="$BUILD" JOBS=1 bash "$ROOT/scripts/build.sh" --target dealvem > /dev/null
cmake --build "$BUILD" -j1 --target benchmark_cook_membrane > /dev/null

TMP="$(mktemp)"
start=$(date +%s)
load_start="$(cut -d' ' -f1-3 /proc/loadavg)"
"$BUILD/benchmarks/benchmark_cook_membrane" "$@" > "$TMP"
{
  echo "## Cook's membrane at finite strain: VEM against deal.II FE_Q(2)"
  echo
  echo "benchmarks/cook_membrane/run.sh $*"
  echo
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'), dealvem $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(getconf _NPROCESSORS_ONLN) cores (a VM shared with other work), one thread"
  echo "- load average at start / end: $load_start / $(cut -d' ' -f1-3 /proc/loadavg); run time $(( $(date +%s) - start )) s"
  echo
  cat "$TMP"
} > "$OUT"
rm -f "$TMP"
cat "$OUT"
