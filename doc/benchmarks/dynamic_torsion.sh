#!/bin/sh
# Benchmark B-14 (Table 7.5): dynamic torsion of the elasto-plastic prism
# 1 x 1 x 5 mm (prm/dynamic_torsion.prm: J2 material of B-13, rho_0 = 7.85
# g/cm^3, bottom clamped, top turned one rotation per 10 us from rest,
# implicit Newmark with adaptive steps of 1 degree, cut down to 0.1 degree,
# grown up to 5 degrees) on N x N x 5N cells with randomly moved interior
# nodes. For every formulation, seed and predictor:
#   D1 (Distortion 0.25): turn to 360 degrees, max equivalent plastic strain;
#   D2 (Distortion 0.45): turn on until a 0.1 degree step fails (exit code
#       1 of pg_solve), the failure angle = final time x 36000 degrees/ms,
#       or until D2_DEGREES (default 2520) or LIMIT seconds of wall time
#       (then the angle reached is a lower bound, marked "cut off").
# Environment (all optional):
#   FORMULATIONS="<code>|<code>..."  default "FEM|FEM H1P0|VCPBG Unl|VCPBG V5sn U1SIG|VCPBG Unl+P1C"
#   SEEDS="1 2 3"       random seeds of the distortion (default "1")
#   CASES="D1 D2"       which meshes (default both)
#   PREDICTORS="newmark|last converged state"  'Time/Newmark predictor'
#                       (default both; 'last converged state' is the source's)
#   D2_DEGREES=2520     the D2 runs stop there at the latest
#   LIMIT=<seconds>     wall-time limit of one run (default none)
#   OUT=<file>          results file (default doc/benchmarks/dynamic_torsion/results_N<N>.txt)
#   APPEND=1            append to the results instead of starting them
#   KEEP=1              keep the work directory (VTU of every run) and print it
#   FIXED=1             fixed 1 degree steps, a run stops at the first failed
#                       step (how dynamic_torsion.md was measured)
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/dynamic_torsion.sh build-release/applications/pg_solve/pg_solve [N]
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
N=${2:-7}
FORMULATIONS=${FORMULATIONS:-"FEM|FEM H1P0|VCPBG Unl|VCPBG V5sn U1SIG|VCPBG Unl+P1C"}
SEEDS=${SEEDS:-1}
CASES=${CASES:-"D1 D2"}
PREDICTORS=${PREDICTORS:-"newmark|last converged state"}
D2_DEGREES=${D2_DEGREES:-2520}
PRM=$(dirname "$0")/../../prm/dynamic_torsion.prm
DIR=doc/benchmarks/dynamic_torsion
OUT=${OUT:-$DIR/results_N$N.txt}
WORK=$(mktemp -d)
mkdir -p "$DIR"
# adaptive steps (1 degree, cut to 0.1, grown to 5), or with FIXED=1 (or a
# pg_solve without them) fixed 1 degree steps; a run stops at the first
# step that fails
ADAPTIVE=""
if [ -n "$FIXED" ]; then
  ADAPTIVE="  set Time step control = fixed"
elif "$PG_SOLVE" --print-parameters 2>/dev/null | grep -q "Time step control"; then
  ADAPTIVE="  set Time step control = adaptive
  set Minimum time step = 2.7777777777777776e-06
  set Maximum time step = 1.3888888888888888e-04"
fi
[ -n "$APPEND" ] ||
  echo "# case | formulation | seed | predictor | mesh | DoFs | status | angle reached (deg) | max equivalent plastic strain | steps | step cuts | smallest step (deg) | Newton iterations | wall (s)" > "$OUT"

for case in $CASES; do
  if [ "$case" = D1 ]; then
    distortion=0.25
    degrees=360
  else
    distortion=0.45
    degrees=$D2_DEGREES
  fi
  echo "$FORMULATIONS" | tr '|' '\n' | while read -r f; do
    for seed in $SEEDS; do
      echo "$PREDICTORS" | tr '|' '\n' | while read -r predictor; do
        dir="$WORK/$case-$(echo "$f" | tr ' +' '_p')-$seed-$(echo "$predictor" | tr ' ' '_')"
        mkdir -p "$dir"
        # the prm, with later subsections overriding its entries
        cat "$PRM" > "$dir/run.prm"
        cat >> "$dir/run.prm" <<END
subsection Geometry
  set Subdivisions = $N, $N, $((5 * N))
  set Distortion   = $distortion
  set Random seed  = $seed
end
subsection Discretization
  set Formulation = $f
end
subsection Time
  set End time          = $(awk "BEGIN { printf \"%.15g\", $degrees * 0.01 / 360 }")
  set Newmark predictor = $predictor
  set Output interval   = 0
$ADAPTIVE
end
subsection Output
  set Directory = $dir/out
  set VTU       = $([ -n "$KEEP" ] && echo true || echo false)
end
END
        start=$(date +%s.%N)
        rc=0
        if [ -n "$LIMIT" ]; then
          timeout -s INT "$LIMIT" "$PG_SOLVE" "$dir/run.prm" > "$dir/run.log" 2>&1 || rc=$?
        else
          "$PG_SOLVE" "$dir/run.prm" > "$dir/run.log" 2>&1 || rc=$?
        fi
        wall=$(awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $start }")
        /usr/bin/env python3 - "$dir/out" "$case" "$f" "$seed" "$predictor" "$N" $rc "$wall" "$degrees" >> "$OUT" <<'END'
import json, sys
out, case, f, seed, predictor, n, rc, wall, degrees = sys.argv[1:]
try:
    s = json.load(open(out + "/summary.json"))
except (OSError, ValueError):
    print("%s | %s | %s | %s | %s x %s x %d | - | no summary (exit %s) | - | - | - | - | - | - | %s"
          % (case, f, seed, predictor, n, n, 5 * int(n), rc, wall))
    sys.exit(0)
d = s.get("dynamics", {})
deg = 36000.0  # degrees per ms: one rotation per 0.01 ms
if "final_time" in d:
    angle = d["final_time"] * deg
else:  # no "dynamics" block (fixed 1 degree steps): the last converged step
    last = [l.split() for l in open(out + "/statistics.txt") if l.strip() and not l.startswith("#")]
    angle = float(last[-1][0]) if last else 0.0
if rc == "0":
    status = "reached %s" % degrees
elif s.get("status") == "interrupted" or rc in ("124", "130"):
    status = "cut off (wall-time limit)"
else:
    status = "failed"
small = d.get("smallest_time_step", float("nan")) * deg
print("%s | %s | %s | %s | %s x %s x %d | %d | %s | %.1f | %.3g | %s | %s | %.2g | %s | %s" % (
    case, f, seed, predictor, n, n, 5 * int(n), s["n_dofs"], status, angle,
    s.get("max_equivalent_plastic_strain", float("nan")), d.get("n_steps", "-"),
    d.get("step_cuts", "-"), small, s.get("newton_iterations", "-"), wall))
END
        tail -n 1 "$OUT"
      done
    done
  done
done
if [ -n "$KEEP" ]; then
  echo "work directory kept: $WORK"
else
  rm -rf "$WORK"
fi
