# Fig. 6 at 2 particles per cell (issue 10): RMS of v_A / |v_0| against the number of cells, one panel
# per shape function; dashed: 1 particle per cell (the Dyka suite's sweep), solid: 2 particles per
# cell; FE red, NPC blue. Dotted verticals: where grid crossing starts (crossing ratio of paper/08_test_cases.md (Grid-crossing bands)
# = 1) at 2 ppc (1011 cells) and 1 ppc (2021 cells). Crosses at the top: the run stopped.
# gnuplot -e "dir='...'; data='...'; out='...'" dyka_fig6_2ppc.gp
load dir."/common.gp"
up(i) = (i eq 'fe' ? 'FE' : 'NPC')
w = 12; h = 4
one = data.'/dyka_sweep.csv'; two = data.'/dyka_2ppc.csv'
colour(i) = (i eq 'fe' ? '#d62728' : '#1f77b4')
panel(s, title) = sprintf("set title '%s'; plot for [i in 'fe npc'] one using (strcol(1) eq '%s' && strcol(2) eq i && strcol(12) eq 'ok' ? $3 : NaN):8 with linespoints dt 2 pt 6 lc rgb colour(i) title up(i).', 1 ppc', for [i in 'fe npc'] two using (strcol(1) eq '%s' && strcol(2) eq i && strcol(8) eq 'ok' ? $3 : NaN):5 with linespoints lw 2 pt 7 lc rgb colour(i) title up(i).', 2 ppc', for [i in 'fe npc'] one using (strcol(1) eq '%s' && strcol(2) eq i && strcol(12) eq 'failed' ? $3 : NaN):(8) with points pt 2 ps 1.5 lc rgb colour(i) notitle, for [i in 'fe npc'] two using (strcol(1) eq '%s' && strcol(2) eq i && strcol(8) eq 'failed' ? $3 : NaN):(8) with points pt 2 ps 2 lw 2 lc rgb colour(i) notitle", title, s, s, s, s)
draw = "set multiplot layout 1,3 title 'Fig. 6 at 1 and 2 particles per cell: RMS of v_A / |v_0| against the number of cells (CFL 0.5, 200 µs)'; set logscale xy; set xrange [7:8000]; set yrange [0.02:10]; set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set key top left font ',7'; set arrow 1 from 1011, graph 0 to 1011, graph 1 nohead dt 3 lc rgb '#555555'; set arrow 2 from 2021, graph 0 to 2021, graph 1 nohead dt 3 lc rgb '#999999'; " . \
  panel('linear', 'linear (Q4)') . "; " . panel('ugimp', 'uGIMP') . "; " . panel('lme', 'LME, γ = 3') . "; unset multiplot"
load dir."/output.gp"
