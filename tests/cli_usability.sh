#!/usr/bin/env bash
# What a user sees besides errors:
#   help: `mpm --help`, `mpm run|shape|plot --help` print usage, the scene keys with defaults and units, and
#     the exit codes; `mpm run --print-scene` prints the resolved scene and runs nothing;
#   seeing a run: run.json holds the resolved scene, snapshots.pvd lists every snapshot with its time,
#     `mpm plot` draws observers.png and energy.png (with exact.csv), and fails with 2 or 3 and a message;
#   warnings: `warning: FILE:LINE: KEY: ...` on stderr for a suspicious scene, never stopping the run.
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
scene=$root/scenes/dyka_bar.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect CODE -- ARGS...: runs mpm, stdout in $work/out, stderr in $work/err
expect() {
  local code=$1; shift 2
  "$mpm" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  [[ $got -eq $code ]] || fail "mpm $* -> exit $got (want $code), stderr: $(head -c 600 "$work/err")"
}

# --- help -----------------------------------------------------------------------------------------
for command in "--help" "run --help" "shape --help" "plot --help" "help run"; do
  # shellcheck disable=SC2086
  expect 0 -- $command
  grep -q "^Exit codes:" "$work/out" || fail "mpm $command: no exit codes"
  grep -qi "^usage: mpm" "$work/out" || fail "mpm $command: no usage"
done
expect 0 -- run "$scene" --help
grep -qE "^  solver\.cfl +0\.5 +- " "$work/out" || fail "mpm run --help: no solver.cfl with its default 0.5"
grep -qE "^  grid\.length +required +m " "$work/out" || fail "mpm run --help: grid.length must be required, in m"
grep -qE "^  exact +\"none\" " "$work/out" || fail "mpm run --help: no exact key"

# --- --print-scene --------------------------------------------------------------------------------
expect 0 -- run "$scene" --print-scene --out "$work/never" --set solver.cfl=0.25
[[ -e "$work/never" ]] && fail "--print-scene must not run or write anything"
grep -q '^cfl = 0.25$' "$work/out" || fail "--print-scene: the override is not in the resolved scene"
grep -q '^courant = "max"$' "$work/out" || fail "--print-scene: a default (solver.courant) is missing"
cp "$work/out" "$work/resolved.toml"
expect 0 -- run "$work/resolved.toml" --print-scene
diff <(tail -n +2 "$work/resolved.toml") <(tail -n +2 "$work/out") >/dev/null ||
  fail "the printed scene, read back and printed again, differs"

# --- a run: run.json, snapshots.pvd, exact.csv, mpm plot ------------------------------------------
expect 0 -- run "$scene" --out "$work/bar"  # the scene sets exact = "dyka_bar" itself
grep -q '"courant" : "max"' "$work/bar/run.json" || fail "run.json: the resolved scene lacks its defaults"
grep -q '"exact" : "dyka_bar"' "$work/bar/run.json" || fail "run.json: the resolved scene lacks the exact key"
# The version (git at build time), the command line and the units, in valid JSON
version=$("$mpm" --version) || fail "mpm --version failed"
[[ $version =~ ^mpm\ [0-9]+\.[0-9]+\.[0-9]+\+(git\.[0-9a-f]+(-dirty)?|unknown)$ ]] || fail "mpm --version printed '$version'"
python3 - "$work/bar/run.json" "${version#mpm }" "$scene" "$work/bar" <<'PY' || fail "run.json: version, command line or units"
import json, sys
run = json.load(open(sys.argv[1]))
assert run["version"] == sys.argv[2], run["version"]
assert run["command_line"][1:] == ["run", sys.argv[3], "--out", sys.argv[4]], run["command_line"]
assert all(name in run["units"] for name in run if name not in ("scene", "units", "scene_units", "column_units")), run["units"]
assert run["units"]["final_time"] == "s" and run["scene_units"]["material.density"] == "kg/m^3"
assert run["column_units"]["observers.csv:NAME.v_x"] == "m/s" and run["column_units"]["energy.csv:kinetic"] == "J/m^2"
PY
# snapshots.pvd: one DataSet per snapshot time of the scene, each file there, with the particles.
pvd=$work/bar/snapshots.pvd
[[ -s $pvd ]] || fail "no snapshots.pvd"
grep -q '<VTKFile type="Collection"' "$pvd" || fail "snapshots.pvd is not a VTK collection"
times=(0.0 2.0e-4)  # output.snapshots of scenes/dyka_bar.toml
count=0
while IFS= read -r line; do
  timestep=$(sed -E 's/.*timestep="([^"]*)".*/\1/' <<<"$line")
  file=$(sed -E 's/.*file="([^"]*)".*/\1/' <<<"$line")
  awk -v a="$timestep" -v b="${times[$count]:-nan}" 'BEGIN{exit !((a - b) <= 1e-12 * (b > 0 ? b : 1) && (b - a) <= 1e-12 * (b > 0 ? b : 1))}' ||
    fail "snapshots.pvd: DataSet $count at t = $timestep, the scene's snapshot is ${times[$count]:-none}"
  [[ -s "$work/bar/$file" ]] || fail "snapshots.pvd lists $file, which does not exist"
  grep -q 'NumberOfPoints="40"' "$work/bar/$file" || fail "$file: not the 40 particles"
  count=$((count + 1))
done < <(grep '<DataSet ' "$pvd")
[[ $count -eq ${#times[@]} ]] || fail "snapshots.pvd has $count DataSets, want ${#times[@]}"
# exact.csv: the appendix's bar at the free-end particle; it starts at -5 m/s, unstressed.
[[ "$(head -1 "$work/bar/exact.csv")" == "t,A.v_x,A.sigma_xx" ]] || fail "exact.csv: wrong header"
[[ "$(sed -n 2p "$work/bar/exact.csv")" == "0,-5,0" ]] || fail "exact.csv: first row $(sed -n 2p "$work/bar/exact.csv")"
[[ $(wc -l <"$work/bar/exact.csv") -eq $(wc -l <"$work/bar/observers.csv") ]] || fail "exact.csv: not one row per sample"
expect 0 -- plot "$work/bar"
for picture in observers.png energy.png; do
  [[ -s "$work/bar/$picture" ]] || fail "mpm plot wrote no $picture"
  [[ "$(head -c 4 "$work/bar/$picture" | tail -c 3)" == "PNG" ]] || fail "$picture is not a PNG"
done
grep -q "'exact.csv' using 1:2" "$work/bar/plot.gp" || fail "the plot does not draw the exact velocity"
# and a 2D run without an exact solution
expect 0 -- run "$root/scenes/soil_block.toml" --out "$work/block" --set solver.end_time=1.0 --set output.snapshots=[1.0] \
  --set 'exact="soil_column"'
[[ "$(head -2 "$work/block/exact.csv" | tr '\n' ' ')" == "t,top.u_y,top.sigma_yy 0,0,0 " ]] ||
  fail "2D exact.csv starts with $(head -2 "$work/block/exact.csv" | tr '\n' ' ')"
# observers.csv ends with each observer's displacement since t = 0, which exact.csv's u_y sits beside in the plot
[[ "$(head -1 "$work/block/observers.csv")" == *",top.sigma_xy,top.u_x,top.u_y" ]] || fail "observers.csv header: $(head -1 "$work/block/observers.csv")"
awk -F, 'NR > 1 && ($10 != $3 - 9.5 && ($10 - ($3 - 9.5)) ^ 2 > 1e-20) { bad = 1 } END { exit bad }' "$work/block/observers.csv" ||
  fail "observers.csv: top.u_y is not y - Y"
expect 0 -- plot "$work/block"
grep -q "'exact.csv' using 1:2 " "$work/block/plot.gp" || fail "the 2D plot does not draw the exact settlement"
[[ -s "$work/block/observers.png" && -s "$work/block/energy.png" ]] || fail "mpm plot of a 2D run wrote no PNG"
grep -q 'timestep="1"' "$work/block/snapshots.pvd" || fail "2D snapshots.pvd lacks t = 1"
grep -q "'exact.csv' using 1:2" "$work/block/plot.gp" || fail "the 2D plot does not draw the exact settlement"
# failures
expect 2 -- plot "$work/nothing"
grep -q "^error: $work/nothing: no such folder" "$work/err" || fail "plot of a missing folder: $(cat "$work/err")"
mkdir "$work/empty"
expect 2 -- plot "$work/empty"
grep -q "^error: $work/empty: holds neither observers.csv nor energy.csv" "$work/err" || fail "plot without CSVs: $(cat "$work/err")"
# a folder of observers alone (another code's, say): observers.png, no energy.csv needed
mkdir "$work/observers_only"
printf 't,A.v_x\n0,1\n1,2\n' >"$work/observers_only/observers.csv"
expect 0 -- plot "$work/observers_only"
[[ -s "$work/observers_only/observers.png" && ! -e "$work/observers_only/energy.png" ]] || fail "plot of observers alone"
expect 2 -- plot
PATH=/nonexistent expect 3 -- plot "$work/bar"
grep -q "^error: $work/bar/observers.png: cannot write: gnuplot failed" "$work/err" || fail "plot without gnuplot: $(cat "$work/err")"
# an exact solution the scene cannot have
expect 2 -- run "$scene" --out "$work/never" --set 'exact="soil_column"'
grep -q "^error: --set(1):1: exact: 'soil_column' is the 2D column" "$work/err" || fail "exact check: $(cat "$work/err")"

# --- warnings: each at its key, and the run goes on (exit 0) --------------------------------------
short=(--set solver.end_time=3e-6 --set output.snapshots=[])
warns() {  # warns PATTERN -- ARGS...: exit 0, and the warning on stderr
  local pattern=$1; shift 2
  expect 0 -- "$@"
  grep -qE "$pattern" "$work/err" || fail "mpm $* -> no warning /$pattern/; stderr: $(cat "$work/err")"
  [[ -s "$work/w/observers.csv" ]] || fail "mpm $*: a warning must not stop the run"
  rm -rf "$work/w"
}
warns "^warning: --set\(1\):1: solver\.cfl: 2\.1 is above the stability limit 2\.000 of linear shapes with forward Euler, from the method.s own linearised step" -- \
  run "$scene" --out "$work/w" --set solver.cfl=2.1 "${short[@]}"
warns "^warning: --set\(1\):1: observer\[0\]\.position: lies outside every \[\[body\]\]" -- \
  run "$scene" --out "$work/w" --set 'observer[0].position=[-0.01]' --set 'exact="none"' "${short[@]}"  # with exact: an error
warns "^warning: --set\(2\):1: grid\.margin_max: LME next to rigid margin nodes behind the fixed face xmax" -- \
  run "$scene" --out "$work/w" --set 'solver.shape="lme"' --set grid.margin_max=[1] "${short[@]}"
# The shipped scenes, and their documented variants, warn of nothing.
for shipped in "$root"/scenes/*.toml; do
  expect 0 -- run "$shipped" --print-scene
  [[ -s "$work/err" ]] && fail "$shipped warns: $(cat "$work/err")"
done
# uGIMP at the fixed wall, with or without a margin cell: clipped at the grid's edge, nothing to warn of.
expect 0 -- run "$scene" --print-scene --set 'solver.shape="ugimp"'
[[ -s "$work/err" ]] && fail "the uGIMP Dyka bar warns: $(cat "$work/err")"
expect 0 -- run "$scene" --print-scene --set 'solver.shape="ugimp"' --set grid.margin_max=[1]
[[ -s "$work/err" ]] && fail "the uGIMP Dyka bar with a margin cell warns: $(cat "$work/err")"

echo "cli_usability: $failures failed"
[[ $failures -eq 0 ]]
