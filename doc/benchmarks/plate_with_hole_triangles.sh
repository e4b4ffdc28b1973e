#!/bin/sh
# The coupled Kirsch plate on Gmsh triangle meshes beside the quadrilateral
# one (doc/benchmarks/plate_with_hole_triangles.md, issue 49): runs
#   FEM (P1 / Q1 everywhere), coupled VCBCPPG V3sn Unl, coupled VCBCPBG
#   V5sn Unl (particles in the ball of radius 2R, P1 / Q1 cells elsewhere)
#   and VCBCPBG V5sn Unl everywhere
# on the unstructured triangle meshes of prm/meshes/plate_with_hole_triangles.geo
# (h = SIZES, made here with gmsh) with prm/plate_with_hole_triangles.prm,
# and on the built-in quadrilateral mesh (Global refinement = LEVELS) with
# prm/plate_with_hole_coupled.prm. Each run's summary.json gives the
# relative L2 and H1 errors, sigma_xx at the hole top (0, R) against
# Kirsch's 3T = 30 and the interface jump: the largest |sigma_xx| difference
# at an FE/meshfree interface vertex between the particle's value and the
# average of the adjacent FE cells (pg's max_interface_stress_jump, the
# column of plate_with_hole_interface_study), here divided by 3T.
#
#   sh doc/benchmarks/plate_with_hole_triangles.sh [pg_solve] [work directory]
#
# pg_solve: a Release build (default build-release/applications/pg_solve/
# pg_solve). Needs gmsh (Debian package gmsh) and gnuplot (gnuplot-nox),
# python3 (standard library only). SIZES="0.4 0.2 ..." and LEVELS="2 3 ..."
# choose the meshes; CONFIGS="FEM|coupled PPG|..." the configurations.
# Writes doc/benchmarks/plate_with_hole_triangles/runs.txt (every run) and
# rates.txt, doc/figures/plate_with_hole_triangles_error_vs_dofs.png and
# doc/figures/plate_with_hole_triangles_sxx_lines.png (sigma_xx along the
# symmetry lines at h = LINES_SIZE, default 0.1: P1, coupled with VC and
# coupled BCPPG Unl without VC, the source's Fig. 7.33).
# About 6 minutes on 2 shared cores with the defaults.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
pg_solve=${1:-$root/build-release/applications/pg_solve/pg_solve}
work=${2:-$PWD/plate_with_hole_triangles}
SIZES=${SIZES:-0.4 0.2 0.1 0.05 0.025}
LEVELS=${LEVELS:-2 3 4 5 6}
CONFIGS=${CONFIGS:-FEM|coupled PPG|coupled PBG|PBG everywhere}
out=$here/plate_with_hole_triangles
figure=$root/doc/figures/plate_with_hole_triangles_error_vs_dofs.png

for tool in gmsh gnuplot python3; do
  command -v $tool > /dev/null ||
    { echo "$tool is needed (Debian packages gmsh, gnuplot-nox, python3)"; exit 1; }
done
[ -x "$pg_solve" ] ||
  { echo "no pg_solve at $pg_solve: build Release first"; exit 1; }
mkdir -p "$work/meshes" "$work/runs" "$out"

for h in $SIZES; do
  gmsh -2 -format msh2 -setnumber h "$h" \
    "$root/prm/meshes/plate_with_hole_triangles.geo" \
    -o "$work/meshes/h$h.msh" > /dev/null
done

# formulation and meshfree region of a configuration
formulation() {
  case "$1" in
    FEM) echo "FEM" ;;
    "coupled PPG") echo "VCBCPPG V3sn Unl" ;;
    "coupled PPG without VC") echo "BCPPG Unl" ;;
    *) echo "VCBCPBG V5sn Unl" ;;
  esac
}
region() {
  case "$1" in
    FEM) echo "none" ;;
    "PBG everywhere") echo "all" ;;
    *) echo "ball 0, 0 : 2" ;;
  esac
}

# run <mesh kind: triangles|quadrilaterals> <h or level> <configuration>
run() {
  key=$(echo "$1_$3_$2" | tr ' ' '_')
  dir=$work/runs/$key
  mkdir -p "$dir"
  if [ "$1" = triangles ]; then
    { cat "$root/prm/plate_with_hole_triangles.prm"
      printf 'subsection Geometry\n  set File name = %s\nend\n' "$work/meshes/h$2.msh"
    } > "$dir/run.prm"
  else
    { cat "$root/prm/plate_with_hole_coupled.prm"
      printf 'subsection Geometry\n  set Global refinement = %s\nend\n' "$2"
    } > "$dir/run.prm"
  fi
  { printf 'subsection Geometry\n  set Meshfree region = %s\nend\n' "$(region "$3")"
    printf 'subsection Discretization\n  set Formulation = %s\nend\n' "$(formulation "$3")"
    printf 'subsection Linear solver\n  set Type = direct\nend\n'
    printf 'subsection Output\n  set Directory = %s\n  set VTU = false\nend\n' "$dir"
  } >> "$dir/run.prm"
  printf '%s\t%s\t%s\t%s\n' "$1" "$3" "$2" "$dir" >> "$work/runs.list"
  start=$(date +%s.%N)
  if "$pg_solve" "$dir/run.prm" > "$dir/log.txt" 2>&1; then status=ok; else status=failed; fi
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }' > "$dir/wall.txt"
  echo "$1 $2 $3: $status ($(cat "$dir/wall.txt") s)"
}

: > "$work/runs.list"
IFS_SAVED=$IFS
IFS='|'
for config in $CONFIGS; do
  IFS=$IFS_SAVED
  for h in $SIZES; do run triangles "$h" "$config"; done
  for level in $LEVELS; do run quadrilaterals "$level" "$config"; done
  IFS='|'
done
IFS=$IFS_SAVED
# Fig. 7.33 of the source on triangles: sigma_xx along the symmetry lines
# with and without VC (h = LINES_SIZE, default 0.1)
LINES_SIZE=${LINES_SIZE:-0.1}
run triangles "$LINES_SIZE" "coupled PPG without VC"
for config in FEM coupled_PPG; do
  [ -d "$work/runs/triangles_${config}_$LINES_SIZE" ] ||
    run triangles "$LINES_SIZE" "$(echo $config | tr '_' ' ')"
done

python3 - "$work" "$out" << 'EOF'
import json, math, os, sys
work, out = sys.argv[1], sys.argv[2]
three_T = 30.0
rows = []
for line in open(os.path.join(work, "runs.list")):
    mesh, config, size, directory = line.rstrip("\n").split("\t")
    row = dict(mesh=mesh, config=config, size=size, ok=False)
    try:
        s = json.load(open(os.path.join(directory, "summary.json")))
        row["ok"] = s["status"] == "finished" and "errors" in s
    except (OSError, ValueError):
        s = {}
    if row["ok"]:
        sxx = s["point_stresses"]["hole top"][0]
        row.update(particles=s["n_particles"], dofs=s["n_dofs"],
                   L2=s["errors"]["L2_relative"], H1=s["errors"]["H1_relative"],
                   sxx=sxx, sxx_error=abs(sxx - three_T) / three_T,
                   jump=s["max_interface_stress_jump"] / three_T,
                   wall=float(open(os.path.join(directory, "wall.txt")).read()))
    else:
        row["message"] = s.get("message", "no summary.json: see log.txt")
    rows.append(row)

def rate(previous, row, key):
    # in h ~ N^(-1/2)
    return -2 * math.log(row[key] / previous[key]) / math.log(row["dofs"] / previous["dofs"])

series = {}
for row in rows:
    series.setdefault((row["mesh"], row["config"]), []).append(row)

with open(os.path.join(out, "runs.txt"), "w") as f:
    f.write("# Kirsch's plate with a hole, triangles (prm/plate_with_hole_triangles.prm, h = mesh size)\n"
            "# and quadrilaterals (prm/plate_with_hole_coupled.prm, level = global refinement);\n"
            "# relative L2 and H1 errors, rates in h ~ N^(-1/2) from the previous mesh, sigma_xx at (0, R)\n"
            "# (Kirsch 30), interface jump / 3T, wall time of the whole pg_solve run (shared machine)\n")
    f.write("%-14s %-22s %5s %9s %7s %9s %5s %9s %5s %7s %9s %9s %7s\n" % (
        "mesh", "configuration", "size", "particles", "DoFs", "L2", "rate", "H1", "rate",
        "sxx", "sxx err", "jump/3T", "wall s"))
    for (mesh, config), rs in series.items():
        previous = None
        for r in rs:
            if not r["ok"]:
                f.write("%-14s %-22s %5s failed: %s\n" % (mesh, config, r["size"], r["message"]))
                previous = None
                continue
            f.write("%-14s %-22s %5s %9d %7d %9.2e %5s %9.2e %5s %7.2f %9.2e %9.2e %7.2f\n" % (
                mesh, config, r["size"], r["particles"], r["dofs"], r["L2"],
                "%.2f" % rate(previous, r, "L2") if previous else "-", r["H1"],
                "%.2f" % rate(previous, r, "H1") if previous else "-",
                r["sxx"], r["sxx_error"], r["jump"], r["wall"]))
            previous = r
        f.write("\n")

# least-squares rates over the last three meshes of each series
with open(os.path.join(out, "rates.txt"), "w") as f:
    f.write("# least-squares rates in h ~ N^(-1/2) over the three finest meshes of each series\n")
    for (mesh, config), rs in series.items():
        ok = [r for r in rs if r["ok"]][-3:]
        if len(ok) < 2:
            continue
        def slope(key):
            x = [math.log(r["dofs"]) for r in ok]
            y = [math.log(r[key]) for r in ok]
            n, sx, sy = len(x), sum(x), sum(y)
            sxx = sum(v * v for v in x)
            sxy = sum(a * b for a, b in zip(x, y))
            return -2 * (n * sxy - sx * sy) / (n * sxx - sx * sx)
        f.write("%-14s %-22s L2 %.2f H1 %.2f\n" % (mesh, config, slope("L2"), slope("H1")))

# gnuplot data: one file per series
for (mesh, config), rs in series.items():
    with open(os.path.join(work, "%s_%s.dat" % (mesh, config.replace(" ", "_"))), "w") as f:
        for r in rs:
            if r["ok"]:
                f.write("%d %.6e %.6e %.6e\n" % (r["dofs"], r["L2"], r["H1"], r["sxx_error"]))
EOF

cd "$work"
gnuplot << EOF
set terminal pngcairo size 1200,480 font ",10"
set output "$figure"
set multiplot layout 1,2 title "Kirsch's plate with a hole: triangles (solid) and quadrilaterals (dashed)"
set logscale xy
set format y "%.0e"
set xlabel "DoFs"
set key top right font ",9"
set grid
configs = "FEM coupled_PPG coupled_PBG PBG_everywhere"
labels = "FEM coupled-VCBCPPG-V3sn coupled-VCBCPBG-V5sn VCBCPBG-V5sn-everywhere"
do for [c=2:3] {
  set ylabel (c == 2 ? "relative L2 error" : "relative H1 error")
  plot for [i=1:4] "triangles_".word(configs, i).".dat" using 1:c \
         with linespoints lw 2 lt i pt 7 title word(labels, i)." P1", \
       for [i=1:4] "quadrilaterals_".word(configs, i).".dat" using 1:c \
         with linespoints lw 2 lt i dt 2 pt 4 title word(labels, i)." Q1"
}
unset multiplot
EOF
lines=$work/runs/triangles
gnuplot -e "dirs='${lines}_FEM_$LINES_SIZE ${lines}_coupled_PPG_$LINES_SIZE ${lines}_coupled_PPG_without_VC_$LINES_SIZE'; labels='P1 P1+VCBCPPG-V3sn-Unl P1+BCPPG-Unl'; out='$root/doc/figures/plate_with_hole_triangles_sxx_lines.png'" \
  "$here/sxx_along_symmetry_lines.gp"
cat "$out/runs.txt" "$out/rates.txt"
echo "tables in $out/, figure $figure"
