# Speed against accuracy (beyond the paper): RMS of v_A against the wall time of each run of the
# mesh sweep, one curve per shape function x integrator; points left to right are 10 ... 2560 cells.
# Today's baselines (data/dyka_baselines.csv: 40, 160, 640 cells, the cubic B-spline also 2560) as points
# of their own, and a ring around each run on its mesh's error-cost front
# (the file's column `pareto`, computed by dyka_suite).
load dir."/common.gp"
w = 9; h = 6
sweep = data.'/dyka_sweep.csv'
baselines = data.'/dyka_baselines.csv'
methods = "linear,fe linear,npc ugimp,fe ugimp,npc lme,fe lme,npc"
colours = "#d62728 #ff9896 #2ca02c #98df8a #1f77b4 #aec7e8"
points = "7 5 7 5 7 5"
extra = "bspline2_fe bspline2_npc bspline3_fe bspline3_npc linear_usl linear_musl bspline2_usl bspline2_musl lme0.8_fe lme0.8_npc lme1.5_fe lme1.5_npc"
extra_colours = "#ff7f0e #ffbb78 #9467bd #c5b0d5 #8c564b #e377c2 #bcbd22 #17becf #7f7f7f #7f7f7f #393b79 #393b79"
extra_points = "9 8 9 8 13 12 11 10 15 14 3 1"
curves = "plot "
do for [k=1:words(methods)] {
  m = word(methods,k); s = m[1:strstrt(m,",")-1]; i = m[strstrt(m,",")+1:]
  curves = curves.sprintf("%s'%s' using (strcol(1) eq '%s' && strcol(2) eq '%s' && strcol(12) eq 'ok' ? $10 : NaN):8 with linespoints pt %s lc rgb '%s' title '%s + %s'", k>1 ? ", " : "", sweep, s, i, word(points,k), word(colours,k), s, i)
}
do for [k=1:words(extra)] {
  curves = curves.sprintf(", '%s' using (strcol(1) eq '%s' && strcol(6) eq 'ok' ? $4 : NaN):3 with points pt %s ps 1.2 lc rgb '%s' title '%s'", baselines, word(extra,k), word(extra_points,k), word(extra_colours,k), word(extra,k))
}
curves = curves.sprintf(", '%s' using (strcol(6) eq 'ok' && $7 == 1 ? $4 : NaN):3 with points pt 6 ps 2.4 lw 1.5 lc rgb 'black' title 'on the error-cost front of its mesh'", baselines)
draw = "set title 'Speed against accuracy: Dyka bar, 10 to 2560 cells, CFL 0.5'; set logscale xy; set yrange [0.04:1]; set xlabel 'wall time per run (s)'; set format x '10^{%L}'; set format y '%g'; set ylabel 'RMS of v_A / |v_0|'; set key outside right font ',7' noenhanced; ".curves
load dir."/output.gp"
