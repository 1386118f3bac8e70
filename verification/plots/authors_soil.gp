# The authors' code (NL-PartSol 1d5da04) beside this project on the soil block: the top particle's settlement u_y(t)
# of the four cases of verification/authors_soil.py, one column per method (LME under the authors' beta + NPC, uGIMP +
# NPC, linear (Q4) + NPC, linear (Q4) + FE; their PCE is our NPC). Top: theirs (other_code_style) and ours under their
# settings (method_style; theirs drawn over ours, their ring around our marker) over 0-20 s; bottom: theirs - ours (µm)
# at their sample times, a thin solid line in the method's colour with its integrator's marker (the difference swings
# every second or so: a dashed line would break up). Their Q4 runs stopped near
# 8.5 s (ours was run to their stop): a black cross on the strip above each of those panels at their last sample, their
# asterisk (other_code_style) just left of it, named in its key. No tic is labelled on a strip (ytics in the data range
# only). The titles quote the largest |theirs - ours| over their settlement from authors_soil.csv.
# From data/authors_soil_CASE.csv (t, theirs, ours, difference: ours interpolated at their times, theirs - ours) and
# data/authors_soil.csv (case, variant, their_end_time, their_settlement, largest_difference, largest_percent, ...),
# both written by verification/authors_soil.py.
#   gnuplot -e "dir='verification/plots'; data='results/studies/data'; out='...'" authors_soil.gp
load dir."/common.gp"
w = 13.3; h = 7.4
cases = 'lme_pce ugimp_pce q4_pce q4_fe'
shapes = 'lme_authors ugimp linear linear'; integrators = 'npc npc npc fe'
history(m) = sprintf('%s/authors_soil_%s.csv', data, word(cases, m))
summary = data.'/authors_soil.csv'
method(m) = method_name(word(shapes, m), word(integrators, m)).(word(integrators, m) eq 'npc' ? ' (their PCE)' : '')
style(m) = method_style(word(shapes, m), word(integrators, m))
full_time = 20.0                                # s, the scene's end
# each case's numbers: their last sample, the largest |theirs - ours| (m, % of their settlement), the difference's range
array end_time[4]; array largest[4]; array percent[4]; array low[4]; array high[4]
do for [m = 1:4] {
  stats summary using (strcol(1) eq word(cases, m) && strcol(2) eq 'their_settings' ? $3 : NaN) nooutput
  end_time[m] = STATS_max
  stats summary using (strcol(1) eq word(cases, m) && strcol(2) eq 'their_settings' ? $5 : NaN) nooutput
  largest[m] = STATS_max
  stats summary using (strcol(1) eq word(cases, m) && strcol(2) eq 'their_settings' ? $6 : NaN) nooutput
  percent[m] = STATS_max
  stats history(m) using (1e6 * $4) nooutput
  low[m] = STATS_min; high[m] = STATS_max
}
stopped(m) = end_time[m] < full_time - 1e-6
# the difference's range, symmetric about zero with a little room
reach(m) = 1.15 * (abs(low[m]) > abs(high[m]) ? abs(low[m]) : abs(high[m]))
# ytics at a round step (1, 2 or 5 times a power of ten, about three per half range), -reach..reach only (none on
# the strip)
step(r) = (r / 3 / 10**floor(log10(r / 3)) < 1.5 ? 1 : r / 3 / 10**floor(log10(r / 3)) < 3.5 ? 2 : 5) \
  * 10**floor(log10(r / 3))
symmetric_tics(r) = sprintf("set ytics %.12g, %.12g, %.12g; ", -floor(r / step(r)) * step(r), step(r), \
  floor(r / step(r)) * step(r))
stop_name(m) = sprintf('theirs stopped at %.2f s', end_time[m])
# the cross on the strip at their last sample, their asterisk just left of it (0.9 s: a marker's width)
stop_mark(m, lo, hi) = sprintf(", '+' using (%.12g):(%.12g) with points %s ps 1.8 notitle, " \
  ."'+' using (%.12g):(%.12g) with points %s title '%s'", end_time[m] - 0.9, strip_y_linear(lo, hi), \
  other_code_style, end_time[m], strip_y_linear(lo, hi), stopped_style, stop_name(m))
every = 250                                    # a marker every 250 of their samples (about 1.7 s)
settlement(m) = sprintf("set title \"%s\"; set xlabel 't (s)'; set ylabel 'u_y of the top particle (m)'; " \
  ."set xrange [0:%g]; set xtics 5; set ytics -0.6, 0.1, 0; ", method(m), full_time) \
  .(stopped(m) ? strip_linear(-0.65, 0.02, 'stopped') : "set yrange [-0.65:0.02]; ") \
  ."set key at graph 0.98, first -0.03 right top samplen 3; " \
  .sprintf("plot '%s' using 1:3 with linespoints %s pi %d title 'ours, their settings', " \
  ."'%s' using 1:2 with linespoints %s ps 1.8 pi %d title 'theirs (NL-PartSol)'", \
  history(m), style(m), every, history(m), other_code_style, every) \
  .(stopped(m) ? stop_mark(m, -0.65, 0.02) : "")."; ".unstrip
difference(m) = sprintf("set title \"theirs − ours, at their sample times:\\nlargest %.2g µm, %.2g %% of their settlement\"; " \
  ."set xlabel 't (s)'; set ylabel 'u_{y,theirs} − u_{y,ours} (µm)'; set xrange [0:%g]; set xtics 5; ", \
  1e6 * largest[m], percent[m], full_time).symmetric_tics(reach(m)) \
  .(stopped(m) ? strip_linear(-reach(m), reach(m), 'stopped') : sprintf("set yrange [%g:%g]; ", -reach(m), reach(m))) \
  ."set key off; " \
  .sprintf("plot '%s' using 1:(1e6 * $4) with linespoints lw 1 dt 1 pt %d pi %d lc rgb '%s' notitle", history(m), \
  marker(word(integrators, m)), every, colour(word(shapes, m))) \
  .(stopped(m) ? stop_mark(m, -reach(m), reach(m)) : "")."; ".unstrip
panels = ''
do for [m = 1:4] { panels = panels.settlement(m).'; ' }
do for [m = 1:4] { panels = panels.difference(m).'; ' }
heading = "The authors' code (NL-PartSol) and ours on the soil block: the top particle's settlement, ours under " \
  ."their settings; theirs and ours lie on one another (top), their difference below.\\nTheir linear (Q4) runs " \
  ."stopped near 8.5 s (crosses on the strips, their asterisk beside; ours was run to their stop)"
draw = "set multiplot layout 2,4 title \"".heading."\"; ".panels."unset multiplot"
load dir."/output.gp"
