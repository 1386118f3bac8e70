#!/usr/bin/env bash
# CB-Geo's hydrostatic column (scenes/hydrostatic_column.toml) against CB-Geo's published values at their coarsest
# cell size, h = 0.01 m, with USF and USL: the check `make studies` makes on all three sizes
# (verification/hydrostatic_column.py: within 0.01 % of verification/data/other_codes.csv), here in every test run.
#   hydrostatic_column.sh MPM
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the study file of `make studies`, its first cell size only
cat >"$work/column.toml" <<TOML
scene = "$root/scenes/hydrostatic_column.toml"
observer = "bottom"

[axes]
"grid.cells, grid.length, body[0].max, solver.dt" = [
  [[2, 10], [0.02, 0.1], [0.02, 0.1], 1.0e-5],
]
solver.stress_update = ["usf", "usl"]
TOML
"$mpm" study "$work/column.toml" --out "$work/study" >"$work/study.log" 2>&1 || {
  echo "FAIL: mpm study of the column failed:"; tail -5 "$work/study.log"; exit 1; }
python3 "$root/verification/hydrostatic_column.py" "$work/study" "$root/verification/data/other_codes.csv" \
  "$work/report.md" "$work/data.csv" || { echo "FAIL: the column differs from CB-Geo's values:"; cat "$work/report.md"; exit 1; }
cat "$work/data.csv"
echo "hydrostatic_column: USF and USL at h = 0.01 m within 0.01 % of CB-Geo's published sigma_yy"
