# Where methods fail, on the Dyka bar (40 cells, 20 ms), from data/dyka_stability.csv (a row per method) and
# data/dyka_stability_runs.csv (a row per run), written by verification/dyka_stability.sh. Left: per method, as
# fractions of the step limit its scan is placed by (column cfl_limit_scanned, named under the method; the body it
# is computed on is column scanned_limit_body: the free bar, the smaller of its limit at rest and with the particles
# moved 1e-6 h towards the free end; the held bar's only where the free bar's analysis finds no stable CFL, and then
# named so in the title and under the method), the largest scanned CFL below which every run at the paper's
# amplitude is stable (bar), every scanned run (dot: stable, in the amplitude's colour, v0 left of the bar's
# middle, v0/100 right; black cross: stopped by the solver) and the step limit of a bar held at both ends (open
# diamond, column cfl_limit_step). A method with no stable CFL in the scan has a triangle at the scan's start and no
# bar. A stopped run below a bar's top or a dot above a cross marks stable CFLs that are not an interval. Right: v_A
# of linear + forward Euler just below (completes 20 ms) and just above (stopped) its limit at the paper's amplitude.
load dir."/common.gp"
w = 13.3; h = 9
set style fill solid 0.5 noborder
csv = data."/dyka_stability.csv"
runs = data."/dyka_stability_runs.csv"
stats csv every ::1 using 0 nooutput
methods = STATS_records
stats csv every ::1 using (strstrt(strcol(13), 'held') == 1 ? 1 : 0) nooutput
held = STATS_sum                     # methods whose scan is placed by the held bar's limit
stats csv every ::1 using (strcol(2) eq 'nan' ? 1 : 0) nooutput
none = STATS_sum                     # methods with no stable CFL in the scan at v0
body(c) = strstrt(strcol(c), 'held') == 1 ? ', held bar' : ''
tic(name) = sprintf('%s (%.3f%s)', strcol(name), column(12), body(13))
amplitude_colour(k) = ramp(k, 2)     # v0, v0/100: a sequence of two amplitudes
limits = held == 0 ? "the free bar''s step limit (in brackets: the smaller at rest and with the particles moved 1e-6 h)" : sprintf("the free bar''s step limit (in brackets; the held bar''s for %d methods, so named)", held)
stats csv every ::1 using ($6 / $12) nooutput
top = (STATS_max > 1.05 ? STATS_max : 1.05) + 0.03   # the scan reaches 1.05; the held bar's limit may lie above
cross = "pt 2 ps 1 lw 1.5 lc rgb c_exact"             # stopped_style, smaller: the runs lie 0.005 apart
left = sprintf("set title 'Stable CFLs of the %d methods scanned, as fractions of %s' noenhanced; ", methods, limits).\
  "set ylabel 'CFL / the step limit scanned'; set yrange [0.55:top]; set xrange [-0.7:methods - 0.3]; set xtics rotate by -35 noenhanced; set boxwidth 0.6; ".\
  "set key outside right top vertical Left reverse samplen 1.5; ".\
  "plot csv every ::1 using 0:($2 / $12):xtic(tic(1)) with boxes lc rgb c_context title 'every run at v_0 below the top stable', ".\
  "csv every ::1 using ($0 - 0.3):(1):(0.6):(0) with vectors nohead lw 1.5 lc rgb c_exact title 'the step limit scanned (1)', ".\
  "csv every ::1 using 0:($6 / $12) with points pt 12 ps 1.6 lw 1.5 lc rgb c_exact title 'step limit of the bar held at both ends', ".\
  "runs every ::1 using ($1 - 0.15):(($3 < -1 && $6 == 1) ? $5 : NaN) with points pt 7 ps 0.6 lc rgb amplitude_colour(1) title 'stable run, v_0 = 5 m/s (left)', ".\
  "runs every ::1 using ($1 + 0.15):(($3 > -1 && $6 == 1) ? $5 : NaN) with points pt 7 ps 0.6 lc rgb amplitude_colour(2) title 'stable run, v_0/100 (right)', ".\
  "runs every ::1 using ($1 + ($3 < -1 ? -0.15 : 0.15)):($6 == 0 ? $5 : NaN) with points ".cross." title 'run stopped by the solver'".\
  (none > 0 ? ", csv every ::1 using 0:(strcol(2) eq 'nan' ? 0.575 : NaN) with points pt 11 ps 1.6 lc rgb c_exact title 'no stable CFL in the scan (v_0)'" : "")
stats data.'/dyka_stability_above.csv' using 1 nooutput
last = STATS_records - 1   # the stopped run's last row
right = sprintf("set title 'linear (Q4) + FE at v_0 = 5 m/s, just below and just above its limit: v_A against t' enhanced; set xtics norotate; set xlabel 't (ms)'; set ylabel 'v_A (m/s)'; set xrange [0:20]; set autoscale y; ").\
  "set key outside right top vertical Left reverse; ".\
  sprintf("plot '%s/dyka_stability_below.csv' using ($1*1e3):2 with lines lw 1 lc rgb ramp(1, 2) title 'CFL %s: completes 20 ms', '%s/dyka_stability_above.csv' using ($1*1e3):2 with lines lw 1 lc rgb ramp(2, 2) title 'CFL %s: stopped by the solver', ", data, below, data, above).\
  sprintf("'%s/dyka_stability_above.csv' every ::last::last using ($1*1e3):2 with points %s title 'where it stopped'", data, stopped_style)
stats runs every ::1 using 5 nooutput prefix "F"   # the scan's factors
title = sprintf("Where methods fail on the Dyka bar (40 cells, 20 ms): each method scanned from %.2f to %.2f times its step limit on the %s, at v_0 = 5 m/s and v_0/100", F_min, F_max, held == 0 ? 'free bar' : 'free bar (held bar where named)')
draw = "set multiplot title title; set lmargin at screen 0.06; set rmargin at screen 0.77; set tmargin at screen 0.90; set bmargin at screen 0.50; ".left."; ".\
  "unset xrange; unset yrange; set tmargin at screen 0.34; set bmargin at screen 0.07; ".right."; unset multiplot"
load dir."/output.gp"
