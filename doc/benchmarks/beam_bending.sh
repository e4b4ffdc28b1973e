#!/bin/sh
# Benchmark G-2 (Ganzenmueller's simply supported beam, section 5.3, Fig. 5):
# runs prm/beam_bending.prm with leapfrog to u_y = 8 mm with (a) classical
# correspondence (PBG U1, WTE1) and (b) VCBCPBG Unl, records the pairing
# indicator against the deflection, and stops once more at u_y = 4.8, 6.6
# and 8 mm for particle snapshots coloured by the second Piola-Kirchhoff
# stress S_xx (SVK, plane strain, from the particle's F). Also tries (a) with
# implicit Newmark steps of T/200 and reports where its Newton iteration
# fails. Writes doc/benchmarks/beam_bending/*.txt and draws
# doc/figures/beam_bending_disorder.png and beam_bending_snapshots.png.
# Usage (from the repository root, with a Release build):
#   sh doc/benchmarks/beam_bending.sh build-release/applications/pg_solve/pg_solve
set -e
PG_SOLVE=${1:-build-release/applications/pg_solve/pg_solve}
OUT=doc/benchmarks/beam_bending
WORK=$(mktemp -d)
T=4.47
mkdir -p "$OUT"
# the time at which the ramp 8 (tau - sin(2 pi tau) / (2 pi)) reaches $1 mm
time_at() {
  awk -v u="$1" -v T=$T 'BEGIN { pi = atan2(0, -1); a = 0; b = 1;
    for (i = 0; i < 60; ++i) { m = (a + b) / 2;
      if (8 * (m - sin(2 * pi * m) / (2 * pi)) < u) a = m; else b = m }
    printf "%.6f", T * (a + b) / 2 }'
}
run() { # name formulation end-time [extra parameters]
  cat prm/beam_bending.prm - > "$WORK/$1.prm" <<END
subsection Discretization
  set Formulation = $2
end
subsection Time
  set End time = $3
end
subsection Output
  set Directory = $WORK/$1
end
$4
END
  "$PG_SOLVE" "$WORK/$1.prm" > "$WORK/$1.log" 2>&1 || echo "$1: pg_solve stopped (exit code $?), see below"
}
for f in u1 unl; do
  code="PBG U1"; [ $f = unl ] && code="VCBCPBG Unl"
  run $f "$code" $T
  # deflection (mm) and the indicator
  awk -v T=$T '!/^#/ { tau = $2 / T; pi = atan2(0, -1);
      print 8 * (tau - sin(2 * pi * tau) / (2 * pi)), $10 }' \
    "$WORK/$f/statistics.txt" > "$OUT/${f}_disorder.txt"
  for u in 4.8 6.6 8; do
    run ${f}_$u "$code" "$(time_at $u)"
    cp "$WORK/${f}_$u/particles.txt" "$OUT/${f}_snapshot_$u.txt"
  done
done
run u1_newmark "PBG U1" $T "subsection Time
  set Integrator = newmark
  set Time step  = 0.02235
end
subsection Newton
  set Relative tolerance = 1e-8
end"
{
  echo "# (a) PBG U1 with Newmark (dt = T/200): the last converged step"
  tail -n 1 "$WORK/u1_newmark/statistics.txt" | awk -v T=$T '{ tau = $2 / T; pi = atan2(0, -1);
    printf "t = %s, u_y = %.2f mm, disorder = %s\n", $2, 8 * (tau - sin(2 * pi * tau) / (2 * pi)), $10 }'
  grep -m 1 "did not converge\|Error\|error" "$WORK/u1_newmark.log" | cut -c1-200
} > "$OUT/u1_newmark.txt"
cat "$OUT/u1_newmark.txt"
echo "# u_y(mm) disorder(U1) disorder(Unl) at the snapshots"
for u in 4.8 6.6 8; do
  awk -v u=$u 'function abs(x) { return x < 0 ? -x : x }
    FNR == 1 { best = 1e9 } abs($1 - u) < best { best = abs($1 - u); d[FILENAME] = $2 }
    END { printf "%s", u; for (f in d) printf " %s %s", f, d[f]; print "" }' \
    "$OUT/u1_disorder.txt" "$OUT/unl_disorder.txt"
done | sed "s|$OUT/||g" | tee "$OUT/disorder_at_snapshots.txt"
gnuplot <<END
set terminal pngcairo size 800,500
set output 'doc/figures/beam_bending_disorder.png'
set xlabel 'deflection u_y of the mid cross-section (mm)'
set ylabel 'pairing indicator'
set key top left
set title 'G-2: simply supported beam, 32 x 4 particles, leapfrog'
plot '$OUT/u1_disorder.txt' u 1:2 w l lw 2 t '(a) PBG U1 (classical correspondence)', \
     '$OUT/unl_disorder.txt' u 1:2 w l lw 2 t '(b) VCBCPBG Unl'
set output 'doc/figures/beam_bending_snapshots.png'
set terminal pngcairo size 1400,700
set multiplot layout 2,3
set size ratio -1
unset key
set xrange [-0.5:8.5]
set yrange [-9:1.5]
unset xlabel
unset ylabel
set cblabel 'S_{xx} (N/mm^2)'
set cbrange [-5e4:5e4]
set palette defined (0 'blue', 1 'white', 2 'red')
lambda = 1e5 * 0.3 / (1.3 * 0.4)
mu = 1e5 / 2.6
Sxx(F11, F12, F21, F22) = lambda * ((F11**2 + F21**2 - 1) / 2 + (F12**2 + F22**2 - 1) / 2) + mu * (F11**2 + F21**2 - 1)
do for [f in "unl u1"] {
  do for [u in "4.8 6.6 8"] {
    set title sprintf('%s, u_y = %s mm', f eq 'u1' ? '(a) PBG U1' : '(b) VCBCPBG Unl', u)
    plot sprintf('$OUT/%s_snapshot_%s.txt', f, u) u (\$1+\$3):(\$2+\$4):(Sxx(\$5,\$6,\$7,\$8)) w p pt 7 ps 0.8 palette
  }
}
unset multiplot
END
rm -rf "$WORK"
echo "wrote $OUT and doc/figures/beam_bending_*.png"
