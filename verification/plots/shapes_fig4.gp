# Fig. 4: N, dN/dx, dN/dy of the central node (rows) for Q4, uGIMP and LME gamma 0.8, 1.8, 4 (columns), from
# shape2d_NAME_centre.csv (x, y, N, dN_dx, dN_dy on the node lattice h = 1), as maps on the signed colour scale
# (blue negative, white zero, red positive), drawn as images: N on [-1, 1], the derivatives on [-1.2, 1.2].
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../shapes_fig4'" shapes_fig4.gp
load dir."/common.gp"
w = 13.3; h = 8.4
names = "linear ugimp lme_0.8 lme_1.8 lme_4"
titles = "'Q4 (linear)' 'uGIMP, l_p = h/4' 'LME γ = 0.8' 'LME γ = 1.8' 'LME γ = 4'"
rows = "N ∂N/∂x ∂N/∂y"
# the panel of shape k (column) and field r (row), all of one size on the page; the colour box beside the last
# column, axis labels on the edges only
left(k) = 0.045 + (k - 1) * 0.18
top(r) = 0.9 - (r - 1) * 0.305
margins(k, r) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set tmargin at screen %g; " \
  ."set bmargin at screen %g; ", left(k), left(k) + 0.14, top(r), top(r) - 0.23)
colour_box(k, r) = k == 5 ? sprintf("set colorbox user origin screen 0.94, screen %g size screen 0.012, screen 0.23; ", \
  top(r) - 0.23) : "unset colorbox; "
panel(k, r) = margins(k, r).colour_box(k, r).sprintf("set title '%s: %s'; set cbrange [%s]; set xlabel '%s'; " \
  ."set ylabel '%s'; plot '%s/shape2d_%s_centre.csv' using 1:2:%d with image", \
  word(titles, k), word(rows, r), r == 1 ? "-1:1" : "-1.2:1.2", r == 3 ? 'x / h' : '', k == 1 ? 'y / h' : '', \
  data, word(names, k), r + 2)
draw = "set size ratio 1; set xrange [-2:2]; set yrange [-2:2]; set xtics 1; set ytics 1; " \
  .palette_signed."; set multiplot layout 3,5 title 'Fig. 4: N, ∂N/∂x, ∂N/∂y (rows) of the central node of a node " \
  ."lattice (h = 1) for Q4, uGIMP and LME (columns), β = γ/h^2; blue negative, red positive'"
do for [r = 1:3] { do for [k = 1:5] { draw = draw."; ".panel(k, r) } }
draw = draw."; unset multiplot"
load dir."/output.gp"
