#!/usr/bin/env bash
# Tooth root stress of step-12's pinion (gear_root_stress.cc): builds
# benchmark_gear_root_stress in the dealvem build (BUILD_DIR, default
# <repo>/build; one core), runs it (one thread) with the load at step-12's
# roll angle -1.447 degrees and at the highest point of single tooth contact
# (with ISO 6336-3 method B), and writes a Markdown report: the machine
# notes, then the program's tables. Arguments are passed to both runs (see
# the header of gear_root_stress.cc: --levels, --vem-levels).
#
# Environment:
#   BUILD_DIR  the dealvem build directory (default: <repo>/build)
#   OUT        the report (default: $BUILD_DIR/benchmarks/gear_root_stress.md)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
OUT="${OUT:-$BUILD/benchmarks/gear_root_stress.md}"
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

[ -f "$BUILD/CMakeCache.txt" ] || BUILD_DIR="$BUILD" JOBS=1 bash "$ROOT/scripts/build.sh" --target dealvem > /dev/null
cmake --build "$BUILD" -j1 --target benchmark_gear_root_stress > /dev/null

TMP="$(mktemp)"
start=$(date +%s)
load_start="$(cut -d' ' -f1-3 /proc/loadavg)"
{
  "$BUILD/benchmarks/benchmark_gear_root_stress" "$@"
  echo
  "$BUILD/benchmarks/benchmark_gear_root_stress" --hpstc "$@"
} > "$TMP"
{
  echo "## Tooth root stress of step-12's pinion: VEM against deal.II FE_Q(2) and ISO 6336-3"
  echo
  echo "benchmarks/gear_root_stress/run.sh $*"
  echo
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'), dealvem $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(getconf _NPROCESSORS_ONLN) cores (a VM shared with other work), one thread"
  echo "- load average at start / end: $load_start / $(cut -d' ' -f1-3 /proc/loadavg); run time $(( $(date +%s) - start )) s"
  echo
  cat "$TMP"
} > "$OUT"
rm -f "$TMP"
cat "$OUT"
