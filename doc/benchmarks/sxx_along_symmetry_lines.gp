# sigma_xx along the symmetry lines of the plate with a hole against Kirsch's
# solution, from stress_along_boundaries.txt (Output/Stress along boundaries
# = 1, 2). Usage:
#   gnuplot -e "dirs='results'; labels='coupled'; out='results/sxx_along_symmetry_lines.png'" \
#           doc/benchmarks/sxx_along_symmetry_lines.gp
# dirs and labels are blank-separated lists of equal length; the exact
# curve is taken from the first directory.
if (!exists("dirs")) dirs = 'results'
if (!exists("labels")) labels = dirs
if (!exists("out")) out = 'sxx_along_symmetry_lines.png'
set terminal pngcairo size 1200,500 font ",11"
set output out
set multiplot layout 1,2 title "sigma_{xx} along the symmetry lines (Kirsch: 3T = 30 at (0, R))"
set grid
set key top right
file(i) = word(dirs, i)."/stress_along_boundaries.txt"
set xlabel "y on x = 0"
set ylabel "sigma_{xx}"
plot "< awk '$1 == 1' ".file(1)." | sort -g -k3" using 3:7 with lines lw 2 lc rgb "black" title "exact", \
     for [i=1:words(dirs)] "< awk '$1 == 1' ".file(i)." | sort -g -k3" using 3:4 with linespoints pt 7 ps 0.6 title word(labels, i)
set xlabel "x on y = 0"
set key bottom right
plot "< awk '$1 == 2' ".file(1)." | sort -g -k2" using 2:7 with lines lw 2 lc rgb "black" title "exact", \
     for [i=1:words(dirs)] "< awk '$1 == 2' ".file(i)." | sort -g -k2" using 2:4 with linespoints pt 7 ps 0.6 title word(labels, i)
unset multiplot
