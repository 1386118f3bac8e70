#!/usr/bin/env bash
# Issue 32's question: can a threading library run the chunks of the particle loops (mpm/core/parallel.hpp)
# and keep today's guarantees? Runs part 2 of make bench (benchmarks/run.sh BUILD --threads: the default
# thread count against --threads 1, quiet and beside a busy loop on one core) for two builds of the CLI in
# turn, ROUNDS times: the team (CMake MPM_THREADS=team, the default) and oneTBB's task arena
# (MPM_THREADS=onetbb, needs Debian's libtbb-dev). The chunks, and so the bits, are the same in both.
#   benchmarks/threads_library.sh TEAM_BUILD_DIR ONETBB_BUILD_DIR [ROUNDS]   (ROUNDS: 2; ~4 minutes a round)
# Writes results/bench/threads_library/{team,onetbb}_ROUND.csv (run.sh's threads.csv, run into
# threads_library/run/, so that make bench's results/bench/threads.csv is left as it was) and summary.csv: per
# build, condition and run, the default over one thread's time (best of each round's 3 interleaved
# repeats) as min and max over the rounds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
team=$1 onetbb=$2 rounds=${3:-2}
[[ $rounds =~ ^[1-9][0-9]?$ ]] || { echo "threads_library: ROUNDS must be 1 to 99, not '$rounds'" >&2; exit 2; }
for build in "$team" "$onetbb"; do
  [[ -x $root/$build/bin/mpm ]] || { echo "threads_library: no CLI at $root/$build/bin/mpm (build its mpm_cli)" >&2; exit 2; }
done
out=$root/results/bench/threads_library
rm -rf "$out"; mkdir -p "$out"
for round in $(seq "$rounds"); do
  for pair in "team:$team" "onetbb:$onetbb"; do
    name=${pair%%:*} build=${pair#*:}
    MPM_BENCH_OUT=$out/run bash "$root/benchmarks/run.sh" "$build" --threads >/dev/null
    cp "$out/run/threads.csv" "$out/${name}_$round.csv"
    echo "threads_library: round $round of $rounds, $name done"
  done
done
# summary.csv: library,condition,dimension,shape,integrator,particles,default_threads,default_over_one_min,_max
{
  echo "library,condition,dimension,shape,integrator,particles,default_threads,default_over_one_min,default_over_one_max"
  for name in team onetbb; do
    tail -q -n +2 "$out"/${name}_*.csv | awk -F, -v lib="$name" '{
      key = lib "," $1 "," $2 "," $3 "," $4 "," $5 "," $7
      if (!(key in lo)) { lo[key] = $10; hi[key] = $10; order[++n] = key }
      if ($10 < lo[key]) lo[key] = $10; if ($10 > hi[key]) hi[key] = $10 }
      END { for (i = 1; i <= n; ++i) printf "%s,%.3f,%.3f\n", order[i], lo[order[i]], hi[order[i]] }'
  done
} >"$out/summary.csv"
column -s, -t "$out/summary.csv"
echo "threads_library: wrote $out/summary.csv"
