# Speed against accuracy (beyond the paper): RMS of v_A / |v0| against the CPU time of each run (one thread), in three
# panels by integrator: forward Euler (FE), the predictor-corrector (NPC), and forward Euler with the stress updated
# last (USL) or modified (MUSL); each method in its palette style (colour: shape; dash and marker: integrator). The
# paper's methods (linear, uGIMP, LME gamma = 3) over the mesh sweep (data/dyka_sweep.csv, 10 ... 2560 cells, one run
# each); today's baselines (B-splines 2 and 3, LME gamma = 0.8 and 1.5, USL, MUSL) on 40, 160, 640 cells, the cubic
# B-spline also on 2560 (data/dyka_baselines.csv). A method's runs are joined by a line up to the grid-crossing band
# (2560 cells: a point of its own). Horizontal bars: fastest to slowest of 5 interleaved repeats (40 and 160 cells;
# for the paper's methods a bar without a marker beside the sweep's point); a baseline's single timing (640, 2560
# cells) widened by the largest spread of the 160-cell repeats, the margin the front asks of it; the title says how
# wide they are at most (a few per cent: within a marker). Boxed: the runs on their mesh's error-cost front (column
# pareto, computed by dyka_suite: no method both more accurate and faster by more than the measured spread). Top axis:
# each mesh at the (geometric) middle of its completed runs' CPU times. The runs that stopped (status failed) and
# those no better than a flat line (the sweep's ending failed) are drawn on the strip above the data at their own CPU
# time (which may lie under another mesh's number), their method's marker above a black cross (stopped) or ring
# (failed), each named in the key with its mesh and CPU time. Under the FE and NPC panels, each method's RMS against
# LME gamma = 3's with the same integrator on the same mesh (per cent, where both completed before the crossing band),
# since the methods lie within a marker of each other above; the title names the methods that stay within a line's
# width of LME there. B-spline 2 equals uGIMP on this bar (1 particle per cell) to a few parts in a million: it is
# drawn with a larger marker, beneath the others, and the titles say so.
load dir."/common.gp"
w = 13.3; h = 10.5
sweep = data.'/dyka_sweep.csv'
baselines = data.'/dyka_baselines.csv'
lo = 0.05; hi = 0.36
# On the strip: the method's marker in its upper half, the black cross or ring below it (so that both read).
top = hi * (hi / lo)**0.1
outcome = hi * (hi / lo)**0.04
stats sweep using ($3 * (strcol(6) eq 'crossing' ? 1 : NaN)) nooutput
crossing = STATS_min  # the first mesh of the grid-crossing band

# A baseline's key "shape_integrator": its shape and integrator (lme3 is LME gamma = 3).
s_of(m) = m[1:strstrt(m, "_") - 1]
i_of(m) = m[strstrt(m, "_") + 1:]
paper(s) = (s eq 'linear' || s eq 'ugimp' || s eq 'lme' || s eq 'lme3')
# The panels: their integrators and today's methods (the paper's shapes come from the sweep).
integrators(p) = p == 3 ? "usl musl" : word("fe npc", p)
in_panel(i, p) = strstrt(" ".integrators(p)." ", " ".i." ") > 0
sweep_shapes = "linear ugimp lme"
base_methods(p) = p == 1 ? "bspline2_fe bspline3_fe lme0.8_fe lme1.5_fe" : p == 2 ? \
  "bspline2_npc bspline3_npc lme0.8_npc lme1.5_npc" : "linear_usl linear_musl bspline2_usl bspline2_musl"
MS = "lw method_lw dt dash(i) pt marker(i) lc rgb colour(s)"                  # a sweep method (s, i)
BS = "lw method_lw dt dash(i_of(m)) pt marker(i_of(m)) ps size(m) lc rgb colour(s_of(m))"  # a baseline m
size(m) = m eq 'bspline2_fe' || m eq 'bspline2_npc' ? 2.0 : 1.1   # B-spline 2, which equals uGIMP here, larger and beneath
BL = "lw method_lw dt dash(i_of(m)) lc rgb colour(s_of(m))"                     # its line

# The runs with no value, one key entry each (built here from the data).
sweep_off(p, what) = in_panel(strcol(2), p) && (what eq 'stopped' ? strcol(12) ne 'ok' : strcol(12) eq 'ok' && strcol(22) eq 'failed')
base_off(p) = in_panel(i_of(strcol(1)), p) && !paper(s_of(strcol(1))) && strcol(6) ne 'ok'
add(style, what, s, i, n, t) = (entries = entries.sprintf(", keyentry with points %s title '%s: %s, %d cells, %.3g s CPU'", style, what, method_name(s, i), n, t), 1)
do for [p = 1:3] {
  entries = ''
  stats sweep using (sweep_off(p, 'stopped') ? add(stopped_style, 'stopped by the solver', strcol(1), strcol(2), $3, $17) : 0) nooutput
  stats baselines using (base_off(p) ? add(stopped_style, 'stopped by the solver', s_of(strcol(1)), i_of(strcol(1)), $2, $8) : 0) nooutput
  stats sweep using (sweep_off(p, 'failed') ? add(failed_style, 'failed, no better than flat', strcol(1), strcol(2), $3, $17) : 0) nooutput
  eval(sprintf("strip_entries%d = entries", p))
}

# The top axis: each mesh at the middle (geometric) of its completed runs' CPU times.
meshes = "10 20 40 80 160 320 640 1280 2560"
mesh_tics = ''
do for [k = 1:words(meshes)] {
  n = word(meshes, k) + 0
  stats sweep using ($3 == n && strcol(22) eq 'done' ? $17 : NaN) nooutput
  mesh_tics = mesh_tics.sprintf("%s'%d' %.6g", k > 1 ? ', ' : '', n, sqrt(STATS_min * STATS_max))
}

# Segments joining a baseline's runs (its rows are not adjacent in the file): seg(k, x, y) is the previous run's x
# (NaN for the first) and sets y0, its y; the state is reset at each file's first row.
px = NaN; py = NaN; x0 = NaN; y0 = NaN
seg_reset(r) = (r == 0 ? (px = NaN, py = NaN) : 0)
seg(k, x, y) = (seg_reset(column(0)), k ? (x0 = px, y0 = py, px = x, py = y, x0) : NaN)

sweep_ok_ = "strcol(12) eq 'ok' && strcol(22) ne 'failed' && $3 < crossing"
# LME gamma = 3's RMS per integrator and mesh (" i:cells:rms" words, the sweep's completed runs before the
# crossing band), the reference of the panels under FE and NPC; ratio(i, n, r) is a run's RMS r against it (%).
lme_list = ''
addref(i, n, r) = (lme_list = lme_list.sprintf(' %s:%d:%.12g', i, n, r), 1)
stats sweep using (strcol(1) eq 'lme' && strcol(12) eq 'ok' && strcol(22) eq 'done' && $3 < crossing ? addref(strcol(2), $3, $8) : 0) nooutput
tag(i, n) = sprintf(' %s:%d:', i, n)
ref(i, n) = strstrt(lme_list, tag(i, n)) == 0 ? NaN : real(lme_list[strstrt(lme_list, tag(i, n)) + strlen(tag(i, n)):])
ratio(i, n, r) = 100 * (r / ref(i, n) - 1)
# Per integrator: how far linear, uGIMP and B-spline 2 lie from LME from 40 cells on (the largest, per cent), and
# how far B-spline 2 lies from uGIMP (relative, on the baselines' meshes).
do for [i in "fe npc"] {
  stats sweep using (strcol(2) eq i && (strcol(1) eq 'linear' || strcol(1) eq 'ugimp') && @sweep_ok_ && $3 >= 40 ? abs(ratio(i, $3, $8)) : NaN) nooutput prefix "W"
  within = W_max
  stats baselines using (strcol(1) eq 'bspline2_'.i && strcol(6) eq 'ok' && $2 >= 40 ? abs(ratio(i, $2, $3)) : NaN) nooutput prefix "W"
  eval(sprintf("within_%s = %.12g", i, W_max > within ? W_max : within))
  gap = 0
  do for [n in "40 160 640"] {
    stats baselines using (strcol(1) eq 'bspline2_'.i && $2 == n ? $3 : NaN) nooutput prefix "B"
    stats baselines using (strcol(1) eq 'ugimp_'.i && $2 == n ? $3 : NaN) nooutput prefix "U"
    gap = abs(B_max / U_max - 1) > gap ? abs(B_max / U_max - 1) : gap
  }
  eval(sprintf("gap_%s = %.12g", i, gap))
}
# The largest spread of the repeated timings (per cent): the horizontal bars.
stats baselines using ($11 > 1 && strcol(6) eq 'ok' ? 100 * ($10 / $9 - 1) : NaN) nooutput prefix "R"
bars = R_max

# The curves of a panel.
sweep_ok = "strcol(12) eq 'ok' && strcol(22) ne 'failed'"
sweep_curves(p) = sprintf("for [s in sweep_shapes] for [i in '%s'] sweep using (strcol(1) eq s && strcol(2) eq i && %s && $3 < crossing ? $17 : NaN):8 with linespoints ps 1.1 @MS notitle, ", integrators(p), sweep_ok).\
  sprintf("for [s in sweep_shapes] for [i in '%s'] sweep using (strcol(1) eq s && strcol(2) eq i && %s && $3 >= crossing ? $17 : NaN):8 with points ps 1.1 @MS notitle, ", integrators(p), sweep_ok).\
  sprintf("for [s in 'linear ugimp lme3'] for [i in '%s'] baselines using (strcol(1) eq s.'_'.i && strcol(6) eq 'ok' && $11 > 1 ? $8 : NaN):3:9:10 with xerrorbars ps 0 lw 1.5 lc rgb colour(s) notitle, ", integrators(p))
base_curves(p) = sprintf("for [m in '%s'] baselines using (strcol(1) eq m && strcol(6) eq 'ok' ? $8 : NaN):3:9:10 with xerrorbars @BS notitle, ", base_methods(p)).\
  sprintf("for [m in '%s'] baselines using (seg(strcol(1) eq m && strcol(6) eq 'ok' && $2 < crossing, $8, $3)):(y0):($8 - x0):($3 - y0) with vectors nohead @BL notitle, ", base_methods(p))
front(p) = sprintf("baselines using (strcol(6) eq 'ok' && $7 == 1 && in_panel(i_of(strcol(1)), %d) ? $8 : NaN):3 with points ".front_style." notitle, ", p)
# On the strip: the method's marker in its colour, the black cross or ring under it.
strip_points(p) = sprintf("for [s in sweep_shapes] for [i in '%s'] sweep using (strcol(1) eq s && strcol(2) eq i && (sweep_off(%d, 'stopped') || sweep_off(%d, 'failed')) ? $17 : NaN):(top) with points ps 1.1 pt marker(i) lc rgb colour(s) notitle, ", integrators(p), p, p).\
  sprintf("for [m in '%s'] baselines using (strcol(1) eq m && base_off(%d) ? $8 : NaN):(top) with points ps 1.1 pt marker(i_of(m)) lc rgb colour(s_of(m)) notitle, ", base_methods(p), p).\
  sprintf("sweep using (sweep_off(%d, 'stopped') ? $17 : NaN):(outcome) with points %s notitle, baselines using (base_off(%d) ? $8 : NaN):(outcome) with points %s notitle, ", p, stopped_style, p, stopped_style).\
  sprintf("sweep using (sweep_off(%d, 'failed') ? $17 : NaN):(outcome) with points %s notitle", p, failed_style)
# The key: each method in its style with its meshes, the front, the grey context, the runs on the strip.
do for [p = 1:3] {
  entries = ''
  if (p < 3) { do for [s in sweep_shapes] {
    i = integrators(p)
    stats sweep using (strcol(1) eq s && strcol(2) eq i ? $3 : NaN) nooutput
    entries = entries.sprintf(", keyentry with linespoints ps 1.1 %s title '%s (%d-%d cells)'", method_style(s, i), method_name(s, i), STATS_min, STATS_max)
  } }
  do for [m in base_methods(p)] {
    stats baselines using (strcol(1) eq m ? $2 : NaN) nooutput
    entries = entries.sprintf(", keyentry with linespoints ps %g %s title '%s (%d-%d cells)%s'", size(m), method_style(s_of(m), i_of(m)), method_name(s_of(m), i_of(m)), STATS_min, STATS_max, size(m) > 1.1 ? ', larger: equals uGIMP' : '')
  }
  eval(sprintf("method_entries%d = entries", p))
}
keys(p) = (p < 3 ? '' : ", keyentry with lines lw 1 lc rgb c_context title 'the paper''s methods (left panels)'").value(sprintf("method_entries%d", p)).\
  ", keyentry with points ".front_style." title 'boxed: on its mesh''s error-cost front'".value(sprintf("strip_entries%d", p))
context = "for [s in sweep_shapes] for [i in 'fe npc'] sweep using (strcol(1) eq s && strcol(2) eq i && ".sweep_ok." && $3 < crossing ? $17 : NaN):8 with lines lw 1 lc rgb c_context notitle, "
panel_title(p) = p == 1 ? 'forward Euler (FE)' : p == 2 ? 'predictor-corrector (NPC)' : 'FE, stress updated last (USL) or modified (MUSL)'
panel(p) = sprintf("set title '%s' offset 0,0.6; ", panel_title(p)).strip_log(lo, hi, 'no value: stopped (×), failed (○)').\
  "plot ".(p == 3 ? context : '').base_curves(p).(p == 3 ? '' : sweep_curves(p)).front(p).strip_points(p).keys(p)

# The panels under FE and NPC: each run's RMS against LME gamma = 3's on its mesh, baselines first (B-spline 2
# beneath), LME itself on 0.
ratio_title(p) = (i = integrators(p), sprintf("%s: RMS against LME γ = 3 + %s on the same mesh%s\nB-spline 2 + %s equals uGIMP + %s to %.0e: drawn larger", \
  integrator_name(i), integrator_name(i), value('within_'.i) < 0.5 ? sprintf(";\nfrom 40 cells linear, uGIMP, B-spline 2 within %.2f %% of it", value('within_'.i)) : '', \
  integrator_name(i), integrator_name(i), value('gap_'.i)))
ratio_curves(p) = sprintf("i = '%s'; B = '%s'; ", integrators(p), base_methods(p)).\
  "plot for [m in B] baselines using (strcol(1) eq m && strcol(6) eq 'ok' && ref(i, $2) == ref(i, $2) ? $8 : NaN):(ratio(i, $2, $3)) with points @BS notitle, ".\
  "for [m in B] baselines using (seg(strcol(1) eq m && strcol(6) eq 'ok' && ref(i, $2) == ref(i, $2), $8, ratio(i, $2, $3))):(y0):($8 - x0):(ratio(i, $2, $3) - y0) with vectors nohead @BL notitle, ".\
  "for [s in sweep_shapes] sweep using (strcol(1) eq s && strcol(2) eq i && @sweep_ok_ && ref(i, $3) == ref(i, $3) ? $17 : NaN):(ratio(i, $3, $8)) with linespoints ps 1.1 @MS notitle"
ratio_panel(p) = sprintf("set title '%s' offset 0,0; ", ratio_title(p)).unstrip."unset x2tics; unset x2label; set x2tics; unset x2tics; unset logscale y; set yrange [*:*]; set ytics auto; set offsets 0, 0, graph 0.06, graph 0.06; ".\
  "set ylabel 'RMS / LME γ = 3''s - 1 (%)'; set key off; ".ratio_curves(p)."; set offsets 0, 0, 0, 0"

col(k) = sprintf("set lmargin at screen %s; set rmargin at screen %s; ", word("0.055 0.385 0.715", k), word("0.31 0.64 0.97", k))
top_row = "set tmargin at screen 0.87; set bmargin at screen 0.55; "
ratio_row = "set tmargin at screen 0.43; set bmargin at screen 0.25; "
key_at(k) = sprintf("set key at screen %s, screen %s left top Left reverse vertical samplen 2.5 noenhanced; ", word("0.055 0.385 0.715", k), k == 3 ? "0.43" : "0.18")
axes = "set logscale xy; set xrange [1e-4:20]; set x2range [1e-4:20]; set logscale x2; set xtics nomirror; set format x '10^{%L}'; ".\
  sprintf("set x2tics (%s) nomirror; set x2label 'cells: the middle of each mesh''s completed runs\n(the strip''s runs at their own CPU time, named in the key)' offset 0,-0.4; ", mesh_tics).\
  "set xlabel 'CPU time per run (s)'; set ytics (0.05, 0.07, 0.1, 0.15, 0.2, 0.3) nomirror; set ylabel 'RMS of v_A / |v_0|'; "
title = sprintf("Speed against accuracy on the Dyka bar (CFL 0.5): RMS of v_A / |v_0| against the CPU time of each run (one thread), one panel per integrator;\nhorizontal bars: fastest to slowest of the repeated timings, at most %.1f %% apart, within a marker at this scale", bars)
draw = "set multiplot title title; ".\
  axes.col(1).top_row.key_at(1).panel(1)."; ".axes.col(2).top_row.key_at(2).panel(2)."; ".axes.col(3).top_row.key_at(3).panel(3)."; ".\
  col(1).ratio_row.ratio_panel(1)."; ".col(2).ratio_row.ratio_panel(2)."; unset multiplot"
load dir."/output.gp"
