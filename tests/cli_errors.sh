#!/usr/bin/env bash
# The CLI's contract on errors (issue 2, item 9):
#   a bad scene or option: one line `error: FILE:LINE: KEY: ...`, exit code 2, no output folder;
#   a run that fails: one line with step, time, particle, position and cause, exit code 3,
#   keeping what was written so far.
set -u
mpm=$1
scene=$(cd "$(dirname "$0")/.." && pwd)/scenes/dyka_bar.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
expect() {  # expect CODE PATTERN -- ARGS...
  local code=$1 pattern=$2; shift 3
  "$mpm" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [[ $got -ne $code ]] || ! grep -qE "$pattern" "$work/err"; then
    echo "FAIL: mpm $* -> exit $got (want $code), stderr: $(cat "$work/err")"
    failures=$((failures + 1))
  fi
}

expect 2 "^error: --set\(1\):1: solver.cfl: must be > 0" -- run "$scene" --out "$work/a" --set solver.cfl=-1
[[ -e "$work/a" ]] && { echo "FAIL: an output folder was made for a bad scene"; failures=$((failures + 1)); }
expect 2 "^error: --set\(1\):1: solver.shape: 'cubic' is not allowed" -- run "$scene" --out "$work/a" --set 'solver.shape="cubic"'
expect 2 "^error: --set\(1\):1: grid.cells: has 2 entries; the scene's dimension needs 1" -- run "$scene" --out "$work/a" --set grid.cells=[40,2]
sed 's/^cfl = 0.5/cfl = 0.0/' "$scene" >"$work/zero_cfl.toml"
line=$(grep -n '^cfl = 0.0' "$work/zero_cfl.toml" | cut -d: -f1)
expect 2 "^error: $work/zero_cfl.toml:$line: solver.cfl: must be > 0" -- run "$work/zero_cfl.toml" --out "$work/a"
expect 2 "^error: $work/missing.toml:0: \(file\)" -- run "$work/missing.toml"
printf '[grid\n' >"$work/broken.toml"
expect 2 "^error: $work/broken.toml:1: \(syntax\)" -- run "$work/broken.toml"
expect 2 "^error: --frobnicate: unknown option" -- run "$scene" --frobnicate
[[ -e "$work/a" ]] && { echo "FAIL: an output folder was made for a bad scene"; failures=$((failures + 1)); }

# A particle driven off the grid (no margin beyond the free end, 5 km/s outwards).
expect 3 "^failure: step [0-9]+, t = .* s, particle [0-9]+ at \(.*\): particle left the grid" -- \
  run "$scene" --out "$work/b" --set grid.margin_min=[0] --set 'initial_velocity[0].velocity=[-5000.0]'
[[ -s "$work/b/observers.csv" && -s "$work/b/run.json" ]] || { echo "FAIL: a failed run must keep what it wrote"; failures=$((failures + 1)); }
grep -q '"status": "failed' "$work/b/run.json" || { echo "FAIL: run.json of a failed run must say so"; failures=$((failures + 1)); }
# An explicit scheme far beyond its stability limit.
expect 3 "^failure: step [0-9]+, t = .* s: unstable: energy grew" -- run "$scene" --out "$work/c" --set solver.cfl=3.0

echo "cli_errors: $failures failed"
[[ $failures -eq 0 ]]
