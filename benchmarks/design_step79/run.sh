#!/usr/bin/env bash
# Peer benchmark (issue 42): the MBB beam of deal.II's step-79 optimized by
# step-79 itself (SAND, interior point, Q1 on 48 x 8 quads) and by dealvem
# (nested analysis with MMA or OC, virtual elements k = 1, 2) on the same
# quads and on centroidal Voronoi meshes: the same domain, load, supports,
# material, volume fraction, SIMP exponent and filter radius (see the header
# of design_step79.cc). Prints the machine, then one comparison table
# (step-79 against dealvem on the same 48 x 8 quads, k = 1, MMA first, then
# the other runs), then step-79's final design evaluated by dealvem on the
# same quads; the report goes to stdout and to $OUT, progress to stderr.
#
# step-79 is not copied into this repository: the script takes the Debian
# file /usr/share/doc/libdeal.ii-doc/examples/step-79/step-79.cc (installing
# libdeal.ii-doc when it is missing), copies it into
# $BUILD/benchmarks/step79-peer/, patches the copy (patch_step79.py: print
# the final compliance, volume, iterations and time, write the densities; no
# VTU file per iteration unless STEP79_VTU is set) and builds it with its own
# CMakeLists.txt against the installed deal.II, in Release.
#
# Environment:
#   BUILD_DIR   the dealvem build directory (default: <repo>/build)
#   WORK        where dealvem's run writes its table, CSV and SVG pictures
#               (default: $BUILD_DIR/benchmarks/design_step79)
#   OUT         the report (default: $BUILD_DIR/benchmarks/design_step79.md)
#   QUICK       1: dealvem on the quads and Voronoi 384 only
#   ARGS        more arguments for benchmark_design_step79 (e.g.
#               "--voronoi 384,1536,6144" or "--minimum 1e-9")
#   JOBS        build jobs (default 2)
#   STEP79_VTU  set: step-79 writes its VTU file per iteration (slower)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
WORK="${WORK:-$BUILD/benchmarks/design_step79}"
OUT="${OUT:-$BUILD/benchmarks/design_step79.md}"
JOBS="${JOBS:-2}"
PEER="$BUILD/benchmarks/step79-peer"
STEP79_SRC=/usr/share/doc/libdeal.ii-doc/examples/step-79
PY=/usr/bin/python3
TIME=/usr/bin/time
# one thread each: the timings compare the methods, not their threading
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

log() { echo "design_step79: $*" >&2; }

# --- step-79's source: Debian's libdeal.ii-doc
if [ ! -f "$STEP79_SRC/step-79.cc" ]; then
  log "installing libdeal.ii-doc (Debian) for step-79 ..."
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  $SUDO apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends libdeal.ii-doc >&2
  [ -f "$STEP79_SRC/step-79.cc" ] || { log "no $STEP79_SRC/step-79.cc after the install"; exit 1; }
fi
[ -x "$TIME" ] || { log "$TIME is missing (Debian package 'time')"; exit 1; }
mkdir -p "$PEER/run" "$WORK"

# --- machine notes
MACHINE="$(mktemp)"
trap 'rm -f "$MACHINE"' EXIT
{
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'), dealvem $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?') (work tree)"
  echo "- CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -n 1), $(lscpu | sed -n 's/^CPU(s): *//p' | head -n 1) CPU(s), $(lscpu | sed -n 's/^Thread(s) per core: *//p' | head -n 1) thread(s) per core; memory $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
  echo "- deal.II $(dpkg-query -W -f='${Version}' libdeal.ii-dev 2>/dev/null || echo '?') (Debian), step-79 from libdeal.ii-doc $(dpkg-query -W -f='${Version}' libdeal.ii-doc 2>/dev/null || echo '?'), both Release, one thread per process"
  echo "- load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$MACHINE"

# --- step-79: copy, patch (only when the result changes, so that a second
# run does not rebuild), build
log "patching and building step-79 in $PEER ..."
# move $1.new to $1 unless they are the same
update() {
  if cmp -s "$1.new" "$1" 2>/dev/null; then rm "$1.new"; else mv "$1.new" "$1"; fi
}
cp "$STEP79_SRC/CMakeLists.txt" "$PEER/CMakeLists.txt.new"
update "$PEER/CMakeLists.txt"
"$PY" "$HERE/patch_step79.py" "$STEP79_SRC/step-79.cc" "$PEER/step-79.cc.new"
update "$PEER/step-79.cc"
{
  cmake -S "$PEER" -B "$PEER/build" -DCMAKE_BUILD_TYPE=Release &&
    cmake --build "$PEER/build" -j "$JOBS"
} > "$PEER/build.log" 2>&1 || { log "building step-79 failed (see $PEER/build.log)"; exit 1; }
STEP79="$PEER/build/step-79"
[ -x "$STEP79" ] || { log "no $STEP79 after the build"; exit 1; }

# --- dealvem: configure again (a build directory made before this
# benchmark existed does not know its target), build the benchmark
[ -f "$BUILD/CMakeCache.txt" ] || BUILD_DIR="$BUILD" JOBS="$JOBS" bash "$ROOT/scripts/build.sh" --target dealvem > /dev/null
log "building benchmark_design_step79 in $BUILD ..."
{
  cmake "$BUILD" && cmake --build "$BUILD" -j "$JOBS" --target benchmark_design_step79
} > "$WORK/build.log" 2>&1 || { log "building benchmark_design_step79 failed (see $WORK/build.log)"; exit 1; }
OURS="$BUILD/benchmarks/benchmark_design_step79"

# --- the runs, one after the other
log "running step-79 (SAND; about 40 s on a 2-core VM) ..."
(cd "$PEER/run" && "$TIME" -v -o step-79.time "$STEP79" > step-79.log 2>&1) ||
  { log "step-79 failed (see $PEER/run/step-79.log)"; exit 1; }
log "step-79: $(grep -m1 '^DEALVEM_STEP79' "$PEER/run/step-79.log" | cut -c16-)"

rm -f "$WORK"/design-mbb-*.svg "$WORK"/design_step79*.csv # no pictures of an earlier run in the report
ours_args=()
[ "${QUICK:-0}" = 1 ] && ours_args+=(--quick)
# shellcheck disable=SC2206
[ -n "${ARGS:-}" ] && ours_args+=($ARGS)
log "running dealvem (${ours_args[*]:-all runs}) ..."
(cd "$WORK" && "$TIME" -v -o design_step79.time "$OURS" "${ours_args[@]}" > design_step79.log 2>&1) ||
  { log "benchmark_design_step79 failed (see $WORK/design_step79.log)"; exit 1; }
(cd "$WORK" && "$OURS" --evaluate "$PEER/run/step79_densities.txt" > design_step79_eval.log 2>&1) ||
  { log "benchmark_design_step79 --evaluate failed (see $WORK/design_step79_eval.log)"; exit 1; }
echo "- load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$MACHINE"

# --- the report
{
  echo "## MBB beam: dealvem against deal.II's step-79"
  echo
  echo "bash benchmarks/design_step79/run.sh (QUICK=${QUICK:-0} ARGS=${ARGS:-})"
  echo
  cat "$MACHINE"
  echo "- step-79: process wall $(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$PEER/run/step-79.time"), peak memory $(sed -n 's/.*Maximum resident set size (kbytes): //p' "$PEER/run/step-79.time") kB; dealvem (all its runs in one process): process wall $(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$WORK/design_step79.time"), peak memory $(sed -n 's/.*Maximum resident set size (kbytes): //p' "$WORK/design_step79.time") kB"
  echo
  "$PY" "$HERE/compare.py" --step79-log "$PEER/run/step-79.log" --ours "$WORK/design_step79.csv" \
    --eval "$WORK/design_step79_eval.csv" \
    --step79-wall "$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$PEER/run/step-79.time")"
  echo
  pictures=""
  for f in "$WORK"/design-mbb-*.svg; do pictures+="$(basename "$f") "; done
  echo "Pictures (final densities, black = 1): ${pictures}in $WORK"
} > "$OUT"
cat "$OUT"
log "report: $OUT (step-79's run in $PEER/run, dealvem's in $WORK)"
