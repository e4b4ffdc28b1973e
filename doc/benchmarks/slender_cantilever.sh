#!/bin/sh
# A mesh nobody in the project wrote: PETSc's Gmsh test mesh square_quad.msh
# (Debian package libpetsc3.18-dev-examples, which libdeal.ii-dev pulls in):
# a strip -0.5 <= x <= 0.5, 0 <= y <= 0.1 of 49 x 4 quadrilaterals, physical
# lines bottom 2, right 3, top 4, left 5. Used as a slender cantilever,
# L/h = 10: clamped on the left (5), a dead shear traction 0.01 (total
# P = 1e-3) on the right (3); plane strain, isochoric-volumetric neo-Hooke,
# E = 1000, nu = $NU (default 0.4999). Tip u_y at (0.5, 0.05) for Global refinement
# 0 ... 3 (4 to 32 cells through the thickness), for FEM Q1, Q1P0 and the
# displacement and mixed PG codes (default horizon factor, direct solver).
# Reference: Q1P0 at refinement 4 (with 'Stagnation tolerance = 1e-4':
# there the direct solve's round-off floor is 7.7e-6 |R_0|). (Timoshenko's beam, P L^3 / (3 E' I) +
# P L / (kappa G A) with E' = E / (1 - nu^2), kappa = 5/6, gives 3.036e-3
# without the clamped end's restraint of the cross-section.)
# Writes doc/benchmarks/slender_cantilever/results_nu<NU>.txt. Locking
# measured apart from softness (issue 45): run it at NU=0.3 as well; when
# results_nu0.4999.txt and results_nu0.3.txt both exist, the script writes
# locking_ratios.txt: per code and refinement tip(0.4999) / tip(0.3) against
# the exact ratio (plane-strain Timoshenko, as above, at both nu; and FEM
# Q1P0 at refinement 4 at both nu). RATIOS_ONLY=1 only rewrites that file.
# WEIGHTS_STUDY=1 (issue 45, deliverable 5) runs BCPBG Unl and the VCBCPBG
# codes Unl, UnlP0, Unl+P1C at refinements 0-2 with both 'Quadrature
# weights' (horizon, eq. 4.30; particle volumes) and writes
# results_nu<NU>_weights.txt.
# Usage (from the repository root):
#   sh doc/benchmarks/slender_cantilever.sh build-release/applications/pg_solve/pg_solve
#   NU=0.3 sh doc/benchmarks/slender_cantilever.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
NU=${NU:-0.4999}
OUT=doc/benchmarks/slender_cantilever
if [ -z "$RATIOS_ONLY" ]; then
MESH=${MESH:-/usr/share/petsc/3.18/share/petsc/datafiles/meshes/square_quad.msh}
[ -r "$MESH" ] || {
  echo "$MESH not found: install libpetsc3.18-dev-examples or set MESH=<path>"
  exit 1
}
WORK=$(mktemp -d)
mkdir -p "$OUT"
WEIGHTS=horizon
if [ -z "$WEIGHTS_STUDY" ]; then
  RESULTS="$OUT/results_nu$NU.txt"
else
  RESULTS="$OUT/results_nu${NU}_weights.txt"
fi
echo "# nu = $NU: formulation | global refinement | DoFs | tip u_y | Newton iterations" > "$RESULTS"

run() { # formulation refinement
  cat > "$WORK/run.prm" <<END
set Dimension = 2
subsection Geometry
  set Mesh              = file
  set File name         = $MESH
  set Global refinement = $2
end
subsection Discretization
  set Formulation = $1
  set Quadrature weights = $WEIGHTS
end
subsection Material
  set Model           = isochoric-volumetric neo-Hooke
  set Young's modulus = 1000
  set Poisson's ratio = $NU
end
subsection Boundary conditions
  set Dirichlet = 5: xy
  set Neumann   = 3
  subsection Traction
    set Function expression = 0; 0.01*t
  end
end
subsection Newton
  set Stagnation tolerance = ${STAGNATION:-1e-6}
end
subsection Linear solver
  set Type = direct
end
subsection Output
  set Directory = $WORK/out
  set VTU       = false
  set Points    = tip: 0.5, 0.05
end
END
  if "$PG_SOLVE" "$WORK/run.prm" > "$WORK/run.log" 2>&1; then
    LABEL="$1"
    [ -n "$WEIGHTS_STUDY" ] && LABEL="$1 ($WEIGHTS)"
    /usr/bin/env python3 - "$WORK/out/summary.json" "$LABEL" "$2" >> "$RESULTS" <<'END'
import json, sys
s = json.load(open(sys.argv[1]))
print("%s | %s | %d | %.5e | %d" % (sys.argv[2], sys.argv[3], s["n_dofs"],
      s["points"]["tip"][1], s["newton_iterations"]))
END
  else
    echo "$1 | $2 | - | failed: $(tail -n 2 "$WORK/run.log" | tr '\n' ' ')" >> "$RESULTS"
  fi
  tail -n 1 "$RESULTS"
}

if [ -n "$WEIGHTS_STUDY" ]; then
  for WEIGHTS in horizon "particle volumes"; do
    for r in 0 1 2; do
      for f in "BCPBG Unl" "VCBCPBG V5sn Unl" "VCBCPBG V5sn UnlP0" \
        "VCBCPBG V5sn Unl+P1C"; do
        run "$f" $r
      done
    done
  done
  rm -rf "$WORK"
  exit 0
fi
# at 103,000 DoFs the direct solve's round-off floor is 7.7e-6 |R_0|
STAGNATION=1e-4
run "FEM Q1P0" 4
STAGNATION=
for r in 0 1 2 3; do
  for f in "FEM" "FEM Q1P0" "VCBCPBG V5sn Unl" "VCBCPBG V5sn UnlP0" \
    "VCBCPPG V3sn UnlP0" "VCBCPBG V5sn Unl+P1C" "VCPBG V5sn U1SIG"; do
    run "$f" $r
  done
done
rm -rf "$WORK"
fi

# the locking ratio tip(nu = 0.4999) / tip(nu = 0.3) of each code on each
# mesh against the exact one
[ -r "$OUT/results_nu0.4999.txt" ] && [ -r "$OUT/results_nu0.3.txt" ] || exit 0
/usr/bin/env python3 - "$OUT/results_nu0.4999.txt" "$OUT/results_nu0.3.txt" \
  > "$OUT/locking_ratios.txt" <<'END'
import sys
def read(name):
    t = {}
    for l in open(name):
        r = [c.strip() for c in l.split("|")]
        if l.startswith("#") or len(r) != 5 or r[2] == "-":
            continue
        t[(r[0], int(r[1]))] = float(r[3])
    return t
a, b = read(sys.argv[1]), read(sys.argv[2])
# plane-strain Timoshenko: P L^3 / (3 E' I) + P L / (kappa G A), E' = E /
# (1 - nu^2), G = E / (2 (1 + nu)), kappa = 5/6, per unit depth
E, P, L, h = 1000.0, 1e-3, 1.0, 0.1
def timoshenko(nu):
    return (P * L**3 / (3 * E / (1 - nu * nu) * h**3 / 12)
            + P * L / (5 / 6 * E / (2 * (1 + nu)) * h))
exact = timoshenko(0.4999) / timoshenko(0.3)
print("# Timoshenko (plane strain): tip %.5e (nu = 0.4999), %.5e (nu = 0.3), "
      "ratio %.4f" % (timoshenko(0.4999), timoshenko(0.3), exact))
q = ("FEM Q1P0", 4)
if q in a and q in b:
    print("# FEM Q1P0, refinement 4: tip %.5e (nu = 0.4999), %.5e (nu = 0.3), "
          "ratio %.4f" % (a[q], b[q], a[q] / b[q]))
print("# formulation | refinement | tip(0.4999) | tip(0.3) | ratio | "
      "ratio / Timoshenko ratio")
for k in a:
    if k in b:
        print("%s | %d | %.5e | %.5e | %.4f | %.3f" % (
            k[0], k[1], a[k], b[k], a[k] / b[k], a[k] / b[k] / exact))
END
cat "$OUT/locking_ratios.txt"
