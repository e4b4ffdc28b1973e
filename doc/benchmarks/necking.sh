#!/bin/sh
# Benchmark B-13 (dissertation section 7.3.5, Figs. 7.22-7.24): necking of
# a clamped elasto-plastic bar, prm/necking.prm (Simo's bar scaled by 5/14,
# elongated by 5 mm; one eighth with mirrored families). For each
# formulation and each saturation stress sigma_yinf (the source's 1.165
# and Simo's 0.715 kN/mm^2): the reaction force of the whole bar (4 times
# the octant's) against the elongation, and the largest equivalent
# plastic strain at the end (ep_max), with the wall time of the run.
#
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/necking.sh build-release/applications/pg_solve/pg_solve [N]
# N: the mesh (doc/benchmarks/necking_mesh.py --n N --m N --nx 4N: 12 N^2
# cells per quarter section, 4 N layers along the half length; default 2).
# Environment:
#   FORMULATIONS="<code>|<code>..."  the formulations (default: those of
#                                    the source's Fig. 7.24 and FEM H1P0)
#   SINF="1.165 0.715"               the saturation stresses
#   STEPS=50                         load steps (each cut at most 6 times)
#   LENGTH=19.048 RADIUS=2.2904 U=5  the bar and its elongation (mm); e.g.
#                                    Simo's own bar: LENGTH=53.334
#                                    RADIUS=6.413 (TAG names the results)
#   TAG=                             appended to the results' names
#   PLOT_ONLY=1                      only draw the figures
#   KEEP=1                           keep the work directory (VTU files;
#                                    the script keeps only the section z = 0
#                                    of the last step, necking_section.py)
# A run whose line is in the results file is skipped (an interrupted study
# resumes). Writes doc/benchmarks/necking/results_N<N><TAG>.txt, the
# curves doc/benchmarks/necking/curve_N<N><TAG>_<sinf>_<code>.txt (elongation
# in mm, force in kN, ep_max) and, with gnuplot, the figures
# doc/figures/necking_N<N><TAG>_<sinf>.png (force), necking_ep_max_N<N><TAG>_<sinf>.png
# (ep_max against the elongation) and
# doc/figures/necking_ep_N<N><TAG>_<sinf>_<code>.png (ep on the section).
set -e
PG_SOLVE=$(realpath "${1:-build-release/applications/pg_solve/pg_solve}")
N=${2:-2}
STEPS=${STEPS:-50}
SINF=${SINF:-1.165 0.715}
LENGTH=${LENGTH:-19.048}
RADIUS=${RADIUS:-2.2904}
U=${U:-5}
TAG=${TAG:-}
OUT=doc/benchmarks/necking
FIG=doc/figures
mkdir -p "$OUT" "$FIG"
RESULTS="$OUT/results_N${N}${TAG}.txt"
[ -n "$FORMULATIONS" ] ||
  FORMULATIONS="FEM H1P0|VCBCPBG V5sn Unl|VCBCPBG V5sn UnlP0|VCBCPBG V5sn Unl+P1C|VCBCPBG V5sn U1SUnl|VCPBG V5sn U1SIG|VCPBG V5sn U2|VCPBG V5sn U2P1|VCPBG V5sn U2P1C|VCBCPPG V3sn UnlP0"
WORK=$(mktemp -d)
[ -n "$KEEP" ] && echo "work directory: $WORK"
[ -f "$RESULTS" ] ||
  echo "# sigma_yinf | formulation | mesh N | DoFs | elongation reached (mm) | F_max (kN) | elongation at F_max (mm) | F at the end (kN) | ep_max at the end | Newton iterations | load steps (cut steps count once) | wall (s) | status" > "$RESULTS"

slug() { echo "$1" | tr ' +' '_p'; }

if [ -z "$PLOT_ONLY" ]; then
  python3 doc/benchmarks/necking_mesh.py "$WORK/bar.msh" --n "$N" --m "$N" \
    --nx $((4 * N)) --length "$LENGTH" --radius "$RADIUS" > /dev/null
  for s in $SINF; do
    echo "$FORMULATIONS" | tr '|' '\n' | while read -r f; do
      if awk -F' [|] ' -v s="$s" -v f="$f" '$1 == s && $2 == f { found = 1 } END { exit !found }' "$RESULTS"; then
        echo "skip: $s $f (in $RESULTS)"
        continue
      fi
      dir="$WORK/$(slug "$f")_$s"
      mkdir -p "$dir"
      cat > "$dir/run.prm" <<END
include $(pwd)/prm/necking.prm
subsection Geometry
  set File name = $WORK/bar.msh
end
subsection Discretization
  set Formulation = $f
end
subsection Material
  set Saturation yield stress = $s
end
subsection Boundary conditions
  subsection Prescribed displacement
    set Function constants  = u = $U
  end
end
subsection Loading
  set Load steps = $STEPS
end
subsection Output
  set Directory = $dir/out
  set VTU       = true
end
END
      start=$(date +%s.%N)
      "$PG_SOLVE" "$dir/run.prm" > "$dir/log" 2>&1 || true
      wall=$(awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $start }")
      curve="$OUT/curve_N${N}${TAG}_${s}_$(slug "$f").txt"
      python3 - "$dir/out" "$s" "$f" "$N" "$wall" "$U" "$curve" "$dir/log" >> "$RESULTS" <<'PY'
import json, sys
d, s, f, n, wall, u, curve, log = sys.argv[1:9]
try:
    summary = json.load(open(d + "/summary.json"))
except (OSError, ValueError):
    summary = {}
rows = []
try:
    names = []
    for line in open(d + "/statistics.txt"):
        if line.startswith("# "):
            names.append(line[line.index(":") + 2:].strip())
            continue
        v = line.split()
        if len(v) >= len(names):
            rows.append(dict(zip(names, map(float, v))))
except OSError:
    pass
with open(curve, "w") as c:
    c.write("# %s, sigma_yinf = %s: elongation (mm) | force of the bar (kN) | "
            "ep_max\n" % (f, s))
    for r in rows:
        c.write("%.6g %.6g %.6g\n" % (r["load factor"] * float(u),
                                      4 * r.get("reaction_4_x", 0.),
                                      r.get("max_equivalent_plastic_strain", 0.)))
status = summary.get("status", "no summary")
if status != "finished":
    message = summary.get("message", "")
    if not message:
        lines = [l.strip() for l in open(log) if l.strip()]
        message = " ".join(lines[-3:])[:300]
    status += ": " + message.replace("|", "/").replace("\n", " ")
if rows:
    forces = [4 * r.get("reaction_4_x", 0.) for r in rows]
    i = max(range(len(forces)), key=lambda k: forces[k])
    last = rows[-1]
    print("%s | %s | %s | %s | %.3g | %.4g | %.3g | %.4g | %.3g | %s | %s | %s | %s" % (
        s, f, n, summary.get("n_dofs", "-"), last["load factor"] * float(u),
        forces[i], rows[i]["load factor"] * float(u), forces[-1],
        last.get("max_equivalent_plastic_strain", 0.),
        summary.get("newton_iterations", "-"),
        summary.get("load_steps", "-"), wall, status))
else:
    print("%s | %s | %s | %s | 0 | - | - | - | - | - | - | %s | %s" % (
        s, f, n, summary.get("n_dofs", "-"), wall, status))
PY
      # the equivalent plastic strain on the section z = 0 at the last step
      python3 doc/benchmarks/necking_section.py "$dir/out" \
        > "$OUT/section_N${N}${TAG}_${s}_$(slug "$f").txt" || true
      [ -n "$KEEP" ] || rm -rf "$dir"
      tail -n 1 "$RESULTS"
    done
  done
fi

# Figures: force against elongation, one panel per sigma_yinf
if command -v gnuplot > /dev/null; then
  for s in $SINF; do
    plots=""
    for c in "$OUT"/curve_N${N}${TAG}_${s}_*.txt; do
      [ -f "$c" ] || continue
      name=$(head -n 1 "$c" | sed 's/^# //; s/, sigma_yinf.*//')
      plots="$plots${plots:+, }'$c' using 1:2 with linespoints pointsize 0.4 title '$name'"
    done
    [ -n "$plots" ] || continue
    gnuplot <<END
set terminal pngcairo size 900,600 noenhanced
set output '$FIG/necking_N${N}${TAG}_${s}.png'
set title 'B-13 necking, N = $N, sigma_yinf = $s kN/mm^2: force of the whole bar'
set xlabel 'elongation (mm)'
set ylabel 'reaction force (kN)'
set key bottom right
set grid
plot $plots
set output '$FIG/necking_ep_max_N${N}${TAG}_${s}.png'
set title 'B-13 necking, N = $N, sigma_yinf = $s kN/mm^2: largest equivalent plastic strain'
set ylabel 'ep_max'
set key top left
plot $(echo "$plots" | sed 's/using 1:2/using 1:3/g')
END
  done
fi
# Figures: the equivalent plastic strain on the section z = 0 at the end
if command -v gnuplot > /dev/null; then
  for c in "$OUT"/section_N${N}${TAG}_*.txt; do
    [ -s "$c" ] || continue
    name=$(basename "$c" .txt | sed 's/^section_//')
    gnuplot <<END
set terminal pngcairo size 900,330 noenhanced
set output '$FIG/necking_ep_$name.png'
set title '$name: equivalent plastic strain on the section z = 0 (deformed)'
set size ratio -1
set xlabel 'x (mm)'
set ylabel 'y (mm)'
set cblabel 'ep'
set cbrange [0:1]
set palette defined (0 'blue', 0.25 'cyan', 0.5 'green', 0.75 'yellow', 1 'red')
plot '$c' using 1:2:3 with points pointtype 7 pointsize 0.8 palette notitle
END
  done
fi
[ -n "$KEEP" ] || rm -rf "$WORK"
