# Where methods fail, on the Dyka bar (40 cells, 20 ms), from data/dyka_stability.csv (a row per method),
# data/dyka_stability_runs.csv (a row per run) and data/dyka_stability_factors.txt (the scan's CFLs as fractions of
# the step limit), written by verification/dyka_stability.sh. Top: a column per method, named in words (its shape's
# colour and its integrator's marker under it; every LME in LME's colour, its gamma written over its marker, as an
# NPC with another Newmark gamma has its gamma_N written over its marker), the scan's CFLs as rows, evenly spaced (the axis names each fraction of
# the step limit the scan is placed by, column cfl_limit_scanned, in brackets under the method; the body it is
# computed on is column scanned_limit_body: the free bar, the smaller of its limit at rest and with the particles
# moved 1e-6 h towards the free end; the held bar's only where the free bar's analysis finds no stable CFL, and then
# named so in the title and under the method). Each run is a dot, v0 black and left, v0/100 grey and right; a run the solver stopped has the black cross over its dot. The bar reaches the last CFL before the
# first stopped run at v0; the black line is the step limit scanned (1, between the rows 0.995 and 1.005), the grey
# one the step limit of a bar held at both ends (column cfl_limit_step; one above the scan's rows is drawn at the top
# with its value). A cross inside a bar's range cannot be: a cross below a dot marks stable CFLs that are not an
# interval. Bottom: v_A of linear + forward Euler at v0 at the two CFLs named by `below` and `above`
# (dyka_stability_below.csv, dyka_stability_above.csv: the last CFL before its first stopped run and that first
# stopped one), one panel each; where the stopped run stopped (the diagnosis's t) is a black vertical line and the
# stopped marker on the strip above the data, linear + FE's marker beside it. The titles say which fractions of the limit they are and which other
# CFLs of the scan stop or complete, at v0 and at v0/100 (from the runs file).
load dir."/common.gp"
w = 13.3; h = 11.5
csv = data."/dyka_stability.csv"
runs = data."/dyka_stability_runs.csv"
stats csv every ::1 using 0 nooutput
methods = STATS_records
stats csv every ::1 using (strstrt(strcol(13), 'held') == 1 ? 1 : 0) nooutput
held = STATS_sum                     # methods whose scan is placed by the held bar's limit
stats csv every ::1 using (strcol(2) eq 'nan' ? 1 : 0) nooutput
none = STATS_sum                     # methods with no stable CFL in the scan at v0

# The scan's factors (one line), evenly spaced rows: row(f) is a factor's row, linear between the scanned ones.
set datafile separator "\t"
stats data.'/dyka_stability_factors.txt' using (factors = strcol(1), 0) nooutput
set datafile separator ","
nf = words(factors)
F(k) = word(factors, k) + 0
row(f) = f <= F(1) ? 1 - (F(1) - f) / (F(2) - F(1)) : f >= F(nf) ? nf + (f - F(nf)) / (F(nf) - F(nf - 1)) : \
  sum [k = 1:nf - 1] ((f >= F(k) && f < F(k + 1)) ? k + (f - F(k)) / (F(k + 1) - F(k)) : 0)
above_scan = nf + 0.75               # a held bar's limit above the scan's last row is drawn here, with its value
held_row(f) = row(f) > nf + 0.5 ? above_scan : row(f)
ftics = ''
do for [k = 1:nf] { ftics = ftics.sprintf("%s'%s' %d", k > 1 ? ', ' : '', word(factors, k), k) }

# A method's key in words: shape (LME's gamma named), integrator and its variant; shape and integrator keys of
# the palette for its colour and marker: every LME in LME's colour (this figure compares methods, it does not vary
# gamma), its gamma written over its marker.
shape_of(m) = m[1:strstrt(m, '_') - 1]
rest_of(m) = m[strstrt(m, '_') + 1:]
is_lme(s) = s[1:3] eq 'lme'
lme_gammas = ''
add_gamma(s) = strstrt(lme_gammas.' ', sprintf(' %g ', real(s[4:]))) > 0 ? 0 : (lme_gammas = lme_gammas.sprintf(' %g', real(s[4:])), 1)
stats csv every ::1 using (is_lme(shape_of(strcol(1))) ? add_gamma(shape_of(strcol(1))) : 0) nooutput
shape_colour(s) = is_lme(s) ? colour('lme') : colour(s)
integrator_of(m) = rest_of(m) eq 'npc_average' ? 'npcavg' : strstrt(rest_of(m), '_') > 0 ? rest_of(m)[1:strstrt(rest_of(m), '_') - 1] : rest_of(m)
word_shape(s) = s[1:3] eq 'lme' ? sprintf('LME γ = %g', real(s[4:])) : shape_name(s)
newmark(m) = rest_of(m)[strstrt(rest_of(m), 'gamma') + 5:]   # NPC's Newmark gamma of a variant
variant(m) = strstrt(rest_of(m), 'gamma') > 0 ? sprintf(', Newmark γ = %s', newmark(m)) : ''
method_words(m) = word_shape(shape_of(m)).' + '.integrator_name(integrator_of(m)).variant(m)
body(c) = strstrt(strcol(c), 'held') == 1 ? ', held bar' : ''
tic(name) = sprintf('%s (%.3f%s)', method_words(strcol(name)), column(12), body(13))
# v0, v0/100: black and grey; their side of the column tells them apart too.
amplitude_colour(k) = k == 1 ? c_exact : c_reference
side(a) = a < -1 ? -0.2 : 0.2        # v0 left of the column's middle, v0/100 right
limits = held == 0 ? "the free bar''s step limit (in brackets: the smaller at rest and with the particles moved 1e-6 h)" : sprintf("the free bar''s step limit (in brackets; the held bar''s for %d methods, so named)", held)
base = -1.05                         # the row of the methods' markers, under the bars
# Over a method's marker: a Newmark variant's gamma_N, an LME's gamma (empty for the others).
over_label(m) = variant(m) ne '' ? "γ_N\n".newmark(m) : is_lme(shape_of(m)) ? sprintf("γ\n%g", real(shape_of(m)[4:])) : ''
over_y = 0.08
# the LME gammas of the columns, increasing, for the key ("1, 3, 5")
gamma_list = ''
do for [g in system("echo '".lme_gammas."' | tr ' ' '\\n' | grep . | sort -g | paste -sd ' ' -")] { gamma_list = gamma_list.(gamma_list eq '' ? '' : ', ').g }
# A palette colour '#rrggbb' as the number `lc rgb variable` takes.
rgb(c) = sum [k = 2:7] (strstrt('0123456789abcdef', c[k:k]) - 1) * 16**(7 - k)

left = sprintf("set title 'Every scanned run of the %d methods, at CFLs that are fractions of %s' noenhanced; ", methods, limits).\
  sprintf("set ylabel 'CFL / the step limit scanned (the scan''s rows, evenly spaced)'; set yrange [-1.5:%g]; set ytics (%s) nomirror; ", above_scan + 1.3, ftics).\
  sprintf("set xrange [-0.7:%g]; set xtics rotate by -40 noenhanced nomirror; set boxwidth 0.7; set grid noxtics ytics; ", methods - 0.3).\
  "set key at screen 0.715, screen 0.905 left top Left reverse samplen 2 enhanced; ".\
  "plot csv every ::1 using 0:(row($2 / $12) + 0.45):xtic(tic(1)) with boxes fs solid 0.5 noborder lc rgb c_context title 'bar: the CFLs below the first run stopped at v_0', ".\
  "csv every ::1 using ($0 - 0.35):(held_row($6 / $12)):(0.7):(0) with vectors nohead lw 3 lc rgb c_reference title 'the step limit of the bar held at both ends', ".\
  "csv every ::1 using ($0 - 0.35):(row(1)):(0.7):(0) with vectors nohead lw 2 lc rgb c_exact title 'the step limit scanned (1)', ".\
  "csv every ::1 using 0:(row($6 / $12) > nf + 0.5 ? above_scan : NaN):(sprintf('%.3f', $6 / $12)) with labels offset 0,0.8 notitle, ".\
  "runs every ::1 using ($1 + side($3)):($3 < -1 ? row($5) : NaN) with points pt 7 ps 0.7 lc rgb amplitude_colour(1) title 'a run at v_0 = 5 m/s (black, left in its column)', ".\
  "runs every ::1 using ($1 + side($3)):($3 > -1 ? row($5) : NaN) with points pt 7 ps 0.7 lc rgb amplitude_colour(2) title 'a run at v_0/100 (grey, right)', ".\
  "runs every ::1 using ($1 + side($3)):($6 == 0 ? row($5) : NaN) with points ".stopped_style." title 'stopped by the solver (× over the run''s dot)', ".\
  "csv every ::1 using 0:(base):(marker(integrator_of(strcol(1)))):(rgb(shape_colour(shape_of(strcol(1))))) with points pt variable ps 1.3 lc rgb variable notitle, ".\
  "csv every ::1 using 0:(over_label(strcol(1)) eq '' ? NaN : over_y):(over_label(strcol(1))) with labels notitle, ".\
  "keyentry with points pt marker('fe') ps 1.3 lc rgb c_reference title 'under a column: shape''s colour, integrator''s marker', ".\
  "keyentry with points pt marker('fe') ps 1.3 lc rgb colour('lme') title sprintf('γ over LME''s marker: its γ (%s)', gamma_list), ".\
  "keyentry with points pt marker('npc') ps 1.3 lc rgb colour('linear') title 'γ_N over NPC''s marker: its Newmark γ'".\
  (none > 0 ? ", csv every ::1 using 0:(strcol(2) eq 'nan' ? 1 : NaN):('no stable CFL') with labels rotate by 90 left offset 0,1 notitle" : "")

# The two runs drawn at the bottom: their fractions of linear + FE's limit, the stop's time, the scan's other outcomes.
stats csv every ::1 using (strcol(1) eq 'linear_fe' ? (limit = $12, diagnosis = strcol(18), 0) : 0) nooutput
stop = real(diagnosis[strstrt(diagnosis, 't = ') + 4:]) * 1e3   # ms
fb = below / limit; fa = above / limit
stopped_too = ''; completes_again = ''
collect(f, ok) = (f > fa + 1e-4 ? (ok ? (completes_again = completes_again.(completes_again eq '' ? '' : ', ').sprintf('%.3f', f)) : (stopped_too = stopped_too.(stopped_too eq '' ? '' : ', ').sprintf('%.3f', f))) : '', 0)
stats runs every ::1 using (strcol(2) eq 'linear_fe' && $3 < -1 ? collect($5, $6 == 1) : 0) nooutput
# and at v0/100 (the column's right dots): the CFLs of the scan it stops at.
small_stops = ''
stats runs every ::1 using (strcol(2) eq 'linear_fe' && $3 > -1 && $6 == 0 ? (small_stops = small_stops.(small_stops eq '' ? '' : ', ').sprintf('%.3f', $5), 0) : 0) nooutput
others = (stopped_too ne '' ? 'at v_0 the scan also stops it at '.stopped_too : '').\
  (completes_again ne '' ? (stopped_too ne '' ? ' and' : 'at v_0 the scan').' completes 20 ms at '.completes_again.' × the limit: its stable CFLs are not an interval' : \
  stopped_too ne '' ? ' × the limit' : 'at v_0 no other CFL of the scan lies between it and the limit').\
  (small_stops ne '' ? '; at v_0/100 it stops at '.small_stops : '; at v_0/100 it completes every CFL of the scan')
stats data.'/dyka_stability_above.csv' using 2 nooutput prefix "A"
stats data.'/dyka_stability_below.csv' using 2 nooutput prefix "B"
vlo = (A_min < B_min ? A_min : B_min); vhi = (A_max > B_max ? A_max : B_max)
vlo = vlo - 0.05 * (vhi - vlo); vhi = vhi + 0.05 * (vhi - vlo)
LF = sprintf("lw 1 dt %d lc rgb '%s'", dash('fe'), colour('linear'))
time_axes = sprintf("set xtics norotate mirror; set xrange [0:20]; set ylabel 'v_A (m/s)'; set ytics %g, 5, %g; set grid xtics ytics; unset label; unset arrow; ", ceil(vlo / 5) * 5, vhi)
run_below = sprintf("set title 'linear (Q4) + FE at v_0 = 5 m/s, CFL %s = %.3f × its step limit %.4f: the last CFL of the scan before its first stopped run; it completes 20 ms' enhanced; ", below, fb, limit).\
  time_axes."unset xlabel; set format x ''; ".sprintf("set yrange [%g:%g]; ", vlo, vhi).\
  "set key at screen 0.715, screen 0.335 left top Left reverse samplen 2; ".\
  sprintf("plot '%s/dyka_stability_below.csv' using ($1*1e3):2 with lines %s title 'v_A, linear (Q4) + FE'", data, LF)
run_above = sprintf("set title 'CFL %s = %.3f × the limit: its first stopped run; the solver stopped it at t = %.2f ms (energy over 100 times its initial value)\n%s' enhanced; ", above, fa, stop, others).\
  time_axes."set xlabel 't (ms)'; set format x '%g'; ".strip_linear(vlo, vhi, 'where it stopped').\
  sprintf("set arrow 1 from %g, graph 0 to %g, graph 1 nohead lw 1.5 lc rgb c_exact front; ", stop, stop).\
  "set key at screen 0.715, screen 0.165 left top Left reverse samplen 2; ".\
  sprintf("plot '%s/dyka_stability_above.csv' using ($1*1e3):2 with lines %s notitle, ", data, LF).\
  sprintf("'+' using (%g):(%g) every ::0::0 with points %s title sprintf('stopped by the solver at t = %%.2f ms', %g), ", stop, strip_y_linear(vlo, vhi), stopped_style, stop).\
  sprintf("'+' using (%g):(%g) every ::0::0 with points pt %d ps 1.3 lc rgb '%s' title 'beside ×: the run''s method, %s', ", stop + 0.3, strip_y_linear(vlo, vhi), marker('fe'), colour('linear'), method_name('linear', 'fe')).\
  "keyentry with lines lw 1.5 lc rgb c_exact title 'the time it stopped'"

stats runs every ::1 using 5 nooutput prefix "S"   # the scan's factors
title = sprintf("Where methods fail on the Dyka bar (40 cells, 20 ms): each method scanned from %.2f to %.2f times its step limit on the %s, at v_0 = 5 m/s and v_0/100", S_min, S_max, held == 0 ? 'free bar' : 'free bar (held bar where named)')
draw = "set multiplot title title; set lmargin at screen 0.07; set rmargin at screen 0.70; set tmargin at screen 0.925; set bmargin at screen 0.555; ".left."; ".\
  "unset xrange; unset yrange; unset xtics; set xtics; unset ylabel; set tmargin at screen 0.335; set bmargin at screen 0.215; ".run_below."; ".\
  "set tmargin at screen 0.165; set bmargin at screen 0.045; ".run_above."; unset multiplot"
load dir."/output.gp"
