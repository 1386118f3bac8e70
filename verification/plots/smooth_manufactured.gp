# 2D manufactured solutions (data/smooth_manufactured.csv): RMS errors of velocity and stress against the cells per
# side. Top row: small amplitude, linear and LME γ = 3 (uGIMP gives linear's numbers, to within a few 1e-5, so it is
# drawn in the middle row only); middle row: the same errors of uGIMP and LME over linear's (same integrator, ppc,
# mesh), linear the red line at 1, uGIMP its markers on it, LME within about 10 %, and (right) MUSL's velocity error
# over USL's at 2x2 ppc, the two that lie on each other in the top right panel, their range of ratios in its title;
# bottom row: large amplitude (diagonal stretch), every shape; under it, one run over another at each mesh where both
# ended, in the numerator's look: velocity (left) and stress (middle) of linear + NPC, LME + FE and LME + NPC at 1x1
# over linear + FE at 1x1 (the four lie on each other), uGIMP at 2x2 over 1x1 (each integrator); right, the
# baselines' velocity: NPC over FE (B-splines, 2x2) and MUSL over USL; each title gives, for each ratio, its largest
# departure from 1 over its longest stretch of meshes within 10 % and those meshes (cells per side), or "apart" with
# its range. Colour: shape function (palette.gp); the integrator's
# dash and marker (FE solid with circles, NPC dashed with squares, USL and MUSL with triangles); 1x1 particles per
# cell filled markers, 2x2 open ones, drawn larger. Right column, top and bottom: today's baselines' velocity error
# at 2x2 ppc, with LME γ = 3 + NPC (2x2) for comparison. Grey dotted: slopes 1 and 2. A run that stopped (black
# cross) or ended no better than a flat field (failed, black ring) lies on the strip above the data, its method's
# marker beside it (right), at its mesh: one strip row per series with such a run, named at its left (method and
# ppc); an amplitude without such a run has no strip, the figure's title says so. No y tic on a strip. Each
# amplitude's panels share the y range of its data (and the strip's height); the legend lies below the panels.
# Every number in the titles is computed here from the CSV.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_manufactured.gp
load dir."/common.gp"
w = 13.3; h = 13.9
file = data.'/smooth_manufactured.csv'
# columns: 1 amplitude, 2 shape, 3 integrator, 4 ppc, 5 cells, 6 velocity error, 7 stress error, 10 status (ok, or
# failed: stopped), 15 ending (done, failed, stopped)
mine(a, s, i, p) = (strcol(1) eq a && strcol(2) eq s && strcol(3) eq i && $4 == p)
done(a, s, i, p) = (mine(a, s, i, p) && strcol(10) eq 'ok' && strcol(15) eq 'done')
# the error of a run that ended (done), NaN otherwise, which breaks its line (a row whose column is nan is skipped)
error(a, s, i, p, col) = (done(a, s, i, p) ? real(strcol(col)) : NaN)
off(a, s, i, p, kind) = (mine(a, s, i, p) && (kind eq 'stopped' ? strcol(10) ne 'ok' : strcol(10) eq 'ok' && strcol(15) eq 'failed'))
# A series is SHAPE/INTEGRATOR/PPC. At small amplitude uGIMP's numbers are linear's: the top row leaves it out
# (paper_small), the middle row draws it.
paper = 'linear/fe/1 linear/fe/2 linear/npc/1 linear/npc/2 ugimp/fe/1 ugimp/fe/2 ugimp/npc/1 ugimp/npc/2 lme/fe/1 lme/fe/2 lme/npc/1 lme/npc/2'
paper_small = 'linear/fe/1 linear/fe/2 linear/npc/1 linear/npc/2 lme/fe/1 lme/fe/2 lme/npc/1 lme/npc/2'
baselines = 'bspline2/fe/2 bspline2/npc/2 bspline3/fe/2 bspline3/npc/2 linear/usl/2 linear/musl/2 lme/npc/2'
rest(m) = m[strstrt(m, '/') + 1:]
part(m, k) = (k == 1 ? m[1:strstrt(m, '/') - 1] : k == 2 ? rest(m)[1:strstrt(rest(m), '/') - 1] : rest(rest(m)))
sel(a, m) = sprintf("mine('%s', '%s', '%s', %s)", a, part(m, 1), part(m, 2), part(m, 3))
point = "pt (part(m, 3) eq '1' ? marker(part(m, 2)) : open(marker(part(m, 2)))) ps (part(m, 3) eq '1' ? 1 : 1.5) lc rgb colour(part(m, 1))"
look = "lw method_lw dt dash(part(m, 2)) ".point
# linear's errors, by amplitude, integrator, ppc and cells, for the middle row's ratios
array linear_error[2 * 2 * 2 * 2 * 64]
key(a, i, p, n, col) = 1 + (a eq 'large') + 2 * (i eq 'npc') + 4 * (p - 1) + 8 * (col - 6) + 16 * int(n)
keep(k, value) = (k >= 1 && k <= 1024 ? (linear_error[k] = value, 0) : 0)
stats file using (strcol(2) eq 'linear' && (strcol(3) eq 'fe' || strcol(3) eq 'npc') && strcol(15) eq 'done' ? keep(key(strcol(1), strcol(3), $4, $5, 6), $6) + keep(key(strcol(1), strcol(3), $4, $5, 7), $7) : 0) nooutput
ratio(a, s, i, p, col) = (done(a, s, i, p) ? real(strcol(col)) / linear_error[key(a, i, p, $5, col)] : NaN)
# y ranges: each amplitude's errors, the ratios
stats file using (strcol(1) eq 'small' && strcol(15) eq 'done' ? $6 : NaN):(strcol(1) eq 'small' && strcol(15) eq 'done' ? $7 : NaN) nooutput
small_low = (STATS_min_x < STATS_min_y ? STATS_min_x : STATS_min_y) / 1.5; small_high = (STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y) * 1.5
stats file using (strcol(1) eq 'large' && strcol(15) eq 'done' ? $6 : NaN):(strcol(1) eq 'large' && strcol(15) eq 'done' ? $7 : NaN) nooutput
large_low = (STATS_min_x < STATS_min_y ? STATS_min_x : STATS_min_y) / 1.5; large_high = (STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y) * 1.5
stats file using (strcol(1) eq 'small' && (strcol(2) eq 'ugimp' || strcol(2) eq 'lme') ? ratio('small', strcol(2), strcol(3), $4, 6) : NaN):\
  (strcol(1) eq 'small' && (strcol(2) eq 'ugimp' || strcol(2) eq 'lme') ? ratio('small', strcol(2), strcol(3), $4, 7) : NaN) nooutput
ratio_low = (STATS_min_x < STATS_min_y ? STATS_min_x : STATS_min_y) - 0.03; ratio_high = (STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y) + 0.03
stats file using (strcol(1) eq 'small' && strcol(2) eq 'ugimp' ? abs(ratio('small', 'ugimp', strcol(3), $4, 6) - 1) : NaN):\
  (strcol(1) eq 'small' && strcol(2) eq 'ugimp' ? abs(ratio('small', 'ugimp', strcol(3), $4, 7) - 1) : NaN) nooutput
ugimp_off = (STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y)  # uGIMP's largest departure from linear's
# MUSL's velocity error over USL's (small amplitude, 2x2 ppc, same mesh): the two lie on each other in the top right
# panel; their ratio is the middle row's right panel, its range [musl_low:musl_high] in that panel's title
array usl_error[64]
do for [k = 1:64] { usl_error[k] = NaN }
stats file using (strcol(1) eq 'small' && strcol(2) eq 'linear' && strcol(3) eq 'usl' && $4 == 2 && strcol(15) eq 'done' && $5 <= 64 ? (usl_error[int($5)] = $6, 0) : 0) nooutput
musl_ratio(dummy) = (done('small', 'linear', 'musl', 2) && $5 <= 64 ? $6 / usl_error[int($5)] : NaN)
stats file using (musl_ratio(0)) nooutput
musl_low = STATS_min; musl_high = STATS_max
ratio_low = (musl_low - 0.03 < ratio_low ? musl_low - 0.03 : ratio_low); ratio_high = (musl_high + 0.03 > ratio_high ? musl_high + 0.03 : ratio_high)
signed(r) = sprintf('%+.1f', 100 * (r - 1))
# The series of each amplitude with a run on the strip (paper's and baselines' apart); each has a row of the strip.
do for [a in 'small large'] { do for [group in 'paper paper_small baselines'] {
  list = ''
  do for [m in value(group)] {
    stats file using ((off(a, part(m, 1), part(m, 2), int(part(m, 3)), 'stopped') || off(a, part(m, 1), part(m, 2), int(part(m, 3)), 'failed')) ? 1 : 0) nooutput
    if (STATS_sum > 0) { list = list.' '.m }
  }
  eval sprintf("onstrip_%s_%s = '%s'", a, group, list)
} }
rank(m, list) = sum [k = 1:words(list)] (word(list, k) eq m ? k : 0)
strip_list(a, group) = value(sprintf('onstrip_%s_%s', a, group))
any_strip(a) = (words(strip_list(a, 'paper')) + words(strip_list(a, 'baselines')) > 0)
# The strip of an amplitude: as many rows as its fullest panel, row_share of the data's (log) height each; row 1 on top.
row_share = 0.075
rows(a) = (words(strip_list(a, 'paper')) > words(strip_list(a, 'baselines')) ? words(strip_list(a, 'paper')) : words(strip_list(a, 'baselines')))
low(a) = (a eq 'small' ? small_low : large_low)
high(a) = (a eq 'small' ? small_high : large_high)
strip_top(a) = high(a) * (high(a) / low(a))**(row_share * rows(a))
row_y(a, k) = high(a) * (high(a) / low(a))**(row_share * (rows(a) - k + 0.5))
# each row named at its left: the method and its ppc (labels 91 on)
ppc_name(p) = (p eq '1' ? '1x1 ppc' : '2x2 ppc')
do for [a in 'small large'] { do for [group in 'paper paper_small baselines'] {
  list = strip_list(a, group); names = ''
  do for [k = 1:words(list)] {
    m = word(list, k)
    names = names . sprintf("set label %d '%s, %s' at graph 0.015, first %.12g left front; ", 90 + k, method_name(part(m, 1), part(m, 2)), ppc_name(part(m, 3)), row_y(a, k))
  }
  if (words(list) == 0 && rows(a) > 0) { names = sprintf("set label 91 'every run here ended (none stopped or failed)' at graph 0.015, first %.12g left front; ", row_y(a, (rows(a) + 1) / 2.0)) }
  eval sprintf("names_%s_%s = names", a, group)
} }
unname = ''
do for [k = 1:12] { unname = unname . sprintf('unset label %d; ', 90 + k) }
on_strip(a, group, kind, how, x) = sprintf("for [m in onstrip_%s_%s] file using (off('%s', part(m, 1), part(m, 2), int(part(m, 3)), '%s') ? $5 * %g : NaN):(row_y('%s', rank(m, onstrip_%s_%s))) with points %s", a, group, a, kind, x, a, a, group, how)
beside = "pt (part(m, 3) eq '1' ? marker(part(m, 2)) : open(marker(part(m, 2)))) ps (part(m, 3) eq '1' ? 1.1 : 1.4) lc rgb colour(part(m, 1))"
strip_runs(a, group) = (words(strip_list(a, group)) == 0 ? '' : ', ' . on_strip(a, group, 'stopped', stopped_style, 1) . ', ' . on_strip(a, group, 'failed', failed_style, 1) . \
  ', ' . on_strip(a, group, 'stopped', beside, 1.06) . ', ' . on_strip(a, group, 'failed', beside, 1.06))
# the y range of an amplitude, with its strip when it has one; tics on every decade up to the data's top, none on the strip
decades(a) = sprintf("set ytics %.12g, 10, %.12g; ", 10**floor(log10(low(a))), high(a))
yrange(a, group) = unname . decades(a) . (any_strip(a) ? sprintf("set yrange [%.12g:%.12g]; ", low(a), strip_top(a)) . strip_common(high(a), strip_top(a), high(a), '') . value(sprintf('names_%s_%s', a, group)) : \
  sprintf("set yrange [%.12g:%.12g]; ", low(a), high(a)) . unstrip)
guides = sprintf(", 0.15 * (x / 8)**-1 with lines %s, 0.15 * (x / 8)**-2 with lines %s", reference_style, reference_style)
# Panels at explicit places: column c (1-3), from t to b pixels from the top (120 px an inch): the top row from 113 to
# 428, the ratios from 536 to 693, the bottom row from 819 to 1184, its ratios from 1350 to 1500, the legend under it.
screen_y(px) = 1 - (px + 17) / (h * 120.0)  # 17 px more for the title's fourth line
at(c, t, b) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; set tmargin at screen %g; ", 0.06 + (c - 1) * 0.325, 0.06 + (c - 1) * 0.325 + 0.28, screen_y(b), screen_y(t))
errors(a, group, col) = sprintf("plot for [m in %s] file using (%s ? $5 : NaN):(error('%s', part(m, 1), part(m, 2), int(part(m, 3)), %d)) with linespoints %s", group, "mine('".a."', part(m, 1), part(m, 2), int(part(m, 3)))", a, col, look) . guides . strip_runs(a, group)
panel(a, group, col, c, t, b, title, ylabel) = at(c, t, b) . "set logscale y; set format y '10^{%L}'; " . yrange(a, group) . sprintf("set title '%s'; set ylabel '%s'; ", title, ylabel) . errors(a, group, col) . "; "
# linear's line at 1 first, uGIMP's markers on it (no line: its lines would cover linear's), LME's lines and markers
ratio_of(s, col) = sprintf("file using (part(m, 1) eq '%s' && mine('small', part(m, 1), part(m, 2), int(part(m, 3))) ? $5 : NaN):(ratio('small', part(m, 1), part(m, 2), int(part(m, 3)), %d))", s, col)
ratios(col, c, title) = at(c, 536, 693) . unstrip . unname . sprintf("unset logscale y; set format y '%%g'; set ytics 0.05; set yrange [%g:%g]; set title '%s'; set ylabel 'error / linear’s'; ", ratio_low, ratio_high, title) . \
  sprintf("plot 1 with lines lw %g lc rgb '%s', ", method_lw, colour('linear')) . "for [m in paper] " . ratio_of('ugimp', col) . " with points " . point . \
  ", for [m in paper] " . ratio_of('lme', col) . " with linespoints " . look . "; set ytics auto; "
vlabel = 'RMS |v_p - v| / Aω'; slabel = 'RMS |σ_p - σ| / σ scale'
stats file using (strcol(10) eq 'failed' ? 1 : 0) nooutput
stops = STATS_sum
stats file using (strcol(10) eq 'ok' && strcol(15) eq 'failed' ? 1 : 0) nooutput
fails = STATS_sum
# the right of the middle row: MUSL over USL, USL's line at 1
musl_panel = at(3, 536, 693) . unstrip . unname . sprintf("unset logscale y; set format y '%%g'; set ytics 0.05; set yrange [%g:%g]; ", ratio_low, ratio_high) . \
  "set title 'small: velocity, MUSL over USL, 2x2 ppc (" . signed(musl_low) . " to " . signed(musl_high) . " %)'; set ylabel 'error / USL’s'; " . \
  "plot 1 with lines " . method_line('linear', 'usl') . ", file using (mine('small', 'linear', 'musl', 2) ? $5 : NaN):(musl_ratio(0)) with linespoints " . \
  sprintf("lw %g dt %d pt %d ps 1.5 lc rgb '%s'", method_lw, dash('musl'), open(marker('musl')), colour('linear')) . "; set ytics auto; "
# The large amplitude's ratio row: one run over another (series NUMERATOR>DENOMINATOR, each SHAPE/INTEGRATOR/PPC),
# at each mesh where both ended, in the numerator's look; velocity (left) and stress (middle): the 1x1 runs that lie
# on each other (linear + NPC, LME + FE and LME + NPC over linear + FE) and uGIMP's 2x2 over 1x1 (each integrator);
# right: the baselines' NPC over FE (B-splines) and MUSL over USL. Every error of the CSV, by amplitude, shape,
# integrator, ppc, cells and column, in E (NaN where the run did not end).
shape_index(s) = (s eq 'linear' ? 0 : s eq 'ugimp' ? 1 : s eq 'lme' ? 2 : s eq 'bspline2' ? 3 : 4)
integrator_index(i) = (i eq 'fe' ? 0 : i eq 'npc' ? 1 : i eq 'usl' ? 2 : 3)
at_E(a, s, i, p, n, col) = 1 + (a eq 'large') + 2 * (col - 6) + 4 * (int(p) - 1) + 8 * integrator_index(i) + 32 * shape_index(s) + 160 * int(n)
array E[160 * 64]
array present[64]  # the meshes of the CSV
do for [k = 1:160 * 64] { E[k] = NaN }
do for [k = 1:64] { present[k] = 0 }
stats file using ($5 < 64 ? (present[int($5)] = 1, done(strcol(1), strcol(2), strcol(3), $4) ? (E[at_E(strcol(1), strcol(2), strcol(3), $4, $5, 6)] = $6, E[at_E(strcol(1), strcol(2), strcol(3), $4, $5, 7)] = $7, 0) : 0) : 0) nooutput
numerator(q) = q[1:strstrt(q, '>') - 1]
denominator(q) = q[strstrt(q, '>') + 1:]
error_of(m, n, col) = E[at_E('large', part(m, 1), part(m, 2), part(m, 3), n, col)]
large_ratio(q, n, col) = (n >= 1 && n < 64 ? error_of(numerator(q), n, col) / error_of(denominator(q), n, col) : NaN)  # NaN on the header
# a ratio's name in its title: over linear + FE, the numerator's method; else its integrator (same shape and ppc),
# its shape (NPC over FE), or none (MUSL over USL, named by its group's lead)
short(s) = (s eq 'linear' ? 'linear' : s eq 'lme' ? 'LME' : s eq 'ugimp' ? 'uGIMP' : s eq 'bspline2' ? 'B-spline 2' : 'B-spline 3')
ratio_name(q) = (denominator(q) eq 'linear/fe/1' ? short(part(numerator(q), 1)).' + '.integrator_name(part(numerator(q), 2)) : \
  part(numerator(q), 2) eq part(denominator(q), 2) ? integrator_name(part(numerator(q), 2)) : \
  part(numerator(q), 2) eq 'musl' ? '' : short(part(numerator(q), 1)))
# The walk over the meshes (q, col and tol set): valid its meshes with a ratio, q_min and q_max its range (r_min and
# r_max kept over a panel), its longest stretch of meshes within tol (the coarsest first): best_n meshes from best_from
# to best_to, best_dev its largest departure there.
tol = 0.1
walk = "valid = 0; q_min = NaN; q_max = NaN; best_n = 0; best_dev = 0; from = NaN; dev = 0; count = 0; " . \
  "do for [c = 1:63] { if (present[c]) { r = large_ratio(q, c, col); if (r == r) { valid = valid + 1; " . \
  "q_min = (q_min == q_min && q_min < r ? q_min : r); q_max = (q_max == q_max && q_max > r ? q_max : r); r_min = (r < r_min ? r : r_min); r_max = (r > r_max ? r : r_max) }; " . \
  "if (r == r && abs(r - 1) <= tol) { if (from != from) { from = c; dev = 0; count = 0 }; dev = (abs(r - 1) > dev ? abs(r - 1) : dev); count = count + 1; " . \
  "if (count > best_n) { best_n = count; best_dev = dev; best_from = from; best_to = c } } else { from = NaN } } }"
percent(x) = sprintf('%.1f %%', ceil(1000 * x) / 10.0)  # a departure, rounded up to 0.1 %
span(a, b) = (sprintf('%.2f', a) eq sprintf('%.2f', b) ? sprintf('%.2f', a) : sprintf('%.2f–%.2f', a, b))
cells_span(a, b) = (a == b ? sprintf('%d', a) : sprintf('%d–%d', a, b))
verdict = "(valid == 0 ? 'no pair' : best_n < 2 ? 'apart (' . span(q_min, q_max) . ')' : '≤ ' . percent(best_dev) . ' (' . cells_span(best_from, best_to) . ')')"
# a panel's groups: LEAD:RATIOS with the ratios joined by commas, groups by |; in its title each group's lead, on a
# line of its own when they do not fit on one line, then its ratios, two a line; its ratios in large_list_ID, its
# y range in large_range_ID
groups_vs = 'over linear + FE, 1x1:linear/npc/1>linear/fe/1,lme/fe/1>linear/fe/1,lme/npc/1>linear/fe/1|uGIMP 2x2 over 1x1:ugimp/npc/2>ugimp/npc/1,ugimp/fe/2>ugimp/fe/1'
groups_base = 'NPC over FE, 2x2:bspline2/npc/2>bspline2/fe/2,bspline3/npc/2>bspline3/fe/2|MUSL over USL, 2x2:linear/musl/2>linear/usl/2'
blank(x) = (strstrt(x, ',') > 0 ? blank(x[1:strstrt(x, ',') - 1].' '.x[strstrt(x, ',') + 1:]) : x)
do for [pc in 'vs:6 vs:7 base:6'] {
  id = pc[1:strstrt(pc, ':') - 1]; col = int(pc[strstrt(pc, ':') + 1:]); spec = value('groups_'.id); list = ''; title = ''; r_min = 1; r_max = 1
  rest_spec = spec
  while (strlen(rest_spec) > 0) {
    bar = strstrt(rest_spec, '|'); group = (bar > 0 ? rest_spec[1:bar - 1] : rest_spec); rest_spec = (bar > 0 ? rest_spec[bar + 1:] : '')
    ratios = blank(group[strstrt(group, ':') + 1:]); lead = group[1:strstrt(group, ':') - 1].':'; line = ''; k = 0
    do for [q in ratios] {
      eval walk; eval 'v = '.verdict; list = list.(valid > 0 ? ' '.q : '')
      line = line.(k == 0 ? '' : k % 2 == 0 ? ",\n" : ', ').ratio_name(q).(ratio_name(q) eq '' ? '' : ' ').v; k = k + 1
    }
    # the lead on the line of the ratios when that fits the panel (about 66 characters; ≤ and – take 3 bytes)
    title = title."\n".lead.(words(ratios) <= 2 && strlen(lead.line) - 4 * words(ratios) <= 66 ? ' ' : "\n").line
  }
  eval sprintf("large_list_%s_%d = list; large_title_%s_%d = title; large_range_%s_%d = '[%.6g:%.6g]'", id, col, id, col, id, col, r_min - 0.08, r_max + 0.08)
}
large_look = "lw method_lw dt dash(part(numerator(q), 2)) pt (part(numerator(q), 3) eq '1' ? marker(part(numerator(q), 2)) : open(marker(part(numerator(q), 2)))) " . \
  "ps (part(numerator(q), 3) eq '1' ? 1 : 1.5) lc rgb colour(part(numerator(q), 1))"
large_tics(range) = (real(range[strstrt(range, ':') + 1:strlen(range) - 1]) - real(range[2:strstrt(range, ':') - 1]) < 0.6 ? 0.1 : \
  real(range[strstrt(range, ':') + 1:strlen(range) - 1]) - real(range[2:strstrt(range, ':') - 1]) < 1.2 ? 0.2 : 0.5)
large_ratios(id, col, c, head) = at(c, 1350, 1500) . unstrip . unname . sprintf("unset logscale y; set format y '%%g'; set ytics %g; set yrange %s; set title '%s%s'; set ylabel 'one run / another'; ", \
  large_tics(value(sprintf('large_range_%s_%d', id, col))), value(sprintf('large_range_%s_%d', id, col)), head, value(sprintf('large_title_%s_%d', id, col))) . \
  "plot 1 with lines " . reference_style . (value(sprintf('large_list_%s_%d', id, col)) eq '' ? '' : \
  sprintf(", for [q in large_list_%s_%d] file using (mine('large', part(numerator(q), 1), part(numerator(q), 2), int(part(numerator(q), 3))) ? $5 : NaN):(large_ratio(q, $5, %d)) with linespoints %s", id, col, col, large_look)) . \
  "; set ytics auto; "
legend_band = sprintf("set lmargin at screen 0.02; set rmargin at screen 0.99; set bmargin at screen 0.003; set tmargin at screen %g; ", screen_y(1560)) . \
  "unset logscale; unset border; unset tics; unset grid; unset title; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; " . unstrip . unname . \
  "set key inside left top vertical Left reverse samplen 3 maxrows 4 width -14; plot -1, " . \
  "for [s in 'linear ugimp lme bspline2 bspline3'] keyentry with lines lw method_lw lc rgb colour(s) title shape_name(s), " . \
  "for [i in 'fe npc usl musl'] keyentry with linespoints lw method_lw dt dash(i) pt marker(i) lc rgb c_exact title integrator_name(i), " . \
  sprintf("keyentry with points pt %d lc rgb '%s' title '1x1 ppc: filled markers', keyentry with points pt %d ps 1.5 lc rgb '%s' title '2x2 ppc: open, large', ", marker('fe'), c_exact, open(marker('fe')), c_exact) . \
  "keyentry with lines ".reference_style." title 'slopes 1 and 2'" . \
  (stops > 0 ? ", keyentry with points ".stopped_style." title 'stopped (its method’s marker beside)'" : "") . \
  (fails > 0 ? ", keyentry with points ".failed_style." title 'failed: error ≥ a flat field’s (marker beside)'" : "") . "; " . \
  "set border; set tics; set grid; "
# the runs of an amplitude on the strip (none: the title says every run ended)
stats file using (strcol(1) eq 'small' && strcol(15) ne 'done' ? 1 : 0) nooutput
small_off = STATS_sum
draw = "set border; set tics; set grid; set key off; set multiplot title '2D manufactured solutions (plane strain, ν = 0.3): RMS errors at 1/8, 1/4, 3/8, 1/2 period against the cells per side\n" . \
  sprintf("at small amplitude uGIMP gives linear’s numbers (to less than %d·10^{%d}): top row linear and LME γ = 3, middle row each over linear’s (uGIMP the markers on 1), and MUSL over USL", \
  ceil(ugimp_off / 10**floor(log10(ugimp_off))), floor(log10(ugimp_off))) . (small_off == 0 ? "\nevery run at small amplitude ended (none stopped or failed): no strip there" : '') . \
  "\nbottom: large amplitude, and under it one run over another, its title: the largest departure from 1 over its longest stretch of meshes within 10 % (cells per side), or “apart” (its range)'; " . \
  "set logscale x; set xrange [7:36]; set xtics (8, 12, 16, 24, 32); set xlabel 'cells per side'; " . \
  panel('small', 'paper_small', 6, 1, 113, 428, 'small amplitude: velocity, linear and LME γ = 3', vlabel) . panel('small', 'paper_small', 7, 2, 113, 428, 'small amplitude: stress, linear and LME γ = 3', slabel) . \
  panel('small', 'baselines', 6, 3, 113, 428, 'small: baselines and LME γ = 3 + NPC, 2x2 ppc, velocity', vlabel) . \
  ratios(6, 1, 'small amplitude: velocity over linear’s (uGIMP, LME)') . ratios(7, 2, 'small amplitude: stress over linear’s (uGIMP, LME)') . musl_panel . \
  panel('large', 'paper', 6, 1, 819, 1184, 'large amplitude (diagonal stretch): velocity', vlabel) . panel('large', 'paper', 7, 2, 819, 1184, 'large amplitude: stress', slabel) . \
  panel('large', 'baselines', 6, 3, 819, 1184, 'large: baselines and LME γ = 3 + NPC, 2x2 ppc, velocity', vlabel) . \
  large_ratios('vs', 6, 1, 'large: velocity, one run over another') . large_ratios('vs', 7, 2, 'large: stress, one run over another') . \
  large_ratios('base', 6, 3, 'large: baselines’ velocity, one run over another') . \
  legend_band . "unset multiplot; " . unstrip . "set lmargin -1; set rmargin -1; set bmargin -1; set tmargin -1"
load dir."/output.gp"
