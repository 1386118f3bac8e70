#!/usr/bin/env bash
# One number for one run, and the profiles beside each snapshot:
#   - a default run of scenes/dyka_bar.toml reproduces, from its own files, the RMS of Eq. (43) that
#     paper/08_test_cases.md prints for it (linear FE, 40 cells), and the LME NPC run the paper's method's;
#     the numbers are read from the book's check markers, never typed here; exact.csv is the solution at
#     particle A's reference position h/2, where the book scores it (the RMS from observers.csv against
#     exact.csv is mpm compare's);
#   - exact_NNNN.csv beside each snapshot (the exact solution at every particle's X), grid.csv;
#   - mpm plot draws profile_NNNN.png (1D: v and sigma against the exact profile; 2D: coloured by --field
#     over the grid lines), with the labels and units promised, one time axis, round-off drawn flat;
#     a bad --field is refused (exit 2) before anything is written, and no string runs in gnuplot.
# Usage: cli_profiles.sh MPM
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
bar=$root/scenes/dyka_bar.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
has() { grep -qF -- "$2" "$1" || fail "$1 lacks: $2"; }
png() { [[ "$(head -c 4 "$1" 2>/dev/null | tail -c 3)" == "PNG" ]] || fail "$1 is not a PNG"; }

# book_number SELECTOR: the number paper/08_test_cases.md prints before <!-- check dyka_sweep.csv SELECTOR -->
book_number() {
  grep -o "[0-9.]*<!-- check dyka_sweep.csv $1 : rms_over_v0 -->" "$root/paper/08_test_cases.md" | head -1 |
    sed 's/<!--.*//'
}
# rounds_to GOT QUOTED: GOT rounded to QUOTED's decimals is QUOTED
rounds_to() {
  awk -v g="$1" -v q="$2" 'BEGIN { n = split(q, p, "."); d = n > 1 ? length(p[2]) : 0
    h = 0.5 * 10 ^ -d; e = g - q; if (e < 0) e = -e; exit !(q != "" && e <= h * (1 + 1e-9)) }'
}
# rms_of FOLDER: rms_normalised of mpm compare on the folder's observers.csv at particle A's X (run.json)
rms_of() {
  local X
  X=$(python3 -c "import json, sys; print(repr(json.load(open(sys.argv[1]))['observed'][0]['reference_position'][0]))" \
    "$1/run.json") || { fail "$1/run.json: no observed particle"; return; }
  "$mpm" compare "$1/observers.csv" "$bar" --at "$X" --column A.v_x=v_x | awk -F, 'NR == 2 { print $5 }'
}

# --- one number for one run --------------------------------------------------------------------
"$mpm" run "$bar" --out "$work/bar" >/dev/null || fail "the default Dyka run"
"$mpm" run "$bar" --out "$work/lme" --set 'solver.shape="lme"' --set 'solver.integrator="npc"' >/dev/null ||
  fail "the LME NPC Dyka run"
for case in "bar shape=linear integrator=fe cells=40" "lme shape=lme integrator=npc cells=40"; do
  folder=${case%% *} selector=${case#* }
  quoted=$(book_number "$selector")
  got=$(rms_of "$work/$folder")
  [[ -n $quoted ]] || fail "paper/08_test_cases.md quotes no RMS for $selector"
  rounds_to "$got" "$quoted" || fail "$folder ($selector): the run's files give $got, the book says $quoted"
done
# exact.csv is what the report scores against: the RMS of observers.csv's A.v_x against exact.csv's, row by row
paste -d, "$work/bar/observers.csv" "$work/bar/exact.csv" | awk -F, -v want="$(rms_of "$work/bar")" '
  NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "A.v_x" && !v) v = i; else if ($i == "A.v_x") e = i } next }
  { s += ($v - $e) ^ 2; n++ }
  END { r = sqrt(s / n) / 5; d = r - want; if (d < 0) d = -d
        if (!(n == 608 && d < 1e-8)) { print r, want, n; exit 1 } }' ||
  fail "observers.csv against exact.csv is not mpm compare's RMS at particle A's reference position"

# --- exact_NNNN.csv beside each snapshot, grid.csv --------------------------------------------
for n in 0000 0001; do
  [[ -s "$work/bar/snapshot_$n.csv" ]] || fail "no snapshot_$n.csv"
  [[ "$(head -1 "$work/bar/exact_$n.csv")" == "id,X,u_x,v_x,sigma_xx" ]] || fail "exact_$n.csv: wrong header"
  [[ $(wc -l <"$work/bar/exact_$n.csv") -eq 41 ]] || fail "exact_$n.csv: not one row per particle"
done
# at t = 0 the quarter X <= L/4 (particles 0-9) moves at -5 m/s, the rest rests, unstressed, undisplaced
awk -F, 'NR > 1 && !($3 == 0 && $4 == ($1 < 10 ? -5 : 0) && $5 == 0) { exit 1 }' "$work/bar/exact_0000.csv" ||
  fail "exact_0000.csv is not the initial data"
# the particles' reference positions: X = (id + 1/2) h
awk -F, 'NR > 1 { d = $2 - ($1 + 0.5) * 0.1333 / 40; if (d * d > 1e-24) exit 1 }' "$work/bar/exact_0001.csv" ||
  fail "exact_0001.csv: X is not each particle's reference position"
[[ "$(head -1 "$work/bar/grid.csv")" == "x_min,x_max,x_cells" ]] || fail "grid.csv: wrong header"
awk -F, 'NR == 2 { exit !(($1 + 0.01333) ^ 2 < 1e-20 && $2 == 0.1333 && $3 == 44) }' "$work/bar/grid.csv" ||
  fail "grid.csv: $(sed -n 2p "$work/bar/grid.csv"), want the 4 margin cells below 0 and 40 cells to L"

# --- mpm plot: 1D ---------------------------------------------------------------------------------
"$mpm" plot "$work/bar" >"$work/out" 2>"$work/err" || fail "mpm plot of the Dyka run: $(cat "$work/err")"
for picture in observers.png energy.png profile_0000.png profile_0001.png; do png "$work/bar/$picture"; done
gp=$work/bar/plot.gp
has "$gp" "set ylabel 'velocity v_x (m/s)'"
has "$gp" "set ylabel 'stress sigma_xx (Pa, tension > 0)'"
has "$gp" "set ylabel 'displacement u_x since t = 0 (m)'"
has "$gp" "set ylabel 'position x (m)'"
has "$gp" "set ylabel 'momentum (kg/(m s): per unit cross-section area)'"
has "$gp" "set ylabel 'energy (J/m^2: per unit cross-section area)'"
has "$gp" "set xlabel 'position x (m)'"
has "$gp" "set rmargin at screen 0.78"
has "$gp" "set xrange [0:0.00020000000000000001]"  # every panel from t = 0 to the end
has "$gp" "'exact_0001.csv' using (column(2) + column(3)):4 smooth unique"
has "$gp" "title 'snapshot 0001, t = 0.0002 s'"
has "$gp" "set arrow from first 0, graph 0 to first 0, graph 1 nohead back"  # the node at the free end
grep -q "wrote $work/bar/profile_0001.png" "$work/out" || fail "mpm plot does not say it wrote profile_0001.png"

# --- mpm plot: 2D, --field ------------------------------------------------------------------------
"$mpm" run "$root/scenes/soil_block.toml" --out "$work/block" --set solver.end_time=1.0 \
  --set 'output.snapshots=[0.0, 1.0]' >/dev/null || fail "a short soil block run"
[[ "$(head -1 "$work/block/exact_0001.csv")" == "id,X,Y,u_x,u_y,v_x,v_y,sigma_xx,sigma_yy,sigma_xy" ]] ||
  fail "2D exact_0001.csv header: $(head -1 "$work/block/exact_0001.csv")"
[[ "$(sed -n 2p "$work/block/grid.csv")" == "0,10,5,0,10,5" ]] || fail "2D grid.csv: $(tail -1 "$work/block/grid.csv")"
"$mpm" plot "$work/block" --field nope >"$work/out" 2>"$work/err"
[[ $? -eq 2 ]] && grep -q "^error: --field: 'nope' is not a column of $work/block/snapshot_0000.csv" "$work/err" ||
  fail "a bad --field: $(cat "$work/err")"
ls "$work/block" | grep -qE '\.png$|plot\.gp' && fail "a refused --field wrote a picture or plot.gp"
"$mpm" plot "$work/block" --field "x' . system('touch $work/F') . '" >/dev/null 2>&1
[[ $? -eq 2 && ! -e $work/F ]] || fail "a --field closing gnuplot's quotes"
"$mpm" plot "$work/block" --field sigma_yy >"$work/out" 2>"$work/err" || fail "--field sigma_yy: $(cat "$work/err")"
for picture in profile_0000.png profile_0001.png; do png "$work/block/$picture"; done
gp=$work/block/plot.gp
has "$gp" "set cblabel 'stress sigma_yy (Pa, tension > 0)'"
has "$gp" "plot 'snapshot_0001.csv' using 2:3:7 with points pt 7 ps 0.6 palette"
has "$gp" "set title 'exact at X + u'"
has "$gp" "set arrow from graph 0, first 2 to graph 1, first 2 nohead back"  # a grid line y = 2 m
has "$gp" "set ylabel 'momentum (kg/s: per unit thickness)'"

# --- round-off drawn flat; a hostile snapshot header stays a string -----------------------------
mkdir "$work/flat"
printf 't,A.v_x\n0,4.49999999\n1,4.50000001\n' >"$work/flat/observers.csv"
printf "id,x,y,s' . system('touch %s/G') . '\n0,0.5,0.5,1\n1,0.6,0.5,2\n" "$work" >"$work/flat/snapshot_0000.csv"
"$mpm" plot "$work/flat" --field "s' . system('touch $work/G') . '" >/dev/null 2>"$work/err" ||
  fail "plot of a flat history and a hostile snapshot: $(cat "$work/err")"
has "$work/flat/plot.gp" "set yrange [4.49999549999999:4.50000450000001]"
has "$work/flat/plot.gp" "set cblabel 's'' . system(''touch"
[[ -e $work/G ]] && fail "a snapshot's column name ran a command in gnuplot"
png "$work/flat/profile_0000.png"

if [[ $failures -gt 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "profiles and the book's number: all checks passed"
