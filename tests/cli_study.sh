#!/usr/bin/env bash
# `mpm study` on a tiny study of the Dyka bar (6 cases, a fraction of a second each): study.csv's rows, a case the
# scene refuses (the predictor-corrector with a stress update last), a fitted order with its standard error, the
# pictures, only the written files' names on stdout; and bad study files: exit 2, `error: FILE:LINE: KEY: why`,
# nothing written. Usage: cli_study.sh MPM
set -u
mpm=$1
scenes=$(cd "$(dirname "$0")/.." && pwd)/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# field FILE ROW COLUMN_NAME: the value of a named column on data row ROW (why, the last column, may hold commas)
field() { awk -F, -v row="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i } NR == row + 1 { print $c }' "$1"; }
number() { [[ $1 =~ ^-?[0-9.]+(e[-+]?[0-9]+)?$ ]]; }

cat >"$work/tiny.toml" <<TOML
scene = "$scenes/dyka_bar.toml"
[set]
solver.end_time = 2.0e-5
solver.integrator = "npc"
output.snapshots = []
[axes]
grid.cells = [[10], [20], [40]]
solver.stress_update = ["usf", "usl"]
TOML
"$mpm" study "$work/tiny.toml" --out "$work/out" --jobs 2 >"$work/stdout" 2>"$work/stderr"
code=$?
[[ $code -eq 0 ]] || fail "mpm study exit $code: $(cat "$work/stderr")"
grep -q "^case 6/6 done, 0 running, 3 refused, 0 stopped, 0 failed$" "$work/stderr" || fail "progress: $(tail -2 "$work/stderr")"
for name in study.csv fits.csv study.gp error.png cost.png; do
  grep -qx "$work/out/$name" "$work/stdout" || fail "stdout does not name $name: $(cat "$work/stdout")"
  [[ -s "$work/out/$name" ]] || fail "$name not written"
done
[[ $(wc -l <"$work/stdout") -eq 5 ]] || fail "stdout holds more than the written files' names: $(cat "$work/stdout")"
csv=$work/out/study.csv
[[ $(head -1 "$csv") == "case,grid.cells,solver.stress_update,status,rms_at_t,rms_at_integrator_time,energy_drift,steps,wall_s,cpu_s,why" ]] ||
  fail "study.csv header: $(head -1 "$csv")"
[[ $(wc -l <"$csv") -eq 7 ]] || fail "study.csv: $(wc -l <"$csv") lines, want 7"
for row in 1 3 5; do  # usf: done, scored at t and at the integrator's time (Eq. 32: the same time), timed
  [[ $(field "$csv" $row status) == done ]] || fail "case $row: $(sed -n "$((row + 1))p" "$csv")"
  for column in rms_at_t rms_at_integrator_time energy_drift steps wall_s cpu_s; do
    number "$(field "$csv" $row $column)" || fail "case $row: $column is '$(field "$csv" $row $column)'"
  done
  [[ $(field "$csv" $row rms_at_t) == "$(field "$csv" $row rms_at_integrator_time)" ]] || fail "Eq. (32)'s velocity belongs to t: no shift"
  [[ -s "$work/out/cases/000$((row - 1))/observers_shifted.csv" ]] || fail "case $row: no observers_shifted.csv"
done
for row in 2 4 6; do  # usl with the predictor-corrector: the scene refuses it; a row, not an error, and no folder
  [[ $(field "$csv" $row status) == refused ]] || fail "case $row is not refused: $(sed -n "$((row + 1))p" "$csv")"
  sed -n "$((row + 1))p" "$csv" | grep -q 'solver.stress_update: the predictor-corrector updates stress first' || fail "case $row: why"
  [[ ! -e "$work/out/cases/000$((row - 1))" ]] || fail "a refused case has a folder"
done
fits=$work/out/fits.csv
[[ $(head -1 "$fits") == "solver.stress_update,score,p,p_stderr,C,points,why" ]] || fail "fits.csv header: $(head -1 "$fits")"
row=$(grep -n '^usf,rms_at_t,' "$fits" | cut -d: -f1)
[[ -n $row ]] && number "$(field "$fits" $((row - 1)) p)" && number "$(field "$fits" $((row - 1)) p_stderr)" ||
  fail "no order fitted for usf: $(cat "$fits")"
grep -q '^usl,rms_at_t,,,,0,0 finite points; a fit needs 3 at least$' "$fits" || fail "usl's row without p: $(cat "$fits")"
# Again into the same folder: the earlier study's files replaced, the same rows
"$mpm" study "$work/tiny.toml" --out "$work/out" --jobs 1 >/dev/null 2>&1 || fail "a second study into the same folder"
[[ $(wc -l <"$csv") -eq 7 ]] || fail "second study.csv: $(wc -l <"$csv") lines"

# A case stopped by energy growth (forward Euler beyond its CFL limit 2): its own outcome with why, no score
cat >"$work/unstable.toml" <<TOML
scene = "$scenes/dyka_bar.toml"
[set]
solver.end_time = 2.0e-5
output.snapshots = []
[axes]
solver.cfl = [2.5]
TOML
"$mpm" study "$work/unstable.toml" --out "$work/unstable" >/dev/null 2>"$work/stderr" || fail "unstable study: $(cat "$work/stderr")"
row=$(sed -n 2p "$work/unstable/study.csv")
[[ $row == 0,2.5,stopped,,,[0-9]*,unstable:\ energy\ grew\ to* ]] || fail "a stopped case: $row"

# Bad study files: exit 2, one line naming FILE:LINE: KEY, nothing on stdout, nothing written
bad() {  # bad PATTERN STUDY_TEXT
  printf '%s\n' "$2" >"$work/bad.toml"
  "$mpm" study "$work/bad.toml" --out "$work/never" >"$work/out.txt" 2>"$work/err.txt"
  local got=$?
  if [[ $got -ne 2 ]] || ! grep -qE "$1" "$work/err.txt" || [[ -s "$work/out.txt" ]] || [[ -e "$work/never" ]]; then
    fail "bad study ($2) -> exit $got, stderr: $(cat "$work/err.txt")"
  fi
}
bad "^error: $work/bad.toml:3: solver.cfll: not a scene key" "scene = \"$scenes/dyka_bar.toml\"
[axes]
solver.cfll = [0.5]"
bad "^error: $work/bad.toml:2: bogus: unknown key" "scene = \"$scenes/dyka_bar.toml\"
bogus = 1
[axes]
solver.cfl = [0.5]"
bad "^error: $work/bad.toml:3: solver.cfl: must be" "scene = \"$scenes/dyka_bar.toml\"
[set]
solver.cfl = -1.0
[axes]
grid.cells = [[10]]"
bad "^error: $work/bad.toml:2: observer: no \[\[observer\]\] 'B' in the scene \(A\)" "scene = \"$scenes/dyka_bar.toml\"
observer = \"B\"
[axes]
grid.cells = [[10]]"
bad "^error: $work/bad.toml:1: scene: required" "[axes]
grid.cells = [[10]]"
bad "^error: $work/nowhere.toml: " "scene = \"nowhere.toml\"
[axes]
grid.cells = [[10]]"

if [[ $failures -gt 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "mpm study: every check passed"
