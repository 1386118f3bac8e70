# Grid crossing isolated on the Dyka bar: RMS of v_A / |v0| against U/h, the free end's largest displacement in cells,
# at 640 cells, each shape and integrator (data/dyka_amplitude.csv). A run that stopped is marked at the top of the axis,
# each series on its own row (its colour and point, a cross through it); a run no better than a flat line (failed) is
# ringed in black; the dotted line is the first cell face (U/h = 1/2).
load dir."/common.gp"
w = 9; h = 5.5
f = data.'/dyka_amplitude.csv'
sel(shape, integrator) = sprintf("f using ((strcol(1) eq '%s' && strcol(2) eq '%s') ? $3 : NaN)", shape, integrator)
colour(shape) = shape eq 'linear' ? "'#d62728'" : shape eq 'ugimp' ? "'#2ca02c'" : "'#1f77b4'"
style(shape, integrator) = " lw 1.5 pt ".(integrator eq 'fe' ? "7" : "6")." dt ".(integrator eq 'fe' ? "1" : "2")." lc rgb ".colour(shape)
row(shape, integrator) = 1.1 + 0.12 * ((shape eq 'linear' ? 0 : shape eq 'ugimp' ? 2 : 4) + (integrator eq 'fe' ? 0 : 1))
one(shape, integrator) = sel(shape, integrator).":5 with linespoints".style(shape, integrator)." title '".shape." ".integrator."', ".sel(shape, integrator).":(strcol(10) eq 'stopped' ? ".sprintf("%g", row(shape, integrator))." : NaN) with points".style(shape, integrator)." ps 1.3 notitle, ".sel(shape, integrator).":(strcol(10) eq 'stopped' ? ".sprintf("%g", row(shape, integrator))." : NaN) with points pt 2 ps 1.8 lc rgb ".colour(shape)." notitle, ".sel(shape, integrator).":(strcol(10) eq 'failed' ? $5 : NaN) with points pt 6 ps 2.2 lw 1.5 lc rgb 'black' notitle"
draw = "set title 'Dyka bar at 640 cells, initial speed swept: crossed points at the top stopped, black rings failed (no better than a flat line)'; set logscale xy; set xrange [0.008:2.5]; set yrange [0.05:2.2]; set xlabel 'U/h (free end displacement / cell)'; set ylabel 'RMS of v_A / |v_0|'; set arrow from 0.5,0.05 to 0.5,2 nohead dt 3 lc rgb '#888888'; set label 'first cell face' at 0.52,0.06 font ',8'; set key outside right font ',8'; plot ".one('linear','fe').", ".one('linear','npc').", ".one('ugimp','fe').", ".one('ugimp','npc').", ".one('lme','fe').", ".one('lme','npc')
load dir."/output.gp"
