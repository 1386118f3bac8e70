# 2D manufactured solutions: RMS errors of velocity (left) and stress (right) against the
# cells per side, small amplitude (top) and large amplitude (bottom); colour: shape function; solid:
# forward Euler, dashed: predictor-corrector; filled points: 2 x 2 particles per cell, open: 1.
# Grey guides: slopes 1 and 2. Runs that stopped are left out. Right column: today's baselines at small
# amplitude, 2 x 2 particles per cell, one colour per method, with LME γ = 3 + NPC in grey for reference.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_manufactured.gp
load dir."/common.gp"
up(i) = (i eq 'fe' ? 'FE' : 'NPC')
w = 14; h = 7
file = data.'/smooth_manufactured.csv'
colour(s) = (s eq 'linear' ? '#2ca02c' : s eq 'ugimp' ? '#9467bd' : '#d62728')
ok(a, s, i, p) = (strcol(1) eq a && strcol(2) eq s && strcol(3) eq i && $4 == p && strcol(10) eq 'ok')
panel(a, col, title, ylabel) = sprintf("set title '%s'; set ylabel '%s'; plot for [s in 'linear ugimp lme'] for [i in 'fe npc'] for [p = 1:2] file using (ok('%s', s, i, p) ? $5 : NaN):%d with linespoints lw 1.5 dt 1+(i eq 'npc') pt (p == 2 ? 7 : 6) lc rgb colour(s) title sprintf('%%s, %%s, %%dx%%d', s, up(i), p, p), 0.15*(x/8)**-1 with lines dt 3 lc rgb '#888888' title 'h^1', 0.15*(x/8)**-2 with lines dt 4 lc rgb '#888888' title 'h^2'", title, ylabel, a, col)
S = 'bspline2 bspline2 bspline3 bspline3 linear linear'; I = 'fe npc fe npc usl musl'
bcolour(k) = word('#ff7f0e #ff7f0e #8c564b #8c564b #17becf #7f7f7f', k)
bname(k) = word('B-spline2,FE B-spline2,NPC B-spline3,FE B-spline3,NPC linear,USL linear,MUSL', k)
bpanel(col, title) = sprintf("set title '%s'; set ylabel ''; plot for [k = 1:6] file using (ok('small', word(S, k), word(I, k), 2) ? $5 : NaN):%d with linespoints lw 1.5 dt 1+(word(I, k) eq 'npc') pt 7 lc rgb bcolour(k) title bname(k).', 2x2', file using (ok('small', 'lme', 'npc', 2) ? $5 : NaN):%d with linespoints lw 3 lc rgb '#bbbbbb' title 'LME γ = 3, NPC, 2x2'", title, col, col)
draw = "set multiplot layout 2,3 title '2D manufactured solutions (plane strain, ν = 0.3): RMS errors at 1/8, 1/4, 3/8, 1/2 period'; set logscale xy; set format y '10^{%L}'; set xrange [6:40]; set yrange [3e-3:3]; set xtics (8, 12, 16, 24, 32); set xlabel 'cells per side'; set key bottom left font ',6' maxrows 6; " . \
  panel('small', 6, 'small amplitude: velocity', 'RMS |v_p - v| / Aω') . "; set key off; " . panel('small', 7, 'small amplitude: stress', 'RMS |σ_p - σ| / σ scale') . "; set key bottom left font ',6' maxrows 4; " . bpanel(6, 'baselines, small amplitude: velocity') . "; set key off; " . \
  panel('large', 6, 'large amplitude (diagonal stretch): velocity', 'RMS |v_p - v| / aω') . "; " . panel('large', 7, 'large amplitude: stress', 'RMS |σ_p - σ| / σ scale') . "; " . bpanel(7, 'baselines, small amplitude: stress') . "; unset multiplot"
load dir."/output.gp"
