#!/bin/sh
# Benchmark B-9 (dissertation section 7.3.1, Figs. 7.16-7.17): the 2-D
# punch of prm/punch_2d.prm (block 2 x 1, the left half of the top edge
# pushed down by u = -t and held horizontally, symmetry at x = 0, roller at
# y = 0, isochoric-volumetric neo-Hooke E = 1, nu = 0.3;
# 100 load steps of 0.01, at most 8 cuts
# each, linearized predictor). Every formulation runs until Newton fails
# (or t = 1). Recorded per formulation: the last load factor reached t
# (from pg_solve's message), the remaining thickness 1 - t, the largest
# u_x and -u_y over all 65 x 33 nodes at the last completed load step, the
# load steps completed, the step cuts, the Newton iterations and the wall
# time. The displacement of every node is recorded through 'Output/Points'
# (one named point per node), which gives the curve max u_x against
# max -u_y over the load history (Fig. 7.16, right) and the last
# configurations (Fig. 7.17).
# N=<cells in x> (default 64, i.e. 64 x 32 as in the source);
# FORMULATIONS="<code>|<code>...": run these only (default FEM, VCBCPPG V3sn
# Unl, VCBCPBG V5sn Unl); MIXED=1 adds FEM Q1P0, VCBCPPG V3sn UnlP0 and
# VCBCPBG V5sn UnlP0. The PBG runs take about 3.5 minutes each at N = 64
# (Release, one core), the others well under a minute.
# PLOT_ONLY=1: only redraw the figure from the files of an earlier run.
# Writes doc/benchmarks/punch_2d/results.txt, per formulation history_<f>.txt
# (t, max u_x, max -u_y per load step) and final_<f>.txt (the nodal
# displacements at the last completed step), and doc/figures/punch_2d.png
# (OUT=<dir> and FIG=<file> to write elsewhere; PYTHON=<python with
# matplotlib>, default /usr/bin/python3).
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/punch_2d.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
N=${N:-64}
M=$((N / 2))
OUT=${OUT:-doc/benchmarks/punch_2d}
FIG=${FIG:-doc/figures/punch_2d.png}
PYTHON=${PYTHON:-/usr/bin/python3}
ROOT=$(pwd)
WORK=$(mktemp -d)
mkdir -p "$OUT" "$(dirname "$FIG")"
RESULTS="$OUT/results.txt"

[ -n "$FORMULATIONS" ] ||
  FORMULATIONS="FEM|VCBCPPG V3sn Unl|VCBCPBG V5sn Unl"
[ -z "$MIXED" ] ||
  FORMULATIONS="$FORMULATIONS|FEM Q1P0|VCBCPPG V3sn UnlP0|VCBCPBG V5sn UnlP0"

# one named point per node: n<i>_<j> at (2 i / N, j / M)
POINTS=$(awk -v n="$N" -v m="$M" 'BEGIN {
  s = ""
  for (j = 0; j <= m; ++j)
    for (i = 0; i <= n; ++i)
      s = s sprintf("%sn%d_%d: %.17g, %.17g", (s == "" ? "" : "; "), i, j, 2 * i / n, j / m)
  print s }')

[ -n "$PLOT_ONLY" ] ||
  echo "# 2-D punch, prm/punch_2d.prm, $N x $M cells; remaining thickness = 1 - t at the last load factor t reached" > "$RESULTS"
[ -n "$PLOT_ONLY" ] ||
  echo "# formulation | DoFs | t reached | remaining thickness (%) | t of last completed step | max u_x | max -u_y | load steps completed | step cuts | Newton iterations | wall (s) | exit code | stop message (shortened)" >> "$RESULTS"

# SYMMETRY_TREATMENT=mirror|constraint: the left edge as a 'Symmetry'
# plane with that treatment (prm/punch_2d.prm holds it by u_x = 0 as a
# Dirichlet condition, which cuts the families there like 'constraint')
SYMMETRY_BLOCK=""
[ -z "$SYMMETRY_TREATMENT" ] || SYMMETRY_BLOCK="subsection Boundary conditions
  set Dirichlet          = 2: y
  set Symmetry           = 0
  set Symmetry treatment = $SYMMETRY_TREATMENT
end"
if [ -z "$PLOT_ONLY" ]; then
k=0
echo "$FORMULATIONS" | tr '|' '\n' | while read -r f; do
  k=$((k + 1))
  cat > "$WORK/run.prm" <<END
include $ROOT/prm/punch_2d.prm
subsection Geometry
  set Subdivisions = $N, $M
end
subsection Discretization
  set Formulation = $f
end
subsection Output
  set Directory = $WORK/out$k
  set VTU       = false
  set Points    = $POINTS
end
$SYMMETRY_BLOCK
END
  rc=0
  "$PG_SOLVE" "$WORK/run.prm" > "$WORK/run$k.log" 2>&1 || rc=$?
  tag=$(echo "$f" | tr ' ' '_')
  "$PYTHON" - "$WORK/out$k" "$WORK/run$k.log" "$f" "$rc" "$N" "$M" "$OUT/history_$tag.txt" "$OUT/final_$tag.txt" >> "$RESULTS" <<'END'
import json, re, sys
out, log, name, rc, n, m, hist, final = sys.argv[1:9]
n, m = int(n), int(m)
s = json.load(open(out + "/summary.json"))
msg = s.get("message", "")
hit = re.search(r"last load factor reached: ([0-9.eE+-]+)", msg)
t = float(hit.group(1)) if hit else (1.0 if s.get("converged") else float("nan"))
text = open(log).read()
cuts = text.count("cutting the step")
rows = [l.split() for l in open(out + "/statistics.txt") if not l.startswith("#")]
# columns: step, load factor, Newton iterations, residual, then u_x, u_y of
# every point in the order of 'Points' (n0_0, n1_0, ...), then wall time
nu = 2 * (n + 1) * (m + 1)
with open(hist, "w") as h:
    h.write("# %s: load factor t, max u_x, max -u_y over all %d nodes, per completed load step\n" % (name, (n + 1) * (m + 1)))
    for r in rows:
        u = [float(v) for v in r[4:4 + nu]]
        h.write("%s %.6g %.6g\n" % (r[1], max(u[0::2]), -min(u[1::2])))
last = rows[-1]
with open(final, "w") as h:
    h.write("# %s at t = %s (last completed load step): X Y u_x u_y per node, i fastest, %d x %d nodes\n" % (name, last[1], n + 1, m + 1))
    for j in range(m + 1):
        for i in range(n + 1):
            k = 2 * (j * (n + 1) + i)
            h.write("%.6g %.6g %.6g %.6g\n" % (2.0 * i / n, 1.0 * j / m, float(last[4 + k]), float(last[5 + k])))
last = rows[-1]
u = [float(v) for v in last[4:4 + nu]]
short = msg.split(". ")[0] if msg else "finished"
print("%s | %d | %.4f | %.1f | %s | %.4f | %.4f | %d | %d | %d | %.1f | %s | %s" % (
    name, s["n_dofs"], t, 100 * (1 - t), last[1], max(u[0::2]), -min(u[1::2]),
    s["load_steps"], cuts, s["newton_iterations"], s["timing"]["total"], rc, short))
END
  tail -n 1 "$RESULTS"
done
fi
rm -rf "$WORK"

"$PYTHON" - "$OUT" "$FIG" "$N" "$M" <<'END'
import glob, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, fig_path, n, m = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
res = [l.split(" | ") for l in open(out + "/results.txt") if not l.startswith("#")]
source = {"FEM": 39.0, "VCBCPPG V3sn Unl": 28.0, "VCBCPBG V5sn Unl": 1.3}
hist, final = {}, {}
for r in res:
    tag = r[0].replace(" ", "_")
    hist[r[0]] = [[float(v) for v in l.split()] for l in open(out + "/history_%s.txt" % tag) if not l.startswith("#")]
    lines = open(out + "/final_%s.txt" % tag).readlines()
    final[r[0]] = (lines[0].split(" at t = ")[1].split()[0], [[float(v) for v in l.split()] for l in lines[1:]])
show = [r[0] for r in res if r[0] in ("FEM", "VCBCPBG V5sn Unl")]
fig, axs = plt.subplots(2, 2, figsize=(11, 8))
ax = list(axs.flat)
for name, rows in hist.items():
    ax[0].plot([r[2] for r in rows], [r[1] for r in rows], label=name)
ax[0].set_xlabel("max $-u_y$ (= $-\\bar u$)")
ax[0].set_ylabel("max $u_x$")
ax[0].set_title("max $u_x$ against max $-u_y$ (load history)")
ax[0].legend(fontsize=8)
names = [r[0] for r in res]
x = range(len(names))
ax[1].bar([i - 0.2 for i in x], [float(r[3]) for r in res], 0.4, label="pg")
ax[1].bar([i + 0.2 for i in x], [source.get(nm, float("nan")) for nm in names], 0.4, label="source (B, 7.3.1)")
ax[1].set_xticks(list(x))
ax[1].set_xticklabels([nm.replace("VCBC", "VCBC\n") for nm in names], fontsize=7)
ax[1].set_ylabel("remaining thickness at failure (%)")
ax[1].set_title("remaining thickness 1 + $\\bar u$ at the last step reached")
ax[1].legend(fontsize=8, loc="upper center")
for a in ax[2 + len(show):]:
    a.axis("off")
for a, name in zip(ax[2:], show):
    t, nodes = final[name]
    X = lambda i, j: nodes[j * (n + 1) + i][0] + nodes[j * (n + 1) + i][2]
    Y = lambda i, j: nodes[j * (n + 1) + i][1] + nodes[j * (n + 1) + i][3]
    for j in range(m + 1):
        a.plot([X(i, j) for i in range(n + 1)], [Y(i, j) for i in range(n + 1)], "k-", lw=0.4)
    for i in range(n + 1):
        a.plot([X(i, j) for j in range(m + 1)], [Y(i, j) for j in range(m + 1)], "k-", lw=0.4)
    a.set_aspect("equal")
    a.set_title("%s at t = %s (last completed step)" % (name, t), fontsize=9)
fig.tight_layout()
fig.savefig(fig_path, dpi=120)
END
echo "wrote $RESULTS and $FIG"
