#!/usr/bin/env bash
# Peer benchmark: the NAFEMS Hertz contact of examples/step-3 solved by
# dealvem (k = 1, 2) and by GetFEM (P1, P2) on the same meshes, in one
# script, one process per solve, interleaved level by level
# (level L: dealvem k = 1, GetFEM P1, dealvem k = 2, GetFEM P2), then a fine
# GetFEM P2 reference on the finest level refined uniformly. Writes a
# Markdown report to stdout and to $OUT; progress goes to stderr.
#
# Needs a build with build/bin/dealvem and the step-3 example (it writes
# the meshes). GetFEM (Debian's python3-getfem, 5.4) is a dependency of
# this benchmark only; it is installed here when /usr/bin/python3 cannot
# import it.
#
# Environment:
#   BUILD_DIR   the dealvem build directory (default: <repo>/build)
#   LEVELS      mesh levels of step-3 (default "0 1 2"; step-3 has 0 to 2)
#   REF_REFINE  uniform refinements of the finest level for the GetFEM
#               reference (default 1; 0: no reference)
#   REF_CHECK   1: solve once more with REF_REFINE + 1 refinements and
#               report how far the reference is from it (level 2: 676k
#               DoFs, about 5 min and 2.3 GB; default 0)
#   WORK        work directory (default: a new /tmp/hertz_peer.XXXXXX, kept)
#   MESH_DIR    take hertz-{block,cylinder}-L.vtk (and step3.log) from this
#               directory instead of running step-3 (e.g. $WORK/mesh of a
#               previous run)
#   OUT         the report (default: $WORK/results.md)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
LEVELS="${LEVELS:-0 1 2}"
REF_REFINE="${REF_REFINE:-1}"
REF_CHECK="${REF_CHECK:-0}"
WORK="${WORK:-$(mktemp -d /tmp/hertz_peer.XXXXXX)}"
OUT="${OUT:-$WORK/results.md}"
PY=/usr/bin/python3 # the system python: python3-getfem is installed for it
TIME=/usr/bin/time
# one thread each, so that the timings compare the codes and not their
# threading (and the runs do not fight over the two cores)
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

log() { echo "hertz_peer: $*" >&2; }

# --- GetFEM, a benchmark-only dependency
if ! "$PY" -c 'import getfem' 2>/dev/null; then
  log "installing python3-getfem (Debian) ..."
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  $SUDO apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq python3-getfem >&2
  "$PY" -c 'import getfem' || { log "GetFEM cannot be imported after the install"; exit 1; }
fi
[ -x "$TIME" ] || { log "$TIME is missing (Debian package 'time')"; exit 1; }

# --- the dealvem programs
DEALVEM="$BUILD/bin/dealvem"
STEP3="$BUILD/examples/step-3"
[ -x "$STEP3" ] || STEP3="$(find "$BUILD" -name step-3 -type f -perm -u+x 2>/dev/null | head -n 1)"
[ -x "$DEALVEM" ] || { log "no $DEALVEM: build dealvem first"; exit 1; }
if [ -z "${MESH_DIR:-}" ] && ! { [ -n "$STEP3" ] && [ -x "$STEP3" ]; }; then
  log "no step-3 binary under $BUILD: build the examples first"
  exit 1
fi

max_level=0
for l in $LEVELS; do
  case "$l" in 0 | 1 | 2) ;; *) log "LEVELS: step-3 writes levels 0, 1 and 2 only"; exit 1 ;; esac
  [ "$l" -gt "$max_level" ] && max_level=$l
done

mkdir -p "$WORK/mesh" "$WORK/output"
log "work directory: $WORK"

# --- machine notes
{
  echo "date:        $(date -u '+%Y-%m-%d %H:%M UTC')"
  cpu="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
  echo "CPU:         $cpu, $(getconf _NPROCESSORS_ONLN) core(s)"
  echo "memory:      $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
  echo "load start:  $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "dealvem:     $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?') (work tree), $DEALVEM"
  echo "GetFEM:      python3-getfem $(dpkg-query -W -f='${Version}' python3-getfem 2>/dev/null || echo '?')"
  echo "threads:     1 per process (DEAL_II_NUM_THREADS, OMP_NUM_THREADS)"
} > "$WORK/machine.txt"

# --- the meshes: step-3 writes hertz-{block,cylinder}-L.vtk for its levels
# (--quick: 0, default: 0 and 1, --study: 0 to 2) and solves them itself;
# its table is kept for the report. A failed check of step-3 is reported
# but does not stop the benchmark.
if [ -n "${MESH_DIR:-}" ]; then
  log "meshes: from $MESH_DIR"
  for l in $LEVELS; do
    cp "$MESH_DIR/hertz-block-$l.vtk" "$MESH_DIR/hertz-cylinder-$l.vtk" "$WORK/mesh/"
  done
  [ ! -f "$MESH_DIR/step3.log" ] || cp "$MESH_DIR/step3.log" "$WORK/mesh/" 2>/dev/null || true
else
  case "$max_level" in 0) flag=--quick ;; 1) flag="" ;; *) flag=--study ;; esac
  log "meshes: step-3 $flag"
  if ! (cd "$WORK/mesh" && "$STEP3" $flag > step3.log 2>&1); then
    log "step-3 failed or reported a failed check (see $WORK/mesh/step3.log); going on with its meshes"
  fi
fi
for l in $LEVELS; do
  for body in block cylinder; do
    [ -s "$WORK/mesh/hertz-$body-$l.vtk" ] || { log "step-3 wrote no hertz-$body-$l.vtk"; exit 1; }
  done
done

# --- one dealvem solve: the parameter file of step-3's parameters()
run_dealvem() {
  local l=$1 k=$2 name="dealvem-$1-k$2"
  cat > "$WORK/$name.prm" <<EOF
set Number of bodies = 2
subsection Mesh
  set Type = vtk file
  set File name = mesh/hertz-block-$l.vtk
end
subsection Material
  set Model = plane strain
  set Young's modulus = 210000
  set Poisson's ratio = 0.3
end
subsection Body 1
  subsection Mesh
    set Type = vtk file
    set File name = mesh/hertz-cylinder-$l.vtk
    set Boundary id offset = 10
  end
  subsection Material
    set Young's modulus = 70000
    set Poisson's ratio = 0.3
  end
end
subsection Discretization
  set Order = $k
end
subsection Contact
  set Pairs = 3 : 10
  set Normal = unilateral
  set Tangential = frictionless
end
subsection Boundary conditions and loads
  set Dirichlet = 2 : xy : 0, 0
  set Rigid boundary = 11 : 0, -35000
  set Point constraints = 0, 50 : x : 0 : 1
end
subsection Output
  set Folder = output
  set Base name = $name
  set Write VTU = false
  set Write JSON = true
  set Write pictures = false
  set Write CSV = true
end
EOF
  (cd "$WORK" && "$TIME" -v -o "$name.time" "$DEALVEM" "$name.prm" > "$name.log" 2>&1) ||
    { log "dealvem failed on level $l, k = $k (see $WORK/$name.log)"; return 1; }
  local size its wall
  size="$(grep -m1 'Contact problem' "$WORK/$name.log" | sed 's/Contact problem: //')"
  its="$(grep -m1 'active set:' "$WORK/$name.log" | sed 's/ *active set: //; s/, active pairs.*//')"
  wall="$(grep -m1 Elapsed "$WORK/$name.time" | sed 's/.*: //')"
  log "level $l: dealvem k = $k: $size, $its, $wall wall"
}

# --- one GetFEM solve (name, order, extra options)
run_getfem() {
  local name=$1 l=$2 order=$3
  shift 3
  (cd "$WORK" && "$TIME" -v -o "$name.time" "$PY" "$HERE/hertz_getfem.py" \
    --block "mesh/hertz-block-$l.vtk" --cylinder "mesh/hertz-cylinder-$l.vtk" --order "$order" \
    --json "$name.json" --profile "$name.csv" "$@" > "$name.log" 2>&1) ||
    { log "GetFEM failed on level $l, P$order (see $WORK/$name.log)"; return 1; }
  log "level $l: $(tail -n 1 "$WORK/$name.log")"
}

status=0
for l in $LEVELS; do
  for k in 1 2; do
    run_dealvem "$l" "$k" || status=1
    run_getfem "getfem-$l-p$k" "$l" "$k" || status=1
  done
done
if [ "$REF_REFINE" -gt 0 ]; then
  log "fine reference: GetFEM P2 on level $max_level refined $REF_REFINE time(s) ..."
  run_getfem getfem-ref "$max_level" 2 --refine "$REF_REFINE" || status=1
  if [ "$REF_CHECK" = 1 ]; then
    log "check of the reference: refined $((REF_REFINE + 1)) time(s) ..."
    run_getfem getfem-ref-check "$max_level" 2 --refine $((REF_REFINE + 1)) || status=1
  fi
fi
echo "load end:    $(cut -d' ' -f1-3 /proc/loadavg)" >> "$WORK/machine.txt"

"$PY" "$HERE/compare.py" --work "$WORK" --levels "$LEVELS" --out "$OUT"
log "report: $OUT (runs kept in $WORK)"
exit $status
