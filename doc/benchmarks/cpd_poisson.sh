#!/bin/sh
# Benchmark C-4: the effective Poisson ratio of bond-based CPD (C2 = 0) at
# the centre of the strip of prm/cpd_poisson_strip.prm against the horizon
# delta/h, with and without 'Partial volumes', next to the lattice sums
# (sum xi_x^2 xi_y^2/|xi|^3 over sum xi_x^4/|xi|^3 of the bonds) and the
# continuum value 1/3. Writes doc/benchmarks/cpd_poisson/nu_vs_horizon.txt
# and draws doc/figures/cpd_poisson_vs_horizon.png.
# Usage (from the repository root):
#   sh doc/benchmarks/cpd_poisson.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/cpd_poisson
WORK=$(mktemp -d)
mkdir -p "$OUT"
TABLE=$OUT/nu_vs_horizon.txt
echo "# delta/h  nu(measured)  nu(lattice sum)  nu(measured, partial volumes)  nu(lattice sum, partial volumes)" > "$TABLE"
lattice() { # factor partial
  awk -v f="$1" -v pv="$2" 'BEGIN { R = int(f) + 2; n = 0; d = 0;
    for (i = -R; i <= R; ++i) for (j = -R; j <= R; ++j) {
      L = sqrt(i*i + j*j); if (L == 0) continue;
      if (pv) { b = f + 0.5 - L; if (b > 1) b = 1; if (b < 0) b = 0 }
      else b = (L <= f) ? 1 : 0;
      n += b*i*i*j*j/L^3; d += b*i^4/L^3 }
    printf "%.4f", n/d }'
}
measure() { # factor partial
  cat prm/cpd_poisson_strip.prm - > "$WORK/run.prm" <<END
subsection Discretization
  set Horizon factor = $1
end
subsection CPD
  set Partial volumes = $2
end
subsection Output
  set Directory = $WORK/out
end
END
  "$PG_SOLVE" "$WORK/run.prm" | awk '/point left/ {l = $5} /point right/ {r = $5}
    /point bottom/ {b = $6} /point top/ {t = $6}
    END { printf "%.4f", -(t - b) / 0.5 / (r - l) }'
}
for f in 1.51 2.01 2.51 3.01 3.51 4.01 4.51 5.01 5.51 6.01; do
  echo "$f $(measure $f false) $(lattice $f 0) $(measure $f true) $(lattice $f 1)" >> "$TABLE"
  echo "delta/h = $f done"
done
cat "$TABLE"
gnuplot <<END
set terminal pngcairo size 800,500
set output 'doc/figures/cpd_poisson_vs_horizon.png'
set xlabel 'horizon delta / lattice spacing h'
set ylabel 'effective Poisson ratio at the centre'
set key bottom right
set grid
plot '$TABLE' u 1:2 w lp pt 7 t 'measured, bonds all-or-nothing', \
     '' u 1:3 w l dt 2 t 'lattice sum', \
     '' u 1:4 w lp pt 5 t 'measured, partial volumes', \
     '' u 1:5 w l dt 3 t 'lattice sum, partial volumes', \
     1./3 w l lw 2 t 'continuum bond-based, 1/3'
END
rm -rf "$WORK"
