# The grid-crossing error isolated (data/smooth_crossing.csv): the vibrating bar on a fixed mesh of 32 cells, CFL 0.5;
# RMS velocity error RMS(v_p - v)/V against the largest displacement over the cell size, U/h (linear axis). One panel
# per integrator (FE, NPC) and particles per cell (1 ppc: filled markers, 2 ppc: open); one curve per shape function
# in its colour (palette.gp): the paper's (linear, uGIMP, LME γ = 3) and today's baselines (B-splines 2 and 3, LME
# γ = 0.8 and 1.5; linear with USL and MUSL in the FE panels). uGIMP is drawn wide, under the others: at 1 ppc
# B-spline 2 lies on it (up to U/h = 1), and with NPC every method keeps the same error (0.015) up to its onset, as the
# titles say. Grey dotted: U/h = 1/(2 ppc) (vertical), where the particle next to the free end first reaches a cell
# face, and a flat field's error (horizontal, about 1/2). Runs that stopped (black cross) or ended no better than a
# flat field (failed, black ring) lie on the strip above the data, their method's marker inside, each method of a
# panel at its own height there. One y range for all panels, the data's; the legend below them.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_crossing.gp
load dir."/common.gp"
w = 13.3; h = 10
file = data.'/smooth_crossing.csv'
# columns: 1 shape, 2 integrator, 3 ppc, 4 U/h, 5 velocity error, 7 status (ok, or failed: stopped), 12 a flat
# field's velocity error, 13 ending (done, failed, stopped)
run(s, i, p) = (strcol(1) eq s && strcol(2) eq i && $3 == p)
done(s, i, p) = (run(s, i, p) && strcol(7) eq 'ok' && strcol(13) eq 'done')
# the error of a run that ended (done) and NaN otherwise, which breaks its line (not $5: a row whose $5 is nan is
# skipped, and the line would join its neighbours across it)
error(s, i, p) = (done(s, i, p) ? real(strcol(5)) : NaN)
off(s, i, p, kind) = (run(s, i, p) && (kind eq 'stopped' ? strcol(7) ne 'ok' : strcol(7) eq 'ok' && strcol(13) eq 'failed'))
stats file using (strcol(13) eq 'done' ? $5 : NaN) nooutput
low = STATS_min / 1.5; top = STATS_max
stats file using 12 nooutput
flat = STATS_max; high = (flat > top ? flat : top) * 1.5
# A method is SHAPE/INTEGRATOR; uGIMP first, so that the others lie over its wide line.
methods(i) = sprintf('ugimp/%s linear/%s lme/%s bspline2/%s bspline3/%s lme0.8/%s lme1.5/%s', i, i, i, i, i, i, i).(i eq 'fe' ? ' linear/usl linear/musl' : '')
sh(m) = m[1:strstrt(m, '/') - 1]
in(m) = m[strstrt(m, '/') + 1:]
wide(m) = (sh(m) eq 'ugimp')
label(m) = (in(m) eq 'usl' || in(m) eq 'musl' ? method_name(sh(m), in(m)) : shape_name(sh(m)).(wide(m) ? ' (wide)' : ''))
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
legend = "for [m in methods('npc')] keyentry with lines lw (wide(m) ? 4 : method_lw) lc rgb colour(sh(m)) title label(m), " . \
  "for [m in 'linear/usl linear/musl'] keyentry with linespoints ".look('m', 1)." title label(m), " . \
  sprintf("keyentry with linespoints lw %g dt %d pt %d lc rgb '%s' title 'FE: solid, circles', ", method_lw, dash('fe'), marker('fe'), c_exact) . \
  sprintf("keyentry with linespoints lw %g dt %d pt %d lc rgb '%s' title 'NPC: dashed, squares', ", method_lw, dash('npc'), marker('npc'), c_exact) . \
  sprintf("keyentry with points pt %d lc rgb '%s' title '2 ppc: open markers', ", open(marker('fe')), c_exact) . \
  "keyentry with lines ".reference_style." title 'vertical: U/h = 1/(2 ppc), a face reached', keyentry with lines ".reference_style." title 'horizontal: a flat field’s error', " . \
  "keyentry with points ".stopped_style." title 'stopped (its method’s marker inside)', keyentry with points ".failed_style." title 'failed: no better than a flat field (likewise)'"
coincide(i, p) = (i eq 'npc' ? (p == 1 ? 'all but LME γ = 0.8 at 0.015 until each leaves' : 'all but linear within 8 % up to U/h = 1') : p == 1 ? 'B-spline 2 lies on uGIMP up to U/h = 1' : 'B-spline 3, LME γ = 0.8 and 1.5 within 25 %')
panel(i, p) = sprintf("set title '%s, %d particle%s per cell: %s'; set arrow 1 from %g, graph 0 to %g, graph 1 nohead %s; ", integrator_name(i), p, p > 1 ? 's' : '', coincide(i, p), 0.5 / p, 0.5 / p, reference_style) . \
  strip_log(low, high, '') . sprintf("plot %g with lines %s, %s", flat, reference_style, curves(i, p)) . strip_runs(i, p)
# The legend: a last panel across the bottom, no axes, its entries only (keyentry; -1 lies outside its range).
legend_panel = "set lmargin at screen 0.02; set rmargin at screen 0.99; set bmargin at screen 0.005; set tmargin at screen 0.14; unset logscale y; unset border; unset tics; unset grid; " . \
  "unset arrow 1; unset title; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; " . unstrip . "set key inside left top horizontal Left reverse samplen 3 maxcols 5; plot -1, " . legend
draw = "set border; set tics; set grid; set lmargin -1; set rmargin -1; set bmargin -1; set tmargin -1; set key off; " . \
  "set multiplot layout 2,2 title 'Grid crossing isolated: vibrating bar, 32 cells, CFL 0.5; RMS velocity error against U/h, one colour per shape function' margins 0.06, 0.99, 0.2, 0.935 spacing 0.06, 0.1; " . \
  "set logscale y; set format y '10^{%L}'; set xrange [0:2.1]; set xtics 0.25; set xlabel 'U / h (largest displacement / cell size)'; set ylabel 'RMS(v_p - v) / V'; " . \
  panel('fe', 1) . "; " . panel('npc', 1) . "; " . panel('fe', 2) . "; " . panel('npc', 2) . "; " . legend_panel . "; unset multiplot; set border; set tics; set grid"
load dir."/output.gp"
