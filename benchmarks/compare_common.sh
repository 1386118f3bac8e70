# Sourced by benchmarks/compare_speed.sh and benchmarks/compare_instructions.sh: the configurations both compare,
# make bench's targets (the Dyka bar at 640 cells, 200 us; the soil block at 10 x 10 cells, 20 s), every shape
# function with forward Euler (USF, USL, MUSL) and the predictor-corrector; and their common start.

# compare_start OLD_MPM NEW_MPM OUT NAME: sets old and new (the binaries' absolute paths), root (the repository),
# out (OUT, made) and work (a temporary folder /tmp/mpm-NAME.*, removed when the script exits)
compare_start() {
  old=$(realpath "$1") new=$(realpath "$2")
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  out=$3
  work=$(mktemp -d "/tmp/mpm-$4.XXXXXX")
  trap 'rm -rf "$work"' EXIT
  mkdir -p "$out"
}

configurations=()
for scene in dyka_bar soil_block; do
  for shape in linear ugimp lme bspline2 bspline3; do
    for method in fe usl musl npc; do configurations+=("$scene $shape $method"); done
  done
done

# settings SCENE SHAPE METHOD: the overrides of a configuration
settings() {
  local cells='[640]'
  [[ $1 == soil_block ]] && cells='[10,10]'
  local integrator=fe update=usf
  [[ $3 == npc ]] && integrator=npc
  [[ $3 == usl || $3 == musl ]] && update=$3
  echo "--set grid.cells=$cells --set solver.shape=\"$2\" --set solver.integrator=\"$integrator\" --set solver.stress_update=\"$update\""
}
