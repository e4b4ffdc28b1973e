#!/bin/sh
# Benchmarks B-15 and B-16 (dissertation section 7.3.7, Table 7.6, Figs.
# 7.27-7.31): the Taylor anvil of prm/taylor_anvil.prm. A copper rod
# (L0 = 32.4 mm, r0 = 3.2 mm, J2 plasticity E = 117 GPa, nu = 0.35,
# sigma_y = 0.4 + 0.1 a GPa, rho = 8.93 g/cm^3) hits a rigid frictionless
# wall with 227 m/s; quarter model with mirrored families at x = 0 and
# y = 0. Units mm, ms, kg, kN, GPa. Recorded per run at 80 us: the final
# length at the centre (z of the top centre minus z of the impact centre),
# the mushroom radius at the impact end (3.2 + u_x of the vertex at
# (3.2, 0, 0)), the largest equivalent plastic strain, the energy balance
# relative to the initial kinetic energy, time steps, wall time, exit code.
# Meshes: prm/meshes/taylor_rod_quarter.geo with N cells on each edge of
# the three blocks of the quarter cross-section (3 N^2 cells per layer) and
# NZ = round(20.25 N) layers (cells about cubic in the core); generated
# here with gmsh (/usr/bin/gmsh, MSH 2.2).
# RUNS="<formulation>|<integrator>[:<value>]|<N list>;..." replaces the
# default set below: leapfrog[:<safety factor>] (default SAFETY, 0.1, of
# the stable step estimated at t = 0) or newmark:<time step in ms>. A run
# whose line is in the results is skipped (delete the file to redo
# everything).
# B16=1: instead, B-16 (750 m/s, L0 = 12.8 mm, 30 us) with VCPBG U1SIG on
# N = ${B16_N:-2} (safety factor 0.02), VTU every 1 us, and the picture of
# the section y = 0 at 3 us (the cavity) and at the last output.
# PLOT_ONLY=1: only the figures and the markdown table of the page. KEEP=1 keeps the work
# directory (and prints it). PYTHON=<python with matplotlib>.
# Writes doc/benchmarks/taylor_anvil/results.txt (B-16: results_b16.txt),
# doc/figures/taylor_anvil_*.png.
# Usage (from the repository root, Release build):
#   sh doc/benchmarks/taylor_anvil.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=${OUT:-doc/benchmarks/taylor_anvil}
FIGS=${FIGS:-doc/figures}
PYTHON=${PYTHON:-/usr/bin/python3}
GMSH=${GMSH:-gmsh}
SAFETY=${SAFETY:-0.1}
ROOT=$(pwd)
WORK=$(mktemp -d)
VTU_DIR=${VTU_DIR:-$OUT/vtu}
mkdir -p "$OUT" "$FIGS" "$VTU_DIR"
if [ -n "$B16" ]; then
  RESULTS="$OUT/results_b16.txt"
  L0=12.8; V0=750; END=0.03; INTERVAL=0.001
  [ -n "$RUNS" ] || RUNS="VCPBG U1SIG|leapfrog:0.02|${B16_N:-2}"
else
  RESULTS="$OUT/results.txt"
  L0=32.4; V0=227; END=0.08; INTERVAL=0.01
  [ -n "$RUNS" ] || RUNS="FEM|leapfrog:0.1|1 2;\
FEM H1P0|leapfrog:0.1|1 2;\
VCPBG Unl|leapfrog:0.1|1;\
VCPBG UnlP0|leapfrog:0.1|1;\
VCPBG U1SIG|leapfrog:0.1|1 2"
  # (Unl+P1C, the source's Newmark with 1000 steps: RUNS="VCPBG
  # Unl+P1C|newmark:0.00008|1"; about 5 CPU-seconds per step at N = 1,
  # doc/benchmarks/taylor_anvil.md)
fi
[ -f "$RESULTS" ] || [ -n "$PLOT_ONLY" ] ||
  echo "# formulation | integrator (dt) | N | NZ | particles (nodes) | DoFs | final length (mm) | mushroom radius (mm) | max e_p | energy balance / E_kin(0) | time steps | t reached (ms) | wall (s) | exit code | message" > "$RESULTS"

if [ -z "$PLOT_ONLY" ]; then
echo "$RUNS" | tr ';' '\n' | while IFS='|' read -r f integ ns; do
  [ -n "$f" ] || continue
  method=${integ%%:*}
  dt=0
  safety=$SAFETY
  if [ "$method" != "$integ" ]; then
    if [ "$method" = newmark ]; then dt=${integ#*:}; else safety=${integ#*:}; fi
  fi
  for n in $ns; do
    nz=$(awk "BEGIN { printf \"%d\", $n * 20.25 * $L0 / 32.4 + 0.5 }")
    if grep -q "^$f | $integ | $n |" "$RESULTS"; then continue; fi
    mesh="$WORK/rod_${n}_${nz}.msh"
    [ -f "$mesh" ] || "$GMSH" -3 -format msh2 -setnumber N "$n" -setnumber NZ "$nz" \
      -setnumber L "$L0" "$ROOT/prm/meshes/taylor_rod_quarter.geo" -o "$mesh" > "$WORK/gmsh.log" 2>&1
    tag=$(echo "$f" | tr ' +' '_p')_N$n
    [ -n "$B16" ] && tag=b16_$tag
    cat > "$WORK/run.prm" <<END
include $ROOT/prm/taylor_anvil.prm
subsection Geometry
  set File name = $mesh
end
subsection Discretization
  set Formulation = $f
end
subsection Time
  set Integrator      = $method
  set Time step       = $dt
  set Safety factor   = $safety
  set End time        = $END
  set Output interval = $INTERVAL
  subsection Initial velocity
    set Function expression = 0; 0; -$V0
  end
end
subsection Linear solver
  set Type = direct
end
subsection Output
  set Directory = $WORK/out_$tag
  set Points    = top centre: 0, 0, $L0; impact centre: 0, 0, 0; impact edge: 3.2, 0, 0
end
END
    rm -rf "$WORK/out_$tag"
    rc=0
    start=$(date +%s.%N)
    "$PG_SOLVE" "$WORK/run.prm" > "$WORK/run_$tag.log" 2>&1 || rc=$?
    wall=$(awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $start }")
    "$PYTHON" - "$WORK/out_$tag" "$f" "$integ" "$n" "$nz" "$rc" "$wall" "$L0" >> "$RESULTS" <<'END'
import json, sys
out, name, integ, n, nz, rc, wall, L0 = sys.argv[1:9]
L0 = float(L0)
try:
    s = json.load(open(out + "/summary.json"))
except (OSError, ValueError):
    print("%s | %s | %s | %s | - | - | - | - | - | - | - | - | %s | %s | no summary.json" % (name, integ, n, nz, wall, rc))
    sys.exit(0)
p = dict((k, v) for k, v in s.get("points", {}).items())
length = L0 + p["top centre"][2] - p["impact centre"][2] if "top centre" in p else float("nan")
radius = 3.2 + p["impact edge"][0] if "impact edge" in p else float("nan")
names, rows = [], []
for l in open(out + "/statistics.txt"):
    if l.startswith("# "):
        names.append(l[2:].split(":", 1)[1].strip() if ":" in l else l[2:].strip())
    elif l.strip() and not l.startswith("#"):
        rows.append([float(x) for x in l.split()])
col = dict((nm, i) for i, nm in enumerate(names))
t = rows[-1][col["time"]] if rows and "time" in col else float("nan")
ekin0 = rows[0][col["kinetic energy"]] if rows and "kinetic energy" in col else float("nan")
bal = rows[-1][col["energy balance"]] / ekin0 if rows and "energy balance" in col else float("nan")
steps = s.get("load_steps", "-")
nodes = s.get("n_particles", 0) or "-"
msg = s.get("message", "") or "finished"
print("%s | %s | %s | %s | %s | %d | %.3f | %.3f | %.3f | %+.3f | %s | %.4g | %s | %s | %s" % (
    name, integ, n, nz, nodes, s["n_dofs"], length, radius,
    s.get("max_equivalent_plastic_strain", float("nan")), bal, steps, t, wall, rc,
    msg.split(". ")[0][:80]))
END
    tail -n 1 "$RESULTS"
    # keep the solution VTU of the last output (B-16: also that nearest to
    # 3 us, and of failed runs too) of a finished run for the pictures, in
    # $VTU_DIR (not committed)
    { [ "$rc" = 0 ] || [ -n "$B16" ]; } &&
      "$PYTHON" - "$WORK/out_$tag" "$VTU_DIR" "$tag" ${B16:+0.003} <<'END'
import os, re, shutil, sys
out, dest, tag = sys.argv[1:4]
try:
    pvd = open(out + "/solution.pvd").read()
except OSError:
    sys.exit(0)
frames = [(float(t), f) for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)]
if not frames:
    sys.exit(0)
def copy(f, when):
    vtu = os.path.join(out, os.path.basename(f).replace(".pvtu", ".0.vtu"))
    if os.path.exists(vtu):
        shutil.copy(vtu, os.path.join(dest, "%s_solution_%s.vtu" % (tag, when)))
copy(frames[-1][1], "final")
if len(sys.argv) > 4:
    t3 = float(sys.argv[4])
    copy(min(frames, key=lambda tf: abs(tf[0] - t3))[1], "0003")
END
    [ -n "$KEEP" ] || rm -rf "$WORK/out_$tag"
  done
done
fi
"$PYTHON" "$ROOT/doc/benchmarks/taylor_anvil_plot.py" "$VTU_DIR" "$FIGS" ${B16:+b16}
# the table of doc/benchmarks/taylor_anvil.md, with the source's numbers
"$PYTHON" - "$RESULTS" <<'END'
import sys, re
rows=[l.rstrip('\n').split(' | ') for l in open(sys.argv[1]) if not l.startswith('#')]
src={'VCPBG Unl':'21.32 / 6.47 / 2.81','VCPBG UnlP0':'21.48 / 7.30 / 3.56','VCPBG Unl+P1C':'21.54 / 7.28 / 3.35','VCPBG U1SIG':'21.45 / 7.26 / 4.46','FEM':'(literature FEM: 21.26–21.66 / 6.89–7.24 / 2.47–3.25)','FEM H1P0':'(literature FEM: 21.26–21.66 / 6.89–7.24 / 2.47–3.25)'}
print('| formulation | integrator | N | particles (nodes) | final length (mm) | mushroom radius (mm) | ē_p,max | energy balance / E_kin(0) | steps | wall (s) | source (Table 7.6): length / radius / ē_p,max |')
print('|---|---|---|---|---|---|---|---|---|---|---|')
order=['FEM','FEM H1P0','VCPBG Unl','VCPBG UnlP0','VCPBG Unl+P1C','VCPBG U1SIG']
rows.sort(key=lambda r:(order.index(r[0]) if r[0] in order else 99, int(r[2]), r[1]))
for r in rows:
    f,integ,n,nz,parts,dofs,L,R,ep,bal,steps,t,wall,rc,msg=r[:15]
    nodes = parts if parts!='-' else str(int(dofs)//3)
    integ = integ.replace('leapfrog:','leapfrog, safety ').replace('newmark:','Newmark, dt = ')
    if rc=='0':
        vals='%s | %s | %s | %s'%(L,R,ep,bal)
    else:
        m=re.search(r'step to t = ([0-9.]+)',msg)
        vals='failed at t = %s ms (inverted cell) | – | – | – '%(m.group(1) if m else t)
    print('| %s | %s | %s | %s | %s | %s | %s | %s |'%(f,integ,n,nodes,vals,steps,wall,src.get(f,'')))
print()
print('Literature envelope (Table 7.6, first seven rows): 21.26–21.66 mm, 6.84–7.24 mm, ē_p,max 2.47–4.06.')
END
if [ -n "$KEEP" ]; then echo "work directory kept: $WORK"; else rm -rf "$WORK"; fi
