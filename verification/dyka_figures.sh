#!/usr/bin/env bash
# The Dyka-bar figures of `make figures`: the paper's Figs. 6-10 (dyka_suite --part figures). Everything beyond the
# paper on the bar (dyka_fair, the baselines and the work-precision chart, the stability map) is make studies'
# (verification/dyka_studies.sh). Called by make_figures.sh with MPM_BIN, MPM_ROOT and MPM_RESULTS set; exits 1 when
# a hard check of the suite fails.
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
scene=$MPM_ROOT/scenes/dyka_bar.toml
status=0
"$MPM_BIN/dyka_suite" "$data" "$MPM_RESULTS/report/20_dyka.md" "$scene" --part figures || status=1

source "$MPM_ROOT/verification/figure.sh"
g() { draw_figure "$2" "$1" || status=1; }
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
ls "$figures"/dyka_fig* >/dev/null 2>&1 || status=1
exit $status
