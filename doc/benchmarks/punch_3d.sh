#!/bin/sh
# Benchmark B-11 (dissertation section 7.3.3, Figs. 7.19-7.20): the 3-D
# punch of prm/punch_3d.prm (quarter block 0.1 x 0.1 x 0.05 m, dead load
# q = 9 N/m^2 on the top patch 0 <= x, y <= 0.05 held horizontally,
# symmetry at x = 0 and y = 0, wall at z = 0, isochoric-volumetric
# neo-Hooke E = 4.8293 N/m^2) on n x n x n/2 cells / (n+1)^2 (n/2+1)
# particles, for nu = 0.4 and nu = 0.49999, and for the incompressible
# IUnlP0 at nu = 0.5 (shown beside nu = 0.49999). Recorded per run: u_z at the
# patch centre (the minimal u_z) at the last completed load step, the
# load factor reached, Newton iterations, wall time and exit code.
# The reference ('overkill') is FEM H1P0 on the finest mesh of REF_N.
# RUNS="<nu>|<formulation>|<linear solver>|<n list>;..." replaces the
# default set below. Each run is skipped when its line is already in
# results.txt (delete the file to redo everything).
# PLOT_ONLY=1: only redraw the figure. PYTHON=<python with matplotlib>.
# TREATMENT=mirror (default: mirrored families at the symmetry planes, the
# full block's solution) or constraint (the dissertation's u_n = 0 with
# families cut off there); MODEL=quarter (default) or full (the whole
# block -0.1 <= x, y <= 0.1 with the centred patch, 4x the particles).
# Q=<load> and STEPS=<load steps> change q = 9 N/m^2 and the 10 steps
# (Q=0.009 STEPS=1: the linear regime).
# Writes doc/benchmarks/punch_3d/results_<TREATMENT>[_full][_q<Q>].txt and
# doc/figures/punch_3d.png (of TREATMENT=mirror, MODEL=quarter, q = 9).
# Usage (from the repository root, with a Release build; about 40 minutes
# on 2 cores):
#   sh doc/benchmarks/punch_3d.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=${OUT:-doc/benchmarks/punch_3d}
PYTHON=${PYTHON:-/usr/bin/python3}
ROOT=$(pwd)
WORK=$(mktemp -d)
TREATMENT=${TREATMENT:-mirror}
MODEL=${MODEL:-quarter}
Q=${Q:-9}
STEPS=${STEPS:-10}
SUFFIX="_$TREATMENT"
[ "$MODEL" = quarter ] || SUFFIX="${SUFFIX}_$MODEL"
[ "$Q" = 9 ] || SUFFIX="${SUFFIX}_q$Q"
RESULTS="$OUT/results$SUFFIX.txt"
if [ "$SUFFIX" = _mirror ]; then FIG=${FIG:-doc/figures/punch_3d.png}; else FIG=${FIG:-doc/figures/punch_3d$SUFFIX.png}; fi
mkdir -p "$OUT" "$(dirname "$FIG")"
if [ "$MODEL" = full ]; then
  # the whole block: patch -0.05 <= x, y <= 0.05, its vertices held in x
  # and y, n x n x n/4 cells (the spacing of the quarter's n/2)
  NZ_DIVISOR=4
  GEOMETRY="  set Lower corner = -0.1, -0.1, 0"
  BOXES="  set Dirichlet boxes = -0.05, -0.05, 0.05 : 0.05, 0.05, 0.05 : xy"
  SYMMETRY="  set Symmetry ="
  PATCH="if(abs(x) < a - e, 1, if(abs(x) < a + e, 0.5, 0)) * if(abs(y) < a - e, 1, if(abs(y) < a + e, 0.5, 0))"
else
  NZ_DIVISOR=2
  GEOMETRY=""
  BOXES=""
  SYMMETRY="  set Symmetry = 0, 2"
  PATCH="if(x < a - e, 1, if(x < a + e, 0.5, 0)) * if(y < a - e, 1, if(y < a + e, 0.5, 0))"
fi

# nu = 0.4: the legend of Fig. 7.20 (left); nu = 0.49999: the formulations
# of the text. PPG tangents are not symmetric: GMRES. Near incompressibility ML's CG does not converge in
# reasonable time, so those runs use the direct solver.
[ -n "$RUNS" ] || RUNS="0.4|FEM|cg|4 8 12 16 24 32;\
0.4|FEM H1P0|cg|4 8 12 16 24 32 40;\
0.4|PPG Unl|gmres|4 8 12 16;\
0.4|PBG Unl|cg|4 8 12 16;\
0.4|VCPBG Unl|cg|4 8 12 16;\
0.4|VCPBG U1SIG|cg|4 8 12;\
0.49999|FEM|direct|4 8 12 16;\
0.49999|FEM H1P0|direct|4 8 12 16 24;\
0.49999|VCPBG Unl|direct|4 8 12;\
0.49999|VCPBG UnlP0|direct|4 8 12;\
0.49999|VCPPG UnlP0|direct|4 8 12;\
0.49999|PBG Unl+P1C|direct|4 8 12;\
0.5|VCPPG IUnlP0|direct|4 8 12;\
0.5|VCPBG IUnlP0|direct|4 8 12"

[ -f "$RESULTS" ] || [ -n "$PLOT_ONLY" ] ||
  echo "# nu | formulation | n | nodes (= particles) | DoFs | u_z at the patch centre | load factor reached | Newton iterations | wall (s) | exit code | stop message (shortened)" > "$RESULTS"

if [ -z "$PLOT_ONLY" ]; then
echo "$RUNS" | tr ';' '\n' | while IFS='|' read -r nu f solver ns; do
  for n in $ns; do
    if grep -q "^$nu | $f | $n |" "$RESULTS"; then continue; fi
    cat > "$WORK/run.prm" <<END
include $ROOT/prm/punch_3d.prm
subsection Geometry
  set Subdivisions = $n, $n, $((n / NZ_DIVISOR))
$GEOMETRY
end
subsection Boundary conditions
$SYMMETRY
  set Symmetry treatment = $TREATMENT
$BOXES
  subsection Traction
    set Function constants  = q = $Q, a = 0.05, e = 1e-9
    set Function expression = 0; 0; -q * t * $PATCH
  end
end
subsection Loading
  set Load steps = $STEPS
end
subsection Discretization
  set Formulation = $f
end
subsection Material
  set Poisson's ratio = $nu
end
subsection Linear solver
  set Type = $solver
end
subsection Output
  set Directory = $WORK/out
  set VTU       = false
end
END
    rm -rf "$WORK/out"
    rc=0
    "$PG_SOLVE" "$WORK/run.prm" > "$WORK/run.log" 2>&1 || rc=$?
    "$PYTHON" - "$WORK/out" "$nu" "$f" "$n" "$rc" "$NZ_DIVISOR" >> "$RESULTS" <<'END'
import json, re, sys
out, nu, name, n, rc, nz_divisor = sys.argv[1:7]
try:
    s = json.load(open(out + "/summary.json"))
except OSError:
    print("%s | %s | %s | - | - | - | 0 | - | - | %s | no summary.json" % (nu, name, n, rc))
    sys.exit(0)
msg = s.get("message", "")
hit = re.search(r"last load factor reached: ([0-9.eE+-]+)", msg)
t = float(hit.group(1)) if hit else (1.0 if s.get("converged") else float("nan"))
rows = [l.split() for l in open(out + "/statistics.txt") if not l.startswith("#")]
# summary.json's points hold the last completed load step in full
# precision; statistics.txt (step, load factor, Newton iterations,
# residual, u of 'punch centre', wall time) only 3 digits
point = s.get("points", {}).get("punch centre")
uz = "%.6g" % point[2] if point else (rows[-1][6] if rows else "-")
short = msg.split(". ")[0] if msg else "finished"
print("%s | %s | %s | %d | %d | %s | %.4f | %d | %.1f | %s | %s" % (
    nu, name, n, (int(n) + 1) ** 2 * (int(n) // int(nz_divisor) + 1), s["n_dofs"], uz, t, s["newton_iterations"],
    s["timing"]["total"], rc, short))
END
    tail -n 1 "$RESULTS"
  done
done
fi
rm -rf "$WORK"

"$PYTHON" - "$RESULTS" "$FIG" <<'END'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
results, fig_path = sys.argv[1:3]
rows = [l.rstrip("\n").split(" | ") for l in open(results) if not l.startswith("#")]
fig, axs = plt.subplots(1, 2, figsize=(12, 4.8))
for ax, nu in zip(axs, ("0.4", "0.49999")):
    series = {}
    for r in rows:
        # (the incompressible IUnlP0 at nu = 0.5 beside nu = 0.49999)
        same = r[0] == nu or (nu == "0.49999" and r[0] == "0.5")
        if same and r[5] != "-" and float(r[6]) == 1.0:
            name = r[1] + (" (nu = 0.5)" if r[0] == "0.5" else "")
            series.setdefault(name, []).append((int(r[3]), float(r[5])))
    ref = sorted(series.get("FEM H1P0", []))
    if ref:
        ax.axhline(ref[-1][1], color="k", lw=0.8,
                   label="FEM H1P0, %d nodes (reference)" % ref[-1][0])
    for name, pts in series.items():
        pts.sort()
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=name)
    ax.set_xscale("log")
    ax.set_xlabel("particles / nodes")
    ax.set_ylabel("minimal $u_z$ (m), at the patch centre")
    ax.set_title(r"3-D punch, $\nu$ = %s (completed runs)" % nu)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(fig_path, dpi=120)
print("wrote", fig_path)

# the tables of doc/benchmarks/punch_3d.md: deviation from the finest
# completed FEM H1P0 run of the same nu
for nu in ("0.4", "0.49999"):
    ref = sorted((int(r[2]), float(r[5])) for r in rows
                 if r[0] == nu and r[1] == "FEM H1P0" and float(r[6]) == 1.0)
    if not ref:
        continue
    n_ref, u_ref = ref[-1]
    print("\nnu = %s, reference FEM H1P0 n = %d: u_z = %.6g" % (nu, n_ref, u_ref))
    print("| formulation | n | nodes | DoFs | u_z (m) | deviation | load factor reached | Newton its | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r[5] == "-" or not (r[0] == nu or (nu == "0.49999" and r[0] == "0.5")):
            continue
        done = float(r[6]) == 1.0
        dev = "%+.1f %%" % (100 * (float(r[5]) / u_ref - 1)) if done else "failed"
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r[1] + (" (nu = 0.5)" if r[0] == "0.5" else ""), r[2], r[3], r[4], r[5], dev, r[6], r[7], r[8]))
END
