#!/usr/bin/env bash
# How the particle loops scale with the cores (mpm/core/parallel.hpp): the 2D soil block at 160 x 160
# cells (102,400 particles), LME + NPC, 200 steps, on 1, 2, 4, 8, 12 and 16 threads, 3 rounds, each round
# every thread count once (interleaved: a busy spell of the machine slows every thread count alike).
#
#   bash benchmarks/thread_scaling.sh MPM_BINARY OUT_DIR
#
# Writes OUT_DIR/thread_scaling.csv (threads,repeat,particle_steps_per_s) and OUT_DIR/summary.csv (per
# thread count: the median, the spread (max - min) / median, the speed-up of the medians over one thread's,
# and the speed-up over the threads), prints the summary, and keeps each run's run.json under OUT_DIR/runs.
# Speed is particle-steps per second of the step's phases (run.json phase_seconds, output excluded).
# On one thread a run takes 4-8 s (2.7e6-5.6e6 particle-steps/s on the machines measured), the script 1-2 minutes on
# 16 cores; each run is stopped after 120 s.
set -euo pipefail

usage() { echo "usage: bash benchmarks/thread_scaling.sh MPM_BINARY OUT_DIR" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
mpm=$1 out=$2
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scene=$root/scenes/soil_block.toml
[[ -f $mpm && -x $mpm ]] || { echo "thread_scaling.sh: $mpm: not an executable file" >&2; exit 2; }
[[ -f $scene ]] || { echo "thread_scaling.sh: $scene: no such scene" >&2; exit 2; }
"$mpm" --version >/dev/null 2>&1 || { echo "thread_scaling.sh: $mpm --version failed: not the mpm CLI?" >&2; exit 2; }
mkdir -p "$out/runs" || { echo "thread_scaling.sh: cannot create $out" >&2; exit 2; }
csv=$out/thread_scaling.csv summary=$out/summary.csv
cores=$(nproc)
thread_counts=(1 2 4 8 12 16)
repeats=3
steps=${THREAD_SCALING_STEPS:-200}  # fewer only to try the script out
if [[ ! $steps =~ ^[1-9][0-9]*$ ]]; then
  echo "thread_scaling.sh: THREAD_SCALING_STEPS=$steps: not a positive whole number" >&2; exit 2
fi
[[ $cores -ge 16 ]] || echo "thread_scaling.sh: warning: $cores cores, fewer than the 16 threads measured" >&2
# dt = 0.1 h / c = 0.034641 / cells s on this scene (c = 28.87 m/s): `steps` steps at 160 cells
end_time=$(awk -v s="$steps" 'BEGIN{printf "%.6e", s * 0.034641 / 160}')
version=$("$mpm" --version 2>&1 | head -1)
echo "thread_scaling.sh: $version on $cores cores ($(uname -n)), $steps steps of 102400 particles"

# speed RUN_JSON: particles x steps / the sum of the step's phases but output
speed() {
  local json=$1 particles steps busy
  particles=$(grep -o '"particles": [0-9]*' "$json" | head -1 | awk '{print $2}')
  steps=$(grep -o '"steps": [0-9]*' "$json" | head -1 | awk '{print $2}')
  busy=$(grep -o '"phase_seconds": {[^}]*}' "$json" | head -1 | tr -d '{}"' | tr ',' '\n' |
    awk -F': ' '$1 !~ /output/ && NF == 2 {sum += $2} END {printf "%.9g", sum}')
  if [[ -z $particles || -z $steps || -z $busy ]]; then
    echo "thread_scaling.sh: $json: no particles, steps or phase_seconds" >&2; exit 1
  fi
  awk -v p="$particles" -v s="$steps" -v b="$busy" 'BEGIN{if (b <= 0) exit 1; printf "%.4e", p * s / b}'
}

echo "threads,repeat,particle_steps_per_s" >"$csv"
start=$(date +%s)
for ((repeat = 1; repeat <= repeats; ++repeat)); do
  for threads in "${thread_counts[@]}"; do
    dir=$out/runs/t${threads}_r$repeat
    rm -rf "$dir"
    if ! timeout 120 "$mpm" run "$scene" --out "$dir" --threads "$threads" --set 'grid.cells=[160,160]' \
        --set 'solver.shape="lme"' --set 'solver.integrator="npc"' --set "solver.end_time=$end_time" \
        --set 'output.snapshots=[]' --set 'output.every=1000000' >"$dir.log" 2>&1; then
      echo "thread_scaling.sh: the run on $threads threads (round $repeat) failed; its output: $dir.log" >&2
      tail -5 "$dir.log" >&2
      exit 1
    fi
    rate=$(speed "$dir/run.json")
    echo "$threads,$repeat,$rate" >>"$csv"
    echo "  round $repeat/$repeats, $threads threads: $rate particle-steps/s ($(( $(date +%s) - start )) s so far)"
  done
done

# The summary: median and spread per thread count, the speed-up of the medians over one thread's.
echo "threads,median_particle_steps_per_s,spread,speed_up,speed_up_per_thread" >"$summary"
one=""
for threads in "${thread_counts[@]}"; do
  rates=$(awk -F, -v t="$threads" 'NR > 1 && $1 == t {print $3}' "$csv" | sort -g)
  median=$(echo "$rates" |
    awk '{v[NR] = $1} END {printf "%.4e", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}')
  [[ -n $one ]] || one=$median
  echo "$rates" | awk -v t="$threads" -v m="$median" -v one="$one" 'NR == 1 {lo = $1} {hi = $1}
    END {printf "%d,%s,%.3f,%.2f,%.3f\n", t, m, (hi - lo) / m, m / one, m / one / t}' >>"$summary"
done
if command -v column >/dev/null; then column -s, -t "$summary"; else cat "$summary"; fi
echo "thread_scaling.sh: wrote $csv and $summary in $(( $(date +%s) - start )) s"
