# Fig. 7: the predictor-corrector against forward Euler (LME γ = 3, 40 cells, CFL 0.5), in three panels so
# that the five curves stay apart: forward Euler and forward Euler damped by the PIC/FLIP blend; the
# predictor-corrector (Eq. 32) and its Newmark average; every curve on the jump at 40-66 µs, where the average lies
# on forward Euler and the blend near Eq. (32): the title names them.
# gnuplot -e "dir='...'; data='...'; out='...'" dyka_fig7.gp
load dir."/common.gp"
w = 13; h = 4.5
f(name) = data.'/dyka_lme_'.name.'_40.csv'
exact = sprintf("'%s' using ($1*1e6):3 with lines %s title 'exact'", f('fe'), exact_style)
curve(name, colour, style, title) = sprintf(", '%s' using ($1*1e6):2 with lines lw 1.5 %s lc rgb '%s' title '%s'", f(name), style, colour, title)
fe = curve('fe', '#d62728', 'dt 1', 'FE') . curve('feblend', '#ff7f0e', 'dt 2', 'FE + PIC/FLIP blend')
npc = curve('npc', '#1f77b4', 'dt 1', 'NPC (Eq. 32)') . curve('npcavg', '#2ca02c', 'dt 2', 'NPC, Newmark average')
common = "set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [0:200]; set yrange [-8:9.5]; set key top center horizontal font ',8'; "
left = common."set title 'forward Euler, undamped and blended'; plot ".exact.fe
middle = common."set title 'predictor-corrector, Eq. (32) and average'; plot ".exact.npc
right = "set title 'all five on the jump at 46 µs: the average lies on FE, the blend near NPC'; set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [40:66]; set yrange [-1.5:8.5]; set key bottom center font ',8'; plot ".exact.fe.npc
draw = "set multiplot layout 1,3 title 'Fig. 7: predictor-corrector against forward Euler (LME γ = 3, 40 cells, CFL 0.5)'; ".left."; ".middle."; ".right."; unset multiplot"
load dir."/output.gp"
