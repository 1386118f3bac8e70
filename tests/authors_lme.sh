#!/usr/bin/env bash
# The authors' LME one option away: LME + NPC at gamma 3 under solver.lme_beta = "authors", on the authors' grid (no
# cell beyond the free end), follows particle A's velocity history from the authors' code (NL-PartSol 1d5da04,
# verification/data/nl_partsol_dyka_lme_pce_CELLS.csv; how it was made: verification/data/other_codes.csv) within
# 1e-3 v0 at every one of their samples on 40 and 160 cells; this project's default beta at the same gamma does not
# (it is another shape).
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
largest_difference() {  # largest_difference RUN CELLS: max |v_ours - v_theirs| / v0, ours interpolated at their times
  python3 - "$work/$1/observers.csv" "$root/verification/data/nl_partsol_dyka_lme_pce_$2.csv" <<'PY'
import bisect, csv, sys
ours, theirs = (list(csv.DictReader(open(path))) for path in sys.argv[1:3])
t = [float(row["t"]) for row in ours]
v = [float(row["A.v_x"]) for row in ours]
worst = 0.0
for row in theirs:
    s = float(row["t"])
    if s > t[-1]:
        break
    k = max(1, min(bisect.bisect_left(t, s), len(t) - 1))
    w = v[k - 1] + (s - t[k - 1]) / (t[k] - t[k - 1]) * (v[k] - v[k - 1])
    worst = max(worst, abs(w - float(row["A.v_x"])) / 5.0)
print(worst)
PY
}
for cells in 40 160; do
  for rule in authors grid_spacing; do
    "$mpm" run "$root/scenes/dyka_bar.toml" --out "$work/$rule$cells" --set 'solver.shape="lme"' \
      --set 'solver.integrator="npc"' --set "solver.lme_beta=\"$rule\"" --set "grid.cells=[$cells]" \
      --set 'grid.margin_min=[0]' --set 'output.snapshots=[]' >/dev/null 2>&1 || fail "$cells cells, lme_beta = $rule: the run failed"
  done
  authors=$(largest_difference "authors$cells" "$cells")
  standard=$(largest_difference "grid_spacing$cells" "$cells")
  echo "$cells cells, max |dv| / v0 against the authors' code: lme_beta authors $authors, grid_spacing $standard"
  python3 -c "import sys; sys.exit(0 if $authors < 1e-3 else 1)" || fail "$cells cells, lme_beta = authors: $authors >= 1e-3"
  python3 -c "import sys; sys.exit(0 if $standard > 5e-3 else 1)" || fail "$cells cells, grid_spacing: $standard <= 5e-3"
done
echo "authors_lme: $failures failures"
[[ $failures -eq 0 ]]
