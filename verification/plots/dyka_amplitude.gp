# Grid crossing isolated on the Dyka bar: RMS of v_A / |v0| against U/h, the free end's largest displacement in
# cells, at 640 cells, the initial speed swept (data/dyka_amplitude.csv), one panel per integrator (FE, NPC), each
# shape in its palette style. A run that stopped (ending stopped) or is no better than a flat line (ending failed,
# its RMS in the key) is drawn on the strip above the data, one row per shape (linear top, LME bottom), in its
# method's marker under a black cross (stopped) or ring (failed), and named in the key with its amplitudes. The
# dotted line is the first cell face (U/h = 1/2); each title gives how far apart the three shapes lie below it (with
# NPC they coincide).
load dir."/common.gp"
w = 13.3; h = 6
f = data.'/dyka_amplitude.csv'
shapes = "linear ugimp lme"
stats f using (strcol(10) eq 'done' ? $5 : NaN) nooutput
lo = STATS_min / 1.1; hi = STATS_max * 1.12
stats f using 3 nooutput
xlo = STATS_min / 1.4; xhi = STATS_max * 1.4
row(s) = hi * (hi / lo)**(0.035 * (4 - (s eq 'linear' ? 1 : s eq 'ugimp' ? 2 : 3)))  # the strip's row of a shape
mine(s, i) = strcol(1) eq s && strcol(2) eq i

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
        what eq 'stopped' ? 'stopped' : 'failed', shape_name(s), list, what eq 'failed' ? sprintf(' (RMS %.2f-%.2f)', rms_lo, rms_hi) : '')
    }
  } }
  eval(sprintf("entries_%s = entries", i))
  # how far apart the three shapes lie below the first cell face (where every run completes)
  stats f using (strcol(2) eq i && $3 < 0.5 && strcol(10) eq 'done' ? $5 : NaN) nooutput
  eval(sprintf("apart_%s = %.12g", i, 100 * (STATS_max / STATS_min - 1)))
}

MS = "lw method_lw dt dash(i) pt marker(i) lc rgb colour(s)"
curves(i) = sprintf("i = '%s'; ", i).\
  "plot for [s in shapes] f using (mine(s, i) && strcol(10) eq 'done' ? $3 : NaN):5 with linespoints ps 1.2 @MS title method_name(s, i), ".\
  "for [s in shapes] f using (mine(s, i) && strcol(10) ne 'done' ? $3 : NaN):(row(s)) with points ps 1.2 pt marker(i) lc rgb colour(s) notitle, ".\
  "f using (strcol(2) eq i && strcol(10) eq 'stopped' ? $3 : NaN):(row(strcol(1))) with points ".stopped_style." notitle, ".\
  "f using (strcol(2) eq i && strcol(10) eq 'failed' ? $3 : NaN):(row(strcol(1))) with points ".failed_style." notitle".value('entries_'.i)
panel(i) = sprintf("set title '%s, three shapes: below the first cell face they lie within %.1f %% of each other'; ", integrator_name(i), value('apart_'.i)).\
  strip_log(lo, hi, 'stopped (×), failed (○); rows: linear, uGIMP, LME').curves(i)
draw = "set multiplot layout 1,2 title 'Grid crossing isolated: the Dyka bar at 640 cells, the initial speed swept, RMS of v_A / |v_0| against U/h (free end displacement / cell)' margins 0.06, 0.99, 0.30, 0.87 spacing 0.07; ".\
  sprintf("set logscale xy; set xrange [%g:%g]; set xlabel 'U/h (free end displacement / cell)'; set ylabel 'RMS of v_A / |v_0|'; set ytics (0.07, 0.08, 0.09, 0.1, 0.15, 0.2, 0.3, 0.4) nomirror; ", xlo, xhi).\
  sprintf("set arrow 1 from 0.5, graph 0 to 0.5, first %g nohead %s; set label 1 'first cell face' at 0.5, first %g right rotate by 90 offset -0.6,0 front; ", hi, reference_style, hi / 1.03).\
  "set key outside below left Left reverse vertical samplen 2.5; ".panel('fe')."; ".panel('npc')."; unset multiplot"
load dir."/output.gp"
