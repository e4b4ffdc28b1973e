#!/bin/sh
# The VC correction system solved iteratively ('VC solver = automatic', the
# default: GMRES with ILU(0) below 100,000 unknowns and ML AMG from there on
# these regular systems; 'ilu' and 'amg' force one) and directly (KLU with
# shifted refinement, 'VC solver = direct'), on the 3-D cantilever of
# cantilever_case.sh (cg + ML), VCBCPBG V5sn Unl at 'Horizon factor =
# 1.51', and on
# Peridigm's tensile bar (prm/tensile_test.prm, 48,816 DoFs, 63 members per
# family). Prints a markdown table: DoFs, VC phase (matrix, solve, corrected
# tables and the unit-stress residual: timing.txt 'vc'), GMRES iterations,
# the Newton solve and assembly time per Newton step, and the tip or gauge
# displacement (both solvers must agree). Release build, one MPI rank.
#
# Usage (from the repository root):
#   sh doc/benchmarks/vc_solve.sh BUILD [sizes] [tensile] > table.md
# (the rows of the tables of doc/benchmarks/vc_solve.md; do not redirect
# into that page, which has more than the table)
# sizes: the x-subdivisions, y = z = x/4 (default "16 32 48 64");
# tensile: "yes" (default) adds the tensile bar.
# SOLVERS: the 'VC solver' values to run (default "automatic direct";
# "ilu amg" compare the two preconditioners).
set -e
PG=$1/applications/pg_solve/pg_solve
SIZES=${2:-16 32 48 64}
TENSILE=${3:-yes}
[ -x "$PG" ] || { echo "usage: $0 BUILD [sizes] [tensile]" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
. "$(dirname "$0")/cantilever_case.sh"

# row LABEL SOLVER POINT: one table row from $WORK/out
row() {
  python3 - "$WORK/out" "$1" "$2" "$3" <<'PY'
import json, sys
out, label, solver, point = sys.argv[1:]
s = json.load(open(out + "/summary.json"))
t = s["timing"]
steps = max(1, s["newton_iterations"])
vc = s.get("vc_solve", {})
print("| %s | %s | %d | %.2f | %s | %.2f | %.2f | %.6g |" % (
    label, solver, s["n_dofs"], t["vc"], vc.get("iterations", "-"),
    t["solve"] / steps, t["assembly"] / steps, s["points"][point][-1 if point == "tip" else 1]))
PY
}

echo "| problem | VC solver | DoFs | VC phase s | GMRES its | solve s/Newton step | assembly s/Newton step | u_z tip / u_y gauge |"
echo "|---|---|---|---|---|---|---|---|"
for n in $SIZES; do
  m=$((n / 4))
  for solver in ${SOLVERS:-automatic direct}; do
    {
      cantilever_prm 3 "$n" "VCBCPBG V5sn Unl" cg "$WORK/out"
      printf 'subsection Discretization\n  set Horizon factor = 1.51\nend\n'
      printf 'subsection Linear solver\n  set VC solver = %s\nend\n' "$solver"
    } > "$WORK/case.prm"
    rm -rf "$WORK/out"
    "$PG" "$WORK/case.prm" > "$WORK/log" 2>&1 || { echo "| cantilever $n | $solver | failed: $(failure_reason "$WORK/log") |"; continue; }
    row "cantilever $n x $m x $m" "$solver" tip
  done
done
if [ "$TENSILE" = yes ]; then
  for solver in ${SOLVERS:-automatic direct}; do
    sed "s|Formulation = .*|Formulation = VCBCPBG V5sn Unl|; s|Directory = .*|Directory = $WORK/out|" prm/tensile_test.prm > "$WORK/case.prm"
    cat >> "$WORK/case.prm" <<END
subsection Linear solver
  set VC solver = $solver
end
END
    rm -rf "$WORK/out"
    "$PG" "$WORK/case.prm" > "$WORK/log" 2>&1 || { echo "| tensile bar | $solver | failed: $(failure_reason "$WORK/log") |"; continue; }
    row "Peridigm's tensile bar" "$solver" "gauge top"
  done
fi
