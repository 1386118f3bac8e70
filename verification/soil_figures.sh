#!/usr/bin/env bash
# The soil block under ramped gravity (paper section 3.2): Figs. 11-13 (soil_suite --part figures), with the data in
# $MPM_RESULTS/data/soil_*.csv and the report fragment $MPM_RESULTS/report/30_soil.md; `soil_figures.sh studies`: the
# block beyond the paper (soil_suite --part studies: the baselines' fronts, the refinement, crossing, nu = 0.3, the
# stability sweep, the boundaries, free sides, LME gamma on the 2 m grid), its fragment 35_soil.md.
# Called by make_figures.sh (make_studies.sh with "studies"), which sets MPM_BIN (executables), MPM_ROOT (the
# repository) and MPM_RESULTS (results/, results/studies/). Exits 1 when a hard check of the suite fails or a figure
# cannot be drawn.
set -uo pipefail
data=$MPM_RESULTS/data
figures=$MPM_RESULTS/figures
plots=$MPM_ROOT/verification/plots
mkdir -p "$data" "$figures" "$MPM_RESULTS/report"
start=$(date +%s)

part=${1:-figures}
report=$MPM_RESULTS/report/$([[ $part == studies ]] && echo 35_soil.md || echo 30_soil.md)
status=0
"$MPM_BIN/soil_suite" "$data" "$report" "$MPM_ROOT/scenes" --part "$part" || status=1

source "$MPM_ROOT/verification/figure.sh"
draw() {  # draw NAME SCRIPT: verification/plots/SCRIPT.gp -> figures/NAME.png and .pdf
  draw_figure "$2.gp" "out='$figures/$1'" || { echo "soil: figure $2.gp failed"; status=1; }
}
if [[ $part == studies ]]; then
  draw soil_refinement soil_refinement
  draw soil_poisson soil_poisson
  draw soil_gamma soil_gamma
else
  draw soil_fig11_geometry soil_geometry
  draw soil_fig12_stress soil_stress
  draw soil_fig13_settlement soil_settlement
fi

echo "soil: figures in $figures, report $report, in $(( $(date +%s) - start )) s"
exit $status
