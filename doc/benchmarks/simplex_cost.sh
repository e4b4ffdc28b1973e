#!/bin/sh
# Cost of tetrahedra against hexahedra at about 10^5 particles (issue 49,
# deliverable 5; doc/benchmarks/simplex_cost.md): the 3-D Cook membrane of
# prm/cook_membrane_3d.prm (nu = 0.357, neo-Hooke) at a tenth of its load
# in one load step, CG + ML AMG, on
#   tets: the Gmsh mesh of prm/cook_membrane_3d_tets.geo with the target
#         edge length H (default 0.49: about 10^5 vertices; gmsh needed),
#   hex:  'Mesh = cook membrane' with 'Subdivisions = N, N, N/4' (default
#         N = 72: 101,251 vertices), undistorted,
# each with FEM (P1 on the tetrahedra, Q1 on the hexahedra) and VCBCPBG V5sn
# Unl on every cell (particles = vertices). For every run: the set-up
# (mesh, particles and families, shape functions, VC), assembly and solve
# per Newton step, Newton steps, CG iterations, matrix nonzeros per row,
# mean family size, peak memory (/usr/bin/time, maximum resident set size).
# Appends to doc/benchmarks/simplex_cost/results.txt (ONLY=<run> one run:
# "tets FEM", "tets PG", "hex FEM" or "hex PG"). H=0.82 N=44: about 2.4 x
# 10^4 particles.
# Usage (from the repository root, Release build):
#   sh doc/benchmarks/simplex_cost.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
H=${H:-0.49}
N=${N:-72}
OUT=doc/benchmarks/simplex_cost
WORK=${WORK:-$(mktemp -d)}
mkdir -p "$WORK"
mkdir -p "$OUT"
RESULTS="$OUT/results.txt"
[ -f "$RESULTS" ] || echo "# mesh | method | particles | DoFs | Newton steps | CG iterations | mesh s | setup s | shape functions s | VC s | assembly s | solve s | total s | wall s | peak MB | nonzeros per row | mean family | corner u_y | VC solve (iterations)" > "$RESULTS"

MESH_FILE="$WORK/cook_tets_h$H.msh"
if [ ! -f "$MESH_FILE" ]; then
  command -v gmsh > /dev/null || { echo "needs gmsh"; exit 1; }
  /usr/bin/time -f "%e s" -o "$WORK/gmsh.time" gmsh -3 -format msh2 \
    -setnumber h "$H" prm/cook_membrane_3d_tets.geo -o "$MESH_FILE" > "$WORK/gmsh.log" 2>&1
  echo "# gmsh $(gmsh --version 2>&1), h = $H: $(sed -n '/^\$Nodes/{n;p;}' "$MESH_FILE") vertices in $(cat "$WORK/gmsh.time")" >> "$RESULTS"
fi

run() { # mesh method formulation
  [ -n "$ONLY" ] && [ "$1 $2" != "$ONLY" ] && return 0
  name="$1_$2"
  if [ "$1" = tets ]; then
    geometry="  set Mesh = file
  set File name = $MESH_FILE
  set Distortion = 0"
  else
    geometry="  set Subdivisions = $N, $N, $(( N / 4 ))
  set Distortion = 0"
  fi
  cat > "$WORK/$name.prm" <<END
include $(pwd)/prm/cook_membrane_3d.prm
subsection Geometry
$geometry
end
subsection Discretization
  set Formulation = $3
end
subsection Boundary conditions
  subsection Traction
    set Function expression = 0; 0.4 * t; 0
  end
end
subsection Loading
  set Load steps = 1
end
subsection Output
  set Directory = $WORK/$name
  set VTU       = false
end
END
  if /usr/bin/time -f "%e %M" -o "$WORK/$name.time" "$PG_SOLVE" "$WORK/$name.prm" > "$WORK/$name.log" 2>&1; then
    /usr/bin/env python3 - "$WORK/$name/summary.json" "$WORK/$name.time" "$WORK/$name.log" "$1" "$2" >> "$RESULTS" <<'END'
import json, re, sys
s = json.load(open(sys.argv[1]))
wall, kb = open(sys.argv[2]).read().split()[-2:]
log = open(sys.argv[3]).read()
t = s["timing"]
c = s.get("assembly_cost", {})
family = re.search(r"family size: +min \d+, mean ([0-9.]+)", log)
particles = s["n_particles"] if s["n_particles"] > 0 else s["n_dofs"] // 3
vc = s.get("vc_solve", {})
print("%s | %s | %d | %d | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %.0f | %.1f | %s | %.6f | %s (%s)" % (
    sys.argv[4], sys.argv[5], particles, s["n_dofs"], s["newton_iterations"],
    c.get("linear_iterations", 0), t["mesh"], t["setup"],
    t.get("shape_functions", 0.), t.get("vc", 0.), t["assembly"], t["solve"],
    t["total"], wall, int(kb) / 1024., s["matrix_nonzeros"] / s["n_dofs"],
    family.group(1) if family else "0", s["points"]["corner"][1],
    vc.get("solver", "-"), vc.get("iterations", "-")))
END
  else
    echo "$1 | $2 | failed: $(tail -n 3 "$WORK/$name.log" | tr '\n' ' ')" >> "$RESULTS"
  fi
  tail -n 1 "$RESULTS"
}

run tets FEM FEM
run hex FEM FEM
run tets PG "VCBCPBG V5sn Unl"
run hex PG "VCBCPBG V5sn Unl"
[ -n "$KEEP" ] || rm -rf "$WORK"
