# Writes the figure `draw` (a string of gnuplot commands) as out.png and out.pdf at size (w, h) inches.
set terminal pngcairo size w*150, h*150 font ",10"
set output out.".png"
eval(draw)
set terminal pdfcairo size w, h font ",8"
set output out.".pdf"
eval(draw)
unset output
