#!/bin/sh
# Cost per Newton step of every mixed and stabilised formulation against
# its displacement-only counterpart on the same mesh, in one run (issue 13's
# closing table). Two cases, each solved by every formulation with the
# direct solver (the codes with nodal p and Theta need it), Release build:
#  * 2-D: Cook's membrane (prm/cook_membrane_2d.prm's geometry and load),
#    32 x 32 cells, isochoric-volumetric neo-Hooke, E = 108.57, nu = 0.4999
#    (IUnlP0: nu = 0.5, the same mu), 5 load steps, horizon 2.51 h (the
#    WTE2 codes 3.51 h, as in near_incompressible_cook.sh);
#  * 3-D: the torsion prism of B-10 (torsion_prism.sh), 6 x 6 x 30 cells,
#    K = 500, mu = 161.148, the top turned by 30 degrees in one load step
#    with the linearized predictor, horizon 1.51 h (the WTE2 codes 2.01 h).
# Writes doc/benchmarks/mixed_cost/results.txt (one line per run) and
# doc/benchmarks/mixed_cost/table.md (the ratios). CASES="2d 3d" chooses
# the cases; ONLY=<formulation> runs that one and appends its rows.
# Usage (from the repository root, on an otherwise idle machine):
#   sh doc/benchmarks/mixed_cost.sh build-release/applications/pg_solve/pg_solve
set -e
. "$(dirname "$0")/torsion_case.sh"
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
CASES=${CASES:-2d 3d}
OUT=doc/benchmarks/mixed_cost
WORK=$(mktemp -d)
mkdir -p "$OUT"
RESULTS="$OUT/results.txt"
[ -n "$ONLY" ] ||
  echo "# case | formulation | counterpart | horizon factor | DoFs | matrix nonzeros | Newton steps | assembly s/step | solve s/step | tip or corner value" > "$RESULTS"

write_prm_2d() { # formulation horizon nu E
  cat <<END
set Dimension = 2
subsection Geometry
  set Mesh         = cook membrane
  set Subdivisions = 32
end
subsection Discretization
  set Formulation    = $1
  set Horizon factor = $2
end
subsection Material
  set Model           = isochoric-volumetric neo-Hooke
  set Young's modulus = $4
  set Poisson's ratio = $3
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
  set Directory = $WORK/out
  set VTU       = false
  set Points    = probe: 48, 60
end
END
}

write_prm_3d() { # formulation horizon
  torsion_prm 6 "$1" "$2" 30 1 linearized "$WORK/out"
  printf 'subsection Output\n  set Points = probe: 1, 1, 2.5\nend\n'
}

run() { # case formulation counterpart [horizon [nu]]
  [ -n "$ONLY" ] && [ "$2" != "$ONLY" ] && return 0
  if [ "$1" = 2d ]; then
    nu=${5:-0.4999}
    # the same mu = E / (2 (1 + 0.4999)) for nu = 0.5
    E=108.571428571428571
    [ "$nu" = 0.5 ] && E=108.578667149239
    write_prm_2d "$2" "${4:-2.51}" "$nu" "$E" > "$WORK/run.prm"
  else
    write_prm_3d "$2" "${4:-1.51}" > "$WORK/run.prm"
  fi
  rm -rf "$WORK/out"
  if "$PG_SOLVE" "$WORK/run.prm" > "$WORK/run.log" 2>&1; then
    /usr/bin/env python3 - "$WORK/out/summary.json" "$1" "$2" "$3" "${4:-default}" >> "$RESULTS" <<'END'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timing"]
n = max(s["newton_iterations"], 1)
p = s["points"]["probe"]
print("%s | %s | %s | %s | %d | %d | %d | %.4f | %.4f | %.5f" % (
    sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5], s["n_dofs"],
    s["matrix_nonzeros"], n, t["assembly"] / n, t["solve"] / n,
    p[1] if sys.argv[2] == "2d" else p[0]))
END
  else
    echo "$1 | $2 | $3 | ${4:-default} | failed: $(tail -n 3 "$WORK/run.log" | tr '\n' ' ')" >> "$RESULTS"
  fi
  tail -n 1 "$RESULTS"
}

for c in $CASES; do
  if [ "$c" = 2d ]; then
    run 2d "FEM" "-"
    run 2d "FEM Q1P0" "FEM"
  else
    run 3d "FEM" "-"
    run 3d "FEM H1P0" "FEM"
  fi
  run $c "VCBCPBG V5sn Unl" "-"
  run $c "VCBCPBG V5sn UnlP0" "VCBCPBG V5sn Unl"
  run $c "VCBCPPG V3sn Unl" "-"
  run $c "VCBCPPG V3sn UnlP0" "VCBCPPG V3sn Unl"
  run $c "VCBCPBG V5sn U1SUnl" "VCBCPBG V5sn Unl"
  run $c "VCBCPBG V5sn Unl+P1C" "VCBCPBG V5sn Unl"
  run $c "VCPBG V5sn U1" "-"
  run $c "VCPBG V5sn U1SIG" "VCPBG V5sn U1"
  if [ "$c" = 2d ]; then
    run 2d "VCBCPBG V5sn IUnlP0" "VCBCPBG V5sn UnlP0" 2.51 0.5
    run 2d "VCBCPPG V3sn IUnlP0" "VCBCPPG V3sn UnlP0" 2.51 0.5
    run 2d "VCPBG V5sn U2" "-" 3.51
    run 2d "VCPBG V5sn U2P1" "VCPBG V5sn U2" 3.51
    run 2d "VCPBG V5sn U2P1C" "VCPBG V5sn U2" 3.51
  else
    run 3d "VCPBG V5sn U2" "-" 2.01
    run 3d "VCPBG V5sn U2P1" "VCPBG V5sn U2" 2.01
    run 3d "VCPBG V5sn U2P1C" "VCPBG V5sn U2" 2.01
  fi
done
rm -rf "$WORK"

# The ratios: each formulation against its counterpart in the same case
# (the counterpart with the same horizon factor).
/usr/bin/env python3 - "$RESULTS" > "$OUT/table.md" <<'END'
import sys
rows = {}
order = []
for line in open(sys.argv[1]):
    if line.startswith("#"):
        continue
    f = [x.strip() for x in line.split("|")]
    if len(f) < 10:
        order.append((f[0], f[1], f[2], None))
        continue
    key = (f[0], f[1])
    rows[key] = f
    order.append((f[0], f[1], f[2], f))
print("| case | formulation | DoFs | nonzeros | Newton steps | assembly / step (s) | solve / step (s) | counterpart | assembly ratio | total ratio | nonzeros ratio |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for case, name, counterpart, f in order:
    if f is None:
        print("| %s | %s | failed | | | | | %s | | | |" % (case, name, counterpart))
        continue
    a, s = float(f[7]), float(f[8])
    c = rows.get((case, counterpart))
    if c is None:
        print("| %s | %s | %s | %s | %s | %.4f | %.4f | %s | | | |" % (
            case, name, f[4], f[5], f[6], a, s, counterpart))
        continue
    ca, cs = float(c[7]), float(c[8])
    print("| %s | %s | %s | %s | %s | %.4f | %.4f | %s | %.2f | %.2f | %.2f |" % (
        case, name, f[4], f[5], f[6], a, s, counterpart, a / ca,
        (a + s) / (ca + cs), float(f[5]) / float(c[5])))
END
cat "$OUT/table.md"
