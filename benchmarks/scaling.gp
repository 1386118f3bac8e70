# The chart of `make bench` (benchmarks/run.sh): time per particle-step against particles, 1D and 2D,
# per shape and integrator, on one core (solid) and on all cores (dashed); and the share of each
# phase of the step for one run of each kind.   gnuplot -e "csv='...'; out='...'; cores=N" scaling.gp
set datafile separator ","
set key outside right top box font ",9"
set logscale xy
set format x "10^{%T}"
set grid
set xlabel "particles"
set ylabel "time per particle-step (ns)"
shapes = "linear ugimp lme"
integrators = "fe npc"
colour(s) = s eq "linear" ? "#1b9e77" : (s eq "ugimp" ? "#d95f02" : "#7570b3")
point(i) = i eq "fe" ? 7 : 5
# column 1 dimension, 2 shape, 3 integrator, 5 particles, 7 threads, 8 seconds per particle-step
pick(d, s, i, t) = (strcol(1) eq d && strcol(2) eq s && strcol(3) eq i && int(column(7)) == t) ? column(8) * 1e9 : NaN

do for [ext in "png pdf"] {
  if (ext eq "png") { set terminal pngcairo size 1500,1000 font ",10" } else { set terminal pdfcairo size 15in,10in font ",10" }
  set output out.".".ext
  set multiplot layout 2,2 title sprintf("MPM cost per particle-step (make bench); solid: 1 thread, dashed: %d threads", cores)
  set title "1D: Dyka bar, 40 to 20480 cells"
  plot for [s in shapes] for [i in integrators] csv using 5:(pick("1", s, i, 1)) with linespoints lc rgb colour(s) pt point(i) dt 1 title s." + ".i, \
       for [s in shapes] for [i in integrators] csv using 5:(pick("1", s, i, cores)) with linespoints lc rgb colour(s) pt point(i) dt 2 notitle
  set title "2D: soil block, 100 to 10^6 particles"
  plot for [s in shapes] for [i in integrators] csv using 5:(pick("2", s, i, 1)) with linespoints lc rgb colour(s) pt point(i) dt 1 title s." + ".i, \
       for [s in shapes] for [i in integrators] csv using 5:(pick("2", s, i, cores)) with linespoints lc rgb colour(s) pt point(i) dt 2 notitle
  # Phase shares: columns 11-18 = stencils p2g stress forces grid g2p checks output (of the busy time).
  unset logscale
  set format x "%g"
  set style data histograms
  set style histogram rowstacked
  set style fill solid 0.85 border -1
  set boxwidth 0.75
  set yrange [0:1]
  set ylabel "share of the step"
  set xlabel ""
  set xtics rotate by -35 font ",8"
  phase(c, d, n) = (strcol(1) eq d && int(column(4)) == n && int(column(7)) == 1) ? column(c) : NaN
  label(d, n) = (strcol(1) eq d && int(column(4)) == n && int(column(7)) == 1) ? strcol(2)."+".strcol(3) : ""
  set title "1D, 2560 cells, 1 thread: where the time goes"
  plot for [c=11:17] csv using (phase(c, "1", 2560)):xtic(label("1", 2560)) every ::1 title columnheader(c)
  set title "2D, 101124 particles, 1 thread: where the time goes"
  plot for [c=11:17] csv using (phase(c, "2", 159)):xtic(label("2", 159)) every ::1 title columnheader(c)
  unset multiplot
  unset yrange
  set logscale xy
  set format x "10^{%T}"
  set xtics norotate font ",10"
  set style data lines
  set ylabel "time per particle-step (ns)"
  set xlabel "particles"
}
