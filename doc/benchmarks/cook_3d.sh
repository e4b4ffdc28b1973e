#!/bin/sh
# B-12: Cook's membrane in 3-D on irregular particles (dissertation section
# 7.3.4, Fig. 7.21), reconstructed in prm/cook_membrane_3d.prm. For each
# mesh n x n x n/4 (n = 4 ... 24, interior vertices moved at random by up to
# 0.3 x their shortest edge, seed n) the corner displacement u_y at
# (48, 60, 0) and the wall time of the two load steps:
#   (a) nu = 0.357, displacement formulations with CG + ML AMG: FEM Q1 on
#       the same nodes, BCPBG Unl, VCBCPBG V5sn Unl, VCBCPPG V3sn Unl;
#       reference: FEM Q1 on the regular meshes n = 20, 30, 40,
#       extrapolated (the order fitted to the three values);
#   (b) nu = 0.4999999, direct solver (MUMPS), 2 load steps and
#       'Stagnation tolerance = 1e-4' (the round-off floor of the residual
#       is 1e-8 to 1e-5 |R_0| at K/mu = 5e6): FEM Q1, FEM H1P0, VCBCPBG V5sn
#       Unl, BCPBG UnlP0, VCBCPBG V5sn UnlP0, VCBCPBG V5sn Unl+P1C (nodal
#       p and Theta), and the incompressible VCBCPBG V5sn IUnlP0 at nu = 0.5
#       with the same mu; reference: FEM H1P0 on the
#       regular meshes n = 16, 24, 32, extrapolated. The mixed codes run with the default
#       'Condensed fields = linearized'; with 'equilibrium' (CONDENSED=
#       equilibrium) they need 32 load steps (LOAD_STEPS_B=32) and some 500
#       Newton iterations each (cook_3d/results_panel_b_equilibrium.txt).
# Writes doc/benchmarks/cook_3d/results.txt and doc/figures/cook_3d.png
# (doc/figures/cook_3d_tets.png for the tetrahedral panels)
# (PLOT_ONLY=1: redraw from an existing results.txt; ONLY=<label>: run one
# method and append its rows; PANEL=a or b: run one panel and append;
# SIZES_A="32 48 ...": panel a's n instead of 4 8 12 16 24, as for the
# large runs of the wall time against DoFs, e.g.
#   PANEL=a ONLY="FEM Q1" SIZES_A="32 48 64 88 116" sh doc/benchmarks/cook_3d.sh).
# PANEL=tets: the same two panels on unstructured tetrahedral meshes, as the
# source ran them (issue 49): gmsh (not needed otherwise) meshes
# prm/cook_membrane_3d_tets.geo with the target edge lengths H_TETS (default
# "16 5.2 3.5 2.4 1.55": 49 to 4,336 particles, about the range of the
# hexahedral series), and every method runs on the same meshes, FEM being
# P1 on the same nodes (the source's O1): panel ta (nu = 0.357, CG + ML;
# FEM P1, BCPBG Unl, VCBCPBG V5sn Unl, VCBCPPG V3sn Unl) and panel tb
# (nu = 0.4999999, MUMPS; FEM P1, BCPBG UnlP0, VCBCPBG V5sn UnlP0, and
# VCBCPBG V5sn Unl+P1C for h >= H_P1C_MIN, default 2.4). Their rows carry
# three more columns: setup s (mesh, particles, families, shape functions),
# mean family size, matrix nonzeros; the reference values are panel a's and
# b's (hexahedral FEM, extrapolated). PANEL=ta or tb runs one of them.
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/cook_3d.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/cook_3d
WORK=$(mktemp -d)
mkdir -p "$OUT" doc/figures
RESULTS="$OUT/results.txt"

run() { # panel label formulation n distortion nu solver [load steps [stagnation tolerance [E]]]
  # (with MESH_FILE set: n is the label of that mesh file, the mesh size h)
  [ -n "$ONLY" ] && [ "$2" != "$ONLY" ] && return 0
  name=$(echo "$1_$2_$4" | tr ' /' '__')
  if [ -n "$MESH_FILE" ]; then
    geometry="  set Mesh = file
  set File name = $MESH_FILE
  set Distortion = 0"
  else
    nz=$(( $4 / 4 )); [ $nz -ge 1 ] || nz=1
    geometry="  set Subdivisions = $4, $4, $nz
  set Distortion   = $5
  set Random seed  = $4"
  fi
  cat > "$WORK/$name.prm" <<END
include $(pwd)/prm/cook_membrane_3d.prm
subsection Geometry
$geometry
end
subsection Discretization
  set Formulation = $3
end
subsection Material
  set Poisson's ratio = $6
  ${10:+set Young's modulus = ${10}}
end
subsection Linear solver
  set Type = $7
end
subsection Loading
  set Load steps = ${8:-2}
end
subsection Newton
  set Stagnation tolerance = ${9:-1e-6}
  set Condensed fields     = ${CONDENSED:-linearized}
end
subsection Output
  set Directory = $WORK/$name
  set VTU       = false
end
END
  if /usr/bin/time -f "%e %M" -o "$WORK/$name.time" "$PG_SOLVE" "$WORK/$name.prm" > "$WORK/$name.log" 2>&1; then
    /usr/bin/env python3 - "$WORK/$name/summary.json" "$WORK/$name.time" "$1" "$2" "$4" "$WORK/$name.log" "$MESH_FILE" >> "$RESULTS" <<'END'
import json, re, sys
s = json.load(open(sys.argv[1]))
wall, kb = open(sys.argv[2]).read().split()[-2:]
t = s["timing"]
row = "%s | %s | %s | %d | %.5f | %d | %.2f | %.2f | %.2f | %s | %.0f" % (
    sys.argv[3], sys.argv[4], sys.argv[5], s["n_dofs"],
    s["points"]["corner"][1], s["newton_iterations"], t["assembly"],
    t["solve"], t.get("vc", 0.), wall, int(kb) / 1024.)
if sys.argv[7]:
    # tetrahedral rows: setup, mean family size (0: FEM), nonzeros
    family = re.search(r"family size: +min \d+, mean ([0-9.]+)",
                       open(sys.argv[6]).read())
    row += " | %.2f | %s | %d" % (
        t["mesh"] + t["setup"] + t.get("shape_functions", 0.),
        family.group(1) if family else "0", s["matrix_nonzeros"])
print(row)
END
  else
    echo "$1 | $2 | $4 | - | failed: $(tail -n 3 "$WORK/$name.log" | tr '\n' ' ')" >> "$RESULTS"
  fi
  tail -n 1 "$RESULTS"
}

if [ -z "$PLOT_ONLY" ]; then
[ -n "$ONLY" ] || [ -n "$PANEL" ] || echo "# panel | label | n | DoFs | corner u_y | Newton steps | assembly s | solve s | VC s | wall s | peak MB" > "$RESULTS"
if [ "${PANEL:-a}" = a ]; then
for n in 20 30 40; do
  run a reference FEM $n 0 0.357142857142857143 cg
done
for n in ${SIZES_A:-4 8 12 16 24}; do
  run a "FEM Q1" FEM $n 0.3 0.357142857142857143 cg
  run a "BCPBG Unl" "BCPBG Unl" $n 0.3 0.357142857142857143 cg
  run a "VCBCPBG V5sn Unl" "VCBCPBG V5sn Unl" $n 0.3 0.357142857142857143 cg
  run a "VCBCPPG V3sn Unl" "VCBCPPG V3sn Unl" $n 0.3 0.357142857142857143 gmres
done
fi
if [ "${PANEL:-b}" = b ]; then
steps=${LOAD_STEPS_B:-2}
for n in 16 24 32; do
  run b reference "FEM H1P0" $n 0 0.4999999 direct $steps 1e-4
done
for n in 4 8 12 16 24; do
  run b "FEM Q1" FEM $n 0.3 0.4999999 direct $steps 1e-4
  run b "FEM H1P0" "FEM H1P0" $n 0.3 0.4999999 direct $steps 1e-4
  run b "VCBCPBG V5sn Unl" "VCBCPBG V5sn Unl" $n 0.3 0.4999999 direct $steps 1e-4
  run b "BCPBG UnlP0" "BCPBG UnlP0" $n 0.3 0.4999999 direct $steps 1e-4
  run b "VCBCPBG V5sn UnlP0" "VCBCPBG V5sn UnlP0" $n 0.3 0.4999999 direct $steps 1e-4
  run b "VCBCPBG V5sn Unl+P1C" "VCBCPBG V5sn Unl+P1C" $n 0.3 0.4999999 direct $steps 1e-4
  # the incompressible limit: nu = 0.5 with the same mu (E = 3 mu)
  run b "VCBCPBG V5sn IUnlP0" "VCBCPBG V5sn IUnlP0" $n 0.3 0.5 direct $steps 1e-4 108.5714358095243
done
fi
case "$PANEL" in tets|ta|tb)
  command -v gmsh > /dev/null || { echo "PANEL=$PANEL needs gmsh"; exit 1; }
  for h in ${H_TETS:-16 5.2 3.5 2.4 1.55}; do
    MESH_FILE="$WORK/cook_tets_h$h.msh"
    gmsh -3 -format msh2 -setnumber h "$h" prm/cook_membrane_3d_tets.geo \
      -o "$MESH_FILE" > "$WORK/gmsh_h$h.log" 2>&1
    echo "# h = $h: $(sed -n '/^\$Nodes/{n;p;}' "$MESH_FILE") vertices ($(gmsh --version 2>&1))" >> "$RESULTS"
    if [ "$PANEL" != tb ]; then
      run ta "FEM P1" FEM $h 0 0.357142857142857143 cg
      run ta "BCPBG Unl" "BCPBG Unl" $h 0 0.357142857142857143 cg
      run ta "VCBCPBG V5sn Unl" "VCBCPBG V5sn Unl" $h 0 0.357142857142857143 cg
      run ta "VCBCPPG V3sn Unl" "VCBCPPG V3sn Unl" $h 0 0.357142857142857143 gmres
    fi
    if [ "$PANEL" != ta ]; then
      run tb "FEM P1" FEM $h 0 0.4999999 direct 2 1e-4
      run tb "BCPBG UnlP0" "BCPBG UnlP0" $h 0 0.4999999 direct 2 1e-4
      run tb "VCBCPBG V5sn UnlP0" "VCBCPBG V5sn UnlP0" $h 0 0.4999999 direct 2 1e-4
      if [ "$(echo "$h >= ${H_P1C_MIN:-2.4}" | bc)" = 1 ]; then
        run tb "VCBCPBG V5sn Unl+P1C" "VCBCPBG V5sn Unl+P1C" $h 0 0.4999999 direct 2 1e-4
      fi
    fi
  done
  unset MESH_FILE
esac
rm -rf "$WORK"
fi

PYTHON=python3
[ -x /usr/bin/python3 ] && PYTHON=/usr/bin/python3
"$PYTHON" - "$RESULTS" <<'END'
import sys
rows = [l.strip().split(" | ") for l in open(sys.argv[1]) if not l.startswith("#")]
rows = [r for r in rows if len(r) >= 11]


def reference(panel):
    """The finest reference value, or with three regular meshes n1 < n2 <
    n3 the extrapolation u3 + C n3^-p with the order p fitted to them. The
    tetrahedral panels ta and tb take those of a and b."""
    panel = panel[-1]
    ref = sorted((int(r[2]), float(r[4])) for r in rows
                 if r[0] == panel and r[1] == "reference")
    if len(ref) < 3:
        return ref[-1][1] if ref else None
    (n1, u1), (n2, u2), (n3, u3) = ref[-3:]
    ratio = (u2 - u1) / (u3 - u2)
    f = lambda p: (n1**-p - n2**-p) / (n2**-p - n3**-p) - ratio
    lo, hi = 0.2, 6.
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if f(lo) * f(mid) <= 0 else (mid, hi)
    p = 0.5 * (lo + hi)
    return u3 + (u3 - u2) / (n2**-p - n3**-p) * n3**-p


for panel in ("a", "b", "ta", "tb"):
    ref = reference(panel)
    if ref is None:
        continue
    print("panel %s: reference corner u_y = %.4f" % (panel, ref))
    for label in dict.fromkeys(r[1] for r in rows if r[0] == panel and r[1] != "reference"):
        print("  %-20s" % label + "".join(
            " %s=%s: %+.2f %%" % ("h" if panel[0] == "t" else "n", r[2],
                                 100 * (float(r[4]) - ref) / ref)
            for r in rows if r[0] == panel and r[1] == label))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
def figure(pair, path, what):
    """Corner u_y against the particles and accuracy against wall time of
    the two panels of @p pair."""
    fig, ax = plt.subplots(1, 4, figsize=(20, 4.2))
    for k, (panel, title) in enumerate(pair):
        ref = reference(panel)
        for label in dict.fromkeys(r[1] for r in rows if r[0] == panel and r[1] != "reference"):
            data = [r for r in rows if r[0] == panel and r[1] == label]
            # (Unl+P1C: 3 displacements, p and Theta per node)
            particles = [int(r[3]) // (5 if "P1C" in label else 3) for r in data]
            ax[k].semilogx(particles, [float(r[4]) for r in data], marker="o", label=label)
            if ref is not None:
                ax[2 + k].loglog([float(r[9]) for r in data],
                                 [abs(float(r[4]) - ref) / ref for r in data],
                                 marker="o", label=label)
        if ref is not None:
            ax[k].axhline(ref, color="k", lw=0.8)
        ax[k].set_xlabel("nodes (particles)"); ax[k].set_ylabel("corner u_y")
        ax[k].set_title(title); ax[k].legend(fontsize=7)
    for k, title in ((2, "accuracy against time (%s, CG + ML)" % pair[0][0]),
                     (3, "accuracy against time (%s, MUMPS)" % pair[1][0])):
        ax[k].set_xlabel("wall time, 2 load steps [s]")
        ax[k].set_ylabel("|u_y - u_ref| / u_ref")
        ax[k].set_title(title); ax[k].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if any(r[0] in ("a", "b") for r in rows):
    figure((("a", "nu = 0.357, displacement"), ("b", "nu = 0.4999999")),
           "doc/figures/cook_3d.png", "hexahedra")
if any(r[0] in ("ta", "tb") for r in rows):
    figure((("ta", "tetrahedra, nu = 0.357, displacement"),
            ("tb", "tetrahedra, nu = 0.4999999")),
           "doc/figures/cook_3d_tets.png", "tetrahedra")
END
