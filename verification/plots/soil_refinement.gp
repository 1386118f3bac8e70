# Beyond the paper: the soil block on 2, 1 and 0.5 m cells (2 x 2 particles per cell, NPC), errors of the
# top particle's settlement. Left: RMS of u - u_exact over 0-20 s and |u - u_exact| at 20 s against the
# small-strain exact column (paper/07_exact_column.md), with the gap between the small- and finite-strain static columns.
# Right: |mean settlement after the ramp - finite-strain static settlement| (mpm/exact/column_log_strain.hpp): filled
# where the mean lies above the column (settles less), open where below, so that a sign change shows; the bars are
# the estimator's floor (the range of the mean as its window moves back over one period). Points of one h are
# offset sideways by shape so that coinciding ones stay visible.
# Runs that failed (completed = 0) are left out (none does with NPC; the report's table says so).
# gnuplot -e "data='DATA_DIR'; out='.../soil_refinement'" soil_refinement.gp   (writes out.png and out.pdf)
set datafile separator ","
methods = "linear ugimp lme0.8 lme3 bspline2 bspline3"
labels = "'linear (Q4)' 'uGIMP' 'LME {/Symbol g} = 0.8' 'LME {/Symbol g} = 3' 'B-spline 2' 'B-spline 3'"
colours = "#2ca02c #9467bd #1f77b4 #d62728 #ff7f0e #8c564b"
file(m) = data."/soil_refinement_".word(methods, m).".csv"
set logscale xy
set xrange [0.4:2.5]
set xtics ("0.5" 0.5, "1" 1, "2" 2)
set xlabel "cell size h (m)" offset 0,0.3
set grid
set format y "10^{%L}"
# the keys below the panels, over no data: the line styles under the left panel, the methods' colours (both panels)
# under the right one
set key outside bottom center horizontal maxrows 3 font ",9" samplen 2.5
offset(m) = 1 + 0.03 * (m - 3.5)
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 1250,620 font ",11" } else { set terminal pdfcairo size 8.3in,4.1in font ",8" }
  set output out.".".format
  set multiplot layout 1,2 title "Soil block, grid refinement (NPC, CFL 0.1); points of one h offset sideways by shape"
  set title "against the small-strain exact column"
  set ylabel "error of u_y (m)"
  set yrange [1e-3:0.05]
  plot for [m = 1:6] file(m) using ($6 == 1 ? $1 * offset(m) : NaN):2 with linespoints lw 1.5 pt 7 lc rgb word(colours, m) notitle, \
       for [m = 1:6] file(m) using ($6 == 1 ? $1 * offset(m) : NaN):3 with linespoints lw 1.5 dt 2 pt 6 lc rgb word(colours, m) notitle, \
       NaN with linespoints lw 1.5 pt 7 lc rgb "black" title "RMS over 0-20 s", \
       NaN with linespoints lw 1.5 dt 2 pt 6 lc rgb "black" title "|error| at 20 s", \
       file(4) using 1:5 with lines lw 2 lc rgb "black" dt 3 title "small- vs finite-strain gap"
  set title "against the finite-strain static column (mean after the ramp)\nfilled: mean above the column; open: below; bars: the estimator's floor" font ",10"
  set ylabel "|mean u_y - u_{finite strain}| (m)"
  set yrange [5e-6:0.05]
  plot for [m = 1:6] file(m) using ($6 == 1 ? $1 * offset(m) : NaN):4 with lines lw 1.2 lc rgb word(colours, m) title word(labels, m), \
       for [m = 1:6] file(m) using ($6 == 1 ? $1 * offset(m) : NaN):4:($4 - $8 > 5e-6 ? $4 - $8 : 5e-6):($4 + $8) with yerrorbars ps 0 lc rgb word(colours, m) notitle, \
       for [m = 1:6] file(m) using ($6 == 1 && $7 > 0 ? $1 * offset(m) : NaN):4 with points pt 7 ps 1.1 lc rgb word(colours, m) notitle, \
       for [m = 1:6] file(m) using ($6 == 1 && $7 <= 0 ? $1 * offset(m) : NaN):4 with points pt 6 ps 1.2 lw 2 lc rgb word(colours, m) notitle
  unset multiplot
}
