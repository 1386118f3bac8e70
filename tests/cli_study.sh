#!/usr/bin/env bash
# `mpm study` on a tiny study of the Dyka bar (6 cases, a fraction of a second each): study.csv's rows with each
# score's band and ending, a case the scene refuses (the predictor-corrector with a stress update last: ending
# stopped), a fitted order with its standard error and band, the pictures, only the written files' names on stdout;
# a stopped case; a constant exact history (no score fails against it); and bad study files: exit 2, `error: FILE:LINE: KEY: why`,
# nothing written. Usage: cli_study.sh MPM
set -u
mpm=$1
scenes=$(cd "$(dirname "$0")/.." && pwd)/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# field FILE ROW COLUMN_NAME: the value of a named column on data row ROW, the fields read as RFC 4180 quotes them
# (why may hold commas and quotes, and columns follow it)
field() {
  awk -v row="$2" -v name="$3" '
    function fields(line, out,   n, i, ch, quoted, f) {
      n = 0; f = ""; quoted = 0
      for (i = 1; i <= length(line); i++) {
        ch = substr(line, i, 1)
        if (quoted) { if (ch != "\"") f = f ch; else if (substr(line, i + 1, 1) == "\"") { f = f ch; i++ } else quoted = 0 }
        else if (ch == "\"") quoted = 1
        else if (ch == ",") { out[++n] = f; f = "" }
        else f = f ch
      }
      out[++n] = f
      return n
    }
    NR == 1 { n = fields($0, head); for (i = 1; i <= n; i++) if (head[i] == name) c = i }
    NR == row + 1 { fields($0, cell); print cell[c] }' "$1"
}
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
[[ $(head -1 "$csv") == "case,grid.cells,solver.stress_update,status,rms_at_t,rms_at_integrator_time,energy_drift,steps,wall_s,cpu_s,why,rms_at_t_band,rms_at_integrator_time_band,ending_at_t,ending_at_integrator_time" ]] ||
  fail "study.csv header: $(head -1 "$csv")"
[[ $(wc -l <"$csv") -eq 7 ]] || fail "study.csv: $(wc -l <"$csv") lines, want 7"
for row in 1 3 5; do  # usf: done, scored at t and at the integrator's time (Eq. 32: the same time), timed
  [[ $(field "$csv" $row status) == done ]] || fail "case $row: $(sed -n "$((row + 1))p" "$csv")"
  for column in rms_at_t rms_at_integrator_time energy_drift steps wall_s cpu_s rms_at_t_band rms_at_integrator_time_band; do
    number "$(field "$csv" $row $column)" || fail "case $row: $column is '$(field "$csv" $row $column)'"
  done
  for column in ending_at_t ending_at_integrator_time; do  # a whole run that beats a flat line at the exact mean
    [[ $(field "$csv" $row $column) == done ]] || fail "case $row: $column is '$(field "$csv" $row $column)', want done"
  done
  awk -v b="$(field "$csv" $row rms_at_t_band)" -v s="$(field "$csv" $row rms_at_t)" 'BEGIN { exit !(b >= 0 && b < s) }' ||
    fail "case $row: the band of its sampling $(field "$csv" $row rms_at_t_band) is not in [0, its score)"
  [[ $(field "$csv" $row rms_at_t) == "$(field "$csv" $row rms_at_integrator_time)" ]] || fail "Eq. (32)'s velocity belongs to t: no shift"
  [[ -s "$work/out/cases/000$((row - 1))/observers_shifted.csv" ]] || fail "case $row: no observers_shifted.csv"
done
for row in 2 4 6; do  # usl with the predictor-corrector: the scene refuses it; a row, not an error, and no folder
  [[ $(field "$csv" $row status) == refused ]] || fail "case $row is not refused: $(sed -n "$((row + 1))p" "$csv")"
  sed -n "$((row + 1))p" "$csv" | grep -q 'solver.stress_update: the predictor-corrector updates stress first' || fail "case $row: why"
  [[ $(field "$csv" $row ending_at_t),$(field "$csv" $row ending_at_integrator_time) == stopped,stopped ]] ||
    fail "case $row refused: its endings are not stopped: $(sed -n "$((row + 1))p" "$csv")"
  [[ -z $(field "$csv" $row rms_at_t_band) ]] || fail "case $row refused: a band without a score"
  [[ ! -e "$work/out/cases/000$((row - 1))" ]] || fail "a refused case has a folder"
done
fits=$work/out/fits.csv
[[ $(head -1 "$fits") == "solver.stress_update,score,p,p_stderr,C,points,why,p_band,failed" ]] || fail "fits.csv header: $(head -1 "$fits")"
row=$(grep -n '^usf,rms_at_t,' "$fits" | cut -d: -f1)
[[ -n $row ]] && number "$(field "$fits" $((row - 1)) p)" && number "$(field "$fits" $((row - 1)) p_stderr)" ||
  fail "no order fitted for usf: $(cat "$fits")"
[[ -n $row ]] && awk -v b="$(field "$fits" $((row - 1)) p_band)" -v e="$(field "$fits" $((row - 1)) p_stderr)" \
  'BEGIN { d = b - 2 * e; exit !(b > 0 && d * d < 1e-20) }' || fail "usf's p_band is not 2 p_stderr: $(cat "$fits")"
[[ -n $row && $(field "$fits" $((row - 1)) failed) == 0 ]] || fail "usf: a failed case counted: $(cat "$fits")"
grep -q '^usl,rms_at_t,,,,0,0 finite points; a fit needs 3 at least,,0$' "$fits" || fail "usl's row without p: $(cat "$fits")"
# Again into the same folder: the earlier study's files replaced, the same rows
"$mpm" study "$work/tiny.toml" --out "$work/out" --jobs 1 >/dev/null 2>&1 || fail "a second study into the same folder"
[[ $(wc -l <"$csv") -eq 7 ]] || fail "second study.csv: $(wc -l <"$csv") lines"

# dyka_study FILE END_TIME AXIS: a study of the Dyka bar to END_TIME without snapshots along the one axis AXIS
dyka_study() {
  printf 'scene = "%s"\n[set]\nsolver.end_time = %s\noutput.snapshots = []\n[axes]\n%s\n' "$scenes/dyka_bar.toml" "$2" "$3" >"$1"
}
# A case stopped by energy growth (forward Euler beyond its CFL limit 2): its own outcome with why, no score
dyka_study "$work/unstable.toml" 2.0e-5 "solver.cfl = [2.5]"
"$mpm" study "$work/unstable.toml" --out "$work/unstable" >/dev/null 2>"$work/stderr" || fail "unstable study: $(cat "$work/stderr")"
row=$(sed -n 2p "$work/unstable/study.csv")
[[ $row == 0,2.5,stopped,,,[0-9]*,unstable:\ energy\ grew\ to* ]] || fail "a stopped case: $row"
[[ $(field "$work/unstable/study.csv" 1 ending_at_t) == stopped ]] || fail "a stopped case's ending: $row"

# A constant exact history: before the unloading wave reaches the observer near the free end (c t < L/4 = 6.6 us),
# the exact velocity there is v0 at every sample, a flat line at its mean scores 0, and the failed-score rule does not
# apply (mpm::score_ending: the flat line is the exact history itself): every case done, its RMS a point of the fit
# (the rule's failed branch in a fit: the doctests of mpm/study/fits.hpp).
dyka_study "$work/early.toml" 2.0e-6 "grid.cells = [[10], [20], [40]]"
"$mpm" study "$work/early.toml" --out "$work/early" --jobs 2 >"$work/stdout" 2>"$work/stderr" || fail "early study: $(cat "$work/stderr")"
for row in 1 2 3; do
  [[ $(field "$work/early/study.csv" $row status),$(field "$work/early/study.csv" $row ending_at_t) == done,done ]] ||
    fail "early case $row: want done, done: $(sed -n "$((row + 1))p" "$work/early/study.csv")"
done
grep -q '^rms_at_t,[0-9.]*,[0-9.]*,[0-9.]*,3,,[0-9.]*,0$' "$work/early/fits.csv" ||
  fail "a constant exact history's fit: $(cat "$work/early/fits.csv")"

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
