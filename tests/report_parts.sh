#!/usr/bin/env bash
# verification/budget.sh and verification/assemble_report.sh, which make figures and make studies share: a part's
# row has its exit code and its CPU seconds (those of its children, a busy loop's counted); the report keeps the
# other target's part as it was made, or says "not run yet", never an empty or stale heading.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source "$root/verification/budget.sh"
source "$root/verification/assemble_report.sh"
results=$work/results
mkdir -p "$results/report"
budget_open "$results/figures_budget.csv" figures
spin() { awk 'BEGIN { for (k = 0; k < 3e7; k++) s += k; print s > "/dev/null" }'; }
budget_part busy spin
budget_part failing false
row=$(grep '^figures,busy,' "$results/figures_budget.csv")
awk -F, '{ exit !($4 > 0.2 && $5 == 0) }' <<<"$row" || fail "a busy part's row: $row (want CPU > 0.2 s, exit 0)"
grep -q '^figures,failing,[0-9.]*,[0-9.]*,1$' "$results/figures_budget.csv" ||
  fail "a failing part's exit code: $(cat "$results/figures_budget.csv")"
budget_markdown "$results/figures_budget.csv" | grep -q '^| all but the build |' || fail "no sum in the table"
assemble "$results"
grep -q 'Not run yet: `make figures`' "$results/report.md" || fail "figures not run: $(cat "$results/report.md")"
grep -q 'Not run yet: `make studies`' "$results/report.md" || fail "studies not run: $(cat "$results/report.md")"
made_section figures "$root" "$results/figures_budget.csv" 12 >"$results/report/00_made.md"
printf '## Figure section\n\n![a](figures/a.png)\n' >"$results/report/10_a.md"
assemble "$results"
grep -q '^Commit .*, 12 s on' "$results/report.md" || fail "no commit and time: $(cat "$results/report.md")"
grep -q '^| busy |' "$results/report.md" || fail "no budget table in the report"
grep -q 'Not run yet: `make studies`' "$results/report.md" || fail "studies not run, after figures"
mkdir -p "$results/studies/report"
made_section studies "$root" "$results/figures_budget.csv" 34 >"$results/studies/report/00_made.md"
printf '## Study section\n\n![b](figures/b.png)\n' >"$results/studies/report/10_b.md"
assemble "$results"
grep -q '^## Figure section' "$results/report.md" || fail "the figures' part lost when studies wrote"
grep -q '(studies/figures/b.png)' "$results/report.md" || fail "a study's figure not linked under studies/figures/"
grep -q '(figures/a.png)' "$results/report.md" || fail "a figure's link changed"
grep -q 'Not run yet' "$results/report.md" && fail "'not run yet' after both ran"
echo "report_parts: $failures failures"
[[ $failures -eq 0 ]]
