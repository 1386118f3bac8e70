# LME's gamma of Fig. 8 on three meshes (160: no crossing, 640: transition, 2560: crossing), both integrators:
# accuracy (RMS of v_A / |v0|), ringing (total variation of v_A over the exact one's, less 1, on a log axis, so that
# the predictor-corrector's 1.00-1.18 show) and damping (the plateau mean shortfall / |v0|) against gamma, each with the
# band of its even and odd samples as error bars. Runs no better than a flat line (ending failed) are ringed in black
# in the accuracy panel and left out of the other two (their scales would hide the rest; data/dyka_gamma_meshes.csv).
load dir."/common.gp"
w = 13; h = 4.8
f = data.'/dyka_gamma_meshes.csv'
sel(cells, integrator, col, band) = sprintf("f using ((strcol(2) eq '%s' && $1 == %d && (%d == 4 || strcol(11) ne 'failed')) ? $3 : NaN):($%d - (%d == 7 ? 1 : 0)):%d", integrator, cells, col, col, col, band)
colour(cells) = cells == 160 ? "'#1f77b4'" : cells == 640 ? "'#2ca02c'" : "'#d62728'"
one(cells, integrator, col, band) = sel(cells, integrator, col, band)." with yerrorlines lw 1.5 pt ".(integrator eq 'fe' ? "7" : "6")." dt ".(integrator eq 'fe' ? "1" : "2")." lc rgb ".colour(cells)." title '".cells." cells, ".integrator."'"
failed(col) = sprintf(", f using (strcol(11) eq 'failed' ? $3 : NaN):%d with points pt 6 ps 2.2 lw 1.5 lc rgb 'black' title 'failed (no better than a flat line)'", col)
panel(col, band, title, label) = sprintf("set title '%s'; set ylabel '%s'; plot ", title, label).one(160,'fe',col,band).", ".one(160,'npc',col,band).", ".one(640,'fe',col,band).", ".one(640,'npc',col,band).", ".one(2560,'fe',col,band).", ".one(2560,'npc',col,band).(col == 4 ? failed(col) : "")
draw = "set multiplot layout 1,3 title 'LME: γ on three meshes (CFL 0.5; error bars: the even and odd samples)'; set xlabel 'γ'; set xrange [0.6:5.2]; set logscale y; set format y '%g'; set key outside bottom center horizontal font ',8' maxrows 3; ".panel(4,5,'accuracy','RMS of v_A / |v_0|')."; ".panel(7,8,'ringing (failed runs left out)','total variation / exact - 1')."; unset logscale y; set format y '%g'; ".panel(9,10,'damping (failed runs left out)','plateau mean shortfall / |v_0|')."; unset multiplot"
load dir."/output.gp"
