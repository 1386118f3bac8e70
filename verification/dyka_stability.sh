#!/usr/bin/env bash
# Where methods fail: for each shape function x integrator (and LME gamma), the largest CFL for which
# the Dyka bar (40 cells) stays bounded for 5 ms (about 25 periods of the bar), found by bisection on
# the exit code of `mpm run`: 0 = bounded, 3 = the solver itself stopped the run (energy above twice the
# initial energy, NaN, a particle off the grid) with its diagnosis. Twice: at the paper's amplitude
# (v0 = 5 m/s) and at v0/100, where the bar is linear to 1e-5 and the linearised analysis must hold.
# Beside them, the limit from each method's own linearised step (`mpm stability`, 40 cells, the same
# shape and integrator; paper/10_integrator_analysis.md). Methods run in parallel on the machine's cores.
#   dyka_stability.sh MPM SCENE DATA_DIR      writes DATA_DIR/dyka_stability.csv and two runs to draw
set -uo pipefail
mpm=$1 scene=$2 data=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# bisect NAME AMPLITUDE OVERRIDES...: prints "largest_stable_cfl,smallest_unstable_cfl,diagnosis"
bisect() {
  local name=$1 amplitude=$2; shift 2
  local stable=0.5 unstable=4.0 diagnosis="" code
  run() { local cfl=$1; shift; "$mpm" run "$scene" --threads 1 --out "$work/$name" --set output.snapshots=[] --set output.every=100000 \
      --set solver.end_time=5e-3 --set solver.energy_growth_limit=2 --set "initial_velocity[0].velocity=[$amplitude]" \
      --set "solver.cfl=$cfl" "$@" >/dev/null 2>"$work/$name.all"
    local status=$?; grep -v '^warning: ' "$work/$name.all" >"$work/$name.err"; return $status; }  # the diagnosis, not the CFL warning
  run "$stable" "$@"; code=$?
  [[ $code -eq 0 ]] || { echo "nan,$stable,$(tr ',\n' ';' <"$work/$name.err")"; return; }
  run "$unstable" "$@"; code=$?
  [[ $code -eq 3 ]] || { echo "$unstable,nan,stable up to the largest CFL tried"; return; }
  diagnosis=$(tr ',\n' '; ' <"$work/$name.err")
  for _ in $(seq 1 15); do  # (4 - 0.5) / 2^15 = 1.1e-4
    local middle; middle=$(awk -v a="$stable" -v b="$unstable" 'BEGIN{printf "%.5f", (a+b)/2}')
    run "$middle" "$@"; code=$?
    case $code in
      0) stable=$middle ;;
      3) unstable=$middle; diagnosis=$(tr ',\n' '; ' <"$work/$name.err") ;;
      *) echo "nan,nan,mpm exited with $code: $(tr ',\n' ';' <"$work/$name.err")"; return ;;
    esac
  done
  echo "$stable,$unstable,$diagnosis"
}
# method NAME STABILITY_OPTIONS -- SCENE_OVERRIDES...: one row of the table
method() {
  local name=$1 options=() overrides=()
  shift
  while [[ $1 != -- ]]; do options+=("$1"); shift; done; shift
  overrides=("$@")
  local computed large small
  computed=$("$mpm" stability --cells 40 "${options[@]}" | tail -n 1 | cut -d, -f13,14)
  large=$(bisect "$name" -5.0 "${overrides[@]}")
  small=$(bisect "${name}_small" -0.05 "${overrides[@]}")
  echo "$name,${large%%,*},$(echo "$large" | cut -d, -f2),${small%%,*},$(echo "$small" | cut -d, -f2),$computed,$(echo "$large" | cut -d, -f3-)"
}
export -f bisect method
export mpm scene work

{
  for integrator in fe npc; do
    echo "linear_$integrator --integrator $integrator -- --set 'solver.shape=\"linear\"' --set 'solver.integrator=\"$integrator\"'"
    echo "ugimp_$integrator --shape ugimp --integrator $integrator -- --set 'solver.shape=\"ugimp\"' --set 'solver.integrator=\"$integrator\"'"
    for gamma in 1.0 3.0 5.0; do
      echo "lme${gamma}_$integrator --shape lme --lme-gamma $gamma --integrator $integrator -- --set 'solver.shape=\"lme\"' --set solver.lme_gamma=$gamma --set 'solver.integrator=\"$integrator\"'"
    done
  done
  echo "linear_npc_gamma0.75 --integrator npc --newmark-gamma 0.75 -- --set 'solver.integrator=\"npc\"' --set solver.newmark_gamma=0.75"
  echo "linear_npc_average --integrator npc --npc-velocity average -- --set 'solver.integrator=\"npc\"' --set 'solver.npc_velocity=\"average\"'"
} | xargs -P "$(nproc)" -L 1 bash -c 'method "$@"' _ >"$work/rows.csv"

{
  echo "method,largest_stable_cfl,smallest_unstable_cfl,small_amplitude_stable_cfl,small_amplitude_unstable_cfl,cfl_limit_step,cfl_limit_modes,diagnosis"
  sort "$work/rows.csv"
} >"$data/dyka_stability.csv"

# An unstable run next to a stable one: linear + forward Euler just below and just above its limit.
limits=$(grep '^linear_fe,' "$data/dyka_stability.csv")
below=$(echo "$limits" | cut -d, -f2) above=$(echo "$limits" | cut -d, -f3)
for which in below above; do
  cfl=${!which}
  "$mpm" run "$scene" --out "$work/$which" --set output.snapshots=[] --set solver.end_time=5e-3 --set solver.energy_growth_limit=2 \
    --set output.every=10 --set "solver.cfl=$cfl" >/dev/null 2>"$work/$which.err"
  { echo "# CFL $cfl: $(grep -v '^warning: ' "$work/$which.err" | tr '\n' ' ')"; cut -d, -f1,3 "$work/$which/observers.csv"; } >"$data/dyka_stability_$which.csv"
done
cat "$data/dyka_stability.csv"
