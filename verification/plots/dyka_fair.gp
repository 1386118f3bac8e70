# FE against NPC, fairly: RMS of v_A / |v0| against cells on the meshes without grid crossing, per shape
# function: forward Euler compared at t and at t + dt/2 (the time its velocity approximates), the
# predictor-corrector as printed (Eq. 32) and with the Newmark average, and forward Euler damped by a
# PIC/FLIP blend to the predictor-corrector's energy loss.
load dir."/common.gp"
w = 12; h = 4
fair = data.'/dyka_fair.csv'
panel(shape, title) = sprintf("set title '%s'; plot fair using (strcol(1) eq '%s' ? $2 : NaN):3 with linespoints pt 7 lc rgb '#d62728' title 'FE at t', fair using (strcol(1) eq '%s' ? $2 : NaN):4 with linespoints pt 6 dt 2 lc rgb '#d62728' title 'FE at t + dt/2', fair using (strcol(1) eq '%s' ? $2 : NaN):5 with linespoints pt 5 lc rgb '#1f77b4' title 'NPC (Eq. 32)', fair using (strcol(1) eq '%s' ? $2 : NaN):6 with linespoints pt 4 lc rgb '#2ca02c' title 'NPC, Newmark average', fair using (strcol(1) eq '%s' ? $2 : NaN):7 with linespoints pt 9 lc rgb '#9467bd' title 'FE + PIC/FLIP blend'", title, shape, shape, shape, shape, shape)
draw = "set multiplot layout 1,3 title 'FE against NPC, fairly: RMS of v_A (Eq. 43) / |v_0| against the number of cells (no grid crossing)'; set datafile separator ','; set logscale xy; set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set key bottom left font ',8'; ".panel('linear','linear (Q4)')."; ".panel('ugimp','uGIMP')."; ".panel('lme','LME, γ = 3')."; unset multiplot"
load dir."/output.gp"
