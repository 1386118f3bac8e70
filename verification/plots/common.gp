# Shared settings of every figure: CSV input, and one output per format (PNG for the screen,
# PDF for the paper). A figure script sets `out` and defines `draw`, then loads output.gp.
set datafile separator ","
set datafile missing "nan"
set grid lc rgb "#dddddd"
set key noautotitle
exact_style = "lw 2 lc rgb 'black'"
