#!/usr/bin/env bash
# The Dyka bar beyond the paper, in `make studies`: the fair comparison of the integrators (dyka_fair), the two beta
# rules on every mesh, the choices, the energy over 10 periods, today's baselines with their error-cost fronts
# (dyka_work_precision), the experiments that decide the claims (all particles, gamma on three meshes, the step refined
# at fixed h, the initial speed swept: verification/dyka_experiments.hpp) and the stability map (dyka_stability):
# dyka_suite --part studies, then
# verification/dyka_stability.sh. Called by make_studies.sh with MPM_BIN, MPM_ROOT and MPM_RESULTS set (its
# results/studies/); exits 1 when a hard check fails.
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
scene=$MPM_ROOT/scenes/dyka_bar.toml
status=0
"$MPM_BIN/dyka_suite" "$data" "$MPM_RESULTS/report/20_dyka_studies.md" "$scene" --part studies || status=1
bash "$MPM_ROOT/verification/dyka_stability.sh" "$MPM_BIN/mpm" "$scene" "$data" || status=1
echo "studies: dyka: stability map done"

source "$MPM_ROOT/verification/figure.sh"
g() { draw_figure "$2" "$1" || status=1; }
g "out='$figures/dyka_fair'" dyka_fair.gp
g "out='$figures/dyka_fig7_fair'; fair=1" dyka_fig7.gp
g "out='$figures/dyka_work_precision'" dyka_work_precision.gp
for experiment in dyka_space_time dyka_gamma_meshes dyka_temporal dyka_amplitude; do g "out='$figures/$experiment'" "$experiment.gp"; done
below=$(grep '^linear_fe,' "$data/dyka_stability.csv" | cut -d, -f2) above=$(grep '^linear_fe,' "$data/dyka_stability.csv" | cut -d, -f3)
g "out='$figures/dyka_stability'; below='$below'; above='$above'" dyka_stability.gp

# The runs on each mesh's error-cost front (data/dyka_baselines.csv, column pareto), as "40 cells: a, b; 160 cells: ...".
# The fronts and their ties are also in the section "Today's baselines".
front() {
  tail -n +2 "$data/dyka_baselines.csv" | awk -F, '$7 == 1 { list[$2] = list[$2] (list[$2] == "" ? "" : ", ") $1 } END { for (n in list) print n, list[n] }' |
    sort -n | awk '{ n = $1; $1 = ""; printf "%s%s cells:%s", (NR > 1 ? "; " : ""), n, $0 }'
}

# The largest spread of the repeated timings (slowest over fastest - 1, per cent): the horizontal bars of dyka_work_precision.
bars=$(tail -n +2 "$data/dyka_baselines.csv" | awk -F, '$11 > 1 && $6 == "ok" { s = 100 * ($10 / $9 - 1); if (s > m) m = s } END { printf "%.1f", m }')

# The stability map's section of the report.
{
  echo "### Speed against accuracy (\`dyka_work_precision\`)"
  echo
  echo "![dyka_work_precision](figures/dyka_work_precision.png)"
  echo
  echo "RMS of v_A against the CPU time of each run (the thread's, one run per core at a time), one panel per integrator (FE; NPC; FE with USL or MUSL), each method in its shape's colour and its integrator's dash and marker: the paper's methods over the mesh sweep (points left to right: 10 to 2560 cells, one run each; the top axis names the meshes) and today's baselines on their meshes (data/dyka_baselines.csv), the runs on 40 and 160 cells repeated 5 times, interleaved (horizontal bars: fastest to slowest, at most ${bars} % apart, so that at the figure's scale they lie within a marker). Under the FE and NPC panels, each method's RMS against LME γ = 3's with the same integrator on the same mesh (per cent), since in the NPC panel the methods lie within a marker of each other: there linear, uGIMP and B-spline 2 + NPC stay within a fraction of a per cent of LME from 40 cells (the panel's title gives the figure), and B-spline 2 equals uGIMP on this bar to a few parts in a million with either integrator, so it is drawn with a larger marker beneath. The runs that stopped and those no better than a flat line are drawn on the strip above the data at their CPU time, each named in the key. Boxed: the runs on their mesh's error-cost front, no method both more accurate and faster by more than the measured spread (the repeats' ranges apart; a single timing, on 640 and 2560 cells, widened by the largest spread of the 160-cell repeats); the section \"Today's baselines\" above names them with the ties the spread leaves: $(front)."
  echo
  bash "$MPM_ROOT/verification/dyka_stability_report.sh" "$data"
} >"$MPM_RESULTS/report/21_dyka_stability.md"
ls "$figures"/dyka_* >/dev/null 2>&1 || status=1
exit $status
