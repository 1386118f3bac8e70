# Writes the figure `draw` (a string of gnuplot commands) as out.png and out.pdf at (w, h) inches, both with one
# font: 11 px in the PNG (at 120 px per inch; no figure wider than 1600 px), the same share of the page in the PDF.
# A figure script sets no font smaller than `font_size` (tests/figure_style.py). With `table` set (the figure
# wrapper verification/figure.sh does), the curves are also written as gnuplot's table, where the wrapper finds a
# legend entry without data.
font_size = 11
ppi = 120
if (w * ppi > 1600) { print sprintf("%s: %g px wide, more than 1600", out, w * ppi); exit status 1 }
set terminal pngcairo size w * ppi, h * ppi font sprintf(",%d", font_size)
set output out.".png"
eval(draw)
set terminal pdfcairo size w, h font sprintf(",%g", font_size * 72.0 / ppi)
set output out.".pdf"
eval(draw)
unset output
if (exists("table")) { set terminal dumb; set output "/dev/null"; set table table; eval(draw); unset table; unset output }
