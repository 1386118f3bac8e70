# Fig. 7: the predictor-corrector against forward Euler (LME γ = 3, 40 cells, CFL 0.5), as the paper draws it in make
# figures (fair = 0): forward Euler, the predictor-corrector (Eq. 32), both on the jump at 40-66 µs, and both on the
# jump under the authors' β (paper/09_choices.md, 'The authors' beta'). In make studies (fair = 1, out dyka_fig7_fair)
# five curves in four panels, so that they stay apart: forward Euler and forward Euler damped by the PIC/FLIP blend;
# the predictor-corrector and its Newmark average; every curve on the jump, where the average lies on forward Euler
# and the blend near Eq. (32): the title names them; the same on the jump under the authors' β, the blend
# calibrated again under it.
# gnuplot -e "dir='...'; data='...'; out='...'[; fair=1]" dyka_fig7.gp
load dir."/common.gp"
w = 13; h = 8
f(name) = data.'/dyka_lme_'.name.'_40.csv'
exact = sprintf("'%s' using ($1*1e6):3 with lines %s title 'exact'", f('fe'), exact_style)
curve(name, colour, style, title) = sprintf(", '%s' using ($1*1e6):2 with lines lw 1.5 %s lc rgb '%s' title '%s'", f(name), style, colour, title)
if (!exists("fair")) fair = 0
fe = curve('fe', '#d62728', 'dt 1', 'FE')
npc = curve('npc', '#1f77b4', 'dt 1', 'NPC (Eq. 32)')
fe_authors = curve('authors_fe', '#d62728', 'dt 1', 'FE')
npc_authors = curve('authors_npc', '#1f77b4', 'dt 1', 'NPC (Eq. 32)')
if (fair) {
  fe = fe . curve('feblend', '#ff7f0e', 'dt 2', 'FE + PIC/FLIP blend')
  npc = npc . curve('npcavg', '#2ca02c', 'dt 2', 'NPC, Newmark average')
  fe_authors = fe_authors . curve('authors_feblend', '#ff7f0e', 'dt 2', 'FE + PIC/FLIP blend')
  npc_authors = npc_authors . curve('authors_npcavg', '#2ca02c', 'dt 2', 'NPC, Newmark average')
}
common = "set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [0:200]; set yrange [-8:9.5]; set key top center horizontal font ',8'; "
left = common."set title '".(fair ? "forward Euler, undamped and blended" : "forward Euler")."'; plot ".exact.fe
middle = common."set title '".(fair ? "predictor-corrector, Eq. (32) and average" : "predictor-corrector (Eq. 32)")."'; plot ".exact.npc
jump = "set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [40:66]; set yrange [-1.5:8.5]; "
jump = jump."set key bottom center font ',8'; "
right = jump."set title '".(fair ? "all five on the jump at 46 µs: the average lies on FE, the blend near NPC" : "both on the jump at 46 µs")."'; plot ".exact.fe.npc
authors = jump."set title 'the same on the jump under the authors'' β'; plot ".exact.fe_authors.npc_authors
title = "Fig. 7".(fair ? " with the fair variants" : "").": predictor-corrector against forward Euler (LME γ = 3, 40 cells, CFL 0.5; "
title = title."bottom right: the authors'' β)"
draw = "set multiplot layout 2,2 title '".title."'; ".left."; ".middle."; ".right."; ".authors."; unset multiplot"
load dir."/output.gp"
