# v_A(t) of the Dyka bar against the exact solution (appendix A).
# gnuplot -e "data='...csv'; out='...'; caption='...'" dyka_velocity.gp   (writes out.png and out.pdf)
set datafile separator ","
set key top right
set xlabel "t (µs)"
set ylabel "v_A (m/s)"
set xrange [0:200]
set yrange [-8:8]
set grid
set title caption
do for [format in "png pdf"] {
  if (format eq "png") { set terminal pngcairo size 900,540 font ",11" } else { set terminal pdfcairo size 6in,3.6in font ",9" }
  set output out.".".format
  plot data using ($1*1e6):3 with lines lw 2 lc rgb "black" title "exact", \
       data using ($1*1e6):2 with lines lw 1.5 lc rgb "#d62728" title "MPM"
}
