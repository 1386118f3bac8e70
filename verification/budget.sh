#!/usr/bin/env bash
# Sourced by make_figures.sh and make_studies.sh: each part of a target (the build, a suite, a study) timed, wall and
# CPU seconds, into one CSV per target (results/figures_budget.csv, results/studies_budget.csv):
#   target,part,wall_s,cpu_s,exit
# CPU seconds are those of the part's processes and their threads (bash's `times` for the children it waited for),
# the number that stays put on a shared machine; on a quiet machine of C cores a part's wall is about
# max(cpu_s / C, its longest serial run).
#
#   budget_open CSV TARGET     starts the table
#   budget_part NAME CMD...    runs CMD (in this shell, not a subshell), appends its row, returns its exit code
#   budget_markdown CSV        the table as Markdown, with the sums

# budget_children_cpu FILE: the CPU seconds (user + system) of the children this shell has waited for, from the
# output of `times` in FILE (its second line: "0m1.234s 0m0.056s")
budget_children_cpu() {
  tail -n 1 "$1" |
    awk '{ s = 0; for (k = 1; k <= 2; k++) { split($k, a, /[ms]/); s += 60 * a[1] + a[2] }; printf "%.2f\n", s }'
}

budget_open() {
  budget_csv=$1 budget_target=$2 budget_times=$1.times
  echo "target,part,wall_s,cpu_s,exit" >"$budget_csv"
}

budget_part() {
  local name=$1 wall0 cpu0 code
  shift
  # `times` runs in this shell (a subshell's children are not this shell's): its output goes to a file, read after
  times >"$budget_times"
  cpu0=$(budget_children_cpu "$budget_times") wall0=$(date +%s.%N)
  "$@"
  code=$?
  times >"$budget_times"
  awk -v t="$budget_target" -v n="$name" -v w0="$wall0" -v w1="$(date +%s.%N)" -v c0="$cpu0" \
    -v c1="$(budget_children_cpu "$budget_times")" -v e="$code" \
    'BEGIN { printf "%s,%s,%.1f,%.1f,%d\n", t, n, w1 - w0, c1 - c0, e }' >>"$budget_csv"
  rm -f "$budget_times"
  return "$code"
}

budget_markdown() {
  awk -F, 'NR == 1 { print "| part | wall, s | CPU, s | exit |"; print "|---|---|---|---|"; next }
    { print "| " $2 " | " $3 " | " $4 " | " $5 " |" }
    $2 != "build" { w += $3; c += $4 }
    $2 == "build" { bw = $3; bc = $4; b = 1 }
    END {
      printf "| all but the build | %.1f | %.1f | |\n", w, c
      if (b) printf "| all, the build included | %.1f | %.1f | |\n", w + bw, c + bc
    }' "$1"
}
