#!/usr/bin/env bash
# The tables of paper/10_integrator_analysis.md and paper/11_stress_update.md, generated from runs of the
# built CLI, so that no number on those pages is typed by hand:
#   paper/integrator_tables.sh BUILD_DIR          rewrites the tables between their markers in the pages
#   paper/integrator_tables.sh BUILD_DIR --check  exits 1, naming the table, when a page differs (ctest)
# Table "limits": `mpm stability` for each method (the code's own linearised step against the one-mode
# analysis). Table "energy": the energy of scenes/vibrating_bar.toml (64 cells, CFL 0.5, one period) as
# measured by `mpm run`, against (det A)^(T / dt) with Omega = CFL sin(pi / 2N), the discrete first mode.
# Table "stress_update" (paper/11): `mpm stability` of forward Euler with each stress update, USF, USL, MUSL.
set -euo pipefail
build=$1 mode=${2:-write}
root=$(cd "$(dirname "$0")/.." && pwd)
case $build in /*) mpm=$build/bin/mpm ;; *) mpm=$root/$build/bin/mpm ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

limits() {
  echo "| shape | ppc | dim | integrator | gamma | omega_max h / c | limit of Omega | CFL limit, code's step | CFL limit, analysis |"
  echo "|---|---|---|---|---|---|---|---|---|"
  while read -r label options; do
    # shellcheck disable=SC2086
    "$mpm" stability $options | tail -n 1 | awk -F, -v label="$label" '{
      split(label, part, "/"); gsub(/-/, " ", part[1]); gsub(/-/, " ", part[2]);
      printf "| %s | %s | %s | %s | %s | %.4f | %.4f | %.4f | %.4f |\n", part[1], $8, $1, part[2], $4 == "fe" ? "-" : $6, $12, $14 * $12, $13, $14 }'
  done <<'EOF'
linear/forward-Euler --integrator fe
linear/Eq.-(32) --integrator npc --newmark-gamma 0.5
linear/Eq.-(32) --integrator npc --newmark-gamma 0.75
linear/Eq.-(32) --integrator npc --newmark-gamma 1
linear/average --integrator npc --npc-velocity average --newmark-gamma 0.5
linear/average --integrator npc --npc-velocity average --newmark-gamma 0.75
ugimp/forward-Euler --shape ugimp --integrator fe
ugimp/Eq.-(32) --shape ugimp --integrator npc
LME-gamma-0.8/forward-Euler --shape lme --lme-gamma 0.8 --integrator fe
LME-gamma-0.8/Eq.-(32) --shape lme --lme-gamma 0.8 --integrator npc
LME-gamma-1.5/Eq.-(32) --shape lme --lme-gamma 1.5 --integrator npc
LME-gamma-3/forward-Euler --shape lme --lme-gamma 3 --integrator fe
LME-gamma-3/Eq.-(32) --shape lme --lme-gamma 3 --integrator npc
linear/forward-Euler --integrator fe --ppc 2
linear/Eq.-(32) --integrator npc --ppc 2
linear/forward-Euler --integrator fe --dim 2
linear/Eq.-(32) --integrator npc --dim 2
EOF
}

energy() {
  echo "| integrator | gamma | steps | predicted E(T)/E(0) | measured E(T)/E(0) |"
  echo "|---|---|---|---|---|"
  for scheme in eq32 average; do
    for gamma in 0.5 0.75 1; do
      "$mpm" run "$root/scenes/vibrating_bar.toml" --out "$work/$scheme$gamma" --set grid.cells=[64] \
        --set 'solver.integrator="npc"' --set "solver.npc_velocity=\"$scheme\"" --set "solver.newmark_gamma=$gamma" \
        --set output.snapshots=[] >/dev/null
      awk -F, -v scheme="$scheme" -v gamma="$gamma" -v cells=64 -v cfl=0.5 '
        NR == 2 { first = $4 } NR > 1 { last = $4 }
        END {
          pi = atan2(0, -1); Omega = cfl * sin(pi / (2 * cells)); steps = 4 * cells / cfl;
          det = scheme == "eq32" ? 1 - (1 - gamma) * Omega * Omega : 1;
          printf "| %s | %s | %d | %.6f | %.6f |\n", scheme == "eq32" ? "Eq. (32)" : "average", gamma, steps, det ^ steps, last / first }' \
        "$work/$scheme$gamma/energy.csv"
    done
  done
}

stress_update() {
  echo "| shape | ppc | dim | omega_max h / c | USF | USL | MUSL |"
  echo "|---|---|---|---|---|---|---|"
  while read -r label options; do
    row="| ${label//-/ } "
    for update in usf usl musl; do
      # shellcheck disable=SC2086
      line=$("$mpm" stability $options --stress-update "$update" | tail -n 1)
      [[ $update == usf ]] && row+=$(echo "$line" | awk -F, '{ printf "| %s | %s | %.4f ", $8, $1, $12 }')
      row+=$(echo "$line" | awk -F, '{ printf "| %.4f ", $13 }')
    done
    echo "$row|"
  done <<'EOF'
linear --shape linear
uGIMP --shape ugimp
B-spline-2 --shape bspline2
B-spline-3 --shape bspline3
LME-gamma-3 --shape lme --lme-gamma 3
linear --shape linear --ppc 2
B-spline-2 --shape bspline2 --ppc 2
B-spline-3 --shape bspline3 --ppc 2
LME-gamma-3 --shape lme --lme-gamma 3 --ppc 2
linear --shape linear --dim 2
B-spline-2 --shape bspline2 --dim 2
EOF
}

limits >"$work/limits.md"
energy >"$work/energy.md"
stress_update >"$work/stress_update.md"

status=0
for entry in limits:10_integrator_analysis.md energy:10_integrator_analysis.md stress_update:11_stress_update.md; do
  table=${entry%%:*} page=$root/paper/${entry#*:}
  begin="<!-- begin table $table: paper/integrator_tables.sh -->" end="<!-- end table $table -->"
  current=$(awk -v b="$begin" -v e="$end" '$0 == e { inside = 0 } inside { print } $0 == b { inside = 1 }' "$page")
  if [[ $mode == --check ]]; then
    if [[ "$current" != "$(cat "$work/$table.md")" ]]; then
      echo "paper/${entry#*:}: table '$table' differs from what the code gives now:"
      diff <(echo "$current") "$work/$table.md" || true
      echo "(run paper/integrator_tables.sh $build to rewrite it)"
      status=1
    fi
  else
    awk -v b="$begin" -v e="$end" -v file="$work/$table.md" '
      $0 == e { while ((getline line < file) > 0) print line; inside = 0 }
      !inside { print } $0 == b { inside = 1 }' "$page" >"$work/page.md"
    cp "$work/page.md" "$page"
  fi
done
[[ $mode == --check && $status -eq 0 ]] && echo "paper/10_integrator_analysis.md, paper/11_stress_update.md: every table agrees with the code"
exit $status
