#!/usr/bin/env bash
# The soil block under ramped gravity (paper section 3.2): Figs. 11-13 and the figures beyond the paper,
# with the data in $MPM_RESULTS/data/soil_*.csv and the report fragment $MPM_RESULTS/report/30_soil.md.
# Called by make_figures.sh, which sets MPM_BIN (executables), MPM_ROOT (the repository) and
# MPM_RESULTS (results/). Exits 1 when a hard check of the suite fails or a figure cannot be drawn.
set -uo pipefail
data=$MPM_RESULTS/data
figures=$MPM_RESULTS/figures
plots=$MPM_ROOT/verification/plots
mkdir -p "$data" "$figures" "$MPM_RESULTS/report"
start=$(date +%s)

status=0
"$MPM_BIN/soil_suite" "$data" "$MPM_RESULTS/report/30_soil.md" "$MPM_ROOT/scenes" || status=1

draw() {  # draw NAME SCRIPT: verification/plots/SCRIPT.gp -> figures/NAME.png and .pdf
  gnuplot -e "data='$data'; out='$figures/$1'" "$plots/$2.gp" || { echo "soil: gnuplot failed on $2.gp"; status=1; }
}
draw soil_fig11_geometry soil_geometry
draw soil_fig12_stress soil_stress
draw soil_fig13_settlement soil_settlement
draw soil_refinement soil_refinement
draw soil_poisson soil_poisson

echo "soil: figures in $figures, report $MPM_RESULTS/report/30_soil.md, in $(( $(date +%s) - start )) s"
exit $status
