# The grid-crossing error isolated (data/smooth_crossing.csv): the vibrating bar on a fixed mesh of 32 cells, CFL 0.5;
# RMS velocity error RMS(v_p - v)/V against the largest displacement over the cell size, U/h (linear axis). One panel
# per integrator (FE, NPC) and particles per cell (1 ppc: filled markers, 2 ppc: open); one curve per shape function
# in its colour (palette.gp): the paper's (linear, uGIMP, LME γ = 3) and today's baselines (B-splines 2 and 3, LME
# γ = 0.8 and 1.5; linear with USL and MUSL in the FE panels). Under each panel a smaller one draws each method's
# error over uGIMP's at the same U/h (log axis, each its own range, the data's): how close the curves that lie on
# each other above are, and where each leaves the others. uGIMP, drawn wide under the others, is the line at 1
# there; a run with no value has no ratio, nor has a U/h where uGIMP has none (that panel's x label then says so).
# The titles name what coincides, every number computed here from the CSV: two curves coincide at a U/h where their
# ratio is within 3 % of 1 (about a line width on these axes), from the smallest U/h on until it first is not (or
# either has no value); FE panels, B-spline 2 on uGIMP (1 ppc), B-spline 3 on LME γ = 1.5 (2 ppc) and USL on MUSL
# (both), each with its largest departure and the last U/h; NPC panels, every shape on uGIMP, grouped by the last
# U/h where it still coincides, with the largest departure of all, and a shape that never coincides with its range
# of ratios over those U/h. Grey dotted: U/h = 1/(2 ppc) (vertical, in both panels, below the strip), where the
# particle next to the free end first reaches a cell face, and a flat field's error (horizontal, about 1/2). Runs
# that stopped (black cross) or ended no better than a flat field (failed, black ring) lie on the strip above the
# data of the upper panel, their method's marker beside them: one strip row per method with such a run, named at
# its left, each run at its U/h; the x axis starts left of 0 where a row's name needs the room. The y tics stop at
# the data's top (none on the strip). One y range for the four upper panels, the data's; the legend below them.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_crossing.gp
load dir."/common.gp"
w = 13.3; h = 14.5
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
x_high = 2.1
# Every run's error (NaN without a value), by series SHAPE/INTEGRATOR/PPC and U/h, read into arrays in one pass.
key(s, i, p) = sprintf('%s/%s/%d', s, i, p)
stats file using (strcol(1) ne 'shape' ? 1 : 0) nooutput
n = int(STATS_sum)
array K[n]; array X[n]; array E[n]
n = 0
stats file using (strcol(1) ne 'shape' ? (n = n + 1, K[n] = key(strcol(1), strcol(2), $3), X[n] = $4, E[n] = (@row_error), 0) : 0) nooutput
at_x(k, x) = sum [j = 1:n] ((K[j] eq k && abs(X[j] - x) <= 1e-9 * abs(x)) ? j : 0)
error_at(k, x) = (at_x(k, x) > 0 ? E[at_x(k, x)] : NaN)
# The reference of the lower panels, uGIMP; a panel is its integrator (USL and MUSL lie in FE's) and its ppc.
reference = 'ugimp'
ref_error(i, p, x) = error_at(key(reference, i, p), x)
# U/h where the reference has no value (a run of its with none), in panel (i, p): none in today's data
ref_missing(i, p) = sum [j = 1:n] ((K[j] eq key(reference, i, p) && E[j] != E[j]) ? 1 : 0)
# a method's error over the reference's, in panel (i, p) (NaN where either has no value)
ratio(s, m, i, p) = error(s, m, p) / ref_error(i, p, $4)
# each lower panel's range: its ratios', a little wider
do for [i in 'fe npc'] { do for [p = 1:2] {
  stats file using ((strcol(1) ne 'shape' && (strcol(2) eq 'npc' ? 'npc' : 'fe') eq i && $3 == p) ? ratio(strcol(1), strcol(2), i, p) : NaN) nooutput
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

# What coincides, computed. `compare` walks series ka at every U/h in order against series kb: dev is the largest
# |ka/kb - 1| from the smallest U/h on while it stays within tol, x_end the last of those U/h (NaN if none), whole 1
# if that covers every U/h of ka. `spread` gives the range [r_low:r_high] of ka/kb over the U/h up to x_max.
tol = 0.03
compare = "dev = 0; x_end = NaN; alive = 1; do for [j = 1:n] { if (K[j] eq ka) { r = E[j] / error_at(kb, X[j]); if (alive && r == r && abs(r - 1) <= tol) { dev = (abs(r - 1) > dev ? abs(r - 1) : dev); x_end = X[j] } else { alive = 0 } } }; whole = alive"
spread = "r_low = NaN; r_high = NaN; do for [j = 1:n] { if (K[j] eq ka && X[j] <= x_max) { r = E[j] / error_at(kb, X[j]); if (r == r) { r_low = (r_low == r_low && r_low < r ? r_low : r); r_high = (r_high == r_high && r_high > r ? r_high : r) } } }"
percent(x) = sprintf('%.1f %%', ceil(1000 * x) / 10.0)  # a departure, rounded up to 0.1 %
signed(r) = sprintf('%+.0f', 100 * (r - 1))
# "A on B (within d %)" with "up to U/h = x" when it does not hold at every U/h
pair_claim(a, b, p) = sprintf("ka = '%s'; kb = '%s'; %s; claim = (x_end != x_end ? '%s and %s differ by more than %g %%' : sprintf('%s on %s (within %%s)%%s', percent(dev), whole ? ' at every U/h' : sprintf(' up to U/h = %%g', x_end)))", \
  key(sh(a), in(a), p), key(sh(b), in(b), p), compare, label_of(a), label_of(b), 100 * tol, label_of(a), label_of(b))
label_of(m) = (in(m) eq 'usl' || in(m) eq 'musl' ? integrator_name(in(m)) : shape_name(sh(m)))
do for [p = 1:2] {
  eval pair_claim(p == 1 ? 'bspline2/fe' : 'bspline3/fe', p == 1 ? 'ugimp/fe' : 'lme1.5/fe', p)
  first = claim
  eval pair_claim('linear/usl', 'linear/musl', p)
  eval sprintf("coincide_fe_%d = first.'\n'.claim.' (both linear)'", p)
}
# NPC: each shape on uGIMP; grouped by its last coinciding U/h (in the order of uGIMP's U/h), the shapes that never
# coincide apart, with their ratios' range up to the last U/h where another still does.
nl = "\n"
add_piece = "text = text.sep.(strstrt(text, nl) == 0 && strlen(text.sep.piece) > 70 ? nl : '').piece; sep = '; '"
do for [p = 1:2] {
  kb = key(reference, 'npc', p); ends = ''; never = ''; worst = 0; x_max = -1
  do for [m in methods('npc')] { if (sh(m) ne reference) {
    ka = key(sh(m), 'npc', p); eval compare
    if (x_end == x_end) { ends = ends.sprintf(' %s=%g', sh(m), x_end); worst = (dev > worst ? dev : worst); x_max = (x_end > x_max ? x_end : x_max) } else { never = never.' '.sh(m) }
  } }
  # the panel's title after its head: the groups that fit on line 1 (70 characters), then line 2
  text = sprintf('within %s of uGIMP up to U/h = ', percent(worst)); sep = ''
  do for [j = 1:n] { if (K[j] eq kb) {
    names = ''
    do for [e in ends] { if (abs(real(e[strstrt(e, '=') + 1:]) - X[j]) <= 1e-9 * X[j]) { names = names.(names eq '' ? '' : ', ').shape_name(e[1:strstrt(e, '=') - 1]) } }
    if (names ne '') { piece = sprintf('%g: %s', X[j], names); eval add_piece }
  } }
  do for [s in never] {
    ka = key(s, 'npc', p); eval spread
    piece = sprintf('%s %s to %s %% up to U/h = %g', shape_name(s), signed(r_low), signed(r_high), x_max); eval add_piece
  }
  eval sprintf("coincide_npc_%d = text", p)
}
coincide(i, p) = value(sprintf('coincide_%s_%d', i, p))
missing(i, p) = (ref_missing(i, p) > 0 ? sprintf('; no ratio at %d U/h: uGIMP has no value there', ref_missing(i, p)) : '')

# The strip: one row per method of a panel with a run there (stopped or failed), named at its left, each run at its
# U/h, its method's marker beside it (to the right). All panels get the rows of the fullest.
do for [i in 'fe npc'] { do for [p = 1:2] {
  list = ''
  do for [m in methods(i)] {
    first = 1e30
    stats file using ((off(sh(m), in(m), p, 'stopped') || off(sh(m), in(m), p, 'failed')) ? (first = ($4 < first ? $4 : first), 1) : 0) nooutput
    if (STATS_sum > 0) { list = list.' '.m; eval sprintf("first_%s_%s_%d = %.12g", sh(m), in(m), p, first) }
  }
  eval sprintf("onstrip_%s_%d = '%s'", i, p, list)
} }
onstrip(i, p) = value(sprintf('onstrip_%s_%d', i, p))
rows = 1
do for [i in 'fe npc'] { do for [p = 1:2] { rows = (words(onstrip(i, p)) > rows ? words(onstrip(i, p)) : rows) } }
row_share = 0.065  # a row's height, as a share of the data's (log) height
strip_top = high * (high / low)**(row_share * rows)
row_y(k) = high * (high / low)**(row_share * (rows - k + 0.5))
rank(m, list) = sum [k = 1:words(list)] (word(list, k) eq m ? k : 0)
row_name(m) = method_name(sh(m), in(m))
# The x axis starts where every row's name (about 7.3 px a character, from graph 0.01) ends left of its first run.
left(c) = (c == 1 ? 0.06 : 0.565); right(c) = (c == 1 ? 0.49 : 0.995)
panel_px = (right(1) - left(1)) * w * 120
x_low = 0
do for [i in 'fe npc'] { do for [p = 1:2] { do for [m in onstrip(i, p)] {
  need = strlen(row_name(m)) * 7.3 + 0.01 * panel_px + 30
  f = value(sprintf('first_%s_%s_%d', sh(m), in(m), p))
  x = (f - need * x_high / panel_px) / (1 - need / panel_px)
  x_low = (x < x_low ? x : x_low)
} } }
beside = 13 * (x_high - x_low) / panel_px  # the method's marker, 13 px right of the cross or ring
do for [i in 'fe npc'] { do for [p = 1:2] {
  list = onstrip(i, p); text = ''
  do for [k = 1:words(list)] { text = text.sprintf("set label %d '%s' at graph 0.01, first %.12g left front; ", 90 + k, row_name(word(list, k)), row_y(k)) }
  if (words(list) == 0) { text = sprintf("set label 91 'every run here ended (none stopped or failed)' at graph 0.01, first %.12g left front; ", row_y((rows + 1) / 2.0)) }
  eval sprintf("names_%s_%d = text", i, p)
} }
unname = ''
do for [k = 1:12] { unname = unname . sprintf('unset label %d; ', 90 + k) }
on_strip(i, p, kind, x, how) = sprintf("for [m in onstrip_%s_%d] file using (off(sh(m), in(m), %d, '%s') ? $4 + %s : NaN):(row_y(rank(m, onstrip_%s_%d))) with points %s", i, p, p, kind, x, i, p, how)
own_marker(p) = sprintf("pt (%d == 1 ? marker(in(m)) : open(marker(in(m)))) ps 1.4 lc rgb colour(sh(m))", p)
strip_runs(i, p) = (words(onstrip(i, p)) == 0 ? '' : ', ' . \
  on_strip(i, p, 'stopped', '0', stopped_style) . ', ' . on_strip(i, p, 'failed', '0', failed_style) . ', ' . \
  on_strip(i, p, 'stopped', 'beside', own_marker(p)) . ', ' . on_strip(i, p, 'failed', 'beside', own_marker(p)))
curves(i, p) = sprintf("for [m in methods('%s')] file using (run(sh(m), in(m), %d) ? $4 : NaN):(error(sh(m), in(m), %d)) with linespoints %s", i, p, p, look('m', p))
ratios(i, p) = sprintf("for [m in methods('%s')] file using (run(sh(m), in(m), %d) ? $4 : NaN):(ratio(sh(m), in(m), '%s', %d)) with linespoints %s", i, p, i, p, look('m', p))
legend = "for [m in methods('npc')] keyentry with lines lw (wide(m) ? 4 : method_lw) lc rgb colour(sh(m)) title label(m), " . \
  "for [m in 'linear/usl linear/musl'] keyentry with linespoints ".look('m', 1)." title label(m), " . \
  sprintf("keyentry with linespoints lw %g dt %d pt %d lc rgb '%s' title 'FE: solid, circles', ", method_lw, dash('fe'), marker('fe'), c_exact) . \
  sprintf("keyentry with linespoints lw %g dt %d pt %d lc rgb '%s' title 'NPC: dashed, squares', ", method_lw, dash('npc'), marker('npc'), c_exact) . \
  sprintf("keyentry with points pt %d lc rgb '%s' title '2 ppc: open markers', ", open(marker('fe')), c_exact) . \
  "keyentry with lines ".reference_style." title 'vertical: U/h = 1/(2 ppc), a face reached', keyentry with lines ".reference_style." title 'horizontal: a flat field’s error', " . \
  "keyentry with points ".stopped_style." title 'stopped (its method’s marker beside)', keyentry with points ".failed_style." title 'failed: no better than a flat field'"
# Panel (i, p) in column c, row r: the data above, the ratios below; positions in screen fractions.
upper_top(r) = (r == 1 ? 0.935 : lower_bottom(1) - 0.067); upper_bottom(r) = upper_top(r) - 0.25
lower_top(r) = upper_bottom(r) - 0.007; lower_bottom(r) = lower_top(r) - 0.12
place(c, top, bottom) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set tmargin at screen %g; set bmargin at screen %g; ", left(c), right(c), top, bottom)
decades = sprintf("set ytics %.12g, 10, %.12g; ", 10**floor(log10(low)), high)  # tics up to the data's top, none on the strip
# the grey dotted vertical at U/h = 1/(2 ppc), up to `top` (the data's top in the upper panel: not across the strip)
guide(p, top) = sprintf("set arrow 1 from %g, graph 0 to %g, %s nohead %s; ", 0.5 / p, 0.5 / p, top, reference_style)
panel(i, p, c, r) = place(c, upper_top(r), upper_bottom(r)) . \
  "set title '" . sprintf('%s, %d particle%s per cell: ', integrator_name(i), p, p > 1 ? 's' : '') . coincide(i, p) . "'; " . guide(p, sprintf('first %.12g', high)) . \
  "set format x ''; unset xlabel; set ylabel 'RMS(v_p - v) / V'; set format y '10^{%L}'; " . decades . unname . \
  sprintf("set yrange [%.12g:%.12g]; ", low, strip_top) . strip_common(high, strip_top, high, '') . value(sprintf('names_%s_%d', i, p)) . \
  sprintf("plot %g with lines %s, %s", flat, reference_style, curves(i, p)) . strip_runs(i, p) . "; " . \
  place(c, lower_top(r), lower_bottom(r)) . unstrip . unname . guide(p, 'graph 1') . "unset title; set format x '%g'; set xlabel 'U / h (largest displacement / cell size)".missing(i, p)."'; " . \
  sprintf("set ylabel 'error / uGIMP’s'; set format y '%%g'; set ytics %s; set yrange %s; ", value(sprintf('ratio_tics_%s_%d', i, p)), value(sprintf('ratio_range_%s_%d', i, p))) . \
  "plot " . ratios(i, p)
# The legend: a last panel across the bottom, no axes, its entries only (keyentry; -1 lies outside its range).
legend_panel = "set lmargin at screen 0.02; set rmargin at screen 0.99; set bmargin at screen 0.003; set tmargin at screen 0.06; unset logscale y; unset border; unset tics; unset grid; " . \
  "unset arrow 1; unset title; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; " . unstrip . unname . "set key inside left top vertical Left reverse samplen 3 maxrows 4 width -6; plot -1, " . legend
draw = "set border; set tics; set grid; set key off; " . \
  "set multiplot title 'Grid crossing isolated: vibrating bar, 32 cells, CFL 0.5; RMS velocity error against U/h, one colour per shape function; under each panel, each error over uGIMP’s at the same U/h'; " . \
  sprintf("set logscale y; set xrange [%.12g:%g]; set xtics 0, 0.25; ", x_low, x_high) . \
  panel('fe', 1, 1, 1) . "; " . panel('npc', 1, 2, 1) . "; " . panel('fe', 2, 1, 2) . "; " . panel('npc', 2, 2, 2) . "; " . legend_panel . "; unset multiplot; set border; set tics; set grid"
load dir."/output.gp"
