#!/usr/bin/env bash
# Where methods fail: for each shape function x integrator (and LME gamma), the Dyka bar (40 cells) run
# for 20 ms (about 190 periods of the bar) at a scan of CFL numbers around the limit of the method's own
# linearised step (`mpm stability --cells 40`, paper/10_integrator_analysis.md): 0.90 to 1.05 times it.
# A run is unstable when the solver stops it (exit 3: energy above 100 times its initial value, NaN, a
# particle off the grid), with its diagnosis. A true instability grows without bound and passes any
# such bound; 100 stays above the bounded swing of the staggered energy of forward Euler's highest mode
# near its limit, which a bound of 2 would take for an instability. The stable set need not be an interval
# (a bisection would assume it is), so every CFL of the scan is run, at the paper's amplitude (v0 = 5 m/s)
# and at v0/100, where the bar is linear to 1e-5 and the linearised analysis must hold.
# Above the limit the scan stops at its first unstable CFL, the only one the table reads.
#   dyka_stability.sh MPM SCENE DATA_DIR      writes DATA_DIR/dyka_stability.csv, the scan's factors
#                                             (dyka_stability_factors.txt) and two runs to draw
set -uo pipefail
mpm=$1 scene=$2 data=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
factors="0.900 0.920 0.940 0.950 0.960 0.970 0.980 0.985 0.990 0.995 1.005 1.010 1.020 1.050"

# scan NAME AMPLITUDE LIMIT OVERRIDES...: prints "largest_stable,first_unstable,unstable_below_limit,diagnosis"
# largest_stable: the largest CFL of the scan below which every scanned run is stable; first_unstable: the
# smallest unstable CFL of the scan; unstable_below_limit: the unstable CFLs below the step's limit (';').
scan() {
  local name=$1 amplitude=$2 limit=$3; shift 3
  local largest=nan first=nan below="" diagnosis="" all_stable=1
  for factor in $factors; do
    # above the limit only the first unstable CFL is read: the scan stops there
    [[ $first != nan ]] && awk -v f="$factor" 'BEGIN{exit !(f > 1)}' && break
    local cfl; cfl=$(awk -v f="$factor" -v l="$limit" 'BEGIN{printf "%.5f", f * l}')
    "$mpm" run "$scene" --threads 1 --out "$work/$name" --set output.snapshots=[] --set output.every=100000 \
      --set solver.end_time=2e-2 --set solver.energy_growth_limit=100 --set "initial_velocity[0].velocity=[$amplitude]" \
      --set "solver.cfl=$cfl" "$@" >/dev/null 2>"$work/$name.all"
    local code=$?
    if [[ $code -eq 0 ]]; then
      [[ $all_stable -eq 1 ]] && largest=$cfl
    else
      all_stable=0
      [[ $first == nan ]] && { first=$cfl; diagnosis=$(grep -v '^warning: ' "$work/$name.all" | tr ',\n' '; '); }
      awk -v f="$factor" 'BEGIN{exit !(f < 1)}' && below="$below$cfl;"
    fi
  done
  echo "$largest,$first,${below%;},$diagnosis"
}
# method NAME STABILITY_OPTIONS -- SCENE_OVERRIDES...: one row of the table
method() {
  local name=$1 options=() overrides=()
  shift
  while [[ $1 != -- ]]; do options+=("$1"); shift; done; shift
  overrides=("$@")
  local computed limit large small
  computed=$("$mpm" stability --cells 40 "${options[@]}" | tail -n 1 | cut -d, -f13,14)
  limit=${computed%%,*}
  large=$(scan "$name" -5.0 "$limit" "${overrides[@]}")
  small=$(scan "${name}_small" -0.05 "$limit" "${overrides[@]}")
  echo "$name,$(echo "$large" | cut -d, -f1,2),$(echo "$small" | cut -d, -f1,2),$computed,$(echo "$large" | cut -d, -f3),$(echo "$small" | cut -d, -f3),$(echo "$large" | cut -d, -f4-)"
}
export -f scan method
export mpm scene work factors

{
  for integrator in fe npc; do
    echo "linear_$integrator --integrator $integrator -- --set 'solver.shape=\"linear\"' --set 'solver.integrator=\"$integrator\"'"
    echo "ugimp_$integrator --shape ugimp --integrator $integrator -- --set 'solver.shape=\"ugimp\"' --set 'solver.integrator=\"$integrator\"'"
    for gamma in 1.0 3.0 5.0; do
      echo "lme${gamma}_$integrator --shape lme --lme-gamma $gamma --integrator $integrator -- --set 'solver.shape=\"lme\"' --set solver.lme_gamma=$gamma --set 'solver.integrator=\"$integrator\"'"
    done
  done
  # today's baselines: B-splines with both integrators, forward Euler with the stress updated last (USL, MUSL)
  for shape in bspline2 bspline3; do
    for integrator in fe npc; do
      echo "${shape}_$integrator --shape $shape --integrator $integrator -- --set 'solver.shape=\"$shape\"' --set 'solver.integrator=\"$integrator\"'"
    done
  done
  for shape in linear bspline2; do
    for update in usl musl; do
      echo "${shape}_$update --shape $shape --stress-update $update -- --set 'solver.shape=\"$shape\"' --set 'solver.integrator=\"fe\"' --set 'solver.stress_update=\"$update\"'"
    done
  done
  echo "linear_npc_gamma0.75 --integrator npc --newmark-gamma 0.75 -- --set 'solver.integrator=\"npc\"' --set solver.newmark_gamma=0.75"
  echo "linear_npc_gamma1 --integrator npc --newmark-gamma 1 -- --set 'solver.integrator=\"npc\"' --set solver.newmark_gamma=1"
  echo "linear_npc_average --integrator npc --npc-velocity average -- --set 'solver.integrator=\"npc\"' --set 'solver.npc_velocity=\"average\"'"
} | xargs -P "$(nproc)" -L 1 bash -c 'method "$@"' _ >"$work/rows.csv"

{
  echo "method,largest_stable_cfl,smallest_unstable_cfl,small_amplitude_stable_cfl,small_amplitude_unstable_cfl,cfl_limit_step,cfl_limit_modes,unstable_below_limit,small_amplitude_unstable_below_limit,diagnosis"
  sort "$work/rows.csv"
} >"$data/dyka_stability.csv"
echo "$factors" >"$data/dyka_stability_factors.txt"

# An unstable run next to a stable one: linear + forward Euler at the largest stable and the first unstable CFL of its scan.
limits=$(grep '^linear_fe,' "$data/dyka_stability.csv")
below=$(echo "$limits" | cut -d, -f2) above=$(echo "$limits" | cut -d, -f3)
for which in below above; do
  cfl=${!which}
  "$mpm" run "$scene" --out "$work/$which" --set output.snapshots=[] --set solver.end_time=2e-2 --set solver.energy_growth_limit=100 \
    --set output.every=10 --set "solver.cfl=$cfl" >/dev/null 2>"$work/$which.err"
  { echo "# CFL $cfl: $(grep -v '^warning: ' "$work/$which.err" | tr '\n' ' ')"; cut -d, -f1,3 "$work/$which/observers.csv"; } >"$data/dyka_stability_$which.csv"
done
cat "$data/dyka_stability.csv"
