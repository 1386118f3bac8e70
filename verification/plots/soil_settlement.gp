# Fig. 13: vertical displacement u_y(t) = y(t) - Y of the top particle (4.5, 9.5) m for LME gamma = 0.8,
# LME gamma = 3, linear (Q4) and uGIMP, with the predictor-corrector (top) and forward Euler (bottom),
# against the exact column at Y (paper/07_exact_column.md); inset t = 10-15 s, u = -0.6 to -0.5 m.
# gnuplot -e "data='DATA_DIR'; out='.../soil_fig13_settlement'" soil_settlement.gp   (writes out.png and out.pdf)
set datafile separator ","
methods = "lme0.8 lme3 linear ugimp"
labels = "'LME {/Symbol g} = 0.8' 'LME {/Symbol g} = 3' 'linear (Q4)' 'uGIMP'"
colours = "#1f77b4 #d62728 #2ca02c #9467bd"
integrators = "npc fe"
names = "'predictor-corrector (NPC)' 'forward Euler (FE)'"
file(method, integrator) = data."/soil_settlement_".method."_".integrator."_h2.csv"
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 950,1100 font ",11" } else { set terminal pdfcairo size 6.2in,7.2in font ",8" }
  set output out.".".format
  set multiplot title "Fig. 13: settlement of the top particle (4.5, 9.5) m, 2 m cells, CFL 0.1"
  do for [k = 1:2] {
    integrator = word(integrators, k)
    # the panel
    set origin 0, (2 - k) * 0.48
    set size 1, 0.47
    set xrange [0:20]
    set yrange [-0.7:0.05]
    set xlabel "t (s)"
    set ylabel "u_y (m)"
    set title word(names, k)
    set key bottom left
    set grid
    unset object 1
    set object 1 rect from 10, -0.6 to 15, -0.5 fs empty border lc rgb "#555555" dt 2
    plot file("lme3", "npc") using 1:3 with lines lw 2.5 lc rgb "black" title "exact (small strain)", \
         for [m = 1:4] file(word(methods, m), integrator) using 1:2 with lines lw 1.4 lc rgb word(colours, m) title word(labels, m)
    # the inset
    unset object 1
    set origin 0.5, (2 - k) * 0.48 + 0.2
    set size 0.45, 0.22
    set xrange [10:15]
    set yrange [-0.6:-0.5]
    set xtics 1
    set ytics 0.05
    unset xlabel
    unset ylabel
    unset title
    unset key
    set object 2 rect from screen 0.5, screen (2 - k) * 0.48 + 0.2 to screen 0.95, screen (2 - k) * 0.48 + 0.42 fc rgb "white" fs solid 1.0 behind
    plot file("lme3", "npc") using 1:3 with lines lw 2.5 lc rgb "black" notitle, \
         for [m = 1:4] file(word(methods, m), integrator) using 1:2 with lines lw 1.4 lc rgb word(colours, m) notitle
    unset object 2
    set xtics autofreq
    set ytics autofreq
  }
  unset multiplot
}
