#!/usr/bin/env bash
# `make bench`: speed of each shape function x integrator, measured in one run so that the ratios
# are comparable (the machine is shared and noisy: compare ratios, not absolute numbers).
# Writes results/bench/speed.csv: scene, cells, shape, integrator, particles, steps, wall_seconds,
# particle_steps_per_second, speed relative to linear + the same integrator.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.. && pwd)
mpm=$root/$build/bin/mpm
out=$root/results/bench
mkdir -p "$out"
csv=$out/speed.csv
echo "scene,cells,shape,integrator,particles,steps,wall_seconds,particle_steps_per_second,relative_to_linear" >"$csv"
field() { grep -o "\"$1\": [-0-9.e+]*" "$2" | head -1 | awk '{print $2}'; }

bench() {  # bench SCENE LABEL CELLS OVERRIDES...
  local scene=$1 label=$2 cells=$3; shift 3
  for integrator in fe npc; do
    local linear_speed=""
    for shape in linear ugimp lme; do
      local dir=$out/runs/${label}_${cells}_${shape}_${integrator}
      "$mpm" run "$scene" --out "$dir" --set "solver.shape=\"$shape\"" --set "solver.integrator=\"$integrator\"" "$@" >/dev/null
      local speed; speed=$(field particle_steps_per_second "$dir/run.json")
      [[ $shape == linear ]] && linear_speed=$speed
      echo "$label,$cells,$shape,$integrator,$(field particles "$dir/run.json"),$(field steps "$dir/run.json"),$(field wall_seconds "$dir/run.json"),$speed,$(awk -v a="$speed" -v b="$linear_speed" 'BEGIN{printf "%.3f", a/b}')" >>"$csv"
    done
  done
}

bench "$root/scenes/dyka_bar.toml" dyka_bar 40 --set grid.cells=[40]
bench "$root/scenes/dyka_bar.toml" dyka_bar 640 --set grid.cells=[640]
column -s, -t "$csv"
echo "bench: wrote $csv"
