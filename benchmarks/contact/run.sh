#!/usr/bin/env bash
# Contact at the cost of one body (issue 44): the two-block unilateral
# contact patch test of benchmark_contact (k = 2, non-matching quads,
# Solver/Type = CG-AMG constraints, Solver/Preconditioner = automatic: the
# p-multigrid on the condensed stiffness) against the same geometry meshed as
# one body, end to end (mesh to output), serial and on two MPI processes.
#
# Each run is its own process, and the contact and one-body runs alternate:
# a run that follows another in the same process finds its heap already
# faulted in, which on a VM with expensive page faults made the second run
# (the one body) up to 2x faster than in a process of its own. The table
# gives the median of REPEATS alternating pairs and the median of the ratios
# of the pairs.
#
# Before every run the script touches and frees WARM_MB of memory (3072 by
# default; 0: off). This VM (Firecracker, virtio-balloon free page
# reporting) hands pages back to the host when a process frees them, and a
# page the host has to back again costs 7-13 us per 4 KiB fault: which run
# found its pages still backed depended on the order of the runs, and the
# same 1e6-DoF pair measured 1.21-1.68 end to end; after the warm-up 1.275
# and 1.281 (doc/benchmarks.md, "page faults on this VM, a warm-up, huge pages"). The CPU seconds
# (user + system, of all processes) are reported beside the wall time.
# HUGEPAGES=1 runs both sides with glibc's transparent huge pages for the
# heap (GLIBC_TUNABLES=glibc.malloc.hugetlb=1): 70x fewer faults.
#
#   SIZES="100 210" NPS="1 2" TANGENTIAL="multipliers penalty" REPEATS=3 \
#     bash benchmarks/contact/run.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
bash "$ROOT/scripts/build.sh" --target benchmark_contact > /dev/null
SIZES="${SIZES:-100 210}"
NPS="${NPS:-1 2}"
TANGENTIAL="${TANGENTIAL:-multipliers penalty}"
REPEATS="${REPEATS:-3}"
WARM_MB="${WARM_MB:-3072}"
if [ "${HUGEPAGES:-0}" = 1 ]; then export GLIBC_TUNABLES=glibc.malloc.hugetlb=1; fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cd "$TMP"
MPIRUN=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && MPIRUN+=(--allow-run-as-root)

# touch WARM_MB of memory once and free it (see above)
warm() {
  if [ "$WARM_MB" -gt 0 ]; then python3 -c "b = bytearray(b'\\1') * ($WARM_MB << 20)"; fi
}

# one run: prints "seconds cg_iterations dofs cpu_seconds"
run() { # np n tangential which
  local cmd=("$BUILD/benchmarks/benchmark_contact" --n "$2" --solver "CG-AMG constraints" --tangential "$3"
             --preconditioner automatic --run "$4")
  if [ "$1" -gt 1 ]; then cmd=("${MPIRUN[@]}" -np "$1" "${cmd[@]}"); fi
  warm
  local TIMEFORMAT="%U %S"
  { time OMPI_MCA_ess_singleton_isolated=1 "${cmd[@]}" > out.txt 2>&1 || { cat out.txt >&2; exit 1; } ; } 2> cpu.txt
  local total dofs
  total="$(grep "^TOTAL $4 " out.txt)"
  dofs="$(grep "^RESULT $4 " out.txt | cut -d' ' -f4)"
  echo "$(echo "$total" | cut -d' ' -f4) $(echo "$total" | cut -d' ' -f5) $dofs $(awk '{print $1 + $2}' cpu.txt)"
}
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
echo "Load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "Warm-up before each run: ${WARM_MB} MB; GLIBC_TUNABLES=${GLIBC_TUNABLES:-(unset)}"
echo
echo "| n | np | stick by | DoFs contact / one body | CG its contact / one body | end to end s contact / one body (medians) | ratio of medians | median of pair ratios | pair ratios | CPU s contact / one body (medians) | CPU ratio |"
echo "|---:|---:|---|---|---|---|---:|---:|---|---|---:|"
for n in $SIZES; do
  for np in $NPS; do
    for t in $TANGENTIAL; do
      : > one.txt; : > con.txt; : > ratio.txt
      for ((r = 0; r < REPEATS; ++r)); do
        o="$(run "$np" "$n" "$t" onebody)"
        c="$(run "$np" "$n" "$t" contact)"
        echo "$o" >> one.txt
        echo "$c" >> con.txt
        awk -v c="${c%% *}" -v o="${o%% *}" 'BEGIN {printf "%.3f\n", c / o}' >> ratio.txt
      done
      mo="$(cut -d' ' -f1 one.txt | median)"
      mc="$(cut -d' ' -f1 con.txt | median)"
      uo="$(cut -d' ' -f4 one.txt | median)"
      uc="$(cut -d' ' -f4 con.txt | median)"
      printf "| %s | %s | %s | %s / %s | %s / %s | %.2f / %.2f | %.2f | %.2f | %s | %.2f / %.2f | %.2f |\n" "$n" "$np" "$t" \
        "$(head -1 con.txt | cut -d' ' -f3)" "$(head -1 one.txt | cut -d' ' -f3)" \
        "$(head -1 con.txt | cut -d' ' -f2)" "$(head -1 one.txt | cut -d' ' -f2)" "$mc" "$mo" \
        "$(awk -v c="$mc" -v o="$mo" 'BEGIN {print c / o}')" "$(median < ratio.txt)" "$(paste -sd' ' ratio.txt)" \
        "$uc" "$uo" "$(awk -v c="$uc" -v o="$uo" 'BEGIN {print c / o}')"
    done
  done
done
echo
echo "Load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
