# The grid-crossing error isolated: the vibrating bar on a fixed mesh of 32 cells, RMS
# velocity error against the largest displacement over the cell size, U/h; one panel per integrator
# and particles per cell, one line per shape function. Dotted: U/h = 1/(2 ppc), where the particle
# next to the free end first reaches a cell face. Crosses above the data: the run stopped (its error
# is not drawn). Dashed, thin: today's baselines (B-splines, LME γ = 0.8 and 1.5 with the panel's
# integrator; USL and MUSL in the FE panels). The y range is the data's (stats); one legend, below.
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_crossing.gp
load dir."/common.gp"
up(i) = (i eq 'fe' ? 'FE' : 'NPC')
w = 11; h = 7.5
file = data.'/smooth_crossing.csv'
stats file using (strcol(7) eq 'ok' ? $5 : NaN) nooutput
low = STATS_min / 1.5; mark = STATS_max * 2.5; high = STATS_max * 5
colour(s) = (s eq 'linear' ? '#2ca02c' : s eq 'ugimp' ? '#9467bd' : '#d62728')
name(s) = (s eq 'linear' ? 'linear' : s eq 'ugimp' ? 'uGIMP' : 'LME, γ = 3')
B = 'bspline2 bspline3 lme0.8 lme1.5 usl musl'
bcolour(b) = (b eq 'bspline2' ? '#ff7f0e' : b eq 'bspline3' ? '#8c564b' : b eq 'lme0.8' ? '#e377c2' : b eq 'lme1.5' ? '#bcbd22' : b eq 'usl' ? '#17becf' : '#7f7f7f')
bname(b) = (b eq 'bspline2' ? 'B-spline2' : b eq 'bspline3' ? 'B-spline3' : b eq 'lme0.8' ? 'LME, γ = 0.8' : b eq 'lme1.5' ? 'LME, γ = 1.5' : b eq 'usl' ? 'linear, USL' : 'linear, MUSL')
# a baseline's rows in the panel of integrator i: its shape with i, or USL / MUSL in the FE panel
mine(b, i, p) = ($3 == p && (b eq 'usl' || b eq 'musl' ? i eq 'fe' && strcol(2) eq b : strcol(1) eq b && strcol(2) eq i))
baselines(i, p) = sprintf("for [b in B] file using (mine(b, '%s', %d) && strcol(7) eq 'ok' ? $4 : NaN):5 with linespoints lw 1 dt 2 pt 6 ps 0.6 lc rgb bcolour(b), for [b in B] file using (mine(b, '%s', %d) && strcol(7) ne 'ok' ? $4 : NaN):(mark) with points pt 2 ps 1.2 lc rgb bcolour(b)", i, p, i, p)
legend = "for [s in 'linear ugimp lme'] NaN with linespoints lw 1.5 pt 7 lc rgb colour(s) title name(s), for [b in B] NaN with linespoints lw 1 dt 2 pt 6 ps 0.6 lc rgb bcolour(b) title bname(b), NaN with points pt 2 lw 2 lc rgb 'black' title 'run stopped'"
panel(i, p, extra) = sprintf("set title '%s, %d particle%s per cell'; set arrow 1 from %g, graph 0 to %g, graph 1 nohead dt 3 lc rgb '#555555'; plot for [s in 'linear ugimp lme'] file using (strcol(1) eq s && strcol(2) eq '%s' && $3 == %d && strcol(7) eq 'ok' ? $4 : NaN):5 with linespoints lw 1.5 pt 7 lc rgb colour(s), for [s in 'linear ugimp lme'] file using (strcol(1) eq s && strcol(2) eq '%s' && $3 == %d && strcol(7) ne 'ok' ? $4 : NaN):(mark) with points pt 2 ps 1.5 lw 2 lc rgb colour(s), %s%s", up(i), p, p > 1 ? 's' : '', 0.5/p, 0.5/p, i, p, i, p, baselines(i, p), extra)
draw = sprintf("set label 99 'Up to its onset every method keeps its no-crossing error: with NPC their curves coincide there; crosses above the data: runs that stopped (no error drawn).' at screen 0.02, 0.012 font ',8'; set multiplot layout 2,2 title 'Grid crossing isolated: vibrating bar, 32 cells, CFL 0.5; RMS(v_p - v)/V against U/h' margins 0.07, 0.98, 0.14, 0.93 spacing 0.07, 0.1; set logscale xy; set format y '10^{%%L}'; set xrange [0.008:2.5]; set yrange [%g:%g]; set xlabel 'U / h (largest displacement / cell size)'; set ylabel 'RMS(v_p - v) / V'; ", low, high) . \
  "set key at screen 0.02, 0.085 left top horizontal Left reverse font ',8' samplen 2; " . panel('fe', 1, ', '.legend) . "; set key off; " . panel('npc', 1, '') . "; " . panel('fe', 2, '') . "; " . panel('npc', 2, '') . "; unset multiplot; unset label 99"
load dir."/output.gp"
