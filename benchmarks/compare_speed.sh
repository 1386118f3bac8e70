#!/usr/bin/env bash
# Speed of two builds of the command-line program side by side, interleaved in one run: make bench's targets (the
# Dyka bar at 640 cells, 200 us; the soil block at 10 x 10 cells, 20 s), every shape function with forward Euler (USF,
# USL, MUSL) and the predictor-corrector, one thread. Each round runs every configuration with the old and then the
# new binary (their order alternates from round to round), so that a busy spell of the shared machine slows both
# alike; each binary's fastest run of each configuration is kept, and its spread over the rounds is reported.
#   benchmarks/compare_speed.sh OLD_MPM NEW_MPM [ROUNDS]     (ROUNDS: default 5)
# Writes results/bench/speed_compare.csv (one row per run) and speed_compare.md (per configuration: the best
# particle-steps per second of each, new / old, and the range of new / old over the rounds; then make bench's cost
# ratio, each shape's time per particle-step over linear's with the same scene and method, of each binary and new / old), or into
# $COMPARE_SPEED_OUT. The time of a run is the sum of its step's phases (run.json's phase_seconds, output excluded),
# as make bench measures it: set-up and the writing of files are not the solver's speed.
set -euo pipefail
if [[ $# -lt 2 || ! -x "$1" || ! -x "$2" ]]; then
  echo "usage: benchmarks/compare_speed.sh OLD_MPM NEW_MPM [ROUNDS]   (two executables of this project's CLI)" >&2
  exit 2
fi
rounds=${3:-5}
if ! [[ "$rounds" =~ ^[1-9][0-9]?$ ]]; then
  echo "error: ROUNDS: '$rounds' is not a whole number from 1 to 99" >&2
  exit 2
fi
old=$(realpath "$1") new=$(realpath "$2")
root=$(cd "$(dirname "$0")/.." && pwd)
out=${COMPARE_SPEED_OUT:-$root/results/bench}
work=$(mktemp -d /tmp/mpm-compare-speed.XXXXXX)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
csv=$out/speed_compare.csv
phases="stencils p2g stress forces grid g2p checks"

# seconds BINARY SCENE OVERRIDES...: the step's seconds of one run on one thread (the sum of its phases)
seconds() {
  local binary=$1 scene=$2; shift 2
  rm -rf "$work/run"
  "$binary" run "$scene" --out "$work/run" --threads 1 --set output.snapshots=[] --set output.every=1000000 "$@" > /dev/null
  local total=0 value
  for phase in $phases; do
    value=$(grep -o "\"$phase\": [-0-9.e+]*" "$work/run/run.json" | head -1 | awk '{print $2}')
    total=$(awk -v a="$total" -v b="$value" 'BEGIN{printf "%.9g", a + b}')
  done
  local particles steps
  particles=$(grep -o '"particles": [0-9]*' "$work/run/run.json" | head -1 | awk '{print $2}')
  steps=$(grep -o '"steps": [0-9]*' "$work/run/run.json" | head -1 | awk '{print $2}')
  echo "$particles,$steps,$total"
}

configurations=()
for scene in dyka_bar soil_block; do
  for shape in linear ugimp lme bspline2 bspline3; do
    for method in fe usl musl npc; do configurations+=("$scene $shape $method"); done
  done
done
settings() {  # settings SCENE SHAPE METHOD: the overrides of a configuration
  local cells='[640]'
  [[ $1 == soil_block ]] && cells='[10,10]'
  local integrator=fe update=usf
  [[ $3 == npc ]] && integrator=npc
  [[ $3 == usl || $3 == musl ]] && update=$3
  echo "--set grid.cells=$cells --set solver.shape=\"$2\" --set solver.integrator=\"$integrator\" --set solver.stress_update=\"$update\""
}

seconds "$new" "$root/scenes/dyka_bar.toml" --set 'grid.cells=[640]' --set 'solver.shape="lme"' > /dev/null  # warm-up
echo "round,binary,scene,shape,method,particles,steps,seconds,particle_steps_per_second" > "$csv"
for ((round = 1; round <= rounds; ++round)); do
  order=(old new)
  ((round % 2 == 0)) && order=(new old)
  for configuration in "${configurations[@]}"; do
    read -r scene shape method <<< "$configuration"
    read -r -a overrides <<< "$(settings "$scene" "$shape" "$method")"
    for which in "${order[@]}"; do
      binary=$old
      [[ $which == new ]] && binary=$new
      row=$(seconds "$binary" "$root/scenes/$scene.toml" "${overrides[@]}")
      IFS=, read -r particles steps time <<< "$row"
      echo "$round,$which,$scene,$shape,$method,$particles,$steps,$time,$(awk -v p="$particles" -v s="$steps" -v t="$time" 'BEGIN{printf "%.4e", p * s / t}')" >> "$csv"
    done
  done
  echo "compare_speed: round $round of $rounds done" >&2
done

python3 - "$csv" "$out/speed_compare.md" "$old" "$new" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keys = []
for r in rows:
    k = (r["scene"], r["shape"], r["method"])
    if k not in keys: keys.append(k)
def speeds(k, which):
    return {int(r["round"]): float(r["particle_steps_per_second"]) for r in rows
            if (r["scene"], r["shape"], r["method"]) == k and r["binary"] == which}
lines = ["# Speed of two builds, interleaved (benchmarks/compare_speed.sh)", "",
         f"old: `{sys.argv[3]}`; new: `{sys.argv[4]}`. One thread; particle-steps per second, the best of "
         f"{max(int(r['round']) for r in rows)} rounds of each; new / old of the bests, and in brackets the smallest "
         "and largest new / old of one round (the two runs one after the other).", "",
         "| scene | shape | method | old | new | new / old | range of a round's new / old |", "|---|---|---|---|---|---|---|"]
ratios = []
for k in keys:
    o, n = speeds(k, "old"), speeds(k, "new")
    ratio = max(n.values()) / max(o.values())
    ratios.append((ratio, k))
    per_round = [n[r] / o[r] for r in sorted(set(o) & set(n))]
    lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {max(o.values()):.3e} | {max(n.values()):.3e} | {ratio:.3f} | "
                 f"{min(per_round):.3f} - {max(per_round):.3f} |")
low, high = min(ratios), max(ratios)
lines += ["", f"new / old of the bests: from {low[0]:.3f} ({' '.join(low[1])}) to {high[0]:.3f} ({' '.join(high[1])}); "
          f"{sum(1 for r, _ in ratios if r >= 0.95)} of {len(ratios)} configurations at 0.95 or above.", ""]
# make bench's cost ratio: a shape's time per particle-step over linear's, same scene and method, from the bests
lines += ["## Cost relative to linear (make bench's cost ratio), from the same bests", "",
          "| scene | shape | method | old | new | new / old |", "|---|---|---|---|---|---|"]
costs = []
for k in keys:
    if k[1] == "linear" or (k[0], "linear", k[2]) not in keys: continue
    lin = (k[0], "linear", k[2])
    old_cost = max(speeds(lin, "old").values()) / max(speeds(k, "old").values())
    new_cost = max(speeds(lin, "new").values()) / max(speeds(k, "new").values())
    costs.append((new_cost / old_cost, k))
    lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {old_cost:.3f} | {new_cost:.3f} | {new_cost / old_cost:.3f} |")
if costs:
    low, high = min(costs), max(costs)
    lines += ["", f"new / old of the cost ratios: from {low[0]:.3f} ({' '.join(low[1])}) to {high[0]:.3f} "
              f"({' '.join(high[1])}); {sum(1 for r, _ in costs if r <= 1.05)} of {len(costs)} at 1.05 or below "
              "(a higher cost ratio is slower relative to linear).", ""]
open(sys.argv[2], "w").write("\n".join(lines))
print("\n".join(lines))
EOF
