#!/usr/bin/env bash
# The Dyka-bar figures of `make figures` (Figs. 6-10, speed against accuracy, stability map).
# Called by make_figures.sh with MPM_BIN, MPM_ROOT and MPM_RESULTS set; exits 1 when a hard
# check of the suite fails.
set -uo pipefail
data=$MPM_RESULTS/data figures=$MPM_RESULTS/figures plots=$MPM_ROOT/verification/plots
scene=$MPM_ROOT/scenes/dyka_bar.toml
status=0
"$MPM_BIN/dyka_suite" "$data" "$MPM_RESULTS/report/20_dyka.md" "$scene" || status=1
bash "$MPM_ROOT/verification/dyka_stability.sh" "$MPM_BIN/mpm" "$scene" "$data" || status=1
echo "figures: dyka: stability map done"

g() { gnuplot -e "dir='$plots'; data='$data'; $1" "$plots/$2" || status=1; }
g "out='$figures/dyka_fig6'; orders='$data/dyka_orders.csv'" dyka_fig6.gp
series() {  # series NAME CAPTION INSET FILES... -- TITLES...
  local name=$1 caption=$2 inset=$3; shift 3
  local files="" titles=""
  while [[ $1 != -- ]]; do files="$files $data/$1.csv"; shift; done; shift
  titles="$*"
  g "out='$figures/$name'; caption='$caption'; files='${files# }'; titles='$titles'; inset=$inset" dyka_series.gp
}
g "out='$figures/dyka_fig7'" dyka_fig7.gp
series dyka_fig9 "Fig. 9: shape functions, forward Euler (40 cells, CFL 0.5)" 0 \
  dyka_linear_fe_40 dyka_ugimp_fe_40 dyka_lme_fe_40 -- linear uGIMP LME
series dyka_fig10 "Fig. 10: shape functions, predictor-corrector (40 cells, CFL 0.5)" 0 \
  dyka_linear_npc_40 dyka_ugimp_npc_40 dyka_lme_npc_40 -- linear uGIMP LME
g "out='$figures/dyka_fig8'" dyka_fig8.gp
g "out='$figures/dyka_fair'" dyka_fair.gp
g "out='$figures/dyka_work_precision'" dyka_work_precision.gp
below=$(grep '^linear_fe,' "$data/dyka_stability.csv" | cut -d, -f2) above=$(grep '^linear_fe,' "$data/dyka_stability.csv" | cut -d, -f3)
g "out='$figures/dyka_stability'; below='$below'; above='$above'" dyka_stability.gp

# The runs on each mesh's error-cost front (data/dyka_baselines.csv, column pareto), as "40 cells: a, b; 160 cells: ...".
# The fronts and their ties are also in the Dyka bar's section, "Today's baselines".
front() {
  tail -n +2 "$data/dyka_baselines.csv" | awk -F, '$7 == 1 { list[$2] = list[$2] (list[$2] == "" ? "" : ", ") $1 } END { for (n in list) print n, list[n] }' |
    sort -n | awk '{ n = $1; $1 = ""; printf "%s%s cells:%s", (NR > 1 ? "; " : ""), n, $0 }'
}

# The stability map's section of the report.
{
  echo "### Speed against accuracy (\`dyka_work_precision\`)"
  echo
  echo "![dyka_work_precision](figures/dyka_work_precision.png)"
  echo
  echo "RMS of v_A against the CPU time of each run (the thread's, one run per core at a time): the paper's methods over the mesh sweep (points left to right: 10 to 2560 cells, one run each) and today's baselines by family on their meshes (data/dyka_baselines.csv), the runs on 40 and 160 cells repeated 5 times, interleaved (error bars: fastest to slowest). Ringed: the runs on their mesh's error-cost front, no method both more accurate and faster by more than the measured spread (the repeats' ranges apart; a single timing, on 640 and 2560 cells, widened by the largest spread of the 160-cell repeats); the Dyka bar's section \"Today's baselines\" above names them with the ties the spread leaves: $(front)."
  echo
  echo "### Where methods fail: the largest stable CFL (\`dyka_stability\`)"
  echo
  echo "![dyka_stability](figures/dyka_stability.png)"
  echo
  echo "Each method's limit from its own linearised step (\`mpm stability --cells 40\`, a bar held at both ends; paper/10_integrator_analysis.md) and from the one-mode analysis, beside runs of the Dyka bar (40 cells, 20 ms, about 190 periods) at a scan of CFL numbers from 0.90 to 1.05 times the step's limit ($(cat "$data/dyka_stability_factors.txt"); above the limit the scan stops at its first unstable CFL), at the paper's amplitude v0 = 5 m/s and at v0/100. A run is unstable when the solver stops it (energy above 100 times its initial value, NaN, a particle off the grid). Every CFL of the scan is run: the stable CFLs need not form an interval. *Stable up to*: the largest scanned CFL below which every scanned run is stable; *unstable below the limit*: the scanned CFLs below the step's limit whose runs the solver stopped."
  echo
  echo "| method | linearised step | one-mode analysis | v0: stable up to / first unstable | v0: unstable below the limit | v0/100: stable up to / first unstable | v0/100: unstable below the limit | the solver's diagnosis at v0's first unstable CFL |"
  echo "|---|---|---|---|---|---|---|---|"
  tail -n +2 "$data/dyka_stability.csv" | awk -F, '{d=$10; for(i=11;i<=NF;i++) d=d","$i; printf "| %s | %s | %s | %s / %s | %s | %s / %s | %s | %s |\n", $1, $6, $7, ($2 == "nan" ? "below the scan" : $2), $3, ($8 == "" ? "none" : $8), ($4 == "nan" ? "below the scan" : $4), $5, ($9 == "" ? "none" : $9), d}'
  echo
  tail -n +2 "$data/dyka_stability.csv" | awk -F, '
    function gap(run, step) { return 100 * (run - step) / step }
    { damped = $1 ~ /_npc/ && $1 !~ /average/ && $1 !~ /gamma1$/;
      if (damped) { nd++; if ($8 == "" && $9 == "") clean_d++; worst_d = (gap($3, $6) > worst_d) ? gap($3, $6) : worst_d; if (gap($5, $6) > worst_d) worst_d = gap($5, $6) }
      else { nu++; if ($9 == "") clean_small++; else small_list = small_list " " $1 " (" $9 ")";
             if ($8 != "" && $9 == "") { windows++; list = list " " $1 " (" $8 ")" } } }
    END {
      printf "- **Eq. (32) with gamma < 1, damped, against its linearised step:** on %d of its %d rows every scanned run below the step'"'"'s limit is stable at both amplitudes, and the first unstable scanned CFL lies at most %+.2f %% above the limit.\n", clean_d, nd, worst_d;
      printf "- **The undamped schemes (forward Euler with any stress update, the Newmark average, Eq. (32) at gamma = 1):** at v0/100 every scanned run below the limit is stable on %d of %d rows (stopped below it at v0/100:%s). At the paper'"'"'s amplitude %d of the rows stable at v0/100 have runs stopped below the limit:%s. A linear system'"'"'s growth does not depend on its amplitude, so these are nonlinear effects of the bar'"'"'s motion, which the linearisation about rest leaves out; the damping of Eq. (32) (gamma < 1) removes them.\n", clean_small, nu, (small_list == "" ? " none" : small_list), windows, (list == "" ? " none" : list) }'
  above=$(tr ' ' '\n' <"$data/dyka_stability_factors.txt" | awk '$1 > 1 { print; exit }')
  tail -n +2 "$data/dyka_stability.csv" | awk -F, -v above="$above" '
    function gap(run, step) { return 100 * (run - step) / step }
    function where(below, unstable, step) { return below == "" && unstable != "nan" && unstable - above * step <= 1e-4 * step }
    $1 ~ /^bspline|_usl$|_musl$/ {
      n++; small += where($9, $5, $6); large += where($8, $3, $6);
      rows = rows sprintf("%s%s %s: %s (%+.1f %%) / %s (%+.1f %%)%s", (n > 1 ? "; " : ""), $1, $6, $5, gap($5, $6), $3, gap($3, $6), ($8 == "" ? "" : ", at v0 stopped below the limit at " $8)) }
    END {
      printf "- **Today'"'"'s baselines (B-splines, USL, MUSL) against their linearised step:** they fail where it says at v0/100 on %d of their %d rows (every scanned run below the step'"'"'s limit stable, the first scanned CFL above it, %+.1f %%, stopped), at v0 on %d. Per row, the step'"'"'s limit: the first unstable CFL at v0/100 / at v0 (above the limit by): %s.\n", small, n, 100 * (above - 1), large, rows }'
  tail -n +2 "$data/dyka_stability.csv" | awk -F, -v errors="$data/dyka_baselines.csv" '
    function shown(c) { return c == 0 ? "below the scan" : c }
    BEGIN { while ((getline line < errors) > 0) { split(line, f, ","); if (f[2] == 40 && f[6] == "ok") rms[f[1]] = f[3] } }
    { name = $1; sub(/3\.0_/, "3_", name); stable = ($2 == "nan" ? 0 : $2);
      if (stable > widest_cfl) { widest_cfl = stable; widest = $1 }
      if (!(name in rms)) next;
      n++; method[n] = $1; error[n] = rms[name]; cfl[n] = stable;
      if (best == 0 || rms[name] < error[best]) best = n }
    END {
      for (k = 1; k <= n; k++) if (error[k] <= 1.1 * error[best] && (cheap == 0 || cfl[k] > cfl[cheap])) cheap = k;
      for (k = 1; k <= n; k++) rows = rows sprintf("%s%s %.4f / %s", (k > 1 ? "; " : ""), method[k], error[k], shown(cfl[k]));
      printf "- **Accuracy against the size of the step** (RMS/v0 at 40 cells and CFL 0.5, data/dyka_baselines.csv, beside the largest CFL stable at v0): the most accurate, %s (%.4f), has its largest stable CFL %s; of the methods within 10 %% of its error the largest stable step is %s'"'"'s (CFL %s, %.4f), the most accurate for the cost of its steps if the error held at that CFL (RMS at CFL 0.5 / stable up to: %s). The largest stable CFL of every row is %s'"'"'s, %s.\n", method[best], error[best], shown(cfl[best]), method[cheap], cfl[cheap], error[cheap], rows, widest, widest_cfl }'
  echo
} >"$MPM_RESULTS/report/21_dyka_stability.md"
ls "$figures"/dyka_* >/dev/null 2>&1 || status=1
exit $status
