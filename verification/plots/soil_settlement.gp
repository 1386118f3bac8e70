# Fig. 13: vertical displacement u_y(t) = y(t) - Y of the top particle (4.5, 9.5) m for LME gamma = 0.8, LME gamma = 3,
# linear (Q4) and uGIMP (each in its shape's colour), with the predictor-corrector (top row, NPC's dash and marker)
# and forward Euler (bottom row, FE's), against the exact column at Y (paper/07_exact_column.md; black) and the static
# settlement of the finite-strain column at Y (mpm/exact/column_log_strain.hpp, the model the solver discretises;
# grey, dotted), from soil_settlement_SHAPE_INTEGRATOR_h2.csv (t, u, u_exact, u_finite_strain_static; t = 0-20 s).
# Left: the whole run, 0-20 s; right: after the ramp, t = 10-20 s and u = -0.598 to -0.556 m (the dashed box on the
# left) enlarged, with the key beside it, over no data.
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_fig13_settlement'" soil_settlement.gp
load dir."/common.gp"
w = 12.5; h = 10
shapes = "lme0.8 lme3 linear ugimp"
integrators = "npc fe"
file(shape, integrator) = data."/soil_settlement_".shape."_".integrator."_h2.csv"
reference = file("lme3", "npc")                        # u_exact and the finite-strain static column, the same in all
stats reference using 1 nooutput name "time"
box = "set object 1 rect from 10, -0.598 to 20, -0.556 fs empty border lc rgb c_reference dt 2; "
# one panel's curves: the exact, the finite-strain static column, the four shapes with one integrator
curves(integrator, titled) = "plot reference using 1:3 with lines ".exact_style \
  .(titled ? " title 'exact (small strain)'" : "").", reference using 1:4 with lines ".reference_style \
  .(titled ? " title 'finite-strain static'" : "") \
  .", for [s in shapes] file(s, '".integrator."') using 1:2 with linespoints pi 24 ps 0.8 " \
  ."lw method_lw lc rgb colour(s) dt dash('".integrator."') pt marker('".integrator."') " \
  .(titled ? "title method_name(s, '".integrator."')" : "notitle")
whole(k, integrator) = sprintf("set origin 0, %g; set size 0.42, 0.475; ", (2 - k) * 0.475) \
  ."set xrange [0:20]; set yrange [-0.65:0.02]; set xtics autofreq; set ytics autofreq; set xlabel 't (s)'; " \
  ."set ylabel 'u_y (m)'; set title '".integrator_name(integrator).": t = 0-20 s'; unset key; set rmargin; " \
  .box.curves(integrator, 0)."; unset object 1; "
enlarged(k, integrator) = sprintf("set origin 0.42, %g; set size 0.58, 0.475; ", (2 - k) * 0.475) \
  ."set rmargin 27; set xrange [10:20]; set yrange [-0.598:-0.556]; set ytics 0.01; " \
  ."set title '".integrator_name(integrator).": after the ramp, t = 10-20 s (the dashed box, left)" \
  .(integrator eq 'fe' ? "; linear + FE leaves it upwards" : "")."'; " \
  ."set key outside right top vertical samplen 3; ".curves(integrator, 1)."; "
title = sprintf("Fig. 13: settlement u_y(t) of the top particle (4.5, 9.5) m, t = %g-%g s, 2 m cells, CFL 0.1: ", \
  time_min, time_max)."the paper’s four shape functions with NPC (top) and FE (bottom)"
draw = "set multiplot title '".title."'; set grid; "
do for [k = 1:2] { draw = draw.whole(k, word(integrators, k)).enlarged(k, word(integrators, k)) }
draw = draw."unset multiplot"
load dir."/output.gp"
