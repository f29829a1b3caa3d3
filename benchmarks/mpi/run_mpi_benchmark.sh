#!/usr/bin/env bash
# np = 1 (serial path) against np = 2 (distributed path) on two 1e6-DoF
# cases, each run once per np with the same parameter file:
#   - elasticity-1e6.prm: one body, 354 x 354 quads, k = 2, CG with the
#     p-multigrid to 1e-8 (serial: LinearSolver; np = 2: ParallelLinearSolver);
#   - contact-1e6.prm: the contact patch test, 990,216 DoFs, 'CG-AMG
#     constraints' (serial: SaddlePointSolver; np = 2: DistributedContactSolver).
# Prints the wall time of the stages (from the JSON summaries) and the peak
# memory (VmHWM) of each process. Also runs two serial elasticity runs at
# the same time, which shows how much the two cores slow each other down on
# memory-bound work (the ceiling of any np = 2 speed-up on this machine).
# Run on an otherwise idle machine:
#   BUILD_DIR=$PWD/build bash benchmarks/mpi/run_mpi_benchmark.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
BUILD_DIR="$(cd "$BUILD_DIR" && pwd)"
WORK="$BUILD_DIR/benchmarks/mpi"
mkdir -p "$WORK"
cd "$WORK"
FLAGS=(--oversubscribe)
[ "$(id -u)" = 0 ] && FLAGS+=(--allow-run-as-root)
for case in elasticity contact; do
  for np in 1 2; do
    sed "s/Base name *= *\(.*\)-1e6/Base name = \1-1e6-np$np/" "$ROOT/benchmarks/mpi/$case-1e6.prm" > $case-np$np.prm
    /usr/bin/time -f "$case np = $np: %e s wall in total" mpirun "${FLAGS[@]}" -np $np "$BUILD_DIR/bin/dealvem" \
      $case-np$np.prm > $case-np$np.log 2>&1 || { cat $case-np$np.log; exit 1; }

  done
done
# two independent serial runs at once (same input as elasticity np = 1)
sed "s/Base name *= *.*/Base name = concurrent-a/" elasticity-np1.prm > concurrent-a.prm
sed "s/Base name *= *.*/Base name = concurrent-b/" elasticity-np1.prm > concurrent-b.prm
"$BUILD_DIR/bin/dealvem" concurrent-a.prm > concurrent-a.log 2>&1 &
"$BUILD_DIR/bin/dealvem" concurrent-b.prm > concurrent-b.log 2>&1
wait
python3 - <<'PY'
import json
def mem(j):
    return ", ".join(f"{v:.0f} MB" for k, v in sorted(j.get("memory", {}).items()))
for np in (1, 2):
    j = json.load(open(f"output/elasticity-1e6-np{np}.json"))
    c = j["cycles"]["0"]
    t = c["timings"]
    print(f"elasticity np = {np}: {int(c['dofs'])} DoFs, " + ", ".join(f"{k} {v:.2f} s" for k, v in sorted(t.items())) +
          f" (preconditioner set-up {c['solver_setup_seconds']:.2f} s of the solve), CG iterations "
          f"{int(c['solver_iterations'])}, peak memory per process {mem(j)}")
for np in (1, 2):
    j = json.load(open(f"output/contact-1e6-np{np}.json"))
    t = j["timings"]
    print(f"contact np = {np}: {int(j['dofs'])} DoFs, " + ", ".join(f"{k} {v:.2f} s" for k, v in sorted(t.items())) +
          f", CG iterations {int(j['contact']['linear_iterations'])}, constraint rows across processes "
          f"{int(j['contact']['rows_across_processes'])}, peak memory per process {mem(j)}")
for n in ("a", "b"):
    c = json.load(open(f"output/concurrent-{n}.json"))["cycles"]["0"]
    print(f"elasticity np = 1, two runs at once ({n}): solve {c['timings']['solve']:.2f} s "
          f"(preconditioner set-up {c['solver_setup_seconds']:.2f} s)")
PY
