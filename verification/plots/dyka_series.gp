# v_A(t) of several runs against the exact solution (Figs. 7, 9, 10 and the stability pair).
# gnuplot -e "dir='...'; out='...'; caption='...'; files='a.csv b.csv'; titles='A B'; inset=1" dyka_series.gp
# Optional: colour_of='1 2 3 3' (each curve's colour, by its place in `colours`; default: its own place) and
# dashes='1 1 1 2' (each curve's dash type; default: solid), so that a run under another rule is dashed in its colour.
# Each curve carries its own marker every few samples, at intervals that differ from curve to curve, so that curves
# lying on one another (Fig. 10's four, at 40 cells) stay visible and named.
load dir."/common.gp"
w = 9; h = 5
colours = "#d62728 #1f77b4 #2ca02c #9467bd #ff7f0e #8c564b #17becf"
if (!exists("colour_of")) colour_of = ""
if (!exists("dashes")) dashes = ""
colour_k(k) = colour_of eq "" ? word(colours, k) : word(colours, int(word(colour_of, k)))
dash_k(k) = dashes eq "" ? "1" : word(dashes, k)
markers = "6 4 8 12 2 10 14"
intervals = "47 53 59 61 67 71 73"
curves = "plot word(files,1) using ($1*1e6):3 with lines ".exact_style." title 'exact'"
do for [k=1:words(files)] {
  curves = curves.sprintf(", '%s' using ($1*1e6):2 with linespoints lw 1.5 dt %s pt %s pi %s ps 0.9 lc rgb '%s' title '%s'", \
                          word(files,k), dash_k(k), word(markers,k), word(intervals,k), colour_k(k), word(titles,k))
}
main = "set title caption; set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set xrange [0:200]; set yrange [-8:9]; set key top right; ".curves
zoom = "set origin 0.58,0.1; set size 0.38,0.36; unset title; unset xlabel; unset ylabel; set xrange [40:66]; set yrange [-1:7]; set key off; set object 1 rect from graph 0,0 to graph 1,1 behind fc rgb 'white' fs solid; ".curves."; unset object 1"
draw = inset ? "set multiplot; ".main."; ".zoom."; unset multiplot" : main
load dir."/output.gp"
