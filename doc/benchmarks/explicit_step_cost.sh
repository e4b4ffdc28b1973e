#!/bin/sh
# The cost of one explicit (leapfrog) step per particle: the irregular patch
# of prm/ganzenmueller_patch.prm (21 x 21 distorted cells, 484 vertices),
# 2 breathing periods, with Q1 finite elements (the reference, per vertex),
# classical correspondence (PBG U1), VCBCPBG Unl and bond-based CPD at the
# same horizon (2.01 h; C1 = 9 E / (pi delta^3) = 3267 with delta = 2.01/21,
# the calibration of doc/cpd.md, so that its stable step is comparable).
# Reports the residual assembly time and the total
# time per step and vertex (microseconds) and their ratios to FEM, each the
# best of 3 runs, in doc/benchmarks/explicit_step_cost.txt.
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/explicit_step_cost.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/explicit_step_cost.txt
WORK=$(mktemp -d)
echo "# formulation vertices steps assembly_us/(step vertex) total_us/(step vertex) assembly/FEM total/FEM" > "$OUT"
fem_asm=
fem_tot=
for code in "FEM" "PBG U1" "VCBCPBG Unl" "CPD"; do
  name=$(echo "$code" | tr ' ' '_')
  best_asm=1e30
  best_tot=1e30
  for repeat in 1 2 3; do
    cat prm/ganzenmueller_patch.prm - > "$WORK/$name.prm" <<END
subsection Discretization
  set Formulation = $code
end
subsection Time
  set End time        = 3.2
  set Output interval = 0
end
subsection Output
  set Directory = $WORK/$name
end
subsection CPD
  set C1 = 3267
end
END
    "$PG_SOLVE" "$WORK/$name.prm" > "$WORK/$name.log"
    steps=$(grep -o '"load_steps": [0-9]*' "$WORK/$name/summary.json" | grep -o '[0-9]*$')
    asm=$(awk '$1 == "assembly" { print $2 }' "$WORK/$name/timing.txt")
    tot=$(awk '$1 == "total" { print $2 }' "$WORK/$name/timing.txt")
    best_asm=$(echo "$asm $best_asm" | awk '{ print ($1 < $2) ? $1 : $2 }')
    best_tot=$(echo "$tot $best_tot" | awk '{ print ($1 < $2) ? $1 : $2 }')
  done
  n=484
  a=$(echo "$best_asm $steps $n" | awk '{ printf "%.3f", 1e6 * $1 / ($2 * $3) }')
  t=$(echo "$best_tot $steps $n" | awk '{ printf "%.3f", 1e6 * $1 / ($2 * $3) }')
  [ -z "$fem_asm" ] && fem_asm=$a && fem_tot=$t
  echo "$name $n $steps $a $t $(echo "$a $fem_asm" | awk '{ printf "%.1f", $1 / $2 }') $(echo "$t $fem_tot" | awk '{ printf "%.1f", $1 / $2 }')" >> "$OUT"
done
cat "$OUT"
rm -rf "$WORK"
