#!/usr/bin/env bash
# results/report.md from the sections both targets write: `make figures` (the paper's figures, results/report/*.md)
# and `make studies` (everything beyond the paper, results/studies/report/*.md). Each target's first section
# (00_made.md, written by made_section below) names the target, the commit, the time and each part's wall and CPU
# seconds; a target not run yet shows as "not run yet", never with another run's numbers. Run by both targets last.
#
#   verification/assemble_report.sh RESULTS             writes RESULTS/report.md
#   source verification/assemble_report.sh; made_section TARGET ROOT BUDGET_CSV SECONDS >FILE
set -uo pipefail

made_section() {  # made_section TARGET ROOT BUDGET_CSV SECONDS: the target's opening section, on stdout
  local target=$1 root=$2 budget=$3 seconds=$4 commit
  commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null) || commit="unknown (not a git checkout)"
  [[ -n $(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null) ]] && commit="$commit with local changes"
  local what="the paper's figures (Figs. 4, 6-13) with their claims"
  [[ $target == studies ]] && what="everything beyond the paper"
  echo "## Made by \`make $target\`: $what"
  echo
  echo "Commit $commit, $(date -u '+%Y-%m-%d %H:%M UTC'), ${seconds} s on $(nproc) cores. Each part's wall and CPU"
  echo "seconds (results/${budget##*/}; CPU: the part's processes and threads, the robust number on a shared machine):"
  echo
  budget_markdown "$budget"
  echo
}

assemble() {  # assemble RESULTS
  local results=$1
  {
    echo "# Verification report"
    echo
    echo "Two targets write this report: \`make figures\` the paper's figures (Figs. 4, 6-13) with their"
    echo "claims, \`make studies\` everything beyond the paper. Each target's part opens with the commit and"
    echo "time that made it. Figures are in \`figures/\` and \`studies/figures/\` (PNG and PDF), their data in"
    echo "\`data/\` and \`studies/data/\` (CSV). Each claim is the paper's (its captions, as read in"
    echo "paper/08_test_cases.md), a bound of the theory or a study's; **holds** / **does not hold** is what our"
    echo "runs measured."
    echo
    echo "How every verdict is decided (one rule: mpm/analysis/verdict.hpp for the suites and \`mpm study\`,"
    echo "verification/verdict_rule.py for the scripts, both tested on tests/data/verdict_rule_cases.csv):"
    echo
    echo "1. Each compared number carries the band of its own measurement: an RMS, a ringing or a plateau deficit the"
    echo "   larger move when the same history is scored on its even or its odd samples alone; a ratio the sum of its"
    echo "   two numbers' relative bands; a timing the spread of its repeats; a fitted order two standard errors; the"
    echo "   soil's settlement the floor of its estimator; a published value half its last printed digit."
    echo "2. A comparison whose numbers lie within their bands together is **undecided**: neither holds nor fails."
    echo "3. A comparison with a run that stopped is **stopped**: its own outcome, never scored as holding or failing"
    echo "   (in a hard check, a bound of the theory, a stop fails it; an undecided sample does not)."
    echo "4. A run that finished with an RMS no smaller than a flat line's (the exact history's spread about its mean)"
    echo "   has **failed**: beside a finished run it is compared (and loses); two failed runs are not compared (stopped)."
    echo "5. Every verdict counts holds, fails, undecided and stopped over every run of its study; \"holds on k of n\""
    echo "   counts the decided ones. A claim quoted for one mesh is scored on that mesh, its extension to others is a"
    echo "   row of its own."
    echo
    echo "Every verdict as data: \`verdicts.csv\` (claim, rule, holds, fails, undecided, stopped, the places)."
    echo
    echo "### Verdicts changed since the report this one replaces (commit 81964fb, verification/data/verdicts_81964fb.csv)"
    echo
    if python3 "$(dirname "${BASH_SOURCE[0]}")/verdicts.py" "$results" "$(dirname "${BASH_SOURCE[0]}")/data/verdicts_81964fb.csv" >/dev/null; then
      cat "$results/verdicts_changed.md"
    else
      echo "Not listed: verification/verdicts.py could not read the sections (its message above)."
    fi
    echo
    if [[ -f $results/report/00_made.md ]]; then
      cat "$results"/report/*.md
      echo
    else
      printf '## Made by `make figures`: the paper'"'"'s figures\n\nNot run yet: `make figures`.\n\n'
    fi
    if [[ -f $results/studies/report/00_made.md ]]; then
      cat "$results"/studies/report/*.md | sed 's#](figures/#](studies/figures/#g; s#`figures/#`studies/figures/#g; s#`data/#`studies/data/#g'
    else
      printf '## Made by `make studies`: everything beyond the paper\n\nNot run yet: `make studies`.\n\n'
    fi
  } >"$results/report.md"
}

if [[ ${BASH_SOURCE[0]} == "$0" ]]; then
  source "$(dirname "$0")/budget.sh"
  assemble "$1"
fi
