# Fig. 6 at 2 particles per cell: RMS of v_A / |v_0| against the number of cells, one panel
# per shape function; dashed: 1 particle per cell (the Dyka suite's sweep), solid: 2 particles per
# cell; FE red, NPC blue. Dotted verticals: where grid crossing starts (crossing ratio of paper/08_test_cases.md (Grid-crossing bands)
# = 1) at 2 ppc (1011 cells) and 1 ppc (2021 cells). Crosses at the top: the run stopped. Fourth panel:
# today's baselines at 2 ppc (160 and 1280 cells), solid FE, dashed NPC; grey: LME γ = 3 + NPC at 2 ppc.
# gnuplot -e "dir='...'; data='...'; out='...'" dyka_fig6_2ppc.gp
load dir."/common.gp"
up(i) = (i eq 'fe' ? 'FE' : 'NPC')
w = 16; h = 4.5
one = data.'/dyka_sweep.csv'; two = data.'/dyka_2ppc.csv'
colour(i) = (i eq 'fe' ? '#d62728' : '#1f77b4')
panel(s, title) = sprintf("set title '%s'; plot for [i in 'fe npc'] one using (strcol(1) eq '%s' && strcol(2) eq i && strcol(12) eq 'ok' ? $3 : NaN):8 with linespoints dt 2 pt 6 lc rgb colour(i) title up(i).', 1 ppc', for [i in 'fe npc'] two using (strcol(1) eq '%s' && strcol(2) eq i && strcol(8) eq 'ok' ? $3 : NaN):5 with linespoints lw 2 pt 7 lc rgb colour(i) title up(i).', 2 ppc', for [i in 'fe npc'] one using (strcol(1) eq '%s' && strcol(2) eq i && strcol(12) eq 'failed' ? $3 : NaN):(8) with points pt 2 ps 1.5 lc rgb colour(i) notitle, for [i in 'fe npc'] two using (strcol(1) eq '%s' && strcol(2) eq i && strcol(8) eq 'failed' ? $3 : NaN):(8) with points pt 2 ps 2 lw 2 lc rgb colour(i) notitle", title, s, s, s, s)
S = 'bspline2 bspline2 bspline3 bspline3 linear linear lme0.8 lme0.8 lme1.5 lme1.5'; I = 'fe npc fe npc usl musl fe npc fe npc'
bcolour(k) = word('#ff7f0e #ff7f0e #8c564b #8c564b #17becf #7f7f7f #e377c2 #e377c2 #bcbd22 #bcbd22', k)
bname(k) = word('B-spline2,FE B-spline2,NPC B-spline3,FE B-spline3,NPC linear,USL linear,MUSL LME0.8,FE LME0.8,NPC LME1.5,FE LME1.5,NPC', k)
mine(k) = (strcol(1) eq word(S, k) && strcol(2) eq word(I, k))
bpanel = "set title 'baselines, 2 ppc (cross at the top: stopped)'; set yrange [0.04:0.5]; set key top left font ',6' maxrows 6; plot two using (strcol(1) eq 'lme' && strcol(2) eq 'npc' && strcol(8) eq 'ok' ? $3 : NaN):5 with linespoints lw 4 lc rgb '#cccccc' title 'LME γ = 3, NPC', for [k = 1:10] two using (mine(k) && strcol(8) eq 'ok' ? $3 : NaN):5 with linespoints lw 1.5 dt 1+(word(I, k) eq 'npc') pt 7 lc rgb bcolour(k) title bname(k), for [k = 1:10] two using (mine(k) && strcol(8) eq 'failed' ? $3 : NaN):(0.45) with points pt 2 ps 2 lw 2 lc rgb bcolour(k) notitle"
draw = "set multiplot layout 1,4 title 'Fig. 6 at 1 and 2 particles per cell: RMS of v_A / |v_0| against the number of cells (CFL 0.5, 200 µs)'; set logscale xy; set xrange [7:8000]; set yrange [0.02:10]; set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set key top left font ',7'; set arrow 1 from 1011, graph 0 to 1011, graph 1 nohead dt 3 lc rgb '#555555'; set arrow 2 from 2021, graph 0 to 2021, graph 1 nohead dt 3 lc rgb '#999999'; " . \
  panel('linear', 'linear (Q4)') . "; " . panel('ugimp', 'uGIMP') . "; " . panel('lme', 'LME, γ = 3') . "; " . bpanel . "; unset multiplot"
load dir."/output.gp"
