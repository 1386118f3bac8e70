#!/usr/bin/env bash
# `mpm trace`: the phases of one step of every integrator variant, 1D and 2D, on scenes of a few cells; the nodal
# mass and momentum of step 1 and the momentum balance and a reaction checked by hand, in awk, from the particle rows
# the trace prints (never by the program under test); two traces compared (--diff of two files, --against and
# --against-set of two runs): exit 0 when they agree, 1 naming the first difference, 2 for a file that is not a trace;
# bad options refused with exit 2 naming the option, nothing on stdout. Usage: cli_trace.sh MPM
set -u
mpm=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# near GOT WANT TOL: |GOT - WANT| <= TOL
near() { awk -v g="$1" -v w="$2" -v t="$3" 'BEGIN { d = g - w; if (d < 0) d = -d; exit !(d <= t) }'; }
check() {  # check WHAT GOT WANT TOL
  [[ -n "$2" ]] && near "$2" "$3" "$4" || fail "$1: got '$2', want $3 (tolerance $4)"
}
# value FILE PHASE AT INDEX COLUMN: the value of COLUMN in the row of node or particle INDEX after PHASE
value() {
  awk -F, -v phase="$2" -v at="$3" -v index_="$4" -v name="$5" '
    /^phase,/ { delete c; for (i = 1; i <= NF; i++) c[$i] = i; next }
    $1 == phase && $3 == at && $4 == index_ && (name in c) { print $c[name]; exit }' "$1"
}
bad() {  # bad PATTERN ARGS...: exit 2, stderr matching PATTERN, nothing on stdout
  local pattern=$1; shift
  "$mpm" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [[ $got -ne 2 ]] || ! grep -qE "$pattern" "$work/err" || [[ -s "$work/out" ]]; then
    fail "mpm $* -> exit $got (want 2), stderr: $(cat "$work/err"), stdout: $(head -c 200 "$work/out")"
  fi
}

# A bar of 2 cells (h = 1 m) with one particle in each (m_p = 4 kg), particle 0 at +2 m/s, particle 1 at -1 m/s,
# held at x = 2 m: every particle touches node 1.
cat >"$work/bar.toml" <<'EOF'
dimension = 1
[grid]
length = [2.0]
cells = [2]
margin_min = [1]
[material]
young_modulus = 100.0
density = 4.0
[[body]]
min = [0.0]
max = [2.0]
velocity = [-1.0]
[[initial_velocity]]
min = [0.0]
max = [1.0]
velocity = [2.0]
[[fixed]]
face = "xmax"
components = ["x"]
[solver]
end_time = 0.5
EOF

# hand_nodal FILE: m_I and p_I = sum_p N_Ip m_p v_p at nodes 1, 2, 3 (x = 0, 1, 2) from the particles of the reset
# phase, linear hats N_Ip = 1 - |x_p - x_I| / h with h = 1, one line "node mass momentum" each
hand_nodal() {
  awk -F, '/^phase,/ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $1 == "reset" && $3 == "particle" { n++; x[n] = $c["x_p_k"]; m[n] = $c["m_p"]; v[n] = $c["v_p_k_x"] }
    END { for (I = 1; I <= 3; I++) { M = 0; P = 0; xI = I - 1
            for (p = 1; p <= n; p++) {
              d = x[p] - xI; if (d < 0) d = -d; N = d < 1 ? 1 - d : 0; M += N * m[p]; P += N * m[p] * v[p] }
            printf "%d %.15g %.15g\n", I, M, P } }' "$1"
}

for method in fe npc; do
  "$mpm" trace "$work/bar.toml" --step 1 --set "solver.integrator=\"$method\"" >"$work/$method.csv" 2>"$work/err" ||
    fail "mpm trace bar --step 1 ($method): exit $?, $(cat "$work/err")"
  first=$([[ $method == fe ]] && echo mass_momentum || echo mass_predictor)
  [[ $(hand_nodal "$work/$method.csv" | wc -l) -eq 3 ]] || fail "$method: no particle rows in the reset phase"
  while read -r node mass momentum; do
    check "$method: m_I of node $node by hand" "$(value "$work/$method.csv" $first node "$node" m_I)" "$mass" 1e-12
    got=$(value "$work/$method.csv" $first node "$node" p_I_k_x)
    check "$method: p_I of node $node by hand" "$got" "$momentum" 1e-12
  done < <(hand_nodal "$work/$method.csv")
  # the sums by hand: m = (2, 4, 2) kg on the nodes x = 0, 1, 2 (node 1 is x = 0: one margin cell); p = (4, 2, -2)
  check "$method: m_I at x = 1 m" "$(value "$work/$method.csv" $first node 2 m_I)" 4 1e-12
  check "$method: p_I at x = 1 m" "$(value "$work/$method.csv" $first node 2 p_I_k_x)" 2 1e-12
done
check "fe: the fixed node's momentum held" "$(value "$work/fe.csv" fixed_momentum node 3 p_I_k_x)" 0 0
check "fe: the fixed node's force moved into its reaction" "$(value "$work/fe.csv" forces node 3 f_I_k1_x)" 0 0
# USF: the stress of step 1 makes the forces. Node 3 (x = 2 m) sees particle 1 only: f = -V_1 sigma_1 dN/dx, dN/dx = 1
m1=$(value "$work/fe.csv" forces particle 1 m_p)
rho1=$(value "$work/fe.csv" forces particle 1 rho_p_k1)
V1=$(awk -v m="$m1" -v r="$rho1" 'BEGIN { printf "%.15g", m / r }')
sigma1=$(value "$work/fe.csv" forces particle 1 sigma_p_k1_xx)
check "fe: the reaction at the held node, -V_p sigma_p" "$(value "$work/fe.csv" forces node 3 r_I_x)" \
  "$(awk -v V="$V1" -v s="$sigma1" 'BEGIN { printf "%.15g", -V * s }')" 1e-9
# Eq. (12): p_I^{k+1} = p_I^k + dt f_I at node 2, dt from the title line
dt=$(sed -n '1s/.*, dt = \([^ ]*\) s;.*/\1/p' "$work/fe.csv")
p_k=$(value "$work/fe.csv" momentum_balance node 2 p_I_k_x)
f=$(value "$work/fe.csv" momentum_balance node 2 f_I_k1_x)
check "fe: Eq. (12) at node 2" "$(value "$work/fe.csv" momentum_balance node 2 p_I_k1_x)" \
  "$(awk -v p="$p_k" -v dt="$dt" -v f="$f" 'BEGIN { printf "%.15g", p + dt * f }')" 1e-12
# Eq. (30): v_I^{k+1} = v_I^pred + gamma dt f_I / m_I at node 2, gamma = 1/2
dt=$(sed -n '1s/.*, dt = \([^ ]*\) s;.*/\1/p' "$work/npc.csv")
v=$(value "$work/npc.csv" corrector node 2 v_I_pred_x)
f=$(value "$work/npc.csv" corrector node 2 f_I_k1_x)
check "npc: Eq. (30) at node 2" "$(value "$work/npc.csv" corrector node 2 v_I_k1_x)" \
  "$(awk -v v="$v" -v dt="$dt" -v f="$f" 'BEGIN { printf "%.15g", v + 0.5 * dt * f / 4 }')" 1e-12

# Forward Euler's particle acceleration a_p^{k+1}, printed after its update: v_p^{k+1} = v_p^k + dt a_p^{k+1}.
dt=$(sed -n '1s/.*, dt = \([^ ]*\) s;.*/\1/p' "$work/fe.csv")
v_k=$(value "$work/fe.csv" reset particle 1 v_p_k_x)
v_k1=$(value "$work/fe.csv" euler_update particle 1 v_p_k1_x)
check "fe: a_p^{k+1} = (v_p^{k+1} - v_p^k) / dt" "$(value "$work/fe.csv" euler_update particle 1 a_p_k1_x)" \
  "$(awk -v a="$v_k" -v b="$v_k1" -v dt="$dt" 'BEGIN { printf "%.15g", (b - a) / dt }')" 1e-9
[[ -z $(value "$work/fe.csv" momentum_balance particle 1 a_p_k1_x) ]] || fail "fe: a_p^{k+1} before the update"

# Every variant prints its own phases, in order, numbered as its step() numbers them, each with its equations.
phases() { grep '^# phase' "$1" | sed 's/^# phase [0-9]* of [0-9]*: \([a-z_0-9]*\).*/\1/' | tr '\n' ' '; }
expect_fe="reset mass_momentum fixed_momentum velocity_k stress forces momentum_balance euler_update "
expect_usl="reset mass_momentum fixed_momentum velocity_k forces momentum_balance euler_update velocity_k1 stress "
expect_musl="reset mass_momentum fixed_momentum velocity_k forces momentum_balance euler_update reprojection"
expect_musl+=" velocity_k1 stress "
expect_npc="reset mass_predictor fixed_predictor stress forces corrector newmark_update "
[[ $(phases "$work/fe.csv") == "$expect_fe" ]] || fail "fe phases: $(phases "$work/fe.csv")"
[[ $(phases "$work/npc.csv") == "$expect_npc" ]] || fail "npc phases: $(phases "$work/npc.csv")"
grep -q '^# phase 5 of 7: forces, Eqs. (14)-(15)' "$work/fe.csv" || fail "fe: the forces' phase without its equations"
grep -q '^# phase 5 of 6: corrector, Eq. (30)' "$work/npc.csv" || fail "npc: the corrector's phase without Eq. (30)"
for order in usl musl; do
  "$mpm" trace "$work/bar.toml" --step 2 --set "solver.stress_update=\"$order\"" >"$work/$order.csv" 2>"$work/err" ||
    fail "mpm trace --step 2 ($order): exit $?, $(cat "$work/err")"
  expect=expect_$order
  [[ $(phases "$work/$order.csv") == "${!expect}" ]] || fail "$order phases: $(phases "$work/$order.csv")"
done
grep -q '^# phase 8 of 9: velocity_k1' "$work/usl.csv" || fail "usl: v_I^{k+1} not phase 8 (7 is MUSL's)"
grep -q '^# phase 7 of 9: reprojection' "$work/musl.csv" || fail "musl: the reprojection not phase 7"
grep -q '^# phase 4 of 6: forces' "$work/npc.csv" || fail "npc: the forces not phase 4"
awk -F, '/^phase,.*,f_I_k_x,/ { f = 1 } /^phase,.*,a_p_k_x,/ { a = 1 } END { exit !(f && a) }' "$work/usl.csv" ||
  fail "usl: no f_I^k, a_p^k (the forces of the stress at t_k)"
awk -F, '/^phase,/ && $0 ~ /v_I_k1_musl_x/ { found = 1 } END { exit !found }' "$work/musl.csv" ||
  fail "musl: no column v_I_k1_musl"
# Each position update of the predictor-corrector names the velocity that moves the particles.
for position in projected corrected predicted; do
  "$mpm" trace "$work/bar.toml" --step 3 --set 'solver.integrator="npc"' \
    --set "solver.npc_position_velocity=\"$position\"" \
    --set 'solver.npc_velocity="average"' >"$work/npc_$position.csv" 2>"$work/err" ||
    fail "mpm trace npc $position: exit $?, $(cat "$work/err")"
  grep -q "position update $position" "$work/npc_$position.csv" || fail "npc $position: the title does not say it"
done
awk -F, '/^phase,/ { last = $0 } END { exit !(last ~ /a_p_k1_x/) }' "$work/npc_projected.csv" ||
  fail "npc: the particles' a_p^{k+1} missing after the update"
# A step's phase rows: one per node with mass and per particle (3 nodes, 2 particles).
[[ $(grep -c '^newmark_update,' "$work/npc.csv") -eq 5 ]] || fail "npc: not one row per node and particle"
"$mpm" trace "$work/bar.toml" --step 1 --format table >"$work/table.txt" 2>"$work/err" || fail "--format table: exit $?"
grep -q '^phase 6 of 7: momentum_balance, Eq. (12)' "$work/table.txt" || fail "--format table: no phase title"
grep -qE '^ +node +x_I +fixed +m_I' "$work/table.txt" || fail "--format table: no aligned node header"

# 2D: 2 x 2 cells, one particle each, gravity; the nodal masses sum to the particles' (partition of unity).
cat >"$work/block.toml" <<'EOF'
dimension = 2
[grid]
length = [2.0, 2.0]
cells = [2, 2]
margin_max = [1, 1]
[material]
young_modulus = 100.0
poisson_ratio = 0.25
density = 4.0
[[body]]
min = [0.0, 0.0]
max = [2.0, 2.0]
velocity = [1.0, -0.5]
[[fixed]]
face = "ymin"
components = ["x", "y"]
[gravity]
acceleration = [0.0, -10.0]
[solver]
end_time = 0.5
EOF
for method in fe npc; do
  "$mpm" trace "$work/block.toml" --step 2 --set "solver.integrator=\"$method\"" \
    >"$work/2d_$method.csv" 2>"$work/err" ||
    fail "mpm trace 2D ($method): exit $?, $(cat "$work/err")"
  first=$([[ $method == fe ]] && echo mass_momentum || echo mass_predictor)
  sums=$(awk -F, -v first=$first '/^phase,/ { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $1 == first && $3 == "node" { M += $c["m_I"]; P += $c["p_I_k_y"] }
    $1 == "reset" && $3 == "particle" { m += $c["m_p"]; p += $c["m_p"] * $c["v_p_k_y"] }
    END { printf "%.15g %.15g %.15g %.15g", M, m, P, p }' "$work/2d_$method.csv")
  read -r M m P p <<<"$sums"
  check "2D $method: sum of m_I = sum of m_p" "$M" "$m" 1e-12
  [[ $method == npc ]] || check "2D fe: sum of p_I_y = sum of m_p v_p_y" "$P" "$p" 1e-12
  grep -q '^phase,equation,at,index,x_I,y_I,fixed,m_I,' "$work/2d_$method.csv" || fail "2D $method: no y_I column"
  grep -q ',sigma_p_k1_zz,rho_p_k1$' "$work/2d_$method.csv" || fail "2D $method: no sigma_zz, rho column"
  grep -qE '^[a-z_]+,[^,]*,node,[0-9]+,[^,]*,[^,]*,xy,' "$work/2d_$method.csv" ||
    fail "2D $method: no node fixed in x and y"
done

# Two traces compared: --diff of two files, --against(-set) of two runs in one process; exit 0 when they agree, 1
# naming the first difference, the step the titles name first, then phase by phase, row by row, column by column.
compare() {  # compare WANT OUT ARGS...: mpm ARGS exits WANT, its stdout in OUT
  local want=$1 out=$2; shift 2
  "$mpm" "$@" >"$out" 2>"$work/err"
  local got=$?
  [[ $got -eq $want ]] ||
    fail "mpm $* -> exit $got (want $want), stderr: $(cat "$work/err"), stdout: $(head -c 300 "$out")"
}
"$mpm" trace "$work/bar.toml" --step 1 >"$work/again.csv" 2>"$work/err" || fail "mpm trace bar --step 1: exit $?"
compare 0 "$work/same" trace --diff "$work/fe.csv" "$work/again.csv"
grep -qE '^the traces agree: [0-9]+ values in 8 phases, \|A - B\| <= 1e-12 max\(\|A\|, \|B\|, 1\)$' "$work/same" ||
  fail "--diff of two traces of one run: $(cat "$work/same")"
# CFL 0.25 for 0.5: dt = CFL h / c = 0.05 s for 0.1 s (c = 5 m/s), so particle 0's strain, dt dv/dx = -1.5 dt, halves.
"$mpm" trace "$work/bar.toml" --step 1 --set solver.cfl=0.25 >"$work/cfl.csv" 2>"$work/err" || fail "cfl 0.25: exit $?"
compare 1 "$work/cfl" trace --diff "$work/fe.csv" "$work/cfl.csv"
grep -qx 'first difference: the step, dt: 0.1 (A) vs 0.05 (B)' "$work/cfl" || fail "--diff, CFL: $(cat "$work/cfl")"
grep -qx '  6 values differ: phase 4 (stress, Eqs. (16) (17) (3)), particle 0, eps_p_k1_xx: -0.15 (A) vs -0.075 (B)' \
  "$work/cfl" || fail "--diff, CFL: not the stress's phase first: $(cat "$work/cfl")"
grep -qE '^[0-9]+ values differ in the step and 4 phases \(' "$work/cfl" ||
  fail "--diff, CFL: no count: $(cat "$work/cfl")"
# The same comparison in one process: the scene against itself with an override, or against another scene.
compare 1 "$work/cfl_set" trace "$work/bar.toml" --step 1 --against-set solver.cfl=0.25
[[ $(sed -n 2p "$work/cfl_set") == "B: $work/bar.toml --set solver.cfl=0.25" ]] ||
  fail "--against-set: $(head -2 "$work/cfl_set")"
diff <(tail -n +3 "$work/cfl") <(tail -n +3 "$work/cfl_set") >/dev/null ||
  fail "--against-set is not --diff of the files: $(cat "$work/cfl_set")"
{ cat "$work/bar.toml"; echo "cfl = 0.25"; } >"$work/other.toml"  # under [solver], bar.toml's last table
compare 1 "$work/other" trace "$work/bar.toml" --step 1 --against "$work/other.toml"
diff <(tail -n +3 "$work/cfl") <(tail -n +3 "$work/other") >/dev/null || fail "--against is not --diff of the files"
compare 0 "$work/same" trace "$work/bar.toml" --step 1 --against-set solver.cfl=0.5  # the default
compare 0 "$work/same" trace "$work/bar.toml" --step 1 --set solver.cfl=0.25 --against "$work/other.toml"
# One value planted in a copy (a kernel's edit that shows in one phase): named, counted; within a --tolerance.
awk -F, -v OFS=, '/^phase,/ { for (i = 1; i <= NF; i++) c[$i] = i }
  $1 == "forces" && $3 == "node" && $4 == 2 { $c["f_I_k1_int_x"] = 99 } 1' "$work/fe.csv" >"$work/planted.csv"
compare 1 "$work/planted" trace --diff "$work/fe.csv" "$work/planted.csv"
f=$(value "$work/fe.csv" forces node 2 f_I_k1_int_x)
grep -qx "first difference: phase 5 (forces, Eqs. (14)-(15)), node 2, f_I_k1_int_x: $f (A) vs 99 (B)" "$work/planted" &&
  grep -qx '1 value differs in 1 phase (|A - B| > 1e-12 max(|A|, |B|, 1))' "$work/planted" ||
  fail "--diff of a planted value: $(cat "$work/planted")"
awk -F, -v OFS=, '$1 == "reset" && $3 == "particle" && $4 == 1 { $5 = sprintf("%.15g", $5 * (1 + 4e-10)) } 1' \
  "$work/fe.csv" >"$work/near.csv"  # m_p, 4e-10 of it more
compare 1 "$work/out" trace --diff "$work/fe.csv" "$work/near.csv"
compare 0 "$work/out" trace --diff "$work/fe.csv" "$work/near.csv" --tolerance 1e-9
# A row or a phase in one trace only is a difference too; a file that is not a trace is bad input (below).
grep -v '^forces,.*,node,3,' "$work/fe.csv" >"$work/row.csv"
compare 1 "$work/out" trace --diff "$work/fe.csv" "$work/row.csv"
grep -qx 'first difference: phase 5 (forces, Eqs. (14)-(15)), node 3: in A only' "$work/out" ||
  fail "a row missing: $(cat "$work/out")"
compare 1 "$work/out" trace --diff "$work/usl.csv" "$work/musl.csv"
grep -qx '  1 in one trace only: phase 7 (reprojection): in B only' "$work/out" ||
  fail "USL against MUSL: $(cat "$work/out")"
awk -F, -v OFS=, 'NR == 5 { $5 = "abc" } 1' "$work/fe.csv" >"$work/bad.csv"
mkfifo "$work/fifo"
timeout 10 "$mpm" trace --diff "$work/fe.csv" "$work/fifo" >"$work/out" 2>"$work/err"
[[ $? -eq 2 ]] && grep -qx "error: $work/fifo: not a regular file (a FIFO)" "$work/err" ||
  fail "--diff of a FIFO: $(cat "$work/err")"

# Bad input: exit 2, the option named, nothing on stdout.
bad '^error: --step: must be a whole number from 1 to 10000000' trace "$work/bar.toml" --step 0
bad '^error: --step' trace "$work/bar.toml" --step -1
bad '^error: --step: must be a whole number' trace "$work/bar.toml" --step 1.5
bad '^error: --step: must be a whole number from 1 to 10000000' trace "$work/bar.toml" --step 20000000
bad '^error: --step: the run ends after step [0-9]+ \(t = 0.5 s, solver.end_time\)' trace "$work/bar.toml" --step 100000
bad '^error: --step: required' trace "$work/bar.toml"
bad '^error: --format: must be one of csv \| table' trace "$work/bar.toml" --step 1 --format json
bad "^error: .*solver.cfll" trace "$work/bar.toml" --step 1 --set solver.cfll=0.5
bad '^error: --bogus: unknown option' trace "$work/bar.toml" --step 1 --bogus
bad "^error: $work/none.toml" trace "$work/none.toml" --step 1
bad "^error: $work/bad.csv:5: $(sed -n 4p "$work/fe.csv" | cut -d, -f5): 'abc' is not a finite number" \
  trace --diff "$work/fe.csv" "$work/bad.csv"
bad "^error: $work/table.txt:1: not a CSV trace of mpm trace" trace --diff "$work/table.txt" "$work/fe.csv"
bad "^error: $work/none.csv: cannot be read" trace --diff "$work/fe.csv" "$work/none.csv"
bad '^error: --diff: give two trace files, A.csv B.csv, not 1' trace --diff "$work/fe.csv"
bad '^error: --diff: give two trace files, A.csv B.csv, not 3' trace --diff "$work/fe.csv" "$work/fe.csv" "$work/fe.csv"
bad '^error: --step: give it or --diff, not both' trace --diff "$work/fe.csv" "$work/cfl.csv" --step 1
bad '^error: SCENE.toml: give it or --diff, not both' trace "$work/bar.toml" --diff "$work/fe.csv" "$work/cfl.csv"
bad '^error: SCENE.toml: required' trace --step 1
bad '^error: --tolerance: only with --diff, --against or --against-set' trace "$work/bar.toml" --step 1 --tolerance 1e-6
bad '^error: --tolerance: must be a number in \[0, 1\]' trace --diff "$work/fe.csv" "$work/cfl.csv" --tolerance -1
bad '^error: --format: give it or --against-set, not both' trace "$work/bar.toml" --step 1 --against-set solver.cfl=1 \
  --format table
bad '^error: --against-set\(1\):1: solver.cfll: unknown key' trace "$work/bar.toml" --step 1 --set solver.cfl=0.4 \
  --against-set solver.cfll=1
bad "^error: $work/none.toml" trace "$work/bar.toml" --step 1 --against "$work/none.toml"
bad '^error: --against: must name a scene file' trace "$work/bar.toml" --step 1 --against ''
"$mpm" trace --help >"$work/help" && grep -q -- '--step' "$work/help" || fail "mpm trace --help lacks --step"
"$mpm" --help >"$work/help" && grep -q 'mpm trace' "$work/help" || fail "mpm --help lacks mpm trace"

echo "cli_trace: $failures failures"
[[ $failures -eq 0 ]]
