#!/bin/sh
# ML's hierarchy from the tangent against one from the Q1 tangent on the
# cells ('Linear solver/AMG operator = tangent | Q1 cells'): Krylov
# iterations and wall time of the linear solves (ML set-up, the Q1 assembly
# and the iterations) and of the whole run, for VCBCPBG V5sn Unl (cg),
# VCBCPPG V3sn Unl (gmres) and the coupled model (VCBCPPG V3sn Unl on
# x < 2, Q1 on the rest, gmres), all at delta = 1.51 h in 3-D and 2.01 h
# in 2-D (V5sn needs more neighbours there), on the cantilever of
# cantilever_case.sh. Release build, one rank. Times in seconds.
#
# Usage (from the repository root):
#   sh doc/benchmarks/amg_operator.sh BUILD [sizes] [dim] > table.md
# sizes: the x-subdivisions (default "32 48 64"), dim 3 (default) or 2.
set -e
PG=$1/applications/pg_solve/pg_solve
SIZES=${2:-32 48 64}
DIM=${3:-3}
[ -x "$PG" ] || { echo "usage: $0 BUILD [sizes] [dim]" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

. "$(dirname "$0")/cantilever_case.sh"

if [ "$DIM" = 3 ]; then
  half="0, 0, 0 : 2, 1, 1"
  horizon=1.51
else
  half="0, 0 : 2, 1"
  horizon=2.01
fi
echo "| model | n | DoFs | AMG operator | solves | iterations/solve | solve s | Q1 assembly s | total s | u tip (last component) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for n in $SIZES; do
  for model in "VCBCPBG V5sn Unl:cg" "VCBCPPG V3sn Unl:gmres" "coupled:gmres"; do
    formulation=${model%%:*}
    solver=${model##*:}
    region=""
    if [ "$formulation" = coupled ]; then
      formulation="VCBCPPG V3sn Unl"
      region="subsection Geometry
  set Meshfree region = box $half
end"
    fi
    for operator in tangent "Q1 cells"; do
      {
        cantilever_prm "$DIM" "$n" "$formulation" "$solver" "$WORK/out"
        echo "$region"
        printf 'subsection Discretization\n  set Horizon factor = %s\nend\n' "$horizon"
        printf 'subsection Linear solver\n  set AMG operator = %s\nend\n' "$operator"
      } > "$WORK/case.prm"
      rm -rf "$WORK/out"
      if ! "$PG" "$WORK/case.prm" > "$WORK/log" 2>&1; then
        echo "| ${model%%:*} | $n | - | $operator | failed: $(failure_reason "$WORK/log") |"
        continue
      fi
      s="$WORK/out/summary.json"
      dofs=$(summary_number "$s" n_dofs)
      solves=$(summary_number "$s" n_solves)
      its=$(summary_number "$s" linear_iterations)
      solve=$(summary_number "$s" solve | awk '{ printf "%.3g", $1 }')
      q1=$(summary_number "$s" amg_operator | awk '{ printf "%.2g", $1 }')
      total=$(summary_number "$s" total | awk '{ printf "%.3g", $1 }')
      tip=$(grep -o '"tip": \[[^]]*\]' "$s" | head -1 | tr -d '[],' |
        awk '{ printf "%.6g", $NF }')
      echo "| ${model%%:*} | $n | $dofs | $operator | $solves | $(echo "$its $solves" | awk '{ printf "%.1f", $1 / $2 }') | $solve | $q1 | $total | $tip |"
    done
  done
done
