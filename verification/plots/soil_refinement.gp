# Beyond the paper: the soil block on 2, 1 and 0.5 m cells (2 x 2 particles per cell, NPC, CFL 0.1), errors of the
# top particle's settlement, one curve per shape function (soil_refinement_SHAPE.csv: h, rms_error, abs_final_error,
# abs_mean_minus_log_strain_static, model_gap, completed, mean_minus_log_strain_static, mean_floor).
# Left: the RMS of u - u_exact over 0-20 s; middle: |u - u_exact| at 20 s, both against the small-strain exact column
# (paper/07_exact_column.md), with the gap between the small- and finite-strain static columns (grey, dotted). uGIMP,
# LME gamma = 0.8 and the B-splines of degree 2 and 3 lie on one line there: under each, a difference panel draws
# each of those four minus their mean at each h (mm; linear and LME gamma = 3 lie apart above and are left out).
# Right: mean settlement after the ramp - finite-strain static settlement (mpm/exact/column_log_strain.hpp), signed,
# on a symmetric log axis (linear within +-1e-5 m): above zero the mean lies above the column (settles less), below
# zero under it; the bars are the estimator's floor (the range of the mean as its window moves back over one period).
# Points of one h are offset sideways by shape so that coinciding ones stay visible. A run that did not complete
# (completed = 0) is its method's marker inside a cross on the strip above the data of each panel, named in the key;
# the title says when every run completed. One key, below.
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_refinement'" soil_refinement.gp
load dir."/common.gp"
w = 13; h = 8.6
shapes = "linear ugimp lme0.8 lme3 bspline2 bspline3"
alike = "ugimp lme0.8 bspline2 bspline3"          # the four that lie on one line in the left and middle panels
integrator = "npc"
hs = "2 1 0.5"
file(s) = data."/soil_refinement_".s.".csv"
offset(s) = 1 + 0.03 * (words(substr(shapes, 1, strstrt(shapes, s))) - 3.5)   # the shape's place in the list
at(hh) = abs($1 - hh) < 1e-9 * hh
# the runs that did not complete, each named (method and cell size)
failures = 0; failed_names = ""
do for [s in shapes] { do for [hh in hs] {
  stats file(s) using (at(hh + 0) && $6 == 0 ? 1 : 0) nooutput
  if (STATS_sum > 0) { failures = failures + 1
    failed_names = failed_names.sprintf(", keyentry with points %s title 'did not complete: %s, h = %s m'", \
      stopped_style, method_name(s, integrator), hh) }
} }
# the four's mean at each h (completed runs), their range, and the largest deviation from the mean (mm)
array mean_rms[3]; array mean_end[3]; array count[3]
do for [k = 1:3] { mean_rms[k] = 0; mean_end[k] = 0; count[k] = 0
  do for [s in alike] {
    stats file(s) using (at(word(hs, k) + 0) && $6 == 1 ? $2 : 0) nooutput; mean_rms[k] = mean_rms[k] + STATS_sum
    stats file(s) using (at(word(hs, k) + 0) && $6 == 1 ? $3 : 0) nooutput; mean_end[k] = mean_end[k] + STATS_sum
    stats file(s) using (at(word(hs, k) + 0) && $6 == 1 ? 1 : 0) nooutput; count[k] = count[k] + STATS_sum
  }
  mean_rms[k] = count[k] > 0 ? mean_rms[k] / count[k] : NaN; mean_end[k] = count[k] > 0 ? mean_end[k] / count[k] : NaN
}
row(x) = x > 1.5 ? 1 : x > 0.75 ? 2 : 3             # the h of a row (2, 1, 0.5 m) as 1, 2, 3
mean_of(column, x) = column == 2 ? mean_rms[row(x)] : mean_end[row(x)]
lo_rms = 1; hi_rms = 0; lo_end = 1; hi_end = 0; reach_rms = 0; reach_end = 0
do for [s in alike] {
  stats file(s) using ($6 == 1 ? $2 : NaN) nooutput; lo_rms = STATS_min < lo_rms ? STATS_min : lo_rms
  hi_rms = STATS_max > hi_rms ? STATS_max : hi_rms
  stats file(s) using ($6 == 1 ? $3 : NaN) nooutput; lo_end = STATS_min < lo_end ? STATS_min : lo_end
  hi_end = STATS_max > hi_end ? STATS_max : hi_end
  stats file(s) using ($6 == 1 ? 1e3 * abs($2 - mean_of(2, $1)) : NaN) nooutput
  reach_rms = STATS_max > reach_rms ? STATS_max : reach_rms
  stats file(s) using ($6 == 1 ? 1e3 * abs($3 - mean_of(3, $1)) : NaN) nooutput
  reach_end = STATS_max > reach_end ? STATS_max : reach_end
}
done = "($6 == 1 ? $1 * offset(s) : NaN)"      # a completed run's h, offset (inside plot for [s in shapes])
# a run that did not complete: its method's marker inside the cross, on the strip at height y
stopped_at(y, among) = sprintf(", for [s in %s] file(s) using ($6 == 0 ? $1 * offset(s) : NaN):(%.12g) with points " \
  ."pt marker(integrator) lc rgb colour(s), for [s in %s] file(s) using ($6 == 0 ? $1 * offset(s) : NaN):(%.12g) " \
  ."with points %s", among, y, among, y, stopped_style)
# a panel's place on the page (left edge x, bottom b, top t) and title
place(x, b, t, title, label) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; " \
  ."set tmargin at screen %g; set title \"%s\"; set ylabel \"%s\"; ", x, x + 0.255, b, t, title, label)
# top left and middle: the errors against the small-strain exact column (column 2 or 3), with the model gap
exact_panel(x, column, title) = place(x, 0.53, 0.86, title, "error of u_y (m)") \
  ."set logscale xy; set format x ''; unset xlabel; set format y '10^{%L}'; " \
  .(failures > 0 ? strip_log(1e-3, 0.05, 'did not complete').sprintf("set ytics %g, 10, %g; ", 1e-3, 0.05) \
  : "set yrange [1e-3:0.05]; set ytics autofreq; ")."plot " \
  ."for [s in shapes] file(s) using ".done.":".column." with linespoints " \
  ."lw method_lw lc rgb colour(s) dt dash(integrator) pt marker(integrator)" \
  .", file('lme3') using 1:5 with lines ".reference_style \
  .(failures > 0 ? stopped_at(strip_y_log(1e-3, 0.05), "shapes") : "")."; ".unstrip
# under it: the four that coincide, each minus their mean at its h (mm)
alike_panel(x, column, reach, label) = place(x, 0.2, 0.45, "uGIMP, LME γ = 0.8, B-spline 2, 3 − their mean", label) \
  ."unset logscale y; set logscale x; set format x '%g'; set xlabel 'cell size h (m)'; set format y '%g'; " \
  .(failures > 0 ? strip_linear(-1.15 * reach, 1.15 * reach, 'did not complete') \
  : sprintf("set yrange [%g:%g]; ", -1.15 * reach, 1.15 * reach))."set ytics autofreq; plot " \
  ."0 with lines lw 1 lc rgb c_exact, " \
  ."for [s in alike] file(s) using ".done.":(1e3 * ($".column." - mean_of(".column.", $1))) with linespoints " \
  ."lw method_lw lc rgb colour(s) dt dash(integrator) pt marker(integrator)" \
  .(failures > 0 ? stopped_at(strip_y_linear(-1.15 * reach, 1.15 * reach), "alike") : "")."; ".unstrip
# right: mean - finite-strain static, signed, on sign(d) log10(1 + |d| / d0), labelled in d; the floor's bars
d0 = 1e-5
symlog(d) = d >= 0 ? log10(1 + d / d0) : -log10(1 - d / d0)
decade(d) = sprintf('10^{%d}', floor(log10(abs(d)) + 0.5))
tic(d) = sprintf('"%s" %.6g', d == 0 ? '0' : (d < 0 ? '−' : '').decade(d), symlog(d))
symlog_tics = 'set ytics ('.tic(-0.01).', '.tic(-1e-3).', '.tic(-1e-4).', '.tic(0).', '.tic(1e-4).', '.tic(1e-3).'); '
lo_static = symlog(-0.04); hi_static = symlog(0.006)
static_panel(x) = place(x, 0.2, 0.86, "mean u_y after the ramp − u_{finite strain}\\n(against the finite-strain " \
  ."static column)\\nbars: the estimator’s floor", "mean u_y − u_{finite strain} (m)") \
  ."unset logscale y; set logscale x; set format x '%g'; set xlabel 'cell size h (m)'; ".symlog_tics \
  .(failures > 0 ? strip_linear(lo_static, hi_static, 'did not complete') \
  : sprintf("set yrange [%g:%g]; ", lo_static, hi_static)) \
  ."set label 1 'above the column: settles less' at graph 0.03, first symlog(4e-3) left front; " \
  ."set label 2 'below the column: settles more' at graph 0.97, first symlog(-4e-4) right front; plot " \
  ."0 with lines lw 1 lc rgb c_exact, " \
  ."for [s in shapes] file(s) using ".done.":(symlog($7)):(symlog($7 - $8)):(symlog($7 + $8)) with yerrorbars " \
  ."ps 0 lc rgb colour(s), " \
  ."for [s in shapes] file(s) using ".done.":(symlog($7)) with linespoints " \
  ."lw method_lw lc rgb colour(s) dt dash(integrator) pt marker(integrator)" \
  .(failures > 0 ? stopped_at(strip_y_linear(lo_static, hi_static), "shapes") : "")."; ".unstrip \
  ."unset label 1; unset label 2; "
# the one key, a panel of its own across the page below the three
key = "unset logscale; unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid; " \
  ."set lmargin at screen 0.02; set rmargin at screen 0.98; set bmargin at screen 0.01; set tmargin at screen 0.11; " \
  ."set xrange [0:1]; set yrange [0:1]; set key center center vertical maxrows 3 width 1 samplen 3; plot NaN notitle, " \
  ."for [s in shapes] keyentry with linespoints lw method_lw lc rgb colour(s) dt dash(integrator) " \
  ."pt marker(integrator) title method_name(s, integrator), " \
  ."keyentry with lines ".reference_style." title 'small- vs finite-strain static gap', " \
  ."keyentry with yerrorbars ps 0 lc rgb c_exact title 'right: the estimator’s floor'".failed_names."; "
title = "Soil block, grid refinement: 2, 1 and 0.5 m cells (2 × 2 particles per cell), NPC, CFL 0.1: errors of the top " \
  ."particle’s settlement u_y; " \
  .(failures > 0 ? sprintf("%d run%s did not complete (crosses on the strips)", failures, failures == 1 ? "" : "s") \
  : "every run completed") \
  .sprintf(".\\nuGIMP, LME γ = 0.8, B-spline 2 and B-spline 3 lie on one line at the left (RMS %.4f-%.4f m) and in the " \
  ."middle (%.4f-%.4f m at 20 s): below, each minus their mean;\\npoints of one h offset sideways by shape; right, a symmetric log axis (linear within ± 10^{-5} m)", \
  lo_rms, hi_rms, lo_end, hi_end)
settings = "set xrange [0.4:2.5]; set xtics ('0.5' 0.5, '1' 1, '2' 2); set grid; unset key; "
draw = "set multiplot title \"".title."\"; ".settings \
  .exact_panel(0.06, 2, "RMS of u_y − u_{exact} over 0-20 s\\n(against the small-strain exact column)") \
  .alike_panel(0.06, 2, reach_rms, "RMS − their mean (mm)") \
  .exact_panel(0.39, 3, "|u_y − u_{exact}| at 20 s\\n(against the small-strain exact column)") \
  .alike_panel(0.39, 3, reach_end, "error at 20 s − their mean (mm)") \
  .static_panel(0.72).key."unset multiplot"
load dir."/output.gp"
