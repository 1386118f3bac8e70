#!/usr/bin/env bash
# `make studies`: everything beyond the paper's figures, each compared with what it is checked against, into
# results/studies/, and its sections into the one report, results/report.md (after make figures' sections, which
# it leaves in place):
#   results/studies/figures/    each figure as PNG and PDF
#   results/studies/data/       the numbers of each study and comparison as CSV
#   results/studies/report/     this target's sections of the report (00_made.md: commit, time, each part's seconds)
#   results/studies/NAME/       each study file's folder as `mpm study` writes it (study.csv, cases/NNNN/, ...)
#   results/studies_budget.csv  each part's wall and CPU seconds (the build's too, when BUILD_JOBS is given)
# Parts:
#   dyka         the Dyka bar beyond the paper: dyka_fair, the two beta rules on every mesh, the choices, the energy
#                over 10 periods, today's baselines and the work-precision chart, the stability map (dyka_studies.sh)
#   soil         the soil block beyond the paper: today's baselines and their error-cost fronts on the 2 m grid, the
#                refinement to 1 and 0.5 m cells, cell crossing, nu = 0.3, the stability sweep, the boundaries, free
#                sides (soil_figures.sh studies)
#   smooth       the vibrating bar's convergence, grid crossing isolated, the 2D manufactured solutions, Fig. 6 at
#                2 particles per cell against the Dyka part's sweep (smooth_figures.sh)
#   disks        the colliding disks of Sulsky, Chen and Schreyer (disks_figures.sh)
#   hydrostatic_column   CB-Geo's hydrostatic column (studies/hydrostatic_column.toml with `mpm study`) against CB-Geo's
#                published values (verification/hydrostatic_column.py, verification/data/other_codes.csv; figure
#                hydrostatic_column)
#   authors_code the authors' code (NL-PartSol) on the Dyka bar, nine cases, against this project
#                (tests/authors_table.sh, verification/authors_code.py; not a study file: fixed cases; figure
#                authors_code from particle A's histories, data/authors_code/)
#   authors_soil the authors' code on the soil block, four cases, against this project under their settings and with
#                each setting undone (verification/authors_soil.py; figure authors_soil from the histories under their
#                settings, data/authors_soil_*.csv)
# A hard check or a comparison that fails (a case that does not finish, a result outside its tolerance) makes this
# script (and `make studies`) fail; so does a number quoted in paper/ or README.md from these runs that differs
# (check_book_numbers.py --target studies). Each part runs its cases on every core, so the parts run one after the
# other; their progress lines ("studies: ...") reach the terminal, everything else their logs in
# results/studies/report/.
#
#   verification/make_studies.sh BUILD_DIR [BUILD_JOBS]   (BUILD_JOBS: build study_programs first, timed)
set -uo pipefail
build=${1:-build} jobs=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/$build/bin
out=$root/results/studies
rm -rf "$out"
mkdir -p "$out/data" "$out/figures" "$out/report"
start=$(date +%s)
export MPM_BIN=$bin MPM_ROOT=$root MPM_RESULTS=$out
source "$root/verification/budget.sh"
source "$root/verification/assemble_report.sh"
source "$root/verification/figure.sh"
budget_open "$root/results/studies_budget.csv" studies

status=0
if [[ -n $jobs ]]; then
  budget_part build cmake --build "$root/$build" --target study_programs -j "$jobs" ||
    { echo "studies: the build failed"; exit 1; }
  start=$(date +%s)
fi
suite() {  # suite NAME LOG [ARGUMENT]: runs verification/NAME.sh, its log to LOG, its progress lines to the terminal
  bash "$root/verification/$1.sh" ${3:+"$3"} 2>&1 | tee "$2" | grep --line-buffered '^figures:\|^studies:' |
    sed -u 's/^figures:/studies:/'
  return "${PIPESTATUS[0]}"
}
study() {  # study NAME COMMAND...: runs studies/NAME.toml into $out/NAME, then COMMAND, both logged to report/NAME.log
  local name=$1
  shift
  "$bin/mpm" study "$root/studies/$name.toml" --out "$out/$name" >"$out/report/$name.log" 2>&1 &&
    "$@" >>"$out/report/$name.log" 2>&1
}
hydrostatic_column() {  # the study's report section and data (hydrostatic_column.py), then its figure, drawn even
  # when a comparison fails (the section shows it); either failing fails the part
  local plots=$root/verification/plots data=$out/data code=0
  python3 "$root/verification/hydrostatic_column.py" "$out/hydrostatic_column" "$root/verification/data/other_codes.csv" \
    "$out/report/55_hydrostatic_column.md" "$data/hydrostatic_column.csv" || code=1
  draw_figure hydrostatic_column.gp "out='$out/figures/hydrostatic_column'" || code=1
  return $code
}
authors_code() {  # the table, particle A's histories (data/authors_code/), the report section, the figure
  local plots=$root/verification/plots data=$out/data
  { bash "$root/tests/authors_table.sh" "$bin/mpm" --write "$data/authors_table.csv" --histories "$data/authors_code" &&
      python3 "$root/verification/authors_code.py" "$data/authors_table.csv" "$out/report/60_authors_code.md" &&
      draw_figure authors_code.gp "out='$out/figures/authors_code'; histories='$data/authors_code'; theirs='$root/verification/data'"; } \
    >"$out/report/authors_code.log" 2>&1
}
authors_soil() {  # the runs, the report section, the histories under their settings (data/authors_soil_*.csv),
  # the figure
  local plots=$root/verification/plots data=$out/data
  { python3 "$root/verification/authors_soil.py" "$bin/mpm" "$root/scenes/soil_block.toml" "$root/verification/data" \
      "$data/authors_soil.csv" "$out/report/61_authors_soil.md" &&
      draw_figure authors_soil.gp "out='$out/figures/authors_soil'"; } >"$out/report/authors_soil.log" 2>&1
}
done_line() { echo "studies: $1 done ($(( $(date +%s) - start )) s)"; }

budget_part dyka suite dyka_studies "$out/report/dyka.log" ||
  { echo "studies: the Dyka bar beyond the paper failed, see $out/report/dyka.log"; status=1; }
done_line "Dyka bar"
budget_part soil suite soil_figures "$out/report/soil.log" studies ||
  { echo "studies: the soil block beyond the paper failed, see $out/report/soil.log"; status=1; }
done_line "soil block"
budget_part smooth suite smooth_figures "$out/report/smooth.log" ||
  { echo "studies: smooth data failed, see $out/report/smooth.log"; status=1; }
# Fig. 6 at 2 particles per cell compares the smooth part's runs with the Dyka part's sweep.
budget_part smooth_fig6 suite smooth_figures "$out/report/smooth_fig6.log" fig6 ||
  { echo "studies: Fig. 6 at 2 ppc failed, see $out/report/smooth_fig6.log"; status=1; }
done_line "smooth data"
budget_part disks suite disks_figures "$out/report/disks.log" ||
  { echo "studies: colliding disks failed, see $out/report/disks.log"; status=1; }
done_line "colliding disks"
budget_part hydrostatic_column study hydrostatic_column hydrostatic_column ||
  { echo "studies: CB-Geo's hydrostatic column failed, see $out/report/hydrostatic_column.log"; status=1; }
done_line "CB-Geo's hydrostatic column"
budget_part authors_code authors_code ||
  { echo "studies: the authors' code beside this project failed, see $out/report/authors_code.log"; status=1; }
done_line "the authors' code on the Dyka bar"
budget_part authors_soil authors_soil ||
  { echo "studies: the authors' code beside this project on the soil block failed, see $out/report/authors_soil.log"; status=1; }
done_line "the authors' code on the soil block"

elapsed=$(( $(date +%s) - start ))
made_section studies "$root" "$root/results/studies_budget.csv" "$elapsed" >"$out/report/00_made.md"
assemble "$root/results"
echo "studies: wrote $out/ and their sections of $root/results/report.md, in ${elapsed} s"
(cd "$root" && python3 verification/check_book_numbers.py --target studies "$root/results" paper/*.md README.md) || {
  echo "studies: a number quoted in paper/ or README.md differs from results/studies/ (above): update the text"
  status=1
}
[[ $status -eq 0 ]] || echo "studies: FAILED (a comparison failed: see the report and the logs in $out/report/)"
exit $status
