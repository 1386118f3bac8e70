# The colliding disks (scenes/colliding_disks.toml: linear shape functions, 20 x 20 cells, 2 x 2 particles per cell,
# CFL 0.4): kinetic, strain and total energy and the size of the total momentum against time, with the predictor-
# corrector (disks_energy.csv: t, kinetic, strain, total, momentum_x, momentum_y) and forward Euler on the same scene
# (disks_energy_fe.csv), each method in its style (linear's colour, the integrator's dash and marker). The title says
# when the two part: the first time their totals differ by more than 1e-3 of the initial energy.
# Called by verification/disks_figures.sh with data and out set.
load dir."/common.gp"
w = 11; h = 7.5
file(i) = data.(i eq 'npc' ? '/disks_energy.csv' : '/disks_energy_fe.csv')
shape = 'linear'
# when the totals part (NPC's and FE's rows are the same times)
parting = system(sprintf("paste -d, %s %s | awk -F, 'NR == 2 {e0 = $4} NR > 1 {d = $4 - $10; " \
  ."if (d < 0) d = -d; if (d > 1e-3 * e0) {print $1; exit}}'", file('npc'), file('fe')))
both(column, titled) = sprintf("plot for [i in 'npc fe'] file(i) using 1:(%s) with linespoints pi 12 ps 0.8 " \
  ."lw method_lw lc rgb colour(shape) dt dash(i) pt marker(i) %s", column, titled ? "title method_name(shape, i)" : "notitle")
margins(x, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; " \
  ."set tmargin at screen %g; ", x + 0.08, x + 0.48, bottom, top)
title = "Colliding disks (scenes/colliding_disks.toml: 20 × 20 cells, 2 × 2 particles per cell, CFL 0.4): " \
  .method_name(shape, 'npc')." against ".method_name(shape, 'fe').";\\n" \
  .(parting eq "" ? "the two coincide throughout" : sprintf("the two coincide until the disks meet: their totals part at t = %.2f s", real(parting)))
draw = "set multiplot title \"".title."\" noenhanced; set xlabel 't (s)'; set xrange [0:3.5]; set grid; unset key; " \
  .margins(0, 0.53, 0.87)."set title 'kinetic energy'; set ylabel 'J per m of thickness'; ".both("$2", 0)."; " \
  .margins(0.5, 0.53, 0.87)."set title 'strain energy'; ".both("$3", 0)."; " \
  .margins(0, 0.08, 0.42)."set title 'total energy'; set key bottom left; ".both("$4", 1)."; unset key; " \
  .margins(0.5, 0.08, 0.42)."set title 'total momentum |p| (zero to round-off)'; set ylabel 'kg m/s per m'; " \
  .both("sqrt($5**2 + $6**2)", 0)."; unset multiplot"
load dir."/output.gp"
