#!/usr/bin/env bash
# verification/figure.sh's draw_figure, the wrapper of every figure of make figures and make studies: it draws a
# figure in the shared style (common.gp, output.gp), and fails on a gnuplot warning (here an empty data file), on a
# legend entry whose curve has no data (every row filtered out), and on a figure wider than 1600 px; a keyentry line
# (a legend entry that only explains a style) and an untitled empty curve pass.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/plots" "$work/data"
cp "$root"/verification/plots/{palette,common,output}.gp "$work/plots/"
printf 't,v\n0,1\n1,2\n' >"$work/data/ok.csv"
printf 't,v\n' >"$work/data/empty.csv"
figure() {  # figure NAME WIDTH PLOT: a figure script plotting PLOT
  printf 'load dir."/common.gp"\nw = %s; h = 3\ndraw = "plot %s"\nload dir."/output.gp"\n' "$2" "$3" >"$work/plots/$1.gp"
}
ok="'\".\$data.\"/ok.csv' using 1:2 with lines \".method_line('lme', 'npc').\" title 'LME'"
figure good 6 "$ok, keyentry with lines @exact_style title 'exact', '\".\$data.\"/ok.csv' using 1:(\$2 > 5 ? \$2 : NaN) notitle"
figure empty_file 6 "$ok, '\".\$data.\"/empty.csv' using 1:2 with lines title 'nothing'"
figure empty_entry 6 "$ok, '\".\$data.\"/ok.csv' using 1:(\$2 > 5 ? \$2 : NaN) with points title 'stopped'"
figure wide 14 "$ok"
sed -i 's/\$data/data/g' "$work"/plots/*.gp
plots=$work/plots data=$work/data
source "$root/verification/figure.sh"
failures=0
expect() {  # expect RC NAME
  draw_figure "$2.gp" "out='$work/$2'" 2>"$work/$2.log"
  local rc=$?
  if [[ $rc != "$1" ]]; then echo "FAIL: $2 returned $rc, expected $1"; cat "$work/$2.log"; failures=$((failures + 1)); fi
}
expect 0 good
[[ -s $work/good.png && -s $work/good.pdf ]] || { echo "FAIL: good drew no PNG and PDF"; failures=$((failures + 1)); }
expect 1 empty_file
grep -q "no valid points" "$work/empty_file.log" || { echo "FAIL: the warning is not shown"; failures=$((failures + 1)); }
expect 1 empty_entry
grep -q "legend entries with no data: \"stopped\"" "$work/empty_entry.log" ||
  { echo "FAIL: the empty legend entry is not named"; cat "$work/empty_entry.log"; failures=$((failures + 1)); }
expect 1 wide
# tests/figure_style.py on a tree with one figure script that sets a colour and a small font of its own, and one
# shell script that runs gnuplot itself: each offence named, exit 1.
mkdir -p "$work/tree/verification/plots"
cp "$work/plots/good.gp" "$work/tree/verification/plots/"
printf 'load dir."/common.gp"\nw = 6; h = 3\ndraw = "set key font \x27,8\x27; plot x lc rgb \x27#123456\x27"\nload dir."/output.gp"\n' \
  >"$work/tree/verification/plots/own.gp"
printf 'gnuplot -e "x=1" own.gp\n' >"$work/tree/verification/own.sh"
python3 "$root/tests/figure_style.py" "$work/tree" >"$work/style.log"
style=$?
for offence in "own.gp:3: a colour of its own (#123456)" "own.gp:3: font size 8 below" "own.sh:1: runs gnuplot itself"; do
  grep -qF "$offence" "$work/style.log" || { echo "FAIL: figure_style.py missed: $offence"; failures=$((failures + 1)); }
done
grep -q "good.gp" "$work/style.log" && { echo "FAIL: figure_style.py faults the good script"; failures=$((failures + 1)); }
[[ $style == 1 ]] || { echo "FAIL: figure_style.py returned $style on offences"; failures=$((failures + 1)); }
echo "figure_wrapper: $failures failure(s)"
exit $((failures > 0))
