# LME's gamma on the soil block (2 m cells), both integrators (LME's colour, each integrator's dash and marker), from
# data/soil_gamma.csv (integrator, gamma, settled_error, mean_floor, ..., swing, swing_floor, exact_swing, ..., status).
# Left, above: accuracy, the settled value against the solver's own finite-strain static column; below it FE's minus
# NPC's in mm (the two lie within a line width of each other above; the title quotes the largest |FE - NPC|), FE's
# marker, about a thin grey zero line, its bars the sum of their bands. Right: the free
# oscillation after the ramp: its swing against the exact column's (black), above it ringing, below it damping.
# Error bars: each measure's band. A failed run is a ring on the strip above its panel's data.
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_gamma'" soil_gamma.gp
load dir."/common.gp"
w = 12; h = 7
f = data.'/soil_gamma.csv'
shape = 'lme'
stats f using (strcol(12) eq 'failed' ? 1 : 0) nooutput name "failing"
failures = int(failing_sum)
# FE's settled error minus NPC's at each gamma both finished, with the sum of their bands
difference = "< awk -F, 'NR > 1 && $12 == \"ok\" {v[$1 \" \" $2] = $3; b[$1 \" \" $2] = $4; g[$2] = 1} " \
  ."END {for (x in g) if ((\"npc \" x) in v && (\"fe \" x) in v) " \
  ."print x \",\" v[\"fe \" x] - v[\"npc \" x] \",\" b[\"fe \" x] + b[\"npc \" x]}' ".f." | sort -t, -g"
stats difference using (1e3 * abs($2)) nooutput name "gap"
largest_difference = gap_max                    # mm
style(i) = sprintf("lw %g lc rgb '%s' dt %d pt %d", method_lw, colour(shape), dash(i), marker(i))
name(i) = 'LME + '.integrator_name(i)
one(i, col, band) = sprintf("f using ((strcol(1) eq '%s' && strcol(12) eq 'ok') ? $2 : NaN):%d:%d with yerrorlines %s title '%s'", \
  i, col, band, style(i), name(i))
failed_at(lo, hi) = failures > 0 ? sprintf(", f using (strcol(12) eq 'failed' ? $2 : NaN):(%.12g) with points %s title 'failed'", \
  strip_y_linear(lo, hi), failed_style) : ""
range(lo, hi) = failures > 0 ? strip_linear(lo, hi, 'failed') : sprintf("set yrange [%g:%g]; ", lo, hi)
margins(x0, x1, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; " \
  ."set tmargin at screen %g; ", x0, x1, bottom, top)
accuracy = margins(0.08, 0.47, 0.45, 0.86).range(0, 0.016) \
  ."set title 'accuracy: settled u_y against the finite-strain static column'; unset xlabel; " \
  ."set ylabel '|mean u_y − u_{static, log}| (m)'; set key bottom right; " \
  ."plot ".one('npc', 3, 4).", ".one('fe', 3, 4).failed_at(0, 0.016)."; ".unstrip
accuracy_difference = margins(0.08, 0.47, 0.08, 0.34)."set xlabel 'γ'; set yrange [-0.4:0.4]; set ytics 0.2; " \
  ."set title 'FE − NPC of the settled error (FE’s marker; bars: the sum of their bands)'; " \
  ."set ylabel 'FE − NPC (mm)'; unset key; " \
  ."plot 0 with lines lw 1 lc rgb c_reference, difference using 1:($2 * 1e3):($3 * 1e3) with yerrorbars " \
  .sprintf("pt %d ps 1.3 lw 1.5 lc rgb colour(shape); set ytics autofreq; ", marker('fe'))
swing = margins(0.58, 0.97, 0.08, 0.86).range(0.003, 0.0065) \
  ."set title 'free oscillation after the ramp: above the exact swing rings, below damps'; " \
  ."set ylabel 'swing of u_y, last 4 T_1 (m)'; set key at graph 0.98, first 0.0064 top right; " \
  ."plot ".one('npc', 7, 8).", ".one('fe', 7, 8) \
  .", f using (strcol(1) eq 'npc' ? $2 : NaN):9 with lines ".exact_style." title 'exact column'".failed_at(0.003, 0.0065)."; ".unstrip
title = "Soil block, 2 m cells: LME’s γ with FE and NPC (error bars: the band of each measure);\n" \
  .sprintf("the two integrators’ accuracy coincides: |FE − NPC| ≤ %.2g mm (below it)", largest_difference) \
  .(failures > 0 ? sprintf("; %d failed run%s on the strips", failures, failures == 1 ? "" : "s") : "; every run finished")
draw = "set multiplot title \"".title."\"; set xlabel 'γ'; set xrange [0.6:5.2]; set grid; " \
  .accuracy.accuracy_difference.swing."unset multiplot"
load dir."/output.gp"
