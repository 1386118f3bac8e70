#!/usr/bin/env bash
# A run's folder tells the truth (mpm/cli/run_command.hpp, mpm/io/run_folder.hpp):
#   - run.json says "running" during the run and ends "done", "failed" or "interrupted" (SIGINT, SIGTERM);
#   - a new run removes what an earlier run or plot left there and touches no other file;
#   - a link where a file goes is refused (exit 2) before anything is written, its target untouched;
#   - a particle file whose particles are too large for uGIMP is refused (exit 2, located at the row)
#     before anything is written: a finished run in the same folder stays whole.
#   - a folder deleted while the run writes: one `cannot write` line, exit 3.
#   bash tests/cli_run_folder.sh build/bin/mpm
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
scene=$root/scenes/dyka_bar.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
status_of() { sed -n 's/^  "status": "\([a-z]*\)",$/\1/p' "$1/run.json" 2>/dev/null; }

# An earlier run with an exact solution, snapshots and a plot's files; then one with neither.
out=$work/run
"$mpm" run "$scene" --out "$out" >/dev/null 2>&1 || fail "the first run"
touch "$out/plot.gp" "$out/observers.png" "$out/snapshot_0007.vtk"
echo "mine" >"$out/notes.txt"
"$mpm" run "$scene" --out "$out" --set 'exact="none"' --set output.snapshots=[] >/dev/null 2>&1 || fail "the second run"
for stale in exact.csv snapshot_0000.csv snapshot_0001.vtp snapshots.pvd plot.gp observers.png snapshot_0007.vtk; do
  [[ -e "$out/$stale" ]] && fail "$stale of the earlier run is still there"
done
[[ $(cat "$out/notes.txt") == mine ]] || fail "a file mpm did not write was touched"
[[ $(status_of "$out") == done ]] || fail "run.json does not say done"
ls -a "$out" | grep -q partial && fail "a temporary of an atomic write was left"

# A link where run.json goes: refused, nothing written, the link's target untouched.
echo "target" >"$work/target"
cp "$out/observers.csv" "$work/observers.before"
rm "$out/energy.csv" && ln -s "$work/target" "$out/energy.csv"
"$mpm" run "$scene" --out "$out" >"$work/stdout" 2>"$work/err"
code=$?
[[ $code -eq 2 ]] && grep -q "^error: $out/energy.csv: is a symbolic link" "$work/err" || fail "a link in the folder: exit $code, $(cat "$work/err")"
[[ $(cat "$work/target") == target ]] || fail "the link's target was written"
cmp -s "$out/observers.csv" "$work/observers.before" || fail "a refused run touched observers.csv"
rm "$out/energy.csv"

# uGIMP and a particle file whose particles are larger than a cell: refused at the row, the earlier run kept.
printf 'x,volume\n0.001,0.001\n0.003,0.5\n' >"$work/large.csv"
cat >"$work/large.toml" <<TOML
[grid]
origin = [0.0]
length = [0.01]
cells = [5]
[material]
young_modulus = 1.0e6
poisson_ratio = 0.0
density = 1000.0
[[body]]
min = [0.0]
max = [0.004]
shape = "file"
file = "large.csv"
[solver]
shape = "ugimp"
end_time = 1.0e-4
TOML
"$mpm" run "$scene" --out "$work/kept" >/dev/null 2>&1
cp -r "$work/kept" "$work/kept.before"
for extra in "" --print-scene; do
  # shellcheck disable=SC2086
  "$mpm" run "$work/large.toml" --out "$work/kept" $extra >"$work/stdout" 2>"$work/err"
  code=$?
  [[ $code -eq 2 ]] && grep -q "^error: $work/large.csv:3: volume: .*uGIMP needs 0 < l_p <= h" "$work/err" ||
    fail "a particle too large for uGIMP ($extra): exit $code, $(cat "$work/err")"
done
diff -r "$work/kept" "$work/kept.before" >/dev/null || fail "a refused scene changed the finished run beside it"

# Stopped by a signal: run.json says running during the run, interrupted after; exit 128 + the signal.
for signal in TERM INT; do
  long=$work/long_$signal
  "$mpm" run "$scene" --out "$long" --set grid.cells=[4000] --set solver.end_time=1.0 --max-steps 1e9 --force >/dev/null 2>"$work/err" &
  pid=$!
  for _ in $(seq 100); do [[ -s "$long/observers.csv" || $(status_of "$long") == running ]] && break; sleep 0.1; done
  [[ $(status_of "$long") == running ]] || fail "run.json does not say running during the run ($signal)"
  sleep 0.5
  kill -$signal $pid
  wait $pid
  code=$?
  want=$((128 + $(kill -l $signal)))
  [[ $code -eq $want ]] || fail "SIG$signal: exit $code, want $want: $(cat "$work/err")"
  [[ $(status_of "$long") == interrupted ]] || fail "SIG$signal: run.json says $(status_of "$long")"
  grep -q "\"failure\": \"stopped by SIG$signal\"" "$long/run.json" || fail "SIG$signal: run.json does not name the signal"
  tail -c 1 "$long/observers.csv" | od -c | grep -q '\\n' || fail "SIG$signal: observers.csv ends in the middle of a line"
done

# The folder deleted while the run writes: the next snapshot fails (its exact profile, exact_0001.csv, is written
# first), one `cannot write` line, exit 3.
gone=$work/gone
"$mpm" run "$scene" --out "$gone" --set grid.cells=[4000] --set solver.end_time=1.0 \
  --set 'output.snapshots=[0.0, 2.0e-5]' --max-steps 1e9 --force >/dev/null 2>"$work/err" &
pid=$!
for _ in $(seq 100); do [[ -s "$gone/snapshots.pvd" ]] && break; sleep 0.1; done
rm -rf "$gone"
wait $pid
code=$?
[[ $code -eq 3 && $(wc -l <"$work/err") -eq 1 ]] &&
  grep -q "^error: $gone/exact_0001.csv: cannot write: " "$work/err" ||
  fail "a folder deleted during the run: exit $code, $(cat "$work/err")"

# --out that is not a folder: a file, a device, a link to nothing: exit 2, nothing written.
touch "$work/afile"
ln -s "$work/nothing" "$work/dangling"
for bad_out in "$work/afile" /dev/null "$work/dangling"; do
  "$mpm" run "$scene" --out "$bad_out" >"$work/stdout" 2>"$work/err"
  code=$?
  [[ $code -eq 2 ]] && grep -q "^error: $bad_out: is " "$work/err" || fail "--out $bad_out: exit $code, $(cat "$work/err")"
done
[[ -s "$work/afile" || -e "$work/nothing" ]] && fail "a refused --out was written"

# Two runs into one folder: the second is refused while the first goes on (the folder would mix their files).
busy=$work/busy
"$mpm" run "$scene" --out "$busy" --set grid.cells=[4000] --set solver.end_time=1.0 --max-steps 1e9 --force >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [[ $(status_of "$busy") == running ]] && break; sleep 0.1; done
"$mpm" run "$root/scenes/vibrating_bar.toml" --out "$busy" >"$work/stdout" 2>"$work/err"
code=$?
[[ $code -eq 2 ]] && grep -q "another mpm run or plot is writing into this folder" "$work/err" ||
  fail "a second run into a busy folder: exit $code, $(cat "$work/err")"
"$mpm" plot "$busy" >"$work/stdout" 2>"$work/err"
[[ $? -eq 2 ]] || fail "a plot of a busy folder: $(cat "$work/err")"
kill -TERM $pid
wait $pid
grep -q '"A.x"\|A.x' "$busy/observers.csv" && [[ $(status_of "$busy") == interrupted ]] || fail "the first run's folder was changed"

# A full disk at run.json leaves no hidden temporary; at plot.gp, no empty picture.
(trap '' XFSZ; ulimit -f 4; exec "$mpm" run "$scene" --out "$work/tiny") >/dev/null 2>&1
ls -a "$work/tiny" | grep -q partial && fail "a temporary of run.json was left"
"$mpm" run "$scene" --out "$work/plotted" >/dev/null 2>&1
(trap '' XFSZ; ulimit -f 0; exec "$mpm" plot "$work/plotted") >/dev/null 2>&1
ls "$work/plotted" | grep -q png && fail "a plot that could not write plot.gp left pictures"

# A closed pipe on standard output: exit 3 and a message, not a silent SIGPIPE.
code=$(python3 -c "
import subprocess, os
r, w = os.pipe(); os.close(r)
p = subprocess.run(['$mpm', 'stability'], stdout=w, stderr=subprocess.PIPE); print(p.returncode)")
[[ $code -eq 3 ]] || fail "a closed pipe: exit $code"

# run.json stays valid JSON whatever bytes the command line holds.
"$mpm" run "$scene" --out "$work/$(printf 'odd\xff')" >/dev/null 2>&1
python3 -c "import json, sys; json.load(open(sys.argv[1], encoding='utf-8'))" "$work/$(printf 'odd\xff')/run.json" ||
  fail "run.json of a folder named with a byte that is not UTF-8 is not JSON"

echo "cli_run_folder: $failures failed"
[[ $failures -eq 0 ]]
