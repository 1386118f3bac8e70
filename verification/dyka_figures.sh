#!/usr/bin/env bash
# The Dyka-bar figures of `make figures` (Figs. 6-10, speed against accuracy, stability map).
# Called by make_figures.sh with MPM_BIN, MPM_ROOT and MPM_RESULTS set; exits 1 when a hard
# check of the suite fails.
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
scene=$MPM_ROOT/scenes/dyka_bar.toml
status=0
"$MPM_BIN/dyka_suite" "$data" "$MPM_RESULTS/report/20_dyka.md" "$scene" || status=1
bash "$MPM_ROOT/verification/dyka_stability.sh" "$MPM_BIN/mpm" "$scene" "$data" || status=1
echo "figures: dyka: stability map done"

g() { gnuplot -e "dir='$plots'; data='$data'; $1" "$plots/$2" || status=1; }
g "out='$figures/dyka_fig6'; orders='$data/dyka_orders.csv'" dyka_fig6.gp
series() {  # series NAME CAPTION INSET SETTINGS FILES... -- TITLES... (SETTINGS: more gnuplot, e.g. colour_of, dashes)
  local name=$1 caption=$2 inset=$3 settings=$4; shift 4
  local files="" titles=""
  while [[ $1 != -- ]]; do files="$files $data/$1.csv"; shift; done; shift
  titles="$*"
  g "out='$figures/$name'; caption='$caption'; files='${files# }'; titles='$titles'; inset=$inset; $settings" dyka_series.gp
}
g "out='$figures/dyka_fig7'" dyka_fig7.gp
# Figs. 9 and 10: LME also under the authors' beta, dashed in LME's colour.
authors="colour_of='1 2 3 3'; dashes='1 1 1 2'"
series dyka_fig9 "Fig. 9: shape functions, forward Euler (40 cells, CFL 0.5)" 0 "$authors" \
  dyka_linear_fe_40 dyka_ugimp_fe_40 dyka_lme_fe_40 dyka_lme_authors_fe_40 -- linear uGIMP LME '"LME, authors’ β"'
series dyka_fig10 "Fig. 10: shape functions, predictor-corrector (40 cells, CFL 0.5)" 0 "$authors" \
  dyka_linear_npc_40 dyka_ugimp_npc_40 dyka_lme_npc_40 dyka_lme_authors_npc_40 -- linear uGIMP LME '"LME, authors’ β"'
g "out='$figures/dyka_fig8'" dyka_fig8.gp
g "out='$figures/dyka_fair'" dyka_fair.gp
g "out='$figures/dyka_work_precision'" dyka_work_precision.gp
below=$(grep '^linear_fe,' "$data/dyka_stability.csv" | cut -d, -f2) above=$(grep '^linear_fe,' "$data/dyka_stability.csv" | cut -d, -f3)
g "out='$figures/dyka_stability'; below='$below'; above='$above'" dyka_stability.gp

# The runs on each mesh's error-cost front (data/dyka_baselines.csv, column pareto), as "40 cells: a, b; 160 cells: ...".
# The fronts and their ties are also in the Dyka bar's section, "Today's baselines".
front() {
  tail -n +2 "$data/dyka_baselines.csv" | awk -F, '$7 == 1 { list[$2] = list[$2] (list[$2] == "" ? "" : ", ") $1 } END { for (n in list) print n, list[n] }' |
    sort -n | awk '{ n = $1; $1 = ""; printf "%s%s cells:%s", (NR > 1 ? "; " : ""), n, $0 }'
}

# The stability map's section of the report.
{
  echo "### Speed against accuracy (\`dyka_work_precision\`)"
  echo
  echo "![dyka_work_precision](figures/dyka_work_precision.png)"
  echo
  echo "RMS of v_A against the CPU time of each run (the thread's, one run per core at a time): the paper's methods over the mesh sweep (points left to right: 10 to 2560 cells, one run each) and today's baselines by family on their meshes (data/dyka_baselines.csv), the runs on 40 and 160 cells repeated 5 times, interleaved (error bars: fastest to slowest). Ringed: the runs on their mesh's error-cost front, no method both more accurate and faster by more than the measured spread (the repeats' ranges apart; a single timing, on 640 and 2560 cells, widened by the largest spread of the 160-cell repeats); the Dyka bar's section \"Today's baselines\" above names them with the ties the spread leaves: $(front)."
  echo
  bash "$MPM_ROOT/verification/dyka_stability_report.sh" "$data"
} >"$MPM_RESULTS/report/21_dyka_stability.md"
ls "$figures"/dyka_* >/dev/null 2>&1 || status=1
exit $status
