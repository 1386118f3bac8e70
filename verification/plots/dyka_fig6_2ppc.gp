# Fig. 6 at 2 particles per cell: RMS of v_A / |v_0| against the number of cells (CFL 0.5, 200 µs), one panel per
# shape function of the paper (linear, uGIMP, LME gamma = 3) with FE and NPC at 1 particle per cell (the Dyka suite's
# sweep, data/dyka_sweep.csv: filled markers) and at 2 (data/dyka_2ppc.csv: open markers), and a fourth panel with
# today's baselines at 2 ppc (160 and 1280 cells; LME gamma = 3 + NPC for reference), their points spread to the right
# of their mesh so that each shows. Each method in its palette style (colour: shape; dash and marker: integrator). A
# line joins a method's runs on adjacent meshes (twice as many cells) on the same side of the start of grid crossing
# (crossing ratio of paper/08_test_cases.md = 1, from the files' crossing_ratio column: 1011 cells at 2 ppc, 2021 at 1
# ppc; dotted verticals, named from the top of the data down); elsewhere the runs are points. The figure's title names
# the meshes of each (1 ppc: the whole sweep; 2 ppc: the 2-ppc study's), and a shape's title the 2-ppc runs of the
# study's meshes that were not made (from the file: linear and uGIMP + NPC at 2560 cells, a choice of cost). Runs that
# stopped (status) and runs no better than a flat line (ending failed) are drawn on the strip above the data (the
# run's own marker, filled 1 ppc or open 2 ppc, above a black cross (stopped) or ring (failed); a mesh's runs side by
# side, 1 ppc left of 2 ppc, FE left of NPC), each named in its panel's key. The baselines' panel's title names the
# baselines' runs at 160 or 1280 cells that are not in the file (not run). The same runs as data/dyka_fig6_2ppc.csv
# (written by smooth_suite --fig6-2ppc), read from the files that say which failed.
# gnuplot -e "dir='...'; data='...'; out='...'" dyka_fig6_2ppc.gp
load dir."/common.gp"
w = 13.3; h = 10.4
one = data.'/dyka_sweep.csv'; two = data.'/dyka_2ppc.csv'
# Columns of the two files: shape, integrator, cells, crossing ratio, RMS / |v0|, status, ending.
S1 = "1 2 3 5 8 12 22"; S2 = "1 2 3 4 5 8 13"
c(p, k) = word(p == 1 ? S1 : S2, k) + 0
file(p) = p == 1 ? one : two
done(p) = strcol(c(p, 6)) eq 'ok' && strcol(c(p, 7)) ne 'failed'
off(p, what) = what eq 'stopped' ? strcol(c(p, 6)) ne 'ok' : strcol(c(p, 6)) eq 'ok' && strcol(c(p, 7)) eq 'failed'

# Axes from the data: the completed runs' range; the start of crossing (cells / crossing ratio) per ppc.
stats one using 8:(done(1) ? $8 : NaN) nooutput prefix "A"
stats two using 5:(done(2) ? $5 : NaN) nooutput prefix "B"
lo = (A_min_y < B_min_y ? A_min_y : B_min_y) / 1.1; hi = (A_max_y > B_max_y ? A_max_y : B_max_y) * 1.12
stats one using ($3 / $5) nooutput prefix "O1"
stats two using ($3 / $4) nooutput prefix "O2"
onset(p) = p == 1 ? O1_mean : O2_mean   # cells at crossing ratio 1
# On the strip: the run's own marker in the upper row, the black cross (stopped) or ring (failed) under it; the runs
# of one mesh side by side, 1 ppc left of 2 ppc, FE left of NPC.
mark_y = hi * (hi / lo)**0.1
cross_y = hi * (hi / lo)**0.04
beside(i, p) = 1.21**((p - 1) * 2 + (i eq 'fe' || i eq 'usl' ? 0 : 1) - 1.5)

# Segments joining a method's runs: seg(k, x, y) is the previous run's x (NaN for the first) and sets y0, its y; the
# state is reset at each file's first row. A segment is drawn only between adjacent meshes on one side of the onset.
px = NaN; py = NaN; x0 = NaN; y0 = NaN
seg_reset(r) = (r == 0 ? (px = NaN, py = NaN) : 0)
seg(k, x, y) = (seg_reset(column(0)), k ? (x0 = px, y0 = py, px = x, py = y, x0) : NaN)
joined(xp, x, o) = (xp == xp && x <= 2.01 * xp && (xp < o) == (x < o)) ? xp : NaN
mine(s, i, p) = strcol(c(p, 1)) eq s && strcol(c(p, 2)) eq i

# The baselines of the fourth panel (at 2 ppc), LME gamma = 3 + NPC last for reference.
B = "bspline2_fe bspline2_npc bspline3_fe bspline3_npc lme0.8_fe lme0.8_npc lme1.5_fe lme1.5_npc linear_usl linear_musl lme_npc"
s_of(m) = m[1:strstrt(m, "_") - 1]
i_of(m) = m[strstrt(m, "_") + 1:]
baseline(p) = p == 2 && strstrt(' '.B.' ', ' '.strcol(1).'_'.strcol(2).' ') > 0

# The runs on the strip of each panel, one key entry each, built from the data.
in_panel(k, p) = k < 4 ? strcol(c(p, 1)) eq word("linear ugimp lme", k) && strstrt(' fe npc ', ' '.strcol(c(p, 2)).' ') > 0 : baseline(p)
add(style, what, k, s, i, p, n) = (entries = entries.sprintf(", keyentry with points %s title '%s: %s, %d cells'", style, what, k < 4 ? sprintf('%s, %d ppc', integrator_name(i), p) : method_name(s, i), n), 1)
do for [k = 1:4] {
  entries = ''
  do for [p = 1:2] { do for [what in "stopped failed"] {
    stats file(p) using (in_panel(k, p) && off(p, what) ? add(what eq 'stopped' ? stopped_style : failed_style, what eq 'stopped' ? 'stopped' : 'failed (flat line)', k, strcol(c(p, 1)), strcol(c(p, 2)), p, column(c(p, 3))) : 0) nooutput
  } }
  eval(sprintf("strip_entries%d = entries", k))
}
strip_entries(k) = value(sprintf("strip_entries%d", k))

# A shape's panel: FE and NPC at 1 and 2 ppc; segments, points, the strip.
shape_curves(s) = sprintf("for [i in 'fe npc'] for [p = 1:2] file(p) using (joined(seg(mine('%s', i, p) && done(p), column(c(p, 3)), column(c(p, 5))), column(c(p, 3)), onset(p))):(y0):(column(c(p, 3)) - x0):(column(c(p, 5)) - y0) with vectors nohead @LS notitle, ", s).\
  sprintf("for [i in 'fe npc'] for [p = 1:2] file(p) using (mine('%s', i, p) && done(p) ? column(c(p, 3)) : NaN):(column(c(p, 5))) with points @PS notitle, ", s).\
  sprintf("for [i in 'fe npc'] for [p = 1:2] file(p) using (mine('%s', i, p) && !done(p) ? column(c(p, 3)) * beside(i, p) : NaN):(mark_y) with points @PS notitle, ", s).\
  sprintf("for [i in 'fe npc'] for [p = 1:2] file(p) using (mine('%s', i, p) && off(p, 'stopped') ? column(c(p, 3)) * beside(i, p) : NaN):(cross_y) with points %s notitle, ", s, stopped_style).\
  sprintf("for [i in 'fe npc'] for [p = 1:2] file(p) using (mine('%s', i, p) && off(p, 'failed') ? column(c(p, 3)) * beside(i, p) : NaN):(cross_y) with points %s notitle", s, failed_style).\
  sprintf(", for [i in 'fe npc'] for [p = 1:2] keyentry with linespoints @LS @PT title sprintf('%%s, %%d ppc', integrator_name(i), p)")
LS = "lw method_lw dt dash(i) lc rgb colour(s)"
PT = "ps 1.2 pt (p == 1 ? marker(i) : open(marker(i)))"
PS = PT." lc rgb colour(s)"
onset_label(n, p) = sprintf("set arrow %d from %g, graph 0 to %g, first %g nohead %s; set label %d '%d ppc: crossing' at first %g, first %g right rotate by 90 offset -0.6,0 front; ", n, onset(p), onset(p), hi, reference_style, n, p, onset(p), hi / 1.03)
onsets = onset_label(1, 2).onset_label(2, 1)
# The meshes of the 2-ppc study (the paper's shapes), and per shape the 2-ppc runs not made, named in its title.
meshes2 = ''
addm(n) = strstrt(meshes2.' ', sprintf(' %d ', n)) > 0 ? 0 : (meshes2 = meshes2.sprintf(' %d', n), 1)
stats two using ((strcol(1) eq 'linear' || strcol(1) eq 'ugimp' || strcol(1) eq 'lme') ? addm($3) : 0) nooutput
do for [s in "linear ugimp lme"] {
  missing = ''
  do for [i in "fe npc"] { do for [n in meshes2] {
    stats two using (strcol(1) eq s && strcol(2) eq i && $3 == n ? 1 : 0) nooutput
    if (STATS_sum == 0) { missing = missing.(missing eq '' ? '' : '; ').sprintf('%s, %s cells', integrator_name(i), n) }
  } }
  eval(sprintf("missing_%s = '%s'", s, missing))
}
stats one using 3 nooutput prefix "M"   # the 1-ppc sweep's meshes
join_meshes = ''
do for [n in meshes2] { join_meshes = join_meshes.(join_meshes eq '' ? '' : ', ').n }
not_run(s) = value('missing_'.s) eq '' ? '' : sprintf("\nnot run at 2 ppc (a choice of cost): %s", value('missing_'.s))
shape_panel(k, s) = sprintf("s = '%s'; set title '%s: FE and NPC at 1 ppc (filled) and 2 ppc (open)%s'; ", s, shape_name(s), not_run(s)).strip_log(lo, hi, 'no value: the run marker above × (stopped) or ○ (failed)').onsets.\
  "plot ".shape_curves(s).strip_entries(k)

# The baselines' panel: each method's points spread to the right of 160 and 1280 cells, one column per method.
spread(k) = 1.05**(k - 1)
bmine(m) = strcol(1) eq s_of(m) && strcol(2) eq i_of(m)
BT = "ps 1.2 pt open(marker(i_of(word(B, k))))"
BP = BT." lc rgb colour(s_of(word(B, k)))"
stats two using ($3 == 1280 && baseline(2) && strcol(1) ne 'linear' && done(2) ? $5 : NaN) nooutput prefix "C"
# The baselines' runs of the two meshes that are not in the file (not run), named in the title.
base_missing = ''
do for [m in B] { do for [n in "160 1280"] {
  stats two using (strcol(1) eq s_of(m) && strcol(2) eq i_of(m) && $3 == n ? 1 : 0) nooutput
  if (STATS_sum == 0) { base_missing = base_missing.(base_missing eq '' ? '' : '; ').sprintf('%s, %s cells', method_name(s_of(m), i_of(m)), n) }
} }
base_title = sprintf("today's baselines at 2 ppc, each method's points spread to the right of 160 and 1280 cells\nat 1280 cells all but linear + USL and MUSL lie within %.4f-%.4f%s", C_min, C_max, \
  base_missing eq '' ? '' : "\nnot run: ".base_missing)
base_panel = "set title base_title; unset arrow; unset label 1; unset label 2; ".strip_log(lo, hi, 'no value: the run marker above × (stopped)').\
  "set xrange [140:2300]; set xtics (160, 1280); set key at first 290, graph 0.86 left top; ".onset_label(1, 2).\
  "plot for [k = 1:words(B)] two using (bmine(word(B, k)) && done(2) ? $3 * spread(k) : NaN):5 with points @BP notitle, ".\
  "for [k = 1:words(B)] two using (bmine(word(B, k)) && !done(2) ? $3 * spread(k) : NaN):(mark_y) with points @BP notitle, ".\
  "for [k = 1:words(B)] two using (bmine(word(B, k)) && off(2, 'stopped') ? $3 * spread(k) : NaN):(cross_y) with points ".stopped_style." notitle, ".\
  "for [k = 1:words(B)] two using (bmine(word(B, k)) && off(2, 'failed') ? $3 * spread(k) : NaN):(cross_y) with points ".failed_style." notitle, ".\
  "for [k = 1:words(B)] keyentry with points @BP title method_name(s_of(word(B, k)), i_of(word(B, k)))".strip_entries(4)

draw = sprintf("set multiplot layout 2,2 title 'Fig. 6 at 1 and 2 particles per cell (ppc): RMS of v_A / |v_0| against the number of cells (CFL 0.5, 200 µs);\n1 ppc: the whole sweep of the Dyka suite, %d-%d cells; 2 ppc: %s cells' margins 0.06, 0.985, 0.07, 0.9 spacing 0.07, 0.11; ", M_min, M_max, join_meshes).\
  "set logscale xy; set xrange [7:4200]; set xlabel 'cells'; set ylabel 'RMS of v_A / |v_0|'; set ytics (0.05, 0.07, 0.1, 0.15, 0.2, 0.3); ".\
  "set key inside bottom left Left reverse samplen 2.5; ".\
  shape_panel(1, 'linear')."; ".shape_panel(2, 'ugimp')."; ".shape_panel(3, 'lme')."; ".base_panel."; unset multiplot"
load dir."/output.gp"
