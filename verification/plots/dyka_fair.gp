# FE against NPC, fairly: per shape function (columns, each in its shape's colour), on the meshes without grid
# crossing (10-160 cells; data/dyka_fair.csv). Top row: RMS of v_A / |v0| against cells for forward Euler compared at
# t and at t + dt/2 (the time its velocity approximates: FE's dash and marker, drawn thin with a small marker), the
# predictor-corrector as printed (Eq. 32) and with the Newmark average, and forward Euler damped by a PIC/FLIP blend
# calibrated on that shape to its own NPC energy, each variant with its integrator's dash and marker. Bottom row:
# each variant's RMS divided by NPC's, so that the curves lying on NPC's in the top row stay apart; the blend's lies
# on NPC's within a line's width from some mesh on, which each bottom title names (from the data: the first mesh
# from which it stays within 0.5 %, and its largest difference from there).
load dir."/common.gp"
w = 13.3; h = 9
fair = data.'/dyka_fair.csv'
# The variants: column, integrator key (its dash and marker), name; FE at t + dt/2 thin, with a small marker.
variants = "3 4 5 6 7"
key_of(c) = c == 3 || c == 4 ? 'fe' : c == 5 ? 'npc' : c == 6 ? 'npcavg' : 'feblend'
name_of(c) = c == 3 ? 'FE at t' : c == 4 ? 'FE at t + dt/2 (thin)' : c == 5 ? 'NPC (Eq. 32)' : c == 6 ? 'NPC, Newmark average' : 'FE + PIC/FLIP blend'
lw_of(c) = c == 4 ? 0.7 : method_lw
ps_of(c) = c == 4 ? 0.6 : 1.3
VS = "lw lw_of(c) dt dash(key_of(c)) pt marker(key_of(c)) ps ps_of(c) lc rgb colour(s)"

# Per shape: the first mesh from which the blend stays within 0.5 % of NPC, and its largest difference from there.
do for [s in "linear ugimp lme"] {
  stats fair using (strcol(1) eq s && abs($7 / $5 - 1) >= 0.005 ? $2 : NaN) nooutput
  off = STATS_records > 0 ? STATS_max : 0
  stats fair using (strcol(1) eq s && $2 > off ? $2 : NaN) nooutput
  from = STATS_min
  stats fair using (strcol(1) eq s && $2 >= from ? abs(100 * ($7 / $5 - 1)) : NaN) nooutput
  eval(sprintf("blend_%s = 'the blend lies on NPC from %d cells (within %.2f %%)'", s, from, STATS_max))
}
sel(s) = sprintf("s = '%s'; ", s)
top(s) = sel(s).sprintf("set title '%s: RMS of v_A / |v_0|'; set logscale y; set yrange [0.1:0.4]; set ytics (0.1, 0.15, 0.2, 0.3, 0.4); set ylabel 'RMS / |v_0|'; set key top right; ", shape_name(s)).\
  "plot for [c in variants] fair using (strcol(1) eq s ? $2 : NaN):(column(c + 0)) with linespoints @VS title name_of(c + 0)"
bottom(s) = sel(s).sprintf("set title '%s: each variant over NPC (Eq. 32);\n%s'; unset logscale y; set ytics auto; set yrange [0.97:1.5]; set ylabel 'RMS / RMS_{NPC}'; set key off; ", shape_name(s), value('blend_'.s)).\
  "plot for [c in variants] fair using (strcol(1) eq s ? $2 : NaN):(column(c + 0) / $5) with linespoints @VS notitle"
draw = "set multiplot layout 2,3 title 'FE against NPC, fairly: RMS of v_A (Eq. 43) / |v_0| against the number of cells (no grid crossing; blend calibrated per shape); same styles in both rows' margins 0.06, 0.99, 0.06, 0.9 spacing 0.06, 0.13; ".\
  "set logscale x; set xrange [8:200]; set xlabel 'cells'; ".top('linear')."; ".top('ugimp')."; ".top('lme')."; ".bottom('linear')."; ".bottom('ugimp')."; ".bottom('lme')."; unset multiplot"
load dir."/output.gp"
