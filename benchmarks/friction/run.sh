#!/usr/bin/env bash
# Coulomb friction at scale: the frictional patch test on two blocks with
# non-matching structured quads (N x N below, round(4N/3) x round(4N/3)
# above), k = 2, E = 7000, nu = 0.3, mu = 0.4, over 4 load steps, solved by
# the condensed solvers ('CG-AMG': CG, or GMRES where pairs slip, with ML AMG
# on the condensed stiffness; 'direct constraints'), serially and with
# mpirun -np 2. Three models on the same meshes:
#   tied     stick by multipliers (no friction law, one static solve): the
#            condensed solve the friction solve is compared with;
#   stick    Coulomb friction, the uniform stress [[0, tau], [tau, -p]] with
#            tau = 0.5 mu p: every pair sticks (one Newton iteration a step);
#   slip     Coulomb friction, the upper block's top moved sideways by
#            0.02 t under the pressure p, the sides loaded by the uniform
#            shear mu p: every pair slips (the non-symmetric condensed
#            system, GMRES);
#   sliding  the slip model's loads at t = 1 without friction (Normal =
#            tied, Tangential = frictionless, one static solve): the same
#            constraints as 'slip' (one per pair) without the friction
#            force, the symmetric condensed solve 'slip' is compared with.
# Prints per run: DoFs, Newton iterations, Krylov iterations, solve time in
# all and per Newton iteration, wall time end to end, peak memory, and for
# np = 2 the largest difference to np = 1 in the interface CSV (pressure
# and shear per pair, relative to the largest value).
#   SIZES="100 210" NPS="1 2" bash benchmarks/friction/run.sh
# (N = 100: 225,444 DoFs; N = 210: 990,216 DoFs). Run on an idle machine.
# TOLERANCE (default 1e-12) and WARM_START (true/false, default true) set
# the Solver section's relative tolerance and Krylov warm start.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
BUILD_DIR="$(cd "$BUILD_DIR" && pwd)"
WORK="${WORK:-$BUILD_DIR/benchmarks/friction}"
SIZES="${SIZES:-100 210}"
NPS="${NPS:-1 2}"
MODELS="${MODELS:-tied stick slip sliding}"
SOLVERS="${SOLVERS:-CG-AMG}"
mkdir -p "$WORK"
cd "$WORK"
FLAGS=(--oversubscribe)
[ "$(id -u)" = 0 ] && FLAGS+=(--allow-run-as-root)

write_prm() { # N model solver name
  local n=$1 model=$2 solver=$3 name=$4 m
  m=$(( (4 * n + 1) / 3 ))
  {
    echo "set Number of bodies = 2"
    echo "subsection Mesh"
    echo "  set Type = structured quads"
    echo "  set Subdivisions = $n, $n"
    echo "end"
    echo "subsection Material"
    echo "  set Young's modulus = 7000"
    echo "  set Poisson's ratio = 0.3"
    echo "end"
    echo "subsection Body 1"
    echo "  subsection Mesh"
    echo "    set Type = structured quads"
    echo "    set Lower left corner = 0, 1"
    echo "    set Upper right corner = 1, 2"
    echo "    set Subdivisions = $m, $m"
    echo "    set Boundary id offset = 10"
    echo "  end"
    echo "  subsection Material"
    echo "    set Young's modulus = 7000"
    echo "    set Poisson's ratio = 0.3"
    echo "  end"
    echo "end"
    echo "subsection Discretization"
    echo "  set Order = 2"
    echo "end"
    echo "subsection Contact"
    echo "  set Pairs = 3 : 12"
    if [ "$model" = tied ]; then
      echo "  set Tangential = multipliers"
    elif [ "$model" = sliding ]; then
      echo "  set Normal = tied"
      echo "  set Tangential = frictionless"
    else
      echo "  set Tangential = coulomb"
      echo "  set Friction coefficient = 0.4"
    fi
    echo "end"
    if [ "$model" = stick ] || [ "$model" = slip ]; then
      echo "subsection Load steps"
      echo "  set Number of steps = 4"
      echo "  set Final time = 1"
      echo "end"
    fi
    echo "subsection Boundary conditions and loads"
    case $model in
      tied)
        echo "  set Function constants = p=10, tau=2"
        echo "  set Dirichlet = 2 : y : 0"
        echo "  set Point constraints = 0, 0 : x : 0"
        echo "  set Traction = 13 : tau, -p; 10 : 0, -tau; 11 : 0, tau; 0 : 0, -tau; 1 : 0, tau; 2 : -tau, 0";;
      stick)
        echo "  set Function constants = p=10, tau=2"
        echo "  set Dirichlet = 2 : y : 0"
        echo "  set Point constraints = 0, 0 : x : 0"
        echo "  set Traction = 13 : tau*t, -p*t; 10 : 0, -tau*t; 11 : 0, tau*t; 0 : 0, -tau*t; 1 : 0, tau*t; 2 : -tau*t, 0";;
      slip|sliding)
        echo "  set Function constants = p=10, tau=4"
        echo "  set Dirichlet = 2 : y : 0; 13 : x : 0.02*t"
        echo "  set Point constraints = 0, 0 : x : 0"
        echo "  set Pressure = 13 : p"
        echo "  set Traction = 10 : 0, -tau; 11 : 0, tau; 0 : 0, -tau; 1 : 0, tau; 2 : -tau, 0";;
    esac
    echo "end"
    echo "subsection Solver"
    echo "  set Type = $solver"
    echo "  set Relative tolerance = ${TOLERANCE:-1e-12}"
    echo "  set Warm start = ${WARM_START:-true}"
    echo "end"
    echo "subsection Output"
    echo "  set Folder = output"
    echo "  set Base name = $name"
    echo "  set Write VTU = false"
    echo "  set Write pictures = false"
    echo "  set Write CSV = true"
    echo "end"
  } > "$name.prm"
}

echo "# friction at scale ($(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))"
for n in $SIZES; do
  for model in $MODELS; do
    for solver in $SOLVERS; do
      for np in $NPS; do
        name="n$n-$model-$(echo "$solver" | tr ' ' '_')-np$np${TAG:-}"
        write_prm "$n" "$model" "$solver" "$name"
        start=$(date +%s.%N)
        mpirun "${FLAGS[@]}" -np "$np" "$BUILD_DIR/bin/dealvem" "$name.prm" > "$name.log" 2>&1 || {
          tail -30 "$name.log"; exit 1; }
        end=$(date +%s.%N)
        python3 - "$name" "$np" "$(echo "$end - $start" | bc)" <<'PY'
import csv, glob, json, sys
name, np, wall = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
j = json.load(open(f"output/{name}.json"))
c = j["contact"]
steps = list(j["steps"].values()) if isinstance(j.get("steps"), dict) else []
newton = sum(int(s["iterations"]) for s in steps) if steps else int(c["active_set_iterations"])
solve = j["timings"]["solve"]
slips = [int(s["slip"]) for s in steps] if steps else []
mem = max(j.get("memory", {}).values()) if j.get("memory") else float("nan")
line = (f"{name}: {int(j['dofs'])} DoFs, Newton iterations {newton}"
        + (f" (slipping pairs per step {slips})" if slips else "")
        + f", Krylov iterations {int(c['linear_iterations'])}, solve {solve:.2f} s = {solve / newton:.2f} s per "
        f"Newton iteration, end to end {wall:.1f} s, peak memory {mem:.0f} MB")
if np > 1:
    def table(n):
        files = sorted(glob.glob(f"output/{n}*interface*.csv"))
        rows = list(csv.reader(open(files[-1])))
        head = rows[0]
        cols = [i for i, h in enumerate(head) if h.strip() in ("multiplier", "tangential_traction")]
        return [[float(r[i]) for i in cols] for r in rows[1:]]
    a, b = table(name), table(name.replace(f"-np{np}", "-np1"))
    scale = max(abs(v) for r in b for v in r)
    diff = max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))
    line += f", max |np{np} - np1| / max = {diff / scale:.1e} over {len(a)} pairs"
print(line, flush=True)
PY
      done
    done
  done
done
