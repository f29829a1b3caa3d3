#!/usr/bin/env bash
# np = 1 (serial path) against np = 2 (distributed path) on the 1e6-DoF
# elasticity case: wall time of the stages (from the JSON summaries) and the
# peak memory (VmHWM) of each process. Run on an otherwise idle machine:
#   BUILD_DIR=build bash benchmarks/mpi/run_mpi_benchmark.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
WORK="$BUILD_DIR/benchmarks/mpi"
mkdir -p "$WORK"
cd "$WORK"
FLAGS=(--oversubscribe)
[ "$(id -u)" = 0 ] && FLAGS+=(--allow-run-as-root)
for np in 1 2; do
  sed "s/Base name = mpi-1e6/Base name = mpi-1e6-np$np/" "$ROOT/benchmarks/mpi/elasticity-1e6.prm" > np$np.prm
  /usr/bin/time -f "np = $np: %e s wall in total" mpirun "${FLAGS[@]}" -np $np "$BUILD_DIR/bin/dealvem" np$np.prm
done
python3 - <<'PY'
import json
for np in (1, 2):
    j = json.load(open(f"output/mpi-1e6-np{np}.json"))
    c = j["cycles"]["0"]
    t = c["timings"]
    mem = [v for k, v in sorted(j["memory"].items())]
    print(f"np = {np}: {int(c['dofs'])} DoFs, " + ", ".join(f"{k} {v:.2f} s" for k, v in sorted(t.items())) +
          f", CG iterations {int(c['solver_iterations'])}, peak memory per process " + ", ".join(f"{m:.0f} MB" for m in mem))
PY
