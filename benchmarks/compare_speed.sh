#!/usr/bin/env bash
# Speed of two builds of the command-line program side by side, in one run: make bench's targets (the Dyka bar at 640
# cells, 200 us; the soil block at 10 x 10 cells, 20 s), every shape function with forward Euler (USF, USL, MUSL) and
# the predictor-corrector, one thread. Two ways to pair the runs (COMPARE_SPEED_MODE):
#   interleaved (default)  each round runs every configuration with the old and then the new binary (their order
#                          alternates from round to round), so that a busy spell of the shared machine slows both alike;
#   simultaneous           each round runs the old and the new binary at the same time, each pinned to a CPU of its
#                          own (taskset, the first two CPUs allowed; they swap from round to round), so that a busy
#                          spell of the host falls on both runs at once; needs two CPUs.
# Each binary's fastest run of each configuration is kept, and its spread over the rounds is reported.
#   benchmarks/compare_speed.sh OLD_MPM NEW_MPM [ROUNDS]     (ROUNDS: default 5)
# Writes results/bench/speed_compare.csv (one row per run) and speed_compare.md (per configuration: the best
# particle-steps per second of each, new / old, and the range and median of new / old over the rounds; then make
# bench's cost ratio, each shape's time per particle-step over linear's with the same scene and method, of each binary
# and new / old, of the bests and the median of a round's), or into $COMPARE_SPEED_OUT. The time of a run is the sum of
# its step's phases (run.json's phase_seconds, output excluded), as make bench measures it: set-up and the writing of
# files are not the solver's speed.
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
mode=${COMPARE_SPEED_MODE:-interleaved}
if [[ $mode != interleaved && $mode != simultaneous ]]; then
  echo "error: COMPARE_SPEED_MODE: '$mode' is not allowed; use interleaved | simultaneous" >&2
  exit 2
fi
if [[ $mode == simultaneous ]] && { [[ $(nproc) -lt 2 ]] || ! command -v taskset > /dev/null; }; then
  echo "error: COMPARE_SPEED_MODE=simultaneous needs two cores and taskset (util-linux); this machine has $(nproc)" >&2
  exit 2
fi
source "$(dirname "$0")/compare_common.sh"
compare_start "$1" "$2" "${COMPARE_SPEED_OUT:-$(cd "$(dirname "$0")/.." && pwd)/results/bench}" compare-speed
csv=$out/speed_compare.csv
phases="stencils p2g stress forces grid g2p checks"

# seconds DIR BINARY SCENE OVERRIDES...: the step's seconds of one run on one thread (the sum of its phases), its
# files in DIR; run under the command in the array pin (taskset -c CPU) when it is set. Fails (status 1) unless
# the run ended done.
pin=()
seconds() {
  local dir=$1 binary=$2 scene=$3; shift 3
  rm -rf "$dir"
  if ! "${pin[@]}" "$binary" run "$scene" --out "$dir" --threads 1 --set output.snapshots=[] --set output.every=1000000 \
      "$@" > /dev/null || ! grep -q '"status": "done"' "$dir/run.json"; then
    echo "error: $binary run $scene $*: the run did not end done ($dir/run.json)" >&2
    return 1
  fi
  local total=0 value
  for phase in $phases; do
    value=$(grep -o "\"$phase\": [-0-9.e+]*" "$dir/run.json" | head -1 | awk '{print $2}')
    total=$(awk -v a="$total" -v b="$value" 'BEGIN{printf "%.9g", a + b}')
  done
  local particles steps
  particles=$(grep -o '"particles": [0-9]*' "$dir/run.json" | head -1 | awk '{print $2}')
  steps=$(grep -o '"steps": [0-9]*' "$dir/run.json" | head -1 | awk '{print $2}')
  echo "$particles,$steps,$total"
}

# row ROUND WHICH CPU SCENE SHAPE METHOD PARTICLES,STEPS,SECONDS: one line of the CSV file
row() {
  local particles steps time
  IFS=, read -r particles steps time <<< "$7"
  echo "$1,$2,$3,$4,$5,$6,$particles,$steps,$time,$(awk -v p="$particles" -v s="$steps" -v t="$time" 'BEGIN{printf "%.4e", p * s / t}')"
}

for binary in "$old" "$new"; do  # warm-up
  seconds "$work/run" "$binary" "$root/scenes/dyka_bar.toml" --set 'grid.cells=[640]' --set 'solver.shape="lme"' > /dev/null
done
# The two CPUs of the simultaneous mode: the first two this process may run on (two logical CPUs; whether they are
# two physical cores the script cannot tell).
cpus=(0 1)
[[ $mode == simultaneous ]] && read -r -a cpus <<< "$(python3 -c 'import os; print(*sorted(os.sched_getaffinity(0))[:2])')"
echo "round,binary,cpu,scene,shape,method,particles,steps,seconds,particle_steps_per_second" > "$csv"
for ((round = 1; round <= rounds; ++round)); do
  order=(old new)
  ((round % 2 == 0)) && order=(new old)
  for configuration in "${configurations[@]}"; do
    read -r scene shape method <<< "$configuration"
    read -r -a overrides <<< "$(settings "$scene" "$shape" "$method")"
    if [[ $mode == simultaneous ]]; then  # order[0] on cpus[0], order[1] on cpus[1], at the same time
      pids=()
      for cpu in 0 1; do
        binary=$old
        [[ ${order[cpu]} == new ]] && binary=$new
        (pin=(taskset -c "${cpus[cpu]}") && seconds "$work/run$cpu" "$binary" "$root/scenes/$scene.toml" "${overrides[@]}" \
          > "$work/row$cpu") &
        pids+=($!)
      done
      for pid in "${pids[@]}"; do wait "$pid"; done  # a failed run stops the script (set -e)
      for cpu in 0 1; do row "$round" "${order[cpu]}" "${cpus[cpu]}" "$scene" "$shape" "$method" "$(< "$work/row$cpu")" >> "$csv"; done
    else
      for which in "${order[@]}"; do
        binary=$old
        [[ $which == new ]] && binary=$new
        result=$(seconds "$work/run" "$binary" "$root/scenes/$scene.toml" "${overrides[@]}")  # stops on a failed run
        row "$round" "$which" any "$scene" "$shape" "$method" "$result" >> "$csv"
      done
    fi
  done
  echo "compare_speed: round $round of $rounds done" >&2
done

python3 - "$csv" "$out/speed_compare.md" "$old" "$new" "$mode" <<'EOF'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
mode = sys.argv[5]
keys = []
for r in rows:
    k = (r["scene"], r["shape"], r["method"])
    if k not in keys: keys.append(k)
def speeds(k, which):
    return {int(r["round"]): float(r["particle_steps_per_second"]) for r in rows
            if (r["scene"], r["shape"], r["method"]) == k and r["binary"] == which}
pairing = ("the two runs one after the other" if mode == "interleaved" else
           "the two runs at the same time, each on a core of its own, the cores swapped from round to round")
lines = [f"# Speed of two builds, {mode} (benchmarks/compare_speed.sh)", "",
         f"old: `{sys.argv[3]}`; new: `{sys.argv[4]}`. One thread; particle-steps per second, the best of "
         f"{max(int(r['round']) for r in rows)} rounds of each; new / old of the bests, then the smallest, the median "
         f"and the largest new / old of one round ({pairing}).", "",
         "| scene | shape | method | old | new | new / old | a round's new / old: range | median |",
         "|---|---|---|---|---|---|---|---|"]
ratios, medians = [], []
for k in keys:
    o, n = speeds(k, "old"), speeds(k, "new")
    ratio = max(n.values()) / max(o.values())
    ratios.append((ratio, k))
    per_round = [n[r] / o[r] for r in sorted(set(o) & set(n))]
    medians.append((statistics.median(per_round), k))
    lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {max(o.values()):.3e} | {max(n.values()):.3e} | {ratio:.3f} | "
                 f"{min(per_round):.3f} - {max(per_round):.3f} | {medians[-1][0]:.3f} |")
def verdict(values, what, good, bound):
    low, high = min(values), max(values)
    count = sum(1 for r, _ in values if (r >= bound if good == "above" else r <= bound))
    return (f"{what}: from {low[0]:.3f} ({' '.join(low[1])}) to {high[0]:.3f} ({' '.join(high[1])}); "
            f"{count} of {len(values)} at {bound} or {good}.")
lines += ["", verdict(ratios, "new / old of the bests", "above", 0.95),
          verdict(medians, "median of a round's new / old", "above", 0.95), ""]
# make bench's cost ratio: a shape's time per particle-step over linear's, same scene and method: from the bests,
# and from each round's four runs (the median over the rounds of that round's new cost / old cost)
lines += ["## Cost relative to linear (make bench's cost ratio)", "",
          "From the same bests, and the median over the rounds of one round's new cost / old cost.", "",
          "| scene | shape | method | old | new | new / old | a round's new / old: median |",
          "|---|---|---|---|---|---|---|"]
costs, cost_medians = [], []
for k in keys:
    if k[1] == "linear" or (k[0], "linear", k[2]) not in keys: continue
    lin = (k[0], "linear", k[2])
    lo, ln, so, sn = speeds(lin, "old"), speeds(lin, "new"), speeds(k, "old"), speeds(k, "new")
    old_cost = max(lo.values()) / max(so.values())
    new_cost = max(ln.values()) / max(sn.values())
    costs.append((new_cost / old_cost, k))
    per_round = [(ln[r] / sn[r]) / (lo[r] / so[r]) for r in sorted(set(lo) & set(ln) & set(so) & set(sn))]
    cost_medians.append((statistics.median(per_round), k))
    lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {old_cost:.3f} | {new_cost:.3f} | {new_cost / old_cost:.3f} | "
                 f"{cost_medians[-1][0]:.3f} |")
if costs:
    lines += ["", verdict(costs, "new / old of the cost ratios", "below", 1.05),
              verdict(cost_medians, "median of a round's new / old cost ratio", "below", 1.05),
              "(A higher cost ratio is slower relative to linear.)", ""]
open(sys.argv[2], "w").write("\n".join(lines))
print("\n".join(lines))
EOF
