# Grid crossing isolated on the Dyka bar: RMS of v_A / |v0| against U/h, the free end's largest displacement in
# cells, at 640 cells, the initial speed swept (data/dyka_amplitude.csv), one column per integrator (FE, NPC), each
# shape in its palette style. Top row: the RMS; a run that stopped (ending stopped) or is no better than a flat line
# (ending failed, its RMS in the key) is drawn on the strip above the data, one row per shape (named at the row's
# left: linear top, LME bottom, ruled apart), its method's marker in its colour above a black cross (stopped) or ring
# (failed), so that both read, and named in the key with its amplitudes. The dotted line is the first cell face (U/h = 1/2). Bottom row: linear and uGIMP
# against LME gamma = 3 with the same integrator (RMS / LME's - 1, in per cent) where both completed, since the
# shapes lie on each other in the top row (with NPC within a line's width); each title gives how far apart they lie
# below the first cell face.
load dir."/common.gp"
w = 13.3; h = 9.4
f = data.'/dyka_amplitude.csv'
shapes = "linear ugimp lme"
stats f using (strcol(10) eq 'done' ? $5 : NaN) nooutput
lo = STATS_min / 1.1; hi = STATS_max * 1.12
stats f using 3 nooutput
xlo = STATS_min / 1.4; xhi = STATS_max * 1.4
# The strip, taller than common.gp's (three rows, each a method's marker above its cross or ring): its top; a shape's
# row (linear top), at(s, f) the height a fraction f up its row; the rows' names and the rules between them.
tall = 0.48
strip_top = hi * (hi / lo)**tall
order(s) = s eq 'linear' ? 1 : s eq 'ugimp' ? 2 : 3
at(s, f) = hi * (hi / lo)**(tall * (3 - order(s) + f) / 3.0)
mark_row(s) = at(s, 0.7)
cross_row(s) = at(s, 0.3)
rule(k) = sprintf("set arrow %d from graph 0, first %.12g to graph 1, first %.12g nohead lw 1 lc rgb c_context front; ", 93 + k, at('lme', k), at('lme', k))
strip = strip_log(lo, hi, '').sprintf("set yrange [%.12g:%.12g]; ", lo, strip_top).\
  sprintf("set label 91 '%s' at graph 0.01, first %.12g left front; set label 92 '%s' at graph 0.01, first %.12g left front; set label 93 '%s' at graph 0.01, first %.12g left front; ", \
  shape_name('linear'), at('linear', 0.5), shape_name('ugimp'), at('ugimp', 0.5), shape_name('lme'), at('lme', 0.5)).rule(1).rule(2)
unstrip_rows = unstrip."unset label 91; unset label 92; unset label 93; unset arrow 94; unset arrow 95; "
mine(s, i) = strcol(1) eq s && strcol(2) eq i

# LME gamma = 3's RMS per integrator and amplitude (" i:U/h:rms" words), the bottom row's reference.
lme_list = ''
addref(i, u, r) = (lme_list = lme_list.sprintf(' %s:%g:%.12g', i, u, r), 1)
stats f using (strcol(1) eq 'lme' && strcol(10) eq 'done' ? addref(strcol(2), $3, $5) : 0) nooutput
tag(i, u) = sprintf(' %s:%g:', i, u)
ref(i, u) = strstrt(lme_list, tag(i, u)) == 0 ? NaN : real(lme_list[strstrt(lme_list, tag(i, u)) + strlen(tag(i, u)):])

# The key entries of the runs on the strip: per method and outcome, its amplitudes (and the failed runs' RMS).
list = ''; rms_lo = 1e9; rms_hi = 0
add(u, r) = (list = list.(list eq '' ? '' : ', ').sprintf('%g', u), rms_lo = r < rms_lo ? r : rms_lo, rms_hi = r > rms_hi ? r : rms_hi, 1)
do for [i in "fe npc"] {
  entries = ''
  do for [s in shapes] { do for [what in "stopped failed"] {
    list = ''; rms_lo = 1e9; rms_hi = 0
    stats f using (mine(s, i) && strcol(10) eq what ? add($3, what eq 'failed' ? real(strcol(5)) : 0) : 0) nooutput
    if (list ne '') {
      entries = entries.sprintf(", keyentry with points %s title '%s: %s at U/h = %s%s'", what eq 'stopped' ? stopped_style : failed_style, \
        what eq 'stopped' ? 'stopped' : 'failed', method_name(s, i), list, what eq 'failed' ? sprintf(' (RMS %.2f-%.2f)', rms_lo, rms_hi) : '')
    }
  } }
  eval(sprintf("entries_%s = entries", i))
  # how far apart the three shapes lie below the first cell face (where every run completes), and the largest
  # difference of linear and uGIMP from LME there (per cent)
  stats f using (strcol(2) eq i && $3 < 0.5 && strcol(10) eq 'done' ? $5 : NaN) nooutput
  eval(sprintf("apart_%s = %.12g", i, 100 * (STATS_max / STATS_min - 1)))
  stats f using (strcol(2) eq i && strcol(1) ne 'lme' && $3 < 0.5 && strcol(10) eq 'done' ? abs(100 * ($5 / ref(i, $3) - 1)) : NaN) nooutput
  eval(sprintf("within_%s = %.12g", i, STATS_max))
  stats f using (strcol(2) eq i && $3 < 0.5 ? $3 : NaN) nooutput
  eval(sprintf("below_%s = '%g-%g'", i, STATS_min, STATS_max))
}

MS = "lw method_lw dt dash(i) pt marker(i) lc rgb colour(s)"
curves(i) = sprintf("i = '%s'; ", i).\
  "plot for [s in shapes] f using (mine(s, i) && strcol(10) eq 'done' ? $3 : NaN):5 with linespoints ps 1.2 @MS title method_name(s, i), ".\
  "for [s in shapes] f using (mine(s, i) && strcol(10) ne 'done' ? $3 : NaN):(mark_row(s)) with points ps 1.3 pt marker(i) lc rgb colour(s) notitle, ".\
  "f using (strcol(2) eq i && strcol(10) eq 'stopped' ? $3 : NaN):(cross_row(strcol(1))) with points ".stopped_style." notitle, ".\
  "f using (strcol(2) eq i && strcol(10) eq 'failed' ? $3 : NaN):(cross_row(strcol(1))) with points ".failed_style." notitle".value('entries_'.i)
cell_face = sprintf("set arrow 1 from 0.5, graph 0 to 0.5, first %g nohead %s; set label 1 'first cell face' at 0.5, first %g right rotate by 90 offset -0.6,0 front; ", hi, reference_style, hi / 1.03)
panel(i) = sprintf("set title '%s: below the first cell face the three shapes lie within %.2f %% of each other%s'; ", integrator_name(i), value('apart_'.i), value('apart_'.i) < 1 ? ",\nwithin the width of a line: drawn apart below" : '').\
  "set logscale y; set ylabel 'RMS of v_A / |v_0|'; set ytics (0.07, 0.08, 0.09, 0.1, 0.15, 0.2, 0.3, 0.4) nomirror; set format x ''; unset xlabel; ".\
  strip.cell_face.curves(i)
difference(i) = sprintf("i = '%s'; ", i).\
  sprintf("set title '%s: linear and uGIMP against LME γ = 3 + %s; at U/h = %s within %.2f %% of it'; ", integrator_name(i), integrator_name(i), value('below_'.i), value('within_'.i)).\
  unstrip_rows."unset logscale y; set yrange [*:*]; set ytics auto; set offsets 0, 0, graph 0.1, graph 0.1; set format x '%g'; set xlabel 'U/h (free end displacement / cell)'; ".\
  "set ylabel 'RMS / LME γ = 3''s - 1 (%)'; set key off; unset label 1; ".\
  sprintf("set arrow 1 from 0.5, graph 0 to 0.5, graph 1 nohead %s; ", reference_style).\
  sprintf("plot 0 with lines %s notitle, for [s in 'linear ugimp'] f using (mine(s, i) && strcol(10) eq 'done' && ref(i, $3) == ref(i, $3) ? $3 : NaN):(100 * ($5 / ref(i, $3) - 1)) with linespoints ps 1.2 @MS notitle; set offsets 0, 0, 0, 0", reference_style)
side(k) = sprintf("set lmargin at screen %s; set rmargin at screen %s; ", word("0.065 0.565", k), word("0.475 0.975", k))
top_row = "set tmargin at screen 0.895; set bmargin at screen 0.52; "
bottom_row = "set tmargin at screen 0.445; set bmargin at screen 0.255; "
key(k) = sprintf("set key at screen %s, screen 0.185 left top Left reverse vertical samplen 2.5; ", word("0.065 0.565", k))
draw = "set multiplot title 'Grid crossing isolated: the Dyka bar at 640 cells, the initial speed swept, RMS of v_A / |v_0| against U/h (free end displacement / cell)'; ".\
  sprintf("set logscale x; set xrange [%g:%g]; ", xlo, xhi).\
  side(1).top_row.key(1).panel('fe')."; ".side(2).top_row.key(2).panel('npc')."; ".\
  side(1).bottom_row.difference('fe')."; ".side(2).bottom_row.difference('npc')."; unset multiplot"
load dir."/output.gp"
