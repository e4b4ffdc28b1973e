#!/bin/sh
# Benchmark G-1 (Ganzenmueller's stability demonstration): runs
# prm/ganzenmueller_patch.prm for 20 breathing periods with (a) classical
# correspondence (PBG U1, WTE1) and (b) VCBCPBG Unl, and once more up to
# the 1st, 3rd and 10th contraction (t = 0.5 T, 2.5 T, 9.5 T) for particle
# snapshots. Collects the disorder indicator per period and the time per
# explicit step and particle in doc/benchmarks/ganzenmueller/ and draws
# doc/figures/ganzenmueller_disorder.png and ganzenmueller_snapshots.png.
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/ganzenmueller.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/ganzenmueller
WORK=$(mktemp -d)
T=1.6
mkdir -p "$OUT"
run() { # name formulation end-time
  cat prm/ganzenmueller_patch.prm - > "$WORK/$1.prm" <<END
subsection Discretization
  set Formulation = $2
end
subsection Time
  set End time = $3
end
subsection Output
  set Directory = $WORK/$1
end
END
  "$PG_SOLVE" "$WORK/$1.prm" > "$WORK/$1.log"
}
printf "# formulation particles steps assembly_s total_s assembly_us_per_step_particle total_us_per_step_particle\n" > "$OUT/timing.txt"
for f in u1 unl; do
  code="PBG U1"; [ $f = unl ] && code="VCBCPBG Unl"
  run $f "$code" 32
  # t/T and the indicator; the largest value of each period
  awk -v T=$T '!/^#/ { print $2 / T, $10 }' "$WORK/$f/statistics.txt" \
    > "$OUT/${f}_disorder.txt"
  awk '{ p = int($1 - 1e-9); if (p < 0) p = 0; if ($2 > m[p]) m[p] = $2 }
       END { print "# period max_disorder"; for (i = 0; i < 20; ++i) print i + 1, m[i] }' \
    "$OUT/${f}_disorder.txt" > "$OUT/${f}_per_period.txt"
  n=$(grep -o '"n_particles": [0-9]*' "$WORK/$f/summary.json" | grep -o '[0-9]*$')
  steps=$(grep -o '"load_steps": [0-9]*' "$WORK/$f/summary.json" | grep -o '[0-9]*$')
  asm=$(awk '$1 == "assembly" { print $2 }' "$WORK/$f/timing.txt")
  tot=$(awk '$1 == "total" { print $2 }' "$WORK/$f/timing.txt")
  echo "$code" | tr ' ' '_' | awk -v n=$n -v s=$steps -v a=$asm -v t=$tot \
    '{ printf "%s %d %d %.2f %.2f %.3f %.3f\n", $1, n, s, a, t, 1e6 * a / (s * n), 1e6 * t / (s * n) }' \
    >> "$OUT/timing.txt"
  for c in 1 3 10; do
    run ${f}_c$c "$code" $(echo "($c - 0.5) * $T" | bc -l)
    cp "$WORK/${f}_c$c/particles.txt" "$OUT/${f}_contraction_$c.txt"
  done
done
cat "$OUT/timing.txt"
paste "$OUT/u1_per_period.txt" "$OUT/unl_per_period.txt"
gnuplot <<END
set terminal pngcairo size 800,500
set output 'doc/figures/ganzenmueller_disorder.png'
set xlabel 't / T'
set ylabel 'disorder indicator'
set logscale y
set key top left
set title 'G-1: irregular patch, 10 % stretch released (484 particles)'
plot '$OUT/u1_disorder.txt' w l lw 2 t '(a) PBG U1 (classical correspondence)', \
     '$OUT/unl_disorder.txt' w l lw 2 t '(b) VCBCPBG Unl'
set output 'doc/figures/ganzenmueller_snapshots.png'
set terminal pngcairo size 1200,800
unset logscale
set multiplot layout 2,3
set size ratio -1
unset key
set xrange [-0.1:1.1]
set yrange [-0.1:1.1]
unset xlabel
unset ylabel
do for [f in "unl u1"] {
  do for [c in "1 3 10"] {
    set title sprintf('%s, contraction %s', f eq 'u1' ? '(a) PBG U1' : '(b) VCBCPBG Unl', c)
    plot sprintf('$OUT/%s_contraction_%s.txt', f, c) u (\$1+\$3):(\$2+\$4) w p pt 7 ps 0.4
  }
}
unset multiplot
END
rm -rf "$WORK"
