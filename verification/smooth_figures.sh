#!/usr/bin/env bash
# Smooth data: the vibrating bar's convergence, the grid-crossing error isolated, the 2D
# manufactured solutions, and the Dyka bar at 2 particles per cell; data in $MPM_RESULTS/data/smooth_*.csv
# (the runs, the orders with their standard errors, the crossing onsets, the CPU time's measured spread)
# and dyka_2ppc.csv, report fragment $MPM_RESULTS/report/40_smooth.md. Called by make_studies.sh
# (MPM_BIN, MPM_ROOT, MPM_RESULTS set) after the Dyka part; Fig. 6 at 2 particles per
# cell is drawn afterwards, by `smooth_figures.sh fig6`, once the Dyka suite's sweep is written.
# Exits 1 when a hard check of the suite fails or a figure cannot be drawn.
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
status=0
source "$MPM_ROOT/verification/figure.sh"
g() { draw_figure "$2" "$1" || { echo "smooth: figure $2 failed"; status=1; }; }

if [[ ${1:-} == fig6 ]]; then
  "$MPM_BIN/smooth_suite" --fig6-2ppc "$data" "$MPM_RESULTS/report/22_dyka_2ppc.md" || status=1
  g "out='$figures/dyka_fig6_2ppc'" dyka_fig6_2ppc.gp
  exit $status
fi

start=$(date +%s)
"$MPM_BIN/smooth_suite" "$data" "$MPM_RESULTS/report/40_smooth.md" "$MPM_ROOT/scenes/vibrating_bar.toml" "$MPM_ROOT/scenes/dyka_bar.toml" "$MPM_ROOT/scenes/manufactured_square.toml" || status=1
g "out='$figures/smooth_bar_small'; amplitude='small'; caption='Vibrating bar, small amplitude (V/ω = 1e-6 L): RMS errors at T/4, T/2, 3T/4, T against the exact first mode'" smooth_bar.gp
g "out='$figures/smooth_bar_large'; amplitude='large'; caption='Vibrating bar, large amplitude (V/ω = 0.05 L): RMS errors against the finite-strain reference'" smooth_bar.gp
g "out='$figures/smooth_crossing'" smooth_crossing.gp
g "out='$figures/smooth_manufactured'" smooth_manufactured.gp
echo "smooth: figures in $figures, report $MPM_RESULTS/report/40_smooth.md, in $(( $(date +%s) - start )) s"
exit $status
