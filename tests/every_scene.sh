#!/usr/bin/env bash
# Every scene of scenes/ runs with every shape function (linear, ugimp, lme, bspline2, bspline3) and
# integrator (fe, npc, and forward Euler with the stress updated last: usl, musl) for the first 5 % of
# its end time (tens of steps): exit code 0, and every number written
# (observers, energy, a snapshot at the end) finite. Usage: every_scene.sh MPM [SCENES_DIR]
set -u
mpm=$1
scenes=${2:-$(cd "$(dirname "$0")/.." && pwd)/scenes}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0 runs=0
for scene in "$scenes"/*.toml; do
  end_time=$(awk -F= '/^end_time[[:space:]]*=/ { gsub(/[[:space:]]|#.*/, "", $2); print $2; exit }' "$scene")
  [[ -n "$end_time" ]] || { echo "FAIL: $scene: no end_time"; failures=$((failures + 1)); continue; }
  short=$(awk -v t="$end_time" 'BEGIN { printf "%.6g", t / 20 }')
  for shape in linear ugimp lme bspline2 bspline3; do
    for integrator in fe npc usl musl; do
      method=(--set "solver.shape=\"$shape\"" --set "solver.integrator=\"${integrator/*sl/fe}\"")
      [[ $integrator == *sl ]] && method+=(--set "solver.stress_update=\"$integrator\"")
      out=$work/$(basename "$scene" .toml)_${shape}_$integrator
      runs=$((runs + 1))
      if ! "$mpm" run "$scene" --out "$out" "${method[@]}" \
        --set "solver.end_time=$short" --set "output.snapshots=[$short]" >"$work/log" 2>&1; then
        echo "FAIL: $(basename "$scene") $shape + $integrator: exit $? ($(tail -1 "$work/log"))"
        failures=$((failures + 1))
        continue
      fi
      # A number that is not finite: nan or inf as a CSV field (C++ writes nan, -nan, inf, -inf).
      if grep -qiE '(^|,)-?(nan|inf)(,|$)' "$out"/*.csv || [[ $(ls "$out"/snapshot_*.csv 2>/dev/null | wc -l) -ne 1 ]]; then
        echo "FAIL: $(basename "$scene") $shape + $integrator: non-finite output or no snapshot at t = $short"
        failures=$((failures + 1))
      fi
    done
  done
done
echo "every_scene: $runs runs, $failures failed"
[[ $runs -ge 160 && $failures -eq 0 ]]
