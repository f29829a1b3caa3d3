#!/usr/bin/env bash
# Peer benchmark: one position of the spur gear pair of
# examples/parameters/gear-pair.prm (z1 = 20, z2 = 31, m = 4, single tooth
# pair at the pitch point) solved by dealvem (k = 2) and by GetFEM (P2) on
# the same meshes, one process per solve, one thread each; writes a Markdown
# report to stdout and to $OUT (progress on stderr).
#
# The gear's bore is clamped. The main load is a prescribed rotation of
# the pinion's bore about its centre by ANGLE (rad, counter-clockwise),
# u = (R(ANGLE) - I)(x - c1): both codes take it as Dirichlet data. The
# transmission error is then the angle itself, the same in both; what is
# compared is the torque it takes (the mesh stiffness T/ANGLE, the figure
# that the transmission error under a given torque follows from), the peak
# contact pressure, the contact width and the solve time. The second load
# (LOADS) is the torque TORQUE on the pinion's bore with its angle an
# unknown (the bore turns rigidly about its centre): that angle is the
# transmission error, compared directly.
#
# The meshes: benchmark_gear_peer_mesh (gear_peer_mesh.cc) builds each gear
# with the program's own 'Mesh' section code (Type = spur gear) and writes it
# as legacy VTK with its boundary ids; dealvem's run reads these files
# (Type = vtk file) and gear_getfem.py cuts their polygons into triangles on
# their own vertices. So both codes have the same nodes and boundary edges
# (GetFEM's P2 adds the edge midpoints of the triangles). With CHECK_DIRECT=1
# dealvem also solves each level with the gears meshed in the run itself
# (Type = spur gear) as a check that the VTK round trip changes nothing.
#
# Needs the dealvem build (BUILD_DIR); builds the targets dealvem_app and
# benchmark_gear_peer_mesh there (one job). GetFEM (Debian's python3-getfem,
# 5.4) is installed here when /usr/bin/python3 cannot import it.
#
# Environment:
#   BUILD_DIR    the dealvem build directory (default: <repo>/build)
#   LEVELS       mesh levels (default "0 1 2 3"): 0 = no global refinement,
#                flanks at 0.04 mm; 1 = one global refinement, flanks at
#                0.02 mm (gear-pair.prm's mesh); 2 = one global refinement,
#                flanks at 0.01 mm; 3 = two global refinements, flanks at
#                0.01 mm (the bodies away from the contact refined too)
#   ANGLE        the pinion's rotation in rad (default 0.0017, about the
#                angle that gear-pair.prm's torque 9400 N mm/mm gives)
#   TORQUE       the torque of the second load (default 9400 N mm/mm)
#   LOADS        "angle torque" (default), "angle" or "torque"
#   CHECK_DIRECT 1: also run dealvem on the gears meshed in the run (default 1)
#   WORK         work directory (default: a new /tmp/gear_peer.XXXXXX, kept)
#   OUT          the report (default: $WORK/results.md)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
LEVELS="${LEVELS:-0 1 2 3}"
ANGLE="${ANGLE:-0.0017}"
TORQUE="${TORQUE:-9400}"
LOADS="${LOADS:-angle torque}"
CHECK_DIRECT="${CHECK_DIRECT:-1}"
WORK="${WORK:-$(mktemp -d /tmp/gear_peer.XXXXXX)}"
OUT="${OUT:-$WORK/results.md}"
mkdir -p "$WORK"
PY=/usr/bin/python3 # the system python: python3-getfem is installed for it
TIME=/usr/bin/time
# one thread each: the timings compare the codes, not their threading
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

log() { echo "gear_peer: $*" >&2; }

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

# --- the dealvem programs (one build job: the machine may be shared)
[ -f "$BUILD/CMakeCache.txt" ] || BUILD_DIR="$BUILD" JOBS=1 bash "$ROOT/scripts/build.sh" --target dealvem > /dev/null
log "building dealvem_app and benchmark_gear_peer_mesh in $BUILD ..."
# configure again: a build directory made before this benchmark existed does
# not know its target yet
cmake "$BUILD" > "$WORK/build.log" 2>&1 || { log "cmake failed (see $WORK/build.log)"; exit 1; }
cmake --build "$BUILD" -j1 --target dealvem_app benchmark_gear_peer_mesh >> "$WORK/build.log" 2>&1 ||
  { log "build failed (see $WORK/build.log)"; exit 1; }
DEALVEM="$BUILD/bin/dealvem"
MESHER="$BUILD/benchmarks/benchmark_gear_peer_mesh"

for l in $LEVELS; do
  case "$l" in 0 | 1 | 2 | 3) ;; *) log "LEVELS: 0 to 3 only"; exit 1 ;; esac
done
mkdir -p "$WORK/mesh" "$WORK/output"
log "work directory: $WORK"

# --- machine notes
{
  echo "date:        $(date -u '+%Y-%m-%d %H:%M UTC')"
  cpu="$(lscpu | sed -n 's/^Model name: *//p' | head -n 1)"
  echo "CPU:         $cpu, $(getconf _NPROCESSORS_ONLN) core(s)"
  echo "memory:      $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
  echo "load start:  $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "dealvem:     $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?') (work tree), $DEALVEM"
  echo "GetFEM:      python3-getfem $(dpkg-query -W -f='${Version}' python3-getfem 2>/dev/null || echo '?')"
  echo "threads:     1 per process (DEAL_II_NUM_THREADS, OMP_NUM_THREADS, OPENBLAS_NUM_THREADS)"
  echo "loads:       $LOADS: angle $ANGLE rad or torque $TORQUE N mm/mm (pinion bore, counter-clockwise about (0, 0))"
} > "$WORK/machine.txt"

# the mesh settings of a level: global refinements, flank cell size
level_settings() {
  case "$1" in
    0) echo "0 0.04" ;;
    1) echo "1 0.02" ;;
    2) echo "1 0.01" ;;
    3) echo "2 0.01" ;;
  esac
}

# the 'Gear' subsection of a body: which (pinion|gear), level
gear_section() {
  local which=$1 refs cell
  read -r refs cell <<< "$(level_settings "$2")"
  if [ "$which" = pinion ]; then
    cat <<EOF
    set Module              = 4
    set Number of teeth     = 20
    set Pressure angle      = 20
    set Backlash            = 0.1
    set Tip relief          = 0.01
    set Bore radius         = 16
    set Centre              = 0, 0
    set Rotation            = -4.428380275608647
    set Teeth               = 19, 3
    set Global refinements  = $refs
    set Flank cell size     = $cell
    set Refined teeth       = 0, 1
    set Refined radii       = 39.5, 40.5
EOF
  else
    cat <<EOF
    set Module              = 4
    set Number of teeth     = 31
    set Pressure angle      = 20
    set Backlash            = 0.1
    set Tip relief          = 0.01
    set Bore radius         = 24.8
    set Centre              = 102, 0
    set Rotation            = 177.14298046734925
    set Teeth               = 30, 3
    set Global refinements  = $refs
    set Flank cell size     = $cell
    set Refined teeth       = 0, 1
    set Refined radii       = 61.5, 62.5
EOF
  fi
}

# --- the meshes: one VTK file per gear and level
make_meshes() {
  local l=$1 which
  for which in pinion gear; do
    {
      echo "subsection Mesh"
      echo "  set Type = spur gear"
      echo "  subsection Gear"
      gear_section "$which" "$l"
      echo "  end"
      echo "end"
    } > "$WORK/mesh/$which-$l.prm"
    "$MESHER" "$WORK/mesh/$which-$l.prm" "$WORK/mesh/$which-$l.vtk" >> "$WORK/mesh/mesher.log" 2>&1 ||
      { log "the mesher failed on $which, level $l (see $WORK/mesh/mesher.log)"; return 1; }
  done
  log "level $l: $(tail -n 2 "$WORK/mesh/mesher.log" | sed 's/ (spur gear.*//' | tr '\n' ';')"
}

# --- one dealvem solve: name, level, source of the meshes (vtk | direct),
# load (angle | torque)
run_dealvem() {
  local name=$1 l=$2 source=$3 load=$4 rotation="angle $ANGLE"
  [ "$load" = angle ] || rotation="torque $TORQUE"
  {
    echo "set Number of bodies = 2"
    if [ "$source" = vtk ]; then
      echo "subsection Mesh"
      echo "  set Type = vtk file"
      echo "  set File name = mesh/pinion-$l.vtk"
      echo "end"
    else
      echo "subsection Mesh"
      echo "  set Type = spur gear"
      echo "  subsection Gear"
      gear_section pinion "$l"
      echo "  end"
      echo "end"
    fi
    cat <<EOF
subsection Material
  set Young's modulus = 210000
  set Poisson's ratio = 0.3
  set Model           = plane strain
end
subsection Body 1
  subsection Mesh
EOF
    if [ "$source" = vtk ]; then
      echo "    set Type = vtk file"
      echo "    set File name = mesh/gear-$l.vtk"
      echo "    set Boundary id offset = 10"
    else
      echo "    set Type = spur gear"
      echo "    set Boundary id offset = 10"
      echo "    subsection Gear"
      gear_section gear "$l"
      echo "    end"
    fi
    cat <<EOF
  end
  subsection Material
    set Young's modulus = 210000
    set Poisson's ratio = 0.3
  end
end
subsection Discretization
  set Order = 2
end
subsection Contact
  set Pairs      = 1 : 11
  set Normal     = unilateral
  set Tangential = frictionless
end
subsection Boundary conditions and loads
  set Dirichlet             = 10 : xy : 0, 0
  set Rotation about centre = 0 : 0, 0 : $rotation
end
subsection Output
  set Folder         = output
  set Base name      = $name
  set Moment point   = 102, 0
  set Write VTU      = false
  set Write JSON     = true
  set Write pictures = false
  set Write CSV      = true
end
EOF
  } > "$WORK/$name.prm"
  (cd "$WORK" && "$TIME" -v -o "$name.time" "$DEALVEM" "$name.prm" > "$name.log" 2>&1) ||
    { log "dealvem failed: $name (see $WORK/$name.log)"; return 1; }
  log "$name: $(grep -m1 'Contact problem' "$WORK/$name.log" | sed 's/Contact problem: //'), $(grep -m1 Elapsed "$WORK/$name.time" | sed 's/.*: //') wall"
}

run_getfem() {
  local name=$1 l=$2 load=$3 value=$ANGLE
  [ "$load" = angle ] || value=$TORQUE
  (cd "$WORK" && "$TIME" -v -o "$name.time" "$PY" "$HERE/gear_getfem.py" \
    --pinion "mesh/pinion-$l.vtk" --gear "mesh/gear-$l.vtk" --gear-centre 102 0 --pitch-point 40 0 \
    "--$load" "$value" --order 2 --json "$name.json" --profile "$name.csv" > "$name.log" 2>&1) ||
    { log "GetFEM failed: $name (see $WORK/$name.log)"; return 1; }
  log "$name: $(tail -n 1 "$WORK/$name.log")"
}

status=0
for l in $LEVELS; do
  make_meshes "$l" || { status=1; continue; }
  for load in $LOADS; do
    case "$load" in angle) tag="" ;; torque) tag="torque-" ;; *) log "LOADS: angle and/or torque"; exit 1 ;; esac
    run_dealvem "dealvem-$tag$l" "$l" vtk "$load" || status=1
    run_getfem "getfem-$tag$l" "$l" "$load" || status=1
  done
  if [ "$CHECK_DIRECT" = 1 ]; then
    run_dealvem "dealvem-direct-$l" "$l" direct angle || status=1
  fi
done
echo "load end:    $(cut -d' ' -f1-3 /proc/loadavg)" >> "$WORK/machine.txt"

"$PY" "$HERE/compare.py" --work "$WORK" --levels "$LEVELS" --angle "$ANGLE" --torque "$TORQUE" --out "$OUT"
log "report: $OUT (runs kept in $WORK)"
exit $status
