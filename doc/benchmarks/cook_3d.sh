#!/bin/sh
# B-12: Cook's membrane in 3-D on irregular particles (dissertation section
# 7.3.4, Fig. 7.21), reconstructed in prm/cook_membrane_3d.prm. For each
# mesh n x n x n/4 (n = 4 ... 24, interior vertices moved at random by up to
# 0.3 x their shortest edge, seed n) the corner displacement u_y at
# (48, 60, 0) and the wall time of the two load steps:
#   (a) nu = 0.357, displacement formulations with CG + ML AMG: FEM Q1 on
#       the same nodes, BCPBG Unl, VCBCPBG V5sn Unl, VCBCPPG V3sn Unl;
#       reference: FEM Q1 on the regular 40 x 40 x 10 mesh;
#   (b) nu = 0.4999999, direct solver (MUMPS): FEM Q1, FEM H1P0, VCBCPBG
#       V5sn Unl, BCPBG UnlP0, VCBCPBG V5sn UnlP0; reference: FEM H1P0 on
#       the regular 32 x 32 x 8 mesh.
# Writes doc/benchmarks/cook_3d/results.txt and doc/figures/cook_3d.png
# (PLOT_ONLY=1: redraw from an existing results.txt; ONLY=<label>: run one
# method and append its rows).
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/cook_3d.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/cook_3d
WORK=$(mktemp -d)
mkdir -p "$OUT" doc/figures
RESULTS="$OUT/results.txt"

run() { # panel label formulation n distortion nu solver
  [ -n "$ONLY" ] && [ "$2" != "$ONLY" ] && return 0
  name=$(echo "$1_$2_$4" | tr ' /' '__')
  nz=$(( $4 / 4 )); [ $nz -ge 1 ] || nz=1
  cat > "$WORK/$name.prm" <<END
include $(pwd)/prm/cook_membrane_3d.prm
subsection Geometry
  set Subdivisions = $4, $4, $nz
  set Distortion   = $5
  set Random seed  = $4
end
subsection Discretization
  set Formulation = $3
end
subsection Material
  set Poisson's ratio = $6
end
subsection Linear solver
  set Type = $7
end
subsection Output
  set Directory = $WORK/$name
  set VTU       = false
end
END
  if /usr/bin/time -f "%e %M" -o "$WORK/$name.time" "$PG_SOLVE" "$WORK/$name.prm" > "$WORK/$name.log" 2>&1; then
    /usr/bin/env python3 - "$WORK/$name/summary.json" "$WORK/$name.time" "$1" "$2" "$4" >> "$RESULTS" <<'END'
import json, sys
s = json.load(open(sys.argv[1]))
wall, kb = open(sys.argv[2]).read().split()[-2:]
t = s["timing"]
print("%s | %s | %s | %d | %.5f | %d | %.2f | %.2f | %.2f | %s | %.0f" % (
    sys.argv[3], sys.argv[4], sys.argv[5], s["n_dofs"],
    s["points"]["corner"][1], s["newton_iterations"], t["assembly"],
    t["solve"], t.get("vc", 0.), wall, int(kb) / 1024.))
END
  else
    echo "$1 | $2 | $4 | - | failed: $(tail -n 3 "$WORK/$name.log" | tr '\n' ' ')" >> "$RESULTS"
  fi
  tail -n 1 "$RESULTS"
}

if [ -z "$PLOT_ONLY" ]; then
[ -n "$ONLY" ] || echo "# panel | label | n | DoFs | corner u_y | Newton steps | assembly s | solve s | VC s | wall s | peak MB" > "$RESULTS"
run a reference FEM 40 0 0.357142857142857143 cg
for n in 4 8 12 16 24; do
  run a "FEM Q1" FEM $n 0.3 0.357142857142857143 cg
  run a "BCPBG Unl" "BCPBG Unl" $n 0.3 0.357142857142857143 cg
  run a "VCBCPBG V5sn Unl" "VCBCPBG V5sn Unl" $n 0.3 0.357142857142857143 cg
  run a "VCBCPPG V3sn Unl" "VCBCPPG V3sn Unl" $n 0.3 0.357142857142857143 gmres
done
run b reference "FEM H1P0" 32 0 0.4999999 direct
for n in 4 8 12 16 24; do
  run b "FEM Q1" FEM $n 0.3 0.4999999 direct
  run b "FEM H1P0" "FEM H1P0" $n 0.3 0.4999999 direct
  run b "VCBCPBG V5sn Unl" "VCBCPBG V5sn Unl" $n 0.3 0.4999999 direct
  run b "BCPBG UnlP0" "BCPBG UnlP0" $n 0.3 0.4999999 direct
  run b "VCBCPBG V5sn UnlP0" "VCBCPBG V5sn UnlP0" $n 0.3 0.4999999 direct
done
rm -rf "$WORK"
fi

PYTHON=python3
[ -x /usr/bin/python3 ] && PYTHON=/usr/bin/python3
"$PYTHON" - "$RESULTS" <<'END'
import sys
rows = [l.strip().split(" | ") for l in open(sys.argv[1]) if not l.startswith("#")]
rows = [r for r in rows if len(r) == 11]
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
for k, (panel, title) in enumerate((("a", "nu = 0.357, displacement"),
                                    ("b", "nu = 0.4999999"))):
    ref = [float(r[4]) for r in rows if r[0] == panel and r[1] == "reference"]
    for label in dict.fromkeys(r[1] for r in rows if r[0] == panel and r[1] != "reference"):
        data = [r for r in rows if r[0] == panel and r[1] == label]
        particles = [int(r[3]) // 3 for r in data]
        ax[k].semilogx(particles, [float(r[4]) for r in data], marker="o", label=label)
        if panel == "a" and label in ("FEM Q1", "VCBCPBG V5sn Unl"):
            ax[2].loglog([int(r[3]) for r in data], [float(r[9]) for r in data],
                         marker="o", label=label)
    if ref:
        ax[k].axhline(ref[0], color="k", lw=0.8)
    ax[k].set_xlabel("nodes (particles)"); ax[k].set_ylabel("corner u_y")
    ax[k].set_title(title); ax[k].legend(fontsize=7)
ax[2].set_xlabel("DoFs"); ax[2].set_ylabel("wall time, 2 load steps [s]")
ax[2].set_title("cost (panel a runs, CG + ML)"); ax[2].legend(fontsize=7)
fig.tight_layout()
fig.savefig("doc/figures/cook_3d.png", dpi=110)
END
