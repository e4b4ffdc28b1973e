#!/bin/sh
# Peridigm's tensile test (prm/tensile_test.prm) with FEM, BCPBG Unl,
# VCBCPBG V5sn Unl (cg), the stabilised correspondence VCPBG U1SIG (cg) and
# Peridigm's model, PBG U1 with the hourglass
# force 0.02 (gmres), on the merged mesh and on the mesh as it comes from
# Cubit (252 coincident node pairs, merged on reading). Prints the markdown
# table of doc/benchmarks/tensile_test.md: wall time of the whole run, the
# displacement at the gauge point (0.0317, 1.238, 0) and the reaction u_y
# of each grip (Dirichlet boxes 1 and 2), and keeps the logs (and, from
# now on, timing.txt) in doc/benchmarks/tensile_test/.
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/tensile_test.sh build-release/applications/pg_solve/pg_solve
# RANKS=2 runs every case under 'mpirun -np 2' (one thread per rank on a
# 2-core machine; on 1 rank pg_solve uses all cores for its threads).
# The columns setup ... solve are the phases of timing.txt (s).
# AMG_OPERATOR=tangent (or 'Q1 cells') sets 'Linear solver/AMG operator'
# (default: automatic, i.e. Q1 cells for the PG codes on this mesh) and
# names it beside the formulation.
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
RANKS=${RANKS:-1}
LAUNCH=""
if [ "$RANKS" -gt 1 ]; then
  LAUNCH="mpirun -np $RANKS"
fi
DATA=../shared/data/peridigm_tensile_test
OUT=doc/benchmarks/tensile_test
WORK=$(mktemp -d)
mkdir -p "$OUT"
echo "| mesh | formulation | ranks x threads | wall time (s) | setup | shape functions | vc | assembly | solve | Newton its | gauge u_x | gauge u_y | gauge u_z | reaction grip y<0 | reaction grip y>0 |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
# MESHES="tensile_test" or FORMULATIONS="..." run a subset; MESHES=exodus
# runs Peridigm's tensile_test.g itself (node sets instead of boxes).
for mesh in ${MESHES:-tensile_test tensile_test_unmerged}; do
  for formulation in ${FORMULATIONS:-FEM BCPBG_Unl VCBCPBG_V5sn_Unl VCPBG_U1SIG PBG_U1_hourglass}; do
    formulation=$(echo "$formulation" | tr '_' ' ')
    name=$(echo "${mesh}_$formulation" | tr ' ' '_')
    # Peridigm's own model: the classical correspondence with its hourglass
    # force (coefficient 0.02, its deformation gradient with omega = 1);
    # the tangent is not symmetric, so GMRES
    extra=""
    code="$formulation"
    if [ "$formulation" = "PBG U1 hourglass" ]; then
      code="PBG U1"
      extra="  set Hourglass coefficient = 0.02
  set Weight exponent = 0
end
subsection Linear solver
  set Type = gmres"
    fi
    label="$formulation"
    if [ -n "${AMG_OPERATOR:-}" ]; then
      label="$formulation, AMG operator $AMG_OPERATOR"
      name="${name}_amg_$(echo "$AMG_OPERATOR" | tr ' ' '_')"
    fi
    if [ "$RANKS" -gt 1 ]; then
      name="${name}_${RANKS}_ranks"
    fi
    # prm/tensile_test.prm reads Peridigm's tensile_test.g with its node
    # sets (MESHES=exodus); the Gmsh conversions get the grips as boxes
    if [ "$mesh" = exodus ]; then
      file=../shared/data/peridigm_examples/tensile_test.g
      boxes=/dev/null
    else
      file=$DATA/$mesh.msh
      boxes=doc/benchmarks/tensile_test_gmsh.prm
    fi
    cat prm/tensile_test.prm "$boxes" - > "$WORK/$name.prm" <<END
subsection Geometry
  set File name = $file
end
subsection Discretization
  set Formulation = $code
$extra
end
subsection Linear solver
  set AMG operator = ${AMG_OPERATOR:-automatic}
end
subsection Output
  set Directory = $WORK/$name
end
END
    start=$(date +%s.%N)
    status=0
    $LAUNCH "$PG_SOLVE" "$WORK/$name.prm" > "$OUT/$name.log" 2>&1 || status=$?
    end=$(date +%s.%N)
    cp "$WORK/$name/timing.txt" "$OUT/$name.timing.txt" 2>/dev/null || true
    python3 - "$WORK/$name" "$mesh" "$label" "$start" "$end" "$status" <<'PY'
import json, os, sys
out, mesh, formulation, start, end, status = sys.argv[1:]
wall = float(end) - float(start)
try:
    s = json.load(open(os.path.join(out, "summary.json")))
    phases, threads = {}, "?"
    for line in open(os.path.join(out, "timing.txt")):
        f = line.split()
        if f[0] == "threads":  # "threads N per MPI rank, R ranks"
            threads = "%s x %s" % (f[5], f[1])
        else:
            phases[f[0]] = float(f[1])
    u = s["points"]["gauge top"]
    if "node_set_reactions" in s:  # the grips: nodelist_1 and nodelist_2
        n = s["node_set_reactions"]
        r = [n["nodelist_1"], n["nodelist_2"]]
    else:
        r = s.get("box_reactions", [[0, 0, 0], [0, 0, 0]])
    print("| %s | %s | %s | %.1f | %s | %d | %.4g | %.4g | %.4g | %.4g | %.4g |" % (
        mesh, formulation, threads, wall,
        " | ".join("%.2f" % phases.get(p, 0) for p in
                   ("setup", "shape_functions", "vc", "assembly", "solve")),
        s["newton_iterations"], u[0], u[1], u[2], r[0][1], r[1][1]))
except Exception as e:
    print("| %s | %s | | %.1f | | | | | | exit %s | | | | | |" % (mesh, formulation, wall, status))
PY
  done
done
echo "| Peridigm (README: 1 step) | elastic correspondence | 1 x 1 | 268.9 | | | | 88 (FD Jacobian) | 150 | 5 | -9.44e-4 | 8.111e-3 | -1.97e-4 | -2.324e9 | 2.324e9 |"
rm -rf "$WORK"
