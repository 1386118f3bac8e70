# Speed against accuracy (beyond the paper): RMS of v_A / |v0| against the CPU time of each run, in four panels
# (at most 7 entries each): the paper's methods over the mesh sweep (10 ... 2560 cells, left to right, one run
# each), and today's baselines on 40, 160, 640 cells (the cubic B-spline also 2560) by family, each drawn over
# the paper's methods in grey. Error bars: fastest to slowest of 5 interleaved repeats (40 and 160 cells).
# A single timing (640, 2560 cells) is drawn with a bar from its time to its time widened by the largest spread
# of the 160-cell repeats, the margin the front asks of it. Ringed and labelled with their cells: the runs on their mesh's error-cost front (data/dyka_baselines.csv, column pareto, computed by dyka_suite:
# no method both more accurate and faster by more than the measured spread).
load dir."/common.gp"
w = 12; h = 8
sweep = data.'/dyka_sweep.csv'
baselines = data.'/dyka_baselines.csv'
methods = "linear,fe linear,npc ugimp,fe ugimp,npc lme,fe lme,npc"
colours = "#d62728 #ff9896 #2ca02c #98df8a #1f77b4 #aec7e8"
s_of(m) = m[1:strstrt(m,",")-1]; i_of(m) = m[strstrt(m,",")+1:]
paper(grey) = sprintf("plot for [k=1:6] sweep using (strcol(1) eq s_of(word(methods,k)) && strcol(2) eq i_of(word(methods,k)) && strcol(12) eq 'ok' ? $17 : NaN):8 with linespoints pt (k %% 2 ? 7 : 5) ps 0.8 lc rgb (%d ? '#c8c8c8' : word(colours,k)) title (%d ? (k == 1 ? 'paper methods, 10-2560 cells' : '') : s_of(word(methods,k)).' + '.i_of(word(methods,k)))", grey, grey)
ring = sprintf("baselines using (strcol(6) eq 'ok' && $7 == 1 && (strcol(1) eq word(group,1) || strcol(1) eq word(group,2) || strcol(1) eq word(group,3) || strcol(1) eq word(group,4)) ? $8 : NaN):3 with points pt 6 ps 2.4 lw 1.5 lc rgb 'black' title 'on its mesh''s front (label: cells)', baselines using (strcol(6) eq 'ok' && $7 == 1 && (strcol(1) eq word(group,1) || strcol(1) eq word(group,2) || strcol(1) eq word(group,3) || strcol(1) eq word(group,4)) ? $8 : NaN):3:(strcol(2)) with labels offset 1.6,0.7 font ',6' notitle")
family = "for [k=1:4] baselines using (strcol(1) eq word(group,k) && strcol(6) eq 'ok' ? $8 : NaN):3:9:10 with xerrorlines pt 6+k ps 1.1 lw 1.5 lc rgb word(fcolours,k) title word(group,k)"
fcolours = "#ff7f0e #9467bd #8c564b #17becf"
own = "linear_fe linear_npc ugimp_fe ugimp_npc lme3_fe lme3_npc"
mine(m) = (m eq word(own,1) || m eq word(own,2) || m eq word(own,3) || m eq word(own,4) || m eq word(own,5) || m eq word(own,6))
first = "set title 'paper methods: the sweep (one run each), the repeats of 40 and 160 cells (error bars)'; ".paper(0).", for [k=1:6] baselines using (strcol(1) eq word(own,k) && strcol(6) eq 'ok' && $11 > 1 ? $8 : NaN):3:9:10 with xerrorbars pt 1 ps 0.8 lc rgb word(colours,k) notitle, baselines using (strcol(6) eq 'ok' && $7 == 1 && mine(strcol(1)) ? $8 : NaN):3 with points pt 6 ps 2.4 lw 1.5 lc rgb 'black' title 'on its mesh''s front (label: cells)', baselines using (strcol(6) eq 'ok' && $7 == 1 && mine(strcol(1)) ? $8 : NaN):3:(strcol(2)) with labels offset 1.6,0.7 font ',6' notitle"
panel(title, members) = sprintf("set title '%s'; group = '%s'; ", title, members).paper(1).", ".family.", ".ring
draw = "set multiplot layout 2,2 title 'Speed against accuracy: Dyka bar, CFL 0.5 (CPU time per run, one thread)'; set logscale xy; set xrange [5e-5:30]; set yrange [0.05:0.7]; set xlabel 'CPU time per run (s)'; set format x '10^{%L}'; set format y '%g'; set ylabel 'RMS of v_A / |v_0|'; set key bottom left font ',7' noenhanced; ".first."; ".panel('B-splines (uGIMP = quadratic B-spline)', 'bspline2_fe bspline2_npc bspline3_fe bspline3_npc')."; ".panel('stress updated last (USL) or modified (MUSL)', 'linear_usl linear_musl bspline2_usl bspline2_musl')."; ".panel('LME at small γ', 'lme0.8_fe lme0.8_npc lme1.5_fe lme1.5_npc')."; unset multiplot"
load dir."/output.gp"
