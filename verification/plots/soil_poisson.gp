# Beyond the paper: the soil block with nu = 0.3 and lateral rollers (LME gamma = 3, NPC, 2 m cells, CFL 0.1).
# Left: sigma_xx against sigma_yy on every particle at t = 20 s (soil_poisson_t20.csv), with sigma_xx =
# nu/(1-nu) sigma_yy, and below it each particle's relative difference from that line (they coincide to 1e-5).
# Right: u_y(t) of the top particle (4.5, 9.5) m (soil_settlement_lme3_npc_h2_nu0.3.csv) against the exact column
# with the constrained modulus M and the static settlement of the finite-strain column, and below it u_y - u_exact
# (the method's line with its marker every 20 samples).
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_poisson'" soil_poisson.gp
load dir."/common.gp"
w = 12; h = 7.5
nu = 0.3
k0 = nu / (1 - nu)
stresses = data."/soil_poisson_t20.csv"
history = data."/soil_settlement_lme3_npc_h2_nu0.3.csv"
run = "lme3"; integrator = "npc"
particle_style = method_style(run, integrator)." ps 0.9"
line_style = method_style(run, integrator)." pi 20"   # the method's line with its marker every 20 samples (1.4 s)
stats stresses using (abs($5 / (k0 * $6) - 1)) nooutput name "ratio"
stats history using (abs($2 - $3) * 1e3) nooutput name "gap"
# the four panels' margins on the page: the left or the right half (x = 0 or 0.5), the upper or the lower row
margins(x, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; " \
  ."set tmargin at screen %g; ", x + 0.08, x + 0.48, bottom, top)
upper(x) = margins(x, 0.5, 0.87)
lower(x) = margins(x, 0.08, 0.4)
stress_panel = upper(0)."set title 'particles at t = 20 s'; set xlabel 'σ_{yy} (MPa)'; set ylabel 'σ_{xx} (MPa)'; " \
  ."set xrange [-0.65:0.02]; set key top left; plot x * k0 with lines ".exact_style." title 'ν/(1-ν) σ_{yy}', " \
  ."stresses using ($6/1e6):($5/1e6) with points ".particle_style." title '".method_name(run, integrator)."'; "
ratio_panel = lower(0)."set title ''; set xlabel 'σ_{yy} (MPa)'; set ylabel 'σ_{xx} / (ν/(1-ν) σ_{yy}) − 1 (10^{-6})'; " \
  ."set yrange [-30:30]; unset key; plot 0 with lines ".exact_style.", " \
  ."stresses using ($6/1e6):(($5 / (k0 * $6) - 1) * 1e6) with points ".particle_style."; set yrange [*:*]; "
history_panel = upper(0.5)."set title 'top particle (4.5, 9.5) m'; set xlabel 't (s)'; set ylabel 'u_y (m)'; " \
  ."set xrange [0:20]; set key top right; " \
  ."plot history using 1:3 with lines ".exact_style." title 'exact, M = E(1-ν)/((1+ν)(1-2ν))', " \
  ."history using 1:4 with lines ".reference_style." title 'finite-strain static', " \
  ."history using 1:2 with linespoints ".line_style." title '".method_name(run, integrator)."'; "
gap_panel = lower(0.5)."set title ''; set xlabel 't (s)'; set ylabel 'u_y − u_{exact} (mm)'; unset key; " \
  ."plot 0 with lines ".exact_style.", history using 1:(($2 - $3) * 1e3) with linespoints ".line_style."; "
title = "Soil block, ν = 0.3, lateral rollers, ".method_name(run, integrator).", 2 m cells, CFL 0.1: " \
  ."σ_{xx} against σ_{yy} at t = 20 s (left), the top particle’s settlement (right);\\n" \
  .sprintf("below, each against the exact: the particles lie on ν/(1-ν) σ_{yy} within %.0f×10^{-6}, ", ratio_max * 1e6) \
  .sprintf("the settlement within %.1f mm of the exact column", gap_max)
draw = "set multiplot title \"".title."\"; set grid; ".stress_panel.ratio_panel.history_panel.gap_panel."unset multiplot"
load dir."/output.gp"
