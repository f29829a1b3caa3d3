#!/usr/bin/env bash
# Build (./build) and run the benchmarks; write doc/benchmarks.md.
# Each case runs in its own process so that the peak memory is its own.
# MAX_DOFS limits the elasticity sizes (default 1e6); CONTACT_SIZES the
# contact sizes n (default "30 100 210").
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
bash "$ROOT/scripts/build.sh" --target benchmark_elasticity benchmark_contact > /dev/null
MAX_DOFS="${MAX_DOFS:-1000000}"
CONTACT_SIZES="${CONTACT_SIZES:-30 100 210}"
OUT="$ROOT/doc/benchmarks.md"
TMP="$(mktemp -d)"
cd "$TMP"

elastic="$TMP/elastic.txt"
for dofs in 1000 10000 100000 1000000; do
  [ "$dofs" -le "$MAX_DOFS" ] || continue
  for c in voronoi quads quads-full feq; do
    "$BUILD/benchmarks/benchmark_elasticity" --case $c --dofs $dofs | grep RESULT >> "$elastic"
  done
done
contact="$TMP/contact.txt"
for n in $CONTACT_SIZES; do
  for s in UMFPACK KLU GMRES-AMG; do
    # the direct KLU and the GMRES solve get slow on the largest size: skipped there
    if [ "$n" -gt 100 ] && [ "$s" != "UMFPACK" ]; then continue; fi
    "$BUILD/benchmarks/benchmark_contact" --n $n --solver $s | grep RESULT | sed "s/^RESULT /RESULT $s /" >> "$contact"
  done
done
# the condensed contact solve (contact constraints on slave DoFs, CG + AMG;
# the one-body run uses CG + AMG too), with stick by tangential multipliers
# and by the default penalty (1e3 E/h; skipped on the largest size: the stiff
# springs slow CG down, see doc/benchmarks.md); end-to-end times of the
# contact run in $total
total="$TMP/total.txt"
: > "$total"
for n in $CONTACT_SIZES; do
  for t in multipliers penalty; do
    if [ "$n" -gt 100 ] && [ "$t" = penalty ]; then continue; fi
    "$BUILD/benchmarks/benchmark_contact" --n $n --solver "CG-AMG constraints" --tangential $t > "$TMP/run.txt"
    grep RESULT "$TMP/run.txt" | sed "s/^RESULT /RESULT CG-AMG-constraints($t) /" >> "$contact"
    grep TOTAL "$TMP/run.txt" | sed "s/^TOTAL /TOTAL CG-AMG-constraints($t) /" >> "$total"
  done
done

{
  echo "# Benchmarks"
  echo
  echo "Measured by \`benchmarks/run_benchmarks.sh\` on $(date -u +%Y-%m-%d):"
  echo "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"
  echo "$(free -g | awk '/Mem:/{print $2}') GiB, $(g++ --version | head -1), Release build, one MPI process, one thread."
  echo "Times are wall-clock seconds of one run; ratios compare runs in the same script on the same machine."
  echo
  echo "## Elasticity: VEM k = 2 against deal.II's FE_Q(2) (step-8 assembly)"
  echo
  echo "Unit square, left side clamped, body force. VEM on centroidal Voronoi meshes (5 Lloyd"
  echo "iterations) and on structured quads; FE_Q(2)^2 on the same structured quads, assembled as in"
  echo "deal.II's step-8 (FEValues, QGauss(3)). All solved by CG + ML AMG with the three rigid-body"
  echo "modes as near-null space, relative tolerance 1e-8. Setup = DoF distribution, constraints and"
  echo "sparsity pattern. kDoF/s = thousands of DoFs per second of the stage. \"VEM k=2 quads\""
  echo "reuses the element matrices of translated cells (the default, as deal.II's FEValues does"
  echo "for the FE_Q(2) run through its CellSimilarity); \"quads, every cell\" computes each element."
  echo
  echo "| case | cells | DoFs | mesh s | setup s | assembly s | solve s (CG its) | assembly kDoF/s | solve kDoF/s | assembly time per DoF / FE_Q(2) | peak MB |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  awk '
    { key=$2; c[NR]=$0 }
    $2=="feq" { feq[$4>0?int(log($4)/log(10)+0.5):0]=$7/$4 }
    END {
      for (i=1;i<=NR;i++) {
        split(c[i],f," ");
        d=f[4]; e=int(log(d)/log(10)+0.5);
        ratio = (e in feq) ? sprintf("%.2f", (f[7]/d)/feq[e]) : "-";
        printf("| %s | %d | %d | %.3f | %.3f | %.3f | %.2f (%d) | %.0f | %.0f | %s | %.0f |\n",
          (f[2]=="feq"?"FE_Q(2)":(f[2]=="quads"?"VEM k=2 quads":(f[2]=="quads-full"?"VEM k=2 quads, every cell":"VEM k=2 Voronoi"))),
          f[3], d, f[5], f[6], f[7], f[8], f[9], d/f[7]/1000, d/f[8]/1000, ratio, f[10]);
      }
    }' "$elastic"
  echo
  echo "## Contact patch test against one body with a matching mesh"
  echo
  echo "Two stacked blocks with non-matching structured quads (n and n + n/3 + 1 per side), k = 2,"
  echo "unilateral contact, stick by penalty, pressure on top; against one body [0,1]x[0,2] with a"
  echo "matching mesh of about the same number of DoFs, same load, supports and solver. Assembly of the"
  echo "contact problem includes the contact blocks; insertion = node insertion and pairing."
  echo
  echo "| solver | n | DoFs contact | multipliers | DoFs one body | insertion s | assembly s contact / one body | solve s contact / one body | ratio assembly | ratio solve |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  awk '
    $3=="contact" { s=$2; n=$4; cd=$5; cm=$6; ins=$8; ca=$9; cs=$10 }
    $3=="onebody" { printf("| %s | %d | %d | %d | %d | %.3f | %.3f / %.3f | %.3f / %.3f | %.2f | %.2f |\n",
                           s, n, cd, cm, $5, ins, ca, $9, cs, $10, ca/$9, cs/$10) }' "$contact"
  echo
  echo "CG-AMG-constraints(t): the contact constraints written as affine constraints on one slave DoF"
  echo "each, the stiffness condensed and solved by CG + ML AMG (the one-body run by CG + AMG too), stick"
  echo "by tangential multipliers or by the default penalty. End to end (mesh to output, contact run):"
  echo
  echo "| solver | n | wall s | CG iterations (all solves) | active-set iterations |"
  echo "|---|---:|---:|---:|---:|"
  awk '{ printf("| %s | %d | %.2f | %d | %d |\n", $2, $4, $5, $6, $7) }' "$total"
  echo
  echo "Raw lines: \`RESULT case cells dofs t_mesh t_setup t_assembly t_solve iterations peak_MB\` and"
  echo "\`RESULT solver contact|onebody n dofs multipliers t_mesh t_insertion t_assembly t_solve\`."
  echo
  echo '```'
  cat "$elastic" "$contact" "$total"
  echo '```'
} > "$OUT"
echo "wrote $OUT"
