# Point A against every particle: RMS of v_A / |v0| (solid) and the all-particle space-time norm / |v0| (dashed)
# against the number of cells, per integrator (data/dyka_sweep.csv; runs that stopped have no point, named in the title;
# runs no better than a flat line ringed in black). With the predictor-corrector the three shapes' curves lie on each
# other up to 1280 cells: the title says so.
load dir."/common.gp"
w = 11; h = 4.8
f = data.'/dyka_sweep.csv'
sel(shape, integrator, col) = sprintf("f using ((strcol(1) eq '%s' && strcol(2) eq '%s') ? $3 : NaN):%d", shape, integrator, col)
colour(shape) = shape eq 'linear' ? "'#d62728'" : shape eq 'ugimp' ? "'#2ca02c'" : "'#1f77b4'"
two(shape, integrator) = sel(shape, integrator, 8)." with linespoints lw 1.5 pt 7 lc rgb ".colour(shape)." title '".shape.", point A', ".sel(shape, integrator, 26)." with linespoints lw 1.5 pt 6 dt 2 lc rgb ".colour(shape)." title '".shape.", all particles'"
failed(integrator) = sprintf(", f using ((strcol(2) eq '%s' && strcol(22) eq 'failed') ? $3 : NaN):8 with points pt 6 ps 2.2 lw 1.5 lc rgb 'black' title 'failed'", integrator)
panel(integrator, title) = sprintf("set title '%s'; plot ", title).two('linear', integrator).", ".two('ugimp', integrator).", ".two('lme', integrator).failed(integrator)
draw = "set multiplot layout 1,2 title 'Point A against every particle (CFL 0.5)'; set logscale xy; set xrange [8:3200]; set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set key outside bottom center horizontal font ',8' maxrows 2; ".panel('fe', 'FE (linear stops at 2560 cells: no point)')."; ".panel('npc', 'NPC (the shapes coincide to 1280 cells; linear stops at 2560)')."; unset multiplot"
load dir."/output.gp"
