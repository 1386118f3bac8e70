# Fig. 6: RMS of v_A / |v_0| against the number of cells (CFL 0.5), one panel per shape function, forward Euler (FE)
# and the predictor-corrector (NPC) in the method style of palette.gp (the shape's colour, the integrator's dash and
# marker; FE's markers drawn larger, under NPC's, so that both show where they meet). The background is shaded by
# the grid-crossing band of paper/08_test_cases.md (c_band1: negligible, c_band2: transition, c_band3: crossing);
# the fitted order of each band ± its standard error is printed on the panel, named by its method ('no fit': a band
# with fewer than 3 finished runs). Only runs that ended `done` are drawn as values; a run the solver stopped (×) or
# one no better than a flat line (failed, ○) is drawn on the strip above the data (common.gp), its method's marker in
# its colour inside the black cross or ring, FE left of NPC, and named (method and mesh) on the strip.
# LME's panel also holds its runs under the authors' β (lme_authors colour, the integrator's filled markers, drawn
# smaller and thinner on top of γ = 3's so that both show where they meet).
# Reads dyka_sweep.csv and dyka_sweep_authors.csv (column 1 shape, 2 integrator, 3 cells, 8 rms_over_v0, 22 ending:
# done, failed or stopped) and dyka_orders.csv (shape, integrator, band, order, ..., standard_error).
# gnuplot -e "dir='...'; data='...'; out='...'; orders='.../dyka_orders.csv'" dyka_fig6.gp
load dir."/common.gp"
w = 12.5; h = 5.2
sweep = data.'/dyka_sweep.csv'; authors = data.'/dyka_sweep_authors.csv'
band1 = 0.1 / (3.298e-5 / (0.5 * 0.1333)); band2 = 1.0 / (3.298e-5 / (0.5 * 0.1333))
xlo = 7; xhi = 3600
# The y range holds every finished run's RMS (both files); the bottom leaves room for the fitted orders.
stats sweep using (strcol(22) eq 'done' ? $8 : NaN) nooutput
lo = STATS_min; hi = STATS_max
stats authors using (strcol(22) eq 'done' ? $8 : NaN) nooutput
lo = (STATS_min < lo ? STATS_min : lo) / 1.9; hi = (STATS_max > hi ? STATS_max : hi) * 1.25
ystrip = strip_y_log(lo, hi)
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
# On the strip FE lies left of NPC (the same mesh), so that two runs of one mesh stay apart.
shift(integrator) = integrator eq 'fe' ? 0.86 : 1.16
done_curve(file, shape, i) = sprintf("'%s' using (is('%s','%s','done') ? $3 : NaN):8 with linespoints %s ps %g title '%s'", \
  file, shape, i, style(shape, i), size(shape, i), method_name(shape, i))
# A run on the strip: its method's marker in its colour, the black cross (stopped) or ring (failed) over it.
ended(file, shape, i, ending) = sprintf("'%s' using (is('%s','%s','%s') ? $3 * shift('%s') : NaN):(ystrip) with points pt %d ps 1 lc rgb '%s' notitle, ", \
  file, shape, i, ending, i, marker(i), colour(shape)). \
  sprintf("'%s' using (is('%s','%s','%s') ? $3 * shift('%s') : NaN):(ystrip) with points %s notitle", \
  file, shape, i, ending, i, ending eq 'stopped' ? stopped_style : failed_style)
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

# make figures runs the authors' β to 640 cells (every mesh in make studies): the panel's title says where its
# curves end (authors_last, the largest mesh in dyka_sweep_authors.csv).
stats authors using 3 nooutput
authors_last = int(STATS_max)
lme_title = sprintf("LME: γ = 3 and the authors’ β (to %d cells)\\nNPC under both β coincide from 40 cells", authors_last)
lme_more = ", ".curves(authors, 'lme_authors')

fig_title = "Fig. 6: RMS of v_A (Eq. 43) / |v_0| against the number of cells (CFL 0.5); shading: grid-crossing band "
fig_title = fig_title."(light: negligible, middle: transition, dark: crossing)\nPrinted: fitted order ± s.e. per band "
fig_title = fig_title."(negligible | transition | crossing). Strip above the data: × stopped by the solver, ○ failed "
fig_title = fig_title."(RMS no smaller than a flat line's),\nthe method's marker inside, FE left of NPC. FE and NPC meet near 320 cells: "
fig_title = fig_title."FE's markers are drawn larger, under NPC's; the authors' β smaller, over γ = 3's"
draw = "set multiplot layout 1,3 title fig_title margins 0.055, 0.965, 0.24, 0.8 spacing 0.05, 0.1; ". \
  sprintf("set logscale xy; set xrange [%g:%g]; set ytics (%s); ", xlo, xhi, yticks). \
  "set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set key at graph 0.5, screen 0.1 center top maxrows 2 Left reverse samplen 3 width 1; ". \
  panel('linear', 'linear (Q4)', '')."; set ylabel ''; ".panel('ugimp', 'uGIMP', '')."; ". \
  panel('lme', lme_title, lme_more)."; unset multiplot"
load dir."/output.gp"
