#!/usr/bin/env bash
# paper/13_lab.md, the lab: every ```sh block of the page runs as written, in order, in a scratch folder holding
# the scenes and build/bin/mpm (the ```bash blocks, which edit or rebuild the code, are left to the tests the page
# names), and each exercise's answer is checked against what they print and write. Exercise 1 also checks every
# particle number of paper/12_worked_example.md's tables (the `<!-- worked INTEGRATOR STEP particle P QUANTITY -->`
# markers of the particle update) against the snapshot one step of the run writes. Usage: lab.sh MPM
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
awk '/^```sh$/ { block++; inside = 1; next }
     inside && /^```$/ { inside = 0; next }
     inside { print > (dir "/block" block ".sh") }' dir="$work" "$root/paper/13_lab.md"
for block in 1 2 3 4 5; do
  [[ -s "$work/block$block.sh" ]] || { fail "lab block $block not found"; continue; }
  (cd "$work" && bash "block$block.sh" >"out$block" 2>"err$block") || fail "lab block $block: $(cat "$work/err$block")"
done
[[ -s "$work/block6.sh" ]] && fail "paper/13_lab.md has more sh blocks than this test checks"

# 1. One step by hand: the book's particle numbers against the snapshots (x, v_x, sigma_xx, density).
column_of() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
checked=0
while read -r value integrator particle quantity; do
  case $integrator in fe) folder=we-fe ;; npc) folder=we-npc ;; npc_corrected) folder=we-corrected ;; *) continue ;; esac
  case $quantity in x) name=x ;; v) name=v_x ;; stress) name=sigma_xx ;; density) name=density ;; *) continue ;; esac
  snapshot=$work/$folder/snapshot_0000.csv
  [[ -f $snapshot ]] || { fail "no $folder/snapshot_0000.csv"; continue; }
  got=$(awk -F, -v c="$(column_of "$snapshot" "$name")" -v row=$((particle + 2)) 'NR == row { print $c }' "$snapshot")
  awk -v a="$got" -v b="$value" 'BEGIN { d = a - b; exit !(d < 5e-4 && d > -5e-4 && a != "") }' ||
    fail "paper/12: $integrator particle $particle $quantity: the book says $value, the run $got"
  checked=$((checked + 1))
done < <(grep -oE '[-−]?[0-9.]+<!-- worked [a-z_]+ [0-9]+ particle [0-9] [a-z_]+ -->' "$root/paper/12_worked_example.md" |
  sed -E 's/−/-/; s/<!-- worked ([a-z_]+) [0-9]+ particle ([0-9]) ([a-z_]+) -->/ \1 \2 \3/')
[[ $checked -ge 18 ]] || fail "only $checked particle numbers of paper/12 checked"

# 2. Free fall: x = 0.5 + 9.81 / 2 as printed; 0.5 + 9.81 / 2 + g dt t - g dt^2 / 2 (dt = 5e-4) corrected.
last_x() { awk -F, 'END { print $2 }' "$work/$1/observers.csv"; }
awk -v x="$(last_x fall-projected)" 'BEGIN { exit !(x - 5.405 < 1e-9 && 5.405 - x < 1e-9) }' ||
  fail "free fall, projected: x = $(last_x fall-projected), not 5.405"
awk -v x="$(last_x fall-corrected)" 'BEGIN { e = 5.405 + 9.81 * 5e-4 - 9.81 * 2.5e-7 / 2; exit !(x - e < 1e-9 && e - x < 1e-9) }' ||
  fail "free fall, corrected: x = $(last_x fall-corrected), not 5.405 + g dt t - g dt^2 / 2"

# 3. The stability limits and the runs just above and below them.
limits=$(awk -F, '$1 == "1" { print $4, $13 }' "$work/out3")
awk '$1 == "fe" && $2 > 1.999 && $2 < 2.001 { fe = 1 } $1 == "npc" && $2 > 1.4137 && $2 < 1.4147 { npc = 1 }
     END { exit !(fe && npc) }' <<<"$limits" || fail "mpm stability: $limits (want fe 2, npc 1.414)"
for expected in "fe at CFL 1.95: exit 0" "fe at CFL 2.05: exit 3" "npc at CFL 1.38: exit 0" "npc at CFL 1.45: exit 3" \
  "usf at CFL 0.75: exit 0" "usl at CFL 0.75: exit 3" "musl at CFL 0.75: exit 0" \
  "linear at 2560 cells: exit 3" "ugimp at 2560 cells: exit 0"; do
  grep -qxF "$expected" "$work"/out[345] || fail "want '$expected': $(cat "$work"/out[345] | tr '\n' ';')"
done

grep -q "^failure: .*unstable: energy grew" "$work/out5" || fail "linear at 2560 cells: no energy growth in $(cat "$work/out5")"

# 6. The call the exercise comments out is still there; 7. the planted bug still applies.
grep -qF 'newmark_corrector(newmark_gamma, dt, grid);' "$root/mpm/integrators/newmark_predictor_corrector.hpp" ||
  fail "exercise 6: no corrector call to comment out in newmark_predictor_corrector.hpp"
original=$(awk -F'\t' '$1 == "force_internal_mass" { print $4 }' "$root/tests/mutants/mutants.tsv")
[[ -n $original && $(grep -cF "$original" "$root/mpm/transfer/nodal_forces.hpp") -eq 1 ]] ||
  fail "exercise 7: the mutant force_internal_mass no longer applies to mpm/transfer/nodal_forces.hpp"
replacement=$(awk -F'\t' '$1 == "force_internal_mass" { print $5 }' "$root/tests/mutants/mutants.tsv")
for text in "${original#*= }" "${replacement#*= }"; do
  grep -qF "\`${text%;}\`" "$root/paper/13_lab.md" || fail "exercise 7: the page does not quote '${text%;}'"
done

echo "lab: $checked numbers of the worked example, 7 exercises, $failures failed"
[[ $failures -eq 0 ]]
