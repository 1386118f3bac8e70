#!/usr/bin/env bash
# `make bench`: speed of each shape function x integrator, measured in one run so that the ratios
# are comparable (the machine is shared and noisy: compare ratios, not absolute numbers).
# Writes results/bench/speed.csv: scene, cells, shape, integrator, particles, steps, wall_seconds,
# particle_steps_per_second, speed relative to linear + the same integrator.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
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
# 2D: the soil block at 1 m cells (400 particles, about 5800 steps to 20 s).
bench "$root/scenes/soil_block.toml" soil_block 10x10 --set grid.cells=[10,10] --set output.snapshots=[] --set output.every=100
column -s, -t "$csv"
echo "bench: wrote $csv"
# Memory: the largest resident set of the biggest 1D run (5120 cells, 20 us), per shape function.
memory=$out/memory.csv
echo "shape,max_resident_kib" >"$memory"
for shape in linear ugimp lme; do
  kib=$(/usr/bin/time -f "%M" "$mpm" run "$root/scenes/dyka_bar.toml" --out "$out/runs/memory_$shape" \
    --set grid.cells=[5120] --set "solver.shape=\"$shape\"" --set solver.end_time=2.0e-5 --set output.snapshots=[] 2>&1 >/dev/null | tail -1)
  echo "$shape,$kib" >>"$memory"
done
column -s, -t "$memory"
echo "bench: wrote $memory"
