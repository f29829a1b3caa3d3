#!/usr/bin/env bash
# 3D elasticity on polyhedra against deal.II's FE_Q(1) and FE_Q(2): builds
# benchmark_polyhedral in the dealvem build (BUILD_DIR, default <repo>/build),
# runs every case at every size in a process of its own (one thread), or in
# NP MPI processes of one thread each, and writes a Markdown table (time per
# DoF of assembly and solve, CG-AMG iterations, peak memory per DoF). See the
# header of polyhedral.cc.
#
# Environment:
#   BUILD_DIR  the dealvem build directory (default: <repo>/build)
#   SIZES      target DoF counts (default: "100000 300000")
#   NP         MPI processes per case (default: 1, no mpirun); with NP > 1
#              the times are the slowest process's, the memory the sum over
#              the processes
#   CASES      the cases (default: "feq1 feq2 vem-hex vem-voronoi")
#   OUT        the report (default: $BUILD_DIR/benchmarks/polyhedral.md)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
OUT="${OUT:-$BUILD/benchmarks/polyhedral.md}"
SIZES="${SIZES:-100000 300000}"
NP="${NP:-1}"
CASES="${CASES:-feq1 feq2 vem-hex vem-voronoi}"
[[ "$NP" =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: NP must be a positive integer, not '$NP'" >&2; exit 1; }
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 OMPI_MCA_ess_singleton_isolated=1

[ -f "$BUILD/CMakeCache.txt" ] || BUILD_DIR="$BUILD" JOBS=1 bash "$ROOT/scripts/build.sh" --target dealvem > /dev/null
cmake --build "$BUILD" -j1 --target benchmark_polyhedral > /dev/null
mkdir -p "$(dirname "$OUT")"
# one process: run the program itself (the serial path, as before MPI);
# more: mpirun, which may put more processes than cores on the machine
LAUNCH=()
if [ "$NP" -gt 1 ]; then
  LAUNCH=(mpirun --oversubscribe -np "$NP")
  [ "$(id -u)" -ne 0 ] || LAUNCH+=(--allow-run-as-root)
  PROCESSES="$NP MPI processes"
  HOW="$NP MPI processes per case (mpirun), one thread each; times: the slowest process in each stage; memory: the sum of the processes' peaks"
else
  PROCESSES="one process"
  HOW="one process per case, one thread"
fi
{
  echo "## 3D elasticity: VEM k = 1 on polyhedra against deal.II FE_Q(1) and FE_Q(2), $PROCESSES"
  echo
  echo "benchmarks/polyhedral/run.sh, SIZES=\"$SIZES\" NP=$NP: $HOW; $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load at start $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%Y-%m-%d)"
  echo
  echo "| case | cells | DoFs | assembly µs/DoF | solve µs/DoF | CG-AMG iterations | peak memory B/DoF | matrix entries per row |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|"
  for n in $SIZES; do
    for c in $CASES; do
      # a case that fails (out of memory, say) gets a row saying so
      if ! line="$(${LAUNCH[@]+"${LAUNCH[@]}"} "$BUILD/benchmarks/benchmark_polyhedral" --case $c --dofs $n 2>&1 | grep '^RESULT')"; then
        echo "| $c | – | about $n | failed (see: ${LAUNCH[*]}${LAUNCH[*]:+ }benchmark_polyhedral --case $c --dofs $n) | | | | |"
        continue
      fi
      read -r _ name cells dofs tmesh tasm tsolve its mb nnz <<< "$line"
      awk -v n="$name" -v c="$cells" -v d="$dofs" -v a="$tasm" -v s="$tsolve" -v i="$its" -v m="$mb" -v z="$nnz" \
        'BEGIN { printf "| %s | %d | %d | %.2f | %.2f | %d | %.0f | %.1f |\n", n, c, d, 1e6*a/d, 1e6*s/d, i, m*1048576/d, z }'
    done
  done
} > "$OUT"
cat "$OUT"
