#!/usr/bin/env bash
# The CLI's contract on errors:
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
expect 2 "^error: $work/missing.toml: cannot be read: no such file" -- run "$work/missing.toml"
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

# Every input validated before anything runs; each bad input below with the key
# it must name. None may leave an output folder behind.
bad() {  # bad PATTERN ARGS...: exit 2, the message located and naming its key, no output folder
  local pattern=$1; shift
  expect 2 "$pattern" -- "$@"
  [[ -e "$work/a" ]] && { echo "FAIL: mpm $* made an output folder"; failures=$((failures + 1)); rm -rf "$work/a"; }
}
soil=$(dirname "$scene")/soil_block.toml
bad "^error: --set\(1\):1: \.: not a key" run "$scene" --out "$work/a" --set .=1
bad "^error: --set\(1\):1: body\[x\]\.max: not a key" run "$scene" --out "$work/a" --set 'body[x].max=[1.0]'
bad "^error: --set\(1\):1: body\[0\]: not a key" run "$scene" --out "$work/a" --set 'body[0]=1'
bad "^error: --set\(1\):1: body\.min: 'body' is an array of tables" run "$scene" --out "$work/a" --set 'body.min=[0.0]'
bad "^error: --set\(1\):1: body\[7\]\.min: no table body\[7\]" run "$scene" --out "$work/a" --set 'body[7].min=[0.0]'
bad "^error: --set\(1\):1: solver\.cfl: give one value only" run "$scene" --out "$work/a" --set 'solver.cfl=0.5
x=1'
grep -v '^cells' "$scene" >"$work/no_cells.toml"
bad "^error: $work/no_cells.toml:[0-9]+: grid\.cells: missing" run "$work/no_cells.toml" --out "$work/a"
{ printf 'title = "deep"\n'; yes a. | head -n 200000 | tr -d '\n'; echo 'b = 1'; } >"$work/deep.toml"
bad "^error: $work/deep.toml:2: \(syntax\): dotted keys nest deeper than 64 levels" run "$work/deep.toml" --out "$work/a"
{ printf 'x = '; yes '[' | head -n 100000 | tr -d '\n'; echo; } >"$work/brackets.toml"
bad "^error: $work/brackets.toml:1: \(syntax\): brackets nest deeper" run "$work/brackets.toml" --out "$work/a"
# A table header that does not start with a key: toml++ 3.3 would trip its own assertion (UB in release).
{ cat "$scene"; printf '[[[1]]]\n'; } >"$work/header.toml"
bad "^error: $work/header.toml:[0-9]+: \(syntax\): a table header must start with a key" run "$work/header.toml" --out "$work/a"
bad "^error: --set\(1\):1: a\.a\.a.*: not a key" run "$scene" --out "$work/a" --set "$(yes a. | head -n 50000 | tr -d '\n')b=1"
bad "^error: --set\(1\):1: grid\.cells: the scene needs 1e\+08 particles" run "$scene" --out "$work/a" --set 'grid.cells=[100000000]' --max-memory 8G
bad "^error: --set\(1\):1: grid\.cells: has 2 entries" run "$scene" --out "$work/a" --set 'grid.cells=[1000000,1000000]'
bad "^error: --set\(1\):1: grid\.cells: the scene needs 4e\+12 particles" run "$soil" --out "$work/a" --set 'grid.cells=[1000000,1000000]'
bad "^error: --set\(1\):1: grid\.margin_max: entries must be whole numbers in \[0, 100000000\], got 2147483647" \
  run "$scene" --out "$work/a" --set 'grid.margin_max=[2147483647]'
bad "^error: --set\(1\):1: grid\.margin_max: the scene needs .* the limit is 1 GiB" run "$scene" --out "$work/a" --set 'grid.margin_max=[90000000]' --max-memory 1G
bad "^error: --set\(1\):1: body\[0\]\.particles_per_cell: entries must be whole numbers in \[1, 100000000\]" \
  run "$scene" --out "$work/a" --set 'body[0].particles_per_cell=[1000000000]'
bad "^error: --set\(1\):1: body\[0\]\.particles_per_cell: the scene needs 4e\+09 particles" run "$scene" --out "$work/a" --set 'body[0].particles_per_cell=[100000000]'
bad "^error: --set\(1\):1: grid\.margin_min: entries must be whole numbers" run "$scene" --out "$work/a" --set 'grid.margin_min=[2147483000]'
bad "^error: --set\(1\):1: dimension: must be an integer in \[1, 2\], got 4294967297" run "$scene" --out "$work/a" --set dimension=4294967297
bad "^error: --set\(1\):1: output\.every: must be an integer in \[1, 2147483647\], got 4294967297" run "$scene" --out "$work/a" --set output.every=4294967297
# Integers near 2^63 are checked and named as written (toml++ holds them exactly, no double does).
bad "^error: --set\(1\):1: grid\.margin_max: entries must be whole numbers in \[0, 100000000\], got 9223372036854775807" \
  run "$scene" --out "$work/a" --set 'grid.margin_max=[9223372036854775807]'
bad "^error: --set\(1\):1: grid\.cells: entries must be whole numbers in \[1, 100000000\], got 9223372036854775807" \
  run "$scene" --out "$work/a" --set 'grid.cells=[9223372036854775807]'
bad "^error: --set\(1\):1: output\.snapshots: times must lie in \[0, solver\.end_time\]" run "$scene" --out "$work/a" --set 'output.snapshots=[9223372036854775807]'
# A required table the scene lacks is refused at the key that needs it, at a line of the file (never 0).
printf '[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n[[body]]\nmin = [0.0]\nmax = [1.0]\n' >"$work/no_solver.toml"
bad "^error: $work/no_solver.toml:1: solver\.end_time: missing; a number is required" run "$work/no_solver.toml" --out "$work/a"
# The 1D grid's memory: 10^7 cells under 2048 particles hold 7 nodal copies of the scatter (2.7 GiB with the process, not 0.6)
printf '[grid]\nlength = [1.0]\ncells = [10000000]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n[[body]]\nmin = [0.0]\nmax = [0.0002048]\n[solver]\nend_time = 1e-9\n' >"$work/long_grid.toml"
bad "^error: $work/long_grid.toml:3: grid\.cells: the scene needs 2\.05e\+03 particles, 1e\+07 nodes .* about 2\.7 GiB; the limit is 2 GiB" \
  run "$work/long_grid.toml" --out "$work/a" --max-memory 2G
# The finite-strain bar's failure is located at the key of its amplitude
bad "^error: $(dirname "$scene")/vibrating_bar.toml:[1-9][0-9]*: exact_parameters\.velocity_amplitude: FiniteStrainBar: stretch fell below" \
  exact "$(dirname "$scene")/vibrating_bar.toml" --strain finite --set constants.amplitude_ratio=0.3 --at 0 --times 0:1e-4:1e-3
bad "^error: --set\(1\):1: solver\.end_time: must be a finite number, got inf" run "$scene" --out "$work/a" --set solver.end_time=inf
bad "^error: --set\(1\):1: solver\.cfl: must be a finite number, got inf" run "$soil" --out "$work/a" --set solver.cfl=inf
bad "^error: --set\(1\):1: solver\.cfl: must be in \(0, 10\]" run "$soil" --out "$work/a" --set solver.cfl=1e6
bad "^error: --set\(1\):1: output\.snapshots: must hold finite numbers only, got nan" run "$scene" --out "$work/a" --set 'output.snapshots=[nan]'
bad "^error: --set\(1\):1: observer\[0\]\.position: must hold finite numbers only, got nan" run "$scene" --out "$work/a" --set 'observer[0].position=[nan]'
bad "^error: --set\(1\):1: solver\.energy_growth_limit: must be a finite number, got nan" run "$scene" --out "$work/a" --set solver.energy_growth_limit=nan
bad "^error: --set\(1\):1: grid\.cells: entries must be whole numbers in \[1, 100000000\], got 3e\+09" run "$scene" --out "$work/a" --set 'grid.cells=[3e9]'
bad "^error: --set\(1\):1: grid\.length: must hold finite numbers only, got inf" run "$scene" --out "$work/a" --set 'grid.length=[inf]'
bad "^error: --set\(2\):1: solver\.lme_tol: too large for lme_gamma = 3" run "$scene" --out "$work/a" --set 'solver.shape="lme"' --set solver.lme_tol=0.5
bad "^error: --set\(2\):1: solver\.lme_gamma: too large for lme_tol" run "$scene" --out "$work/a" --set 'solver.shape="lme"' --set solver.lme_gamma=30
bad "^error: --set\(1\):1: solver\.lme_gamma: the scene needs .* stencil nodes per particle" run "$soil" --out "$work/a" --set solver.lme_gamma=1e-6
bad "^error: --set\(1\):1: solver\.foo: unknown key" run "$scene" --out "$work/a" --set solver.foo.bar=1
bad "^error: --set\(1\):1: newtable: unknown key" run "$scene" --out "$work/a" --set newtable.x=1
bad "^error: --set\(1\):1: title: must be one line of printable text" run "$scene" --out "$work/a" --set 'title="two\nlines"'
bad "^error: --set\(1\):1: observer\[0\]\.position: lies outside the grid" run "$scene" --out "$work/a" --set 'observer[0].position=[5.0]'
bad "^error: .*dyka_bar.toml:[0-9]+: solver\.end_time: end_time / dt = .* more than the limit of 100;.*--force" run "$scene" --out "$work/a" --max-steps 100
bad "^error: .*dyka_bar.toml:[0-9]+: grid\.cells: the scene needs 40 particles.*the limit is 10 KiB \(--max-memory\)" run "$scene" --out "$work/a" --max-memory 10K
bad "^error: --max-memory: 'lots' is not a size" run "$scene" --out "$work/a" --max-memory lots
bad "^error: --max-steps: must be a number in \[1, .*got 'nan'" run "$scene" --out "$work/a" --max-steps nan
bad "^error: --out: must not be empty" run "$scene" --out ""
bad "^error: $work: is a folder, not a regular file" run "$work" --out "$work/a"
# A scene that is not a regular file is refused at once (a FIFO never waited on), for each command reading one.
mkfifo "$work/fifo.toml"
printf 't,v\n0,1\n' >"$work/c.csv"
printf '#!/bin/sh\nexec timeout -s KILL 10 "%s" "$@"\n' "$mpm" >"$work/mpm_in_10s"  # a hang fails (exit 137), never blocks
chmod +x "$work/mpm_in_10s"
untimed=$mpm
mpm=$work/mpm_in_10s
for command in "run $work/fifo.toml --out $work/a" "run $work/fifo.toml --print-scene" "exact $work/fifo.toml --at 0 --times 0:1e-5:1e-4" \
               "compare $work/c.csv $work/fifo.toml --at 0 --column v=v_x"; do
  # shellcheck disable=SC2086
  bad "^error: $work/fifo.toml: not a regular file \(a FIFO\)" $command
done
mpm=$untimed
bad "^error: /dev/null: not a regular file \(a device\)" run /dev/null --print-scene
# LME's estimate counts its copy of the stencils: 40 particles x 2.35e6 nodes at gamma 1e-11 need 2.8 GiB (2.9 GB measured)
bad "^error: --set\(2\):1: solver\.lme_gamma: the scene needs 40 particles, .* about 2\.82 GiB; the limit is 2 GiB" \
  run "$scene" --out "$work/a" --set 'solver.shape="lme"' --set solver.lme_gamma=1e-11 --max-memory 2G
# mpm stability refuses, as mpm shape does, an LME support reaching beyond 100 cells (out of memory, then Newton's failure)
for gamma in 1e-12 1e-18; do
  bad "^error: --lme-gamma: too small for the support tolerance 1e-06: the support would reach beyond 100 cells" \
    stability --shape lme --lme-gamma $gamma
done
# A Poisson ratio just below 0.5 is valid: the CFL check's body takes it as it is (it read 0.5 at 6 digits)
succeeds() {  # succeeds ARGS...: exit 0
  "$mpm" "$@" >"$work/out" 2>"$work/err" || { echo "FAIL: mpm $* -> exit $?, stderr: $(cat "$work/err")"; failures=$((failures + 1)); }
}
succeeds stability --poisson-ratio 0.4999999 --dim 2
succeeds run "$(dirname "$scene")/colliding_disks.toml" --out "$work/nearly_incompressible" --set material.poisson_ratio=0.4999999 \
  --set solver.end_time=1e-4 --set output.snapshots=[]
# A number too small for a double is said to be that, not "not finite"
printf 'x,volume\n0.01,1e-320\n' >"$work/tiny.csv"
bad "^error: --set\(2\):1: body\[0\]\.file: $work/tiny.csv:2: volume: '1e-320' is too small" \
  run "$scene" --out "$work/a" --set 'body[0].shape="file"' --set "body[0].file=\"$work/tiny.csv\""
bad "^error: --at: coordinates must lie within" shape --dim 1 --kind linear --at 1e300
bad "^error: --at: 'nan' is not" shape --dim 1 --kind linear --at nan
bad "^error: --dim: must be a whole number from 1 to 2, got '2x'" shape --dim 2x --kind linear --at 0.5,0.5
bad "^error: --at: '0.5,' is not" shape --dim 1 --kind linear --at 0.5,
# mpm stability: every option validated before anything is computed, the option named
bad "^error: --newmark-gamma: must be a number in \[0, 1\], got '1.5'" stability --integrator npc --newmark-gamma 1.5
bad "^error: --shape: must be one of linear \| ugimp \| lme \| bspline2 \| bspline3, got 'cubic'" stability --shape cubic
bad "^error: --ppc: must be a whole number from 1 to 5, got '2.5'" stability --ppc 2.5
bad "^error: --cells: the body would have 1008 unknowns, more than 1000" stability --dim 2 --cells 12
bad "^error: --flip-fraction: must be a number in \[0, 1\], got 'nan'" stability --flip-fraction nan
bad "^error: --lme-gamma: too large for lme_tol" stability --shape lme --lme-gamma 50
bad "^error: --bogus: unknown option" stability --bogus 1
# --force lifts the step limit, and the run is whole
"$mpm" run "$scene" --out "$work/forced" --max-steps 100 --force >"$work/out" 2>&1 &&
  grep -q '"status": "done"' "$work/forced/run.json" || { echo "FAIL: --force must run the scene"; failures=$((failures + 1)); }

# Output that cannot be written: exit 3 naming the file, never "wrote".
cannot_write() {  # cannot_write FILE-PATTERN ARGS...
  local pattern=$1; shift
  expect 3 "^error: $pattern: cannot write" -- "$@"
  grep -q wrote "$work/out" && { echo "FAIL: mpm $* said wrote"; failures=$((failures + 1)); }
}
touch "$work/file"
cannot_write "$work/file/x" run "$scene" --out "$work/file/x"
if [[ -d /proc/self ]]; then cannot_write "/proc/self/run.json" run "$scene" --out /proc/self; fi
if [[ $(id -u) -ne 0 ]]; then  # root writes through permissions
  mkdir "$work/readonly" && chmod 555 "$work/readonly"
  cannot_write "$work/readonly/run.json" run "$scene" --out "$work/readonly"
fi
# A full disk, or a file size limit (RLIMIT_FSIZE, with SIGXFSZ ignored so that the write fails with
# EFBIG): run.json (about 6 kB) cannot be written at 4 KiB; at 8 KiB run.json is written and exact.csv
# (13 kB) is the first file cut short, and run.json then says the run failed.
limited() { (trap '' XFSZ; ulimit -f "$1"; shift; "$mpm" "$@"); }
limited 4 run "$scene" --out "$work/limit4" >"$work/out" 2>"$work/err"
[[ $? -eq 3 ]] && grep -qE "^error: $work/limit4/run.json: cannot write: File too large" "$work/err" && ! grep -q wrote "$work/out" ||
  { echo "FAIL: a run.json cut short by a size limit: $(cat "$work/err")"; failures=$((failures + 1)); }
limited 8 run "$scene" --out "$work/limit8" >"$work/out" 2>"$work/err"
[[ $? -eq 3 ]] && grep -qE "^error: $work/limit8/exact.csv: cannot write: File too large" "$work/err" && ! grep -q wrote "$work/out" &&
  grep -q '"status": "failed"' "$work/limit8/run.json" ||
  { echo "FAIL: a CSV cut short by a size limit: $(cat "$work/err")"; failures=$((failures + 1)); }
# Standard output that cannot be written: exit 3, whatever the command.
if [[ -w /dev/full ]]; then
  for arguments in "--help" "--version" "run $scene --print-scene" "stability" "shape --dim 1 --kind linear --at 0.5" \
    "exact $scene --at 0.001 --times 0:1e-5:1e-4" "run --help"; do
    # shellcheck disable=SC2086
    "$mpm" $arguments >/dev/full 2>"$work/err"
    code=$?
    [[ $code -eq 3 ]] && grep -q "standard output: cannot write" "$work/err" ||
      { echo "FAIL: mpm $arguments >/dev/full -> exit $code: $(cat "$work/err")"; failures=$((failures + 1)); }
  done
fi

echo "cli_errors: $failures failed"
[[ $failures -eq 0 ]]
