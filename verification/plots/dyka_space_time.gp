# Point A against every particle: RMS of v_A / |v0| (left column) and the all-particle space-time norm / |v0| (right
# column) against the number of cells, per integrator (rows: FE, NPC; the key of a row at its right), and in the third
# row linear and uGIMP against LME gamma = 3 with the same integrator (the RMS of v_A, left, or the space-time norm,
# right, over LME's - 1, in per cent, where both completed before the crossing band: the curves of the rows above lie
# on each other there), each shape in its palette style (data/dyka_sweep.csv, CFL 0.5). A line joins a method's meshes
# up to the grid-crossing band (2560 cells: a point of its own). Runs that stopped (status failed) or are no better
# than a flat line (ending failed) are drawn on the strip above the data, one row per shape (named at its left: linear
# top, LME bottom, ruled apart), the method's marker in its colour above a black cross (stopped) or ring (failed), so
# that both read, and named in the key. Each
# title gives how far apart the three shapes lie before the crossing band (with NPC they coincide); the third row's
# titles how close linear and uGIMP + NPC lie to LME gamma = 3 + NPC from 40 cells.
load dir."/common.gp"
w = 13.3; h = 13
f = data.'/dyka_sweep.csv'
shapes = "linear ugimp lme"
done = "strcol(12) eq 'ok' && strcol(22) eq 'done'"
stats f using ($3 * (strcol(6) eq 'crossing' ? 1 : NaN)) nooutput
crossing = STATS_min  # the first mesh of the grid-crossing band
stats f using (@done ? ($8 < $26 ? $8 : $26) : NaN) nooutput
lo = STATS_min / 1.15
stats f using (@done ? ($8 > $26 ? $8 : $26) : NaN) nooutput
hi = STATS_max * 1.15
# The strip, taller than common.gp's (three rows, each a method's marker above its cross or ring): a shape's row
# (linear top), at(s, f) the height a fraction f up its row; the rows' names and the rules between them.
tall = 0.45
order(s) = s eq 'linear' ? 1 : s eq 'ugimp' ? 2 : 3
at(s, f) = hi * (hi / lo)**(tall * (3 - order(s) + f) / 3.0)
mark_row(s) = at(s, 0.7)
cross_row(s) = at(s, 0.3)
rule(k) = sprintf("set arrow %d from graph 0, first %.12g to graph 1, first %.12g nohead lw 1 lc rgb c_context front; ", 93 + k, at('lme', k), at('lme', k))
strip = strip_log(lo, hi, '').sprintf("set yrange [%.12g:%.12g]; ", lo, hi * (hi / lo)**tall).\
  sprintf("set label 91 '%s' at graph 0.01, first %.12g left front; set label 92 '%s' at graph 0.01, first %.12g left front; set label 93 '%s' at graph 0.01, first %.12g left front; ", \
  shape_name('linear'), at('linear', 0.5), shape_name('ugimp'), at('ugimp', 0.5), shape_name('lme'), at('lme', 0.5)).rule(1).rule(2)
unstrip_rows = unstrip."unset label 91; unset label 92; unset label 93; unset arrow 94; unset arrow 95; "
mine(s, i) = strcol(1) eq s && strcol(2) eq i
off(what) = what eq 'stopped' ? strcol(12) ne 'ok' : strcol(12) eq 'ok' && strcol(22) eq 'failed'

# Per integrator: the key entries of the runs on the strip (one per method and outcome, its meshes), and how far
# apart the shapes lie before the crossing band (the largest max / min - 1 over the meshes), per measure.
list = ''
add(n) = (list = list.(list eq '' ? '' : ', ').sprintf('%d', n), 1)
do for [i in "fe npc"] {
  entries = ''
  do for [s in shapes] { do for [what in "stopped failed"] {
    list = ''
    stats f using (mine(s, i) && off(what) ? add($3) : 0) nooutput
    if (list ne '') {
      entries = entries.sprintf(", keyentry with points %s title '%s: %s, %s cells'", what eq 'stopped' ? stopped_style : failed_style, \
        what eq 'stopped' ? 'stopped' : 'failed (flat line)', method_name(s, i), list)
    }
  } }
  eval(sprintf("entries_%s = entries", i))
  do for [c in "8 26"] {
    apart = 0
    do for [n in "10 20 40 80 160 320 640 1280 2560"] {
      if (n + 0 < crossing) {
        stats f using (strcol(2) eq i && $3 == n && @done ? column(c + 0) : NaN) nooutput
        apart = STATS_max / STATS_min - 1 > apart ? STATS_max / STATS_min - 1 : apart
      }
    }
    eval(sprintf("apart_%s_%s = %.12g", i, c, 100 * apart))
  }
}

# LME gamma = 3's norms per integrator, measure and mesh, the reference of the third row.
do for [i in "fe npc"] { do for [c in "8 26"] { do for [n in "10 20 40 80 160 320 640 1280 2560"] {
  stats f using (mine('lme', i) && $3 == n && @done ? column(c + 0) : 0) nooutput
  eval(sprintf("ref_%s_%s_%s = %s", i, c, n, STATS_max > 0 ? sprintf('%.12g', STATS_max) : 'NaN'))
} } }
ref(i, c, n) = value(sprintf("ref_%s_%d_%d", i, c, n))
# How close linear and uGIMP + NPC lie to LME gamma = 3 + NPC from 40 cells to the crossing band (%), per measure.
do for [c in "8 26"] {
  stats f using (strcol(2) eq 'npc' && strcol(1) ne 'lme' && $3 >= 40 && $3 < crossing && @done ? abs(100 * (column(c + 0) / ref('npc', c + 0, $3) - 1)) : NaN) nooutput
  eval(sprintf("npc_within_%s = %.12g", c, STATS_max))
}

MS = "lw method_lw dt dash(i) pt marker(i) lc rgb colour(s)"
stats f using ($3 < crossing ? $3 : NaN) nooutput
last = STATS_max      # the last mesh before the crossing band
panel(i, c) = sprintf("i = '%s'; set title '%s, %s: the shapes lie within %.1f %% of each other to %d cells'; ", i, integrator_name(i), c == 8 ? 'point A' : 'every particle', value(sprintf('apart_%s_%d', i, c)), last).\
  strip.\
  sprintf("plot for [s in shapes] f using (mine(s, i) && @done && $3 < crossing ? $3 : NaN):%d with linespoints ps 1.1 @MS title method_name(s, i), ", c).\
  sprintf("for [s in shapes] f using (mine(s, i) && @done && $3 >= crossing ? $3 : NaN):%d with points ps 1.1 @MS notitle, ", c).\
  "for [s in shapes] f using (mine(s, i) && !(@done) ? $3 : NaN):(mark_row(s)) with points ps 1.3 pt marker(i) lc rgb colour(s) notitle, ".\
  "f using (strcol(2) eq i && off('stopped') ? $3 : NaN):(cross_row(strcol(1))) with points ".stopped_style." notitle, ".\
  "f using (strcol(2) eq i && off('failed') ? $3 : NaN):(cross_row(strcol(1))) with points ".failed_style." notitle".value('entries_'.i)
difference(c) = sprintf("set title '%s: linear and uGIMP against LME γ = 3 with the same integrator;\nwith NPC within %.2f %% of it from 40 cells (the dashed curves on 0)'; unset logscale y; set ytics auto; set yrange [*:*]; set offsets 0, 0, graph 0.06, graph 0.06; ", c == 8 ? 'point A' : 'every particle', value(sprintf('npc_within_%d', c))).unstrip_rows.\
  sprintf("set ylabel '%s / LME γ = 3''s - 1 (%%)'; ", c == 8 ? 'RMS of v_A' : 'space-time norm').\
  sprintf("plot 0 with lines %s notitle, for [i in 'fe npc'] for [s in 'linear ugimp'] f using (mine(s, i) && @done && $3 < crossing ? $3 : NaN):(100 * (column(%d) / ref(i, %d, $3) - 1)) with linespoints ps 1.1 @MS title method_name(s, i)", reference_style, c, c)
rows = "margins 0.06, 0.72, 0.05, 0.93 spacing 0.07, 0.07"
draw = "set multiplot layout 3,2 title 'Point A against every particle on the Dyka bar (CFL 0.5): RMS of v_A / |v_0| (left) and the all-particle space-time norm / |v_0| (right) against the number of cells' ".rows."; ".\
  "set logscale x; set xrange [7:3600]; set xlabel 'cells'; ".\
  "set key at screen 0.735, graph 0.86 left top Left reverse samplen 2.5; ".\
  "set logscale y; set ytics (0.04, 0.05, 0.07, 0.1, 0.15, 0.2, 0.3) nomirror; ".\
  "unset key; set ylabel 'RMS / |v_0|'; ".panel('fe', 8)."; set key; unset ylabel; ".panel('fe', 26)."; ".\
  "unset key; set ylabel 'RMS / |v_0|'; ".panel('npc', 8)."; set key; unset ylabel; ".panel('npc', 26)."; ".\
  "unset key; ".difference(8)."; set key; ".difference(26)."; unset multiplot"
load dir."/output.gp"
