# FE against NPC, fairly: per shape function (columns), on the meshes without grid crossing (10-160 cells).
# Top row: RMS of v_A / |v0| against cells for forward Euler compared at t and at t + dt/2 (the time its
# velocity approximates), the predictor-corrector as printed (Eq. 32) and with the Newmark average, and
# forward Euler damped by a PIC/FLIP blend calibrated on that shape to its own NPC energy. Bottom row: each
# variant's RMS divided by NPC's, so that curves lying on NPC's in the top row stay apart (the blend's
# within a few per cent of NPC).
load dir."/common.gp"
w = 12; h = 7
fair = data.'/dyka_fair.csv'
sel(shape) = sprintf("fair using (strcol(1) eq '%s' ? $2 : NaN)", shape)
pts = "with linespoints ps 1.2"
top(shape, title) = sprintf("set title '%s'; set logscale y; set yrange [0.1:0.4]; set ytics (0.1, 0.15, 0.2, 0.3, 0.4); set ylabel 'RMS / |v_0|'; set key top right font ',8'; plot ", title).sel(shape).":3 ".pts." pt 7 lc rgb '#d62728' title 'FE at t', ".sel(shape).":4 ".pts." pt 6 dt 2 lc rgb '#d62728' title 'FE at t + dt/2', ".sel(shape).":5 ".pts." pt 5 lc rgb '#1f77b4' title 'NPC (Eq. 32)', ".sel(shape).":6 ".pts." pt 4 lc rgb '#2ca02c' title 'NPC, Newmark average', ".sel(shape).":7 ".pts." pt 9 dt 3 lc rgb '#9467bd' title 'FE + PIC/FLIP blend'"
bottom(shape) = "set title ''; unset logscale y; set ytics auto; set yrange [0.97:1.5]; set ylabel 'RMS / RMS_{NPC}'; set key top right font ',8'; plot 1 with lines lc rgb '#1f77b4' title 'NPC', ".sel(shape).":($3/$5) ".pts." pt 7 lc rgb '#d62728' title 'FE at t', ".sel(shape).":($4/$5) ".pts." pt 6 dt 2 lc rgb '#d62728' title 'FE at t + dt/2', ".sel(shape).":($6/$5) ".pts." pt 4 lc rgb '#2ca02c' title 'NPC, Newmark average', ".sel(shape).":($7/$5) ".pts." pt 9 dt 3 lc rgb '#9467bd' title 'FE + PIC/FLIP blend'"
draw = "set multiplot layout 2,3 title 'FE against NPC, fairly: RMS of v_A (Eq. 43) / |v_0| against the number of cells (no grid crossing; blend calibrated per shape)'; set logscale x; set xrange [8:200]; set xlabel 'cells'; ".top('linear','linear (Q4)')."; ".top('ugimp','uGIMP')."; ".top('lme','LME, γ = 3')."; ".bottom('linear')."; ".bottom('ugimp')."; ".bottom('lme')."; unset multiplot"
load dir."/output.gp"
