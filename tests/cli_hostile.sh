#!/usr/bin/env bash
# Hostile inputs and folders, as an attacker or a careless user would give them:
#   - nothing runs from data: a CSV header name closing gnuplot's quotes (observers.csv, energy.csv, exact.csv),
#     an output path starting with '|', a newline in `compare --plot PATH`;
#   - no file written through a symbolic link (plot.gp, plot.log, observers.png, compare's picture);
#   - "wrote" only over a whole picture: a folder in the way of a PNG is exit 3 `cannot write`;
#   - inputs that are not regular files (FIFO, device, folder, /proc/self/mem) refused at once with exit 2,
#     a line over 1 MiB refused, a UTF-8 byte-order mark skipped.
# Every command runs under `timeout 10`: a hang is a failure, not a stuck test. Usage: cli_hostile.sh MPM
set -u
mpm=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")  # absolute: some cases run in another folder
scenes=$(cd "$(dirname "$0")/.." && pwd)/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# expect CODE PATTERN -- ARGS...: `mpm ARGS` exits CODE within 10 s, stderr matching PATTERN ("" for any)
expect() {
  local code=$1 pattern=$2; shift 3
  timeout 10 "$mpm" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [[ $got -ne $code ]] || { [[ -n $pattern ]] && ! grep -qE -- "$pattern" "$work/err"; }; then
    fail "mpm $(printf '%q ' "$@")-> exit $got (want $code), stderr: $(head -c 300 "$work/err")"
  fi
}
bar=$scenes/dyka_bar.toml
disks=$scenes/colliding_disks.toml
payload() { printf "%s' . system('touch %s') . '" "$1" "$work/$2"; }  # a name that closes gnuplot's quote, then a command

# --- nothing runs from data ----------------------------------------------------------------------
if command -v gnuplot >/dev/null; then
  mkdir "$work/inject_observers" "$work/inject_energy" "$work/inject_exact"
  printf 't,%s\n0,1\n1,2\n' "$(payload A.x pwned_observers)" >"$work/inject_observers/observers.csv"
  printf 't,kinetic,%s\n0,1,2\n1,2,3\n' "$(payload momentum_x pwned_energy)" >"$work/inject_energy/energy.csv"
  printf 't,A.v_x,%s\n0,1,2\n1,2,3\n' "$(payload A.v_y pwned_exact)" >"$work/inject_exact/observers.csv"
  cp "$work/inject_exact/observers.csv" "$work/inject_exact/exact.csv"
  for folder in inject_observers inject_energy inject_exact; do
    expect 0 "" -- plot "$work/$folder"
    grep -q "^wrote $work/$folder/" "$work/out" || fail "plot $folder: no wrote: $(cat "$work/out")"
    grep -q "''touch" "$work/$folder/plot.gp" || fail "plot $folder: the header's quote is not doubled in plot.gp"
    (cd "$work/$folder" && timeout 10 gnuplot plot.gp 2>/dev/null)  # the script kept, rerun by hand: still harmless
  done
  for name in pwned_observers pwned_energy pwned_exact; do [[ -e $work/$name ]] && fail "a header ran a command: $name exists"; done
  mkdir "$work/pipe"
fi
# the CSV of compare (the Dyka bar at X = L/2, times within L/4 < ct < 3L/4)
awk 'BEGIN { c = sqrt(200e9 / 7833); L = 0.1333; print "step,time,label,vel"
  for (n = 1; n <= 20; n++) printf "%d,%.17g,x,%.17g\n", n, (L / 4 + L / 2 * n / 21) / c, -2.4 }' >"$work/other.csv"
compare_args=("$bar" --at 0.06665 --time-column time --column vel=v_x)
if command -v gnuplot >/dev/null; then  # a relative path starting with | is a file, not a pipe to a shell
  (cd "$work/pipe" && timeout 10 "$mpm" compare "$work/other.csv" "${compare_args[@]}" --plot "|touch pwned_pipe.png" >/dev/null 2>"$work/err") ||
    fail "compare --plot '|touch pwned_pipe.png': $(cat "$work/err")"
  [[ -e "$work/pipe/pwned_pipe.png" ]] && fail "compare --plot '|...' ran a shell command"
  [[ -s "$work/pipe/|touch pwned_pipe.png" ]] || fail "compare --plot '|...' wrote no file of that name"
fi
expect 2 "^error: --plot: the path holds a control character" -- compare "$work/other.csv" "${compare_args[@]}" \
  --plot "$work/a
set output '$work/pwned_newline.png'
b.png"
[[ -s $work/out || -e "$work/pwned_newline.png" ]] && fail "compare --plot with a newline wrote something"
expect 2 "^error: --column: a column name holds a control character" -- compare "$work/other.csv" "$bar" --at 0 --column "$(printf 'v\tx')=v_x"
mkdir "$work/control"
printf 't,A.v\tx\n0,1\n' >"$work/control/observers.csv"
expect 2 "^error: $work/control/observers.csv:1: column 2: its name holds a control character" -- plot "$work/control"
[[ -e "$work/control/plot.gp" ]] && fail "plot wrote plot.gp for a refused header"
expect 2 "^error: plot: the folder's name holds a control character" -- plot "$work/a
b"

# --- no file written through a symbolic link; "wrote" only over a whole picture ------------------
if command -v gnuplot >/dev/null; then
  mkdir "$work/linked"
  printf 't,A.v_x\n0,1\n1,2\n' >"$work/linked/observers.csv"
  for name in plot.gp plot.log observers.png; do
    echo precious >"$work/victim_$name"
    ln -s "$work/victim_$name" "$work/linked/$name"
  done
  ln -s "$work/linked" "$work/linked_folder"  # the folder itself may be a link
  expect 0 "" -- plot "$work/linked_folder"
  for name in plot.gp plot.log observers.png; do
    [[ $(cat "$work/victim_$name") == precious ]] || fail "plot wrote through the link $name"
    [[ -L "$work/linked/$name" ]] && fail "$name is still a link"
  done
  [[ -f "$work/linked/plot.gp" && -s "$work/linked/observers.png" ]] || fail "plot of a linked folder: no plot.gp or picture"
  echo precious >"$work/victim_compare"
  ln -s "$work/victim_compare" "$work/link.png"
  expect 0 "^wrote $work/link.png" -- compare "$work/other.csv" "${compare_args[@]}" --plot "$work/link.png"
  [[ $(cat "$work/victim_compare") == precious ]] || fail "compare --plot wrote through a link"
  [[ -L "$work/link.png" ]] && fail "compare --plot left the link"
  # a folder in the way of a picture: exit 3 `cannot write`, never "wrote"
  mkdir -p "$work/blocked/observers.png/inside"
  printf 't,A.v_x\n0,1\n1,2\n' >"$work/blocked/observers.csv"
  expect 3 "^error: $work/blocked/observers.png: cannot write" -- plot "$work/blocked"
  grep -q wrote "$work/out" && fail "plot said wrote with a folder in the way"
else
  echo "cli_hostile: gnuplot missing: its cases skipped"
fi

# --- inputs that are not regular files: refused at once, exit 2 ----------------------------------
mkfifo "$work/fifo.csv"
expect 2 "^error: $work/fifo.csv: not a regular file" -- compare "$work/fifo.csv" "${compare_args[@]}"
expect 2 "^error: --times-file $work/fifo.csv: not a regular file" -- exact "$bar" --at 0 --times-file "$work/fifo.csv"
expect 2 "^error: .*body\[0\].file: $work/fifo.csv: not a regular file" -- run "$disks" --print-scene --set 'body[0].shape="file"' \
  --set "body[0].file=\"$work/fifo.csv\""
mkdir "$work/fifo_run"
mkfifo "$work/fifo_run/observers.csv"
expect 2 "^error: $work/fifo_run/observers.csv: not a regular file" -- plot "$work/fifo_run"
mkdir "$work/zero_run"
ln -s /dev/zero "$work/zero_run/observers.csv"  # endless, without a newline
expect 2 "^error: $work/zero_run/observers.csv: not a regular file \(a device\)" -- plot "$work/zero_run"
expect 2 "^error: --times-file $work: is a folder, not a regular file" -- exact "$bar" --at 0 --times-file "$work"
expect 2 "^error: --times-file /proc/self/mem: not a regular file" -- exact "$bar" --at 0 --times-file /proc/self/mem
grep -q "internal error" "$work/err" && fail "/proc/self/mem: internal error"
# a header line of 2 MB: refused, in bounded memory (at most 256 MB resident, what a sanitized build needs)
mkdir "$work/long_run"
{ printf 't'; head -c 2000000 /dev/zero | tr '\0' 'x'; printf '\n0\n'; } >"$work/long_run/observers.csv"
expect 2 "^error: $work/long_run/observers.csv:1: a line longer than 1 MiB" -- plot "$work/long_run"
/usr/bin/time -f %M -o "$work/kib" timeout 10 "$mpm" plot "$work/long_run" >/dev/null 2>&1
[[ $(tail -1 "$work/kib") -le 262144 ]] || fail "plot of a 2 MB header line took $(tail -1 "$work/kib") KiB"

# --- a UTF-8 byte-order mark (as spreadsheets write) is skipped ------------------------------------
printf '\xef\xbb\xbf0\n1e-5\n' >"$work/bom_times.txt"
expect 0 "" -- exact "$bar" --at 0 --times-file "$work/bom_times.txt"
[[ $(wc -l <"$work/out") -eq 3 ]] || fail "times file with a BOM: $(($(wc -l <"$work/out") - 1)) rows, want 2 (the first time kept)"
{ printf '\xef\xbb\xbf'; cut -d, -f2,4 "$work/other.csv"; } >"$work/bom_other.csv"  # the time column first, after the mark
expect 0 "" -- compare "$work/bom_other.csv" "${compare_args[@]}"
grep -q "^vel,v_x,20," "$work/out" || fail "compare CSV with a BOM: $(cat "$work/out")"
printf '\xef\xbb\xbfx,y,volume\n0.1,0.1,0.001\n' >"$work/bom_particles.csv"
expect 0 "" -- run "$disks" --print-scene --set 'body[0].shape="file"' --set "body[0].file=\"$work/bom_particles.csv\""

# Content gnuplot cannot draw is the user's mistake (exit 2 before any picture), not gnuplot's failure.
odd() {  # odd NAME HEADER-AND-ROWS: a folder whose observers.csv holds them
  mkdir -p "$work/odd_$1" && printf "$2" >"$work/odd_$1/observers.csv"
}
odd nothing 't,foo\n0,1\n'
odd header_only 't,A.x\n'
odd words 't,A.x\n0,abc\n'
odd panels "t$(for q in $(seq 0 999); do printf ',A.q%d' "$q"; done)\n0$(for q in $(seq 0 999); do printf ',1'; done)\n"
expect 2 "observers.csv: 0 quantities" -- plot "$work/odd_nothing"
expect 2 "observers.csv: has a header but no data row" -- plot "$work/odd_header_only"
expect 2 "observers.csv:2: A.x: 'abc' is not a number" -- plot "$work/odd_words"
expect 2 "observers.csv: 1000 quantities .* at most 16" -- plot "$work/odd_panels"
ls "$work"/odd_*/*.png >/dev/null 2>&1 && fail "a refused plot left a picture"
# compare --plot onto a folder: refused before anything is printed; a column named twice is ambiguous.
mkdir -p "$work/folder.png"
expect 2 "^error: --plot: .*folder.png: give a .png file \(not a folder\)" -- compare "$work/other.csv" "$bar" --at 0 \
  --column vel=v_x --time-column time --plot "$work/folder.png"
[[ -s "$work/out" ]] && fail "compare printed its scores before refusing --plot"
printf 'time,v,v\n0,1,2\n' >"$work/twice.csv"
expect 2 "column 'v' appears more than once" -- compare "$work/twice.csv" "$bar" --at 0 --column v=v_x --time-column time

[[ $failures -eq 0 ]] && echo "cli_hostile: all passed"
exit $((failures > 0))
