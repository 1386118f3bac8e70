# LME's gamma on the soil block (2 m cells), both integrators: accuracy (RMS of u_y over 0-20 s), ringing (the swing
# of u_y over the last 4 T1, with the exact column's as a line) and damping (the energy lost after the ramp, its trend), each
# with its band as error bars (data/soil_gamma.csv).
load dir."/common.gp"
w = 13; h = 4.6
f = data.'/soil_gamma.csv'
sel(integrator, col, band) = sprintf("f using ((strcol(1) eq '%s') ? $2 : NaN):%d:%d", integrator, col, band)
one(integrator, col, band) = sel(integrator, col, band)." with yerrorlines lw 1.5 pt ".(integrator eq 'fe' ? "7 dt 1 lc rgb '#d62728'" : "6 dt 2 lc rgb '#1f77b4'")." title '".(integrator eq 'fe' ? "FE" : "NPC")."'"
panel(col, band, title, label) = sprintf("set title '%s'; set ylabel '%s'; plot ", title, label).one('npc',col,band).", ".one('fe',col,band)
exact = ", f using 2:8 with lines lc rgb 'black' dt 4 title 'exact column'"
draw = "set multiplot layout 1,3 title 'Soil block, 2 m cells: LME γ (error bars: the band of each measure)'; set xlabel 'γ'; set xrange [0.6:5.2]; set key top right font ',8'; ".panel(3,4,'accuracy','RMS of u_y (m)')."; set logscale y; ".panel(6,7,'ringing','swing of u_y, last 4 T_1 (m)').exact."; ".panel(9,10,'damping','energy lost after the ramp (trend)')."; unset multiplot"
load dir."/output.gp"
