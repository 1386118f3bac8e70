# The vibrating bar (data/smooth_bar.csv), at the amplitude `amplitude` (small: against the exact first mode; large:
# against the finite-strain reference): RMS error of the velocity (rows 1 and 3) and of the stress (rows 2 and 4)
# against the number of cells. One panel per shape function, in its colour (palette.gp): the paper's (linear, uGIMP,
# LME γ = 3; rows 1-2) and today's baselines at CFL 0.5 (B-splines 2 and 3, linear with USL and MUSL; rows 3-4). In a
# panel the integrator is the dash and the marker (FE solid with circles, NPC dashed with squares, USL and MUSL with
# triangles); 1 particle per cell filled markers, 2 open ones, drawn larger so that a filled one on the same value
# shows inside; at small amplitude the paper's shapes also at CFL 0.1, thin lines with small markers (CFL 0.5: the
# usual lines). Grey dotted: slopes 1 and 2, and the line at 1 of a ratio panel.
# At small amplitude, where twin runs lie on each other, a ratio panel under each panel draws one twin over the
# other at each mesh (log axis, the range of its ratios): 2 ppc over 1 ppc (velocity of the paper's shapes, both
# rows of the B-splines; open markers, each integrator at each CFL), CFL 0.1 over CFL 0.5 (stress of the paper's
# shapes; thin lines, each integrator at 1 and 2 ppc), MUSL over USL (at 1 and 2 ppc). Its title gives, for each
# ratio, the largest departure from 1 over the meshes from the finest down while it stays within 7 % (about a line
# width on these axes), and the coarsest of those meshes when it is not the coarsest run ("apart" when not even the
# finest is within); the uGIMP panels' titles give uGIMP's largest departure from linear's numbers; every number
# computed here from the CSV. At large amplitude, where twins lie on each other at the coarse meshes, the ratio panel
# draws 2 ppc over 1 ppc for each integrator (open markers) and the second integrator over the first at 1 ppc (NPC
# over FE, MUSL over USL; filled markers); its title gives, for each ratio, the largest departure from 1 over its
# longest stretch of meshes within 7 % and those meshes, or "apart" with the ratio's range, or "no pair" (no mesh where
# both ended, not drawn); a panel with no pair at all says so.
# A run that stopped (black cross) or ended no better than a flat field (failed, black ring) lies on the strip above
# the data, its method's marker beside it (right), at its mesh: the strip has one row per series of the panel (from
# the top: the first integrator at 1 and 2 ppc, then the second), each row with a run named at its left ("FE,
# 1 ppc"); no y tic on the strip. The velocity rows share one y range, the stress rows another, each the range of
# its data; the legend lies below the panels.
# gnuplot -e "dir='...'; data='...'; out='...'; amplitude='small|large'; caption='...'" smooth_bar.gp
load dir."/common.gp"
w = 13.3
sweep = data.'/smooth_bar.csv'
small = (amplitude eq 'small')
# columns: 1 amplitude, 2 shape, 3 integrator, 4 ppc, 5 CFL, 6 cells, 7 velocity error, 8 stress error, 12 status (ok,
# or failed: stopped), 18 ending (done, failed, stopped)
mine(s, i, p, c) = (strcol(1) eq amplitude && strcol(2) eq s && strcol(3) eq i && $4 == p && abs($5 - c) < 1e-9)
done(s, i, p, c) = (mine(s, i, p, c) && strcol(12) eq 'ok' && strcol(18) eq 'done')
# the error of a run that ended (done), NaN otherwise, which breaks its line (a row whose column is nan is skipped)
error(s, i, p, c, col) = (done(s, i, p, c) ? real(strcol(col)) : NaN)
off(s, i, p, kind) = (mine(s, i, p, 0.5) && (kind eq 'stopped' ? strcol(12) ne 'ok' : strcol(12) eq 'ok' && strcol(18) eq 'failed'))
stats sweep using (strcol(1) eq amplitude && strcol(18) eq 'done' ? $7 : NaN) nooutput
vlow = STATS_min / 1.6; vhigh = STATS_max * 1.6
stats sweep using (strcol(1) eq amplitude && strcol(18) eq 'done' ? $8 : NaN) nooutput
slow = STATS_min / 1.6; shigh = STATS_max * 1.6
stats sweep using (strcol(1) eq amplitude && strcol(18) ne 'done' ? 1 : 0) nooutput
outcomes = STATS_sum  # runs on the strip
stats sweep using (strcol(1) eq amplitude && strcol(12) ne 'ok' ? 1 : 0) nooutput
stops = STATS_sum
stats sweep using (strcol(1) eq amplitude && strcol(18) eq 'failed' ? 1 : 0) nooutput
fails = STATS_sum
stats sweep using (strcol(1) eq amplitude ? $6 : NaN) nooutput
xhigh = STATS_max * 1.5
xlow = STATS_min / (outcomes > 0 ? 3.3 : 1.5)  # room at the left of the strip for its rows' names
# A method's look: its shape's colour, its integrator's dash and marker; 2 ppc open and larger; CFL 0.1 thin, small.
cfls(s, i) = (small && (i eq 'fe' || i eq 'npc') && s ne 'bspline2' && s ne 'bspline3' ? '0.5 0.1' : '0.5')
curves(s, i, col) = sprintf("for [p = 2:1:-1] for [c in '%s'] sweep using (mine('%s', '%s', p, real(c)) ? $6 : NaN):(error('%s', '%s', p, real(c), %d)) with linespoints lw (real(c) > 0.3 ? method_lw : 0.8) dt %d pt (p == 1 ? %d : %d) ps ((real(c) > 0.3 ? 1 : 0.6) * (p == 2 ? 1.5 : 1)) lc rgb '%s'", \
  cfls(s, i), s, i, s, i, col, dash(i), marker(i), open(marker(i)), colour(s))

# Every run of this amplitude by series SHAPE/INTEGRATOR/PPC/CFL and mesh, its errors (NaN without a value), in arrays.
series_key(s, i, p, c) = sprintf('%s/%s/%d/%g', s, i, p, c)
row_key(dummy) = series_key(strcol(2), strcol(3), $4, $5)  # the series of the row being read
stats sweep using (strcol(1) eq amplitude ? 1 : 0) nooutput
n = int(STATS_sum)
array K[n]; array C[n]; array V[n]; array S[n]
n = 0
stats sweep using (strcol(1) eq amplitude ? (n = n + 1, K[n] = row_key(0), C[n] = $6, V[n] = (strcol(12) eq 'ok' && strcol(18) eq 'done' ? $7 : NaN), \
  S[n] = (strcol(12) eq 'ok' && strcol(18) eq 'done' ? $8 : NaN), 0) : 0) nooutput
at_mesh(k, m) = sum [j = 1:n] ((K[j] eq k && C[j] == m) ? j : 0)
value_at(k, m, col) = (at_mesh(k, m) > 0 ? (col == 7 ? V[at_mesh(k, m)] : S[at_mesh(k, m)]) : NaN)
# fields of a series key: 1 shape, 2 integrator, 3 ppc, 4 CFL
head(k) = (strstrt(k, '/') > 0 ? k[1:strstrt(k, '/') - 1] : k)
field(k, f) = (f == 1 ? head(k) : field(k[strstrt(k, '/') + 1:], f - 1))

# The ratio panels: a ratio is NUMERATOR>DENOMINATOR (series keys); a panel's ratios, grouped (one title line a
# group), by its rule. Small amplitude: ppc (2 over 1 ppc, a group per CFL), cfl (CFL 0.1 over 0.5, a group per
# ppc), musl (MUSL over USL, one group). Large amplitude, twins: 2 over 1 ppc for each integrator (group ppc), the
# second integrator over the first at 1 ppc (group pair).
rule(s, i1, col) = (!small ? 'twins' : i1 eq 'usl' ? 'musl' : (col == 8 && cfls(s, i1) eq '0.5 0.1') ? 'cfl' : 'ppc')
rule_name(r) = (r eq 'ppc' ? '2 ppc / 1 ppc' : r eq 'cfl' ? 'CFL 0.1 / CFL 0.5' : r eq 'musl' ? 'MUSL / USL' : 'twin / twin')
groups(s, i1, col) = (rule(s, i1, col) eq 'ppc' ? cfls(s, i1) : rule(s, i1, col) eq 'cfl' ? '1 2' : rule(s, i1, col) eq 'twins' ? 'ppc pair' : 'all')
group_name(r, g, s, i1) = (r eq 'ppc' ? (cfls(s, i1) eq '0.5' ? '' : 'at CFL '.g) : r eq 'cfl' ? 'at '.g.' ppc' : '')
# a group's title line starts with its lead
lead(r, g, s, i1, i2, first) = (r eq 'twins' ? (g eq 'ppc' ? '2 ppc / 1 ppc' : integrator_name(i2).' / '.integrator_name(i1).' at 1 ppc') : \
  (first ? rule_name(r).(group_name(r, g, s, i1) eq '' ? '' : ' ') : '').group_name(r, g, s, i1)).': '
ratios_of(s, i1, i2, col, g) = (rule(s, i1, col) eq 'twins' ? (g eq 'ppc' ? sprintf('%s>%s %s>%s', series_key(s, i1, 2, 0.5), series_key(s, i1, 1, 0.5), series_key(s, i2, 2, 0.5), series_key(s, i2, 1, 0.5)) : \
  sprintf('%s>%s', series_key(s, i2, 1, 0.5), series_key(s, i1, 1, 0.5))) : rule(s, i1, col) eq 'ppc' ? sprintf('%s>%s %s>%s', series_key(s, i1, 2, real(g)), series_key(s, i1, 1, real(g)), series_key(s, i2, 2, real(g)), series_key(s, i2, 1, real(g))) : \
  rule(s, i1, col) eq 'cfl' ? sprintf('%s>%s %s>%s', series_key(s, i1, int(g), 0.1), series_key(s, i1, int(g), 0.5), series_key(s, i2, int(g), 0.1), series_key(s, i2, int(g), 0.5)) : \
  sprintf('%s>%s %s>%s', series_key(s, 'musl', 1, 0.5), series_key(s, 'usl', 1, 0.5), series_key(s, 'musl', 2, 0.5), series_key(s, 'usl', 2, 0.5)))
numerator(q) = q[1:strstrt(q, '>') - 1]
denominator(q) = q[strstrt(q, '>') + 1:]
# a ratio's name in its group line: the integrator (cfl, ppc rules, twins' ppc group) or the ppc (musl rule); none
# for the twins' pair, named by its line's lead
item_name(r, q) = (r eq 'musl' ? field(numerator(q), 3).' ppc' : r eq 'twins' && field(numerator(q), 2) ne field(denominator(q), 2) ? '' : integrator_name(field(numerator(q), 2)))
# The walk over a ratio q's meshes in order (col, tol set): r_min, r_max its range (kept over a panel), valid its
# meshes with a ratio, q_min and q_max its own range. Small amplitude: from the mesh where its last stretch within tol
# starts (NaN if the finest is not within), dev its largest departure there, count its meshes, coarsest the coarsest
# mesh with a value. Large amplitude: its longest stretch within tol (the coarsest first), best_from to best_to,
# best_n meshes, best_dev its largest departure there.
tol = 0.07
walk = "from = NaN; dev = 0; count = 0; coarsest = NaN; valid = 0; q_min = NaN; q_max = NaN; best_n = 0; best_dev = 0; best_from = NaN; best_to = NaN; " . \
  "ka = numerator(q); kb = denominator(q); do for [j = 1:n] { if (K[j] eq ka) { " . \
  "r = (col == 7 ? V[j] : S[j]) / value_at(kb, C[j], col); if (r == r) { valid = valid + 1; coarsest = (coarsest == coarsest ? coarsest : C[j]); r_min = (r < r_min ? r : r_min); r_max = (r > r_max ? r : r_max); " . \
  "q_min = (q_min == q_min && q_min < r ? q_min : r); q_max = (q_max == q_max && q_max > r ? q_max : r) }; " . \
  "if (r == r && abs(r - 1) <= tol) { if (from != from) { from = C[j]; dev = 0; count = 0 }; dev = (abs(r - 1) > dev ? abs(r - 1) : dev); count = count + 1; " . \
  "if (count > best_n) { best_n = count; best_dev = dev; best_from = from; best_to = C[j] } } else { from = NaN } } }"
percent(x) = sprintf('%.1f %%', ceil(1000 * x) / 10.0)  # a departure, rounded up to 0.1 %
meshes(a, b) = (a == b ? sprintf('at %d cells', a) : sprintf('at %d–%d cells', a, b))
verdict_small = "(from != from || count < 2 ? 'apart' : '≤ ' . percent(dev) . (from > coarsest ? sprintf(' from %d cells', from) : ''))"
span(a, b) = (sprintf('%.2g', a) eq sprintf('%.2g', b) ? sprintf('%.2g', a) : sprintf('%.2g–%.2g', a, b))
verdict_large = "(valid == 0 ? 'no pair' : best_n == 0 ? 'apart (' . span(q_min, q_max) . ')' : '≤ ' . percent(best_dev) . ' ' . meshes(best_from, best_to))"
# a ratio's piece of its title line, after the walk (which sets verdict)
walk = walk . '; verdict = ' . (small ? verdict_small : verdict_large)
piece(r, q) = item_name(r, q) . (item_name(r, q) eq '' ? '' : ' ') . verdict
# for each panel with ratios: ratios_ID (its ratios), ratio_title_ID (its title), ratio_range_ID
panel_id(s, i1, col) = sprintf('%s_%s_%d', s, i1, col)
paper_panels = 'linear/fe/npc ugimp/fe/npc lme/fe/npc'
baseline_panels = 'bspline2/fe/npc bspline3/fe/npc linear/usl/musl'
# A ratio with no mesh where both runs ended is named in the title but not drawn; a panel with none says so. The
# range of a panel: its ratios', widened by margin (at large amplitude enough for a marker at each end).
margin = (small ? 1.12 : 1.45)
do for [pn in paper_panels.' '.baseline_panels] { do for [col = 7:8] {
  s = field(pn, 1); i1 = field(pn, 2); i2 = field(pn, 3); rl = rule(s, i1, col); list = ''; title = ''; r_min = 1; r_max = 1
  do for [g in groups(s, i1, col)] {
    line = lead(rl, g, s, i1, i2, title eq ''); sep = ''
    do for [q in ratios_of(s, i1, i2, col, g)] { eval walk; list = list.(valid > 0 ? ' '.q : ''); line = line.sep.piece(rl, q); sep = ', ' }
    title = title.line."\n"
  }
  id = panel_id(s, i1, col); title = (list eq '' ? 'no mesh where both twins ended: nothing to compare' : title[1:strlen(title) - 1])
  eval sprintf("ratios_%s = list; ratio_title_%s = title; ratio_range_%s = '[%.6g:%.6g]'", id, id, id, r_min / margin, r_max * margin)
  eval sprintf("ratio_name_%s = '%s'", id, rule_name(rl))
} }
# a ratio panel's tics, by how many times its top is its bottom
span_of(range) = real(range[strstrt(range, ':') + 1:strlen(range) - 1]) / real(range[2:strstrt(range, ':') - 1])
ratio_tics(range) = (span_of(range) < 1.4 ? '(0.9, 0.95, 1, 1.05, 1.1, 1.15)' : span_of(range) < 4 ? '(0.5, 0.6, 0.8, 1, 1.2, 1.5, 2)' : \
  span_of(range) < 100 ? '(0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100)' : span_of(range) < 400 ? '(0.01, 0.03, 0.1, 0.3, 1, 3, 10, 30, 100)' : '(0.001, 0.01, 0.1, 1, 10, 100)')
# a ratio's look: its numerator's (shape's colour, integrator's dash and marker, open at 2 ppc, thin and small at CFL 0.1)
ratio_look = "lw (real(field(numerator(q), 4)) > 0.3 ? method_lw : 0.8) dt dash(field(numerator(q), 2)) " . \
  "pt (field(numerator(q), 3) eq '1' ? marker(field(numerator(q), 2)) : open(marker(field(numerator(q), 2)))) " . \
  "ps ((real(field(numerator(q), 4)) > 0.3 ? 1 : 0.6) * (field(numerator(q), 3) eq '2' ? 1.5 : 1)) lc rgb colour(field(numerator(q), 1))"
# (gnuplot reads a curve's options even for an empty list: a panel with no ratio draws the line at 1 alone)
ratio_curves(id, col) = (value('ratios_'.id) eq '' ? 'plot 1 with lines '.reference_style : sprintf("plot 1 with lines %s, for [q in ratios_%s] sweep using (strcol(1) eq amplitude && row_key(0) eq numerator(q) ? $6 : NaN):" . \
  "(strcol(12) eq 'ok' && strcol(18) eq 'done' ? column(%d) / value_at(denominator(q), $6, %d) : NaN) with linespoints %s", reference_style, id, col, col, ratio_look))
# uGIMP's largest departure from linear's numbers (same integrator, ppc, CFL, mesh), velocity and stress
do for [col = 7:8] {
  worst = 0
  do for [j = 1:n] { if (field(K[j], 1) eq 'ugimp') {
    r = (col == 7 ? V[j] : S[j]) / value_at('linear'.K[j][6:], C[j], col)
    worst = (r == r && abs(r - 1) > worst ? abs(r - 1) : worst)
  } }
  eval sprintf("ugimp_off_%d = worst", col)
}

# The strip: one row per series of a panel, k = 1 (top) to 4: the first integrator at 1 and 2 ppc, then the second;
# each run at its mesh. A row is named at its left when it holds a run (count_SHAPE_INTEGRATOR_PPC: its runs there).
rows = 4
row_share = 0.11  # a row's height, as a share of the data's (log) height
row_y(lo, hi, k) = hi * (hi / lo)**(row_share * (rows - k + 0.5))
do for [series in 'linear/fe linear/npc ugimp/fe ugimp/npc lme/fe lme/npc bspline2/fe bspline2/npc bspline3/fe bspline3/npc linear/usl linear/musl'] {
  do for [ppc = 1:2] {
    series_shape = series[1:strstrt(series, '/') - 1]; series_integrator = series[strstrt(series, '/') + 1:]
    stats sweep using ((off(series_shape, series_integrator, ppc, 'stopped') || off(series_shape, series_integrator, ppc, 'failed')) ? 1 : 0) nooutput
    eval sprintf("count_%s_%s_%d = %d", series_shape, series_integrator, ppc, STATS_sum)
  }
}
count(s, i, p) = value(sprintf('count_%s_%s_%d', s, i, p))
row_name(s, i, p, k, lo, hi) = (count(s, i, p) > 0 ? sprintf("set label %d '%s, %d ppc' at graph 0.015, first %.12g left front; ", 90 + k, integrator_name(i), p, row_y(lo, hi, k)) : '')
row_names(s, i1, i2, lo, hi) = (outcomes == 0 ? '' : row_name(s, i1, 1, 1, lo, hi) . row_name(s, i1, 2, 2, lo, hi) . row_name(s, i2, 1, 3, lo, hi) . row_name(s, i2, 2, 4, lo, hi))
unname = "unset label 91; unset label 92; unset label 93; unset label 94; "
beside = 1.2  # the method's marker lies right of the cross or ring, at 1.2 times its mesh
own_marker(s, i) = sprintf("pt (p == 1 ? %d : %d) ps (p == 1 ? 1.1 : 1.4) lc rgb '%s'", marker(i), open(marker(i)), colour(s))
on_strip(s, i, first, kind, lo, hi, x, how) = sprintf("for [p = 1:2] sweep using (off('%s', '%s', p, '%s') ? $6 * %g : NaN):(row_y(%.12g, %.12g, %d + p)) with points %s", s, i, kind, x, lo, hi, first ? 0 : 2, how)
strip_runs(s, i, first, lo, hi) = (outcomes == 0 ? '' : sprintf(", %s, %s, %s, %s", on_strip(s, i, first, 'stopped', lo, hi, 1, stopped_style), on_strip(s, i, first, 'failed', lo, hi, 1, failed_style), \
  on_strip(s, i, first, 'stopped', lo, hi, beside, own_marker(s, i)), on_strip(s, i, first, 'failed', lo, hi, beside, own_marker(s, i))))
guides = sprintf(", 0.05 * (x / 8)**-1 with lines %s, 0.05 * (x / 8)**-2 with lines %s", reference_style, reference_style)
strip_top(lo, hi) = hi * (hi / lo)**(row_share * rows)
# the y tics: every decade up to hi, none on the strip
decades(lo, hi) = sprintf("set ytics %.12g, 10, %.12g; ", 10**floor(log10(lo)), hi)
yrange(lo, hi) = unname . decades(lo, hi) . (outcomes > 0 ? sprintf("set yrange [%.12g:%.12g]; ", lo, strip_top(lo, hi)) . strip_common(hi, strip_top(lo, hi), hi, '') : \
  sprintf("set yrange [%.12g:%.12g]; ", lo, hi).unstrip)

# Places, in pixels from the top (120 px an inch): the figure's title, then per row of panels its title, the data
# panel, the ratio panel's title and the ratio panel, the x label; the legend at the bottom.
title_px = (small ? 56 : 72); panel_title_px = 26; ratio_title_px = 56; xlabel_px = 60; legend_px = 62
data_px = (small ? 220 : 260); ratio_px = 110
block_px = panel_title_px + data_px + ratio_title_px + ratio_px + xlabel_px
h = (title_px + 4 * block_px + legend_px) / 120.0
screen_y(px) = 1 - px / (h * 120.0)
data_top(r) = screen_y(title_px + (r - 1) * block_px + panel_title_px)
data_bottom(r) = screen_y(title_px + (r - 1) * block_px + panel_title_px + data_px)
ratio_top(r) = screen_y(title_px + (r - 1) * block_px + panel_title_px + data_px + ratio_title_px)
ratio_bottom(r) = screen_y(title_px + (r - 1) * block_px + panel_title_px + data_px + ratio_title_px + ratio_px)
column_left(c) = 0.06 + (c - 1) * 0.33
place(c, top, bottom) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set tmargin at screen %g; set bmargin at screen %g; ", column_left(c), column_left(c) + 0.275, top, bottom)
# One panel: shape s with integrators i1 and i2; col 7 (velocity) or 8 (stress); in column c, row r; its ratio panel
# under it.
panel(s, i1, i2, col, c, r, title) = place(c, data_top(r), data_bottom(r)) . sprintf("set title '%s'; set ylabel '%s'; set logscale y; set format y '10^{%%L}'; ", title, col == 7 ? 'RMS(v_p - v) / V' : 'RMS(σ_p - σ) / ZV') . \
  "set format x ''; unset xlabel; " . \
  (col == 7 ? yrange(vlow, vhigh) . row_names(s, i1, i2, vlow, vhigh) : yrange(slow, shigh) . row_names(s, i1, i2, slow, shigh)) . "plot " . curves(s, i1, col) . ", " . curves(s, i2, col) . guides . \
  strip_runs(s, i1, 1, col == 7 ? vlow : slow, col == 7 ? vhigh : shigh) . strip_runs(s, i2, 0, col == 7 ? vlow : slow, col == 7 ? vhigh : shigh) . "; " . \
  ratio_panel(panel_id(s, i1, col), col, c, r)
ratio_panel(id, col, c, r) = place(c, ratio_top(r), ratio_bottom(r)) . unname . unstrip . \
  "set title '" . value('ratio_title_'.id) . "'; set ylabel '" . value('ratio_name_'.id) . "'; set format y '%g'; set ytics " . ratio_tics(value('ratio_range_'.id)) . \
  "; set yrange " . value('ratio_range_'.id) . "; set format x '%g'; set xlabel 'cells'; " . ratio_curves(id, col) . "; "
quantity(col) = (col == 7 ? 'velocity' : 'stress')
same_as_linear(col) = (small ? ', linear’s numbers within '.percent(value(sprintf('ugimp_off_%d', col))) : '')
paper_row(col, r) = panel('linear', 'fe', 'npc', col, 1, r, shape_name('linear').': '.quantity(col).', FE and NPC') . \
  panel('ugimp', 'fe', 'npc', col, 2, r, shape_name('ugimp').': '.quantity(col).same_as_linear(col)) . \
  panel('lme', 'fe', 'npc', col, 3, r, shape_name('lme').': '.quantity(col))
baseline_row(col, r) = panel('bspline2', 'fe', 'npc', col, 1, r, 'baseline '.shape_name('bspline2').': '.quantity(col)) . \
  panel('bspline3', 'fe', 'npc', col, 2, r, 'baseline '.shape_name('bspline3').': '.quantity(col)) . \
  panel('linear', 'usl', 'musl', col, 3, r, 'baseline '.shape_name('linear').': '.quantity(col).', USL and MUSL')
neutral(i) = sprintf("lw %g dt %d pt %d lc rgb '%s'", method_lw, dash(i), marker(i), c_exact)
legend = sprintf("keyentry with linespoints %s title 'FE: solid, circles', keyentry with linespoints %s title 'NPC: dashed, squares', ", neutral('fe'), neutral('npc')) . \
  sprintf("keyentry with linespoints %s title 'USL: triangles up', keyentry with linespoints %s title 'MUSL: triangles down', ", neutral('usl'), neutral('musl')) . \
  sprintf("keyentry with points pt %d lc rgb '%s' title '1 ppc: filled markers', keyentry with points pt %d ps 1.5 lc rgb '%s' title '2 ppc: open, larger', ", marker('fe'), c_exact, open(marker('fe')), c_exact) . \
  (small ? sprintf("keyentry with linespoints lw %g pt %d lc rgb '%s' title 'CFL 0.5', keyentry with linespoints lw 0.8 pt %d ps 0.6 lc rgb '%s' title 'CFL 0.1: thin, small markers', ", method_lw, marker('fe'), c_exact, marker('fe'), c_exact) : '') . \
  "keyentry with lines ".reference_style." title 'slopes 1 and 2; in a ratio panel, 1'" . \
  (stops > 0 ? ", keyentry with points ".stopped_style." title 'stopped (its method’s marker beside)'" : '') . \
  (fails > 0 ? ", keyentry with points ".failed_style." title 'failed: no better than a flat field (likewise)'" : '')
legend_panel = sprintf("set lmargin at screen 0.02; set rmargin at screen 0.99; set bmargin at screen 0.003; set tmargin at screen %g; ", 1 - (title_px + 4 * block_px + 4) / (h * 120.0)) . \
  "unset logscale; unset border; unset tics; unset grid; unset title; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; " . unstrip . unname . \
  "set key inside left top horizontal Left reverse samplen 3 maxrows 3; plot -1, " . legend
note = (small ? 'under each panel, twin runs one over the other; its title: the largest departure from 1 over the finest meshes while within 7 % (a line width), or “apart”' : \
  "rows 1-2: the paper’s shape functions, rows 3-4: today’s baselines; all at CFL 0.5; under each panel, twin runs one over the other: 2 ppc over 1 ppc (open markers) and the second\n" . \
  "integrator over the first at 1 ppc (filled); its title: the largest departure from 1 over the longest stretch of meshes within 7 % (a line width), or “apart” (the ratio’s range), “no pair” when no mesh has both")
draw = "set border; set tics; set grid; set key off; " . \
  sprintf("set multiplot title '%s\n%s'; set logscale x; set xrange [%g:%g]; set xtics (8, 16, 32, 64, 128, 256); ", caption, note, xlow, xhigh) . \
  paper_row(7, 1) . paper_row(8, 2) . baseline_row(7, 3) . baseline_row(8, 4) . legend_panel . "; unset multiplot; set border; set tics; set grid"
load dir."/output.gp"
