#!/usr/bin/env bash
# The colliding disks of Sulsky, Chen and Schreyer (1994), scenes/colliding_disks.toml: runs the scene and
# draws its kinetic, strain and total energy and its momentum against time (results/figures/disks_energy).
# Called by make_studies.sh (MPM_BIN, MPM_ROOT, MPM_RESULTS set: results/studies/).
# Hard checks: the total momentum stays zero to round-off (no support, no body force: |p| <= 1e-12 of
# the disks' sum of |m v|); the total energy stays bounded (within [0.5, 1.01] of the initial energy).
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
run=$MPM_RESULTS/report/disks_run
status=0
"$MPM_BIN/mpm" run "$MPM_ROOT/scenes/colliding_disks.toml" --out "$run" --set 'output.every=1' >"$run.log" 2>&1 || status=1
cp "$run/energy.csv" "$data/disks_energy.csv" || status=1
gnuplot -e "dir='$plots'; data='$data'; out='$figures/disks_energy'" "$plots/disks_energy.gp" || status=1
# sum |m v| over the particles at t = 0: twice rho pi r^2 |v| per unit thickness is its continuum value; the
# particles' own is the initial kinetic energy's 2 E_0 / |v| (all particles move at |v| = 0.1 sqrt 2 m/s).
read -r momentum energy_low energy_high initial < <(awk -F, 'NR == 2 { e0 = $4 }
  NR > 1 { for (k = 5; k <= 6; k++) { m = $k < 0 ? -$k : $k; if (m > p) p = m }; if ($4 > hi) hi = $4; if (lo == "" || $4 < lo) lo = $4 }
  END { printf "%.3e %.6g %.6g %.6g\n", p, lo, hi, e0 }' "$data/disks_energy.csv")
scale=$(awk -v e="$initial" 'BEGIN { printf "%.6g", 2 * e / (0.1 * sqrt(2)) }')
momentum_ok=$(awk -v p="$momentum" -v s="$scale" 'BEGIN { print (p <= 1e-12 * s) ? "**holds**" : "**FAILS (hard check)**" }')
energy_ok=$(awk -v lo="$energy_low" -v hi="$energy_high" -v e="$initial" 'BEGIN { print (lo >= 0.5 * e && hi <= 1.01 * e) ? "**holds**" : "**FAILS (hard check)**" }')
[[ $momentum_ok == "**holds**" && $energy_ok == "**holds**" ]] || status=1
{
  echo "## Colliding disks (Sulsky, Chen and Schreyer 1994)"
  echo
  echo "\`scenes/colliding_disks.toml\`: two disks of radius 0.2 m (E = 1000 Pa, nu = 0.3, rho = 1000 kg/m^3, 20 x 20 cells,"
  echo "2 x 2 particles per cell, linear shape functions, predictor-corrector, CFL 0.4) meet at +-(0.1, 0.1) m/s and"
  echo "bounce off; \`figures/disks_energy\` draws their energies and momentum to t = 3.5 s."
  echo
  echo "![disks_energy](figures/disks_energy.png)"
  echo
  echo "| check | measured | verdict |"
  echo "|---|---|---|"
  echo "| total momentum stays zero (no support, no body force): largest \\|p\\| <= 1e-12 of sum \\|m v\\| = $scale kg m/s per m | $momentum | $momentum_ok |"
  echo "| total energy bounded: within [0.5, 1.01] of the initial $initial J/m | from $energy_low to $energy_high | $energy_ok |"
  echo
} >"$MPM_RESULTS/report/50_disks.md"
echo "figures: colliding disks: momentum $momentum, energy $energy_low to $energy_high (initial $initial)"
exit $status
