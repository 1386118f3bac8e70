#!/usr/bin/env bash
# `make figures`: the paper's figures (Figs. 4, 6-13) with the paper's claims about them, checked against the exact
# solutions, into results/:
#   results/figures/          each figure as PNG (screen) and PDF (paper)
#   results/data/             the data of each figure as CSV
#   results/report/           this target's sections of the report (00_made.md: commit, time, each part's seconds)
#   results/report.md         the report: these sections, then make studies' (or "not run yet")
#   results/figures_budget.csv  each part's wall and CPU seconds (the build's too, when BUILD_JOBS is given)
# Everything beyond the paper (baselines, smooth and manufactured solutions, grid crossing, the stability map,
# work-precision, other codes) is `make studies` (make_studies.sh), which leaves these sections in place.
# A check that fails a bound the theory gives makes this script (and `make figures`) fail; a claim of the paper
# that our runs do not support is reported as such, and does not. So does a number quoted in paper/ or README.md
# that differs from these results (check_book_numbers.py --target figures: the numbers these runs make).
#
#   verification/make_figures.sh BUILD_DIR [BUILD_JOBS]   (BUILD_JOBS: build figure_programs first, timed)
#
# Each suite writes its data, its figures and a report fragment results/report/NN_name.md, and exits 1 when one of
# its hard checks fails. Each suite uses every core (never more threads than cores), so they run one after the other;
# their progress lines ("figures: ...") reach the terminal, everything else goes to their logs in results/report/.
set -uo pipefail
build=${1:-build} jobs=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/$build/bin
out=$root/results
rm -rf "$out/figures" "$out/data" "$out/report" "$out/report.md"
mkdir -p "$out/figures" "$out/data" "$out/report"
start=$(date +%s)
export MPM_BIN=$bin MPM_ROOT=$root MPM_RESULTS=$out
source "$root/verification/budget.sh"
source "$root/verification/assemble_report.sh"
budget_open "$out/figures_budget.csv" figures

status=0
if [[ -n $jobs ]]; then
  budget_part build cmake --build "$root/$build" --target figure_programs -j "$jobs" ||
    { echo "figures: the build failed"; exit 1; }
  start=$(date +%s)
fi
suite() {  # suite NAME LOG: runs verification/NAME.sh, its log to LOG, its progress lines to the terminal
  bash "$root/verification/$1.sh" 2>&1 | tee "$2" | grep --line-buffered '^figures:'
  return "${PIPESTATUS[0]}"
}
budget_part shapes suite shape_figures "$out/report/shapes.log" ||
  { echo "figures: shape functions (Fig. 4) failed, see $out/report/shapes.log"; status=1; }
echo "figures: shape functions done ($(( $(date +%s) - start )) s)"
budget_part dyka suite dyka_figures "$out/report/dyka.log" ||
  { echo "figures: Dyka bar (Figs. 6-10) failed, see $out/report/dyka.log"; status=1; }
echo "figures: Dyka bar done ($(( $(date +%s) - start )) s)"
budget_part soil suite soil_figures "$out/report/soil.log" ||
  { echo "figures: soil block (Figs. 11-13) failed, see $out/report/soil.log"; status=1; }
echo "figures: soil block done ($(( $(date +%s) - start )) s)"

elapsed=$(( $(date +%s) - start ))
made_section figures "$root" "$out/figures_budget.csv" "$elapsed" >"$out/report/00_made.md"
assemble "$out"
echo "figures: wrote $out/figures/, data in $out/data/, report $out/report.md, in ${elapsed} s"
# The numbers paper/ and README.md quote from these runs, each marked with its source, against them.
(cd "$root" && python3 verification/check_book_numbers.py --target figures "$out" paper/*.md README.md) || {
  echo "figures: a number quoted in paper/ or README.md differs from results/ (above): update the text"; status=1; }
[[ $status -eq 0 ]] || echo "figures: FAILED (a hard check failed: see the report and the logs in $out/report/)"
exit $status
