# The vibrating bar (data/smooth_bar.csv), at the amplitude `amplitude` (small: against the exact first mode; large:
# against the finite-strain reference): RMS error of the velocity (rows 1 and 3) and of the stress (rows 2 and 4)
# against the number of cells. One panel per shape function, in its colour (palette.gp): the paper's (linear, uGIMP,
# LME γ = 3; rows 1-2) and today's baselines at CFL 0.5 (B-splines 2 and 3, linear with USL and MUSL; rows 3-4). In a
# panel the integrator is the dash and the marker (FE solid with circles, NPC dashed with squares, USL and MUSL with
# triangles); 1 particle per cell filled markers, 2 open ones, drawn larger so that a filled one on the same value
# shows inside; at small amplitude the paper's shapes also at CFL 0.1, thin lines with small markers (CFL 0.5: the
# usual lines). Grey dotted: slopes 1 and 2. A run that stopped (black cross) or ended no better than a flat field
# (failed, black ring) lies on the strip above the data, its method's marker inside, at its mesh: the strip has one
# row per series of the panel (from the top: the first integrator at 1 and 2 ppc, then the second), each row with
# a run named at its left ("FE, 1 ppc"). The velocity rows share one y range, the stress rows another, each the
# range of its data; the legend lies below the panels.
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
h = (outcomes > 0 ? 13.5 : 12)  # taller with the strip's rows, so that the data keep their height
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
# The strip: one row per series of a panel, k = 1 (top) to 4: the first integrator at 1 and 2 ppc, then the second;
# each run at its mesh. A row is named at its left when it holds a run (count_SHAPE_INTEGRATOR_PPC: its runs there).
rows = 4
row_share = 0.1  # a row's height, as a share of the data's (log) height
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
inside(s, i) = sprintf("pt (p == 1 ? %d : %d) ps 1.2 lc rgb '%s'", marker(i), open(marker(i)), colour(s))
on_strip(s, i, first, kind, lo, hi, how) = sprintf("for [p = 1:2] sweep using (off('%s', '%s', p, '%s') ? $6 : NaN):(row_y(%.12g, %.12g, %d + p)) with points %s", s, i, kind, lo, hi, first ? 0 : 2, how)
strip_runs(s, i, first, lo, hi) = (outcomes == 0 ? '' : sprintf(", %s, %s, %s, %s", on_strip(s, i, first, 'stopped', lo, hi, stopped_style), on_strip(s, i, first, 'failed', lo, hi, failed_style), \
  on_strip(s, i, first, 'stopped', lo, hi, inside(s, i)), on_strip(s, i, first, 'failed', lo, hi, inside(s, i))))
guides = sprintf(", 0.05 * (x / 8)**-1 with lines %s, 0.05 * (x / 8)**-2 with lines %s", reference_style, reference_style)
strip_top(lo, hi) = hi * (hi / lo)**(row_share * rows)
# the y tics: every decade up to hi, none on the strip
decades(lo, hi) = sprintf("set ytics %.12g, 10, %.12g; ", 10**floor(log10(lo)), hi)
yrange(lo, hi) = unname . decades(lo, hi) . (outcomes > 0 ? sprintf("set yrange [%.12g:%.12g]; ", lo, strip_top(lo, hi)) . strip_common(hi, strip_top(lo, hi), hi, '') : \
  sprintf("set yrange [%.12g:%.12g]; ", lo, hi).unstrip)
# One panel: shape s with integrators i1 and i2; col 7 (velocity) or 8 (stress).
panel(s, i1, i2, col, title) = sprintf("set title '%s'; set ylabel '%s'; ", title, col == 7 ? 'RMS(v_p - v) / V' : 'RMS(σ_p - σ) / ZV') . \
  (col == 7 ? yrange(vlow, vhigh) . row_names(s, i1, i2, vlow, vhigh) : yrange(slow, shigh) . row_names(s, i1, i2, slow, shigh)) . "plot " . curves(s, i1, col) . ", " . curves(s, i2, col) . guides . \
  strip_runs(s, i1, 1, col == 7 ? vlow : slow, col == 7 ? vhigh : shigh) . strip_runs(s, i2, 0, col == 7 ? vlow : slow, col == 7 ? vhigh : shigh)
quantity(col) = (col == 7 ? 'velocity' : 'stress')
paper_row(col) = panel('linear', 'fe', 'npc', col, shape_name('linear').': '.quantity(col).', FE and NPC') . "; " . \
  panel('ugimp', 'fe', 'npc', col, shape_name('ugimp').': '.quantity(col).(small ? ', the same numbers as linear' : '')) . "; " . \
  panel('lme', 'fe', 'npc', col, shape_name('lme').': '.quantity(col)) . "; "
baseline_row(col) = panel('bspline2', 'fe', 'npc', col, 'baseline '.shape_name('bspline2').': '.quantity(col)) . "; " . \
  panel('bspline3', 'fe', 'npc', col, 'baseline '.shape_name('bspline3').': '.quantity(col)) . "; " . \
  panel('linear', 'usl', 'musl', col, 'baseline '.shape_name('linear').': '.quantity(col).', USL and MUSL'.(small ? ' (they coincide)' : '')) . "; "
neutral(i) = sprintf("lw %g dt %d pt %d lc rgb '%s'", method_lw, dash(i), marker(i), c_exact)
legend = sprintf("keyentry with linespoints %s title 'FE: solid, circles', keyentry with linespoints %s title 'NPC: dashed, squares', ", neutral('fe'), neutral('npc')) . \
  sprintf("keyentry with linespoints %s title 'USL: triangles up', keyentry with linespoints %s title 'MUSL: triangles down', ", neutral('usl'), neutral('musl')) . \
  sprintf("keyentry with points pt %d lc rgb '%s' title '1 ppc: filled markers', keyentry with points pt %d ps 1.5 lc rgb '%s' title '2 ppc: open, larger', ", marker('fe'), c_exact, open(marker('fe')), c_exact) . \
  (small ? sprintf("keyentry with linespoints lw %g pt %d lc rgb '%s' title 'CFL 0.5', keyentry with linespoints lw 0.8 pt %d ps 0.6 lc rgb '%s' title 'CFL 0.1: thin, small markers', ", method_lw, marker('fe'), c_exact, marker('fe'), c_exact) : '') . \
  "keyentry with lines ".reference_style." title 'slopes 1 and 2'" . \
  (stops > 0 ? ", keyentry with points ".stopped_style." title 'stopped (its method’s marker inside)'" : '') . \
  (fails > 0 ? ", keyentry with points ".failed_style." title 'failed: no better than a flat field'" : '')
legend_panel = "set lmargin at screen 0.02; set rmargin at screen 0.99; set bmargin at screen 0.005; set tmargin at screen 0.075; unset logscale; unset border; unset tics; unset grid; " . \
  "unset title; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; " . unstrip . unname . "set key inside left top horizontal Left reverse samplen 3 maxrows 3; plot -1, " . legend
note = (small ? 'coinciding: NPC at 1 and 2 ppc, and B-spline 3 + FE at 1 and 2 ppc (velocity: the filled marker inside the open one); FE at CFL 0.5 and 0.1 (stress: the thin line on the thick one)' : \
  'rows 1-2: the paper’s shape functions, rows 3-4: today’s baselines; all at CFL 0.5')
draw = "set border; set tics; set grid; set lmargin -1; set rmargin -1; set bmargin -1; set tmargin -1; set key off; " . \
  sprintf("set multiplot layout 4,3 title '%s\n%s' margins 0.06, 0.99, 0.11, 0.935 spacing 0.06, 0.07; set logscale xy; set format y '10^{%%L}'; set xrange [%g:%g]; set xtics (8, 16, 32, 64, 128, 256); set xlabel 'cells'; ", caption, note, xlow, xhigh) . \
  paper_row(7) . paper_row(8) . baseline_row(7) . baseline_row(8) . legend_panel . "; unset multiplot; set border; set tics; set grid"
load dir."/output.gp"
