# Fig. 4, 1D: N and dN/dx of the node at x = 0 (h = 1) for each shape function.
load dir."/common.gp"
w = 11; h = 4.2
names = "linear ugimp lme_0.8 lme_1.8 lme_4"
titles = "'linear' 'uGIMP, l_p = h/4' 'LME γ = 0.8' 'LME γ = 1.8' 'LME γ = 4'"
colours = "black #2ca02c #440154 #277f8e #a0da39"
curves(column) = ""
plot_of(column) = "plot ".sprintf("'%s/shape1d_%s_centre.csv' using 1:%d with lines lw 1.5 lc rgb '%s' title '%s'", data, word(names,1), column, word(colours,1), word(titles,1)).sprintf(", '%s/shape1d_%s_centre.csv' using 1:%d with lines lw 1.5 lc rgb '%s' title '%s'", data, word(names,2), column, word(colours,2), word(titles,2)).sprintf(", '%s/shape1d_%s_centre.csv' using 1:%d with lines lw 1.5 lc rgb '%s' title '%s'", data, word(names,3), column, word(colours,3), word(titles,3)).sprintf(", '%s/shape1d_%s_centre.csv' using 1:%d with lines lw 1.5 lc rgb '%s' title '%s'", data, word(names,4), column, word(colours,4), word(titles,4)).sprintf(", '%s/shape1d_%s_centre.csv' using 1:%d with lines lw 1.5 lc rgb '%s' title '%s'", data, word(names,5), column, word(colours,5), word(titles,5))
draw = "set multiplot layout 1,2 title 'Fig. 4 (1D): the shape function of the node at x = 0, h = 1'; set xlabel 'x / h'; set xrange [-5:5]; set key top right font ',8'; set ylabel 'N'; set yrange [-0.05:1.1]; ".plot_of(2)."; set ylabel 'dN/dx'; set yrange [-1.15:1.15]; ".plot_of(3)."; unset multiplot"
load dir."/output.gp"
