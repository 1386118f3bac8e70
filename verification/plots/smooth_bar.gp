# The vibrating bar: RMS error of velocity (top) and stress (bottom) against the number of
# cells, one column per shape function; colour: integrator (FE red, NPC blue); solid with circles: 1
# particle per cell, dashed with squares: 2; filled points: CFL 0.5, open: CFL 0.1. Grey guides: slopes
# 1 and 2. A run that stopped is a cross above the data (its error is not drawn; 2 ppc higher). Fourth column:
# today's baselines (CFL 0.5), one colour per method, ppc as in the other columns. Each row's y range
# is the range of its data (stats), the x range the meshes run; the legends lie below the panels.
# gnuplot -e "dir='...'; data='...'; out='...'; amplitude='small|large'; caption='...'" smooth_bar.gp
load dir."/common.gp"
w = 15; h = 7.5
sweep = data.'/smooth_bar.csv'
mine(s, i, p, c) = (strcol(1) eq amplitude && strcol(2) eq s && strcol(3) eq i && $4 == p && abs($5 - c) < 1e-9)
ok(s, i, p, c) = (mine(s, i, p, c) && strcol(12) eq 'ok')
stopped(s, i, p, c) = (mine(s, i, p, c) && strcol(12) ne 'ok')
colour(i) = (i eq 'fe' ? '#d62728' : '#1f77b4')
point(p, c) = (p == 1 ? (c > 0.3 ? 7 : 6) : (c > 0.3 ? 5 : 4))
stats sweep using (strcol(1) eq amplitude && strcol(12) eq 'ok' ? $7 : NaN) nooutput
vlow = STATS_min / 2; vhigh = STATS_max * 16; vmark = STATS_max * 2.5
stats sweep using (strcol(1) eq amplitude && strcol(12) eq 'ok' ? $8 : NaN) nooutput
slow = STATS_min / 2; shigh = STATS_max * 16; smark = STATS_max * 2.5
stats sweep using (strcol(1) eq amplitude && strcol(12) ne 'ok' ? 1 : 0) nooutput
if (STATS_sum == 0) { vhigh = vhigh / 8; shigh = shigh / 8 }  # no stopped run: no room for its marks
stats sweep using (strcol(1) eq amplitude ? $6 : NaN) nooutput
xlow = STATS_min / 1.3; xhigh = STATS_max * 1.3
curves(s, col, mark) = sprintf("for [i in 'fe npc'] for [p = 1:2] for [c in '0.5 0.1'] sweep using (ok('%s', i, p, real(c)) ? $6 : NaN):%d with linespoints lw 1.5 dt p pt point(p, real(c)) lc rgb colour(i), for [i in 'fe npc'] for [p = 1:2] for [c in '0.5 0.1'] sweep using (stopped('%s', i, p, real(c)) ? $6 : NaN):(%g * (p == 2 ? 2.5 : 1)) with points pt 2 ps 1.5 lw 2 lc rgb colour(i), 0.05*(x/8)**-1 with lines dt 3 lc rgb '#888888', 0.05*(x/8)**-2 with lines dt 4 lc rgb '#888888'", s, col, s, mark)
legend = "NaN with lines lw 2 lc rgb '#d62728' title 'FE', NaN with lines lw 2 lc rgb '#1f77b4' title 'NPC', NaN with linespoints dt 1 pt 7 lc rgb 'black' title '1 ppc', NaN with linespoints dt 2 pt 5 lc rgb 'black' title '2 ppc', " . (amplitude eq 'small' ? "NaN with points pt 7 lc rgb 'black' title 'CFL 0.5 (filled)', NaN with points pt 6 lc rgb 'black' title 'CFL 0.1 (open)', " : "") . "NaN with lines dt 3 lc rgb '#888888' title 'slopes 1 (dotted) and 2', NaN with points pt 2 lw 2 lc rgb 'black' title 'run stopped (upper: 2 ppc)'"
S = 'bspline2 bspline2 bspline3 bspline3 linear linear'; I = 'fe npc fe npc usl musl'
bcolour(k) = word('#ff7f0e #8c564b #2ca02c #9467bd #17becf #7f7f7f', k)
bname(k) = word('B-spline2,FE B-spline2,NPC B-spline3,FE B-spline3,NPC linear,USL linear,MUSL', k)
bcurves(col, mark) = sprintf("for [k = 1:6] for [p = 1:2] sweep using (ok(word(S, k), word(I, k), p, 0.5) ? $6 : NaN):%d with linespoints lw 1.5 dt p pt (p == 1 ? 7 : 5) lc rgb bcolour(k), for [k = 1:6] for [p = 1:2] sweep using (stopped(word(S, k), word(I, k), p, 0.5) ? $6 : NaN):(%g * (p == 2 ? 2.5 : 1)) with points pt 2 ps 1.5 lw 2 lc rgb bcolour(k)", col, mark)
blegend = "for [k = 1:6] NaN with lines lw 2 lc rgb bcolour(k) title bname(k)"
panel(s, title, col, ylabel, mark, extra) = sprintf("set title '%s'; set ylabel '%s'; plot %s%s", title, ylabel, curves(s, col, mark), extra)
bpanel(title, col, mark, extra) = sprintf("set title '%s'; set ylabel ''; plot %s%s", title, bcurves(col, mark), extra)
row(col, ylabel, low, high, mark, legends) = sprintf("set yrange [%g:%g]; ", low, high) . \
  (legends ? "set key at screen 0.03, 0.1 left top horizontal Left reverse font ',8' samplen 2; " : "set key off; ") . panel('linear', 'linear', col, ylabel, mark, legends ? ', '.legend : '') . "; set key off; " . \
  panel('ugimp', 'uGIMP', col, '', mark, '') . "; " . panel('lme', 'LME, γ = 3', col, '', mark, '') . "; " . \
  (legends ? "set key at screen 0.76, 0.1 left top horizontal Left reverse font ',8' samplen 2; " : "") . bpanel('baselines: B-splines, USL, MUSL (CFL 0.5)', col, mark, legends ? ', '.blegend : '') . "; set key off"
note = (amplitude eq 'small' ? "set label 99 'At small amplitude uGIMP coincides with linear (the same numbers), and NPC at 1 and 2 ppc nearly coincide (squares over circles); in the baselines B-spline2 and B-spline3 with NPC coincide, and so do USL and MUSL.' at screen 0.03, 0.015 font ',8'; " : "")
draw = note . sprintf("set multiplot layout 2,4 title caption margins 0.05, 0.99, 0.15, 0.92 spacing 0.04, 0.08; set logscale xy; set format y '10^{%%L}'; set xrange [%g:%g]; set xlabel 'cells'; ", xlow, xhigh) . \
  row(7, 'RMS(v_p - v) / V', vlow, vhigh, vmark, 0) . "; set title ''; " . row(8, 'RMS(σ_p - σ) / ZV', slow, shigh, smark, 1) . "; unset multiplot; unset label 99"
load dir."/output.gp"
