# The chart of `make bench` (benchmarks/run.sh): time per particle-step against particles, 1D and 2D,
# per shape and integrator, on one core (solid) and on all cores (dashed); and the share of each
# phase of the step for one run of each kind.   gnuplot -e "csv='...'; out='...'; cores=N" scaling.gp
# Each series is filtered out of the CSV by awk first, so that its points are consecutive and joined.
shapes = "linear ugimp lme"
integrators = "fe npc"
colour(s) = s eq "linear" ? "#1b9e77" : (s eq "ugimp" ? "#d95f02" : "#7570b3")
point(i) = i eq "fe" ? 7 : 5
# columns: 1 dimension, 2 shape, 3 integrator, 4 cells, 5 particles, 7 threads, 8 seconds per particle-step,
# 11-17 the shares of stencils p2g stress forces grid g2p checks
series(d, s, i, t) = sprintf("< awk -F, '$1 == %s && $2 == \"%s\" && $3 == \"%s\" && $7 == %d {print $5, $8 * 1e9}' %s", d, s, i, t, csv)
shares(d, n) = sprintf("< awk -F, '$1 == %s && $4 == %d && $7 == 1 {print $2 \"+\" $3, $11, $12, $13, $14, $15, $16, $17}' %s", d, n, csv)
phase_names = "stencils p2g stress forces grid g2p checks"

do for [ext in "png pdf"] {
  if (ext eq "png") { set terminal pngcairo size 1500,1000 font ",10" } else { set terminal pdfcairo size 15in,10in font ",10" }
  set output out.".".ext
  set multiplot layout 2,2 title sprintf("MPM cost per particle-step (make bench); solid: 1 thread, dashed: %d threads", cores)
  set key outside right top box font ",9"
  set logscale xy
  set format x "10^{%T}"
  set grid
  set xlabel "particles"
  set ylabel "time per particle-step (ns)"
  set title "1D: Dyka bar, 40 to 20480 cells"
  plot for [s in shapes] for [i in integrators] series("1", s, i, 1) using 1:2 with linespoints lc rgb colour(s) pt point(i) dt 1 title s." + ".i, \
       for [s in shapes] for [i in integrators] series("1", s, i, cores) using 1:2 with linespoints lc rgb colour(s) pt point(i) dt 2 notitle
  set title "2D: soil block, 100 to 10^6 particles"
  plot for [s in shapes] for [i in integrators] series("2", s, i, 1) using 1:2 with linespoints lc rgb colour(s) pt point(i) dt 1 title s." + ".i, \
       for [s in shapes] for [i in integrators] series("2", s, i, cores) using 1:2 with linespoints lc rgb colour(s) pt point(i) dt 2 notitle
  # Phase shares (of the step's busy time, output excluded), one bar per shape + integrator.
  unset logscale
  unset grid
  set format x "%g"
  set style data histograms
  set style histogram rowstacked
  set style fill solid 0.85 border -1
  set boxwidth 0.7
  set yrange [0:1]
  set ylabel "share of the step"
  set xlabel ""
  set xtics rotate by -30 font ",9"
  set title "1D, 2560 cells, 1 thread: where the time goes"
  plot for [c=2:8] shares("1", 2560) using c:xtic(1) title word(phase_names, c - 1)
  set title "2D, 101124 particles, 1 thread: where the time goes"
  plot for [c=2:8] shares("2", 159) using c:xtic(1) title word(phase_names, c - 1)
  unset multiplot
  unset yrange
  set style data lines
  set xtics norotate font ",10"
}
