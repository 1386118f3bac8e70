#!/usr/bin/env bash
# Runs every shipped scene with every shape function and integrator (USL and MUSL too) for a few steps with the
# sanitized `mpm` (make sanitize): an AddressSanitizer or UndefinedBehaviorSanitizer report, a
# signal or any exit code other than 0 (done) or 3 (the method failed, told in one line) fails.
#
#   bash tests/sanitize_scenes.sh build-sanitize/bin/mpm
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export ASAN_OPTIONS=${ASAN_OPTIONS:-exitcode=86:abort_on_error=0:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-exitcode=86:print_stacktrace=1}
failures=0 runs=0
for scene in "$root"/scenes/*.toml; do
  # a few steps of each: 3 of the Dyka bar, 3 of the soil block
  if grep -q '^dimension = 1' "$scene"; then few=(--set solver.end_time=1e-6 --set 'output.snapshots=[0.0, 1e-6]' --set grid.margin_max=[1])
  else few=(--set solver.end_time=0.02 --set 'output.snapshots=[0.0, 0.02]' --set grid.margin_min=[1,1] --set grid.margin_max=[1,0]); fi
  # a scene with a fixed step (solver.dt): 3 of its steps
  dt=$(awk -F= '/^dt[[:space:]]*=/ { gsub(/[[:space:]]|#.*/, "", $2); print $2; exit }' "$scene")
  [[ -n "$dt" ]] &&
    few+=(--set "solver.end_time=$(awk -v dt="$dt" 'BEGIN { printf "%.6g", 3 * dt }')" --set 'output.snapshots=[0.0]')
  for shape in linear ugimp lme bspline2 bspline3; do
    for integrator in fe npc usl musl; do
      method=(--set "solver.shape=\"$shape\"" --set "solver.integrator=\"${integrator/*sl/fe}\"")
      [[ $integrator == *sl ]] && method+=(--set "solver.stress_update=\"$integrator\"")
      runs=$((runs + 1))
      name="$(basename "$scene" .toml)_${shape}_$integrator"
      "$mpm" run "$scene" --out "$work/$name" "${few[@]}" "${method[@]}" \
        >"$work/out" 2>"$work/err"
      code=$?
      if [[ $code -ne 0 && $code -ne 3 ]] || grep -qE "runtime error|Sanitizer" "$work/err"; then
        echo "FAIL: $name: exit $code"; head -n 30 "$work/err"; failures=$((failures + 1))
      fi
    done
  done
done
echo "sanitize_scenes: $runs runs, $failures failed"
[[ $failures -eq 0 ]]
