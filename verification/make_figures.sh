#!/usr/bin/env bash
# `make figures`: runs every verification case and draws every figure into results/figures/
# (PNG for the screen, PDF for the paper), with the data of each figure as CSV in results/data/.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/results
mkdir -p "$out/figures" "$out/data"
start=$(date +%s)

"$root/$build/bin/dyka_suite" "$out/data" "$root/scenes/dyka_bar.toml"
gnuplot -e "data='$out/data/velocity_A_linear_fe_40.csv'; out='$out/figures/dyka_velocity_A'; caption='Dyka bar, point A: linear shape functions, forward Euler, 40 cells, CFL 0.5'" \
  "$root/verification/plots/dyka_velocity.gp"

echo "figures: wrote $out/figures/ (data in $out/data/) in $(( $(date +%s) - start )) s"
