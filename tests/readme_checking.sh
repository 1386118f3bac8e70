#!/usr/bin/env bash
# README.md, "Checking your own code": its three command blocks (the ```sh blocks after the marker line
# `<!-- tests/readme_checking.sh runs the three blocks below -->`) run as written, in a scratch folder
# holding the scenes and build/bin/mpm; every command must succeed (the Dyka bar's compare within its
# --tolerance) and write what the README says, and the scores README quotes from the second block (the
# Dyka bar sampled at every step and at every 10th) must be the ones it prints. Usage: readme_checking.sh MPM
set -u
mpm=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
mkdir -p "$work/build/bin"
ln -s "$mpm" "$work/build/bin/mpm"
cp -r "$root/scenes" "$work/scenes"
awk '/<!-- tests\/readme_checking.sh runs the three blocks below -->/ { armed = 1 }
     armed && /^```sh$/ { block++; inside = 1; next }
     inside && /^```$/ { inside = 0; if (block == 3) exit; next }
     inside { print > (dir "/block" block ".sh") }' dir="$work" "$root/README.md"
for block in 1 2 3; do
  [[ -s "$work/block$block.sh" ]] || { fail "README block $block not found"; continue; }
  (cd "$work" && bash -e "block$block.sh" >"out$block" 2>"err$block") || fail "README block $block: $(cat "$work/err$block")"
done
first=$(sed -n 2p "$work/exact_A.csv")
[[ $first == "0,0.00166625,0,-5,0" ]] || fail "exact_A.csv starts $first"
rows=$(($(wc -l <"$work/mine.csv") - 1))  # every row of the CSV is a sample
grep -q "^v_A,v_x,$rows," "$work/out1" || fail "compare of mine.csv ($rows rows): $(cat "$work/out1")"
# block 2: a header and the score at every step, then ten scores at every 10th step; README quotes them
# rounded to 4 digits: the first, then the smallest and the largest of the ten
scores=$(awk -F, '$1 == "A.v_x" { print $5 }' "$work/out2")
[[ $(wc -l <<<"$scores") -eq 11 ]] || fail "block 2 printed $(wc -l <<<"$scores") scores, want 11: $(cat "$work/out2")"
every=$(head -n 1 <<<"$scores" | awk '{ printf "%.4f", $1 }')
range=$(tail -n 10 <<<"$scores" | sort -g | sed -n '1p;$p' | awk '{ printf "%.4f ", $1 }')
read -r smallest largest <<<"$range"
grep -q "^$every<!-- check dyka_sweep.csv" "$root/README.md" || fail "README does not quote $every at every step"
grep -q "10th step from $smallest to $largest " "$root/README.md" ||
  fail "README does not quote 'every 10th step from $smallest to $largest'"
grep -q "^u_top,u_y," "$work/out3" || fail "compare of settlement.csv: $(cat "$work/out3")"
for picture in mine.png settlement.png; do
  [[ "$(head -c 4 "$work/$picture" 2>/dev/null | tail -c 3)" == "PNG" ]] || fail "$picture is not a PNG"
done
echo "readme_checking: $failures failed"
[[ $failures -eq 0 ]]
