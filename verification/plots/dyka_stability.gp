# Where methods fail: the largest stable CFL of each method on the Dyka bar (40 cells, bounded for 20 ms),
# at the paper's amplitude (bars) and at 1/100 of it (circles), beside the limit of the method's own
# linearised step (`mpm stability`, crosses); and v_A of linear + forward Euler just below and just above
# its limit at the paper's amplitude.
load dir."/common.gp"
w = 12; h = 4.5
set style fill solid 0.8 noborder
left = sprintf("set title 'largest scanned CFL stable for 20 ms (every smaller one stable too)'; set ylabel 'CFL'; set yrange [0:4]; set xtics rotate by -40 font ',8' noenhanced; set boxwidth 0.7; set key top right font ',8'; plot '%s/dyka_stability.csv' every ::1 using 0:2:xtic(1) with boxes lc rgb '#1f77b4' title 'runs, v_0 = 5 m/s', '' every ::1 using 0:4 with points pt 6 ps 2.2 lw 2 lc rgb '#2ca02c' title 'runs, v_0/100', '' every ::1 using 0:6 with points pt 2 ps 1.5 lw 2 lc rgb '#d62728' title 'linearised step'", data)
right = sprintf("set title sprintf('linear + FE: CFL %%s (bounded) and %%s (stopped by the solver)', below, above); set xtics norotate font ',10'; set xlabel 't (ms)'; set ylabel 'v_A (m/s)'; set xrange [0:*]; set yrange [*:*]; set autoscale y; set key top right; plot '%s/dyka_stability_below.csv' using ($1*1e3):2 with lines lc rgb '#1f77b4' title 'stable', '%s/dyka_stability_above.csv' using ($1*1e3):2 with lines lc rgb '#d62728' title 'unstable'", data, data)
draw = "set multiplot layout 1,2; ".left."; ".right."; unset multiplot"
load dir."/output.gp"
