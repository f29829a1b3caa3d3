#!/usr/bin/env bash
# Build (./build) and run the benchmarks; write doc/benchmarks.md (with the
# peer comparisons against GetFEM of benchmarks/hertz_peer/run.sh and
# benchmarks/gear_peer/run.sh at its end).
# Each case runs in its own process so that the peak memory is its own.
# MAX_DOFS limits the elasticity sizes (default 1e6); CONTACT_SIZES the
# contact sizes n (default "30 100 210").
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
bash "$ROOT/scripts/build.sh" --target benchmark_elasticity benchmark_contact dealvem_app step-3 > /dev/null
MAX_DOFS="${MAX_DOFS:-1000000}"
CONTACT_SIZES="${CONTACT_SIZES:-30 100 210}"
OUT="$ROOT/doc/benchmarks.md"
TMP="$(mktemp -d)"
cd "$TMP"

elastic="$TMP/elastic.txt"
load_start="$(cut -d' ' -f1 /proc/loadavg)"
# VEM with the default preconditioner of CG on k = 2 (p-multigrid) and with
# plain AMG (the previous default), FE_Q(2) with its AMG
for dofs in 1000 10000 100000 1000000; do
  [ "$dofs" -le "$MAX_DOFS" ] || continue
  for run in "voronoi pmg" "quads-full pmg" "quads pmg" "feq amg" "voronoi amg" "quads amg"; do
    set -- $run
    "$BUILD/benchmarks/benchmark_elasticity" --case $1 --precond $2 --dofs $dofs | grep RESULT >> "$elastic"
  done
done
# the preconditioner candidates on the Voronoi mesh (CANDIDATE_DOFS, default
# 1e5): label, then benchmark_elasticity options
candidates="$TMP/candidates.txt"
CANDIDATE_DOFS="${CANDIDATE_DOFS:-100000}"
while IFS='|' read -r label opts; do
  [ -n "$label" ] || continue
  eval "set -- $opts"
  "$BUILD/benchmarks/benchmark_elasticity" --case voronoi --dofs "$CANDIDATE_DOFS" "$@" | grep RESULT |
    sed "s/^RESULT/CANDIDATE $label|/" >> "$candidates"
done <<'LIST'
AMG: ML Chebyshev degree 2, threshold 1e-4, MIS aggregation (previous default)|--precond amg
AMG: Chebyshev degree 3|--precond amg --sweeps 3
AMG: Chebyshev degree 4|--precond amg --sweeps 4
AMG: symmetric Gauss-Seidel, 2 sweeps|--precond amg --smoother "symmetric Gauss-Seidel" --sweeps 2
AMG: aggregation threshold 0|--precond amg --threshold 0
AMG: aggregation threshold 0.02|--precond amg --threshold 0.02
AMG: uncoupled aggregation (deal.II's higher_order_elements)|--precond amg --uncoupled 1
AMG: two translations only (constant modes)|--precond amg --rotation 0
AMG: Cuthill-McKee numbering|--precond amg --renumber cm
p-multigrid: Chebyshev degree 2 on k = 2|--precond pmg --degree 2
p-multigrid: Chebyshev degree 3 on k = 2 (default)|--precond pmg
p-multigrid: Chebyshev degree 4 on k = 2|--precond pmg --degree 4
p-multigrid: coarse ML Chebyshev degree 3|--precond pmg --sweeps 3
p-multigrid: coarse ML symmetric Gauss-Seidel, 1 sweep|--precond pmg --smoother "symmetric Gauss-Seidel" --sweeps 1
p-multigrid: coarse ML uncoupled aggregation|--precond pmg --uncoupled 1
p-multigrid: Cuthill-McKee numbering|--precond pmg --renumber cm
LIST
"$BUILD/benchmarks/benchmark_elasticity" --case feq --dofs "$CANDIDATE_DOFS" | grep RESULT |
  sed "s/^RESULT/CANDIDATE FE_Q(2) with its AMG (reference)|/" >> "$candidates"
load_end="$(cut -d' ' -f1 /proc/loadavg)"
contact="$TMP/contact.txt"
# the contact run and its one-body run, each in its own process (a second run
# in the same process finds the heap faulted in: up to 2x faster on a VM)
contact_pair() {
  "$BUILD/benchmarks/benchmark_contact" "$@" --run contact
  "$BUILD/benchmarks/benchmark_contact" "$@" --run onebody
}
for n in $CONTACT_SIZES; do
  for s in UMFPACK KLU GMRES-AMG; do
    # the direct KLU and the GMRES solve get slow on the largest size: skipped there
    if [ "$n" -gt 100 ] && [ "$s" != "UMFPACK" ]; then continue; fi
    contact_pair --n $n --solver $s | grep RESULT | sed "s/^RESULT /RESULT $s /" >> "$contact"
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
    contact_pair --n $n --solver "CG-AMG constraints" --tangential $t > "$TMP/run.txt"
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
  echo "deal.II's step-8 (FEValues, QGauss(3)). CG to the relative tolerance 1e-8. VEM k = 2 is"
  echo "preconditioned by the default of \`LinearSolver\` for k = 2, the two-level p-multigrid"
  echo "(Chebyshev degree 3 on k = 2, one ML V-cycle on the Galerkin k = 1 level of the same polygons),"
  echo "and, for comparison, by the previous default, ML AMG on the whole matrix; FE_Q(2) by ML AMG. All"
  echo "ML hierarchies use smoothed aggregation with the three rigid-body modes as near-null space."
  echo "The machine is shared: the 1-minute load average was $load_start at the start and $load_end at"
  echo "the end of the elasticity runs (on $(nproc) cores), so a single run's time can be off by tens"
  echo "of percent and ratios of runs minutes apart inherit that; CG iteration counts are deterministic."
  echo
  echo "### Solve, the comparable figure: CG iterations and time per DoF against FE_Q(2)"
  echo
  echo "Same DoF count (within 0.6 %), same tolerance, same right-hand side; solve s includes copying"
  echo "the matrix into Trilinos, building the preconditioner (column setup s: AMG hierarchy, for"
  echo "the p-multigrid also P^T A P and the Chebyshev eigenvalue estimate) and, for the p-multigrid,"
  echo "building the prolongation from the DoF handler. nnz/row = matrix entries per row: a Voronoi"
  echo "cell has about six vertices, so its rows couple more DoFs than the rows of quads. Growth ="
  echo "iterations at 1e6 / iterations at 1e5 DoFs. Targets (issue 11): iterations / FE_Q(2) <= 1.3 at"
  echo "1e5 and 1e6 DoFs, growth <= 1.2."
  echo
  echo "| case | preconditioner | DoFs | nnz/row | CG its | its / FE_Q(2) | growth 1e5 -> 1e6 | solve s (setup s) | solve µs/DoF | solve time per DoF / FE_Q(2) |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  awk '
    function ex(d) { return int(log(d)/log(10)+0.5) }
    function name(c) { return c=="feq" ? "FE_Q(2)" : (c=="voronoi" ? "VEM k=2 Voronoi" : "VEM k=2 quads") }
    $2=="quads-full" { next }
    { n++; line[n]=$0; e=ex($4); its[$2" "$12" "e]=$9 }
    $2=="feq" { fits[ex($4)]=$9; ftime[ex($4)]=$8/$4 }
    END {
      for (i=1;i<=n;i++) {
        split(line[i],f," "); e=ex(f[4]);
        if (e < 4) continue;
        g = (e==6 && (f[2]" "f[12]" 5") in its) ? sprintf("%.2f", f[9]/its[f[2]" "f[12]" 5"]) : "-";
        printf("| %s | %s | %d | %.1f | %d | %.2f | %s | %.2f (%.2f) | %.2f | %.2f |\n",
          name(f[2]), (f[12]=="pmg" ? "p-multigrid" : "AMG"), f[4], f[14], f[9], f[9]/fits[e], g,
          f[8], f[11]+f[13], f[8]/f[4]*1e6, (f[8]/f[4])/ftime[e]);
      }
    }' "$elastic"
  echo
  echo "### Preconditioner candidates (VEM k = 2 Voronoi, $(awk -F'|' 'NR==1{split($2,f," "); print f[3]}' "$candidates") DoFs)"
  echo
  echo "Each row one run of \`benchmark_elasticity --case voronoi\` with the options named (ML"
  echo "settings of the whole matrix for AMG, of the coarse k = 1 level for the p-multigrid); the last"
  echo "row is FE_Q(2) on the same number of DoFs. ML's non-smoothed aggregation (\"NSSA\", deal.II's"
  echo "elliptic = false) is left out: with these smoothers it had not converged after 75 s. MueLu:"
  echo "Debian's deal.II 9.4 is built without it (DEAL_II_TRILINOS_WITH_MUELU unset), so its"
  echo "wrapper is not available. Cuthill-McKee renumbers the assembled system before the solve"
  echo "(not timed)."
  echo
  echo "| candidate | CG its | its / FE_Q(2) | solve s (setup s) | solve time / FE_Q(2) |"
  echo "|---|---:|---:|---:|---:|"
  awk -F'|' '
    { n++; lab[n]=$1; sub(/^CANDIDATE /,"",lab[n]); rest[n]=$2 }
    $1 ~ /FE_Q/ { split($2,f," "); fi=f[8]; ft=f[7] }
    END {
      for (i=1;i<=n;i++) {
        split(rest[i],f," ");
        printf("| %s | %d | %.2f | %.2f (%.2f) | %.2f |\n", lab[i], f[8], f[8]/fi, f[7], f[10]+f[12], f[7]/ft);
      }
    }' "$candidates"
  echo
  echo "### All stages"
  echo
  echo "Setup = DoF distribution, constraints and sparsity pattern; kDoF/s = thousands of DoFs per"
  echo "second of the stage. The comparable assembly figure is \"quads, every cell\": each element"
  echo "matrix computed, as deal.II's step-8 loop does for FE_Q(2). \"quads, reusing translated cells\""
  echo "(the default of \`ElasticityAssembler\`) keeps the whole element matrix of a translated"
  echo "polygon, which step-8's loop does not do (FEValues' CellSimilarity only reuses the shape"
  echo "function gradients), so its ratio is not a like-for-like comparison. VEM rows: p-multigrid."
  echo
  echo "| case | cells | DoFs | mesh s | setup s | assembly s | solve s (CG its) | assembly kDoF/s | solve kDoF/s | assembly time per DoF / FE_Q(2) | peak MB |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  awk '
    $12=="amg" && $2!="feq" { next }
    { n++; c[n]=$0 }
    $2=="feq" { feq[$4>0?int(log($4)/log(10)+0.5):0]=$7/$4 }
    END {
      for (i=1;i<=n;i++) {
        split(c[i],f," ");
        d=f[4]; e=int(log(d)/log(10)+0.5);
        ratio = (e in feq) ? sprintf("%.2f", (f[7]/d)/feq[e]) : "-";
        printf("| %s | %d | %d | %.3f | %.3f | %.3f | %.2f (%d) | %.0f | %.0f | %s | %.0f |\n",
          (f[2]=="feq"?"FE_Q(2)":(f[2]=="quads"?"VEM k=2 quads, reusing translated cells":(f[2]=="quads-full"?"VEM k=2 quads, every cell":"VEM k=2 Voronoi"))),
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
  echo "Raw lines: \`RESULT case cells dofs t_mesh t_setup t_assembly t_solve iterations peak_MB"
  echo "t_precond_setup precond t_prolongation nnz_per_row\` (\`CANDIDATE label|\` the same fields) and"
  echo "\`RESULT solver contact|onebody n dofs multipliers t_mesh t_insertion t_assembly t_solve\`."
  echo
  echo '```'
  cat "$elastic" "$candidates" "$contact" "$total"
  echo '```'
} > "$OUT"
# the peer comparison of the contact accuracy and solve (Hertz, dealvem
# against GetFEM on step-3's meshes); HERTZ_PEER=0 skips it
if [ "${HERTZ_PEER:-1}" != "0" ]; then
  BUILD_DIR="$BUILD" OUT="$TMP/hertz.md" WORK="$TMP/hertz" bash "$ROOT/benchmarks/hertz_peer/run.sh" > /dev/null
  { echo; sed 's/^#/##/' "$TMP/hertz.md"; } >> "$OUT"
fi
# the gear pair of examples/parameters/gear-pair.prm at the pitch point,
# dealvem against GetFEM on the same meshes (p_max, torque, transmission
# error, solve time; about 6 minutes); GEAR_PEER=0 skips it
if [ "${GEAR_PEER:-1}" != "0" ]; then
  BUILD_DIR="$BUILD" OUT="$TMP/gear.md" WORK="$TMP/gear" bash "$ROOT/benchmarks/gear_peer/run.sh" > /dev/null
  { echo; sed 's/^#/##/' "$TMP/gear.md"; } >> "$OUT"
fi
echo "wrote $OUT"
