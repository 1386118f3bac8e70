# 2D manufactured solutions: RMS errors of velocity (left) and stress (middle) against the
# cells per side, small amplitude (top) and large amplitude (bottom); colour: shape function; solid:
# forward Euler, dashed: predictor-corrector; filled points: 2 x 2 particles per cell, open: 1.
# Grey guides: slopes 1 and 2. A run that stopped is a cross above the data. Right column: today's
# baselines' velocity error at 2 x 2 particles per cell, small (top) and large amplitude (bottom), one
# colour per method, with LME γ = 3 + NPC in grey for reference. Each row's y range is its data's.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_manufactured.gp
load dir."/common.gp"
w = 14; h = 7.5
file = data.'/smooth_manufactured.csv'
colour(s) = (s eq 'linear' ? '#2ca02c' : s eq 'ugimp' ? '#9467bd' : '#d62728')
mine(a, s, i, p) = (strcol(1) eq a && strcol(2) eq s && strcol(3) eq i && $4 == p)
ok(a, s, i, p) = (mine(a, s, i, p) && strcol(10) eq 'ok')
stopped(a, s, i, p) = (mine(a, s, i, p) && strcol(10) ne 'ok')
stats file using (strcol(1) eq 'small' ? $6 : NaN):(strcol(1) eq 'small' ? $7 : NaN) nooutput
small_low = (STATS_min_x < STATS_min_y ? STATS_min_x : STATS_min_y) / 1.5; small_high = (STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y) * 1.5
stats file using (strcol(1) eq 'large' && strcol(10) eq 'ok' ? $6 : NaN):(strcol(1) eq 'large' && strcol(10) eq 'ok' ? $7 : NaN) nooutput
large_low = (STATS_min_x < STATS_min_y ? STATS_min_x : STATS_min_y) / 1.5; large_mark = (STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y) * 2.5; large_high = large_mark * 2
stats file using (strcol(10) ne 'ok' ? 1 : 0) nooutput
if (STATS_sum == 0) { large_high = large_mark / 2 }  # no stopped run: no room for its marks
mark(a) = (a eq 'small' ? small_high : large_mark)
panel(a, col, title, ylabel) = sprintf("set title '%s'; set ylabel '%s'; plot for [s in 'linear ugimp lme'] for [i in 'fe npc'] for [p = 1:2] file using (ok('%s', s, i, p) ? $5 : NaN):%d with linespoints lw 1.5 dt 1+(i eq 'npc') pt (p == 2 ? 7 : 6) lc rgb colour(s), for [s in 'linear ugimp lme'] for [i in 'fe npc'] for [p = 1:2] file using (stopped('%s', s, i, p) ? $5 : NaN):(%g) with points pt 2 ps 1.5 lw 2 lc rgb colour(s), 0.15*(x/8)**-1 with lines dt 3 lc rgb '#888888', 0.15*(x/8)**-2 with lines dt 4 lc rgb '#888888'", title, ylabel, a, col, a, mark(a))
legend = ", NaN with lines lw 2 lc rgb '#2ca02c' title 'linear', NaN with lines lw 2 lc rgb '#9467bd' title 'uGIMP', NaN with lines lw 2 lc rgb '#d62728' title 'LME, γ = 3', NaN with lines dt 1 lc rgb 'black' title 'FE', NaN with lines dt 2 lc rgb 'black' title 'NPC', NaN with points pt 6 lc rgb 'black' title '1x1 ppc', NaN with points pt 7 lc rgb 'black' title '2x2 ppc', NaN with points pt 2 lw 2 lc rgb 'black' title 'run stopped'"
S = 'bspline2 bspline2 bspline3 bspline3 linear linear'; I = 'fe npc fe npc usl musl'
bcolour(k) = word('#ff7f0e #ff7f0e #8c564b #8c564b #17becf #7f7f7f', k)
bname(k) = word('B-spline2,FE B-spline2,NPC B-spline3,FE B-spline3,NPC linear,USL linear,MUSL', k)
bpanel(a, title, extra) = sprintf("set title '%s'; set ylabel ''; plot for [k = 1:6] file using (ok('%s', word(S, k), word(I, k), 2) ? $5 : NaN):6 with linespoints lw 1.5 dt 1+(word(I, k) eq 'npc') pt 7 lc rgb bcolour(k) title (%d ? bname(k) : ''), for [k = 1:6] file using (stopped('%s', word(S, k), word(I, k), 2) ? $5 : NaN):(%g) with points pt 2 ps 1.5 lw 2 lc rgb bcolour(k), file using (ok('%s', 'lme', 'npc', 2) ? $5 : NaN):6 with linespoints lw 3 lc rgb '#bbbbbb' title (%d ? 'LME γ = 3, NPC' : '')", title, a, extra, a, mark(a), a, extra)
draw = "set label 99 'At small amplitude linear coincides with uGIMP (green hidden under purple); USL and MUSL nearly coincide.' at screen 0.02, 0.012 font ',8'; set multiplot layout 2,3 title '2D manufactured solutions (plane strain, ν = 0.3): RMS errors at 1/8, 1/4, 3/8, 1/2 period' margins 0.06, 0.99, 0.15, 0.92 spacing 0.05, 0.1; set logscale xy; set format y '10^{%L}'; set xrange [7:36]; set xtics (8, 12, 16, 24, 32); set xlabel 'cells per side'; " . \
  sprintf("set yrange [%g:%g]; ", small_low, small_high) . "set key at screen 0.02, 0.09 left top horizontal Left reverse font ',8' samplen 2; " . panel('small', 6, 'small amplitude: velocity', 'RMS |v_p - v| / Aω') . legend . "; set key off; " . panel('small', 7, 'small amplitude: stress', 'RMS |σ_p - σ| / σ scale') . "; set key at screen 0.68, 0.09 left top horizontal Left reverse font ',8' samplen 2; " . bpanel('small', 'baselines, 2x2 ppc, small amplitude: velocity', 1) . "; set key off; " . \
  sprintf("set yrange [%g:%g]; ", large_low, large_high) . panel('large', 6, 'large amplitude (diagonal stretch): velocity', 'RMS |v_p - v| / aω') . "; " . panel('large', 7, 'large amplitude: stress', 'RMS |σ_p - σ| / σ scale') . "; " . bpanel('large', 'baselines, 2x2 ppc, large amplitude: velocity', 0) . "; unset multiplot; unset label 99"
load dir."/output.gp"
