#!/usr/bin/env bash
# Fig. 4: N, dN/dx and dN/dy of the central node of a 2D node lattice (h = 1) for linear (Q4),
# uGIMP (particle length h/2) and LME with several gamma (beta = gamma/h^2), and the same in 1D,
# all drawn by `mpm shape`'s function (verification/shape_tables.cpp). Called by make_figures.sh (MPM_BIN, MPM_ROOT, MPM_RESULTS set).
# Hard check: the partition of unity at every sampled point, to 1e-9.
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
kinds=("linear" "ugimp" "lme 0.8" "lme 1.8" "lme 4")
status=0

# The stencils of every kind on a 41 x 41 lattice of points on [-2, 2]^2 and 1001 points on [-5, 5], as `mpm shape
# --dim D --kind KIND [--gamma G] --at X[,Y] ...` prints them (verification/shape_tables.cpp: the same function).
"$MPM_BIN/shape_tables" "$data" || status=1
unity_report=""
for kind in "${kinds[@]}"; do
  set -- $kind
  name=$1${2:+_$2}
  # the central node's values at every point (0 where it is not in the stencil)
  awk -F, 'NR>1 && $2==0 && $3==0 {n[$1]=$4; gx[$1]=$5; gy[$1]=$6}
           END{print "x,y,N,dN_dx,dN_dy"; for(p=0;p<41*41;p++){i=p%41; j=int(p/41); printf "%g,%g,%.10g,%.10g,%.10g\n", -2+0.1*i, -2+0.1*j, n[p]+0, gx[p]+0, gy[p]+0; if(i==40) print ""}}' \
    "$data/shape2d_$name.csv" >"$data/shape2d_${name}_centre.csv"
  awk -F, 'NR>1 && $2==0 {n[$1]=$3; g[$1]=$4} END{print "x,N,dN_dx"; for(p=0;p<=1000;p++) printf "%g,%.10g,%.10g\n", -5+0.01*p, n[p]+0, g[p]+0}' \
    "$data/shape1d_$name.csv" >"$data/shape1d_${name}_centre.csv"
  worst=$(awk -F, 'NR>1 {s[$1]+=$4} END{w=0; for(p in s){d=s[p]-1; if(d<0)d=-d; if(d>w)w=d}; printf "%.2e", w}' "$data/shape2d_$name.csv")
  unity_report="$unity_report| $kind (2D, 1681 points) | $worst | $(awk -v w="$worst" 'BEGIN{print (w<=1e-9) ? "**holds**" : "**FAILS (hard check)**"}') |\n"
  awk -v w="$worst" 'BEGIN{exit !(w<=1e-9)}' || status=1
done

source "$MPM_ROOT/verification/figure.sh"
draw_figure shapes_fig4.gp "out='$figures/shapes_fig4'" || status=1
draw_figure shapes_fig4_1d.gp "out='$figures/shapes_fig4_1d'" || status=1

# How far each LME is from the linear hat along the line (1D), and its support.
distance() { paste -d, "$data/shape1d_$1_centre.csv" "$data/shape1d_linear_centre.csv" | awk -F, 'NR>1 {d=$2-$5; if(d<0)d=-d; if(d>w)w=d} END{printf "%.4f", w}'; }
support() { awk -F, 'NR>1 && $2>1e-6 {x=$1<0?-$1:$1; if(x>w)w=x} END{printf "%.2f", w}' "$data/shape1d_$1_centre.csv"; }
d08=$(distance lme_0.8) d18=$(distance lme_1.8) d4=$(distance lme_4)
{
  echo "## Shape functions (Fig. 4: \`shapes_fig4\`, \`shapes_fig4_1d\`)"
  echo
  echo "![shapes_fig4](figures/shapes_fig4.png)"
  echo
  echo "The figure: N, dN/dx and dN/dy (rows) of the central node of the 2D lattice (h = 1) for Q4, uGIMP and LME γ = 0.8,"
  echo "1.8 and 4 (columns), on one signed colour scale per row (white at zero)."
  echo
  echo "![shapes_fig4_1d](figures/shapes_fig4_1d.png)"
  echo
  echo "The same in 1D: N and dN/dx of the node at x = 0, and below each its difference from the linear hat, where uGIMP"
  echo "and LME γ = 4, which lie within a line width of the hat above except near the nodes, show; the title gives how near"
  echo "(in h) and by how much at most they differ there, computed from the curves."
  echo
  echo "| claim | measured | verdict |"
  echo "|---|---|---|"
  echo -e "${unity_report%\\n}" | sed 's/^| \(.*\) | \(.*\) | \(.*\) |$/| Bound: partition of unity, sum_I N_I = 1 to 1e-9: \1 | largest |sum N - 1| = \2 | \3 |/'
  echo "| LME approaches the linear interpolant as γ grows (1D, max \|N_LME - N_linear\| of the central node) | γ = 0.8: $d08; γ = 1.8: $d18; γ = 4: $d4 | $(awk -v a="$d08" -v b="$d18" -v c="$d4" 'BEGIN{print (a>b && b>c) ? "**holds**" : "**does not hold**"}') |"
  echo "| LME's support widens as γ falls (1D, largest \|x\|/h with N > 1e-6): linear $(support linear), uGIMP $(support ugimp) | γ = 0.8: $(support lme_0.8); γ = 1.8: $(support lme_1.8); γ = 4: $(support lme_4) | $(awk -v a="$(support lme_0.8)" -v b="$(support lme_1.8)" -v c="$(support lme_4)" 'BEGIN{print (a>b && b>c) ? "**holds**" : "**does not hold**"}') |"
  echo
} >"$MPM_RESULTS/report/10_shapes.md"
exit $status
