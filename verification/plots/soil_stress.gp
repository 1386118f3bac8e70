# Fig. 12: sigma_yy of the soil block's paper run (LME gamma = 3, NPC, 2 m cells, CFL 0.1) at t = 0, 5 and 20 s, one
# row each. Left: the particles at their current positions (soil_stress_tT.csv), one colour scale. Middle: the
# particles' sigma_yy against their current height, with the exact small-strain sigma_yy(Y, t) at the exact current
# height Y + u(Y, t) (soil_stress_profile_tT.csv) and, at 20 s, the static finite-strain column. Right: the
# differences at the same reference height Y: the particles' sigma_yy minus the exact (column sigma_yy_exact), and at
# 20 s the finite-strain static column minus the small-strain exact, on its own (top, grey) axis: it is under 1 kPa,
# so that in the middle panel it lies under the exact line.
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_fig12_stress'" soil_stress.gp
load dir."/common.gp"
w = 13; h = 11
times = "0 5 20"
particles(t) = data."/soil_stress_t".t.".csv"
profile(t) = data."/soil_stress_profile_t".t.".csv"
run = "lme3"; integrator = "npc"
particle_style = method_style(run, integrator)." ps 0.8"
# How far the finite-strain static column lies from the small-strain exact at 20 s: in stress at one Y (kPa), in height
stats profile("20") using (($5 - $3) / 1e3) nooutput name "stress_gap"
stats profile("20") using (abs($4 - $2) * 100) nooutput name "height_gap"
stress_gap = -stress_gap_min
height_gap = height_gap_max
stats particles("20") using (abs($6 - $7) / 1e3) nooutput name "error20"

# the map: each particle as a 1 m square (its initial share of the block) at its current position
map(t) = "set size ratio -1; set xrange [-0.5:10.5]; set yrange [-0.5:10.5]; set xlabel 'x (m)'; " \
  ."set ylabel 'y (m)'; set title 't = ".t." s: the particles'; unset key; set colorbox; unset x2tics; " \
  ."set cblabel 'σ_{yy} (MPa)'; unset grid; " \
  ."plot particles('".t."') using 1:2:(0.45):(0.45):($6/1e6) with boxxyerror fs solid 1.0 noborder lc palette z, " \
  ."data.'/soil_geometry_grid.csv' using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb c_mesh; "
# the profile, on the same height axis
profile_curves(t) = "plot profile('".t."') using ($3/1e6):2 with lines ".exact_style." title 'exact, small strain'" \
  .(t eq "20" ? ", profile('".t."') using ($5/1e6):4 with lines ".reference_style." title 'static, finite strain'" : "") \
  .", particles('".t."') using ($6/1e6):2 with points ".particle_style." title '".method_name(run, integrator)."'"
profile_panel(t) = "set size noratio; set xrange [-0.7:0.05]; set xlabel 'σ_{yy} (MPa)'; " \
  ."set ylabel 'current height y (m)'; set title 't = ".t." s: σ_{yy} against height'; " \
  ."set key top left; set grid; unset colorbox; ".profile_curves(t)."; "
# the differences at one reference height; at 20 s the finite-strain column's on the top axis
# (its zero under the bottom axis's: 70 / 120 of the width)
gap_axis = sprintf("set x2range [-1.4:1.0]; set x2tics 0.5 textcolor rgb c_reference; " \
  ."set x2label 'finite strain − small strain (kPa)' textcolor rgb c_reference; ")
difference_curves(t) = "plot profile('".t."') using (0):1 with lines ".exact_style \
  .", particles('".t."') using (($6 - $7)/1e3):4 with points ".particle_style \
  .(t eq "20" ? ", profile('".t."') using (($5 - $3)/1e3):1 axes x2y1 with lines ".reference_style : "")
difference_panel(t) = "set xrange [-70:50]; set yrange [0:10]; set xlabel 'σ_{yy} − σ_{yy, exact} (kPa)'; " \
  ."set ylabel 'reference height Y (m)'; set title 't = ".t." s: minus the exact, at one Y'; unset key; " \
  .(t eq "20" ? gap_axis : "unset x2tics; unset x2label; ") \
  .difference_curves(t)."; unset x2tics; unset x2label; "

title = "Fig. 12: σ_{yy} of the soil block, ".method_name(run, integrator).", 2 m cells, CFL 0.1, at t = 0, 5 and 20 s: " \
  ."on the particles (left), against height with the exact (middle), minus the exact at one reference height Y (right)\n"
title = title.sprintf("At 20 s the finite-strain static column lies within %.2f kPa and %.1f cm of the small-strain exact, ", \
  stress_gap, height_gap)
title = title.sprintf("under its line in the middle panel (right: its difference, top axis); the particles are off by up to %.0f kPa", \
  error20_max)
draw = "set cbrange [-0.6:0]; ".palette_compression."; set multiplot layout 3,3 rowsfirst title \"".title."\"; "
do for [k = 1:3] {
  t = word(times, k)
  draw = draw.map(t).profile_panel(t).difference_panel(t)
}
draw = draw."unset multiplot"
load dir."/output.gp"
