#!/usr/bin/env bash
# The numbers of `make bench` that matter, in words (Markdown): benchmarks/summary.sh OUT_DIR CORES
set -euo pipefail
out=$1 cores=$2
speed=$out/speed.csv scaling=$out/scaling.csv
# value SCENE SHAPE INTEGRATOR COLUMN_NAME: one cell of speed.csv, its column found by name in the header
value() { [[ -s $speed ]] || return 0; awk -F, -v s="$1" -v sh="$2" -v i="$3" -v name="$4" 'NR == 1 {for (k = 1; k <= NF; ++k) if ($k == name) c = k; next}
  c && $1 == s && $2 == sh && $3 == i {print $c}' "$speed"; }
echo "# make bench: summary"
echo
echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs));"
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg). Speeds are particle-steps per second of the step's phases"
echo "(run.json phase_seconds, output excluded); ratios come from runs made minutes apart in one \`make bench\`."
echo
echo "## Targets (one thread)"
echo
echo "| what | measured | target | |"
echo "|---|---|---|---|"
# check NAME MEASURED TARGET OP FORMAT: a row of the table; a value that is missing or not a number is "not measured"
check() { awk -v m="$2" -v t="$3" -v op="$4" -v name="$1" -v fmt="$5" 'BEGIN{
  if (m !~ /^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$/) { printf "| %s | %s | %s %s | **not measured** |\n", name, m, op, t; exit }
  ok = op == ">=" ? m >= t : m <= t;
  printf "| %s | " fmt " | %s " fmt " | %s |\n", name, m, op, t, ok ? "**met**" : "**not met**"}'; }
check "Dyka bar 640 cells, linear + FE (particle-steps/s)" "$(value dyka_bar linear fe particle_steps_per_second)" 3e7 ">=" "%.3g"
check "Dyka bar 640 cells, LME gamma 3 + NPC (particle-steps/s)" "$(value dyka_bar lme npc particle_steps_per_second)" 1e7 ">=" "%.3g"
for i in fe npc; do
  check "1D: LME cost / linear cost, $i" "$(value dyka_bar lme $i relative_to_linear)" 2 "<=" "%.2f"
  check "2D soil block (400 particles): LME cost / linear cost, $i" "$(value soil_block lme $i relative_to_linear)" 3 "<=" "%.2f"
  for degree in 2 3; do  # target: a B-spline step at most 1.5 x a linear one in 1D, 2 x in 2D
    check "1D: B-spline $degree cost / linear cost, $i" "$(value dyka_bar bspline$degree $i relative_to_linear)" 1.5 "<=" "%.2f"
    check "2D soil block (400 particles): B-spline $degree cost / linear cost, $i" "$(value soil_block bspline$degree $i relative_to_linear)" 2 "<=" "%.2f"
  done
done
speedup() { awk -F, -v s="$1" -v i="$2" -v n="$cores" '$1 == 2 && $2 == s && $3 == i && $5 >= 100000 && $5 < 200000 {
    if ($7 == 1) one = $8; else if ($7 == n) many = $8 } END { if (one && many) printf "%.3f", one / many; else print "nan" }' "$scaling"; }
if [[ -s $scaling && $cores -ge 2 ]]; then
  for method in "linear fe" "lme npc"; do
    set -- $method
    check "2D soil block, 101124 particles, $1 + $2: speed-up on $cores cores" "$(speedup "$1" "$2")" 1.7 ">=" "%.2f"
  done
fi
threads_csv=$out/threads.csv
if [[ -s $threads_csv ]]; then
  echo
  echo "## Threads: the default against one thread (threads.csv)"
  echo
  echo "Time of a run with the default thread count over its time on \`--threads 1\` (the step's phases, best of 3"
  echo "interleaved rounds each), quiet and with a busy loop of the benchmark's own on one core, 1D Dyka bar and"
  echo "2D soil block of 10^3 to 10^6 particles, linear + FE and LME + NPC:"
  echo
  echo "| what | measured | target | |"
  echo "|---|---|---|---|"
  worst() { awk -F, -v c="$1" 'NR > 1 && $1 == c { if (w == "" || $10 > w) w = $10 } END { print (w == "" ? "nan" : w) }' "$threads_csv"; }
  least_speed_up() { awk -F, 'NR > 1 && $1 == "quiet" && $2 == 2 && $5 >= 100000 { if (l == "" || $11 < l) l = $11 } END { print (l == "" ? "nan" : l) }' "$threads_csv"; }
  check "quiet: largest time of the default / time of one thread" "$(worst quiet)" 1.10 "<=" "%.2f"
  check "loaded (a busy loop on one core): largest time of the default / time of one thread" "$(worst loaded)" 1.10 "<=" "%.2f"
  [[ $cores -ge 2 ]] && check "quiet: least speed-up of the default, 2D, >= 10^5 particles, $cores cores" "$(least_speed_up)" 1.7 ">=" "%.2f"
  echo
  echo "| condition | run | particles | threads | default / one |"
  echo "|---|---|---|---|---|"
  awk -F, 'NR > 1 { printf "| %s | %sD %s + %s | %d | %d | %.2f |\n", $1, $2, $3, $4, $5, $7, $10 }' "$threads_csv"
fi
if [[ ! -s $scaling ]]; then  # `benchmarks/run.sh BUILD --targets`: no scaling runs
  echo
  echo "(No scaling.csv: the threads and the growth of cost were not measured.)"
  exit 0
fi
echo
echo "## Threads: speed-up on $cores cores (time on 1 thread / time on $cores)"
echo
echo "| run | particles | speed-up |"
echo "|---|---|---|"
awk -F, -v n="$cores" 'NR > 1 && ($4 >= 2560 || ($1 == 2 && $5 >= 10000)) {
    key = $1 "D " $2 " + " $3 ", " $4 " cells"; particles[key] = $5
    if ($7 == 1) one[key] = $8; else if ($7 == n) many[key] = $8 }
  END { for (k in one) if (k in many) printf "| %s | %d | %.2f |\n", k, particles[k], one[k] / many[k] }' "$scaling" | sort -t'|' -k2
echo
echo "## How cost grows (one thread)"
echo
echo "Time per particle-step at the smallest and largest runs, and the first size at which it is 30 % above"
echo "its least value (where cost stops growing linearly with the particles):"
echo
echo "| run | least ns | at particles | largest run ns | first size 30 % above least | resident bytes per particle (largest) |"
echo "|---|---|---|---|---|---|"
awk -F, 'NR > 1 && $7 == 1 { key = $1 "D " $2 " + " $3; n[key]++; p[key, n[key]] = $5; t[key, n[key]] = $8 * 1e9; b[key, n[key]] = $NF }
  END { for (k in n) { least = 1e30; at = 0
          for (j = 1; j <= n[k]; ++j) if (t[k, j] < least) { least = t[k, j]; at = p[k, j] }
          first = "none"
          for (j = 1; j <= n[k]; ++j) if (p[k, j] > at && t[k, j] > 1.3 * least) { first = p[k, j]; break }
          printf "| %s | %.1f | %d | %.1f | %s | %s |\n", k, least, at, t[k, n[k]], first, b[k, n[k]] } }' "$scaling" | sort
echo
echo "Why: the step streams the particle arrays and the stencils (several hundred bytes per particle,"
echo "see the last column) and scatters into the nodes; while they fit in the caches (L2 $(lscpu | awk -F: '/L2 cache/ {print $2}' | xargs),"
echo "L3 $(lscpu | awk -F: '/L3 cache/ {print $2}' | xargs)) the cost per particle-step is flat, once they no longer do it rises to"
echo "what the memory bandwidth allows. At the small end the fixed cost of a step (the grid's reset, the"
echo "timers, starting threads) is shared by few particles, so the cost per particle-step rises there too."
