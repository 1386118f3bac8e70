#!/usr/bin/env bash
# paper/13_lab.md, the lab: every ```sh block of the page runs as written, in order, in a scratch folder holding
# the scenes and build/bin/mpm (the ```bash blocks, which edit or rebuild the code, are left to the tests the page
# names), and each exercise's answer is checked against what they print and write. Exercise 1 also checks every
# particle number of paper/12_worked_example.md's tables (the `<!-- worked INTEGRATOR STEP particle P QUANTITY -->`
# markers of the particle update) against the snapshot one step of the run writes. Usage: lab.sh MPM
set -u
mpm=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
mkdir -p "$work/build/bin"
ln -s "$mpm" "$work/build/bin/mpm"
cp -r "$root/scenes" "$work/scenes"
awk '/^```sh$/ { block++; inside = 1; next }
     inside && /^```$/ { inside = 0; next }
     inside { print > (dir "/block" block ".sh") }' dir="$work" "$root/paper/13_lab.md"
for block in 1 2 3 4 5; do
  [[ -s "$work/block$block.sh" ]] || { fail "lab block $block not found"; continue; }
  (cd "$work" && bash "block$block.sh" >"out$block" 2>"err$block") || fail "lab block $block: $(cat "$work/err$block")"
done
[[ -s "$work/block6.sh" ]] && fail "paper/13_lab.md has more sh blocks than this test checks"

# 1. One step by hand: the book's particle numbers against the snapshots (x, v_x, sigma_xx, density).
column_of() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
checked=0
while read -r value integrator particle quantity; do
  case $integrator in fe) folder=we-fe ;; npc) folder=we-npc ;; npc_corrected) folder=we-corrected ;; *) continue ;; esac
  case $quantity in x) name=x ;; v) name=v_x ;; stress) name=sigma_xx ;; density) name=density ;; *) continue ;; esac
  snapshot=$work/$folder/snapshot_0000.csv
  [[ -f $snapshot ]] || { fail "no $folder/snapshot_0000.csv"; continue; }
  got=$(awk -F, -v c="$(column_of "$snapshot" "$name")" -v row=$((particle + 2)) 'NR == row { print $c }' "$snapshot")
  awk -v a="$got" -v b="$value" 'BEGIN { d = a - b; exit !(d < 5e-4 && d > -5e-4 && a != "") }' ||
    fail "paper/12: $integrator particle $particle $quantity: the book says $value, the run $got"
  checked=$((checked + 1))
done < <(grep -oE '[-−]?[0-9.]+<!-- worked [a-z_]+ [0-9]+ particle [0-9] [a-z_]+ -->' "$root/paper/12_worked_example.md" |
  sed -E 's/−/-/; s/<!-- worked ([a-z_]+) [0-9]+ particle ([0-9]) ([a-z_]+) -->/ \1 \2 \3/')
[[ $checked -ge 18 ]] || fail "only $checked particle numbers of paper/12 checked"

# 2. Free fall: x = 0.5 + 9.81 / 2 as printed; 0.5 + 9.81 / 2 + g dt t - g dt^2 / 2 (dt = 5e-4) corrected.
last_x() { awk -F, 'END { print $2 }' "$work/$1/observers.csv"; }
awk -v x="$(last_x fall-projected)" 'BEGIN { exit !(x - 5.405 < 1e-9 && 5.405 - x < 1e-9) }' ||
  fail "free fall, projected: x = $(last_x fall-projected), not 5.405"
awk -v x="$(last_x fall-corrected)" 'BEGIN { e = 5.405 + 9.81 * 5e-4 - 9.81 * 2.5e-7 / 2; exit !(x - e < 1e-9 && e - x < 1e-9) }' ||
  fail "free fall, corrected: x = $(last_x fall-corrected), not 5.405 + g dt t - g dt^2 / 2"

# 3. The stability limits and the runs just above and below them.
limits=$(awk -F, '$1 == "1" { print $4, $13 }' "$work/out3")
awk '$1 == "fe" && $2 > 1.999 && $2 < 2.001 { fe = 1 } $1 == "npc" && $2 > 1.4137 && $2 < 1.4147 { npc = 1 }
     END { exit !(fe && npc) }' <<<"$limits" || fail "mpm stability: $limits (want fe 2, npc 1.414)"
for expected in "fe at CFL 1.95: exit 0" "fe at CFL 2.05: exit 3" "npc at CFL 1.38: exit 0" "npc at CFL 1.45: exit 3" \
  "usf at CFL 0.75: exit 0" "usl at CFL 0.75: exit 3" "musl at CFL 0.75: exit 0" \
  "linear at 2560 cells: exit 3" "ugimp at 2560 cells: exit 0"; do
  grep -qxF "$expected" "$work"/out[345] || fail "want '$expected': $(cat "$work"/out[345] | tr '\n' ';')"
done

grep -q "^failure: .*unstable: energy grew" "$work/out5" || fail "linear at 2560 cells: no energy growth in $(cat "$work/out5")"
# 5, its last sentence: with the scene's own 4 cells of margin the linear run stops earlier, its free end's particle
# off the grid
(cd "$work" && "$mpm" run scenes/dyka_bar.toml --out crossing-margin4 --set grid.cells=[2560] --set solver.shape='"linear"' \
  --set solver.end_time=7.0e-5 --set output.snapshots=[] >/dev/null 2>crossing-margin4.log)
margin4=$(grep -h "^failure" "$work/crossing-margin4.log") margin400=$(grep -h "^failure" "$work"/crossing-linear.log)
t4=$(sed -n 's/.*t = \([0-9.e+-]*\) s.*/\1/p' <<<"$margin4") t400=$(sed -n 's/.*t = \([0-9.e+-]*\) s.*/\1/p' <<<"$margin400")
[[ $margin4 == *"particle left the grid"* ]] || fail "linear at 2560 cells, 4 cells of margin: '$margin4', want a particle off the grid"
python3 -c "import sys; sys.exit(not float(sys.argv[1]) < float(sys.argv[2]))" "${t4:-nan}" "${t400:-nan}" ||
  fail "linear at 2560 cells: stopped at t = $t4 s with 4 cells of margin, not before $t400 s with 400"
# 3. mpm run warns above each limit and only there.
for run in fe-2.05:2.000 npc-1.45:1.414; do
  log=$work/cfl-${run%%:*}.log cfl=${run%%:*} cfl=${cfl#*-}
  grep -qF "solver.cfl: $cfl is above the stability limit ${run#*:}" "$log" ||
    fail "exercise 3: no warning above the limit in $log: $(cat "$log")"
done
for run in fe-1.95 npc-1.38; do
  ! grep -q "above the stability limit" "$work/cfl-$run.log" || fail "exercise 3: a warning below the limit ($run)"
done

# 6. The call the exercise comments out is still there; 7. the planted bug still applies (its answer: below).
grep -qF 'newmark_corrector(newmark_gamma, dt, grid);' "$root/mpm/integrators/newmark_predictor_corrector.hpp" ||
  fail "exercise 6: no corrector call to comment out in newmark_predictor_corrector.hpp"
original=$(awk -F'\t' '$1 == "force_internal_mass" { print $4 }' "$root/tests/mutants/mutants.tsv")
[[ -n $original && $(grep -cF "$original" "$root/mpm/transfer/nodal_forces.hpp") -eq 1 ]] ||
  fail "exercise 7: the mutant force_internal_mass no longer applies to mpm/transfer/nodal_forces.hpp"
replacement=$(awk -F'\t' '$1 == "force_internal_mass" { print $5 }' "$root/tests/mutants/mutants.tsv")
for text in "${original#*= }" "${replacement#*= }"; do
  grep -qF "\`${text%;}\`" "$root/paper/13_lab.md" || fail "exercise 7: the page does not quote '${text%;}'"
done

# 7. The planted bug's answer: forward Euler's step 1 from the trace, with m_p for V_p = m_p / rho_p in Eq. (14)
# (the mutant's one change) carried through Eqs. (12), (19) and (21) with linear hats, against the page's numbers.
"$mpm" trace "$root/scenes/worked_example.toml" --step 1 >"$work/trace.csv" 2>"$work/trace.err" ||
  fail "exercise 7: mpm trace: $(cat "$work/trace.err")"
answer=$(grep -oE '\\mathbf f_I\^\{int\} = \([^)]*\)|v_p = \([^)]*\)|x_p = \([^)]*\)' "$root/paper/13_lab.md" |
  sed -n '/f_I/,$p' | tr -d '\\' | head -3 | tr '\n' ';')
python3 - "$work/trace.csv" "$answer" <<'PY' || fail "exercise 7: the page's answer is not the mutant's step (above)"
import re, sys
rows, header, dt = {}, [], None
for line in open(sys.argv[1]):
    line = line.strip()
    if line.startswith("# mpm trace"):
        dt = float(re.search(r"dt = ([0-9.e+-]+) s", line).group(1))
    if not line or line.startswith("#"):
        continue
    fields = line.split(",")
    if fields[0] == "phase":
        header = fields
    else:
        rows.setdefault((fields[0], fields[2]), []).append(dict(zip(header, fields)))
nodes, particles = rows[("forces", "node")], rows[("stress", "particle")]
x_I = [float(n["x_I"]) for n in nodes]
h = x_I[1] - x_I[0]
def hat(x, I): return max(0.0, 1.0 - abs(x - x_I[I]) / h)
def slope(x, I): return 0.0 if hat(x, I) == 0.0 else (1.0 if x < x_I[I] else -1.0) / h
f_int, f_int_true = [0.0] * len(nodes), [0.0] * len(nodes)
for p in particles:
    x, m, sigma, rho = (float(p[k]) for k in ("x_p_k", "m_p", "sigma_p_k1_xx", "rho_p_k1"))
    for I in range(len(nodes)):
        f_int[I] -= sigma * slope(x, I) * m
        f_int_true[I] -= sigma * slope(x, I) * m / rho
f = [0.0 if n["fixed"] != "-" else float(n["f_I_k1_x"]) + float(n["r_I_x"]) - f_int_true[I] + f_int[I]
     for I, n in enumerate(nodes)]
m_I = [float(n["m_I"]) for n in nodes]
p_k1 = [float(n["p_I_k_x"]) + dt * f[I] for I, n in enumerate(nodes)]
v = [float(p["v_p_k_x"]) + dt * sum(hat(float(p["x_p_k"]), I) * f[I] / m_I[I] for I in range(len(nodes)))
     for p in particles]
x = [float(p["x_p_k"]) + dt * sum(hat(float(p["x_p_k"]), I) * p_k1[I] / m_I[I] for I in range(len(nodes)))
     for p in particles]
got = {"f_I^{int}": f_int, "v_p": v, "x_p": x}
quoted = dict(re.findall(r"(?:mathbf )?(f_I\^\{int\}|v_p|x_p) = \(([^)]*)\)", sys.argv[2]))
ok = len(quoted) == 3
for name, values in got.items():
    texts = [t.strip().replace("−", "-") for t in quoted.get(name, "").split(",")]
    for text, value in zip(texts, values):
        tolerance = 0.5 * 10.0 ** -(len(text.split(".")[1]) if "." in text else 0)
        ok = ok and len(texts) == len(values) and abs(float(text) - value) <= tolerance + 1e-12
    print(f"exercise 7: {name}: the page ({quoted.get(name)}), the mutant's step {[round(g, 6) for g in values]}")
sys.exit(0 if ok else 1)
PY

echo "lab: $checked numbers of the worked example, 7 exercises, $failures failed"
[[ $failures -eq 0 ]]
