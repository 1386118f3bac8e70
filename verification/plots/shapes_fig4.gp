# Fig. 4: N, dN/dx, dN/dy of the central node (rows) for Q4, uGIMP and LME gamma 0.8, 1.8, 4 (columns).
load dir."/common.gp"
w = 14; h = 8.4
names = "linear ugimp lme_0.8 lme_1.8 lme_4"
titles = "'Q4 (linear)' 'uGIMP, l_p = h/4' 'LME γ = 0.8' 'LME γ = 1.8' 'LME γ = 4'"
rows = "N dN/dx dN/dy"
set view map
set size ratio 1
set palette defined (-1 "#2166ac", 0 "white", 1 "#b2182b")
unset colorbox
set xrange [-2:2]; set yrange [-2:2]
set tics font ",7"
panel(k, r) = sprintf("%s; set title '%s: %s' font ',9'; set cbrange [%s]; splot '%s/shape2d_%s_centre.csv' using 1:2:%d with pm3d", k==5 ? 'set colorbox' : 'unset colorbox', word(titles,k), word(rows,r), r==1 ? "-1:1" : "-1.2:1.2", data, word(names,k), r+2)
draw = "set multiplot layout 3,5 title 'Fig. 4: shape function of the central node of a node lattice (h = 1), β = γ/h^2'"
do for [r=1:3] { do for [k=1:5] { draw = draw."; ".panel(k, r) } }
draw = draw."; unset multiplot"
load dir."/output.gp"
