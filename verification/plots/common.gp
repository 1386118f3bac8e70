# Shared settings of every figure: the one visual identity (palette.gp), CSV input, and the strip that holds the runs
# with no value. A figure script loads this, sets `out`, the size (w, h) in inches and `draw` (a string of gnuplot
# commands), then loads output.gp, which writes out.png and out.pdf with one font size for all.
load dir."/palette.gp"
set datafile separator ","
set datafile missing "nan"
set grid lc rgb c_grid
set key noautotitle
# The strip above the data, where a run with no value (stopped by the solver, failed) is drawn: the y range [lo:hi]
# holds every value; the strip, shaded and ruled off, lies above hi. strip_log and strip_linear are commands to eval
# (one per panel); strip_y_log and strip_y_linear the height of a point on the strip. No tic is labelled in the
# strip (ytics up to hi only).
strip_top_log(lo, hi) = hi * (hi / lo)**0.14
strip_y_log(lo, hi) = hi * (hi / lo)**0.07
strip_top_linear(lo, hi) = hi + 0.14 * (hi - lo)
strip_y_linear(lo, hi) = hi + 0.07 * (hi - lo)
strip_common(hi, top, y, name) = sprintf("set object 90 rect from graph 0, first %.12g to graph 1, graph 1 behind fc rgb '%s' fs solid noborder; set arrow 90 from graph 0, first %.12g to graph 1, first %.12g nohead lw 1 lc rgb '%s' front; set label 90 '%s' at graph 0.01, first %.12g left front; ", hi, c_strip, hi, hi, c_exact, name, y)
strip_log(lo, hi, name) = sprintf("set yrange [%.12g:%.12g]; ", lo, strip_top_log(lo, hi)).strip_common(hi, strip_top_log(lo, hi), strip_y_log(lo, hi), name)
strip_linear(lo, hi, name) = sprintf("set yrange [%.12g:%.12g]; ", lo, strip_top_linear(lo, hi)).strip_common(hi, strip_top_linear(lo, hi), strip_y_linear(lo, hi), name)
unstrip = "unset object 90; unset arrow 90; unset label 90; "
