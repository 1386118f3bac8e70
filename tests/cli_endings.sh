#!/usr/bin/env bash
# Runs that end and folders that stay honest (issue 49), one regression test per defect found:
#   - work bombs: a velocity of 1e300 by a constant, 1e9 by a formula, 80,000 output times: refused (exit 2) from the
#     particles' own speeds and the landings, with --force too where time could not advance; a run whose steps outgrow
#     its estimate fails at --max-steps (exit 3, `failure: step N, t = T s: ...`);
#   - signals: SIGHUP (and SIGUSR1) end a run as "interrupted" with every CSV whole; SIGTERM while an earlier run's
#     files are removed leaves run.json "interrupted", never the old "done";
#   - studies: SIGTERM is forwarded to the runs and waited for (no orphan; study.csv not written); SIGKILL takes the
#     runs with it (PR_SET_PDEATHSIG); a link or a file at cases/0000 is refused before anything is written; a stale
#     observers_shifted.csv never survives; each run has its --max-memory;
#   - a study over a live run's case folder is refused; a stop signal at the study's start reaches its runs; a run's
#     folder swapped for a link ends with exit 3 and run.json where the run began; a soft material's long first
#     Courant step is no reference for a collapse (the referee's findings);
#   - names: a scene or study named `...toml` or `..toml`, or whose runs/NAME leads to the current folder, has no
#     default folder (exit 2, nothing written);
#   - mpm plot takes the folder's lock before it reads.
# Usage: cli_endings.sh MPM
set -u
mpm=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
status_of() { sed -n 's/^  "status": "\([a-z]*\)",$/\1/p' "$1" 2>/dev/null; }
# The processes whose command line mentions $1 (procps may be missing: /proc is read directly).
processes_naming() {
  local file
  for file in /proc/[0-9]*/cmdline; do
    { tr '\0' ' ' <"$file"; } 2>/dev/null | grep -qF -- "$1" && echo "${file//[^0-9]/}"
  done
}

# 1. Work bombs.
timeout -s KILL 20 "$mpm" run "$root/scenes/vibrating_bar.toml" --set constants.amplitude_ratio=1e300 --out "$work/a" \
  2>"$work/err"
code=$?
[[ $code -eq 2 ]] || fail "amplitude_ratio = 1e300: exit $code, want 2 (the loop would take ~1e300 steps)"
grep -q "solver.end_time: end_time / dt = .* no run can take that many steps" "$work/err" || fail "1e300: $(cat "$work/err")"
timeout -s KILL 20 "$mpm" run "$root/scenes/vibrating_bar.toml" --set constants.amplitude_ratio=1e300 --force --out "$work/a" \
  2>/dev/null
[[ $? -eq 2 && ! -e $work/a ]] || fail "amplitude_ratio = 1e300 --force: not refused"
walls() {  # walls VELOCITY EXTRA: a 1D bar held at both ends, its particles' velocity set by a formula
  printf '%s\n' "dimension = 1" "[grid]" "length = [1.0]" "cells = [10]" "[material]" "young_modulus = 100.0" \
    "density = 1.0" "[[body]]" "min = [0.0]" "max = [1.0]" "[[fixed]]" 'face = "xmin"' 'components = ["x"]' \
    "[[fixed]]" 'face = "xmax"' 'components = ["x"]' "[initial_field]" "velocity = [\"$1\"]" "[solver]" \
    "end_time = 1.0" "$2"
}
walls 1e9 "" >"$work/walls.toml"
timeout -s KILL 20 "$mpm" run "$work/walls.toml" --max-steps 1000 --out "$work/b" 2>"$work/err"
code=$?
[[ $code -eq 2 && ! -e $work/b ]] || fail "a formula velocity of 1e9 m/s: exit $code, want 2 with nothing written"
grep -q "^error: .*walls.toml:20: solver.end_time: end_time / dt = 1 s / 5e-11 s = 2e+10 time steps" "$work/err" ||
  fail "the estimate ignores the formula's velocity: $(cat "$work/err")"
times=$(seq -s ', ' 1 80000 | awk '{ gsub(/[0-9]+/, "&e-6"); print }')
walls 0.0 "[output]
times = [$times]" >"$work/times.toml"
timeout -s KILL 20 "$mpm" run "$work/times.toml" --max-steps 1000 --set solver.end_time=0.09 --out "$work/c" 2>"$work/err"
code=$?
[[ $code -eq 2 && ! -e $work/c ]] || fail "80,000 output times under --max-steps 1000: exit $code, want 2"
grep -q "= 18 time steps and 80000 landings on output times" "$work/err" || fail "landings not counted: $(cat "$work/err")"
# a particle falling through a slow material: C = |v| grows, dt shrinks; 4 steps at t = 0, 9 to the end
cat >"$work/fall.toml" <<'TOML'
dimension = 2
[grid]
length = [4.0, 10.0]
cells = [4, 10]
[material]
young_modulus = 1.0
density = 1.0
[[body]]
min = [1.0, 8.0]
max = [2.0, 9.0]
velocity = [0.0, -2.0]
[gravity]
acceleration = [0.0, -9.81]
[solver]
end_time = 1.0
TOML
timeout -s KILL 20 "$mpm" run "$work/fall.toml" --max-steps 4 --out "$work/d" >"$work/out" 2>"$work/err"
code=$?
[[ $code -eq 3 ]] || fail "a run past --max-steps 4: exit $code, want 3"
grep -q "^failure: step 4, t = .* s: the run reached its limit of 4 steps before end_time = 1 s" "$work/err" ||
  fail "--max-steps not counted during the run: $(cat "$work/err")"
[[ $(status_of "$work/d/run.json") == failed ]] || fail "--max-steps: run.json $(status_of "$work/d/run.json")"
grep -q wrote "$work/out" && fail "--max-steps: stdout says wrote"
"$mpm" run "$work/fall.toml" --max-steps 4 --force --out "$work/d" >/dev/null 2>&1 || fail "--force does not lift the limit"

# 2. Signals during a run: a 1D bar of 4000 cells, a few seconds (longer under a sanitizer).
long_run=(run "$root/scenes/dyka_bar.toml" --set 'grid.cells=[4000]' --set solver.end_time=2e-3 --set 'output.snapshots=[]')
for signal in HUP USR1; do
  "$mpm" "${long_run[@]}" --out "$work/e" >/dev/null 2>"$work/err" &
  pid=$!
  for _ in $(seq 100); do [[ $(status_of "$work/e/run.json") == running ]] && break; sleep 0.05; done
  sleep 0.3
  kill -s $signal $pid
  wait $pid
  code=$?
  number=$(kill -l $signal)
  [[ $code -eq $((128 + number)) ]] || fail "SIG$signal: exit $code, want $((128 + number))"
  [[ $(status_of "$work/e/run.json") == interrupted ]] || fail "SIG$signal: run.json says $(status_of "$work/e/run.json")"
  grep -q "^interrupted: SIG$signal at t = " "$work/err" || fail "SIG$signal: $(cat "$work/err")"
  for csv in "$work"/e/*.csv; do
    [[ $(tail -c 1 "$csv" | od -An -c | tr -d ' ') == '\n' ]] || fail "SIG$signal: $csv cut mid-line"
  done
done
# an earlier run's 30,000 files and its run.json "done": SIGTERM while they are removed
mkdir -p "$work/f"
(cd "$work/f" && seq -f 'snapshot_%04g.csv' 0 9999 | xargs touch && seq -f 'snapshot_%04g.vtp' 0 9999 | xargs touch &&
  seq -f 'exact_%04g.csv' 0 9999 | xargs touch)
printf '{\n  "status": "done",\n}\n' >"$work/f/run.json"
"$mpm" "${long_run[@]}" --out "$work/f" >/dev/null 2>"$work/err" &
pid=$!
for _ in $(seq 200); do [[ $(status_of "$work/f/run.json") != done ]] && break; sleep 0.01; done
kill -s TERM $pid
wait $pid
code=$?
state=$(status_of "$work/f/run.json")
[[ $code -eq 143 && $state == interrupted ]] || fail "SIGTERM while clearing: exit $code, run.json $state"
grep -q "^interrupted: SIGTERM" "$work/err" || fail "SIGTERM while clearing: no message: $(cat "$work/err")"

# 3. Studies.
cat >"$work/study.toml" <<TOML
scene = "$root/scenes/dyka_bar.toml"
[set]
solver.end_time = 2.0e-2
output.snapshots = []
[axes]
grid.cells = [[2000], [2001], [2002], [2003]]
TOML
"$mpm" study "$work/study.toml" --out "$work/s" --jobs 2 >/dev/null 2>"$work/err" &
pid=$!
for _ in $(seq 200); do [[ $(status_of "$work/s/cases/0000/run.json") == running ]] && break; sleep 0.05; done
sleep 0.3
kill -s TERM $pid
wait $pid
code=$?
[[ $code -eq 143 ]] || fail "SIGTERM to mpm study: exit $code, want 143"
grep -q "^interrupted: SIGTERM; " "$work/err" || fail "SIGTERM to mpm study: $(tail -2 "$work/err")"
[[ -z $(processes_naming "$work/s") ]] || fail "mpm study left its runs behind: $(processes_naming "$work/s")"
[[ ! -e $work/s/study.csv ]] || fail "an interrupted study wrote study.csv"
for json in "$work"/s/cases/*/run.json; do
  [[ $(status_of "$json") =~ ^(interrupted|done)$ ]] || fail "$json says $(status_of "$json") after the study ended"
done
"$mpm" study "$work/study.toml" --out "$work/k" --jobs 2 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do [[ $(status_of "$work/k/cases/0000/run.json") == running ]] && break; sleep 0.05; done
kill -s KILL $pid
wait $pid 2>/dev/null
for _ in $(seq 100); do [[ -z $(processes_naming "$work/k") ]] && break; sleep 0.1; done
[[ -z $(processes_naming "$work/k") ]] || fail "the runs outlived a killed study: $(processes_naming "$work/k")"
[[ $(status_of "$work/k/cases/0000/run.json") == interrupted ]] ||
  fail "a run of a killed study: run.json $(status_of "$work/k/cases/0000/run.json")"
# a link, then a file, at cases/0000: refused before anything is written, the link's target untouched
tiny=$work/tiny.toml
sed 's/2.0e-2/2.0e-6/; s/\[\[2000\], \[2001\], \[2002\], \[2003\]\]/[[10]]/' "$work/study.toml" >"$tiny"
mkdir -p "$work/t/cases" "$work/target"
echo canary >"$work/target/observers.csv"
ln -s "$work/target" "$work/t/cases/0000"
"$mpm" study "$tiny" --out "$work/t" >/dev/null 2>"$work/err"
code=$?
[[ $code -eq 2 ]] || fail "a link at cases/0000: exit $code, want 2"
grep -q "^error: $work/t/cases/0000: is a symbolic link" "$work/err" || fail "a link at cases/0000: $(cat "$work/err")"
[[ $(cat "$work/target/observers.csv") == canary ]] || fail "the study wrote through the link at cases/0000"
rm "$work/t/cases/0000" && echo mine >"$work/t/cases/0000"
"$mpm" study "$tiny" --out "$work/t" >/dev/null 2>"$work/err"
[[ $? -eq 2 && ! -e $work/t/study.csv ]] || fail "a file at cases/0000: not refused: $(cat "$work/err")"
# a reused case folder: the stale scores of an earlier study never survive, and each run has its --max-memory
rm "$work/t/cases/0000" && mkdir "$work/t/cases/0000"
echo stale >"$work/t/cases/0000/observers_shifted.csv"
echo mine >"$work/t/cases/0000/notes.txt"
"$mpm" study "$tiny" --out "$work/t" >/dev/null 2>"$work/err" || fail "tiny study: $(cat "$work/err")"
grep -q stale "$work/t/cases/0000/observers_shifted.csv" && fail "a stale observers_shifted.csv survived"
[[ -e $work/t/cases/0000/notes.txt ]] || fail "the user's file in a case folder was removed"
grep -q '"--max-memory", "[0-9]' "$work/t/cases/0000/run.json" || fail "the study's run has no --max-memory"

# a run into a case folder of the study's own folder: the study refuses to clear it (exit 2), and the run goes on
mkdir -p "$work/l/cases"
"$mpm" "${long_run[@]}" --out "$work/l/cases/0000" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [[ $(status_of "$work/l/cases/0000/run.json") == running ]] && break; sleep 0.05; done
"$mpm" study "$tiny" --out "$work/l" >/dev/null 2>"$work/err"
code=$?
[[ $code -eq 2 ]] && grep -q "^error: $work/l/cases/0000: another mpm run or plot is writing" "$work/err" ||
  fail "a study over a live run's folder: exit $code: $(cat "$work/err")"
kill -s TERM $pid
wait $pid
[[ $(status_of "$work/l/cases/0000/run.json") == interrupted ]] || fail "the live run's folder was taken by the study"
# a stop signal at once, while the study starts its first runs: forwarded, the study ends long before its cases would
start=$SECONDS
"$mpm" study "$work/study.toml" --out "$work/q" --jobs 2 >/dev/null 2>&1 &
pid=$!
sleep 0.03
kill -s TERM $pid
wait $pid
code=$?
[[ $code -eq 143 && $((SECONDS - start)) -lt 8 ]] || fail "a study stopped at its start: exit $code after $((SECONDS - start)) s"
[[ -z $(processes_naming "$work/q") ]] || fail "a study stopped at its start left runs behind"
# a run's folder replaced by a link during the run: exit 3, run.json in the folder the run began in, none in the link's
"$mpm" "${long_run[@]}" --out "$work/m" >/dev/null 2>"$work/err" &
pid=$!
for _ in $(seq 100); do [[ $(status_of "$work/m/run.json") == running ]] && break; sleep 0.05; done
mkdir -p "$work/elsewhere"
mv "$work/m" "$work/m_began" && ln -s "$work/elsewhere" "$work/m"
kill -s TERM $pid
wait $pid
code=$?
[[ $code -eq 3 && ! -e $work/elsewhere/run.json && $(status_of "$work/m_began/run.json") == failed ]] ||
  fail "a run's folder swapped for a link: exit $code, $(ls "$work/elsewhere"), $(status_of "$work/m_began/run.json")"
grep -q "moved or replaced during the run" "$work/err" || fail "a swapped folder not named: $(cat "$work/err")"
# a default folder that is a link to the folder above: refused, the user's file there untouched
mkdir -p "$work/up/runs"
cp "$root/scenes/dyka_bar.toml" "$work/up/bar.toml"
echo mine >"$work/up/observers.csv"
ln -s .. "$work/up/runs/bar"
(cd "$work/up" && "$mpm" run bar.toml --set solver.end_time=1e-6 --set 'output.snapshots=[]' >/dev/null 2>"$work/err")
code=$?
[[ $code -eq 2 && $(cat "$work/up/observers.csv") == mine ]] || fail "runs/bar -> ..: exit $code: $(cat "$work/err")"
grep -q "^error: runs/bar: leads (through a symbolic link) to " "$work/err" || fail "runs/bar -> ..: $(cat "$work/err")"
# a soft material whose Courant step at t = 0 (500000 s) is far beyond end_time: its ~20 steps are not a collapse
cat >"$work/soft.toml" <<'TOML'
dimension = 2
[grid]
length = [4.0, 100.0]
cells = [4, 100]
[material]
young_modulus = 1.0e-12
density = 1.0
[[body]]
min = [1.0, 90.0]
max = [2.0, 91.0]
[gravity]
acceleration = [0.0, -9.81]
[solver]
end_time = 2.0
[output]
times = [0.5, 1.0, 1.5]
TOML
"$mpm" run "$work/soft.toml" --out "$work/soft" >/dev/null 2>"$work/err" || fail "a soft falling block: $(cat "$work/err")"

# 4. Names with no folder of their own: refused, nothing written in the current folder or runs/.
mkdir -p "$work/dots"
for name in ...toml ..toml study:...toml; do
  rm -rf "$work/dots" && mkdir "$work/dots"
  if [[ $name == study:* ]]; then name=${name#study:} command=study && cp "$tiny" "$work/dots/$name"
  else command=run && cp "$root/scenes/dyka_bar.toml" "$work/dots/$name"; fi
  (cd "$work/dots" && "$mpm" $command "$name" >/dev/null 2>"$work/err")
  code=$?
  stem=${name%toml}
  stem=${stem%.}
  [[ $code -eq 2 ]] || fail "mpm $command $name: exit $code, want 2"
  grep -qF "error: $name: its name without the extension is '$stem', and runs/$stem is no folder of its own" "$work/err" ||
    fail "mpm $command $name: $(cat "$work/err")"
  [[ $(ls -A "$work/dots") == "$name" ]] || fail "mpm $command $name wrote: $(ls -A "$work/dots")"
done

# 5. mpm plot waits for no one: a folder held by a run (here by flock(1)) is refused before anything is read.
"$mpm" run "$root/scenes/dyka_bar.toml" --set solver.end_time=1e-5 --set "output.snapshots=[]" --out "$work/p" >/dev/null 2>&1 || fail "a short run failed"
if command -v flock >/dev/null; then
  flock "$work/p" sleep 3 &
  holder=$!
  sleep 0.3
  "$mpm" plot "$work/p" >/dev/null 2>"$work/err"
  code=$?
  [[ $code -eq 2 ]] && grep -q "another mpm run or plot is writing into this folder" "$work/err" ||
    fail "mpm plot of a locked folder: exit $code: $(cat "$work/err")"
  kill $holder 2>/dev/null
  wait $holder 2>/dev/null
fi
echo "cli_endings: $failures failed"
[[ $failures -eq 0 ]]
