# The authors' code (NL-PartSol 1d5da04) beside this project on the Dyka bar: particle A's velocity v_A(t) of the
# nine cases of tests/authors_table.sh, one column per method (linear + FE, uGIMP + NPC, LME under the authors' beta +
# NPC; their PCE is our NPC). Rows: the histories at 40 cells and at 640 cells, ours (method_style), theirs
# (other_code_style; at 640 cells uGIMP also on their grid extended by 4 cells beyond the free end and a row above and
# below: another run of theirs, other_code_style drawn thick, under ours) and the exact solution at A's reference
# position h/2 (exact_style); each title says whether ours and theirs coincide, with the largest |ours - theirs| / v0
# from authors_table.csv (and, for uGIMP at 640 cells on their own grid, when theirs departs: the first time
# |ours - theirs| > v0 / 2, from the difference history, and the table's RMS gap). Bottom row: the envelope of
# |ours - theirs| / v0 (v0 = 5 m/s), the largest in each 2 µs of their sample times, on the three meshes (the ramp;
# against uGIMP's extended grid in the thick other-code style), on a log axis, with room above 1 for the key.
# Ours: histories/ours_STEM.csv (t, A.v_x, exact_v_x) and histories/difference_STEM.csv (t, dv_over_v0), written by
# `tests/authors_table.sh MPM --histories DIR` (ours on the grid that matches theirs, the run of the table's
# max |dv|/v0); theirs: theirs/nl_partsol_dyka_STEM.csv (t, A.x, A.v_x). STEM is e.g. linear_fe_40, ugimp_pce_640.
# The numbers: data/authors_table.csv (shape, integrator, cells, their_grid, ..., rms_gap_percent, ...,
# max_dv_over_v0, ...).
#   gnuplot -e "dir='verification/plots'; data='results/studies/data'; out='...'" authors_code.gp
#   (optional: histories='...' (default data/authors_code), theirs='...' (default verification/data))
load dir."/common.gp"
if (!exists("histories")) histories = data.'/authors_code'
if (!exists("theirs")) theirs = dir.'/../data'
w = 13.3; h = 10.4
shapes = 'linear ugimp lme_authors'; integrators = 'fe npc npc'; stems = 'linear_fe ugimp_pce lme_pce'
table_shapes = 'linear ugimp lme'                   # the shape keys of authors_table.csv
meshes = '40 160 640'
extended = '640_margin4_rows1'                      # uGIMP at 640 cells on their grid extended
ours(m, cells) = sprintf('%s/ours_%s_%s.csv', histories, word(stems, m), cells)
difference(m, cells) = sprintf('%s/difference_%s_%s.csv', histories, word(stems, m), cells)
their(m, cells) = sprintf('%s/nl_partsol_dyka_%s_%s.csv', theirs, word(stems, m), cells)
method(m) = method_name(word(shapes, m), word(integrators, m)).(word(integrators, m) eq 'npc' ? ' (their PCE)' : '')
# their run on the extended grid: the other code's style, thick
extended_style = 'lw 3.5 '.other_code_style[strstrt(other_code_style, 'dt'):]

# the table's numbers: column col of the row (method m, cells, their grid)
summary = data.'/authors_table.csv'
pick(m, cells, grid, col) = (stats_m = m, stats_cells = cells, stats_grid = grid, stats_col = col, 0)
row_value = "stats summary using (strcol(1) eq word(table_shapes, stats_m) && strcol(3) eq stats_cells && " \
  ."strcol(4) eq stats_grid ? column(stats_col) : NaN) nooutput"
array largest[9]                                    # max |dv| / v0 of method m on mesh k, at 3 (m - 1) + k
do for [m = 1:3] { do for [k = 1:3] {
  dummy = pick(m, word(meshes, k), 'strip', 9); eval(row_value); largest[3 * (m - 1) + k] = STATS_max
} }
dummy = pick(2, '640', 'margin4_rows1', 9); eval(row_value); largest_extended = STATS_max
dummy = pick(2, '640', 'strip', 7); eval(row_value); gap_percent = STATS_max
stats difference(2, '640') using (abs($2) > 0.5 ? 1 : 0) nooutput; departing = STATS_sum > 0
if (departing) { stats difference(2, '640') using (abs($2) > 0.5 ? $1 * 1e6 : NaN) nooutput }
departure = departing ? STATS_min : NaN             # µs: uGIMP at 640 cells, theirs on their own grid
# a number as 9.5·10^{-4}
sci(x) = x >= 0.1 ? sprintf('%.2g', x) : \
  sprintf('%.2g·10^{%d}', x / 10**floor(log10(x) + 1e-9), floor(log10(x) + 1e-9))

# the envelope of |dv| / v0: the largest in each bin of 2 µs, curve c (3 (m - 1) + k, 10 for the extended grid)
bin = 2.0; bins = 100
array envelope[10 * bins]
do for [i = 1:10 * bins] { envelope[i] = 0 }
fill(c) = (stats_offset = (c - 1) * bins, 0)
into_bin = "stats stats_file using (b = int($1 * 1e6 / bin) + 1, (b >= 1 && b <= bins) ? " \
  ."(envelope[stats_offset + b] = abs($2) > envelope[stats_offset + b] ? abs($2) : envelope[stats_offset + b]) " \
  .": 0) nooutput"
do for [m = 1:3] { do for [k = 1:3] {
  dummy = fill(3 * (m - 1) + k); stats_file = difference(m, word(meshes, k)); eval(into_bin)
} }
dummy = fill(10); stats_file = difference(2, extended); eval(into_bin)
peak(c, b) = envelope[(c - 1) * bins + b] > 0 ? envelope[(c - 1) * bins + b] : NaN

every(cells) = int(1.5 * cells)     # a marker every 1.5 cells' worth of steps: about ten on each curve
# (titles joined with `.`: gnuplot's sprintf drops characters when a long format meets UTF-8 arguments)
coincide(m, k) = 'ours and theirs coincide: |v_{ours} − v_{theirs}| ≤ '.sci(largest[3 * (m - 1) + k]).' v_0'
departs = (departing ? sprintf('on their own grid theirs departs after %.0f µs (|Δv| > v_0/2; ', departure) \
  : 'on their own grid (').sprintf('RMS gap %.0f %%);', gap_percent)."\\non their grid extended, ours and theirs coincide: |Δv| ≤ ".sci(largest_extended).' v_0'
history(m, k) = "set title \"".method(m).', '.word(meshes, k)." cells:\\n" \
  .(m == 2 && k == 3 ? departs : coincide(m, k))."\"; set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; " \
  ."unset logscale y; set xrange [0:200]; set yrange [-7.5:12.5]; set ytics -5, 5, 10; set format y '%g'; " \
  ."set key top left; plot " \
  .sprintf("'%s' using ($1 * 1e6):3 with lines %s title 'exact at X_A = h/2', ", ours(m, word(meshes, k)), \
    exact_style) \
  .(m == 2 && k == 3 ? sprintf("'%s' using ($1 * 1e6):3 with linespoints %s pi %d title " \
    ."'theirs (NL-PartSol), their grid extended', ", their(m, extended), extended_style, every(640) + 15) : '') \
  .sprintf("'%s' using ($1 * 1e6):2 with linespoints %s pi %d title 'ours', " \
    ."'%s' using ($1 * 1e6):3 with linespoints %s pi %d title 'theirs (NL-PartSol)'", \
  ours(m, word(meshes, k)), method_style(word(shapes, m), word(integrators, m)), every(word(meshes, k)), \
  their(m, word(meshes, k)), other_code_style, every(word(meshes, k)) + 7)
gap(m) = "set title \"".method(m).":\\nlargest |v_{ours} − v_{theirs}| / v_0 in each ".sprintf('%g', bin)." µs\"; " \
  ."set xlabel 't (µs)'; set ylabel 'max |v_{ours} − v_{theirs}| / v_0'; set xrange [0:200]; " \
  ."set yrange [1e-6:1e3]; set logscale y; set ytics 1e-6, 10, 1; set format y '10^{%T}'; " \
  ."set key top left horizontal ".(m == 2 ? 'maxrows 2 width 1' : 'maxrows 1 width 0')." samplen 2; " \
  .sprintf("plot for [k = 3:1:-1] [b = 1:%d:1] '+' using ((b - 0.5) * bin):(peak(3 * (%d - 1) + k, b)) " \
  ."with lines lw 1.5 lc rgb ramp(k, 3) title word(meshes, k).' cells'", bins, m) \
  .(m == 2 ? sprintf(", [b = 1:%d:1] '+' using ((b - 0.5) * bin):(peak(10, b)) with linespoints %s pi 10 " \
  ."title '640, their grid extended'", bins, extended_style) : '')
panels = ''
do for [k = 1:3:2] { do for [m = 1:3] { panels = panels.history(m, k).'; ' } }
do for [m = 1:3] { panels = panels.gap(m).'; ' }
heading = "The authors' code (NL-PartSol) and ours on the Dyka bar: particle A's velocity, ours on their grid; " \
  ."bottom, the envelope of their difference at their times (the largest in each ".sprintf('%g', bin)." µs)"
draw = "set multiplot layout 3,3 title \"".heading."\"; ".panels."unset multiplot"
load dir."/output.gp"
