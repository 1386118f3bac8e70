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
series() {  # series NAME INTEGRATOR CAPTION: v_A(t) of the four shapes at 40 cells (dyka_series.gp), differences below
  g "out='$figures/$1'; shapes='linear ugimp lme lme_authors'; integrator='$2'; caption='$3'" dyka_series.gp
}
g "out='$figures/dyka_fig7'" dyka_fig7.gp
# Figs. 9 and 10: linear, uGIMP, LME and LME under the authors' beta, each in its shape's colour (palette.gp).
series dyka_fig9 fe "Fig. 9: shape functions, forward Euler (40 cells, CFL 0.5): linear and uGIMP lie on one another, the two LMEs apart (bottom: each minus linear)"
series dyka_fig10 npc "Fig. 10: shape functions, predictor-corrector (40 cells, CFL 0.5): all four lie on one another, as do their errors (bottom: each minus linear)"
g "out='$figures/dyka_fig8'" dyka_fig8.gp
ls "$figures"/dyka_fig* >/dev/null 2>&1 || status=1
exit $status
