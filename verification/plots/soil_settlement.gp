# Fig. 13: vertical displacement u_y(t) = y(t) - Y of the top particle (4.5, 9.5) m for LME gamma = 0.8,
# LME gamma = 3, linear (Q4) and uGIMP, with the predictor-corrector (top) and forward Euler (bottom),
# against the exact column at Y (paper/07_exact_column.md) and the static settlement of the finite-strain column at Y
# (mpm/exact/column_log_strain.hpp, the model the solver discretises; dashed). Left: 0-20 s; right: after the ramp,
# t = 10-20 s and u = -0.598 to -0.556 m (the dashed box on the left), with the key beside it, over no data.
# gnuplot -e "data='DATA_DIR'; out='.../soil_fig13_settlement'" soil_settlement.gp   (writes out.png and out.pdf)
set datafile separator ","
methods = "lme0.8 lme3 linear ugimp"
labels = "'LME {/Symbol g} = 0.8' 'LME {/Symbol g} = 3' 'linear (Q4)' 'uGIMP'"
colours = "#1f77b4 #d62728 #2ca02c #9467bd"
integrators = "npc fe"
names = "'predictor-corrector (NPC)' 'forward Euler (FE)'"
file(method, integrator) = data."/soil_settlement_".method."_".integrator."_h2.csv"
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 1250,1000 font ",11" } else { set terminal pdfcairo size 8.2in,6.6in font ",8" }
  set output out.".".format
  set multiplot title "Fig. 13: settlement of the top particle (4.5, 9.5) m, 2 m cells, CFL 0.1"
  do for [k = 1:2] {
    integrator = word(integrators, k)
    # the whole history
    set origin 0, (2 - k) * 0.47
    set size 0.45, 0.46
    set xrange [0:20]
    set yrange [-0.65:0.02]
    set xtics autofreq
    set ytics autofreq
    set xlabel "t (s)"
    set ylabel "u_y (m)"
    set title word(names, k)
    unset key
    set grid
    set object 1 rect from 10, -0.598 to 20, -0.556 fs empty border lc rgb "#555555" dt 2
    plot file("lme3", "npc") using 1:3 with lines lw 2.5 lc rgb "black", \
         file("lme3", "npc") using 1:4 with lines lw 1.5 dt 2 lc rgb "black", \
         for [m = 1:4] file(word(methods, m), integrator) using 1:2 with lines lw 1.4 lc rgb word(colours, m)
    unset object 1
    # after the ramp, enlarged (the dashed box on the left); the key beside it, over no data
    set origin 0.45, (2 - k) * 0.47
    set size 0.55, 0.46
    set rmargin 22
    set xrange [10:20]
    set yrange [-0.598:-0.556]
    set ytics 0.01
    set title word(names, k).": after the ramp (t = 10-20 s)".(k == 2 ? "; linear FE leaves it upwards (left)" : "")
    set key outside right top vertical font ",9" samplen 2
    plot file("lme3", "npc") using 1:3 with lines lw 2.5 lc rgb "black" title "exact (small strain)", \
         file("lme3", "npc") using 1:4 with lines lw 1.5 dt 2 lc rgb "black" title "finite-strain static", \
         for [m = 1:4] file(word(methods, m), integrator) using 1:2 with lines lw 1.4 lc rgb word(colours, m) title word(labels, m)
    unset rmargin
  }
  unset multiplot
}
