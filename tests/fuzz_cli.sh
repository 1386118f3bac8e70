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
# range or order): exit 0, 2 or 3 within 10 s, nothing run.
#
#   bash tests/fuzz_cli.sh build/bin/mpm [CASES] [SEED]
# CASES defaults to $MPM_FUZZ_CASES or 300 (what `make test` runs); SEED to $MPM_FUZZ_SEED or 11.
# The same seed gives the same cases. Failing cases are printed with a command that reproduces them;
# MPM_FUZZ_KEEP=DIR keeps their scene files there.
set -u
mpm=$1
cases=${2:-${MPM_FUZZ_CASES:-300}}
seed=${3:-${MPM_FUZZ_SEED:-11}}
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
# observers.csv): not regular files, a byte-order mark, a line over 1 MiB, a header name that closes
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
  for reader in times compare particles plot; do
    mkdir -p "$work/hostile"
    file=$work/hostile/observers.csv
    hostile $class "$file"
    case $reader in
      times) arguments=(exact "$root/scenes/dyka_bar.toml" --at 0 --times-file "$file") ;;
      compare) arguments=(compare "$file" "$root/scenes/dyka_bar.toml" --at 0 --column A.v_x=v_x) ;;
      particles) arguments=(run "$root/scenes/colliding_disks.toml" --print-scene --set 'body[0].shape="file"' --set "body[0].file=\"$file\"") ;;
      plot) arguments=(plot "$work/hostile") ;;
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
summary=""
for code in "${!codes[@]}"; do summary+=" exit $code: ${codes[$code]};"; done
echo "fuzz_cli: $cases cases (seed $seed) in $((SECONDS - start)) s:$summary $failures failed"
[[ $failures -eq 0 ]]
