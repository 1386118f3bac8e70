# Beyond the paper: the soil block on 2, 1 and 0.5 m cells (2 x 2 particles per cell, NPC, CFL 0.1), errors of the
# top particle's settlement, one curve per shape function (soil_refinement_SHAPE.csv: h, rms_error, abs_final_error,
# abs_mean_minus_log_strain_static, model_gap, completed, mean_minus_log_strain_static, mean_floor).
# Left: the RMS of u - u_exact over 0-20 s; middle: |u - u_exact| at 20 s, both against the small-strain exact column
# (paper/07_exact_column.md), with the gap between the small- and finite-strain static columns (grey, dotted).
# Right: |mean settlement after the ramp - finite-strain static settlement| (mpm/exact/column_log_strain.hpp): filled
# where the mean lies above the column (settles less), open where below, so that a sign change shows; the bars are
# the estimator's floor (the range of the mean as its window moves back over one period). Points of one h are
# offset sideways by shape so that coinciding ones stay visible. A run that did not complete (completed = 0) is a
# cross on the strip above the data of each panel; the title says when every run completed. One key, below.
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_refinement'" soil_refinement.gp
load dir."/common.gp"
w = 13; h = 6.2
shapes = "linear ugimp lme0.8 lme3 bspline2 bspline3"
integrator = "npc"
file(s) = data."/soil_refinement_".s.".csv"
offset(s) = 1 + 0.03 * (words(substr(shapes, 1, strstrt(shapes, s))) - 3.5)   # the shape's place in the list
failures = 0
do for [s in shapes] { stats file(s) using ($6 == 0 ? 1 : 0) nooutput; failures = failures + STATS_sum }
done = "($6 == 1 ? $1 * offset(s) : NaN)"      # a completed run's h, offset (inside plot for [s in shapes])
stopped_at(lo, hi) = sprintf(", for [s in shapes] file(s) using ($6 == 0 ? $1 * offset(s) : NaN):(%.12g) with points %s", \
  strip_y_log(lo, hi), stopped_style)
# a panel: its margins (left edge on the page), its range, the strip when a run did not complete
frame(x, lo, hi, title, label) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen 0.27; " \
  ."set tmargin at screen 0.84; set title \"%s\"; set ylabel \"%s\"; ", x, x + 0.255, title, label) \
  .(failures > 0 ? strip_log(lo, hi, 'did not complete').sprintf("set ytics %g, 10, %g; ", lo, hi) \
  : sprintf("set yrange [%g:%g]; ", lo, hi))
# the errors against the small-strain exact column (column 2 or 3), with the model gap
exact_panel(x, column, title, label) = frame(x, 1e-3, 0.05, title, label)."plot " \
  ."for [s in shapes] file(s) using ".done.":".column." with linespoints " \
  ."lw method_lw lc rgb colour(s) dt dash(integrator) pt marker(integrator)" \
  .", file('lme3') using 1:5 with lines ".reference_style \
  .(failures > 0 ? stopped_at(1e-3, 0.05) : "")."; ".unstrip
# against the finite-strain column: the line, the floor's bars, then filled (mean above) or open (below) markers
static_panel(x) = frame(x, 5e-6, 0.05, "|mean u_y after the ramp − u_{finite strain}|\\n(against the finite-strain static column)", \
  "error of the mean u_y (m)")."plot " \
  ."for [s in shapes] file(s) using ".done.":4 with lines lw method_lw lc rgb colour(s) dt dash(integrator), " \
  ."for [s in shapes] file(s) using ".done.":4:($4 - $8 > 5e-6 ? $4 - $8 : 5e-6):($4 + $8) with yerrorbars " \
  ."ps 0 lc rgb colour(s), " \
  ."for [s in shapes] file(s) using ($6 == 1 && $7 > 0 ? $1 * offset(s) : NaN):4 with points " \
  ."pt marker(integrator) ps 1.1 lc rgb colour(s), " \
  ."for [s in shapes] file(s) using ($6 == 1 && $7 <= 0 ? $1 * offset(s) : NaN):4 with points " \
  ."pt open(marker(integrator)) ps 1.2 lw 2 lc rgb colour(s)".(failures > 0 ? stopped_at(5e-6, 0.05) : "")."; ".unstrip
# the one key, a panel of its own across the page below the three
key = "unset logscale; unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid; " \
  ."set lmargin at screen 0.02; set rmargin at screen 0.98; set bmargin at screen 0.01; set tmargin at screen 0.17; " \
  ."set xrange [0:1]; set yrange [0:1]; set key center center vertical maxrows 3 width 1 samplen 3; plot NaN notitle, " \
  ."for [s in shapes] keyentry with linespoints lw method_lw lc rgb colour(s) dt dash(integrator) " \
  ."pt marker(integrator) title method_name(s, integrator), " \
  ."keyentry with lines ".reference_style." title 'small- vs finite-strain static gap', " \
  ."keyentry with points pt marker(integrator) lc rgb c_exact title 'right: mean above (settles less)', " \
  ."keyentry with points pt open(marker(integrator)) lw 2 lc rgb c_exact title 'right: mean below (settles more)', " \
  ."keyentry with yerrorbars ps 0 lc rgb c_exact title 'right: the estimator’s floor'" \
  .(failures > 0 ? ", keyentry with points ".stopped_style." title 'did not complete'" : "")."; "
title = "Soil block, grid refinement: 2, 1 and 0.5 m cells (2 × 2 particles per cell), NPC, CFL 0.1: errors of the top " \
  ."particle’s settlement u_y;\\npoints of one h offset sideways by shape; " \
  .(failures > 0 ? sprintf("%d run%s did not complete (crosses on the strips)", failures, failures == 1 ? "" : "s") : "every run completed")
settings = "set logscale xy; set xrange [0.4:2.5]; set xtics ('0.5' 0.5, '1' 1, '2' 2); set xlabel 'cell size h (m)'; " \
  ."set format y '10^{%L}'; set grid; unset key; "
draw = "set multiplot title \"".title."\"; ".settings \
  .exact_panel(0.06, 2, "RMS of u_y − u_{exact} over 0-20 s\\n(against the small-strain exact column)", "error of u_y (m)") \
  .exact_panel(0.39, 3, "|u_y − u_{exact}| at 20 s\\n(against the small-strain exact column)", "error of u_y (m)") \
  .static_panel(0.72).key."unset multiplot"
load dir."/output.gp"
