# LME's gamma of Fig. 8 on three meshes (160: no crossing, 640: transition, 2560: crossing), both integrators
# (data/dyka_gamma_meshes.csv): accuracy (RMS of v_A / |v0|), ringing (total variation of v_A over the exact one's,
# less 1, on a log axis, so that the predictor-corrector's 1.00-1.18 show) and damping (the plateau mean shortfall /
# |v0|; its title names the curves that lie on 0 within a line's width, and a second damping panel beside it zooms on
# 0, with every curve that has a run in the zoom's range, so that those read) against gamma, each with the band of
# its even and odd samples as error bars (the title says how wide they are at most: within a marker except in the
# zoom). A mesh is a colour of the ramp, an integrator its dash and marker. Runs no better than a flat line (ending
# failed) and runs that stopped are drawn on the strip above the data of every panel (FE left of its gamma, NPC
# right), their mesh's colour and integrator's marker above a black ring (failed) or cross (stopped), and named in the
# key (with the failed runs' RMS); the strip's label names only the outcomes that occur.
load dir."/common.gp"
w = 13.3; h = 9.6
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
lo(p) = value(sprintf("lo%d", p)); hi(p) = value(sprintf("hi%d", p))   # panel 4 (the damping zoom): set below
# Tics in the data range only (none in the strip): on a log axis 1, 1.5, 2, 3, 5, 7 times the powers of ten when the
# range spans less than two decades, the powers alone otherwise; on a linear axis a step of 1, 2 or 5 powers of ten.
tics = ''
logtics(a, b) = (tics = '', sum [e = floor(log10(a)):ceil(log10(b))] sum [k = 1:6] (m = (log10(b / a) < 2 ? word("1 1.5 2 3 5 7", k) + 0 : (k == 1)), \
  v = m * 10.0**e, (m > 0 && v >= a && v <= b) ? (tics = tics.(tics eq '' ? '' : ', ').sprintf('%g', v), 1) : 0), sprintf('set ytics (%s); ', tics))
step(r) = (e = 10.0**floor(log10(r / 5)), r / e <= 10 ? e : r / e <= 20 ? 2 * e : 5 * e)
lintics(a, b) = sprintf('set ytics %.12g, %.12g, %.12g; ', ceil(a / step(b - a)) * step(b - a), step(b - a), b)
# On the strip: the run's marker in the upper half, its outcome (ring, cross) in the lower half.
top(p) = p < 3 ? hi(p) * (hi(p) / lo(p))**0.1 : hi(p) + 0.1 * (hi(p) - lo(p))
under(p) = p < 3 ? hi(p) * (hi(p) / lo(p))**0.04 : hi(p) + 0.04 * (hi(p) - lo(p))
# The strip's label: the outcomes that occur.
stats f using (strcol(11) eq 'failed' ? 1 : 0) nooutput prefix "NF"
stats f using (strcol(11) eq 'stopped' ? 1 : 0) nooutput prefix "NS"
strip_name = 'no value: marker above '.(NS_sum > 0 ? '× (stopped)' : '').(NS_sum > 0 && NF_sum > 0 ? ', ' : '').(NF_sum > 0 ? '○ (failed)' : '')

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
damping_title = flat eq '' ? 'damping' : sprintf("damping: %s lie on 0 here\n(|shortfall| / |v_0| at most %.2g): zoomed at the right", flat, flat_max)
# The zoom (panel 4): the range of the flat curves (with their bands), in units of zs (a power of ten); it draws every
# curve with a run inside it, cut where a run lies outside (named in its title).
flat_has(n, i) = strstrt(', '.flat.', ', sprintf(', %s cells %s, ', n, integrator_name(i))) > 0
stats f using (@done && flat_has(strcol(1), strcol(2)) ? $9 - $10 : NaN) nooutput prefix "ZL"
stats f using (@done && flat_has(strcol(1), strcol(2)) ? $9 + $10 : NaN) nooutput prefix "ZH"
zlo = flat eq '' ? -1 : ZL_min - 0.1 * (ZH_max - ZL_min); zhi = flat eq '' ? 1 : ZH_max + 0.1 * (ZH_max - ZL_min)
zs = 10.0**(-floor(log10(abs(zlo) > abs(zhi) ? abs(zlo) : abs(zhi))))
lo4 = zlo * zs; hi4 = zhi * zs
zoomed = ''; outside = ''
do for [n in meshes] { do for [i in "fe npc"] {
  stats f using ($1 == n && strcol(2) eq i && @done && $9 >= zlo && $9 <= zhi ? 1 : 0) nooutput
  if (STATS_sum > 0) {
    zoomed = zoomed.sprintf(' %s:%s', n, i)
    stats f using ($1 == n && strcol(2) eq i && @done && ($9 < zlo || $9 > zhi) ? \
      (outside = outside.(outside eq '' ? '' : '; ').sprintf('%s cells %s at γ = %g: %.2g', n, integrator_name(i), $3, $9), 1) : 0) nooutput
  }
} }
in_zoom(n, i) = strstrt(zoomed.' ', sprintf(' %s:%s ', n, i)) > 0
zoom_title = sprintf("damping zoomed on 0: the curves with a run in it%s", outside eq '' ? '' : "\ncut where a run lies outside (".outside.')')
# The error bars (the band of the even and odd samples) at most: on the log panels, relative to the value; on the
# damping panel, relative to its range.
stats f using (@done ? $5 / $4 : NaN) nooutput prefix "E1"
stats f using (@done ? $8 / ($7 - 1) : NaN) nooutput prefix "E2"
stats f using (@done ? $10 / (hi3 - lo3) : NaN) nooutput prefix "E3"
bars = 100 * (E1_max > E2_max ? (E1_max > E3_max ? E1_max : E3_max) : (E2_max > E3_max ? E2_max : E3_max))

# A panel: a curve per mesh and integrator, the strip. Panel 4 (the zoom, of the damping's columns, times zs) draws
# the curves that in_zoom accepts, each value outside the zoom undefined (the line is cut there).
MS = "lw method_lw dt dash(i) pt marker(i) lc rgb mesh_colour(n + 0)"
q(p) = p == 4 ? 3 : p
shown(p, n, i) = p < 4 || in_zoom(n, i)
y(p, v) = p < 4 ? v : (v >= zlo && v <= zhi ? v * zs : NaN)
curves(p) = sprintf("plot for [n in meshes] for [i in 'fe npc'] f using ($1 == n && strcol(2) eq i && @done && shown(%d, n, i) ? $3 : NaN):(y(%d, column(%d) - %d)):(column(%d) * (%d < 4 ? 1 : zs)) with yerrorlines ps 1.1 @MS %s, ", p, p, col(q(p)), shift(q(p)), band(q(p)), p, p == 1 ? "title sprintf('%s cells, %s', n, integrator_name(i))" : 'notitle').\
  sprintf("for [n in meshes] for [i in 'fe npc'] f using ($1 == n && strcol(2) eq i && !(@done) && shown(%d, n, i) ? $3 + beside(i) : NaN):(%.12g) with points ps 1.1 pt marker(i) lc rgb mesh_colour(n + 0) notitle, ", p, top(p)).\
  sprintf("f using (strcol(11) eq 'failed' && shown(%d, strcol(1), strcol(2)) ? $3 + beside(strcol(2)) : NaN):(%.12g) with points %s notitle, ", p, under(p), failed_style).\
  sprintf("f using (strcol(11) eq 'stopped' && shown(%d, strcol(1), strcol(2)) ? $3 + beside(strcol(2)) : NaN):(%.12g) with points %s notitle", p, under(p), stopped_style).\
  (p == 1 ? entries : '')
panel(p, title, label) = sprintf("set title '%s'; set ylabel '%s'; ", title, label).\
  (p < 3 ? strip_log(lo(p), hi(p), strip_name).logtics(lo(p), hi(p)) : strip_linear(lo(p), hi(p), strip_name).lintics(lo(p), hi(p))).curves(p)
# The layout: accuracy and ringing above; damping and its zoom (when some curves lie on 0) below; the key at the bottom.
at(l, r, b, t) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; set tmargin at screen %g; ", l, r, b, t)
zoom = flat ne ''
draw = sprintf("set multiplot title 'LME: γ on three meshes (CFL 0.5), FE and NPC: accuracy, ringing and damping against γ; error bars: the even and odd samples,\nat most %.1f %% of a value (of the range in the damping panel), within a marker except in the damping zoom'; ", bars).\
  "set xlabel 'γ'; set xrange [0.5:5.4]; set logscale y; set format y '%g'; ".\
  "set key at screen 0.5, screen 0.01 center bottom vertical maxrows 4 Left reverse samplen 2.5; ".\
  at(0.06, 0.49, 0.57, 0.89).panel(1, 'accuracy', 'RMS of v_A / |v_0|')."; set key off; ".\
  at(0.56, 0.99, 0.57, 0.89).panel(2, 'ringing', 'total variation / exact - 1')."; unset logscale y; ".\
  at(0.06, zoom ? 0.49 : 0.99, 0.16, 0.46).panel(3, damping_title, 'plateau mean shortfall / |v_0|')."; ".\
  (zoom ? at(0.56, 0.99, 0.16, 0.46).panel(4, zoom_title, sprintf('plateau mean shortfall / |v_0| (10^{%d})', -log10(zs)))."; " : '')."unset multiplot"
load dir."/output.gp"
