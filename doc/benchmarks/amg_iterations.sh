#!/bin/sh
# Krylov iterations per Newton solve against DoFs with ML's near-null space
# as translations (deal.II's constant modes, before issue 14) and as rigid
# body modes ('Linear solver/AMG near-null space'), for FEM, BCPBG Unl
# (cg), VCBCPPG V3sn Unl and a coupled model (gmres), on a 3-D cantilever
# (length 4, 1 x 1 section, clamped at x = 0, a dead downward traction on
# x = 4, neo-Hooke E = 1000, nu = 0.3, cells distorted by 0.25, one load
# step, 'Tolerance' 1e-10). Release build, one MPI rank.
#
# Usage (from the repository root):
#   sh doc/benchmarks/amg_iterations.sh BUILD [sizes] > table.md
# (the table of doc/benchmarks/amg_iterations.md; do not redirect into
# that page, which has more than the table)
# sizes: the x-subdivisions, y = z = x/4 (default "16 24 32 48").
set -e
PG=$1/applications/pg_solve/pg_solve
SIZES=${2:-16 24 32 48}
[ -x "$PG" ] || { echo "usage: $0 BUILD [sizes]" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

. "$(dirname "$0")/cantilever_case.sh"

echo "| model | solver | n | DoFs | null space | solves | iterations/solve | solve s/solve | u_z tip |"
echo "|---|---|---|---|---|---|---|---|---|"
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
    # PG beyond 32 x 8 x 8 costs minutes per run here: FEM only
    [ "$formulation" != FEM ] && [ "$n" -gt 32 ] && continue
    for nullspace in translations "rigid body modes"; do
      {
        cantilever_prm 3 "$n" "$formulation" "$solver" "$WORK/out"
        echo "$region"
        printf 'subsection Linear solver\n  set AMG near-null space = %s\nend\n' "$nullspace"
      } > "$WORK/case.prm"
      rm -rf "$WORK/out"
      if ! "$PG" "$WORK/case.prm" > "$WORK/log" 2>&1; then
        echo "| $model | $solver | $n | - | $nullspace | failed: $(failure_reason "$WORK/log") |"
        continue
      fi
      s="$WORK/out/summary.json"
      dofs=$(summary_number "$s" n_dofs)
      solves=$(summary_number "$s" n_solves)
      its=$(summary_number "$s" linear_iterations)
      solve=$(grep -o '"solve": [0-9.e+-]*' "$s" | awk '{ print $2 }')
      tip=$(grep -o '"tip": \[[^]]*\]' "$s" | head -1 | tr -d '[],' |
        awk '{ printf "%.6g", $4 }')
      echo "| ${model%%:*} | $solver | $n | $dofs | $nullspace | $solves | $(echo "$its $solves" | awk '{ printf "%.1f", $1 / $2 }') | $(echo "$solve $solves" | awk '{ printf "%.3g", $1 / $2 }') | $tip |"
    done
  done
done
