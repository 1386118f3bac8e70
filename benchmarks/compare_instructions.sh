#!/usr/bin/env bash
# Work of two builds of the command-line program side by side, counted instead of timed: the instructions each
# executes per particle-step (valgrind's callgrind, counting only inside mpm::Simulation::run, the time loop) on make
# bench's targets (the Dyka bar at 640 cells, 200 us; the soil block at 10 x 10 cells, 20 s), every shape function
# with forward Euler (USF, USL, MUSL) and the predictor-corrector, one thread. A count is the same on every run of a
# binary, so it resolves a difference of a per cent where the timings of a shared machine (benchmarks/compare_speed.sh)
# spread by tens of per cent; it is not a speed (a cache miss or a division costs more than an addition), only the
# work that the speed divides.
#   benchmarks/compare_instructions.sh OLD_MPM NEW_MPM
# Writes results/bench/instructions_compare.csv (one row per run) and instructions_compare.md (per configuration:
# each binary's instructions per particle-step and new / old; then make bench's cost ratio in instructions, each
# shape's count per particle-step over linear's with the same scene and method, of each binary and new / old), or into
# $COMPARE_INSTRUCTIONS_OUT. The two binaries' runs share the cores (two at a time). Needs valgrind (Debian's valgrind).
set -euo pipefail
if [[ $# -ne 2 || ! -x "$1" || ! -x "$2" ]]; then
  echo "usage: benchmarks/compare_instructions.sh OLD_MPM NEW_MPM   (two executables of this project's CLI)" >&2
  exit 2
fi
if ! command -v valgrind > /dev/null; then
  echo "error: valgrind is not installed (Debian's valgrind: .ci/install-deps.sh installs it)" >&2
  exit 2
fi
source "$(dirname "$0")/compare_common.sh"
compare_start "$1" "$2" "${COMPARE_INSTRUCTIONS_OUT:-$(cd "$(dirname "$0")/.." && pwd)/results/bench}" compare-instructions
csv=$out/instructions_compare.csv

# count NAME BINARY SCENE OVERRIDES...: prints particles,steps,instructions of one run on one thread, the
# instructions those executed inside mpm::Simulation<...>::run (its set-up and the files written after it excluded)
count() {
  local name=$1 binary=$2 scene=$3; shift 3
  local dir=$work/$name
  if ! valgrind --tool=callgrind --callgrind-out-file="$dir.callgrind" --toggle-collect='mpm::Simulation<*>::run(*' \
      "$binary" run "$scene" --out "$dir" --threads 1 --set output.snapshots=[] --set output.every=1000000 "$@" \
      > /dev/null 2> "$dir.log" || ! grep -q '"status": "done"' "$dir/run.json" 2> /dev/null; then
    echo "error: $name: the run did not end done ($dir.log, $dir/run.json)" >&2
    exit 1
  fi
  local particles steps instructions
  particles=$(grep -o '"particles": [0-9]*' "$dir/run.json" | head -1 | awk '{print $2}')
  steps=$(grep -o '"steps": [0-9]*' "$dir/run.json" | head -1 | awk '{print $2}')
  instructions=$(awk '/^(summary|totals):/ {print $2; exit}' "$dir.callgrind")
  if [[ -z $instructions || $instructions -eq 0 ]]; then
    echo "error: $name: callgrind counted no instruction inside mpm::Simulation::run ($dir.log)" >&2
    exit 1
  fi
  echo "$particles,$steps,$instructions"
}

echo "binary,scene,shape,method,particles,steps,instructions,instructions_per_particle_step" > "$csv"
done_count=0
for configuration in "${configurations[@]}"; do
  read -r scene shape method <<< "$configuration"
  read -r -a overrides <<< "$(settings "$scene" "$shape" "$method")"
  pids=()
  for which in old new; do
    binary=$old
    [[ $which == new ]] && binary=$new
    (count "${which}_${scene}_${shape}_$method" "$binary" "$root/scenes/$scene.toml" "${overrides[@]}" \
      > "$work/$which.row") &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done  # a failed run stops the script (set -e)
  for which in old new; do
    IFS=, read -r particles steps instructions < "$work/$which.row"
    echo "$which,$scene,$shape,$method,$particles,$steps,$instructions,$(awk -v i="$instructions" -v p="$particles" \
      -v s="$steps" 'BEGIN{printf "%.2f", i / (p * s)}')" >> "$csv"
  done
  done_count=$((done_count + 1))
  echo "compare_instructions: $done_count of ${#configurations[@]} configurations done" >&2
done

python3 - "$csv" "$out/instructions_compare.md" "$old" "$new" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
per = {(r["binary"], r["scene"], r["shape"], r["method"]):  # from the counts, not the CSV's rounded column
       int(r["instructions"]) / (int(r["particles"]) * int(r["steps"])) for r in rows}
keys = []
for r in rows:
    k = (r["scene"], r["shape"], r["method"])
    if k not in keys: keys.append(k)
lines = ["# Instructions per particle-step of two builds (benchmarks/compare_instructions.sh)", "",
         f"old: `{sys.argv[3]}`; new: `{sys.argv[4]}`. One thread; valgrind's callgrind, counting inside "
         "mpm::Simulation::run only; the same on every run of a binary.", "",
         "| scene | shape | method | old | new | new / old |", "|---|---|---|---|---|---|"]
ratios = []
for k in keys:
    o, n = per[("old",) + k], per[("new",) + k]
    ratios.append((n / o, k))
    lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {o:.1f} | {n:.1f} | {n / o:.4f} |")
def verdict(values, what, bound):
    low, high = min(values), max(values)
    count = sum(1 for r, _ in values if r <= bound)
    return (f"{what}: from {low[0]:.5f} ({' '.join(low[1])}) to {high[0]:.5f} ({' '.join(high[1])}); "
            f"{count} of {len(values)} at {bound} or below.")
lines += ["", verdict(ratios, "new / old of the instructions per particle-step", 1.05), ""]
lines += ["## Cost relative to linear in instructions (make bench's cost ratio, counted)", "",
          "| scene | shape | method | old | new | new / old |", "|---|---|---|---|---|---|"]
costs = []
for k in keys:
    if k[1] == "linear" or (k[0], "linear", k[2]) not in keys: continue
    old_cost = per[("old",) + k] / per[("old", k[0], "linear", k[2])]
    new_cost = per[("new",) + k] / per[("new", k[0], "linear", k[2])]
    costs.append((new_cost / old_cost, k))
    lines.append(f"| {k[0]} | {k[1]} | {k[2]} | {old_cost:.3f} | {new_cost:.3f} | {new_cost / old_cost:.5f} |")
if costs:
    lines += ["", verdict(costs, "new / old of the cost ratios in instructions", 1.05),
              "(A higher cost ratio is more work relative to linear.)", ""]
open(sys.argv[2], "w").write("\n".join(lines))
print("\n".join(lines))
EOF
