#!/bin/sh
# Benchmark B-8 (numerical inf-sup test): runs prm/inf_sup.prm for every
# formulation on regular and distorted (0.3) meshes, N = 2..32, collects
# the tables in doc/benchmarks/inf_sup/ and draws doc/figures/inf_sup.png.
# ONLY=<name>: run that variant alone (e.g. ONLY=pbg_u2p1).
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/inf_sup.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/inf_sup
WORK=$(mktemp -d)
mkdir -p "$OUT"
run() { # name formulation pressure-space distortion
  [ -n "$ONLY" ] && [ "${1%_*}" != "$ONLY" ] && return 0
  cat prm/inf_sup.prm - > "$WORK/$1.prm" <<END
subsection Geometry
  set Distortion = $4
end
subsection Discretization
  set Formulation = $2
end
subsection Analysis
  set Pressure space = $3
end
subsection Output
  set Directory = $WORK/$1
end
END
  echo "== $1: $2, $3, distortion $4"
  "$PG_SOLVE" "$WORK/$1.prm" | grep "inf-sup N ="
  cp "$WORK/$1/inf_sup.txt" "$OUT/$1.txt"
}
for d in 0 0.3; do
  tag=regular; [ "$d" = 0 ] || tag=distorted
  run q1_$tag         FEM       displacement $d
  run q1p0_$tag       FEM       P0           $d
  run pbg_unl_$tag    "PBG Unl noBC" displacement $d
  run bcpbg_unl_$tag  "BCPBG Unl" displacement $d
  run pbg_u1_$tag     "PBG U1"    displacement $d
  run pbg_unlp0_$tag  "PBG Unl noBC" P0        $d
  run bcpbg_unlp0_$tag "BCPBG Unl" P0          $d
  run pbg_u2_$tag     "PBG U2"    displacement $d
  run pbg_u2p1_$tag   "PBG U2"    P1           $d
  run pbg_u2p1c_$tag  "PBG U2"    P1C          $d
  run bcpbg_unl_p1c_$tag "BCPBG Unl" P1C+bubble $d
done
rm -rf "$WORK"
gnuplot doc/benchmarks/inf_sup.gp
