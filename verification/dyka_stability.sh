#!/usr/bin/env bash
# Where methods fail (issue 4, item 8): for each shape function x integrator (and LME gamma), the
# largest CFL for which the Dyka bar (40 cells) stays bounded to 200 us, found by bisection on the
# exit code of `mpm run`: 0 = bounded, 3 = the solver itself stopped the run (energy growth, NaN,
# a particle off the grid) with its diagnosis. Methods run in parallel on the machine's cores.
#   dyka_stability.sh MPM SCENE DATA_DIR      writes DATA_DIR/dyka_stability.csv and two runs to draw
set -uo pipefail
mpm=$1 scene=$2 data=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# bisect NAME OVERRIDES...: prints "NAME,largest_stable_cfl,smallest_unstable_cfl,diagnosis"
bisect() {
  local name=$1; shift
  local stable=0.05 unstable=4.0 diagnosis="" code
  run() { local cfl=$1; shift; "$mpm" run "$scene" --threads 1 --out "$work/$name" --set output.snapshots=[] --set output.every=1000 --set "solver.cfl=$cfl" "$@" >/dev/null 2>"$work/$name.err"; }
  run "$stable" "$@"; code=$?
  [[ $code -eq 0 ]] || { echo "$name,nan,$stable,$(tr ',\n' ';' <"$work/$name.err")"; return; }
  run "$unstable" "$@"; code=$?
  [[ $code -eq 3 ]] || { echo "$name,$unstable,nan,stable up to the largest CFL tried"; return; }
  diagnosis=$(tr ',\n' '; ' <"$work/$name.err")
  for _ in 1 2 3 4 5 6 7 8 9; do  # (4 - 0.05) / 2^9 < 0.008
    local middle; middle=$(awk -v a="$stable" -v b="$unstable" 'BEGIN{printf "%.4f", (a+b)/2}')
    run "$middle" "$@"; code=$?
    case $code in
      0) stable=$middle ;;
      3) unstable=$middle; diagnosis=$(tr ',\n' '; ' <"$work/$name.err") ;;
      *) echo "$name,nan,nan,mpm exited with $code: $(tr ',\n' ';' <"$work/$name.err")"; return ;;
    esac
  done
  echo "$name,$stable,$unstable,$diagnosis"
}
export -f bisect
export mpm scene work

{
  for integrator in fe npc; do
    echo "linear_$integrator --set 'solver.shape=\"linear\"' --set 'solver.integrator=\"$integrator\"'"
    echo "ugimp_$integrator --set 'solver.shape=\"ugimp\"' --set grid.margin_max=[1] --set 'solver.integrator=\"$integrator\"'"  # a rigid cell behind the wall
    for gamma in 1.0 3.0 5.0; do
      echo "lme${gamma}_$integrator --set 'solver.shape=\"lme\"' --set solver.lme_gamma=$gamma --set 'solver.integrator=\"$integrator\"'"
    done
  done
} | xargs -P "$(nproc)" -L 1 bash -c 'bisect "$@"' _ >"$work/rows.csv"

{
  echo "method,largest_stable_cfl,smallest_unstable_cfl,diagnosis"
  sort "$work/rows.csv"
} >"$data/dyka_stability.csv"

# An unstable run next to a stable one: linear + forward Euler just below and just above its limit.
limits=$(grep '^linear_fe,' "$data/dyka_stability.csv")
below=$(echo "$limits" | cut -d, -f2) above=$(echo "$limits" | cut -d, -f3)
for which in below above; do
  cfl=${!which}
  "$mpm" run "$scene" --out "$work/$which" --set output.snapshots=[] --set "solver.cfl=$cfl" >/dev/null 2>"$work/$which.err"
  { echo "# CFL $cfl: $(tr '\n' ' ' <"$work/$which.err")"; cut -d, -f1,3 "$work/$which/observers.csv"; } >"$data/dyka_stability_$which.csv"
done
cat "$data/dyka_stability.csv"
