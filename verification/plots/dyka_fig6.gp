# Fig. 6: RMS of v_A / |v_0| against the number of cells (CFL 0.5), one panel per shape function, forward Euler (FE)
# and the predictor-corrector (NPC) in the method style of palette.gp (the shape's colour, the integrator's dash and
# marker; FE's markers drawn larger, under NPC's, so that both show where they meet). The background is shaded by
# the grid-crossing band of paper/08_test_cases.md (c_band1: negligible, c_band2: transition, c_band3: crossing);
# the fitted order of each band ± its standard error is printed on the panel, named by its method ('no fit': a band
# with fewer than 3 finished runs). Only runs that ended `done` are drawn as values; a run the solver stopped (×) or
# one no better than a flat line (failed, ○) is drawn on the strip above the data (common.gp), its method's marker in
# its colour above the black cross or ring (so that circle or square and colour read), FE left of NPC (and the
# authors' β right of γ = 3's where they have runs there), and named (method and mesh) on the strip.
# LME's panel also holds its runs under the authors' β (lme_authors colour, the integrator's filled markers, drawn
# smaller and thinner on top of γ = 3's so that both show where they meet). Under each panel, a difference panel of the
# runs that finished under both: linear and uGIMP FE's RMS over NPC's − 1 in % (the shape's colour, FE's dash and
# marker), where the sign changes named in the title; LME the authors' β's RMS over γ = 3's − 1 in %, per integrator
# (lme_authors colour, the integrator's dash and marker), the meshes from which NPC's two coincide (within 1 %) and
# their largest difference there named in the title, computed from the CSVs.
# Reads dyka_sweep.csv and dyka_sweep_authors.csv (column 1 shape, 2 integrator, 3 cells, 8 rms_over_v0, 22 ending:
# done, failed or stopped) and dyka_orders.csv (shape, integrator, band, order, ..., standard_error).
# gnuplot -e "dir='...'; data='...'; out='...'; orders='.../dyka_orders.csv'" dyka_fig6.gp
load dir."/common.gp"
w = 12.5; h = 7
sweep = data.'/dyka_sweep.csv'; authors = data.'/dyka_sweep_authors.csv'
band1 = 0.1 / (3.298e-5 / (0.5 * 0.1333)); band2 = 1.0 / (3.298e-5 / (0.5 * 0.1333))
xlo = 7; xhi = 3600
# The y range holds every finished run's RMS (both files); the bottom leaves room for the fitted orders.
stats sweep using (strcol(22) eq 'done' ? $8 : NaN) nooutput
lo = STATS_min; hi = STATS_max
stats authors using (strcol(22) eq 'done' ? $8 : NaN) nooutput
lo = (STATS_min < lo ? STATS_min : lo) / 1.9; hi = (STATS_max > hi ? STATS_max : hi) * 1.25
# On the strip: the run's own marker in its upper half, the black cross (stopped) or ring (failed) under it.
mark_y = hi * (hi / lo)**0.105
cross_y = hi * (hi / lo)**0.046
# Labelled y tics within the data range only (none on the strip).
yticks = ''
do for [t in '0.02 0.03 0.05 0.07 0.1 0.15 0.2 0.3 0.5 0.7 1'] { if (t + 0 >= lo && t + 0 <= hi) { yticks = yticks.(yticks eq '' ? '' : ', ').t } }

# A run of `shape` and `integrator` that ended so (done, stopped, failed).
is(shape, integrator, ending) = strcol(1) eq shape && strcol(2) eq integrator && strcol(22) eq ending
# FE's markers larger than NPC's, so that a point where they meet shows both; the authors' β smaller and thinner
# still, drawn on top of γ = 3's.
size(shape, integrator) = (shape eq 'lme_authors' ? 0.7 : 1.0) * (integrator eq 'fe' ? 1.5 : 1.0)
style(shape, integrator) = shape eq 'lme_authors' ? \
  sprintf("lw 1 dt %d pt %d lc rgb '%s'", dash(integrator), marker(integrator), colour(shape)) : method_style(shape, integrator)
# On the strip FE lies left of NPC (the same mesh), so that two runs of one mesh stay apart; where the authors' β
# has runs on the strip too, LME's four methods side by side (γ = 3 left of the authors' β).
stats authors using (strcol(22) ne 'done' ? 1 : 0) nooutput
authors_off = STATS_sum
shift(shape, integrator) = authors_off == 0 || (shape ne 'lme' && shape ne 'lme_authors') ? (integrator eq 'fe' ? 0.83 : 1.17) : \
  word(shape eq 'lme' ? '0.57 0.74' : '0.95 1.22', integrator eq 'fe' ? 1 : 2) + 0
done_curve(file, shape, i) = sprintf("'%s' using (is('%s','%s','done') ? $3 : NaN):8 with linespoints %s ps %g title '%s'", \
  file, shape, i, style(shape, i), size(shape, i), method_name(shape, i))
# A run on the strip: its method's marker in its colour, the black cross (stopped) or ring (failed) under it.
ended(file, shape, i, ending) = sprintf("'%s' using (is('%s','%s','%s') ? $3 * shift('%s', '%s') : NaN):(mark_y) with points pt %d ps %g lc rgb '%s' notitle, ", \
  file, shape, i, ending, shape, i, marker(i), shape eq 'lme_authors' ? 1.0 : 1.3, colour(shape)). \
  sprintf("'%s' using (is('%s','%s','%s') ? $3 * shift('%s', '%s') : NaN):(cross_y) with points %s notitle", \
  file, shape, i, ending, shape, i, ending eq 'stopped' ? stopped_style : failed_style)
curves(file, shape) = done_curve(file, shape, 'fe').', '.done_curve(file, shape, 'npc').', '. \
  ended(file, shape, 'fe', 'stopped').', '.ended(file, shape, 'npc', 'stopped').', '. \
  ended(file, shape, 'fe', 'failed').', '.ended(file, shape, 'npc', 'failed')

# The runs of `shape` that ended so, as "LME γ = 3 + FE and NPC, 2560 cells" (empty if none).
ended_runs(file, shape, ending) = system(sprintf("awk -F, '$1 == \"%s\" && $22 == \"%s\" {c[$3] = c[$3] (c[$3] == \"\" ? \"\" : \" and \") toupper($2)} END {for (n in c) print n, c[n]}' %s | sort -n | awk '{n = $1; $1 = \"\"; printf \"%%s%%s, %%s cells\", (NR > 1 ? \"; \" : \"\"), substr($0, 2), n}'", shape, ending, file))
ended_text(file, shape, ending) = (r = ended_runs(file, shape, ending), r eq '' ? '' : shape_name(shape).' + '.r)
# The strip's name: every run on it, by outcome (its symbol), method and mesh.
runs_text(file, shape) = (t1 = ended_text(file, shape, 'stopped'), t2 = ended_text(file, shape, 'failed'), \
  (t1 eq '' ? '' : '× stopped: '.t1).(t1 ne '' && t2 ne '' ? '; ' : '').(t2 eq '' ? '' : '○ failed: '.t2))
strip_name(shape) = (a1 = runs_text(sweep, shape), a2 = shape eq 'lme' ? runs_text(authors, 'lme_authors') : '', \
  a1.(a1 ne '' && a2 ne '' ? '; ' : '').a2)
# The fitted order of a band, "0.32±0.03" or "no fit"; a method's three, named by the method.
order_of(shape, integrator, band) = system(sprintf("awk -F, '$1==\"%s\" && $2==\"%s\" && $3==\"%s\" {if ($4 != \"nan\" && $4 != \"-nan\") printf \"%%.2f±%%.1g\", $4, $8; else printf \"no fit\"}' %s", shape, integrator, band, orders))
orders_text(shape, i) = sprintf('%s: %s | %s | %s', method_name(shape, i), order_of(shape, i, 'negligible'), \
  order_of(shape, i, 'transition'), order_of(shape, i, 'crossing'))

# The grid-crossing bands, up to the strip; the fitted orders at the bottom left.
bands = sprintf("set object 1 rect from %g,%g to %g,%g behind fc rgb '%s' fs solid noborder; ", xlo, lo, band1, hi, c_band1). \
  sprintf("set object 2 rect from %g,%g to %g,%g behind fc rgb '%s' fs solid noborder; ", band1, lo, band2, hi, c_band2). \
  sprintf("set object 3 rect from %g,%g to %g,%g behind fc rgb '%s' fs solid noborder; ", band2, lo, xhi, hi, c_band3)
panel(shape, title, more) = "set title \"".title."\"; ".strip_log(lo, hi, strip_name(shape)).bands. \
  "set label 1 '".orders_text(shape, 'fe')."' at graph 0.03, graph 0.115 front; ". \
  "set label 2 '".orders_text(shape, 'npc')."' at graph 0.03, graph 0.05 front; ". \
  "plot ".curves(sweep, shape).more

# The difference panels: "cells,percent" of the runs of (shape a, integrator a) in file a and (shape b, integrator b)
# in file b that both ended `done`, a's RMS over b's − 1 in %, by mesh.
apart_runs(fa, sa, ia, fb, sb, ib) = sprintf("awk -F, 'FNR == NR {if ($1 == \"%s\" && $2 == \"%s\" && $22 == \"done\") b[$3] = $8; next} $1 == \"%s\" && $2 == \"%s\" && $22 == \"done\" && ($3 in b) {print $3 \",\" ($8 / b[$3] - 1) * 100}' %s %s", \
  sb, ib, sa, ia, fb, fa)
fe_npc(shape) = apart_runs(sweep, shape, 'fe', sweep, shape, 'npc')
authors_lme(i) = apart_runs(authors, 'lme_authors', i, sweep, 'lme', i)
# "L C M" of a difference: L the largest |difference|, C the smallest mesh from which every difference is within 1 %
# and M the largest there (C and M "-" where the finest mesh's is not within 1 %).
coincide(runs) = system(runs." | awk -F, '{c[NR] = $1; d[NR] = $2 < 0 ? -$2 : $2} END {m = 0; l = 0; from = \"-\"; on = 1; for (k = NR; k >= 1; k--) {if (d[k] > l) l = d[k]; if (d[k] > 1) on = 0; if (on) {if (d[k] > m) m = d[k]; from = c[k]}} printf \"%.2g %s %s\", l, from, (from == \"-\" ? \"-\" : sprintf(\"%.2g\", m))}'")
# Where a difference changes sign: "between A and B cells" (the first change), or "above 0 on every mesh".
sign_change(runs) = system(runs." | awk -F, 'NR > 1 && ($2 > 0) != (p > 0) && t == \"\" {t = \"changes sign between \" c \" and \" $1 \" cells\"} {c = $1; p = $2} END {print (t != \"\" ? t : (p > 0 ? \"above 0 on every mesh\" : \"below 0 on every mesh\"))}'")
# The range of a difference panel (all its curves), widened by a tenth.
diff_lo = 0; diff_hi = 0
widen(runs) = system(runs." | awk -F, 'BEGIN {lo = 0; hi = 0} {if ($2 < lo) lo = $2; if ($2 > hi) hi = $2} END {print lo, hi}'")
do for [r in 'linear ugimp'] { span = widen(fe_npc(r)); diff_lo = (word(span, 1) + 0 < diff_lo ? word(span, 1) + 0 : diff_lo); diff_hi = (word(span, 2) + 0 > diff_hi ? word(span, 2) + 0 : diff_hi) }
pad = 0.1 * (diff_hi - diff_lo); diff_lo = diff_lo - pad; diff_hi = diff_hi + pad
zero = sprintf("0 with lines lw 1 lc rgb '%s' notitle", c_context)
# A difference curve, `runs` the expression (text) of its command (no key entry: its style is the method's of the
# key, its quantity the y label's).
diff_curve(runs, style) = sprintf("('< '.%s) using 1:2 with linespoints %s notitle", runs, style)

# Panels' places (screen fractions): three columns, each a panel over its difference panel; the key below.
column_left(k) = 0.055 + (k - 1) * 0.32
place(k, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; set tmargin at screen %g; ", \
  column_left(k), column_left(k) + 0.27, bottom, top)
top_panel(k) = place(k, 0.43, 0.82)."set xlabel ''; set format x ''; set logscale y; ".sprintf("set ytics (%s); ", yticks)
diff_panel(k) = place(k, 0.2, 0.41).unstrip."unset title; unset label 1; unset label 2; unset logscale y; set ytics autofreq; set format x '%g'; set xlabel 'cells'; ". \
  "unset object 1; unset object 2; unset object 3; ". \
  sprintf("set object 4 rect from %g, graph 0 to %g, graph 1 behind fc rgb '%s' fs solid noborder; ", xlo, band1, c_band1). \
  sprintf("set object 5 rect from %g, graph 0 to %g, graph 1 behind fc rgb '%s' fs solid noborder; ", band1, band2, c_band2). \
  sprintf("set object 6 rect from %g, graph 0 to %g, graph 1 behind fc rgb '%s' fs solid noborder; ", band2, xhi, c_band3)
back_to_top = "unset object 4; unset object 5; unset object 6; "
shape_diff(k, shape) = diff_panel(k).sprintf("set yrange [%g:%g]; set ylabel 'FE / NPC − 1 (%%)'; ", diff_lo, diff_hi). \
  "plot ".diff_curve("fe_npc('".shape."')", method_style(shape, 'fe')).", ".zero

# make figures runs the authors' β to 640 cells (every mesh in make studies): the panel's title says where its
# curves end (authors_last, the largest mesh in dyka_sweep_authors.csv).
stats authors using 3 nooutput
authors_last = int(STATS_max)
npc_same = coincide(authors_lme('npc'))
fe_same = coincide(authors_lme('fe'))
same_text(c) = word(c, 2) eq '-' ? 'apart on every mesh' : sprintf('within %s %% from %s cells', word(c, 3), word(c, 2))
key_text(i, c) = sprintf('%s: |Δ| ≤ %s %%', integrator_name(i), word(c, 1)). \
  (word(c, 2) eq '-' || word(c, 2) + 0 == authors_last ? '' : sprintf('; ≤ %s %% from %s cells', word(c, 3), word(c, 2)))
lme_title = sprintf("LME: γ = 3 and the authors’ β (to %d cells)\\nNPC under both β %s (below)", authors_last, same_text(npc_same))
lme_more = ", ".curves(authors, 'lme_authors')
# Its range leaves the top right free for the key (the differences there are small).
span = widen("{ ".authors_lme('fe')."; ".authors_lme('npc')."; }")
lme_range = sprintf("set yrange [%g:%g]; ", word(span, 1) - 1, word(span, 2) * 1.8)
lme_diff = diff_panel(3).lme_range."set ylabel 'authors’ β / γ = 3 − 1 (%)'; set key inside top right Left reverse samplen 3 width -9; ". \
  "plot ".sprintf("('< '.authors_lme('fe')) using 1:2 with linespoints %s title '%s', ", style('lme_authors', 'fe'), key_text('fe', fe_same)). \
  sprintf("('< '.authors_lme('npc')) using 1:2 with linespoints %s title '%s', ", style('lme_authors', 'npc'), key_text('npc', npc_same)).zero
shape_title(shape) = shape_name(shape)."\\nFE / NPC − 1 ".sign_change(fe_npc(shape))." (below)"
# The key of the method curves, below the panels.
method_key = "set key at graph 0.5, screen 0.08 center top maxrows 2 Left reverse samplen 3 width 1 noopaque; "

fig_title = "Fig. 6: RMS of v_A (Eq. 43) / |v_0| against the number of cells (CFL 0.5); shading: grid-crossing band "
fig_title = fig_title."(light: negligible, middle: transition, dark: crossing)\nPrinted: fitted order ± s.e. per band "
fig_title = fig_title."(negligible | transition | crossing). Strip above the data: × stopped by the solver, ○ failed "
fig_title = fig_title."(RMS no smaller than a flat line's),\nthe method's marker above it, FE left of NPC. FE's markers are drawn "
fig_title = fig_title."larger, under NPC's; the authors' β smaller, over γ = 3's.\nBelow, in %, for the runs that finished under both: "
fig_title = fig_title."FE's RMS over NPC's − 1 (linear, uGIMP); the authors' β's RMS over γ = 3's − 1, per integrator (LME)"
draw = "set multiplot title fig_title; ". \
  sprintf("set logscale x; set xrange [%g:%g]; ", xlo, xhi). \
  "set ylabel 'RMS / |v_0|'; ".method_key.top_panel(1).panel('linear', shape_title('linear'), '')."; ".shape_diff(1, 'linear')."; ". \
  back_to_top."set ylabel ''; ".method_key.top_panel(2).panel('ugimp', shape_title('ugimp'), '')."; ".shape_diff(2, 'ugimp')."; ". \
  back_to_top."set ylabel ''; ".method_key.top_panel(3).panel('lme', lme_title, lme_more)."; ".lme_diff."; unset multiplot"
load dir."/output.gp"
