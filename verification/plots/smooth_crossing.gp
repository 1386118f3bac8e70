# The grid-crossing error isolated (data/smooth_crossing.csv): the vibrating bar on a fixed mesh of 32 cells, CFL 0.5;
# RMS velocity error RMS(v_p - v)/V against the largest displacement over the cell size, U/h (linear axis). One panel
# per integrator (FE, NPC) and particles per cell (1 ppc: filled markers, 2 ppc: open); one curve per shape function
# in its colour (palette.gp): the paper's (linear, uGIMP, LME γ = 3) and today's baselines (B-splines 2 and 3, LME
# γ = 0.8 and 1.5; linear with USL and MUSL in the FE panels). Under each panel a smaller one draws each method's
# error over uGIMP's at the same U/h (log axis, each its own range, the data's): how close the curves that lie on
# each other above are, and where each leaves the others. uGIMP, drawn wide under the others, is the line at 1
# there; a run with no value has no ratio, nor has a U/h where uGIMP has none (that panel's x label then says so).
# The titles name what coincides, as the data have it: FE at 1 ppc, B-spline 2 on uGIMP (within 2 %) and USL on
# MUSL up to U/h = 0.4; NPC at 1 ppc, all but LME γ = 0.8 (15 % above) at 0.015 until each leaves; FE at 2 ppc,
# B-spline 3 on LME γ = 1.5 (within 7 %) and USL on MUSL to U/h = 0.2; NPC at 2 ppc, all but linear within 7 % of
# uGIMP up to U/h = 1. Grey dotted: U/h = 1/(2 ppc) (vertical, in both panels), where the particle next to the free
# end first reaches a cell face, and a flat field's error (horizontal, about 1/2). Runs that stopped (black cross)
# or ended no better than a flat field (failed, black ring) lie on the strip above the data of the upper panel,
# their method's marker inside, each method of a panel at its own height there. One y range for the four upper
# panels, the data's; the legend below them.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_crossing.gp
load dir."/common.gp"
w = 13.3; h = 12.5
file = data.'/smooth_crossing.csv'
# columns: 1 shape, 2 integrator, 3 ppc, 4 U/h, 5 velocity error, 7 status (ok, or failed: stopped), 12 a flat
# field's velocity error, 13 ending (done, failed, stopped)
run(s, i, p) = (strcol(1) eq s && strcol(2) eq i && $3 == p)
# the row's error if its run ended (done) and NaN otherwise, which breaks its line (not $5: a row whose $5 is nan is
# skipped, and the line would join its neighbours across it)
row_error = 'strcol(7) eq "ok" && strcol(13) eq "done" ? real(strcol(5)) : NaN'
error(s, i, p) = (run(s, i, p) ? @row_error : NaN)
off(s, i, p, kind) = (run(s, i, p) && (kind eq 'stopped' ? strcol(7) ne 'ok' : strcol(7) eq 'ok' && strcol(13) eq 'failed'))
stats file using (strcol(13) eq 'done' ? $5 : NaN) nooutput
low = STATS_min / 1.5; top = STATS_max
stats file using 12 nooutput
flat = STATS_max; high = (flat > top ? flat : top) * 1.5
# The reference of the lower panels: uGIMP's error at each (panel, U/h), read into arrays in one stats pass; a
# panel is its integrator (USL and MUSL lie in FE's) and its ppc.
reference = 'ugimp'
panel_of(i) = (i eq 'npc' ? 'npc' : 'fe')
key(i, p) = sprintf('%s %d', i, p)
stats file using (strcol(1) eq reference ? 1 : 0) nooutput
array ref_key[int(STATS_sum)]; array ref_x[int(STATS_sum)]; array ref_e[int(STATS_sum)]
n_ref = 0
stats file using (strcol(1) eq reference ? (n_ref = n_ref + 1, ref_key[n_ref] = key(strcol(2), $3), ref_x[n_ref] = $4, \
  ref_e[n_ref] = (@row_error), 0) : 0) nooutput
ref_index(i, p, x) = sum [k = 1:n_ref] ((ref_key[k] eq key(i, p) && abs(ref_x[k] - x) <= 1e-9 * abs(x)) ? k : 0)
ref_error(i, p, x) = (ref_index(i, p, x) > 0 ? ref_e[ref_index(i, p, x)] : NaN)
# U/h where the reference has no value (a run of its with none, or no run), in panel (i, p): none in today's data
ref_missing(i, p) = sum [k = 1:n_ref] ((ref_key[k] eq key(i, p) && ref_e[k] != ref_e[k]) ? 1 : 0)
# a method's error over the reference's, in panel (i, p) (NaN where either has no value)
ratio(s, m, i, p) = error(s, m, p) / ref_error(i, p, $4)
# each lower panel's range: its ratios', a little wider
do for [i in 'fe npc'] { do for [p = 1:2] {
  stats file using ((panel_of(strcol(2)) eq i && $3 == p) ? ratio(strcol(1), strcol(2), i, p) : NaN) nooutput
  eval sprintf("ratio_range_%s_%d = '[%.6g:%.6g]'", i, p, STATS_min / 1.25, STATS_max * 1.25)
  eval sprintf("ratio_tics_%s_%d = '%s'", i, p, STATS_max / STATS_min < 30 ? '(0.5, 1, 2, 5, 10, 20)' : '(0.01, 0.03, 0.1, 0.3, 1, 3, 10, 30, 100)')
} }
# A method is SHAPE/INTEGRATOR; uGIMP first, so that the others lie over its wide line.
methods(i) = sprintf('ugimp/%s linear/%s lme/%s bspline2/%s bspline3/%s lme0.8/%s lme1.5/%s', i, i, i, i, i, i, i).(i eq 'fe' ? ' linear/usl linear/musl' : '')
sh(m) = m[1:strstrt(m, '/') - 1]
in(m) = m[strstrt(m, '/') + 1:]
wide(m) = (sh(m) eq 'ugimp')
label(m) = (in(m) eq 'usl' || in(m) eq 'musl' ? method_name(sh(m), in(m)) : shape_name(sh(m)).(wide(m) ? ' (wide; the line at 1 below)' : ''))
look(m, p) = sprintf("lw (wide(m) ? 4 : method_lw) dt dash(in(m)) pt (%d == 1 ? marker(in(m)) : open(marker(in(m)))) ps (wide(m) ? 1.9 : 1) lc rgb colour(sh(m))", p)
# The methods of panel (i, p) with a run on the strip, each at its own height there (by its rank in the panel's
# list), every other one a little to the right.
do for [i in 'fe npc'] { do for [p = 1:2] {
  list = ''
  do for [m in methods(i)] {
    stats file using ((off(sh(m), in(m), p, 'stopped') || off(sh(m), in(m), p, 'failed')) ? 1 : 0) nooutput
    if (STATS_sum > 0) { list = list.' '.m }
  }
  eval sprintf("onstrip_%s_%d = '%s'", i, p, list)
} }
rank(m, list) = sum [k = 1:words(list)] (word(list, k) eq m ? k : 0)
dx(m, list) = (rank(m, list) % 2 ? -0.025 : 0.025) * (words(list) > 1)
sy(m, list) = strip_y_log(low, high) * (high / low)**(0.12 * ((rank(m, list) - 0.5) / words(list) - 0.5))
on_strip(i, p, kind, how) = sprintf("for [m in onstrip_%s_%d] file using (off(sh(m), in(m), %d, '%s') ? $4 + dx(m, onstrip_%s_%d) : NaN):(sy(m, onstrip_%s_%d)) with points %s", i, p, p, kind, i, p, i, p, how)
strip_runs(i, p) = (words(value(sprintf('onstrip_%s_%d', i, p))) == 0 ? '' : ', ' . \
  on_strip(i, p, 'stopped', stopped_style) . ', ' . on_strip(i, p, 'failed', failed_style) . ', ' . \
  on_strip(i, p, 'stopped', sprintf("pt (%d == 1 ? marker(in(m)) : open(marker(in(m)))) ps 1.2 lc rgb colour(sh(m))", p)) . ', ' . \
  on_strip(i, p, 'failed', sprintf("pt (%d == 1 ? marker(in(m)) : open(marker(in(m)))) ps 1.2 lc rgb colour(sh(m))", p)))
curves(i, p) = sprintf("for [m in methods('%s')] file using (run(sh(m), in(m), %d) ? $4 : NaN):(error(sh(m), in(m), %d)) with linespoints %s", i, p, p, look('m', p))
ratios(i, p) = sprintf("for [m in methods('%s')] file using (run(sh(m), in(m), %d) ? $4 : NaN):(ratio(sh(m), in(m), '%s', %d)) with linespoints %s", i, p, i, p, look('m', p))
legend = "for [m in methods('npc')] keyentry with lines lw (wide(m) ? 4 : method_lw) lc rgb colour(sh(m)) title label(m), " . \
  "for [m in 'linear/usl linear/musl'] keyentry with linespoints ".look('m', 1)." title label(m), " . \
  sprintf("keyentry with linespoints lw %g dt %d pt %d lc rgb '%s' title 'FE: solid, circles', ", method_lw, dash('fe'), marker('fe'), c_exact) . \
  sprintf("keyentry with linespoints lw %g dt %d pt %d lc rgb '%s' title 'NPC: dashed, squares', ", method_lw, dash('npc'), marker('npc'), c_exact) . \
  sprintf("keyentry with points pt %d lc rgb '%s' title '2 ppc: open markers', ", open(marker('fe')), c_exact) . \
  "keyentry with lines ".reference_style." title 'vertical: U/h = 1/(2 ppc), a face reached', keyentry with lines ".reference_style." title 'horizontal: a flat field’s error', " . \
  "keyentry with points ".stopped_style." title 'stopped (its method’s marker inside)', keyentry with points ".failed_style." title 'failed: no better than a flat field (likewise)'"
coincide(i, p) = (i eq 'npc' ? (p == 1 ? 'all but LME γ = 0.8 (+15 %) within 1.5 % of 0.015 until each leaves' : 'all but linear within 7 % of uGIMP up to U/h = 1') : \
  p == 1 ? 'B-spline 2 on uGIMP (within 2 %); USL on MUSL up to U/h = 0.4' : 'B-spline 3 on LME γ = 1.5 (within 7 %); USL on MUSL to U/h = 0.2')
missing(i, p) = (ref_missing(i, p) > 0 ? sprintf('; no ratio at %d U/h: uGIMP has no value there', ref_missing(i, p)) : '')
# Panel (i, p) in column c, row r: the data above, the ratios below; positions in screen fractions.
left(c) = (c == 1 ? 0.06 : 0.565); right(c) = (c == 1 ? 0.49 : 0.995)
upper_top(r) = (r == 1 ? 0.94 : 0.505); upper_bottom(r) = upper_top(r) - 0.22
lower_top(r) = upper_bottom(r) - 0.008; lower_bottom(r) = lower_top(r) - 0.14
place(c, top, bottom) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set tmargin at screen %g; set bmargin at screen %g; ", left(c), right(c), top, bottom)
panel(i, p, c, r) = place(c, upper_top(r), upper_bottom(r)) . \
  sprintf("set title '%s, %d particle%s per cell: %s'; set arrow 1 from %g, graph 0 to %g, graph 1 nohead %s; ", integrator_name(i), p, p > 1 ? 's' : '', coincide(i, p), 0.5 / p, 0.5 / p, reference_style) . \
  "set format x ''; unset xlabel; set ylabel 'RMS(v_p - v) / V'; set format y '10^{%L}'; set ytics autofreq; " . \
  strip_log(low, high, '') . sprintf("plot %g with lines %s, %s", flat, reference_style, curves(i, p)) . strip_runs(i, p) . "; " . \
  place(c, lower_top(r), lower_bottom(r)) . unstrip . "unset title; set format x '%g'; set xlabel 'U / h (largest displacement / cell size)".missing(i, p)."'; " . \
  sprintf("set ylabel 'error / uGIMP’s'; set format y '%%g'; set ytics %s; set yrange %s; ", value(sprintf('ratio_tics_%s_%d', i, p)), value(sprintf('ratio_range_%s_%d', i, p))) . \
  "plot " . ratios(i, p)
# The legend: a last panel across the bottom, no axes, its entries only (keyentry; -1 lies outside its range).
legend_panel = "set lmargin at screen 0.02; set rmargin at screen 0.99; set bmargin at screen 0.005; set tmargin at screen 0.085; unset logscale y; unset border; unset tics; unset grid; " . \
  "unset arrow 1; unset title; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; " . unstrip . "set key inside left top vertical Left reverse samplen 3 maxrows 4 width -14; plot -1, " . legend
draw = "set border; set tics; set grid; set key off; " . \
  "set multiplot title 'Grid crossing isolated: vibrating bar, 32 cells, CFL 0.5; RMS velocity error against U/h, one colour per shape function; under each panel, each error over uGIMP’s at the same U/h'; " . \
  "set logscale y; set xrange [0:2.1]; set xtics 0.25; " . \
  panel('fe', 1, 1, 1) . "; " . panel('npc', 1, 2, 1) . "; " . panel('fe', 2, 1, 2) . "; " . panel('npc', 2, 2, 2) . "; " . legend_panel . "; unset multiplot; set border; set tics; set grid"
load dir."/output.gp"
