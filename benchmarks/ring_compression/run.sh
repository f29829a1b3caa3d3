#!/usr/bin/env bash
# The rubber ring compressed between two rigid plates (issue 23): the
# deal.II FE_Q(2) reference (ring_reference.cc, plain deal.II, an augmented
# Lagrangian against the plate) and dealvem's finite sliding
# (ring_vem.cc, k = 1 and 2) in one script, with the ratio VEM / reference
# of the plate force at every d. Builds benchmark_ring_reference and
# benchmark_ring_vem in the dealvem build (BUILD_DIR, default
# <repo>/build; one core) and runs them one after the other (one thread).
#
# Environment:
#   BUILD_DIR       the dealvem build directory (default: <repo>/build)
#   OUT             the report (default: $BUILD_DIR/benchmarks/ring_compression.md)
#   REF_MAX         the finest refinement of the reference (default 5:
#                   4096 cells, 33410 DoFs, about 4 minutes; 6 takes ~30)
#   VEM_CASES       "k:r:m ..." the VEM runs (order, ring refinements, plate
#                   cells; default "2:1:19 2:2:31 2:3:60 2:4:100 1:3:60")
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
OUT="${OUT:-$BUILD/benchmarks/ring_compression.md}"
REF_MAX="${REF_MAX:-5}"
VEM_CASES="${VEM_CASES:-2:1:19 2:2:31 2:3:60 2:4:100 1:3:60}"
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

[ -f "$BUILD/CMakeCache.txt" ] || BUILD_DIR="$BUILD" JOBS=1 bash "$ROOT/scripts/build.sh" --target dealvem > /dev/null
cmake --build "$BUILD" -j1 --target benchmark_ring_reference benchmark_ring_vem > /dev/null
mkdir -p "$(dirname "$OUT")"

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
start=$(date +%s)
load_start="$(cut -d' ' -f1-3 /proc/loadavg)"
t0=$(date +%s)
"$BUILD/benchmarks/benchmark_ring_reference" --min-refinements 2 --max-refinements "$REF_MAX" > "$TMP/reference.txt"
t_ref=$(( $(date +%s) - t0 ))
awk '/^# reference:/ {on = 1; next} on && NF == 3 {print $1, $2, $3}' "$TMP/reference.txt" > "$TMP/ref.dat"
for case in $VEM_CASES; do
  IFS=: read -r k r m <<< "$case"
  t0=$(date +%s)
  if "$BUILD/benchmarks/benchmark_ring_vem" "$k" "$r" "$m" > "$TMP/vem-$k-$r.txt"; then
    echo "$(( $(date +%s) - t0 ))" > "$TMP/vem-$k-$r.time"
  else
    echo "failed" > "$TMP/vem-$k-$r.time"
  fi
done
{
  echo "## Rubber ring compressed by a rigid plate: dealvem finite sliding against deal.II FE_Q(2)"
  echo
  echo "benchmarks/ring_compression/run.sh (REF_MAX=$REF_MAX, VEM_CASES=\"$VEM_CASES\")"
  echo
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'), dealvem $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(getconf _NPROCESSORS_ONLN) cores (a VM shared with other work), one thread"
  echo "- load average at start / end: $load_start / $(cut -d' ' -f1-3 /proc/loadavg); run time $(( $(date +%s) - start )) s (reference $t_ref s)"
  echo
  echo "Plate force per unit thickness on the quarter model; the ratio VEM / reference."
  echo
  header="| d | reference (FE_Q(2), error estimate) |"
  rule="|---|---|"
  for case in $VEM_CASES; do
    IFS=: read -r k r m <<< "$case"
    dofs=$(awk '$1 == "0.05" && NF >= 8 {print $2; exit}' "$TMP/vem-$k-$r.txt")
    header="$header k = $k, r = $r ($dofs DoFs, $(cat "$TMP/vem-$k-$r.time") s) |"
    rule="$rule---|"
  done
  echo "$header"
  echo "$rule"
  while read -r d f e; do
    line="| $d | $f ($e) |"
    for case in $VEM_CASES; do
      IFS=: read -r k r m <<< "$case"
      v=$(awk -v d="$d" '/^# vem:/ {on = 1; next} on && $1 == d {print $2}' "$TMP/vem-$k-$r.txt")
      if [ -n "$v" ] && [ "$f" != "nan" ]; then
        line="$line $(awk -v v="$v" -v f="$f" 'BEGIN {printf "%.6f", v / f}') |"
      else
        line="$line - |"
      fi
    done
    echo "$line"
  done < "$TMP/ref.dat"
  echo
  echo "### The reference program's report"
  echo
  echo '```'
  cat "$TMP/reference.txt"
  echo '```'
  for case in $VEM_CASES; do
    IFS=: read -r k r m <<< "$case"
    echo
    echo "### VEM k = $k, r = $r, plate $m x 3"
    echo
    echo '```'
    cat "$TMP/vem-$k-$r.txt"
    echo '```'
  done
} > "$OUT"
cat "$OUT"
