# The vibrating bar: RMS error of velocity (top) and stress (bottom) against the number of
# cells, one column per shape function; colour: integrator (FE red, NPC blue); solid: 1 particle per
# cell, dashed: 2; filled points: CFL 0.5, open: CFL 0.1. Grey guides: slopes 1 and 2. Runs that
# stopped are left out (their line breaks). Fourth column: today's baselines (CFL 0.5), one colour per
# method, solid 1 particle per cell, dashed 2.
# gnuplot -e "dir='...'; data='...'; out='...'; amplitude='small|large'; caption='...'" smooth_bar.gp
load dir."/common.gp"
up(i) = (i eq 'fe' ? 'FE' : 'NPC')
w = 15; h = 7
sweep = data.'/smooth_bar.csv'
ok(s, i, p, c) = (strcol(1) eq amplitude && strcol(2) eq s && strcol(3) eq i && $4 == p && abs($5 - c) < 1e-9 && strcol(12) eq 'ok')
colour(i) = (i eq 'fe' ? '#d62728' : '#1f77b4')
curves(s, col) = sprintf("for [i in 'fe npc'] for [p = 1:2] for [c in '0.5 0.1'] sweep using (ok('%s', i, p, real(c)) ? $6 : NaN):%d with linespoints lw 1.5 dt p pt (real(c) > 0.3 ? 7 : 6) lc rgb colour(i) title sprintf('%%s, %%d ppc, CFL %%s', up(i), p, c), 0.05*(x/8)**-1 with lines dt 3 lc rgb '#888888' title 'h^1', 0.05*(x/8)**-2 with lines dt 4 lc rgb '#888888' title 'h^2'", s, col)
S = 'bspline2 bspline2 bspline3 bspline3 linear linear'; I = 'fe npc fe npc usl musl'
bcolour(k) = word('#ff7f0e #ff7f0e #8c564b #8c564b #17becf #7f7f7f', k)
bname(k) = word('B-spline2,FE B-spline2,NPC B-spline3,FE B-spline3,NPC linear,USL linear,MUSL', k)
bcurves(col) = sprintf("for [k = 1:6] for [p = 1:2] sweep using (ok(word(S, k), word(I, k), p, 0.5) ? $6 : NaN):%d with linespoints lw 1.5 dt p pt (word(I, k) eq 'npc' ? 9 : 7) lc rgb bcolour(k) title sprintf('%%s, %%d ppc', bname(k), p)", col)
bpanel(title, col) = sprintf("set title '%s'; set ylabel ''; plot %s", title, bcurves(col))
panel(s, title, col, ylabel) = sprintf("set title '%s'; set ylabel '%s'; plot %s", title, ylabel, curves(s, col))
draw = "set multiplot layout 2,4 title caption; set logscale xy; set format y '10^{%L}'; set xrange [6:340]; set yrange [1e-6:2]; set xlabel 'cells'; set key bottom left font ',6' maxrows 4; " . \
  panel('linear', 'linear', 7, 'RMS(v_p - v) / V') . "; set key off; " . panel('ugimp', 'uGIMP', 7, '') . "; " . panel('lme', 'LME, γ = 3', 7, '') . "; set key bottom left font ',6' maxrows 6; " . bpanel('baselines: B-splines, USL, MUSL', 7) . "; set key off; " . \
  panel('linear', '', 8, 'RMS(σ_p - σ) / ZV') . "; " . panel('ugimp', '', 8, '') . "; " . panel('lme', '', 8, '') . "; " . bpanel('', 8) . "; unset multiplot"
load dir."/output.gp"
