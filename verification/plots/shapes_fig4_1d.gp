# Fig. 4, 1D: N (left) and dN/dx (right) of the node at x = 0 (h = 1) for linear, uGIMP and LME gamma 0.8, 1.8, 4
# (shape1d_NAME_centre.csv: x, N, dN_dx); below each, the difference from the linear hat (the files pasted side by
# side), where uGIMP and LME gamma = 4, which lie within a line width of it above, show. Linear and uGIMP in their
# shapes' colours, the LME gammas as a ramp (4 darkest, 0.8 lightest). The title says how close uGIMP and LME gamma = 4
# lie to the hat: within a line width (|N - N_linear| < 0.01, |dN/dx - dN_linear/dx| < 0.02) farther from a node
# (x = 0, +-1) than the distance it gives, and by how much at most they differ nearer; the lower panels' titles give
# each one's largest difference; every number computed here from the CSVs.
# gnuplot -e "dir='verification/plots'; data='DATA_DIR'; out='.../shapes_fig4_1d'" shapes_fig4_1d.gp
load dir."/common.gp"
w = 12; h = 7.5
names = "linear ugimp lme_0.8 lme_1.8 lme_4"
titles = "'linear (Q4)' 'uGIMP, l_p = h/4' 'LME γ = 0.8' 'LME γ = 1.8' 'LME γ = 4'"
file(k) = sprintf("%s/shape1d_%s_centre.csv", data, word(names, k))
against_linear(k) = sprintf("< paste -d, %s %s", file(k), file(1))     # x, N, dN/dx, then the linear hat's
# the LME gammas: steps 1, 2 and 4 of the ramp's 7 (purple, indigo, blue-teal), gamma = 4 (nearest the linear hat and
# uGIMP) darkest; its steps 5 to 7 (sea green to lime) would sit near uGIMP's green
shade(k) = k == 1 ? colour('linear') : k == 2 ? colour('ugimp') : ramp(int(word('4 2 1', k - 2)), 7)
style(k) = sprintf("with lines lw %g lc rgb '%s'", k == 1 ? 2 : 1.5, shade(k))
one(k, column) = sprintf("'%s' using 1:%d %s title '%s'", file(k), column, style(k), word(titles, k))
curves(column) = "plot ".one(1, column).", ".one(2, column).", ".one(3, column).", ".one(4, column).", ".one(5, column)
minus_linear(k, column) = sprintf(", '%s' using 1:($%d - $%d) %s", against_linear(k), column, column + 3, style(k))
differences(column) = "plot ".sprintf("'%s' using 1:(0) %s", file(1), style(1)).minus_linear(2, column) \
  .minus_linear(3, column).minus_linear(4, column).minus_linear(5, column)
margins(x, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; " \
  ."set tmargin at screen %g; ", x + 0.07, x + 0.48, bottom, top)
upper(x) = margins(x, 0.45, 0.87)."unset xlabel; "
lower(x) = margins(x, 0.08, 0.37)."set xlabel 'x / h'; unset key; "
# For uGIMP (2) and LME gamma = 4 (5): the largest difference from the hat, of N (column 2) and dN/dx (column 3), and
# the farthest a point lies from its nearest node (x = 0, +-1, ...) where the difference is more than a line width
# (0.01 of N, 0.02 of dN/dx); largest_K_C and near_K_C.
width(column) = (column == 2 ? 0.01 : 0.02)
do for [k in '2 5'] { do for [column = 2:3] {
  stats against_linear(int(k)) using (abs(column(column) - column(column + 3))):(abs(column(column) - column(column + 3)) > width(column) ? abs($1 - floor($1 + 0.5)) : 0) nooutput
  eval sprintf("largest_%s_%d = STATS_max_x; near_%s_%d = STATS_max_y", k, column, k, column)
} }
closeness = sprintf("uGIMP and LME γ = 4 lie on the hat, within a line width (N within %g, ∂N/∂x within %g), farther than %.2f h and %.2f h from a node (∂N/∂x: %.2f h and %.2f h);\n", \
  width(2), width(3), near_2_2, near_5_2, near_2_3, near_5_3) . sprintf("nearer they differ from it by up to %.3f and %.3f in N, %.2f and %.2f in ∂N/∂x (at the hat’s kinks, where its slope jumps)", largest_2_2, largest_5_2, largest_2_3, largest_5_3)
differences_title(column) = sprintf(column == 2 ? "set title '%s: uGIMP up to %.3f, LME γ = 4 up to %.3f'; " : "set title '%s: uGIMP up to %.2f, LME γ = 4 up to %.2f (at the kinks)'; ", \
  column == 2 ? 'N − N_{linear}' : '∂N/∂x − ∂N_{linear}/∂x', value(sprintf('largest_2_%d', column)), value(sprintf('largest_5_%d', column)))
draw = "set multiplot title 'Fig. 4 (1D): the shape function N of the node at x = 0 and its derivative (h = 1, β = γ/h^2); " \
  ."below, each minus the linear hat’s\n".closeness."'; set xrange [-5:5]; set grid; set key top right; " \
  .upper(0)."set title 'N'; set ylabel 'N'; set yrange [-0.05:1.1]; ".curves(2)."; " \
  .upper(0.5)."set title '∂N/∂x'; set ylabel '∂N/∂x'; set yrange [-1.15:1.15]; ".curves(3)."; " \
  .lower(0).differences_title(2)."set ylabel 'N − N_{linear}'; set yrange [-0.55:0.55]; ".differences(2)."; " \
  .lower(0.5).differences_title(3)."set ylabel '∂N/∂x − ∂N_{linear}/∂x'; set yrange [-1.1:1.1]; ".differences(3)."; unset multiplot"
load dir."/output.gp"
