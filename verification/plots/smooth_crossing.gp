# The grid-crossing error isolated: the vibrating bar on a fixed mesh of 32 cells, RMS
# velocity error against the largest displacement over the cell size, U/h; one panel per integrator
# and particles per cell, one line per shape function. Dotted: U/h = 1/(2 ppc), where the particle
# next to the free end first reaches a cell face. Crosses at the top: the run stopped. Dashed, thin:
# today's baselines (B-splines, LME γ = 0.8 and 1.5 with the panel's integrator; USL and MUSL in the FE panels).
# gnuplot -e "dir='...'; data='...'; out='...'" smooth_crossing.gp
load dir."/common.gp"
up(i) = (i eq 'fe' ? 'FE' : 'NPC')
w = 11; h = 7
file = data.'/smooth_crossing.csv'
colour(s) = (s eq 'linear' ? '#2ca02c' : s eq 'ugimp' ? '#9467bd' : '#d62728')
name(s) = (s eq 'linear' ? 'linear' : s eq 'ugimp' ? 'uGIMP' : 'LME, γ = 3')
B = 'bspline2 bspline3 lme0.8 lme1.5 usl musl'
bcolour(b) = (b eq 'bspline2' ? '#ff7f0e' : b eq 'bspline3' ? '#8c564b' : b eq 'lme0.8' ? '#e377c2' : b eq 'lme1.5' ? '#bcbd22' : b eq 'usl' ? '#17becf' : '#7f7f7f')
bname(b) = (b eq 'bspline2' ? 'B-spline2' : b eq 'bspline3' ? 'B-spline3' : b eq 'lme0.8' ? 'LME, γ = 0.8' : b eq 'lme1.5' ? 'LME, γ = 1.5' : b eq 'usl' ? 'linear, USL' : 'linear, MUSL')
# a baseline's rows in the panel of integrator i: its shape with i, or USL / MUSL in the FE panel
mine(b, i, p) = ($3 == p && (b eq 'usl' || b eq 'musl' ? i eq 'fe' && strcol(2) eq b : strcol(1) eq b && strcol(2) eq i))
baselines(i, p) = sprintf("for [b in B] file using (mine(b, '%s', %d) && strcol(7) eq 'ok' ? $4 : NaN):5 with linespoints lw 1 dt 2 pt 6 ps 0.6 lc rgb bcolour(b) title bname(b), for [b in B] file using (mine(b, '%s', %d) && strcol(7) eq 'failed' ? $4 : NaN):(1.0) with points pt 2 ps 1.2 lc rgb bcolour(b) notitle", i, p, i, p)
panel(i, p) = sprintf("set title '%s, %d particle%s per cell'; set arrow 1 from %g, graph 0 to %g, graph 1 nohead dt 3 lc rgb '#555555'; plot for [s in 'linear ugimp lme'] file using (strcol(1) eq s && strcol(2) eq '%s' && $3 == %d && strcol(7) eq 'ok' ? $4 : NaN):5 with linespoints lw 1.5 pt 7 lc rgb colour(s) title name(s), for [s in 'linear ugimp lme'] file using (strcol(1) eq s && strcol(2) eq '%s' && $3 == %d && strcol(7) eq 'failed' ? $4 : NaN):(1.0) with points pt 2 ps 1.5 lc rgb colour(s) notitle, %s", up(i), p, p > 1 ? 's' : '', 0.5/p, 0.5/p, i, p, i, p, baselines(i, p))
draw = "set multiplot layout 2,2 title 'Grid crossing isolated: vibrating bar, 32 cells, CFL 0.5; RMS(v_p - v)/V against U/h'; set logscale xy; set format y '10^{%L}'; set xrange [0.008:2.5]; set yrange [1e-3:2]; set xlabel 'U / h (largest displacement / cell size)'; set ylabel 'RMS(v_p - v) / V'; set key top left font ',7' maxrows 5; " . \
  panel('fe', 1) . "; " . panel('npc', 1) . "; " . panel('fe', 2) . "; " . panel('npc', 2) . "; unset multiplot"
load dir."/output.gp"
