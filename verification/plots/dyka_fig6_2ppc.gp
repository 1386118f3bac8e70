# Fig. 6 at 2 particles per cell: RMS of v_A / |v_0| against the number of cells, one panel
# per shape function; dashed with open points: 1 particle per cell (the Dyka suite's sweep at CFL 0.5),
# solid with filled points: 2 particles per cell; FE red, NPC blue. Dotted verticals: where grid
# crossing starts (crossing ratio of paper/08_test_cases.md (Grid-crossing bands) = 1) at 2 ppc
# (1011 cells) and 1 ppc (2021 cells). Crosses above the data: the run stopped (no error drawn; 2 ppc
# higher, FE left of NPC). Fourth panel: today's baselines at 2 ppc (160 and 1280 cells), solid FE, dashed NPC; grey:
# LME γ = 3 + NPC at 2 ppc. Axes: the data's range (stats); legends below the panels.
# Reads dyka_fig6_2ppc.csv (ppc, shape, integrator, cells, crossing_ratio, rms_over_v0, status), written by
# smooth_suite --fig6-2ppc, and dyka_2ppc.csv for the baselines.
# gnuplot -e "dir='...'; data='...'; out='...'" dyka_fig6_2ppc.gp
load dir."/common.gp"
w = 16; h = 5.2
file = data.'/dyka_fig6_2ppc.csv'; two = data.'/dyka_2ppc.csv'
colour(i) = (i eq 'fe' ? '#d62728' : '#1f77b4')
stats file using 4:(strcol(7) eq 'ok' ? $6 : NaN) nooutput
xlow = STATS_min_x / 1.4; xhigh = STATS_max_x * 1.4; ylow = STATS_min_y / 1.3; mark = STATS_max_y * 1.8; yhigh = STATS_max_y * 4
mine(s, i, p) = (strcol(2) eq s && strcol(3) eq i && $1 == p)
panel(s, title, extra) = sprintf("set title '%s'; plot for [i in 'fe npc'] for [p = 1:2] file using (mine('%s', i, p) && strcol(7) eq 'ok' ? $4 : NaN):6 with linespoints lw p dt 3-p pt (p == 1 ? 6 : 7) lc rgb colour(i), for [i in 'fe npc'] for [p = 1:2] file using (mine('%s', i, p) && strcol(7) ne 'ok' ? $4 * (i eq 'fe' ? 0.92 : 1.08) : NaN):(mark * (p == 2 ? 1.6 : 1)) with points pt 2 ps 1.5 lw 2 lc rgb colour(i)%s", title, s, s, extra)
legend = ", NaN with lines lw 2 lc rgb '#d62728' title 'FE', NaN with lines lw 2 lc rgb '#1f77b4' title 'NPC', NaN with linespoints dt 2 pt 6 lc rgb 'black' title '1 ppc', NaN with linespoints lw 2 pt 7 lc rgb 'black' title '2 ppc', NaN with lines dt 3 lc rgb '#555555' title 'crossing starts: 2 ppc (1011), 1 ppc (2021 cells)', NaN with points pt 2 lw 2 lc rgb 'black' title 'run stopped (upper: 2 ppc)'"
S = 'bspline2 bspline3 lme0.8 lme1.5 usl musl'
bcolour(k) = word('#ff7f0e #8c564b #e377c2 #bcbd22 #17becf #7f7f7f', k)
bname(k) = word('B-spline2 B-spline3 LME,γ=0.8 LME,γ=1.5 linear,USL linear,MUSL', k)
bmine(k) = (word(S, k) eq 'usl' || word(S, k) eq 'musl' ? strcol(1) eq 'linear' && strcol(2) eq word(S, k) : strcol(1) eq word(S, k))
bpanel = "set title 'baselines, 2 ppc: solid FE, dashed NPC'; plot two using (strcol(1) eq 'lme' && strcol(2) eq 'npc' && strcol(8) eq 'ok' ? $3 : NaN):5 with linespoints lw 4 lc rgb '#cccccc' title 'LME γ = 3, NPC', for [k = 1:6] for [i in 'fe npc usl musl'] two using (bmine(k) && strcol(2) eq i && strcol(8) eq 'ok' ? $3 : NaN):5 with linespoints lw 1.5 dt 1+(i eq 'npc') pt 7 lc rgb bcolour(k), for [k = 1:6] two using (bmine(k) && strcol(8) ne 'ok' ? $3 : NaN):(mark) with points pt 2 ps 2 lw 2 lc rgb bcolour(k), for [k = 1:6] NaN with lines lw 2 lc rgb bcolour(k) title bname(k)"
draw = "set label 99 'At 1280 cells the B-splines, LME γ = 0.8 and 1.5 with NPC and LME γ = 3 with NPC coincide (RMS 0.072-0.074: see the report).' at screen 0.55, 0.015 font ',8'; " . sprintf("set multiplot layout 1,4 title 'Fig. 6 at 1 and 2 particles per cell: RMS of v_A / |v_0| against the number of cells (CFL 0.5, 200 µs)' margins 0.05, 0.99, 0.24, 0.88 spacing 0.04, 0.1; set logscale xy; set xrange [%g:%g]; set yrange [%g:%g]; set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set arrow 1 from 1011, graph 0 to 1011, graph 1 nohead dt 3 lc rgb '#555555'; set arrow 2 from 2021, graph 0 to 2021, graph 1 nohead dt 3 lc rgb '#999999'; ", xlow, xhigh, ylow, yhigh) . \
  "set key at screen 0.03, 0.1 left top horizontal Left reverse maxrows 3 font ',8' samplen 2; " . panel('linear', 'linear (Q4)', legend) . "; set key off; " . panel('ugimp', 'uGIMP', '') . "; " . panel('lme', 'LME, γ = 3', '') . "; set ylabel ''; set key at screen 0.76, 0.1 left top horizontal Left reverse maxrows 3 font ',8' samplen 2; " . bpanel . "; unset multiplot; unset label 99"
load dir."/output.gp"
