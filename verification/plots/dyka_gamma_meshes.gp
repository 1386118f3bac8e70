# LME's gamma of Fig. 8 on three meshes (160: no crossing, 640: transition, 2560: crossing), both integrators
# (data/dyka_gamma_meshes.csv): accuracy (RMS of v_A / |v0|), ringing (total variation of v_A over the exact one's,
# less 1, on a log axis, so that the predictor-corrector's 1.00-1.18 show) and damping (the plateau mean shortfall /
# |v0|; its title names the curves that lie on 0 within a line's width) against gamma, each with the band of its even
# and odd samples as error bars. A mesh is a colour of the ramp, an integrator its dash and marker. Runs no better
# than a flat line (ending failed) and runs that stopped are drawn on the strip above the data of every panel (FE left
# of its gamma, NPC right), in their mesh's colour and their integrator's marker under a black ring (failed) or cross
# (stopped), and named in the key (with the failed runs' RMS).
load dir."/common.gp"
w = 13.3; h = 5.6
f = data.'/dyka_gamma_meshes.csv'
meshes = "160 640 2560"
mesh_colour(n) = ramp(n == 160 ? 1 : n == 640 ? 2 : 3, 3)
done = "strcol(11) eq 'done'"
beside(i) = i eq 'fe' ? -0.08 : 0.08

# The y ranges of the completed runs (with their bands), per panel: column, band column, shift (ringing: less 1).
col(p) = word("4 7 9", p) + 0
band(p) = word("5 8 10", p) + 0
shift(p) = p == 2 ? 1 : 0
do for [p = 1:3] {
  stats f using (@done ? column(col(p)) - shift(p) - column(band(p)) : NaN) nooutput prefix "L"
  stats f using (@done ? column(col(p)) - shift(p) + column(band(p)) : NaN) nooutput prefix "H"
  stats f using (@done ? column(col(p)) - shift(p) : NaN) nooutput prefix "V"
  if (p < 3) { lo = V_min / 1.25; hi = H_max * 1.25 } else { lo = L_min - 0.05 * (H_max - L_min); hi = H_max + 0.05 * (H_max - L_min) }
  eval(sprintf("lo%d = %.12g; hi%d = %.12g", p, lo, p, hi))
}
lo(p) = value(sprintf("lo%d", p)); hi(p) = value(sprintf("hi%d", p))
# Tics in the data range only (none in the strip): on a log axis 1, 1.5, 2, 3, 5, 7 times the powers of ten when the
# range spans less than two decades, the powers alone otherwise; on a linear axis a step of 1, 2 or 5 powers of ten.
tics = ''
logtics(a, b) = (tics = '', sum [e = floor(log10(a)):ceil(log10(b))] sum [k = 1:6] (m = (log10(b / a) < 2 ? word("1 1.5 2 3 5 7", k) + 0 : (k == 1)), \
  v = m * 10.0**e, (m > 0 && v >= a && v <= b) ? (tics = tics.(tics eq '' ? '' : ', ').sprintf('%g', v), 1) : 0), sprintf('set ytics (%s); ', tics))
step(r) = (e = 10.0**floor(log10(r / 5)), r / e <= 10 ? e : r / e <= 20 ? 2 * e : 5 * e)
lintics(a, b) = sprintf('set ytics %.12g, %.12g, %.12g; ', ceil(a / step(b - a)) * step(b - a), step(b - a), b)
top(p) = p < 3 ? strip_y_log(lo(p), hi(p)) : strip_y_linear(lo(p), hi(p))

# The key entries of the runs on the strip: per mesh, integrator and outcome, its gammas (and the failed runs' RMS).
list = ''; rms_lo = 1e9; rms_hi = 0
add(g, r) = (list = list.(list eq '' ? '' : ', ').sprintf('%g', g), rms_lo = r < rms_lo ? r : rms_lo, rms_hi = r > rms_hi ? r : rms_hi, 1)
entries = ''
do for [n in meshes] { do for [i in "fe npc"] { do for [what in "failed stopped"] {
  list = ''; rms_lo = 1e9; rms_hi = 0
  stats f using ($1 == n && strcol(2) eq i && strcol(11) eq what ? add($3, what eq 'failed' ? real(strcol(4)) : 0) : 0) nooutput
  if (list ne '') {
    entries = entries.sprintf(", keyentry with points %s title '%s: %s cells, %s, γ = %s%s'", what eq 'failed' ? failed_style : stopped_style, \
      what eq 'failed' ? 'failed (flat line)' : 'stopped', n, integrator_name(i), list, what eq 'failed' ? sprintf(' (RMS %.2f-%.2f)', rms_lo, rms_hi) : '')
  }
} } }

# The damping curves that lie on 0 within 2 % of the panel's range (about a line's width): named in its title.
flat = ''; flat_max = 0
do for [n in meshes] { do for [i in "fe npc"] {
  stats f using ($1 == n && strcol(2) eq i && @done ? abs($9) : NaN) nooutput
  if (STATS_max < 0.02 * (hi(3) - lo(3))) {
    flat = flat.(flat eq '' ? '' : ', ').sprintf('%s cells %s', n, integrator_name(i)); flat_max = STATS_max > flat_max ? STATS_max : flat_max
  }
} }
damping_title = flat eq '' ? 'damping' : sprintf("damping: %s lie on 0\n(|shortfall| / |v_0| at most %.2g: about a line''s width)", flat, flat_max)

# A panel: a curve per mesh and integrator, the strip.
MS = "lw method_lw dt dash(i) pt marker(i) lc rgb mesh_colour(n + 0)"
curves(p) = sprintf("plot for [n in meshes] for [i in 'fe npc'] f using ($1 == n && strcol(2) eq i && @done ? $3 : NaN):(column(%d) - %d):%d with yerrorlines ps 1.1 @MS title sprintf('%%s cells, %%s', n, integrator_name(i)), ", col(p), shift(p), band(p)).\
  sprintf("for [n in meshes] for [i in 'fe npc'] f using ($1 == n && strcol(2) eq i && !(@done) ? $3 + beside(i) : NaN):(%.12g) with points ps 1.1 pt marker(i) lc rgb mesh_colour(n + 0) notitle, ", top(p)).\
  sprintf("f using (strcol(11) eq 'failed' ? $3 + beside(strcol(2)) : NaN):(%.12g) with points %s notitle, ", top(p), failed_style).\
  sprintf("f using (strcol(11) eq 'stopped' ? $3 + beside(strcol(2)) : NaN):(%.12g) with points %s notitle", top(p), stopped_style).\
  (p == 1 ? entries : '')
panel(p, title, label) = sprintf("set title '%s'; set ylabel '%s'; ", title, label).\
  (p < 3 ? strip_log(lo(p), hi(p), 'no value (○ ×)').logtics(lo(p), hi(p)) : strip_linear(lo(p), hi(p), 'no value (○ ×)').lintics(lo(p), hi(p))).curves(p)
draw = "set multiplot layout 1,3 title 'LME: γ on three meshes (CFL 0.5), FE and NPC: accuracy, ringing and damping against γ (error bars: the even and odd samples)' margins 0.055, 0.99, 0.27, 0.87 spacing 0.065; ".\
  "set xlabel 'γ'; set xrange [0.5:5.4]; set logscale y; set format y '%g'; ".\
  "set key at screen 0.5, screen 0.02 center bottom vertical maxrows 4 Left reverse samplen 2.5; ".\
  panel(1, 'accuracy', 'RMS of v_A / |v_0|')."; set key off; ".\
  panel(2, 'ringing', 'total variation / exact - 1')."; unset logscale y; ".\
  panel(3, damping_title, 'plateau mean shortfall / |v_0|')."; unset multiplot"
load dir."/output.gp"
