#!/bin/sh
# sigma_xx along the symmetry lines of the plate with a hole (Fig. 7.33 of
# the dissertation): FE everywhere, the coupled model with VC (the default
# of prm/plate_with_hole_coupled.prm) and without, against Kirsch.
# Usage: sh doc/benchmarks/plate_with_hole_lines.sh [pg_solve] [refinement]
# Writes doc/figures/sxx_along_symmetry_lines.png.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
pg_solve=${1:-$root/build/applications/pg_solve/pg_solve}
refinement=${2:-4}
work=$(mktemp -d)
for case in "FEM:FEM" "coupled-VCBCPPG:VCBCPPG V3sn Unl" "coupled-BCPPG:BCPPG Unl"; do
  name=${case%%:*}
  code=${case#*:}
  mkdir -p "$work/$name"
  { cat "$root/prm/plate_with_hole_coupled.prm"
    printf 'subsection Discretization\n  set Formulation = %s\nend\n' "$code"
    printf 'subsection Geometry\n  set Global refinement = %s\nend\n' "$refinement"
    printf 'subsection Output\n  set Directory = %s\n  set VTU = false\nend\n' "$work/$name"
  } > "$work/$name.prm"
  echo "running $name ($code), refinement $refinement"
  "$pg_solve" "$work/$name.prm" | grep -E "DoFs|errors"
done
gnuplot -e "dirs='$work/FEM $work/coupled-VCBCPPG $work/coupled-BCPPG'; labels='FEM VCBCPPG-coupled BCPPG-coupled'; out='$root/doc/figures/sxx_along_symmetry_lines.png'" \
  "$here/sxx_along_symmetry_lines.gp"
echo "wrote $root/doc/figures/sxx_along_symmetry_lines.png"
