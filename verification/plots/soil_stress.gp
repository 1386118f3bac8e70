# Fig. 12: sigma_yy on the particles at their current positions at t = 0, 5 and 20 s (LME gamma = 3,
# NPC, CFL 0.1), one colour scale, and beside each map the profile: the particles' sigma_yy against
# their current height with the exact sigma_yy(Y, t) at the exact current height Y + u(Y, t).
# gnuplot -e "data='DATA_DIR'; out='.../soil_fig12_stress'" soil_stress.gp   (writes out.png and out.pdf)
set datafile separator ","
times = "0 5 20"
set cbrange [-0.6:0]
set palette defined (-0.6 "#08306b", -0.45 "#2171b5", -0.3 "#6baed6", -0.15 "#c6dbef", 0 "#fff5eb")
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 1000,1300 font ",11" } else { set terminal pdfcairo size 6.5in,8.5in font ",8" }
  set output out.".".format
  set multiplot layout 3,2 rowsfirst title "Fig. 12: sigma_{yy} (MPa), soil block, LME {/Symbol g} = 3, NPC, CFL 0.1"
  do for [k = 1:3] {
    t = word(times, k)
    # the map: each particle as a 1 m square (its initial share of the block) at its current position
    set size ratio -1
    set xrange [-0.5:10.5]
    set yrange [-0.5:10.5]
    set xlabel "x (m)"
    set ylabel "y (m)"
    set title "t = ".t." s"
    unset key
    set colorbox
    set cblabel "sigma_{yy} (MPa)"
    plot data."/soil_stress_t".t.".csv" using 1:2:(0.45):(0.45):($6/1e6) with boxxyerror fs solid 1.0 noborder lc palette z, \
         data."/soil_geometry_grid.csv" using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb "#9a9a9a"
    # the profile beside it, on the same height axis
    set size noratio
    set xrange [-0.7:0.05]
    set xlabel "sigma_{yy} (MPa)"
    set ylabel "current height y (m)"
    set title "t = ".t." s: particles and exact"
    set key top left
    set grid
    unset colorbox
    if (t eq "20") {
      plot data."/soil_stress_profile_t".t.".csv" using ($3/1e6):2 with lines lw 2 lc rgb "black" title "exact, small strain", \
           data."/soil_stress_profile_t".t.".csv" using ($5/1e6):4 with lines lw 1.5 dt 2 lc rgb "#7f7f7f" title "static, finite strain", \
           data."/soil_stress_t".t.".csv" using ($6/1e6):2 with points pt 7 ps 0.8 lc rgb "#d62728" title "particles (MPM)"
    } else {
      plot data."/soil_stress_profile_t".t.".csv" using ($3/1e6):2 with lines lw 2 lc rgb "black" title "exact, small strain", \
           data."/soil_stress_t".t.".csv" using ($6/1e6):2 with points pt 7 ps 0.8 lc rgb "#d62728" title "particles (MPM)"
    }
    unset grid
  }
  unset multiplot
}
