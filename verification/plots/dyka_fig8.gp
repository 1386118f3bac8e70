# Fig. 8: sensitivity of LME to gamma: v_A(t) for each gamma (NPC, 40 cells) against the exact
# solution, and RMS against gamma for both integrators, under beta = gamma / h^2 and the authors' beta (dashed).
load dir."/common.gp"
w = 12; h = 4.5
gammas = "0.8 1 1.5 2 3 4 5"
colours = "#440154 #46327e #365c8d #277f8e #1fa187 #4ac16d #a0da39"
curves = sprintf("plot '%s/dyka_gamma_npc_0.8.csv' using ($1*1e6):3 with lines %s title 'exact'", data, exact_style)
do for [k=1:words(gammas)] { curves = curves.sprintf(", '%s/dyka_gamma_npc_%s.csv' using ($1*1e6):2 with lines lw 1.2 lc rgb '%s' title 'γ = %s'", data, word(gammas,k), word(colours,k), word(gammas,k)) }
left = "set title 'v_A(t), LME (β = γ / h^2), predictor-corrector, 40 cells'; set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [0:200]; set yrange [-7:8]; set key top right font ',8'; ".curves
right = "set title 'RMS of v_A against γ (40 cells)'; set xlabel 'γ (solid: β = γ / h^2; dashed: the authors'' β = γ / hbar^2)'; "
right = right."set ylabel 'RMS / |v_0|'; set xrange [0.5:5.5]; set autoscale y; set key top right; "
right = right.sprintf("plot '%s/dyka_gamma.csv' using 1:4 with linespoints pt 7 lc rgb '#d62728' title 'FE', ", data)
right = right."'' using 1:5 with linespoints pt 5 lc rgb '#1f77b4' title 'NPC', "
right = right."'' using 1:7 with linespoints pt 6 dt 2 lc rgb '#d62728' title 'FE, authors β', "
right = right."'' using 1:8 with linespoints pt 4 dt 2 lc rgb '#1f77b4' title 'NPC, authors β'"
draw = "set multiplot layout 1,2 title 'Fig. 8: sensitivity of LME to γ'; ".left."; ".right."; unset multiplot"
load dir."/output.gp"
