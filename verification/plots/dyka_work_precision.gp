# Speed against accuracy (beyond the paper): RMS of v_A against the wall time of each run of the
# mesh sweep, one curve per shape function x integrator; points left to right are 10 ... 2560 cells.
load dir."/common.gp"
w = 8; h = 5.5
sweep = data.'/dyka_sweep.csv'
methods = "linear,fe linear,npc ugimp,fe ugimp,npc lme,fe lme,npc"
colours = "#d62728 #ff9896 #2ca02c #98df8a #1f77b4 #aec7e8"
points = "7 5 7 5 7 5"
curves = "plot "
do for [k=1:words(methods)] {
  m = word(methods,k); s = m[1:strstrt(m,",")-1]; i = m[strstrt(m,",")+1:]
  curves = curves.sprintf("%s'%s' using (strcol(1) eq '%s' && strcol(2) eq '%s' && strcol(12) eq 'ok' ? $10 : NaN):8 with linespoints pt %s lc rgb '%s' title '%s + %s'", k>1 ? ", " : "", sweep, s, i, word(points,k), word(colours,k), s, i)
}
draw = "set title 'Speed against accuracy: Dyka bar, 10 to 2560 cells, CFL 0.5'; set logscale xy; set xlabel 'wall time per run (s)'; set format x '10^{%L}'; set format y '%g'; set ylabel 'RMS of v_A / |v_0|'; set key bottom left font ',8'; ".curves
load dir."/output.gp"
