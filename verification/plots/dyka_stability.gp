# Where methods fail (beyond the paper): the largest stable CFL of each method (Dyka bar, 40 cells,
# 200 µs), and v_A of linear + forward Euler just below and just above its limit.
load dir."/common.gp"
w = 12; h = 4.5
set style fill solid 0.8 noborder
left = sprintf("set title 'largest CFL that stays bounded to 200 µs'; set ylabel 'CFL'; set yrange [0:*]; set xtics rotate by -40 font ',8' noenhanced; set boxwidth 0.7; plot '%s/dyka_stability.csv' every ::1 using 0:2:xtic(1) with boxes lc rgb '#1f77b4', '' every ::1 using 0:2:(sprintf('%%.2f',$2)) with labels offset 0,0.7 font ',8'", data)
right = sprintf("set title sprintf('linear + FE: CFL %%s (bounded) and %%s (stopped by the solver)', below, above); set xtics norotate font ',10'; set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [0:200]; set autoscale y; set key top right; plot '%s/dyka_stability_below.csv' using ($1*1e6):2 with lines lc rgb '#1f77b4' title 'stable', '%s/dyka_stability_above.csv' using ($1*1e6):2 with linespoints pt 7 ps 0.5 lc rgb '#d62728' title 'unstable'", data, data)
draw = "set multiplot layout 1,2; ".left."; ".right."; unset multiplot"
load dir."/output.gp"
