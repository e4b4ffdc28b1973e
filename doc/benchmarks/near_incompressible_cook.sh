#!/bin/sh
# Volumetric locking on Cook's membrane (2-D plane strain, the
# isochoric-volumetric neo-Hooke with E = 108.57 and nu = 0.4999, K/mu =
# 5000; the tip load of prm/cook_membrane_2d.prm in 5 load steps): the
# vertical tip displacement against the number of DoFs for the displacement
# formulations (FEM Q1, VCBCPBG V5sn Unl, VCBCPPG V3sn Unl), their mixed
# counterparts (FEM Q1P0, VCBCPBG V5sn UnlP0, VCBCPPG V3sn UnlP0) and a
# coupled mixed model (UnlP0 particles on the right half, Q1P0 cells on the
# left), with the time per Newton step. The reference is FEM Q1P0 on a
# 256 x 256 mesh. Writes doc/benchmarks/near_incompressible_cook/results.txt
# and doc/figures/near_incompressible_cook.png (PLOT_ONLY=1: redraw the
# figure from an existing results.txt; ONLY=<label>: run one method and
# append its rows). U1SUnl (eq. 6.18) is shown with the displacement
# formulations: its pseudo-energy takes nu~ = 0.49; the quadratic U2 and its
# mixed U2P1 (eq. 6.10, p and Theta linear per family) as a pair too, and
# the mixed codes with nodal p and Theta, Unl+P1C and U2P1C; and the
# incompressible IUnlP0 at nu = 0.5 with the same shear modulus.
# NU=0.3 (issue 45: the locking ratio tip(0.4999) / tip(0.3) of each code on
# each mesh) runs the same codes at that nu with the same E, without the
# IUnlP0 rows and the figure, into near_incompressible_cook/results_nu0.3.txt;
# NS="4 8 16" limits the meshes (default 4 8 16 32 64).
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/near_incompressible_cook.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/near_incompressible_cook
WORK=$(mktemp -d)
mkdir -p "$OUT" doc/figures
NU=${NU:-0.4999}
NS=${NS:-4 8 16 32 64}
RESULTS="$OUT/results.txt"
[ "$NU" = 0.4999 ] || RESULTS="$OUT/results_nu$NU.txt"

run() { # label formulation N [meshfree region [horizon factor [nu [E]]]]
  # ONLY=<label>: run that method alone and append its rows
  [ -n "$ONLY" ] && [ "$1" != "$ONLY" ] && return 0
  name=$(echo "$1_$3" | tr ' /' '__')
  region=${4:-all}
  horizon=${5:-2.51}
  nu=${6:-$NU}
  E=${7:-108.571428571428571}
  [ "$2" = FEM ] || [ "$2" = "FEM Q1P0" ] && region=none
  cat > "$WORK/$name.prm" <<END
set Dimension = 2
subsection Geometry
  set Mesh              = cook membrane
  set Subdivisions      = $3
  set Global refinement = 0
  set Meshfree region   = $region
end
subsection Discretization
  set Formulation    = $2
  set Horizon factor = $horizon
end
subsection Material
  set Model           = isochoric-volumetric neo-Hooke
  set Young's modulus = $E
  set Poisson's ratio = $nu
end
subsection Boundary conditions
  set Dirichlet = 0: xy
  set Neumann   = 1
  subsection Traction
    set Function expression = 0; t
  end
end
subsection Loading
  set Load steps = 5
end
subsection Linear solver
  set Type = direct
end
subsection Output
  set Directory = $WORK/$name
  set VTU       = false
  set Points    = tip: 48, 60
end
END
  if "$PG_SOLVE" "$WORK/$name.prm" > "$WORK/$name.log" 2>&1; then
    /usr/bin/env python3 - "$WORK/$name/summary.json" "$1" "$2" "$3" >> "$RESULTS" <<'END'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timing"]
n = max(s["newton_iterations"], 1)
print("%s | %s | %s | %d | %.6f | %d | %.4f | %.2f" % (
    sys.argv[2], sys.argv[3], sys.argv[4], s["n_dofs"],
    s["points"]["tip"][1], n, (t["assembly"] + t["solve"]) / n, t["total"]))
END
  else
    echo "$1 | $2 | $3 | - | failed: $(tail -n 3 "$WORK/$name.log" | tr '\n' ' ')" >> "$RESULTS"
  fi
  tail -n 1 "$RESULTS"
}

if [ -z "$PLOT_ONLY" ]; then
[ -n "$ONLY" ] || echo "# label | formulation | N | DoFs | tip u_y | Newton steps | seconds per Newton step (assembly + solve) | total seconds" > "$RESULTS"
run reference "FEM Q1P0" 256
for N in $NS; do
  run "FEM Q1" FEM $N
  run "FEM Q1P0" "FEM Q1P0" $N
  run "VCBCPBG V5sn Unl" "VCBCPBG V5sn Unl" $N
  run "VCBCPBG V5sn UnlP0" "VCBCPBG V5sn UnlP0" $N
  run "VCBCPPG V3sn Unl" "VCBCPPG V3sn Unl" $N
  run "VCBCPPG V3sn UnlP0" "VCBCPPG V3sn UnlP0" $N
  run "coupled UnlP0/Q1P0" "VCBCPPG V3sn UnlP0" $N "box 24, -1 : 49, 61"
  run "VCBCPBG V5sn U1SUnl" "VCBCPBG V5sn U1SUnl" $N
  # WTE2 needs two particle columns on each side: the cells at the tip
  # have an aspect ratio of 3, where 2.51 h holds one column (singular)
  run "VCPBG V5sn U2" "VCPBG V5sn U2" $N all 3.51
  run "VCPBG V5sn U2P1" "VCPBG V5sn U2P1" $N all 3.51
  run "VCPBG V5sn U1SIG" "VCPBG V5sn U1SIG" $N
  # nodal p and Theta (eqs. 6.11-6.16)
  run "VCBCPBG V5sn Unl+P1C" "VCBCPBG V5sn Unl+P1C" $N
  run "VCPBG V5sn U2P1C" "VCPBG V5sn U2P1C" $N all 3.51
  # the incompressible IUnlP0 at nu = 0.5 with the same mu = E / (2 (1 +
  # 0.4999)) (E = 3 mu): the incompressible limit of the reference problem
  [ "$NU" = 0.4999 ] || continue
  run "VCBCPBG V5sn IUnlP0" "VCBCPBG V5sn IUnlP0" $N all 2.51 0.5 108.578667149239
  run "VCBCPPG V3sn IUnlP0" "VCBCPPG V3sn IUnlP0" $N all 2.51 0.5 108.578667149239
done
rm -rf "$WORK"
fi
[ "$NU" = 0.4999 ] || exit 0

# Debian's python3 has matplotlib (python3-matplotlib); a python3 without it
# skips the figure.
PYTHON=python3
[ -x /usr/bin/python3 ] && PYTHON=/usr/bin/python3
"$PYTHON" - "$RESULTS" <<'END'
import sys
rows = [l.split(" | ") for l in open(sys.argv[1]) if not l.startswith("#")]
rows = [r for r in rows if len(r) == 8]
ref = float([r for r in rows if r[0] == "reference"][0][4])
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
for i, label in enumerate(dict.fromkeys(r[0] for r in rows if r[0] != "reference")):
    data = [r for r in rows if r[0] == label]
    dofs = [int(r[3]) for r in data]
    dashed = ("Unl" in label and "P0" not in label and "P1C" not in label
              or label == "FEM Q1" or label.endswith(" U2"))
    style = "--" if dashed else "-"
    color = plt.cm.tab20(i % 20)
    ax[0].semilogx(dofs, [float(r[4]) for r in data], style, marker="o", color=color, label=label)
    ax[1].loglog(dofs, [abs(float(r[4]) - ref) / ref for r in data], style, marker="o", color=color, label=label)
ax[0].axhline(ref, color="k", lw=0.8)
ax[0].set_xlabel("DoFs"); ax[0].set_ylabel("tip u_y")
ax[1].set_xlabel("DoFs"); ax[1].set_ylabel("|u_y - u_ref| / u_ref")
ax[0].set_title("Cook's membrane, nu = 0.4999 (dashed: displacement)")
ax[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig("doc/figures/near_incompressible_cook.png", dpi=110)
END
