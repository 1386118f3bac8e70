#!/usr/bin/env bash
# README.md, "Checking your own code": its two command blocks (the ```sh blocks after the marker line
# `<!-- tests/readme_checking.sh runs the two blocks below -->`) run as written, in a scratch folder
# holding the scenes and build/bin/mpm; every command must succeed (the Dyka bar's compare within its
# --tolerance) and write what the README says. Usage: readme_checking.sh MPM
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
awk '/<!-- tests\/readme_checking.sh runs the two blocks below -->/ { armed = 1 }
     armed && /^```sh$/ { block++; inside = 1; next }
     inside && /^```$/ { inside = 0; if (block == 2) exit; next }
     inside { print > (dir "/block" block ".sh") }' dir="$work" "$root/README.md"
for block in 1 2; do
  [[ -s "$work/block$block.sh" ]] || { fail "README block $block not found"; continue; }
  (cd "$work" && bash -e "block$block.sh" >"out$block" 2>"err$block") || fail "README block $block: $(cat "$work/err$block")"
done
[[ "$(sed -n 2p "$work/exact_tip.csv")" == "0,0,0,-5,0" ]] || fail "exact_tip.csv starts $(sed -n 2p "$work/exact_tip.csv")"
rows=$(($(wc -l <"$work/mine.csv") - 1))  # every row of the CSV is a sample
grep -q "^v_tip,v_x,$rows," "$work/out1" || fail "compare of mine.csv ($rows rows): $(cat "$work/out1")"
grep -q "^u_top,u_y," "$work/out2" || fail "compare of settlement.csv: $(cat "$work/out2")"
for picture in mine.png settlement.png; do
  [[ "$(head -c 4 "$work/$picture" 2>/dev/null | tail -c 3)" == "PNG" ]] || fail "$picture is not a PNG"
done
echo "readme_checking: $failures failed"
[[ $failures -eq 0 ]]
