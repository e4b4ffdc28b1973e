#!/bin/sh
# The speed-against-error study of the plate with a hole
# (doc/benchmarks/plate_with_hole.md): builds pg in Release, runs
# prm/plate_with_hole_study.prm and prm/plate_with_hole_horizon_study.prm
# with pg_study, draws the plots with gnuplot (installed from Debian's
# packages if missing) and copies tables and figures into doc/.
#
#   sh doc/benchmarks/plate_with_hole.sh [work directory]
#
# About 25 minutes on 2 cores. The runs' files stay in the work directory
# (default: ./plate_with_hole_study).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-$PWD/plate_with_hole_study}

if ! command -v gnuplot > /dev/null; then
  echo "installing gnuplot (Debian package gnuplot-nox)"
  apt-get install -y -q gnuplot-nox > /dev/null
fi

cmake -S "$root" -B "$root/build-release" -DCMAKE_BUILD_TYPE=Release -DPG_NATIVE_ARCH=ON > /dev/null
cmake --build "$root/build-release" -j2 --target pg_study
pg_study=$root/build-release/applications/pg_study/pg_study

mkdir -p "$work"
cd "$work"
for study in plate_with_hole_study plate_with_hole_horizon_study; do
  "$pg_study" "$root/prm/$study.prm" | tee "$study.log"
  directory=$(sed -n 's/^ *set Directory *= *//p' "$root/prm/$study.prm")
  (cd "$directory" && gnuplot study.gp)
  mkdir -p "$here/$study"
  cp "$directory"/study.txt "$directory"/rates.txt "$here/$study/"
  [ -f "$directory/time_to_error.txt" ] && cp "$directory/time_to_error.txt" "$here/$study/"
done
cp study_plate_with_hole/error_vs_time.png "$root/doc/figures/plate_with_hole_error_vs_time.png"
cp study_plate_with_hole/error_vs_dofs.png "$root/doc/figures/plate_with_hole_error_vs_dofs.png"
echo "tables in $here/plate_with_hole_study*/, figures in $root/doc/figures/"
