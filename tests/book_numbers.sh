#!/usr/bin/env bash
# verification/check_book_numbers.py (run by make figures and make studies against results/) on a results folder and
# pages made by hand: a number that matches its source passes (also scaled by a factor, a per cent); a stale
# one, a missing row, a missing file, a bad factor and a regular expression that matches nothing each fail,
# naming the page's line.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
check=$root/verification/check_book_numbers.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
mkdir -p "$work/results/data"
printf 'shape,integrator,cells,rms_over_v0\nlinear,fe,40,0.17183\nlinear,npc,40,0.16424\n' >"$work/results/data/sweep.csv"
printf '| mass | largest relative error 2.48e-14 | **holds** |\n' >"$work/results/report.md"
page=$work/page.md
expect() {  # expect CODE PATTERN: runs the check on $page
  local code=$1 pattern=$2
  python3 "$check" "$work/results" "$page" >"$work/out" 2>&1
  local got=$?
  [[ $got -eq $code ]] || fail "exit $got, want $code: $(cat "$work/out")"
  grep -qE "$pattern" "$work/out" || fail "no /$pattern/ in: $(cat "$work/out")"
}
printf 'RMS 0.1718<!-- check sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 --> and +0.16<!-- check sweep.csv shape=linear integrator=npc cells=40.0 : rms_over_v0 -->;\nmass 2.48e-14<!-- check report.md /largest relative error ([-+0-9.e]+)/ -->.\n' >"$page"
expect 0 "3 quoted numbers checked.*0 differ"
printf 'line one\nRMS 0.1719<!-- check sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 -->\n' >"$page"
expect 1 "page.md:2: 0.1719: the results say 0.17183"
printf 'mass 2.6e-14<!-- check report.md /largest relative error ([-+0-9.e]+)/ -->\n' >"$page"
expect 1 "page.md:1: 2.6e-14: the results say 2.48e-14"
printf 'RMS 0.17<!-- check sweep.csv shape=ugimp integrator=fe cells=40 : rms_over_v0 -->\n' >"$page"
expect 1 "0 rows of sweep.csv match"
printf 'RMS 0.17<!-- check nothing.csv shape=linear : rms_over_v0 -->\n' >"$page"
expect 1 "no .*nothing.csv"
printf 'RMS 0.17<!-- check sweep.csv shape=linear integrator=fe : rms -->\n' >"$page"
expect 1 "sweep.csv has no column rms"
printf 'mass 1e-14<!-- check report.md /smallest error ([0-9.e-]+)/ -->\n' >"$page"
expect 1 "matches nothing"
printf 'RMS 17.18<!-- check sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 * 100 --> %%\n' >"$page"
expect 0 "1 quoted numbers checked.*0 differ"
printf 'RMS 17.3<!-- check sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 * 100 --> %%\n' >"$page"
expect 1 "page.md:1: 17.3: the results say 17.18"
printf 'RMS 17.18<!-- check sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 * a hundred -->\n' >"$page"
expect 1 "the factor after"
# A CSV that ships in verification/data (other codes' numbers) is read when results/data has none of that name.
printf 'theirs 0.1644<!-- check other_codes.csv code=NL-PartSol case=dyka_bar/lme_pce/40_cells quantity=rms_over_v0 : value -->\n' >"$page"
expect 0 "1 quoted numbers checked.*0 differ"
printf 'theirs 0.1655<!-- check other_codes.csv code=NL-PartSol case=dyka_bar/lme_pce/40_cells quantity=rms_over_v0 : value -->\n' >"$page"
expect 1 "page.md:1: 0.1655: the results say 0.164373"
# --target: make figures checks what results/data holds, make studies what results/studies/data holds; a number the
# other target makes, or whose source is missing while the other target has not run, is left to it; once both ran,
# a missing source fails.
expect_target() {  # expect_target TARGET CODE PATTERN
  python3 "$check" --target "$1" "$work/results" "$page" >"$work/out" 2>&1
  local got=$?
  [[ $got -eq $2 ]] || fail "--target $1: exit $got, want $2: $(cat "$work/out")"
  grep -qE "$3" "$work/out" || fail "--target $1: no /$3/ in: $(cat "$work/out")"
}
mkdir -p "$work/results/studies/data" "$work/results/studies/report" "$work/results/report"
printf 'shape,rms\nlinear,0.5\n' >"$work/results/studies/data/smooth.csv"
printf 'RMS 0.1718<!-- check sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 --> and 0.6<!-- check smooth.csv shape=linear : rms -->\n' >"$page"
expect_target figures 0 "1 quoted numbers checked.*0 differ.*1 left to make studies"
expect_target studies 1 "page.md:1: 0.6: the results say 0.5"
printf 'RMS 0.1<!-- check later.csv shape=linear : rms -->\n' >"$page"
expect_target figures 0 "0 quoted numbers checked.*1 left to make studies"
touch "$work/results/studies/report/00_made.md"
expect_target figures 1 "no .*later.csv"
# A report.md expression may match the same claim in either target's part: before the other target has run it is left
# to it (make studies alone must not read the figures' claim off its own part); once both ran, the figures' part first.
rm -f "$work/results/report/00_made.md"
printf '| Fig. 7: NPC stays | (3 hold, 0 fail) |\n' >"$work/results/studies/report/20_dyka.md"
printf '%s\n' 'holds on 3<!-- check report.md /Fig\. 7: NPC stays[^|]*\| \(([0-9]+) hold/ -->' >"$page"
expect_target studies 0 "0 quoted numbers checked.*1 left to make figures"
printf '| Fig. 7: NPC stays | (1 hold, 0 fail) |\n' >"$work/results/report/20_dyka.md"
touch "$work/results/report/00_made.md"
expect_target studies 0 "0 quoted numbers checked.*1 left to make figures"
expect 1 "page.md:1: 3: the results say 1"
echo "book_numbers: $failures failures"
[[ $failures -eq 0 ]]
