# Figs. 9 and 10: v_A(t) of several shape functions under one integrator against the exact solution, each curve in the
# method style of palette.gp (the shape's colour; the integrator's dash and marker, markers every few samples at
# intervals that differ from curve to curve). Curves that lie on one another in the top panel are told apart below it:
# the middle panel draws each run's error v_A − v_exact, the bottom panel each run minus the first shape's run
# (v_A − v_A of the first shape, its largest |difference| |Δ| in the key), where the shapes part.
# Reads dyka_<shape>_<integrator>_<cells>.csv (t, v_A, v_exact; the runs share their sampling to 0.01 %).
# gnuplot -e "dir='...'; data='...'; out='...'; caption='...'; shapes='linear ugimp lme lme_authors'; integrator='fe'" dyka_series.gp
# Optional: cells (default 40).
load dir."/common.gp"
w = 10; h = 9
if (!exists("cells")) cells = 40
file(s) = sprintf("%s/dyka_%s_%s_%d.csv", data, s, integrator, cells)
first = word(shapes, 1)
every(k) = word("47 53 59 61 67 71 73", k)
# The method style of run k (inside `plot for [k = ...]`, as gnuplot options evaluated per curve).
style_k = "lw method_lw dt dash(integrator) pt marker(integrator) pi int(every(k)) ps 0.9 lc rgb colour(word(shapes, k))"
# Run k minus the first shape's run, sample by sample; its largest |difference| (over the whole run) for the key.
pair(k) = sprintf("< paste -d, %s %s", file(word(shapes, k)), file(first))
largest = ""
do for [k = 2:words(shapes)] {
  stats pair(k) using (abs($2 - $5)) nooutput
  largest = largest.sprintf(" %.2g", STATS_max)
}
zero = sprintf("0 with lines lw 1 lc rgb '%s' notitle", c_context)

# Panels' places (screen fractions): one column, the three panels on one another.
place(bottom, top) = sprintf("set lmargin at screen 0.09; set rmargin at screen 0.77; set bmargin at screen %g; set tmargin at screen %g; ", bottom, top)
common = "set xrange [0:200]; set key at screen 0.78, graph 1 left top Left reverse samplen 3; "
runs = "plot '".file(first)."' using ($1*1e6):3 with lines ".exact_style." title 'exact'"
runs = runs.sprintf(", for [k = 1:%d] file(word(shapes, k)) using ($1*1e6):2 with linespoints ".style_k." title shape_name(word(shapes, k))", words(shapes))
errors = sprintf("plot for [k = 1:%d] file(word(shapes, k)) using ($1*1e6):($2 - $3) with linespoints ".style_k." title shape_name(word(shapes, k)), %s", \
  words(shapes), zero)
apart = sprintf("plot for [k = 2:%d] pair(k) using ($1*1e6):($2 - $5) with linespoints ".style_k." title sprintf('%%s: |Δ| ≤ %%s', shape_name(word(shapes, k)), word(largest, k - 1)), %s", \
  words(shapes), zero)

top = place(0.55, 0.935).common."set xlabel ''; set format x ''; set ylabel 'v_A (m/s)'; set yrange [-8:9]; ".runs
middle = place(0.32, 0.535).common."unset title; set ylabel 'v_A − v_{exact} (m/s)'; set autoscale y; ".errors
bottom = place(0.08, 0.305).common."set xlabel 't (µs)'; set format x '%g'; set ylabel 'v_A − v_A(".shape_name(first).") (m/s)'; ".apart
draw = "set multiplot title caption; ".top."; ".middle."; ".bottom."; unset multiplot"
load dir."/output.gp"
