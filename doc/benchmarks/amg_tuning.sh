#!/bin/sh
# ML's parameters for the wide PG stencils (issue 14, deliverable 2):
# Krylov iterations and wall time per linear solve for a list of 'Linear
# solver/AMG parameters' variants, on the cantilever of amg_iterations.sh
# (3-D, length 4, 1 x 1 section, n x n/4 x n/4 cells distorted by 0.25,
# clamped at x = 0, a dead downward traction on x = 4, neo-Hooke E = 1000,
# nu = 0.3, one load step, 'Tolerance' 1e-10, rigid body modes as ML's
# near-null space), for BCPBG Unl (cg), VCBCPPG V3sn Unl (gmres) and the
# coupled model (VCBCPPG V3sn Unl on x < 2, Q1 on the rest; gmres), and
# FEM (cg) for comparison. Release build, one MPI rank. (METIS aggregation
# is not among the variants: Debian's ML is built without METIS, and pg
# refuses it.)
#
# Usage (from the repository root):
#   sh doc/benchmarks/amg_tuning.sh BUILD [sizes] > table.md
# sizes: the x-subdivisions (default "24 32").
set -e
PG=$1/applications/pg_solve/pg_solve
SIZES=${2:-24 32}
[ -x "$PG" ] || { echo "usage: $0 BUILD [sizes]" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

. "$(dirname "$0")/cantilever_case.sh"

# name|AMG parameters
VARIANTS="pg's default|
Chebyshev degree 3|smoother: sweeps = 3
Chebyshev degree 4|smoother: sweeps = 4
symmetric Gauss-Seidel, 2 sweeps|smoother: type = symmetric Gauss-Seidel
aggregation threshold 0.01|aggregation: threshold = 0.01
prolongator damping 1.0|aggregation: damping factor = 1.0
unsmoothed prolongator|aggregation: damping factor = 0.0
uncoupled aggregation|aggregation: type = Uncoupled"

echo "| model | n | DoFs | ML variant | solves | iterations/solve | solve s/solve | u_z tip |"
echo "|---|---|---|---|---|---|---|---|"
for n in $SIZES; do
  for model in "FEM:cg" "BCPBG Unl:cg" "VCBCPPG V3sn Unl:gmres" "coupled:gmres"; do
    formulation=${model%%:*}
    solver=${model##*:}
    region=""
    if [ "$formulation" = coupled ]; then
      formulation="VCBCPPG V3sn Unl"
      region="subsection Geometry
  set Meshfree region = box 0, 0, 0 : 2, 1, 1
end"
    fi
    echo "$VARIANTS" | while IFS='|' read -r variant amg; do
      {
        cantilever_prm 3 "$n" "$formulation" "$solver" "$WORK/out"
        echo "$region"
        printf 'subsection Linear solver\n  set AMG parameters = %s\nend\n' "$amg"
      } > "$WORK/case.prm"
      rm -rf "$WORK/out"
      if ! "$PG" "$WORK/case.prm" > "$WORK/log" 2>&1; then
        echo "| ${model%%:*} | $n | - | $variant | failed: $(failure_reason "$WORK/log") |"
        continue
      fi
      s="$WORK/out/summary.json"
      dofs=$(summary_number "$s" n_dofs)
      solves=$(summary_number "$s" n_solves)
      its=$(summary_number "$s" linear_iterations)
      solve=$(grep -o '"solve": [0-9.e+-]*' "$s" | awk '{ print $2 }')
      tip=$(grep -o '"tip": \[[^]]*\]' "$s" | head -1 | tr -d '[],' |
        awk '{ printf "%.6g", $4 }')
      echo "| ${model%%:*} | $n | $dofs | $variant | $solves | $(echo "$its $solves" | awk '{ printf "%.1f", $1 / $2 }') | $(echo "$solve $solves" | awk '{ printf "%.3g", $1 / $2 }') | $tip |"
    done
  done
done
