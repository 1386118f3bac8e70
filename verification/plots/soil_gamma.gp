# LME's gamma on the soil block (2 m cells), both integrators: accuracy (the settled value against the solver's own
# finite-strain static column), and the free oscillation after the ramp: its swing against the exact column's (a line),
# above it ringing, below it damping; error bars: each measure's band (data/soil_gamma.csv).
load dir."/common.gp"
w = 11; h = 4.6
f = data.'/soil_gamma.csv'
sel(integrator, col, band) = sprintf("f using ((strcol(1) eq '%s') ? $2 : NaN):%d:%d", integrator, col, band)
one(integrator, col, band) = sel(integrator, col, band)." with yerrorlines lw 1.5 pt ".(integrator eq 'fe' ? "7 dt 1 lc rgb '#d62728'" : "6 dt 2 lc rgb '#1f77b4'")." title '".(integrator eq 'fe' ? "FE" : "NPC")."'"
panel(col, band, title, label) = sprintf("set title '%s'; set ylabel '%s'; plot ", title, label).one('npc',col,band).", ".one('fe',col,band)
exact = ", f using 2:9 with lines lc rgb 'black' dt 4 title 'exact column'"
draw = "set multiplot layout 1,2 title 'Soil block, 2 m cells: LME γ (error bars: the band of each measure)'; set xlabel 'γ'; set xrange [0.6:5.2]; set key top left font ',8'; ".panel(3,4,'accuracy: settled u_y against the finite-strain column (FE and NPC coincide)','|mean u_y - u_{static,log}| (m)')."; set key bottom right; ".panel(7,8,'free oscillation after the ramp: above the exact swing rings, below damps','swing of u_y, last 4 T_1 (m)').exact."; unset multiplot"
load dir."/output.gp"
