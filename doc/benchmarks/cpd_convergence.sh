#!/bin/sh
# Benchmarks C-1 and C-2 (Javili et al. 2020, section 4.1, Figs. 5 and 6):
# bond-based peridynamics (CPD with C2 = 0) on the unit square, with and
# without the centred square hole of side 0.4, clamped edges x = 0 and x = 1
# pulled apart by 0.1 % (prm/cpd_square_extension.prm).
#
#  C-1: fixed horizon delta = 0.05025, lattice spacing h = 1/40, 1/80,
#       1/100, 1/160 (delta/h = 2.01, 4.02, 5.025, 8.04); the grips are
#       layers of ceil(delta/h) rows outside x = 0 and x = 1.
#  C-2: delta/h = 8.5 fixed, h = 1/40, 1/50, 1/110, 1/210 (delta = 0.2125,
#       0.17, 0.0773, 0.0405; the source's 0.21, 0.17, 0.08, 0.04 with h
#       chosen so that the hole's edges lie on the lattice), against Q1
#       finite elements (h = 1/420, linear elastic, plane stress, nu = 1/3:
#       the continuum limit of 2-D bond-based peridynamics).
# Both studies run without and with 'Partial volumes'. The profiles u_y
# along AA' (y = 0.7) and BB' (y = 1) are compared at x = 0, 0.05, ..., 1
# (C-1) or 0, 0.1, ..., 1 (C-2), points of every lattice. With
# CLAMP=edges the grips are left out and only the lattice lines x = 0 and
# x = 1 are held (the convergence then fails; doc/cpd.md).
# Writes doc/benchmarks/cpd_convergence/{fixed_horizon,nonlocal_limit}.txt
# and the figures doc/figures/cpd_fixed_horizon.png and
# doc/figures/cpd_nonlocal_limit.png (with CLAMP=edges: the same names
# ending in _clamped_edges).
# Usage (from the repository root, a Release build is advised):
#   sh doc/benchmarks/cpd_convergence.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/cpd_convergence
WORK=${WORK:-$(mktemp -d)}
mkdir -p "$OUT"

# run <name> <lattice spacing 1/n: n> <horizon factor> <hole: true|false>
#     <partial volumes> [FEM]: profiles to $WORK/<name>.txt. CPD: the grips
#     are ceil(factor) lattice rows on either side of the unit square. FEM:
#     the unit square clamped at x = 0 and x = 1 (rigid grips add nothing).
run() {
  box=
  [ "$4" = true ] && box='box 0.3,0.3 : 0.7,0.7'
  if [ "${6:-}" = FEM ]; then
    geometry="set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = $2"
    formulation=FEM
  else
    m=$(awk -v f="$3" 'BEGIN { m = int(f); if (m < f) ++m; print m }')
    [ "${CLAMP:-layers}" = edges ] && m=0
    geometry="set Lower corner = $(awk -v m="$m" -v n="$2" 'BEGIN { printf "%.17g", -m / n }'), 0
  set Upper corner = $(awk -v m="$m" -v n="$2" 'BEGIN { printf "%.17g", 1 + m / n }'), 1
  set Subdivisions = $(($2 + 2 * m)), $2"
    formulation=CPD
  fi
  cat prm/cpd_square_extension.prm - > "$WORK/$1.prm" <<END
subsection Geometry
  $geometry
  set Hole         = $box
end
subsection Discretization
  set Formulation    = $formulation
  set Horizon factor = $3
end
subsection CPD
  set Partial volumes = $5
end
subsection Material
  set Model           = linear elastic
  set Plane           = stress
  set Poisson's ratio = 0.333333333333333
end
subsection Output
  set Directory    = $WORK/$1
  set Line samples = 201
end
END
  start=$(date +%s.%N)
  "$PG_SOLVE" "$WORK/$1.prm" > "$WORK/$1.log"
  printf '%-28s %8s DoFs %7.1f s\n' "$1" \
    "$(awk '/DoFs:/ {print $2}' "$WORK/$1.log")" \
    "$(echo "$(date +%s.%N) - $start" | bc)"
  grep -v '^#' "$WORK/$1/displacement_along_lines.txt" > "$WORK/$1.txt"
}

# deviation <a> <b> <spacing>: max |u_y(a) - u_y(b)| on AA' and BB' at the
# samples x = k * spacing, over max |u_y(b)| on the same samples
deviation() {
  awk -v step="$3" 'function onlattice(x) { k = x / step; return (k - int(k + 0.5))^2 < 1e-12 }
    FNR == NR { if (onlattice($3)) ref[$1 " " $3] = $6; next }
    onlattice($3) && (($1 " " $3) in ref) {
      d = $6 - ref[$1 " " $3]; if (d < 0) d = -d; if (d > dmax) dmax = d
      r = ref[$1 " " $3]; if (r < 0) r = -r; if (r > rmax) rmax = r }
    END { printf "%.3e", dmax / rmax }' "$WORK/$2.txt" "$WORK/$1.txt"
}

# C-1: the fixed horizon
SUFFIX=
[ "${CLAMP:-layers}" = edges ] && SUFFIX=_clamped_edges
TABLE=$OUT/fixed_horizon$SUFFIX.txt
{
  echo "# C-1: delta = 0.05025 fixed; change of the u_y profiles (AA' and BB',"
  echo "# x = 0, 0.05, ..., 1) from the previous lattice, relative to max |u_y|"
  echo "# specimen  partial_volumes  h  delta/h  change  min_u_y(BB')  min_u_y(AA')"
} > "$TABLE"
for hole in false true; do
  for pv in false true; do
    previous=
    for case in 40:2.01 80:4.02 100:5.025 160:8.04; do
      n=${case%%:*}
      f=${case#*:}
      name=c1_hole${hole}_pv${pv}_$n
      run "$name" "$n" "$f" "$hole" "$pv"
      change=-
      [ -n "$previous" ] && change=$(deviation "$name" "$previous" 0.05)
      specimen=full
      [ "$hole" = true ] && specimen=holed
      awk -v s="$specimen" -v pv="$pv" -v n="$n" -v f="$f" -v c="$change" \
        '$1 == "BB" && $6 < bb {bb = $6} $1 == "AA" && $6 < aa {aa = $6}
         END { printf "%-6s %-5s 1/%-4s %6s %10s %12.5e %12.5e\n", s, pv, n, f, c, bb, aa }' \
        "$WORK/$name.txt" >> "$TABLE"
      previous=$name
    done
  done
done
cat "$TABLE"

# C-2: the non-local limit
TABLE=$OUT/nonlocal_limit$SUFFIX.txt
{
  echo "# C-2: delta/h = 8.5; deviation of the u_y profiles (AA' and BB',"
  echo "# x = 0, 0.1, ..., 1) from Q1 FEM (h = 1/420, plane stress, nu = 1/3),"
  echo "# relative to max |u_y| of FEM"
  echo "# specimen  partial_volumes  h  delta  deviation  min_u_y(BB')"
} > "$TABLE"
for hole in false true; do
  run "fem_hole$hole" 420 1 "$hole" false FEM
  specimen=full
  [ "$hole" = true ] && specimen=holed
  for pv in false true; do
    for n in 40 50 110 210; do
      name=c2_hole${hole}_pv${pv}_$n
      run "$name" "$n" 8.5 "$hole" "$pv"
      awk -v s="$specimen" -v pv="$pv" -v n="$n" -v d="$(deviation "$name" "fem_hole$hole" 0.1)" \
        '$1 == "BB" && $6 < bb {bb = $6}
         END { printf "%-6s %-5s 1/%-4s %7.4f %10s %12.5e\n", s, pv, n, 8.5 / n, d, bb }' \
        "$WORK/$name.txt" >> "$TABLE"
    done
  done
done
cat "$TABLE"

# figures: u_y along AA' and BB', full and holed specimen
plot() { # <png> <title> <prefix> <fem: yes|no> <n1> <label1> ...
  png=$1 title=$2 prefix=$3 fem=$4
  shift 4
  {
    echo "set terminal pngcairo size 1100,800"
    echo "set output '$png'"
    echo "set multiplot layout 2,2 title '$title'"
    echo "set xlabel 'x'; set ylabel 'u_y'; set key bottom center font ',9'"
    echo "set format y '%.1e'"
    for hole in false true; do
      for line in AA BB; do
        specimen=full
        [ "$hole" = true ] && specimen='with hole'
        printf "set title \"%s, line %s'\"\n" "$specimen" "$line"
        printf "plot "
        [ "$fem" = yes ] && printf "'%s' u 3:(strcol(1) eq '%s' ? \$6 : 1/0) w l lw 3 lc 'black' t 'Q1 FEM, nu = 1/3', " \
          "$WORK/fem_hole$hole.txt" "$line"
        set -- "$@"
        i=0
        for arg in "$@"; do
          i=$((i + 1))
          if [ $((i % 2)) -eq 1 ]; then n=$arg; continue; fi
          printf "'%s' u 3:(strcol(1) eq '%s' ? \$6 : 1/0) w l dt %s lw 2 t '%s', " \
            "$WORK/${prefix}_hole${hole}_pvfalse_$n.txt" "$line" "$([ "$fem" = yes ] && echo 2 || echo 1)" "$arg"
        done
        echo "1/0 notitle"
      done
    done
    echo "unset multiplot"
  } > "$WORK/plot.gp"
  gnuplot "$WORK/plot.gp"
}
plot doc/figures/cpd_fixed_horizon$SUFFIX.png \
  "C-1: bond-based peridynamics, delta = 0.05025, 0.1 % extension" c1 no \
  40 "h = 1/40" 80 "h = 1/80" 100 "h = 1/100" 160 "h = 1/160"
plot doc/figures/cpd_nonlocal_limit$SUFFIX.png \
  "C-2: bond-based peridynamics (dashed), delta/h = 8.5, against Q1 FEM" c2 yes \
  40 "delta = 0.2125" 50 "delta = 0.17" 110 "delta = 0.0773" 210 "delta = 0.0405"
echo "wrote $OUT/*$SUFFIX.txt and doc/figures/cpd_*$SUFFIX.png"
