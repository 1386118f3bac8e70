#!/usr/bin/env bash
# A structural fuzzer of the `mpm` command: mutates the shipped scenes/*.toml (delete,
# duplicate, swap or truncate lines, replace values and characters) and adds hostile --set
# overrides, then runs the real binary on each case and asserts the CLI's contract:
#   - the exit code is 0, 2 or 3 only: no signal, no timeout (a hang or a run past its budget);
#   - exit 2: the first line of stderr is `error: FILE:LINE: KEY: ...`, `error: --set(n):1: KEY: ...`
#     or `error: --OPTION: ...`, and no output folder was made;
#   - exit 3: one line naming the failure, and stdout never says "wrote";
#   - exit 0: "wrote", run.json says "done", and the run took at most twice its step budget.
# Then hostile files for each reader of a file (FIFO, device, folder, /proc, byte-order mark, a long line, a
# header name that closes gnuplot's quote, a control character, other separators, decimal commas, times out of
# range or order): exit 0, 2 or 3 within 10 s, nothing run. Then each shipped scene under a file size limit.
# Then four generated classes (issue 49), CASES / 20 of each (rounded up), drawn from the seed:
#   - work bombs: a small bar whose initial velocity or body force is a huge, overflowing or singular formula,
#     many output times, a random --max-steps, sometimes --force: 0, 2 or 3 within 20 s, never past the limit;
#   - stop signals during `mpm run` (into an earlier run's files too): exit 0 or 128 + N, run.json done or
#     interrupted, never running or clearing, every CSV whole, no old snapshot beside a new run's "done";
#   - stop signals and SIGKILL during `mpm study`: no process left, no study.csv, no run.json running;
#   - links under a study's or run's folder, scene and study files named ...toml and ..toml: exit 2 naming
#     the path, nothing written, the link's target untouched.
#
#   bash tests/fuzz_cli.sh build/bin/mpm [CASES] [SEED]
# CASES defaults to $MPM_FUZZ_CASES or 300 (what `make test` runs); SEED to $MPM_FUZZ_SEED or 11.
# The same seed gives the same cases. Failing cases are printed with a command that reproduces them;
# MPM_FUZZ_KEEP=DIR keeps their scene files there.
set -u
mpm=$1
cases=${2:-${MPM_FUZZ_CASES:-300}}
seed=${3:-${MPM_FUZZ_SEED:-11}}
generated=$(((cases + 19) / 20))  # cases of each generated class (issue 49): 15 at 300
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
RANDOM=$seed
# The budget bounds a run's work: steps x (particles x stencil + nodes) <= 300 x 4 MiB of arrays,
# a second or two even for LME in 2D on a loaded 2-core machine.
max_steps=300
budget=(--max-memory 4M --max-steps $max_steps)
time_limit=30  # seconds per case

scenes=("$root"/scenes/*.toml)
values=(0 1 -1 2 3 0.5 -0.5 1e-300 1e300 -1e300 inf -inf nan +nan 4294967297 2147483647 -2147483648
  9223372036854775807 9223372036854775808 18446744073709551617 -9223372036854775809
  99999999999999999999999999 1e9 3e9 0.1 20 '"lme"' '"ugimp"' '"linear"' '"npc"' '"fe"' '"sum"' '"gauss"' '"xmax"' '"ymin"'
  '""' '"a\nb"' '"x"' true '[]' '[0]' '[1]' '[1.0]' '[-1.0]' '[nan]' '[inf]' '[1e9]' '[3e9]' '[0.0, 0.0]' '[2, 2]'
  '[1, 1e9]' '[0.0, 1.0, 2.0]' '["x"]' '["y"]' '["x", "y"]' '[[1]]' '{a = 1}' '[ "x", 1 ]' '1979-05-27' '0x10'
  '[0.0, 1e-4, 2e-4]' '[100000000]' '[2147483000]' '[10, 10]' '[0.05]' '[5.0]' '[4.5, 9.5]' '[-5000.0]')
junk_keys=(. .. a..b 'body[x].max' 'body[-1].min' 'body[0]' 'body[99].min' body.min 'x[0]' solver 'solver.cfl.x'
  grid.cells.x 'observer[0]' 'fixed[0].face.x' new.table.key title.x '"quoted".key' 'a b' '')
shape_options=(--dim --kind --at --gamma --cell-size --particle-size --tol --bogus)
shape_values=(1 2 2x 3 linear ugimp lme 0.5 0.5, ,0.5 0.5,0.5 0.25,0.5,0.75 nan inf -inf 1e300 -1 0 1e-9 0.9 3 20 '' x)

# Sets $picked to a random entry of the array named $1. Never called in $(...): a subshell reseeds
# RANDOM, and the cases would no longer follow from the seed.
pick() { local -n list=$1; picked=${list[RANDOM % ${#list[@]}]}; }

# The dotted keys of a scene with their values, `section.key<TAB>value` and `array[k].key<TAB>value`.
keys_of() {
  awk '{ sub(/[ \t]*#.*/, "") }
       /^\[\[/ { gsub(/[\[\] ]/, ""); prefix = $0 "[" count[$0]++ "]"; next }
       /^\[/   { gsub(/[\[\] ]/, ""); prefix = $0; next }
       /^[A-Za-z_]+ *=/ { key = $1; sub(/=.*/, "", key); value = $0; sub(/^[^=]*= */, "", value)
                          print (prefix == "" ? "" : prefix ".") key "\t" value }' "$1"
}

# A plausible change of a scene's value: every number in it scaled by one factor (x2, x0.5, x10, ...).
scale_numbers() {  # scale_numbers VALUE FACTOR
  awk -v f="$2" '{
    out = ""; rest = $0
    while (match(rest, /-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) {
      out = out substr(rest, 1, RSTART - 1) sprintf("%.6g", substr(rest, RSTART, RLENGTH) * f)
      rest = substr(rest, RSTART + RLENGTH)
    }
    print out rest }' <<<"$1"
}

# Sets $override to one --set: a key of the scene with a hostile value, or with its own value
# scaled (always, given "scaled").
factors=(2 0.5 10 0.1 -1 3 1.5 100)
some_override() {
  local key value
  pick entries
  key=${picked%%$'\t'*} value=${picked#*$'\t'}
  if [[ ${1:-} == scaled || $((RANDOM % 2)) -eq 0 ]] && [[ $value =~ [0-9] ]]; then
    pick factors
    override="$key=$(scale_numbers "$value" "$picked")"
  else
    pick values
    override="$key=$picked"
  fi
}

# Applies one random mutation to the file $1 in place.
mutate_file() {
  local file=$1 lines n m line
  lines=$(wc -l <"$file")
  [[ $lines -gt 0 ]] || return
  n=$((RANDOM % lines + 1)) m=$((RANDOM % lines + 1))
  case $((RANDOM % 6)) in
    0) sed -i "${n}d" "$file" ;;
    1) line=$(sed -n "${n}p" "$file")
       if [[ $line == *=* ]]; then
         pick values
         awk -v n="$n" -v v="$picked" 'NR == n { sub(/=.*/, "= " v) } { print }' "$file" >"$file.new" && mv "$file.new" "$file"
       fi ;;
    2) sed -i "${n}p" "$file" ;;
    3) head -c $((RANDOM % ($(wc -c <"$file") + 1))) "$file" >"$file.new" && mv "$file.new" "$file" ;;
    4) local chars='0123456789-.e[]="#,x '
       awk -v n="$n" -v c="${chars:RANDOM % ${#chars}:1}" -v r="$RANDOM" \
         'NR == n && length($0) > 0 { p = r % length($0) + 1; $0 = substr($0, 1, p - 1) c substr($0, p + 1) } { print }' \
         "$file" >"$file.new" && mv "$file.new" "$file" ;;
    5) awk -v n="$n" -v m="$m" 'NR == FNR { l[FNR] = $0; next } { print (FNR == n ? l[m] : FNR == m ? l[n] : $0) }' \
         "$file" "$file" >"$file.new" && mv "$file.new" "$file" ;;
  esac
}

failures=0
declare -A codes=()
report() {  # report CASE WHAT COMMAND...
  local number=$1 what=$2; shift 2
  failures=$((failures + 1))
  echo "FAIL case $number: $what"
  printf '  reproduce: %q' "$mpm"; printf ' %q' "$@"; echo
  if [[ -n ${scene_copy:-} ]]; then
    echo "  scene: $(tr '\n' '|' <"$scene_copy" | head -c 600)"
    [[ -n ${MPM_FUZZ_KEEP:-} ]] && mkdir -p "$MPM_FUZZ_KEEP" && cp "$scene_copy" "$MPM_FUZZ_KEEP/"  # the whole scene, to reproduce
  fi
  echo "  stderr: $(head -c 400 "$work/err")"
}

start=$SECONDS
for ((number = 0; number < cases; ++number)); do
  out="$work/out_$number"
  scene_copy=""
  if ((RANDOM % 10 == 0)); then  # `mpm shape`
    arguments=(shape)
    for ((k = RANDOM % 6; k >= 0; --k)); do
      pick shape_options && arguments+=("$picked")
      pick shape_values && arguments+=("$picked")
    done
  else
    pick scenes && scene=$picked
    scene_copy="$work/case_$number.toml"
    cp "$scene" "$scene_copy"
    mapfile -t entries < <(keys_of "$scene")
    # short runs: the mutations below come later and win
    if [[ $scene == *dyka* ]]; then short=(--set solver.end_time=1e-5 --set 'output.snapshots=[0.0, 1e-5]')
    elif grep -q '^dt *=' "$scene"; then short=(--set solver.end_time=1e-3 --set 'output.snapshots=[0.0, 1e-3]')  # a fixed step
    else short=(--set solver.end_time=0.1 --set 'output.snapshots=[0.0, 0.1]'); fi
    arguments=(run "$scene_copy" --out "$out" "${budget[@]}" "${short[@]}")
    gentle=$((RANDOM % 3 == 0))  # a third of the cases: only plausible changes, so that many run
    for ((k = RANDOM % 3; k >= 0; --k)); do
      ((gentle)) && { some_override scaled; arguments+=(--set "$override"); continue; }
      case $((RANDOM % 3)) in
        0) mutate_file "$scene_copy" ;;
        1) some_override && arguments+=(--set "$override") ;;
        2) if ((RANDOM % 4 == 0)); then pick junk_keys && key=$picked && pick values && arguments+=(--set "$key=$picked")
           else some_override && arguments+=(--set "$override"); fi ;;
      esac
    done
  fi
  timeout -s KILL $time_limit "$mpm" "${arguments[@]}" >"$work/stdout" 2>"$work/err"
  code=$?
  [[ -n ${MPM_FUZZ_VERBOSE:-} ]] && echo "case $number: exit $code: $(head -n 1 "$work/err" | cut -c1-150)"
  codes[$code]=$((${codes[$code]:-0} + 1))
  case $code in
    0)
      if [[ ${arguments[0]} == run ]]; then
        grep -q "^wrote " "$work/stdout" || report $number "exit 0 without 'wrote'" "${arguments[@]}"
        grep -q '"status": "done"' "$out/run.json" 2>/dev/null || report $number "exit 0 but run.json does not say done" "${arguments[@]}"
        steps=$(sed -n 's/.*"steps": \([0-9]*\).*/\1/p' "$out/run.json" 2>/dev/null)
        [[ -n $steps && $steps -le $((2 * max_steps)) ]] || report $number "ran $steps steps, past its budget of $max_steps" "${arguments[@]}"
      fi ;;
    2)
      first=$(head -n 1 "$work/err")
      if ! [[ $first =~ ^error:\ [^:]+:[0-9]+:\ [^:]+:\ .+ || $first =~ ^error:\ --[a-z-]+:\ .+ || $first =~ ^error:\ --set\([0-9]+\):1:\ .+ ]]; then
        report $number "exit 2 without a located message" "${arguments[@]}"
      fi
      [[ -e $out ]] && report $number "exit 2 but an output folder was made" "${arguments[@]}" ;;
    3)
      grep -q "wrote" "$work/stdout" && report $number "exit 3 but stdout says wrote" "${arguments[@]}"
      grep -qE "^(failure: step|error: .*: cannot write)" "$work/err" || report $number "exit 3 without a failure line" "${arguments[@]}" ;;
    137) report $number "killed after ${time_limit} s: a hang, or a run past its budget" "${arguments[@]}" ;;
    *) report $number "exit $code (a signal or an unexpected code)" "${arguments[@]}" ;;
  esac
  rm -rf "$out" "$scene_copy"
done
# Hostile files for every reader of a file (the times file, compare's CSV, a particle file, a run folder's
# observers.csv, a trace for mpm trace --diff): not regular files, a byte-order mark, a line over 1 MiB, a header name that closes
# gnuplot's quote and runs a command, a control character, ';' or tab separators, decimal commas, sample
# times after the end time or repeated and decreasing. Each returns within 10 s with 0, 2 or 3, runs
# nothing, and exit 2 says `error: ` and names the file.
hostile() {  # hostile CLASS FILE: makes FILE of that class
  rm -rf "$2"
  case $1 in
    fifo) mkfifo "$2" ;;
    device) ln -s /dev/zero "$2" ;;
    folder) mkdir "$2" ;;
    proc) ln -s /proc/self/mem "$2" ;;
    bom) printf '\xef\xbb\xbft,A.v_x,x,y,volume\n0,1,0.1,0.1,0.001\n' >"$2" ;;
    long) { head -c 1100000 /dev/zero | tr '\0' 7; printf '\n'; } >"$2" ;;
    inject) printf "t,A.x' . system('touch %s') . '\n0,1\n" "$work/pwned" >"$2" ;;
    control) printf 't,A.v\001x\n0,1\n' >"$2" ;;
    semicolon) printf 't;A.v_x;x;y;volume\n0;1;0.1;0.1;0.001\n' >"$2" ;;
    tabs) printf 't\tA.v_x\tx\ty\tvolume\n0\t1\t0.1\t0.1\t0.001\n' >"$2" ;;
    decimal) printf 't;A.v_x;x;y;volume\n0;1,5;0,1;0,1;0,001\n' >"$2" ;;
    late) printf 't,A.v_x,x,y,volume\n0,1,0.1,0.1,0.001\n1,1,0.3,0.1,0.001\n' >"$2" ;;
    backwards) printf 't,A.v_x\n1e-5,1\n1e-5,1\n0,1\n' >"$2" ;;
  esac
}
hostile_cases=0
for class in fifo device folder proc bom long inject control semicolon tabs decimal late backwards; do
  for reader in times compare particles plot trace; do
    mkdir -p "$work/hostile"
    file=$work/hostile/observers.csv
    hostile $class "$file"
    case $reader in
      times) arguments=(exact "$root/scenes/dyka_bar.toml" --at 0 --times-file "$file") ;;
      compare) arguments=(compare "$file" "$root/scenes/dyka_bar.toml" --at 0 --column A.v_x=v_x) ;;
      particles) arguments=(run "$root/scenes/colliding_disks.toml" --print-scene --set 'body[0].shape="file"' --set "body[0].file=\"$file\"") ;;
      plot) arguments=(plot "$work/hostile") ;;
      trace) arguments=(trace --diff "$file" "$file") ;;  # the same file twice: a trace agrees with itself (0)
    esac
    hostile_cases=$((hostile_cases + 1))
    timeout -s KILL 10 "$mpm" "${arguments[@]}" >"$work/stdout" 2>"$work/err"
    code=$?
    [[ -n ${MPM_FUZZ_VERBOSE:-} ]] && echo "case $class/$reader: exit $code: $(head -n 1 "$work/err" | cut -c1-150)"
    codes[$code]=$((${codes[$code]:-0} + 1))
    scene_copy=""
    [[ $code -eq 0 || $code -eq 2 || $code -eq 3 ]] || report "$class/$reader" "exit $code (a hang, a signal or an unexpected code)" "${arguments[@]}"
    [[ $code -eq 2 ]] && ! grep -q "^error: .*$file" "$work/err" && report "$class/$reader" "exit 2 without naming the file" "${arguments[@]}"
    [[ -e $work/pwned ]] && report "$class/$reader" "a header ran a command" "${arguments[@]}"
    grep -q "internal error" "$work/err" && report "$class/$reader" "internal error" "${arguments[@]}"
    rm -rf "$work/hostile" "$work/pwned"
  done
done
cases=$((cases + hostile_cases))
# Truncated writes: each shipped scene run, then plotted, under a file size limit (RLIMIT_FSIZE, SIGXFSZ
# ignored, so a write past it fails with EFBIG as on a full disk). Exit 0 only with every file whole
# (run.json done, each CSV ending in a newline); else exit 3 `cannot write`, never "wrote", and run.json,
# when it could be written, not "done". A snapshot is written whole or not at all (atomically).
limited() { (trap '' XFSZ; ulimit -f "$1"; shift; exec "$mpm" "$@"); }
truncated_cases=0
for scene in "${scenes[@]}"; do
  for kib in 2 8 32 128; do
    out=$work/limited
    rm -rf "$out"
    if [[ $scene == *dyka* ]]; then short=(--set solver.end_time=1e-5)
    elif grep -q '^dt *=' "$scene"; then short=(--set solver.end_time=1e-3)  # a fixed step: 100 of them
    else short=(--set solver.end_time=0.1); fi
    for arguments in "run $scene --out $out ${short[*]} --set output.snapshots=[0.0]" "plot $out"; do
      truncated_cases=$((truncated_cases + 1))
      # shellcheck disable=SC2086
      timeout -s KILL 30 bash -c "$(declare -f limited); mpm=$mpm; limited $kib $arguments" >"$work/stdout" 2>"$work/err"
      code=$?
      codes[$code]=$((${codes[$code]:-0} + 1))
      scene_copy=""
      case $code in
        0) [[ $arguments == run* ]] || continue
           grep -q '"status": "done"' "$out/run.json" || report "limit $kib K" "exit 0, run.json not done" $arguments
           for csv in "$out"/*.csv; do
             [[ -s $csv && $(tail -c 1 "$csv" | od -An -c | tr -d ' ') == '\n' ]] || report "limit $kib K" "exit 0 with $csv cut short" $arguments
           done ;;
        2) [[ $arguments == plot* ]] || report "limit $kib K" "exit 2" $arguments ;;  # plot of a run that wrote no CSV
        3) grep -q wrote "$work/stdout" && report "limit $kib K" "exit 3 but said wrote" $arguments
           grep -q "cannot write" "$work/err" || report "limit $kib K" "exit 3 without cannot write" $arguments
           grep -q '"status": "done"' "$out/run.json" 2>/dev/null && [[ $arguments == run* ]] && report "limit $kib K" "run.json says done" $arguments
           for snapshot in "$out"/snapshot_*.csv; do
             [[ ! -e $snapshot || $(tail -c 1 "$snapshot" | od -An -c | tr -d ' ') == '\n' ]] || report "limit $kib K" "$snapshot cut short" $arguments
           done ;;
        *) report "limit $kib K" "exit $code" $arguments ;;
      esac
    done
  done
done
cases=$((cases + truncated_cases))
# The generated classes (issue 49): $generated cases of each, drawn from the seed. A case that runs in the
# background is started by start_mpm and waited for by await; its exit code counts in $codes as the others'.
generated_cases=0
count_case() {  # count_case LABEL: counts the case that ended with $code
  generated_cases=$((generated_cases + 1))
  codes[$code]=$((${codes[$code]:-0} + 1))
  [[ -n ${MPM_FUZZ_VERBOSE:-} ]] && echo "case $1: exit $code: $(head -n 1 "$work/err" | cut -c1-150)"
}
# Starts `mpm ARGUMENTS...` in the background with every stop signal at its default action (a script's background
# job would ignore SIGINT and SIGQUIT, and mpm leaves an ignored signal ignored) and no core file; sets $pid once
# the subshell has become mpm: a signal to the subshell before its exec would run this script's EXIT trap there.
start_mpm() {
  local words tries
  (trap - EXIT INT QUIT; ulimit -c 0; exec "$mpm" "$@") >"$work/stdout" 2>"$work/err" &
  pid=$!
  for ((tries = 0; tries < 1000; ++tries)); do
    mapfile -d '' -t words 2>/dev/null <"/proc/$pid/cmdline" || break  # gone already
    [[ ${#words[@]} -eq 0 || ${words[0]} == "$mpm" ]] && break         # a zombie, or mpm
    sleep 0.001
  done
}
# await PID SECONDS: waits for the process at most that long, then kills it; sets $code and $hung (1: killed).
# (stderr to /dev/null: bash's own "Killed" or "Quit" notice of the process would come while it sleeps)
await() {
  local tenths=$(($2 * 10))
  hung=0
  while kill -0 "$1" && ((tenths-- > 0)); do sleep 0.1; done
  kill -0 "$1" && hung=1 && kill -KILL "$1"
  wait "$1"
  code=$?
} 2>/dev/null
# Sets $delay to a random time below $1 milliseconds, in seconds for sleep.
random_delay() { local ms=$((RANDOM % $1)); printf -v delay '%d.%03d' $((ms / 1000)) $((ms % 1000)); }
# Sets $status to the status in run.json $1 ("" when there is no such file).
status_of() { status=$(sed -n 's/^  "status": "\([a-z]*\)",*$/\1/p' "$1" 2>/dev/null); }
# Sets $steps to the steps in run.json $1 ("" when there is no such file).
steps_of() { steps=$(sed -n 's/^  "steps": \([0-9]*\),*$/\1/p' "$1" 2>/dev/null); }
# Sets $cut to the first of the files given that is not empty and does not end with a newline ("" when none).
cut_csv() {
  local csv
  cut=""
  (($#)) || return
  [[ -z $(tail -q -c 1 -- "$@" 2>/dev/null | tr -d '\n') ]] && return  # the last bytes of all at once: all newlines
  for csv; do
    [[ -s $csv && $(tail -c 1 "$csv" | od -An -c | tr -d ' ') != '\n' ]] && cut=$csv && return
  done
}
# Sets $left to the ids of the processes whose command line holds the text $1 ("" when none).
processes_naming() {
  local file words
  left=""
  for file in /proc/[0-9]*/cmdline; do
    mapfile -d '' -t words 2>/dev/null <"$file" || continue
    [[ "${words[*]}" == *"$1"* ]] && left+=" ${file//[^0-9]/}"
  done
  left=${left# }
}
located='^error: [^:]+:[0-9]+: [^:]+: .+'  # error: FILE:LINE: KEY: why

# 1. Work bombs: a 10-cell bar (E = 100 Pa, rho = 1, c = 10 m/s, end_time 1 s: about 200 steps at rest) whose
# initial velocity, and body force, is a formula drawn from huge, overflowing and singular ones, with walls, up
# to 3000 output times written into the file, a random --max-steps and sometimes --force. Exit 0, 2 or 3 within
# 20 s; 0 and 3 within --max-steps steps (unless --force); 2 located, no folder; 3 `failure: step`.
bomb_velocities=(1e3 1e9 1e300 -1e300 '1e308*x' '-1e12*x*x' 'exp(700)' 'exp(710)' '1e154*1e154' '1e-320' '1/(x-0.5)'
  '1/(x-0.55)' '1/(X-0.45)' 'tan(pi*x/2)' '1e4*sin(pi*x)' '1e5*x' '-1e6*(x-0.5)' 'sqrt(x)*1e2' 'log(x-0.05)'
  'x > 0.3 && x < 0.7 ? 1e9 : 0' '10^(3*x)' 'exp(700*x)')
gentle_velocities=(0 0 1 -3 30 '10*x' '5*sin(pi*x)' 'sin(1e9*x)')  # half the cases: the body force is the bomb
bomb_forces=('' -9.81 30 1e4 '1e3*t' '300*t' '3e3*t' '-1e5*x' '1e5*(x-0.5)' '1e9*t*t' 'exp(1e3*t)' '1/(t-0.01)'
  '1e3*sin(1e4*t)')
bomb_walls=('' xmin xmax 'xmin xmax' 'xmin xmax' 'xmin xmax')
bomb_times=(0 0 0 0 20 100 400 3000)
bomb_limits=(100 200 250 300 400 1000 2000)  # about 200 steps at rest: some limits are met during the run
bomb_case() {  # bomb_case NUMBER
  local number=$1 scene=$work/bomb_$1.toml out=$work/bomb_out_$1 velocity force walls times most face limit end_time
  if ((RANDOM % 2)); then pick bomb_velocities; else pick gentle_velocities; fi
  velocity=$picked
  pick bomb_forces && force=$picked
  pick bomb_walls && walls=$picked
  pick bomb_times && times=$picked
  pick bomb_limits && most=$((picked + RANDOM % 50)) limit=$most
  arguments=(run "$scene" --out "$out" --max-steps "$most")
  # --force lifts the limit: only for 1 ms and without walls, where a fast particle soon leaves the grid
  # (a bar squeezed from both ends, -1e6*(x-0.5), would take its 9 million steps in a second)
  end_time=1.0
  ((RANDOM % 5 == 0)) && arguments+=(--force) && walls="" && limit="" && end_time=1e-3
  {
    printf 'title = "work bomb"\ndimension = 1\n[grid]\nlength = [1.0]\ncells = [10]\n'
    printf '[material]\nyoung_modulus = 100.0\ndensity = 1.0\n[[body]]\nmin = [0.0]\nmax = [1.0]\n'
    for face in $walls; do printf '[[fixed]]\nface = "%s"\ncomponents = ["x"]\n' "$face"; done
    printf '[solver]\nend_time = %s\n[initial_field]\nvelocity = ["%s"]\n' "$end_time" "$velocity"
    [[ -n $force ]] && printf '[body_force]\nacceleration = ["%s"]\n' "$force"
    printf '[[observer]]\nname = "A"\nposition = [0.5]\n[output]\nsnapshots = []\n'
    ((times)) && awk -v n="$times" -v end="$end_time" 'BEGIN { printf "times = ["; for (k = 0; k <= n; k++) printf "%s%.9g", (k ? ", " : ""), k * end / n; print "]" }'
  } >"$scene"
  scene_copy=$scene
  timeout -s KILL 20 "$mpm" "${arguments[@]}" >"$work/stdout" 2>"$work/err"
  code=$?
  count_case "bomb $number"
  steps_of "$out/run.json"
  case $code in
    0) grep -q '"status": "done"' "$out/run.json" 2>/dev/null || report "bomb $number" "exit 0 but run.json does not say done" "${arguments[@]}"
       [[ -n $steps && ( -z $limit || $steps -le $limit ) ]] || report "bomb $number" "exit 0 after $steps steps, past --max-steps $most" "${arguments[@]}" ;;
    2) [[ $(head -n 1 "$work/err") =~ $located ]] || report "bomb $number" "exit 2 without a located message" "${arguments[@]}"
       [[ -e $out ]] && report "bomb $number" "exit 2 but an output folder was made" "${arguments[@]}" ;;
    3) grep -q "^failure: step" "$work/err" || report "bomb $number" "exit 3 without 'failure: step'" "${arguments[@]}"
       [[ -z $steps || -z $limit || $steps -le $limit ]] || report "bomb $number" "exit 3 after $steps steps, past --max-steps $most" "${arguments[@]}" ;;
    137) report "bomb $number" "killed after 20 s: a hang, or a run past its budget" "${arguments[@]}" ;;
    *) report "bomb $number" "exit $code (a signal or an unexpected code)" "${arguments[@]}" ;;
  esac
  rm -rf "$out" "$scene"
}
for ((number = 0; number < generated; ++number)); do bomb_case $number; done

# 2. Stop signals during runs: the Dyka bar of 200 to 400 cells to 2 ms (0.3 to 1 s), into no folder or one
# holding an earlier run's files (a real run's, 2000 more snapshot files beside a run.json saying done, or both),
# sent a random stop signal (sometimes twice at once, as timeout(1) does) after a random delay, often short where
# files are to be removed. Exit 0 or 128 + N within 30 s; exit 0: run.json done, "wrote", and no snapshot of the
# earlier run left; 128 + N with `interrupted: SIGNAME` on stderr: run.json interrupted; without (the default
# action, before the run began writing): no run.json of its own. Never "running" or "clearing" left; every CSV
# ends with a newline.
signal_names=(HUP INT QUIT TERM ALRM USR1 USR2 XCPU VTALRM PROF)
signal_cells=(200 300 400)
earlier_files() {  # made once: an earlier run of three snapshots, and 2000 snapshot files (slow to create on some disks)
  "$mpm" run "$root/scenes/dyka_bar.toml" --out "$work/earlier" --set solver.end_time=1e-5 \
    --set 'output.snapshots=[0.0, 5e-6, 1e-5]' >/dev/null 2>&1 || echo "fuzz_cli: the earlier run failed"
  mkdir -p "$work/old"
  awk -v folder="$work/old" 'BEGIN { for (k = 100; k < 2100; k++) {
    file = sprintf("%s/snapshot_%04d.%s", folder, k, k % 4 ? "csv" : "vtp"); print "id,x\n0,0" > file; close(file) } }'
}
signal_run_case() {  # signal_run_case NUMBER
  local number=$1 out=$work/signalled_run kept name signal twice cells snapshots count file index what
  rm -rf "$out"
  case $((RANDOM % 4)) in  # the old files are hard links (cp -al): quick, and never written, only removed
    0) kept="no folder" ;;
    1) kept="an earlier run" && cp -r "$work/earlier" "$out" ;;
    2) kept="2000 old snapshots" && cp -al "$work/old" "$out" && printf '{\n  "status": "done"\n}\n' >"$out/run.json" ;;
    3) kept="an earlier run and 2000 old snapshots" && cp -r "$work/earlier" "$out" && cp -al "$work/old/." "$out/" ;;
  esac
  pick signal_names && name=$picked
  pick signal_cells && cells=$picked
  if ((RANDOM % 2)); then snapshots='[]' count=0; else snapshots='[0.0, 1e-3]' count=2; fi
  if [[ $kept != "no folder" ]] && ((RANDOM % 2)); then random_delay 80; else random_delay 800; fi
  twice=$((RANDOM % 4 == 0))
  arguments=(run "$root/scenes/dyka_bar.toml" --out "$out" --set solver.end_time=2e-3 --set "grid.cells=[$cells]"
    --set "output.snapshots=$snapshots")
  start_mpm "${arguments[@]}"
  sleep "$delay"
  kill -s "$name" "$pid" 2>/dev/null
  ((twice)) && kill -s "$name" "$pid" 2>/dev/null
  await "$pid" 30
  signal=$(kill -l "$name")
  what="SIG$name" && ((twice)) && what+=" twice"
  what+=" after $delay s into $kept"
  count_case "signalled run $number, $what"
  scene_copy=""
  status_of "$out/run.json"
  ((hung)) && report "signalled run $number" "$what: still running after 30 s" "${arguments[@]}"
  if ((code == 0)); then
    [[ $status == "done" ]] || report "signalled run $number" "$what: exit 0, run.json says '$status'" "${arguments[@]}"
    grep -q "^wrote " "$work/stdout" || report "signalled run $number" "$what: exit 0 without 'wrote'" "${arguments[@]}"
    for file in "$out"/snapshot_* "$out"/exact_[0-9]*; do  # the new run's are NNNN < $count
      index=${file##*_} && index=${index%%.*}
      [[ ! -e $file ]] || { [[ $index =~ ^[0-9]{4}$ ]] && ((10#$index < count)); } && continue
      report "signalled run $number" "$what: $file of the earlier run left beside run.json done" "${arguments[@]}" && break
    done
  elif ((code == 128 + signal)); then
    if grep -q "^interrupted: SIG$name" "$work/err"; then
      [[ $status == interrupted ]] || report "signalled run $number" "$what: interrupted, run.json says '$status'" "${arguments[@]}"
    elif [[ $status != "" && ! ($status == "done" && $kept != "no folder") ]]; then
      report "signalled run $number" "$what: ended by the signal without a word, run.json says '$status'" "${arguments[@]}"
    fi
  elif ((!hung)); then
    report "signalled run $number" "$what: exit $code, want 0 or $((128 + signal))" "${arguments[@]}"
  fi
  [[ $status == running || $status == clearing ]] && report "signalled run $number" "$what: run.json says $status after the run ended" "${arguments[@]}"
  cut_csv "$out"/*.csv
  [[ -n $cut ]] && report "signalled run $number" "$what: $cut does not end with a newline" "${arguments[@]}"
  rm -rf "$out"
}
earlier_files
for ((number = 0; number < generated; ++number)); do signal_run_case $number; done

# 3. Stop signals during studies: a study of 4 to 6 Dyka bars (100 to 320 cells, 2 ms), --jobs 2, sent SIGTERM,
# SIGINT or SIGHUP after a random delay, or SIGKILL. Within 60 s it exits 128 + N (or 0, finished first); no
# process naming the study's folder is left (after SIGKILL, its runs get SIGTERM from PR_SET_PDEATHSIG: 5 s to
# end); no study.csv after a stop signal; no case's run.json says "running" or "clearing"; every CSV is whole.
study_signals=(TERM INT HUP TERM INT HUP KILL)
signal_study_case() {  # signal_study_case NUMBER
  local number=$1 out=$work/signalled_study_$1 study=$work/study_$1.toml n k cells="" name signal json what
  n=$((4 + RANDOM % 3))
  for ((k = 0; k < n; ++k)); do cells+="${cells:+, }[$((100 + 40 * k + RANDOM % 20))]"; done
  printf 'scene = "%s"\n[set]\nsolver.end_time = 2.0e-3\noutput.snapshots = []\n[axes]\ngrid.cells = [%s]\n' \
    "$root/scenes/dyka_bar.toml" "$cells" >"$study"
  pick study_signals && name=$picked
  random_delay 1500
  arguments=(study "$study" --out "$out" --jobs 2)
  start_mpm "${arguments[@]}"
  sleep "$delay"
  kill -s "$name" "$pid" 2>/dev/null
  await "$pid" 60
  signal=$(kill -l "$name")
  what="SIG$name after $delay s"
  count_case "signalled study $number, $what"
  scene_copy=$study
  ((hung)) && report "signalled study $number" "$what: still running after 60 s" "${arguments[@]}"
  for ((k = 0; k < 50; ++k)); do  # at once after a stop signal (the study waits for its runs); 5 s after SIGKILL
    processes_naming "$out"
    [[ -z $left || $name != KILL ]] && break
    sleep 0.1
  done
  if [[ -n $left ]]; then
    report "signalled study $number" "$what: processes left: $(for k in $left; do tr '\0' ' ' <"/proc/$k/cmdline"; echo; done 2>/dev/null | head -c 400)" "${arguments[@]}"
    kill -KILL $left 2>/dev/null
  fi
  if ((code == 0)); then
    [[ -s $out/study.csv ]] || report "signalled study $number" "$what: exit 0 without study.csv" "${arguments[@]}"
  elif ((code == 128 + signal)); then
    [[ $name != KILL && -e $out/study.csv ]] && report "signalled study $number" "$what: exit $code but study.csv written" "${arguments[@]}"
  elif ((code != 0 && !hung)); then
    report "signalled study $number" "$what: exit $code, want 0 or $((128 + signal))" "${arguments[@]}"
  fi
  for json in "$out"/cases/*/run.json; do
    status_of "$json"
    [[ $status == running || $status == clearing ]] && report "signalled study $number" "$what: $json says $status" "${arguments[@]}" && break
  done
  cut_csv "$out"/cases/*/*.csv
  [[ -n $cut ]] && report "signalled study $number" "$what: $cut does not end with a newline" "${arguments[@]}"
  rm -rf "$out" "$study"
}
for ((number = 0; number < generated; ++number)); do signal_study_case $number; done

# 4. Links and dotted names: a study's cases/NNNN a link to a folder holding a canary observers.csv, a dangling
# link or a file; cases/ itself a link to that folder; cases/NNNN/observers.csv or a run's output file a link to
# the canary; a scene or study named `...toml` or `..toml` run without --out in a scratch folder. Exit 2 within
# 20 s, `error: ` naming the path or file on the first line, the canary and every listing unchanged.
link_kinds=(case-link case-dangling case-file cases-link case-inner-link run-link dotted-run dotted-study)
run_outputs=(run.json observers.csv energy.csv grid.csv exact.csv snapshot_0000.csv snapshot_0001.vtp snapshots.pvd)
dotted_names=(...toml ..toml)
links_case() {  # links_case NUMBER
  local number=$1 base=$work/links kind index path before after program=$mpm
  local out=$base/out canary=$base/canary scratch=$base/scratch study=$base/tiny.toml
  rm -rf "$base" && mkdir -p "$canary" "$scratch"
  printf 'canary\n' >"$canary/observers.csv"
  printf 'scene = "%s"\n[set]\nsolver.end_time = 1.0e-5\noutput.snapshots = []\n[axes]\ngrid.cells = [[10], [20], [40]]\n' \
    "$root/scenes/dyka_bar.toml" >"$study"
  pick link_kinds && kind=$picked
  printf -v index '%04d' $((RANDOM % 5))  # the study has cases 0000 to 0002
  arguments=(study "$study" --out "$out" --jobs 2)
  path=$out/cases/$index
  case $kind in
    case-link) mkdir -p "$out/cases" && ln -s "$canary" "$path" ;;
    case-dangling) mkdir -p "$out/cases" && ln -s "$base/nothing" "$path" ;;
    case-file) mkdir -p "$out/cases" && : >"$path" ;;
    cases-link) mkdir -p "$out" && ln -s "$canary" "$out/cases" && path=$out/cases ;;
    case-inner-link) mkdir -p "$path" && ln -s "$canary/observers.csv" "$path/observers.csv" && path+=/observers.csv ;;
    run-link) pick run_outputs && mkdir -p "$out" && ln -s "$canary/observers.csv" "$out/$picked" && path=$out/$picked
      arguments=(run "$root/scenes/dyka_bar.toml" --out "$out" --set solver.end_time=1e-5 --set 'output.snapshots=[]') ;;
    dotted-*) pick dotted_names && path=$picked
      if [[ $kind == dotted-run ]]; then cp "$root/scenes/dyka_bar.toml" "$scratch/$path" && arguments=(run "$path" --set solver.end_time=1e-5)
      else cp "$study" "$scratch/$path" && arguments=(study "$path" --jobs 2); fi ;;
  esac
  before=$(cd "$base" && ls -lAR --time-style=+ . && cat canary/observers.csv)
  [[ $program == */* && $program != /* ]] && program=$PWD/$program  # run from the scratch folder
  (cd "$scratch" && exec timeout -s KILL 20 "$program" "${arguments[@]}") >"$work/stdout" 2>"$work/err"
  code=$?
  count_case "links $number, $kind ${path#"$work"/}"
  after=$(cd "$base" && ls -lAR --time-style=+ . && cat canary/observers.csv)
  scene_copy=""
  [[ $kind == dotted-* ]] && kind+=" (run in an empty folder, no --out)"
  [[ $code -eq 2 ]] || report "links $number" "$kind: exit $code, want 2" "${arguments[@]}"
  [[ $(head -n 1 "$work/err") == "error: "*"$path"* ]] || report "links $number" "$kind: the first line of stderr is not 'error: ...$path...'" "${arguments[@]}"
  [[ $before == "$after" ]] || report "links $number" "$kind: files changed: $(diff <(echo "$before") <(echo "$after") | tr '\n' '|' | head -c 300)" "${arguments[@]}"
  rm -rf "$base"
}
for ((number = 0; number < generated; ++number)); do links_case $number; done
cases=$((cases + generated_cases))
summary=""
for code in "${!codes[@]}"; do summary+=" exit $code: ${codes[$code]};"; done
echo "fuzz_cli: $cases cases (seed $seed) in $((SECONDS - start)) s:$summary $failures failed"
[[ $failures -eq 0 ]]
