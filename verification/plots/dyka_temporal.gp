# The temporal order alone: every particle's v at the end time against the same method at CFL 0.00078125, RMS over the
# particles / |v0|, against the CFL at fixed h (40 and 160 cells), each shape and integrator (data/dyka_temporal.csv),
# with slopes 1/2, 1 and 2 for reference.
load dir."/common.gp"
w = 11; h = 4.8
f = data.'/dyka_temporal.csv'
sel(cells, shape, integrator) = sprintf("f using (($1 == %d && strcol(2) eq '%s' && strcol(3) eq '%s' && $6 > 0) ? $4 : NaN):6", cells, shape, integrator)
colour(shape) = shape eq 'linear' ? "'#d62728'" : shape eq 'ugimp' ? "'#2ca02c'" : "'#1f77b4'"
one(cells, shape, integrator) = sel(cells, shape, integrator)." with linespoints lw 1.5 pt ".(integrator eq 'fe' ? "7" : "6")." dt ".(integrator eq 'fe' ? "1" : "2")." lc rgb ".colour(shape)." title '".shape." ".integrator."'"
slopes = "0.3*(x/0.4)**0.5 with lines lc rgb '#999999' dt 3 title 'slope 1/2', 0.1*(x/0.4) with lines lc rgb '#666666' dt 4 title 'slope 1', 0.1*(x/0.4)**2 with lines lc rgb '#333333' dt 5 title 'slope 2'"
panel(cells) = sprintf("set title '%d cells'; plot ", cells).one(cells,'linear','fe').", ".one(cells,'linear','npc').", ".one(cells,'ugimp','fe').", ".one(cells,'ugimp','npc').", ".one(cells,'lme','fe').", ".one(cells,'lme','npc').", ".slopes
draw = "set multiplot layout 1,2 title 'Step refined at fixed h: v at 200 µs against CFL 0.00078125 (16 times finer than the finest), RMS over the particles / |v_0|'; set logscale xy; set xrange [0.01:0.5]; set yrange [1e-4:0.5]; set xtics (0.0125, 0.025, 0.05, 0.1, 0.2, 0.4); set xlabel 'CFL (dt = CFL h / c)' offset 0,0.8; set ylabel 'difference / |v_0|'; set key outside bottom center horizontal font ',8' maxrows 3; ".panel(40)."; ".panel(160)."; unset multiplot"
load dir."/output.gp"
