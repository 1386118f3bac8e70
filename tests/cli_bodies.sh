#!/usr/bin/env bash
# Bodies beyond boxes: an ellipse (a disk) or a polygon cut from a box of whole cells; overlapping
# bodies refused naming both; an [[initial_velocity]] box that holds no particle is a warning.
# Counts worked by hand (a loop over the seeds, 0.0125 m from the lines of 0.05 m cells at 2 x 2 per cell).
# Usage: cli_bodies.sh MPM
set -u
mpm=$1
scenes=$(cd "$(dirname "$0")/.." && pwd)/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
disks=$scenes/colliding_disks.toml
short=(--set solver.end_time=0.02 --set 'output.snapshots=[0.0]')

# The two disks: 208 particles each (of the 256 seeds of each 8 x 8-cell box), each with its share of a cell.
"$mpm" run "$disks" --out "$work/disks" "${short[@]}" >"$work/out" 2>"$work/err" || fail "colliding disks: $(cat "$work/err")"
[[ $(($(wc -l <"$work/disks/snapshot_0000.csv") - 1)) -eq 416 ]] || fail "disks: $(($(wc -l <"$work/disks/snapshot_0000.csv") - 1)) particles, want 2 x 208"
awk -F, 'NR > 1 { dx = $2 - ($2 < 0.5 ? 0.25 : 0.75); dy = $3 - ($3 < 0.5 ? 0.25 : 0.75); if (dx * dx + dy * dy > 0.04 + 1e-12) bad++ }
         END { exit bad > 0 }' "$work/disks/snapshot_0000.csv" || fail "a disk particle lies outside its disk"
# Initial momentum zero, initial kinetic energy sum m v^2 / 2 = 416 (1000 0.05^2 / 4)(0.02)/2 = 2.6 J/m.
awk -F, 'NR == 2 { d = $4 - 2.6; if (d < 0) d = -d; exit !(d < 1e-12 && $5 < 1e-12 && $5 > -1e-12) }' "$work/disks/energy.csv" ||
  fail "disks: initial energy and momentum $(sed -n 2p "$work/disks/energy.csv")"
# A polygon: the triangle (0.05, 0.05), (0.45, 0.05), (0.05, 0.45) of the first box keeps the seeds with
# x + y < 0.5: 16 x 16 seeds at 0.0625 + 0.025 k, of which those with k_x + k_y <= 14 lie inside: sum_{s=0}^{14} (s + 1)
# = 120; the 16 with k_x + k_y = 15 lie on the edge (x + y = 0.5), where round-off decides: 120 to 136.
"$mpm" run "$disks" --out "$work/triangle" "${short[@]}" --set 'body[0].shape="polygon"' \
  --set 'body[0].vertices=[[0.05, 0.05], [0.45, 0.05], [0.05, 0.45]]' >/dev/null 2>"$work/err" || fail "polygon: $(cat "$work/err")"
kept=$(awk -F, 'NR > 1 && $2 < 0.5' "$work/triangle/snapshot_0000.csv" | wc -l)
[[ $kept -ge 120 && $kept -le 136 ]] || fail "triangle: $kept particles, want 120 to 136"
awk -F, 'NR > 1 && $2 < 0.5 && $2 + $3 > 0.5 + 1e-9 { bad++ } END { exit bad > 0 }' "$work/triangle/snapshot_0000.csv" || fail "a triangle particle lies outside it"

bad() {  # bad PATTERN ARGS...: exit 2, the message, no output folder
  local pattern=$1; shift
  "$mpm" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [[ $got -ne 2 ]] || ! grep -qE "$pattern" "$work/err" || [[ -e "$work/never" ]]; then
    fail "mpm $* -> exit $got (want 2), stderr: $(cat "$work/err")"
  fi
}
# the second body as the box [0.3, 0.95]^2 holds (0.35, 0.35), which lies in the first disk (0.1^2 + 0.1^2 < 0.2^2)
bad "^error: --set\(1\):1: body\[1\].min: overlaps body\[0\] \($disks:[0-9]+\)" run "$disks" --out "$work/never" --set 'body[1].min=[0.3, 0.3]' \
  --set 'body[1].shape="box"'
# an ellipse in the box [0.4, 0.95]^2 (centre 0.675, semi-axes 0.275) and the first disk: the boxes overlap,
# the shapes do not (0.425 sqrt 2 = 0.60 between the centres, 0.2 + 0.275 = 0.475 along that line): no error
"$mpm" run "$disks" --out "$work/corners" "${short[@]}" --set 'body[1].min=[0.4, 0.4]' >/dev/null 2>"$work/err" ||
  fail "shapes in overlapping boxes but apart: $(cat "$work/err")"
bad "^error: --set\(1\):1: body\[0\].vertices: vertex 1 lies outside the body's box" run "$disks" --out "$work/never" \
  --set 'body[0].vertices=[[0.05, 0.05], [0.5, 0.05], [0.05, 0.45]]' --set 'body[0].shape="polygon"'
bad "^error: .*body\[0\].vertices: missing; a polygon needs its vertices" run "$disks" --out "$work/never" --set 'body[0].shape="polygon"'
bad "^error: .*body\[0\].vertices: only a body of shape = \"polygon\" has vertices" run "$disks" --out "$work/never" \
  --set 'body[0].vertices=[[0.05, 0.05], [0.45, 0.05], [0.05, 0.45]]'
bad "^error: --set\(1\):1: body\[0\].shape: a 1D body is a box" run "$scenes/dyka_bar.toml" --out "$work/never" --set 'body[0].shape="ellipse"'
bad "^error: --set\(2\):1: body\[0\].vertices: the polygon holds no particle" run "$disks" --out "$work/never" --set 'body[0].shape="polygon"' \
  --set 'body[0].vertices=[[0.05, 0.05], [0.45, 0.05], [0.45, 0.051]]'
# a polygon must be simple: the bow tie crosses itself
bad "^error: --set\(2\):1: body\[0\].vertices: edges 0 and 2 meet .*: a polygon must be simple" run "$disks" --out "$work/never" \
  --set 'body[0].shape="polygon"' --set 'body[0].vertices=[[0.05, 0.05], [0.45, 0.45], [0.45, 0.05], [0.05, 0.45]]'
# the budget counts the polygon's vertices times its seeds: 10^4 vertices over 2.56e6 seeds are refused at once
{ printf 'dimension = 2\n[grid]\nlength = [1.0, 1.0]\ncells = [20, 20]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n'
  printf '[[body]]\nmin = [0.05, 0.05]\nmax = [0.45, 0.45]\nshape = "polygon"\nparticles_per_cell = [200, 200]\nvertices = '
  awk 'BEGIN { printf "["; for (v = 0; v < 10000; v++) printf "%s[%.9f, %.9f]", (v ? ", " : ""), 0.25 + 0.19 * cos(v * 6.283185307179586 / 10000), 0.25 + 0.19 * sin(v * 6.283185307179586 / 10000); printf "]\n" }'
  printf '[solver]\nend_time = 1.0\n'; } >"$work/polygon.toml"
start=$(date +%s)
bad "^error: $work/polygon.toml:13: body\[0\].vertices: 10000 vertices over 2\.56e\+06 seeds take 2\.56e\+10 point-in-polygon tests" \
  run "$work/polygon.toml" --print-scene
[[ $(($(date +%s) - start)) -le 10 ]] || fail "refusing a costly polygon took $(($(date +%s) - start)) s"
# the soil column's height is its bodies' top: a grid reaching above it changes nothing in the exact solution
"$mpm" exact "$scenes/soil_block.toml" --at 4.5,9.5 --times 0:5:20 >"$work/column.csv" 2>"$work/err" || fail "soil column: $(cat "$work/err")"
"$mpm" exact "$scenes/soil_block.toml" --set 'grid.length=[10.0, 12.0]' --set 'grid.cells=[5, 6]' --at 4.5,9.5 --times 0:5:20 \
  >"$work/taller.csv" 2>"$work/err" || fail "soil column under a taller grid: $(cat "$work/err")"
cmp -s "$work/column.csv" "$work/taller.csv" || fail "the soil column's exact solution changed with the grid's height"
# boxes: the Dyka bar split in two touching boxes is fine, overlapping ones are not
"$mpm" run "$scenes/dyka_bar.toml" --out "$work/two" --set 'exact="none"' \
  --set 'body=[{min = [0.0], max = [0.033325]}, {min = [0.033325], max = [0.1333]}]' --set solver.end_time=1e-6 --set 'output.snapshots=[]' >/dev/null 2>"$work/err" ||
  fail "two touching boxes: $(cat "$work/err")"
bad "^error: --set\(2\):1: body\[1\].min: overlaps body\[0\] \(--set\(2\):1\)" run "$scenes/dyka_bar.toml" --out "$work/never" --set 'exact="none"' \
  --set 'body=[{min = [0.0], max = [0.033325]}, {min = [0.0], max = [0.1333]}]'

# Particles read from a CSV file, beside the scene: four particles of the first disk's box with their own
# volumes and velocities; the second disk as before. Kinetic energy at t = 0, by hand: the disk's 2.6 / 2 = 1.3
# plus sum m v^2 / 2 = 1000 (0.001 (1 + 4) + 0.002 (0.25)) / 2 = 2.75 J/m, the file's rows in mass order.
cp "$disks" "$work/from_file.toml"
printf '# id, position (m), volume (m^2), velocity (m/s)\nid,x,y,volume,v_x,v_y\n1,0.1,0.1,0.001,1,0\n2,0.2,0.1,0.001,0,2\n3,0.3,0.3,0.002,0.5,0\n4,0.4,0.2,0.002,0,0\n' \
  >"$work/particles.csv"
"$mpm" run "$work/from_file.toml" --out "$work/file" "${short[@]}" --set 'body[0].shape="file"' --set 'body[0].file="particles.csv"' \
  >/dev/null 2>"$work/err" || fail "a body read from a file: $(cat "$work/err")"
[[ $(($(wc -l <"$work/file/snapshot_0000.csv") - 1)) -eq 212 ]] || fail "file body: $(($(wc -l <"$work/file/snapshot_0000.csv") - 1)) particles, want 4 + 208"
awk -F, 'NR == 2 { d = $2 - 4.05; if (d < 0) d = -d; exit !(d < 1e-12) }' "$work/file/energy.csv" ||
  fail "file body: initial kinetic energy $(sed -n 2p "$work/file/energy.csv" | cut -d, -f2), want 4.05"
bad "^error: --set\(2\):1: body\[0\].file: .*/missing.csv: cannot be read" run "$work/from_file.toml" --out "$work/never" \
  --set 'body[0].shape="file"' --set 'body[0].file="missing.csv"'
printf 'x,y,volume\n0.1,0.1,0.001\n0.1,fast,0.001\n' >"$work/bad_row.csv"
bad "^error: --set\(2\):1: body\[0\].file: .*/bad_row.csv:3: y: 'fast' is not a finite number" run "$work/from_file.toml" --out "$work/never" \
  --set 'body[0].shape="file"' --set 'body[0].file="bad_row.csv"'
printf 'x,y,volume\n0.1,0.1,0.001\n0.5,0.1,0.001\n' >"$work/outside.csv"
bad "^error: --set\(2\):1: body\[0\].file: .*/outside.csv: particle 2 lies outside the body's box \[min, max\] on x" run "$work/from_file.toml" \
  --out "$work/never" --set 'body[0].shape="file"' --set 'body[0].file="outside.csv"'
bad "^error: .*body\[0\].file: missing; a body of shape = \"file\"" run "$work/from_file.toml" --out "$work/never" --set 'body[0].shape="file"'

# A velocity box that holds no particle: a warning, and the run goes on.
"$mpm" run "$disks" --out "$work/w" "${short[@]}" --set 'initial_velocity=[{min = [0.46, 0.0], max = [0.54, 1.0], velocity = [1.0, 0.0]}]' \
  >/dev/null 2>"$work/err" || fail "a warning stopped the run"
grep -qE "^warning: .*initial_velocity\[0\].min: the box holds no particle" "$work/err" || fail "no warning for an empty box: $(cat "$work/err")"
"$mpm" run "$disks" --out "$work/w2" "${short[@]}" --set 'initial_velocity=[{min = [0.2, 0.2], max = [0.3, 0.3], velocity = [1.0, 0.0]}]' \
  >/dev/null 2>"$work/err" || fail "a run with a velocity box"
grep -q "holds no particle" "$work/err" && fail "a warning for a box that holds particles"

echo "cli_bodies: $failures failed"
[[ $failures -eq 0 ]]
