# Beyond the paper: the soil block with nu = 0.3 and lateral rollers (LME gamma = 3, NPC, 2 m cells).
# Left: sigma_xx against sigma_yy on every particle at t = 20 s, with sigma_xx = nu/(1-nu) sigma_yy.
# Right: u_y(t) of the top particle against the exact column with the constrained modulus M.
# gnuplot -e "data='DATA_DIR'; out='.../soil_poisson'" soil_poisson.gp   (writes out.png and out.pdf)
set datafile separator ","
nu = 0.3
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 1200,500 font ",11" } else { set terminal pdfcairo size 8in,3.3in font ",8" }
  set output out.".".format
  set multiplot layout 1,2 title "Soil block, {/Symbol n} = 0.3, lateral rollers (LME {/Symbol g} = 3, NPC, CFL 0.1)"
  set title "particles at t = 20 s"
  set xlabel "sigma_{yy} (MPa)"
  set ylabel "sigma_{xx} (MPa)"
  set grid
  set key top left
  set xrange [-0.65:0.02]
  plot x * nu / (1 - nu) with lines lw 2 lc rgb "black" title "{/Symbol n}/(1-{/Symbol n}) sigma_{yy}", \
       data."/soil_poisson_t20.csv" using ($6/1e6):($5/1e6) with points pt 7 ps 0.9 lc rgb "#d62728" title "particles"
  set title "top particle (4.5, 9.5) m"
  set xlabel "t (s)"
  set ylabel "u_y (m)"
  set xrange [0:20]
  set key top right
  plot data."/soil_settlement_lme3_npc_h2_nu0.3.csv" using 1:3 with lines lw 2.5 lc rgb "black" title "exact, M = E(1-{/Symbol n})/((1+{/Symbol n})(1-2{/Symbol n}))", \
       data."/soil_settlement_lme3_npc_h2_nu0.3.csv" using 1:2 with lines lw 1.5 lc rgb "#d62728" title "MPM"
  unset multiplot
}
