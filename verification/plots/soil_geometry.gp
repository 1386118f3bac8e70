# Fig. 11: the soil block, its grid, particles and boundary conditions, drawn from the scene itself
# (soil_suite writes them from the solver's set-up): the block (soil_geometry_box.csv), the grid lines
# (soil_geometry_grid.csv), the particles (soil_geometry_particles.csv), the rollers (soil_geometry_fixed.csv: a node
# and its fixed component, 1 = v_y on the base, 0 = v_x on the walls; each drawn as a support, a short stem from the
# node away from the block ending in a bar across the fixed direction, no marker: the markers belong to the methods),
# the observed particle of Fig. 13 (soil_geometry_observer.csv, a '+', no method's marker) and the ramped gravity of
# Eq. (44).
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../soil_fig11_geometry'" soil_geometry.gp
load dir."/common.gp"
w = 6.6; h = 6.8
box = data."/soil_geometry_box.csv"
grid = data."/soil_geometry_grid.csv"
particles = data."/soil_geometry_particles.csv"
fixed = data."/soil_geometry_fixed.csv"
observer = data."/soil_geometry_observer.csv"
stats box using 1 nooutput name "box_xmin"
stats box using 2 nooutput name "box_ymin"
stats box using 3 nooutput name "box_xmax"
stats box using 4 nooutput name "box_ymax"
stats particles using 1 nooutput name "particle"
stats grid using ($1 == $3 ? 1 : 0) nooutput name "vertical"
xmin = box_xmin_max; ymin = box_ymin_max; xmax = box_xmax_max; ymax = box_ymax_max
xmid = 0.5 * (xmin + xmax)
width = xmax - xmin
cells = int(vertical_sum) - 1              # vertical grid lines, less one
gap = 0.04 * width                        # a support's stem, from its node away from the block
bar = 0.03 * width                        # half the support's bar, across the fixed direction
g_x = xmax + 0.15 * width                 # where the gravity arrow stands
scene = sprintf("set size ratio -1; set xrange [%g:%g]; set yrange [%g:%g]; ", \
  xmin - 0.25 * width, xmax + 0.25 * width, ymin - 0.18 * width, ymax + 0.08 * width)
scene = scene."set xlabel 'x (m)'; set ylabel 'y (m)'; set key outside bottom center horizontal maxcols 3; "
scene = scene.sprintf("set object 1 rect from %g, %g to %g, %g fc rgb c_soil fs solid 1.0 noborder behind; ", \
  xmin, ymin, xmax, ymax)
scene = scene.sprintf("set arrow 1 from %g, %g to %g, %g lw 2.5 lc rgb c_load filled; ", \
  g_x, ymax - 0.15 * width, g_x, ymax - 0.4 * width)
scene = scene.sprintf("set label 1 'g(t)' at %g, %g center tc rgb c_load; ", g_x, ymax - 0.1 * width)
scene = scene.sprintf("set label 3 'Eq. (44)' at %g, %g center tc rgb c_load; ", g_x, ymax - 0.45 * width)
scene = scene.sprintf("set label 2 'W = %g m' at %g, %g center; ", width, xmid, ymin - 0.12 * width)
title = sprintf("Fig. 11: soil block (scenes/soil_block.toml), %g m × %g m, %d × %d cells of %g m,\\n", \
  width, ymax - ymin, cells, cells, width / cells)
per_side = int(0.5 + sqrt(particle_records / cells**2))   # particles per cell along each side
title = title.sprintf("%d particles (%d × %d per cell), rollers on the base and the walls, gravity ramped by Eq. (44)", \
  particle_records, per_side, per_side)
curves = "plot grid using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb c_mesh lw 1 title 'grid', "
curves = curves."particles using 1:2 with points pt 7 ps 0.6 lc rgb c_particle title 'particles', "
# supports: v_y = 0 on the base (stem down, bar level), v_x = 0 on the walls (stem outwards, bar upright)
out_x(x) = x < xmid ? -gap : gap
curves = curves."fixed using 1:($3 == 1 ? $2 : NaN):(0):(-gap) with vectors nohead lw 2 lc rgb c_roller_y "
curves = curves."title 'v_y = 0 (roller)', "
curves = curves."fixed using ($1 - bar):($3 == 1 ? $2 - gap : NaN):(2 * bar):(0) with vectors nohead lw 2 "
curves = curves."lc rgb c_roller_y notitle, "
curves = curves."fixed using 1:($3 == 0 ? $2 : NaN):(out_x($1)):(0) with vectors nohead lw 2 lc rgb c_roller_x "
curves = curves."title 'v_x = 0 (roller)', "
curves = curves."fixed using ($1 + out_x($1)):($3 == 0 ? $2 - bar : NaN):(0):(2 * bar) with vectors nohead lw 2 "
curves = curves."lc rgb c_roller_x notitle, "
curves = curves."observer using 1:2 with points pt 1 ps 2.4 lw 2.5 lc rgb c_load title 'observed particle (Fig. 13)'"
draw = scene."set title \"".title."\" noenhanced; ".curves
load dir."/output.gp"
