#!/usr/bin/env bash
# How fast the lab's program runs (make lab: build type Lab, the reference kernels alone) beside the Release build's
# on the same reference kernels (`--kernels reference`), the two binaries interleaved in one run.
#   benchmarks/lab_speed.sh [RELEASE_BUILD_DIR] [LAB_BUILD_DIR] [ROUNDS]     (defaults: build, build-lab, 5)
# Each round runs every configuration below once with each binary (their order alternating by round), one thread, no
# snapshots; a run's time is its wall seconds (run.json's wall_seconds: set-up, the steps and the observers' output
# that the scenes write every step, not the process start): what a student waits for.
# Per configuration: the best of the rounds of each binary and their ratio lab / Release, with the smallest and the
# largest ratio of one round (the two runs of a round measured one after the other). Issue 45's target: the Dyka bar
# at 640 cells within 3x, judged on the largest ratio of a round (not on the bests alone).
# Writes results/bench/lab_speed.csv (one row per run) and lab_speed.md, or into $MPM_BENCH_OUT.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
folder() { [[ $1 == /* ]] && echo "$1" || echo "$root/$1"; }  # a build folder, absolute or from the root
release=$(folder "${1:-build}")/bin/mpm
lab=$(folder "${2:-build-lab}")/bin/mpm
rounds=${3:-5}
if ! [[ "$rounds" =~ ^[1-9][0-9]?$ ]]; then
  echo "error: ROUNDS: '$rounds' is not a whole number from 1 to 99" >&2
  exit 2
fi
for binary in "$release" "$lab"; do
  [[ -x $binary ]] || { echo "error: $binary: no such program (make build; make lab)" >&2; exit 2; }
done
"$lab" run "$root/scenes/dyka_bar.toml" --kernels fast --print-scene > /dev/null 2>&1 &&
  { echo "error: $lab takes --kernels fast: not a lab build (make lab)" >&2; exit 2; }
out=${MPM_BENCH_OUT:-$root/results/bench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
csv=$out/lab_speed.csv

# name|scene|overrides: the Dyka bar at 640 cells as issue 45 names it, with the paper's LME and predictor-corrector
# beside it, and a 2D scene.
configurations=(
  "dyka_640_linear_fe|scenes/dyka_bar.toml|--set grid.cells=[640]"
  "dyka_640_lme_npc|scenes/dyka_bar.toml|--set grid.cells=[640] --set solver.shape=\"lme\" --set solver.integrator=\"npc\""
  "soil_block_lme_npc|scenes/soil_block.toml|--set solver.shape=\"lme\" --set solver.integrator=\"npc\""
)

echo "configuration,round,build,wall_s,steps,particles" > "$csv"
field() { grep -o "\"$1\": [-0-9.e+]*" "$2" | head -1 | awk '{print $2}'; }
for ((round = 1; round <= rounds; ++round)); do
  order=(release lab)
  ((round % 2 == 0)) && order=(lab release)
  for entry in "${configurations[@]}"; do
    IFS='|' read -r name scene overrides <<< "$entry"
    for build in "${order[@]}"; do
      binary=$release
      [[ $build == lab ]] && binary=$lab
      dir=$work/$name-$build
      # shellcheck disable=SC2086  # the overrides are words
      "$binary" run "$root/$scene" --out "$dir" --kernels reference --threads 1 --set output.snapshots=[] \
        $overrides > /dev/null 2> "$work/err" || { echo "error: $build $name: $(cat "$work/err")" >&2; exit 1; }
      grep -q '"status": "done"' "$dir/run.json" || { echo "error: $build $name: not done" >&2; exit 1; }
      echo "$name,$round,$build,$(field wall_seconds "$dir/run.json"),$(field steps "$dir/run.json"),$(field particles "$dir/run.json")" >> "$csv"
    done
  done
  echo "lab_speed: round $round of $rounds" >&2
done

python3 - "$csv" "$out/lab_speed.md" "$rounds" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
lines = ["# The lab's program beside the Release build, on the reference kernels (benchmarks/lab_speed.sh)", "",
         f"Wall seconds of `mpm run ... --kernels reference --threads 1`, best of {sys.argv[3]} interleaved rounds; "
         "lab / Release of the bests, and in brackets the smallest and largest ratio of one round.", "",
         "| configuration | particles | steps | Release best | lab best | lab / Release | target |", "|---|---|---|---|---|---|---|"]
for name in dict.fromkeys(r["configuration"] for r in rows):
    of = lambda build: {int(r["round"]): float(r["wall_s"]) for r in rows if r["configuration"] == name and r["build"] == build}
    release, lab = of("release"), of("lab")
    ratios = [lab[k] / release[k] for k in release if k in lab and release[k] > 0]
    first = next(r for r in rows if r["configuration"] == name)
    target = ""
    if name.startswith("dyka_640"):
        target = "within 3x: " + ("met" if max(ratios) <= 3.0 else "not met") + " on every round"
    lines.append(f"| {name} | {first['particles']} | {first['steps']} | {min(release.values()):.3f} s | "
                 f"{min(lab.values()):.3f} s | {min(lab.values()) / min(release.values()):.2f} "
                 f"[{min(ratios):.2f}, {max(ratios):.2f}] | {target} |")
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
