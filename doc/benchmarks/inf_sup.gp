# beta~ against 1/N (log-log) for the tables of doc/benchmarks/inf_sup.sh.
set terminal pngcairo size 1200,520 font ",10"
set output "doc/figures/inf_sup.png"
set multiplot layout 1,2
set logscale xy
set xlabel "1/N"
set ylabel "inf-sup value beta_h = sqrt(lambda_k)" noenhanced
set key bottom right
set grid
set xrange [0.025:0.6]
set yrange [5e-4:1.2]
names = "q1 q1p0 pbg_unl bcpbg_unl pbg_u1 pbg_unlp0 bcpbg_unlp0 pbg_u2 pbg_u2p1 pbg_u2p1c bcpbg_unl_p1c"
titles = "'Q1 (displacement)' 'Q1P0' 'PBG Unl noBC' 'BCPBG Unl' 'PBG U1 (WTE1)' 'PBG UnlP0 noBC' 'BCPBG UnlP0' 'PBG U2' 'PBG U2P1 (on U2)' 'PBG U2P1C (on U2)' 'BCPBG Unl+P1C'"
do for [tag in "regular distorted"] {
  set title sprintf("clamped unit square, %s mesh%s", tag, tag eq "distorted" ? " (0.3)" : "")
  plot for [i=1:words(names)] sprintf("doc/benchmarks/inf_sup/%s_%s.txt", word(names,i), tag) \
         using (1./$1):7 with linespoints lw 2 title word(titles,i), \
       0.5*x with lines dt 2 lc "gray" title "slope 1"
}
unset multiplot
