# Where methods fail, on the Dyka bar (40 cells, 20 ms): per method, as fractions of the limit of its own linearised
# step on the bar it runs (the scanned limit, named in brackets under the method; the free bar's, or for NPC, whose
# free-bar analysis finds no stable CFL, the held bar's), the largest scanned CFL below which every scanned run at the
# paper's amplitude is stable (bar), every scanned run (dot: stable, cross: stopped by the solver; v0/100 to the right
# of v0) and the limit on a bar held at both ends (open square); a method with no stable CFL in the scan has a
# triangle at the scan's start and no bar. A stopped run below a bar's top or a dot above a cross marks stable CFLs that are not an interval. Right:
# v_A of linear + forward Euler just below and just above its limit at the paper's amplitude.
load dir."/common.gp"
w = 12; h = 5.5
set style fill solid 0.35 noborder
csv = data."/dyka_stability.csv"
runs = data."/dyka_stability_runs.csv"
none(c) = (strcol(c) eq "nan" ? 0.575 : 1/0)  # below the scan's first CFL, 0.6
left = "unset datafile missing; set title 'stable CFLs per method, as fractions of its step limit (in brackets: free bar; NPC: held bar)' font ',10'; " . \
  "set ylabel 'CFL / the method''s step limit'; set yrange [0.55:1.09]; set xrange [-0.7:*]; set xtics rotate by -40 font ',8' noenhanced; set boxwidth 0.6; " . \
  "set key outside bottom center horizontal maxrows 3 font ',8' samplen 1.5; " . \
  "plot csv every ::1 using 0:($2 / $12):xtic(sprintf('%s (%.3f)', strcol(1), $12)) with boxes lc rgb '#1f77b4' title 'every run below the top stable (v_0 = 5 m/s)', " . \
  "runs every ::1 using ($1 - 0.15):(($3 < -1 && $6 == 1) ? $5 : 1/0) with points pt 7 ps 0.4 lc rgb '#1f77b4' title 'run stable, v_0', " . \
  "runs every ::1 using ($1 - 0.15):(($3 < -1 && $6 == 0) ? $5 : 1/0) with points pt 2 ps 1 lw 2 lc rgb '#d62728' title 'run stopped, v_0', " . \
  "runs every ::1 using ($1 + 0.15):(($3 > -1 && $6 == 1) ? $5 : 1/0) with points pt 7 ps 0.4 lc rgb '#2ca02c' title 'run stable, v_0/100', " . \
  "runs every ::1 using ($1 + 0.15):(($3 > -1 && $6 == 0) ? $5 : 1/0) with points pt 1 ps 1 lw 2 lc rgb '#ff7f0e' title 'run stopped, v_0/100', " . \
  "csv every ::1 using ($0 - 0.3):(1):(0.6):(0) with vectors nohead lw 1.5 lc rgb 'black' title 'step limit scanned (free bar; NPC: held bar)', " . \
  "csv every ::1 using 0:($6 / $12) with points pt 4 ps 0.8 lc rgb '#7f7f7f' title 'held bar step limit', " . \
  "csv every ::1 using 0:(none(2)) with points pt 11 ps 1.6 lc rgb '#d62728' title 'no stable CFL in the scan (v_0)'"
right = sprintf("set title sprintf('linear + FE: CFL %%s (completes) and %%s (stopped by the solver)', below, above) font ',10'; set xtics norotate font ',10'; set xlabel 't (ms)'; set ylabel 'v_A (m/s)'; set xrange [0:20]; set autoscale y; set key outside bottom center horizontal font ',9'; plot '%s/dyka_stability_below.csv' using ($1*1e3):2 with lines lc rgb '#1f77b4' title 'stable', '%s/dyka_stability_above.csv' using ($1*1e3):2 with lines lc rgb '#d62728' title 'unstable'", data, data)
draw = "set multiplot layout 1,2; ".left."; unset xrange; unset yrange; ".right."; unset multiplot"
load dir."/output.gp"
