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
