# Fig. 11: the soil block, its grid, particles and boundary conditions, drawn from the scene itself
# (soil_suite writes them from the solver's set-up).
# gnuplot -e "data='DATA_DIR'; out='.../soil_fig11_geometry'" soil_geometry.gp   (writes out.png and out.pdf)
set datafile separator ","
box = data."/soil_geometry_box.csv"
stats box using 1 nooutput name "xmin"
stats box using 2 nooutput name "ymin"
stats box using 3 nooutput name "xmax"
stats box using 4 nooutput name "ymax"
xmid = 0.5 * (xmin_max + xmax_max)
width = xmax_max - xmin_max
gap = 0.035 * width                       # offset of the support symbols from their node
set size ratio -1
set xrange [xmin_max - 0.25 * width : xmax_max + 0.25 * width]
set yrange [ymin_max - 0.18 * width : ymax_max + 0.08 * width]
set xlabel "x (m)"
set ylabel "y (m)"
set key outside bottom center horizontal maxcols 3
set object 1 rect from xmin_max, ymin_max to xmax_max, ymax_max fc rgb "#f2e6d0" fs solid 1.0 noborder behind
set arrow 1 from xmax_max + 0.15 * width, ymax_max - 0.15 * width to xmax_max + 0.15 * width, ymax_max - 0.4 * width lw 2.5 lc rgb "#1f4e9a" filled
set label 1 "g(t)" at xmax_max + 0.15 * width, ymax_max - 0.1 * width center tc rgb "#1f4e9a"
set label 3 "Eq. (44)" at xmax_max + 0.15 * width, ymax_max - 0.45 * width center tc rgb "#1f4e9a"
set label 2 sprintf("W = %g m", width) at xmid, ymin_max - 0.12 * width center
set title "Soil block (scenes/soil_block.toml): grid, particles, supports" noenhanced
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 760,820 font ",11" } else { set terminal pdfcairo size 5in,5.4in font ",9" }
  set output out.".".format
  plot data."/soil_geometry_grid.csv" using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb "#9a9a9a" lw 1 title "grid", \
       data."/soil_geometry_particles.csv" using 1:2 with points pt 7 ps 0.6 lc rgb "#5a3d1e" title "particles", \
       data."/soil_geometry_fixed.csv" using 1:($3 == 1 ? $2 - gap : NaN) with points pt 9 ps 1.3 lc rgb "#c0392b" title "v_y = 0 (roller)", \
       data."/soil_geometry_fixed.csv" using ($3 == 0 ? ($1 < xmid ? $1 - gap : $1 + gap) : NaN):2 with points pt 13 ps 1.1 lc rgb "#1f7a3a" title "v_x = 0 (roller)", \
       data."/soil_geometry_observer.csv" using 1:2 with points pt 3 ps 2.2 lw 2 lc rgb "#1f4e9a" title "observed particle (Fig. 13)"
}
