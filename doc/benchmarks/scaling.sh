#!/bin/sh
# Cost against problem size (issue 14, deliverable 4): wall time, set-up,
# shape functions, VC system, time per Newton step, Krylov iterations per
# solve, peak memory per DoF and nonzeros per row, for FEM and the PG
# methods on one problem, with the ratios against FEM at the same size in
# the same run.
#
# The problem: a cantilever clamped at x = 0 with a dead downward traction
# on its free end, neo-Hooke E = 1000, nu = 0.3, one load step, cells
# distorted by 0.25 (the vertices move by up to 0.25 h), 'Tolerance' 1e-10
# for CG/GMRES with ML AMG and the rigid body modes. 3-D: 4 x 1 x 1 on
# n x n/4 x n/4 cells; 2-D: 4 x 1 on n x n/4 cells. PG everywhere: the
# particles are the vertices (no FE cells).
#
# Usage (from the repository root, Release build):
#   sh doc/benchmarks/scaling.sh BUILD RANKS DIM "SIZES" "MODELS" >> table.md
# MODELS: ';'-separated "formulation:horizon factor:solver" triples, e.g.
#   "FEM::cg;VCBCPBG V5sn Unl:1.51:cg;VCBCPPG V3sn Unl:1.51:gmres".
# Every row gives the time per Newton step as a ratio to the FEM row of the
# same size printed before it (run FEM first), or '-' without one.
# Peak memory is the largest resident set of any rank (GNU time, %M).
# Columns: DoFs, nonzeros per row, set-up (mesh, families, DoFs, sparsity)
# s, shape functions s, VC s, linear solves/ML hierarchies built, Krylov iterations per solve,
# assembly s and solve s per Newton step, s per Newton step, its ratio to
# FEM, wall s, peak MB per rank, kB per DoF (all ranks), tip displacement.
# PG_REUSE_AMG sets 'Linear solver/Reuse AMG' (default true).
# Each run gets at most PG_TIMEOUT seconds (default 1800). A failed run
# prints its row with the message's first line (not the error box's
# dashes). (The runs read no stdin: mpirun would swallow the model list.)
set -e
BUILD=$1
RANKS=${2:-1}
DIM=${3:-3}
SIZES=${4:-16 32 64}
MODELS=${5:-"FEM::cg;VCBCPBG V5sn Unl:1.51:cg"}
PG=$BUILD/applications/pg_solve/pg_solve
[ -x "$PG" ] || {
  echo "usage: $0 BUILD RANKS DIM SIZES MODELS" >&2
  exit 1
}
TIMEOUT=${PG_TIMEOUT:-1800}
# 'Linear solver/Reuse AMG' (true or false)
REUSE=${PG_REUSE_AMG:-true}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
if [ "$RANKS" -gt 1 ]; then
  RUN="mpirun -np $RANKS --bind-to none"
else
  RUN=""
fi

. "$(dirname "$0")/cantilever_case.sh"

echo "$MODELS" | tr ';' '\n' > "$WORK/models"
for n in $SIZES; do
  fem_step=""
  while IFS= read -r model; do
    formulation=$(echo "$model" | cut -d: -f1)
    factor=$(echo "$model" | cut -d: -f2)
    solver=$(echo "$model" | cut -d: -f3)
    # CPD: Silling's bond constant for E = 1000 (nu = 1/4 in 3-D, 1/3 in
    # 2-D): c = 18 K / (pi delta^4), c = 9 E / (pi delta^3), delta = factor h
    c1=$(echo "$DIM $n ${factor:-1}" | awk '{ d = $3 * 4 / $2;
      if ($1 == 3) printf "%.6g", 18 * 1000 / 1.5 / (3.14159265 * d^4);
      else printf "%.6g", 9 * 1000 / (3.14159265 * d^3) }')
    {
      cantilever_prm "$DIM" "$n" "$formulation" "$solver" "$WORK/out"
      [ -n "$factor" ] &&
        printf 'subsection Discretization\n  set Horizon factor = %s\nend\n' "$factor"
      cat << END
subsection CPD
  set C1 = $c1
  set C2 = 0
  set C3 = 0
end
subsection Linear solver
  set AMG near-null space = rigid body modes
  set Reuse AMG           = $REUSE
end
END
    } > "$WORK/case.prm"
    rm -rf "$WORK/out" "$WORK"/mem.*
    start=$(date +%s.%N)
    # shellcheck disable=SC2016
    if ! timeout "$TIMEOUT" $RUN sh -c \
      'exec /usr/bin/time -f %M -o "$0.$$" "$1" "$2"' \
      "$WORK/mem" "$PG" "$WORK/case.prm" < /dev/null > "$WORK/log" 2>&1; then
      echo "| $DIM-D | $formulation | $factor | $RANKS | $n | failed or over ${TIMEOUT} s: $(grep -v -e '^-*$' -e '^Exception' -e '^Aborting' "$WORK/log" | tail -1 | cut -c1-160) |"
      continue
    fi
    wall=$(echo "$start $(date +%s.%N)" | awk '{ printf "%.1f", $2 - $1 }')
    memory=$(cat "$WORK"/mem.* 2> /dev/null | sort -n | tail -1)
    row=$(python3 - "$WORK/out/summary.json" "$wall" "${memory:-0}" "$RANKS" \
      "$fem_step" << 'END'
import json, sys
s = json.load(open(sys.argv[1]))
wall, memory_kb, ranks = float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
fem_step = float(sys.argv[5]) if sys.argv[5] else None
t, c = s["timing"], s["assembly_cost"]
dofs = s["n_dofs"]
solves = max(c["n_solves"], 1)
# the Newton iterations of the load step: residual assemblies with a solve
step = (t["assembly"] + t["solve"]) / solves
tip = s["points"]["tip"][-1]
ratio = "%.2f" % (step / fem_step) if fem_step else "-"
print("%d | %.0f | %.2f | %.2f | %.2f | %d/%d | %.1f | %.3g | %.3g | %.3g | %s | %.1f | %.0f | %.2f | %.6g | %.3g"
      % (dofs, s["matrix_nonzeros"] / dofs, t["setup"] + t["mesh"],
         t["shape_functions"], t.get("vc", 0), solves, c.get("amg_builds", 0),
         c["linear_iterations"] / solves, t["assembly"] / solves,
         t["solve"] / solves, step, ratio, wall,
         memory_kb / 1024, memory_kb * ranks / dofs, tip, step))
END
)
    step=${row##*| }
    row=${row% | *}
    [ "$formulation" = FEM ] && fem_step=$step
    echo "| $DIM-D | $formulation | $factor | $RANKS | $n | $row |"
  done < "$WORK/models"
done
