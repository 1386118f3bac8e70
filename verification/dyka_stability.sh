#!/usr/bin/env bash
# Where methods fail: for each shape function x integrator (and LME gamma), the Dyka bar (40 cells) run for 20 ms
# (about 190 periods of the bar) at a scan of CFL numbers from 0.60 to 1.05 times the limit of the method's own
# linearised step on the body it runs: the free bar itself, at rest and with its particles moved 1e-6 h towards the
# free end (free_bar_limits, mpm::moved_body_cfl_limit; the smaller of the two). The limit on a bar held at both
# ends (`mpm stability --cells 40`, paper/10_integrator_analysis.md) is listed beside it, and used only where the free
# bar's analysis finds no stable CFL (the predictor-corrector: see method(); the table says which body each uses). A run is unstable
# when the solver stops it (exit 3: energy above 100 times its initial value, NaN, a particle off the grid), with its
# diagnosis. A true instability grows without bound and passes any such bound; 100 stays above the bounded swing of
# the staggered energy of forward Euler's highest mode near its limit, which a bound of 2 would take for an
# instability. The stable set need not be an interval, so every CFL of the scan below the limit is run and the
# stable set is reported as it is ("stable at 1.22-2.03 except 1.8352"), at the paper's amplitude (v0 = 5 m/s) and
# at v0/100, where the bar is linear to 1e-5 and the linearised analysis must hold. Above the limit the scan stops at
# its first unstable CFL.
#   dyka_stability.sh MPM SCENE DATA_DIR [FREE_BAR_LIMITS]
#     writes DATA_DIR/dyka_stability.csv (a row per method), dyka_stability_runs.csv (a row per run), the scan's
#     factors (dyka_stability_factors.txt) and two runs to draw; FREE_BAR_LIMITS defaults to MPM's folder's
set -uo pipefail
mpm=$1 scene=$2 data=$3 limits=${4:-$(dirname "$1")/free_bar_limits}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
factors="0.600 0.750 0.850 0.900 0.920 0.940 0.950 0.960 0.970 0.980 0.985 0.990 0.995 1.005 1.010 1.020 1.050"

# scan NAME AMPLITUDE LIMIT OVERRIDES...: runs the scan and prints
#   "largest_stable,first_unstable,unstable_below_limit,stable_set,monotone,diagnosis"
# largest_stable: the largest CFL of the scan below which every scanned run is stable (nan: the first one stopped);
# first_unstable: the smallest unstable CFL of the scan; unstable_below_limit: the unstable CFLs below the limit (';');
# stable_set: every outcome in words (stable_set); monotone: 1 when no stopped CFL lies below a stable one.
# Each run's row "NAME,AMPLITUDE,CFL,FACTOR,STABLE" goes to $work/NAME.runs.
scan() {
  local name=$1 amplitude=$2 limit=$3; shift 3
  local first=nan diagnosis="" outcomes=""
  : >"$work/$name.runs"
  for factor in $factors; do
    # above the limit only the first unstable CFL is read: the scan stops there
    [[ $first != nan ]] && awk -v f="$factor" 'BEGIN{exit !(f > 1)}' && break
    local cfl; cfl=$(awk -v f="$factor" -v l="$limit" 'BEGIN{printf "%.5f", f * l}')
    "$mpm" run "$scene" --threads 1 --out "$work/$name" --set output.snapshots=[] --set output.every=100000 \
      --set solver.end_time=2e-2 --set solver.energy_growth_limit=100 --set "initial_velocity[0].velocity=[$amplitude]" \
      --set "solver.cfl=$cfl" "$@" >/dev/null 2>"$work/$name.all"
    local code=$? stable=1
    if [[ $code -ne 0 ]]; then
      stable=0
      [[ $first == nan ]] && { first=$cfl; diagnosis=$(grep -v '^warning: ' "$work/$name.all" | tr ',\n' '; '); }
    fi
    outcomes="$outcomes $cfl:$factor:$stable"
    echo "$name,$amplitude,$cfl,$factor,$stable" >>"$work/$name.runs"
  done
  echo "$(stable_set "$outcomes"),$first,$diagnosis"
}
# stable_set "CFL:FACTOR:STABLE ...": "largest_stable,unstable_below_limit,description,monotone" where description reads
# "stable at 1.2234-2.0289 except 1.8352; stopped at 2.0493", "stable at 0.42-0.70", "none stable (0.37-0.63 stopped)".
stable_set() {
  echo "$1" | tr ' ' '\n' | awk -F: 'NF == 3 { n++; cfl[n] = $1; factor[n] = $2; ok[n] = $3 }
    END {
      largest = "nan"; for (k = 1; k <= n && ok[k]; k++) largest = cfl[k]
      for (k = 1; k <= n; k++) { if (ok[k]) { if (low == "") low = cfl[k]; high = cfl[k]; top = k }
                                 else if (factor[k] < 1) below = below (below == "" ? "" : ";") cfl[k] }
      if (low == "") { printf "nan,%s,none stable (%s-%s stopped),1\n", below, cfl[1], cfl[n]; exit }
      for (k = 1; k < top; k++) if (!ok[k]) { if (cfl[k] < low) before = before (before == "" ? "" : ";") cfl[k]; else inside = inside (inside == "" ? "" : ";") cfl[k] }
      for (k = top + 1; k <= n; k++) if (!ok[k]) after = after (after == "" ? "" : ";") cfl[k]
      text = (before == "" ? "" : "stopped at " before " then ") "stable at " low "-" high (inside == "" ? "" : " except " inside)
      text = text (after == "" ? "; no stopped run in the scan" : "; stopped at " after)
      printf "%s,%s,%s,%d\n", largest, below, text, (before == "" && inside == "") }'
}
# method NAME STABILITY_OPTIONS -- SCENE_OVERRIDES...: one row of the table
method() {
  local name=$1 options=() overrides=()
  shift
  while [[ $1 != -- ]]; do options+=("$1"); shift; done; shift
  overrides=("$@")
  local held free limit large small
  held=$("$mpm" stability --cells 40 "${options[@]}" | tail -n 1 | cut -d, -f13,14)
  local settings=()
  for ((k = 1; k < ${#overrides[@]}; k += 2)); do settings+=("${overrides[k]}"); done
  free=$("$limits" "$scene" "${settings[@]}" grid.cells=[40])
  # the free bar's limit; the held bar's where the free bar's analysis finds no stable CFL from 0.02 on (0: the
  # predictor-corrector's linearised step on the bar with its empty margin nodes has a spectral radius of 10-25 at
  # every CFL, while its runs are stable: an artefact of the analysis there, not of the runs), marked by its body
  local body="free bar"
  limit=$(echo "$free" | awk -F, '{print ($1 < $2 ? $1 : $2)}')
  awk -v l="$limit" 'BEGIN{exit !(l > 0 && l < 1e3)}' || { limit=${held%%,*}; body="held bar: no stable CFL on the free bar"; }
  large=$(scan "$name" -5.0 "$limit" "${overrides[@]}")
  small=$(scan "${name}_small" -0.05 "$limit" "${overrides[@]}")
  cat "$work/$name.runs" "$work/${name}_small.runs" | sed 's/^[^,]*,/'"$name"',/' >"$work/$name.allruns"
  # largest,below,text,monotone,first,diagnosis
  local L=(); IFS=, read -r -a L <<<"$large"
  local S=(); IFS=, read -r -a S <<<"$small"
  echo "$name,${L[0]},${L[4]},${S[0]},${S[4]},$held,${L[1]},${S[1]},$free,$limit,$body,${L[2]},${S[2]},${L[3]},${S[3]},$(echo "$large" | cut -d, -f6-)"
}
export -f scan stable_set method
export mpm scene work factors limits

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
  echo "method,largest_stable_cfl,smallest_unstable_cfl,small_amplitude_stable_cfl,small_amplitude_unstable_cfl,cfl_limit_step,cfl_limit_modes,unstable_below_limit,small_amplitude_unstable_below_limit,cfl_limit_free_bar,cfl_limit_free_bar_moved,cfl_limit_scanned,scanned_limit_body,stable_set,small_amplitude_stable_set,monotone,small_amplitude_monotone,diagnosis"
  sort "$work/rows.csv"
} >"$data/dyka_stability.csv"
# every run, with the row of its method in dyka_stability.csv (0 for the first method) for the figure
{
  echo "index,method,amplitude,cfl,factor,stable"
  tail -n +2 "$data/dyka_stability.csv" | cut -d, -f1 | awk '{print NR - 1, $1}' | while read -r index name; do
    sed "s/^/$index,/" "$work/$name.allruns"
  done
} >"$data/dyka_stability_runs.csv"
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
