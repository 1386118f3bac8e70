# FE against NPC, fairly: per shape function (columns, each in its shape's colour), on the meshes without grid
# crossing (10-160 cells; data/dyka_fair.csv). Top row: RMS of v_A / |v0| against cells for forward Euler compared at
# t and at t + dt/2 (the time its velocity approximates: FE's dash with the open marker), the predictor-corrector as
# printed (Eq. 32) and with the Newmark average, and forward Euler damped by a PIC/FLIP blend calibrated on that
# shape to its own NPC energy, each variant with its integrator's dash and marker. Bottom row: each variant's RMS
# divided by NPC's, so that the curves lying on NPC's in the top row (the blend's, within a few per cent) stay apart.
load dir."/common.gp"
w = 13.3; h = 8.4
fair = data.'/dyka_fair.csv'
# The variants: column, integrator key (its dash and marker), open marker (1: FE's second variant), name.
variants = "3 4 5 6 7"
key_of(c) = c == 3 || c == 4 ? 'fe' : c == 5 ? 'npc' : c == 6 ? 'npcavg' : 'feblend'
name_of(c) = c == 3 ? 'FE at t' : c == 4 ? 'FE at t + dt/2' : c == 5 ? 'NPC (Eq. 32)' : c == 6 ? 'NPC, Newmark average' : 'FE + PIC/FLIP blend'
pt_of(c) = c == 4 ? open(marker(key_of(c))) : marker(key_of(c))
VS = "lw method_lw dt dash(key_of(c)) pt pt_of(c) ps 1.3 lc rgb colour(s)"
sel(s) = sprintf("s = '%s'; ", s)
top(s) = sel(s).sprintf("set title '%s: RMS of v_A / |v_0|'; set logscale y; set yrange [0.1:0.4]; set ytics (0.1, 0.15, 0.2, 0.3, 0.4); set ylabel 'RMS / |v_0|'; set key top right; ", shape_name(s)).\
  "plot for [c in variants] fair using (strcol(1) eq s ? $2 : NaN):(column(c + 0)) with linespoints @VS title name_of(c + 0)"
bottom(s) = sel(s).sprintf("set title '%s: each variant over NPC (Eq. 32)'; unset logscale y; set ytics auto; set yrange [0.97:1.5]; set ylabel 'RMS / RMS_{NPC}'; set key off; ", shape_name(s)).\
  "plot for [c in variants] fair using (strcol(1) eq s ? $2 : NaN):(column(c + 0) / $5) with linespoints @VS notitle"
draw = "set multiplot layout 2,3 title 'FE against NPC, fairly: RMS of v_A (Eq. 43) / |v_0| against the number of cells (no grid crossing; blend calibrated per shape); same styles in both rows' margins 0.06, 0.99, 0.07, 0.9 spacing 0.06, 0.1; ".\
  "set logscale x; set xrange [8:200]; set xlabel 'cells'; ".top('linear')."; ".top('ugimp')."; ".top('lme')."; ".bottom('linear')."; ".bottom('ugimp')."; ".bottom('lme')."; unset multiplot"
load dir."/output.gp"
