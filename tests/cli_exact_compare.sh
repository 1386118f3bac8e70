#!/usr/bin/env bash
# `mpm exact` and `mpm compare`: their happy paths against closed forms computed here, by
# hand in awk, never by the program under test; and their bad inputs: exit 2, one line naming the
# option or key, nothing on stdout and no file written. Usage: cli_exact_compare.sh MPM
set -u
mpm=$1
scenes=$(cd "$(dirname "$0")/.." && pwd)/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
calc() { awk "BEGIN { printf \"%.17g\", $1 }"; }
# near GOT WANT TOL: |GOT - WANT| <= TOL
near() { awk -v g="$1" -v w="$2" -v t="$3" 'BEGIN { d = g - w; if (d < 0) d = -d; exit !(d <= t) }'; }
# field FILE ROW COLUMN_NAME: the value of a named column on data row ROW (1 = first after the header)
field() { awk -F, -v row="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i } NR == row + 1 { print $c }' "$1"; }
check() {  # check WHAT GOT WANT TOL
  near "$2" "$3" "$4" || fail "$1: got $2, want $3 (tolerance $4)"
}
bad() {  # bad PATTERN ARGS...: exit 2, stderr matching PATTERN, nothing on stdout, no plot file
  local pattern=$1; shift
  "$mpm" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [[ $got -ne 2 ]] || ! grep -qE "$pattern" "$work/err" || [[ -s "$work/out" ]] || [[ -e "$work/never.png" ]]; then
    fail "mpm $* -> exit $got (want 2), stderr: $(cat "$work/err"), stdout: $(head -c 200 "$work/out")"
  fi
}

bar=$scenes/dyka_bar.toml
L=0.1333 E=200e9 rho=7833
c=$(calc "sqrt($E / $rho)")
Z=$(calc "sqrt($E * $rho)")

# --- mpm exact, the Dyka bar (v0 = -5 m/s on [0, L/4], free at 0, fixed at L). By hand: R^I = R^II = v0/2
# on [0, L/4]; at X = L/2 the right-going half (R^I = v0/2) passes while L/4 < ct < 3L/4 and nothing else
# arrives before ct = 5L/4, so there v = v0/2 = -2.5 m/s, sigma = Z (R^II - R^I) = 2.5 Z (tension) and
# u = v0/2 (t - L/(4c)). At the free end before the unloading wave returns (ct < L/4), v = v0, sigma = 0, u = v0 t.
t=$(calc "$L / (2 * $c)")
t0=$(calc "$L / (8 * $c)")
"$mpm" exact "$bar" --at "$(calc "$L / 2")" --at 0 --times "$t:1:$t" >"$work/bar.csv" || fail "mpm exact on the Dyka bar"
[[ $(head -1 "$work/bar.csv") == "t,X,u_x,v_x,sigma_xx" ]] || fail "mpm exact header: $(head -1 "$work/bar.csv")"
[[ $(wc -l <"$work/bar.csv") -eq 3 ]] || fail "mpm exact: one row per time and point"
check "Dyka v(L/2, L/2c)" "$(field "$work/bar.csv" 1 v_x)" -2.5 1e-12
check "Dyka sigma(L/2, L/2c)" "$(field "$work/bar.csv" 1 sigma_xx)" "$(calc "2.5 * $Z")" 1e-4
check "Dyka u(L/2, L/2c)" "$(field "$work/bar.csv" 1 u_x)" "$(calc "-2.5 * ($t - $L / (4 * $c))")" 1e-17
check "Dyka v(0, L/2c)" "$(field "$work/bar.csv" 2 v_x)" 0 1e-12  # the free end rests for L/4 < ct < 7L/4
"$mpm" exact "$bar" --at 0 --times "0:$t0:$t0" >"$work/bar0.csv" || fail "mpm exact at t = 0"
check "Dyka v(0, 0)" "$(field "$work/bar0.csv" 1 v_x)" -5 1e-12
check "Dyka u(0, L/8c)" "$(field "$work/bar0.csv" 2 u_x)" "$(calc "-5 * $t0")" 1e-17
# The same times from a file (a header, a comment and a blank line skipped) give the same rows.
printf 'time\n# comment\n\n%s\n' "$t" >"$work/times.txt"
"$mpm" exact "$bar" --at "$(calc "$L / 2")" --at 0 --times-file "$work/times.txt" >"$work/bar_file.csv" || fail "--times-file"
cmp -s "$work/bar.csv" "$work/bar_file.csv" || fail "--times-file and --times differ"
# Initial data from the scene: a second box at +2 m/s on the quarter next to the fixed end, and a uniform
# initial stress s0 from a formula. At X = L/2, before any front arrives (ct < L/4): v = 0, sigma = s0.
"$mpm" exact "$bar" --set 'initial_field.stress=["-1e6"]' --at "$(calc "$L / 2")" --times "$t0:1:$t0" >"$work/s0.csv" || fail "initial stress"
check "Dyka with initial stress, sigma(L/2, L/8c)" "$(field "$work/s0.csv" 1 sigma_xx)" -1e6 1e-6

# --- the soil column: the static finite-strain settlement (mpm/exact/column_log_strain.hpp) at the top,
# u(H) = (1 - exp(-aH))/a - H with a = rho g / M, and sigma_xx = nu/(1 - nu) sigma_yy = rho g H nu/(1 - nu) at the base.
soil=$scenes/soil_block.toml
"$mpm" exact "$soil" --strain finite --set material.poisson_ratio=0.3 --at 4.5,10 --at 4.5,0 --times 0:7:7 >"$work/soil.csv" \
  || fail "mpm exact on the soil column"
[[ $(head -1 "$work/soil.csv") == "t,X,Y,u_x,u_y,v_x,v_y,sigma_xx,sigma_yy,sigma_xy" ]] || fail "2D header: $(head -1 "$work/soil.csv")"
M=$(calc "5e6 * 0.7 / (1.3 * 0.4)")
a=$(calc "6000 * 9.81 / $M")
check "column u_y(H), finite strain" "$(field "$work/soil.csv" 3 u_y)" "$(calc "(1 - exp(-$a * 10)) / $a - 10")" 1e-12
check "column sigma_xx(0)" "$(field "$work/soil.csv" 4 sigma_xx)" "$(calc "-6000 * 9.81 * 10 * 0.3 / 0.7")" 1e-6
# Small strain, constant gravity: the top falls freely until the base is felt (t < H/c = 0.35 s), v = -g t.
"$mpm" exact "$soil" --set gravity.ramp_period=0 --at 4.5,10 --times 0.1:1:0.1 >"$work/fall.csv" || fail "free fall"
check "column v_y(H, 0.1 s)" "$(field "$work/fall.csv" 1 v_y)" -0.981 1e-3

# --- the vibrating bar, mode 2: v = V cos(3 pi X / 2L) cos(omega t), omega = 3 pi c / 2L; at X = L/9 and
# t = T/8 (omega t = pi/4): V cos(pi/6) cos(pi/4) = V sqrt(6)/4. V = 1e-6 L pi c / (2 L) from the scene's constants.
vib=$scenes/vibrating_bar.toml
V=$(calc "1e-6 * 3.14159265358979 * $c / 2")
T2=$(calc "4 / (3 * $c)")
"$mpm" exact "$vib" --set exact_parameters.mode=2 --at "$(calc "1 / 9")" --times "$(calc "$T2 / 8"):1:1" >"$work/vib.csv" || fail "vibrating bar"
check "vibrating bar mode 2 v" "$(field "$work/vib.csv" 1 v_x)" "$(calc "$V * sqrt(6) / 4")" 1e-15
"$mpm" exact "$vib" --strain finite --at "$(calc "1 / 9")" --times "$(calc "$T2 / 8"):1:1" --set exact_parameters.mode=2 >"$work/vibf.csv" \
  || fail "vibrating bar, finite strain"
check "vibrating bar mode 2 v, finite strain (512 cells)" "$(field "$work/vibf.csv" 1 v_x)" "$(calc "$V * sqrt(6) / 4")" "$(calc "1e-3 * $V")"

# --- manufactured_small: u = A sin(omega t) (sin kX sin kY, sin 2kX sin kY); at (1/4, 1/2) and omega t = pi/2:
# u_x = A sqrt(2)/2, u_y = A. omega = c_p pi / L, c_p = sqrt((lambda + 2G)/rho), E = 10 MPa, nu = 0.3, rho = 2000.
cp=$(calc "sqrt((0.3 * 10e6 / (1.3 * 0.4) + 10e6 / 1.3) / 2000)")
"$mpm" exact "$scenes/manufactured_small.toml" --at 0.25,0.5 --times "$(calc "0.5 / $cp"):1:1" >"$work/ms.csv" || fail "manufactured_small"
check "manufactured u_x" "$(field "$work/ms.csv" 1 u_x)" "$(calc "1e-6 * sqrt(2) / 2")" 1e-18
check "manufactured u_y" "$(field "$work/ms.csv" 1 u_y)" 1e-6 1e-18

# --- mpm compare: a CSV whose error is known in closed form. The Dyka bar at X = L/2, 40 samples in
# L/4 < ct < 3L/4 where v = -2.5 exactly; the CSV holds v + 0.1 and sigma - 1e6 Pa, with other columns
# and another name for the time: rms = max_abs = 0.1 m/s, rms/v0 = 0.02; rms = 1e6 Pa, rms/(Z v0) = 1e6/(5 Z).
awk -v c="$c" -v L="$L" -v Z="$Z" 'BEGIN { print "step,time,label,vel,stress"
  for (n = 1; n <= 40; n++) { t = (L / 4 + L / 2 * n / 41) / c; printf "%d,%.17g,x,%.17g,%.17g\n", n, t, -2.5 + 0.1, 2.5 * Z - 1e6 } }' >"$work/other.csv"
"$mpm" compare "$work/other.csv" "$bar" --at "$(calc "$L / 2")" --time-column time --column vel=v_x --column stress=sigma_xx \
  >"$work/score.csv" || fail "mpm compare (no tolerance: exit 0)"
[[ $(head -1 "$work/score.csv") == "column,quantity,samples,rms,rms_normalised,max_abs,t_of_max,rms_even,rms_odd,ringing,amplitude,amplitude_even,amplitude_odd,flat_rms,ending,ringing_even,ringing_odd,plateau_overshoot,plateau_deficit,plateau_deficit_even,plateau_deficit_odd" ]] ||
  fail "compare header: $(head -1 "$work/score.csv")"
check "compare rms of v, even rows" "$(field "$work/score.csv" 1 rms_even)" 0.1 1e-9
check "compare rms of v, odd rows" "$(field "$work/score.csv" 1 rms_odd)" 0.1 1e-9
[[ $(field "$work/score.csv" 1 ringing) == nan ]] || fail "compare ringing where the exact v is constant: want nan"
# A constant exact v: no amplitude to compare against (nan), and a flat line at its mean scores 0: the failed-score
# rule does not apply there (the flat line is the exact history itself; mpm/analysis/verdict.hpp): ending done.
[[ $(field "$work/score.csv" 1 amplitude) == nan ]] || fail "compare amplitude where the exact v is constant: want nan"
check "compare flat line of a constant v" "$(field "$work/score.csv" 1 flat_rms)" 0 1e-12
[[ $(field "$work/score.csv" 1 ending) == done ]] || fail "compare ending against a flat line that scores 0: want done"
check "compare rms of v" "$(field "$work/score.csv" 1 rms)" 0.1 1e-9
check "compare rms/v0" "$(field "$work/score.csv" 1 rms_normalised)" 0.02 1e-10
check "compare max_abs of v" "$(field "$work/score.csv" 1 max_abs)" 0.1 1e-9
check "compare samples" "$(field "$work/score.csv" 1 samples)" 40 0
check "compare rms of sigma" "$(field "$work/score.csv" 2 rms)" 1e6 1e-2
check "compare rms/(Z v0) of sigma" "$(field "$work/score.csv" 2 rms_normalised)" "$(calc "1e6 / (5 * $Z)")" 1e-9
"$mpm" compare "$work/other.csv" "$bar" --at "$(calc "$L / 2")" --time-column time --column vel=v_x --tolerance 0.03 >/dev/null 2>&1 \
  || fail "compare: rms/v0 = 0.02 within --tolerance 0.03 must exit 0"
"$mpm" compare "$work/other.csv" "$bar" --at "$(calc "$L / 2")" --time-column time --column vel=v_x --tolerance 0.01 >/dev/null 2>"$work/err"
[[ $? -eq 1 ]] || fail "compare: rms/v0 = 0.02 above --tolerance 0.01 must exit 1"
grep -q "above the tolerance 0.01" "$work/err" || fail "compare: exit 1 says why: $(cat "$work/err")"
# The vibrating bar: its closed form plus c = 3e-4 m/s at 25 irregular times over a period: rms = c, rms/V = c/V.
awk -v V="$V" -v c="$c" 'BEGIN { pi = 3.14159265358979; w = pi * c / 2; print "t,v"
  for (n = 0; n < 25; n++) { t = (n + 0.3 * (n % 3)) * 4 / c / 25; printf "%.17g,%.17g\n", t, V * cos(pi / 6) * cos(w * t) + 3e-4 } }' >"$work/vib_other.csv"
"$mpm" compare "$work/vib_other.csv" "$vib" --at "$(calc "1 / 3")" --column v=v_x >"$work/vib_score.csv" || fail "compare the vibrating bar"
check "compare rms, vibrating bar" "$(field "$work/vib_score.csv" 1 rms)" 3e-4 1e-12
check "compare rms/V, vibrating bar" "$(field "$work/vib_score.csv" 1 rms_normalised)" "$(calc "3e-4 / $V")" 1e-9
# Its damping: the offset moves the mean only, amplitude 1 on every row and on each half; the flat line's score is
# the exact series' RMS about its mean, by hand here; rms 3e-4 is below it: done. The same series at 0.4 of its swing
# about its mean (and 3e-4 off): amplitude 0.4 on every row and on each half.
awk -v V="$V" -v c="$c" 'BEGIN { pi = 3.14159265358979; w = pi * c / 2
  for (n = 0; n < 25; n++) { t = (n + 0.3 * (n % 3)) * 4 / c / 25; e[n] = V * cos(pi / 6) * cos(w * t); mean += e[n] / 25 }
  for (n = 0; n < 25; n++) sum += (e[n] - mean) ^ 2
  printf "%.17g %.17g\n", sqrt(sum / 25), mean }' >"$work/vib_flat"
read -r vib_flat vib_mean <"$work/vib_flat"
for column in amplitude amplitude_even amplitude_odd; do
  check "compare $column, vibrating bar offset" "$(field "$work/vib_score.csv" 1 $column)" 1 1e-9
done
check "compare flat_rms, vibrating bar" "$(field "$work/vib_score.csv" 1 flat_rms)" "$vib_flat" "$(calc "1e-9 * $vib_flat")"
[[ $(field "$work/vib_score.csv" 1 ending) == done ]] || fail "compare ending, vibrating bar: want done (rms 3e-4 < $vib_flat)"
awk -F, -v m="$vib_mean" 'NR == 1 { print; next } { printf "%s,%.17g\n", $1, m + 0.4 * ($2 - 3e-4 - m) + 3e-4 }' \
  "$work/vib_other.csv" >"$work/vib_damped.csv"
"$mpm" compare "$work/vib_damped.csv" "$vib" --at "$(calc "1 / 3")" --column v=v_x >"$work/vib_damped_score.csv" || fail "compare damped"
for column in amplitude amplitude_even amplitude_odd; do
  check "compare $column, vibrating bar at 0.4 of its swing" "$(field "$work/vib_damped_score.csv" 1 $column)" 0.4 1e-9
done
if command -v gnuplot >/dev/null; then
  "$mpm" compare "$work/other.csv" "$bar" --at "$(calc "$L / 2")" --time-column time --column vel=v_x --plot "$work/it's.png" >/dev/null 2>&1 \
    || fail "compare --plot"
  [[ -s "$work/it's.png" ]] || fail "compare --plot wrote no picture"
fi

# --- bad inputs: exit 2, a message naming the option or key, nothing written.
bad "^error: --at: required" exact "$bar" --times 0:1:1
bad "^error: --at 0.2: lies outside the body \[0, 0.1333\] m on x" exact "$bar" --at 0.2 --times 0:1:1
bad "^error: --at 1,2: give X \(m\) for this 1D scene" exact "$bar" --at 1,2 --times 0:1:1
bad "^error: --times '0:0:1': needs 0 <= T0 <= T1 and DT > 0" exact "$bar" --at 0 --times 0:0:1
bad "^error: --times 'a:1:2' is not a range" exact "$bar" --at 0 --times a:1:2
bad "^error: --times: missing" exact "$bar" --at 0
bad "^error: --times: give it or --times-file, not both" exact "$bar" --at 0 --times 0:1:1 --times-file "$work/times.txt"
printf 't\n1e-5\nsoon\n' >"$work/bad_times.txt"
bad "^error: --times-file $work/bad_times.txt:3: 'soon' is not a time" exact "$bar" --at 0 --times-file "$work/bad_times.txt"
bad "^error: --times-file $work/none.txt: cannot be read" exact "$bar" --at 0 --times-file "$work/none.txt"
bad "^error: .*exact: the scene names no exact solution" exact "$bar" --set 'exact="none"' --at 0 --times 0:1:1
bad "^error: --strain: 'dyka_bar' has no finite-strain reference" exact "$bar" --strain finite --at 0 --times 0:1:1
bad "^error: --strain: must be one of small \| finite, got 'large'" exact "$bar" --strain large --at 0 --times 0:1:1
bad "^error: --frobnicate: unknown option" exact "$bar" --frobnicate
# hostile sizes end in exit 2, never in a hang: a file without newlines, too many rows, a finite-strain bar run for hours
head -c 2000000 /dev/zero >"$work/zeros.csv"
bad "^error: --times-file $work/zeros.csv:1: a line longer than 1 MiB" exact "$bar" --at 0 --times-file "$work/zeros.csv"
bad "^error: $work/zeros.csv:1: a line longer than 1 MiB" compare "$work/zeros.csv" "$bar" --at 0 --column v=v_x
bad "^error: --times: t = 1e\+308 s is more than a million periods \(.* s\) of the solution" exact "$bar" --at 0 --times 1e308:1:1e308
bad "^error: --times: 600001 times at 2 points: at most 1000000 rows" exact "$bar" --at 0 --at 0.1 --times 0:1e-9:6e-4
bad "^error: --times: the finite-strain vibrating bar would take .* steps to reach t = 10 s" exact "$vib" --strain finite --at 0 --times 10:1:10
bad "^error: SCENE.toml: required" exact --at 0 --times 0:1:1
bad "^error: .*exact_parameters.velocity_amplitude: required by exact = \"vibrating_bar\"" exact "$bar" --set 'exact="vibrating_bar"' --at 0 --times 0:1:1
bad "^error: --set\(1\):1: exact_parameters.displacement_amplitude: must be small" exact "$scenes/manufactured_small.toml" \
  --set exact_parameters.displacement_amplitude=0.1 --at 0.5,0.5 --times 0:1:1
bad "^error: --set\(1\):1: initial_field.velocity: takes more than 1024 values along the bar" exact "$bar" \
  --set 'initial_field.velocity=["X"]' --at 0 --times 0:1:1
bad "^error: .*no column 'speed' in the header \(step, time, label, vel, stress\)" compare "$work/other.csv" "$bar" --at 0 --time-column time --column speed=v_x
bad "^error: .*no column 't' in the header" compare "$work/other.csv" "$bar" --at 0 --column vel=v_x
bad "^error: --column vel=u_y: 'u_y' is not a quantity of this 1D solution" compare "$work/other.csv" "$bar" --at 0 --time-column time --column vel=u_y
bad "^error: --column vel: give COL=QUANTITY" compare "$work/other.csv" "$bar" --at 0 --time-column time --column vel
bad "^error: --column: required" compare "$work/other.csv" "$bar" --at 0
bad "^error: $work/missing.csv: cannot be read" compare "$work/missing.csv" "$bar" --at 0 --column v=v_x
bad "^error: $work: is a folder" compare "$work" "$bar" --at 0 --column v=v_x
bad "^error: .*exact: the scene names no exact solution" compare "$work/other.csv" "$bar" --set 'exact="none"' --at 0 --time-column time --column vel=v_x
bad "^error: --tolerance: must be a number in \[0, .*got '-1'" compare "$work/other.csv" "$bar" --at 0 --time-column time --column vel=v_x --tolerance -1
bad "^error: --plot: $work/no/never.png: give a .png file" compare "$work/other.csv" "$bar" --at 0 \
  --time-column time --column vel=v_x --plot "$work/no/never.png"
bad "^error: SCENE.toml: required" compare "$work/other.csv" --at 0 --column vel=v_x
printf 't,v\n0,1\n1,2,3\n' >"$work/ragged.csv"
bad "^error: $work/ragged.csv:3: 3 fields; the header has 2" compare "$work/ragged.csv" "$bar" --at 0 --column v=v_x --plot "$work/never.png"
printf 't,v\n0,1\n1,fast\n' >"$work/text.csv"
bad "^error: $work/text.csv:3: v: 'fast' is not a finite number" compare "$work/text.csv" "$bar" --at 0 --column v=v_x
printf 't,v\n' >"$work/header_only.csv"
bad "^error: $work/header_only.csv: has a header but no data row" compare "$work/header_only.csv" "$bar" --at 0 --column v=v_x
# Sample times in [0, solver.end_time] (1e-6 of it beyond for round-off), increasing: each refusal names FILE:LINE
# (comments and blank lines counted) and the time column, before any --plot is drawn.
never=(--plot "$work/never.png")
printf 't,v\n-1,0\n' >"$work/negative.csv"
bad "^error: $work/negative.csv:2: t: -1 s is before t = 0" \
  compare "$work/negative.csv" "$bar" --at 0 --column v=v_x "${never[@]}"
printf 't,v\n0,-5\n# a comment\n\n1,0\n' >"$work/late.csv"
bad "^error: $work/late.csv:5: t: 1 s is after the scene's solver.end_time = 0.0002 s: times in ms or us\?" \
  compare "$work/late.csv" "$bar" --at 0 --column v=v_x "${never[@]}"
bad "^error: $work/late.csv:5: t: 1 s is after the scene's solver.end_time = 1e-05 s" \
  compare "$work/late.csv" "$bar" --set solver.end_time=1e-5 --set 'output.snapshots=[]' --at 0 --column v=v_x
printf 't,v\n0,-5\n2.000001e-4,0\n' >"$work/round_off.csv"  # 5e-7 of the end time beyond it: round-off
"$mpm" compare "$work/round_off.csv" "$bar" --at 0 --column v=v_x >/dev/null || fail "compare: 5e-7 beyond the end"
printf 't,v\n0,-5\n2.000003e-4,0\n' >"$work/beyond.csv"  # 1.5e-6 of it beyond
bad "^error: $work/beyond.csv:3: t: 0.0002000003 s is after" compare "$work/beyond.csv" "$bar" --at 0 --column v=v_x
printf 't,v\n0,-5\n1e-5,-5\n1e-5,-5\n' >"$work/repeated.csv"
bad "^error: $work/repeated.csv:4: t: 1e-05 s repeats the time of line 3: the sample times must increase" \
  compare "$work/repeated.csv" "$bar" --at 0 --column v=v_x "${never[@]}"
printf 't,v\n0,-5\n2e-5,-5\n1e-5,-5\n' >"$work/decreasing.csv"
bad "^error: $work/decreasing.csv:4: t: 1e-05 s comes before the time 2e-05 s of line 3" \
  compare "$work/decreasing.csv" "$bar" --at 0 --column v=v_x "${never[@]}"
# --- a unit: the CSV of the known error in mm/s and ms scores 1000 times too much and is warned (exit code
# unchanged); --scale COL=FACTOR brings each column to SI units and the score back to the m/s one.
awk -F, 'NR == 1 { print "time_ms,vel_mm" } NR > 1 { printf "%.17g,%.17g\n", $2 * 1000, $4 * 1000 }' "$work/other.csv" \
  >"$work/mm.csv"
mm=(compare "$work/mm.csv" "$bar" --at "$(calc "$L / 2")" --time-column time_ms --column vel_mm=v_x)
bad "^error: $work/mm.csv:2: time_ms: .* s is after the scene's solver.end_time" "${mm[@]}"
"$mpm" "${mm[@]}" --scale time_ms=0.001 --tolerance 0.03 >"$work/mm_score.csv" 2>"$work/err"
[[ $? -eq 1 ]] || fail "compare in mm/s above --tolerance 0.03 must exit 1"
check "compare rms/v0 in mm/s" "$(field "$work/mm_score.csv" 1 rms_normalised)" "$(calc "(2400 - 2.5) / 5")" 1e-6
grep -q "^warning: column vel_mm: rms_normalised 479.5 is more than 10 times the solution's scale of v_x (m/s, \
SI); its values are about 1000 times the solution's: another unit (mm/s is 1000 times m/s)? --scale vel_mm=0.001 \
converts it$" \
  "$work/err" || fail "compare in mm/s: no warning naming the column, the unit and --scale: $(cat "$work/err")"
"$mpm" "${mm[@]}" --scale time_ms=1e-3 --scale vel_mm=0.001 --tolerance 0.03 >"$work/mm_scaled.csv" 2>"$work/err" ||
  fail "compare --scale: $(cat "$work/err")"
check "compare --scale vel_mm=0.001: rms/v0" "$(field "$work/mm_scaled.csv" 1 rms_normalised)" 0.02 1e-10
[[ -s "$work/err" ]] && fail "compare --scale: a warning left: $(cat "$work/err")"
bad "^error: --scale: give COL=FACTOR with FACTOR a number > 0 \(mm/s to m/s: v=0.001\), got 'vel=0'" \
  compare "$work/other.csv" "$bar" --at 0 --time-column time --column vel=v_x --scale vel=0
bad "^error: --scale: give COL=FACTOR .* got 'vel=nan'" compare "$work/other.csv" "$bar" --at 0 --time-column time \
  --column vel=v_x --scale vel=nan
bad "^error: --scale speed=2: no --column or --time-column names 'speed'" compare "$work/other.csv" "$bar" --at 0 \
  --time-column time --column vel=v_x --scale speed=2 "${never[@]}"
# --- separators: the header tells the file's one separator (';' or ',', else a tab, else spaces); the same
# numbers score the same whatever separates them; a decimal comma is refused at its line.
at_half=(--at "$(calc "$L / 2")" --time-column time --column vel=v_x)
"$mpm" compare "$work/other.csv" "$bar" "${at_half[@]}" >"$work/comma_score.csv"
for separator in ';' $'\t' '   '; do
  sed "s/,/$separator/g" "$work/other.csv" >"$work/separated.csv"
  "$mpm" compare "$work/separated.csv" "$bar" "${at_half[@]}" >"$work/score_s.csv" 2>"$work/err" ||
    fail "compare, separator '$separator': $(cat "$work/err")"
  cmp -s "$work/comma_score.csv" "$work/score_s.csv" || fail "separator '$separator': $(cat "$work/score_s.csv")"
done
printf 't;v\n0;-5\n1e-5;-4,5\n' >"$work/decimal_comma.csv"
bad "^error: $work/decimal_comma.csv:3: v: '-4,5' has a decimal comma; write numbers with a decimal point" \
  compare "$work/decimal_comma.csv" "$bar" --at 0 --column v=v_x "${never[@]}"
printf 't,v\n0,-5\n1e-5,-4,5\n' >"$work/comma_comma.csv"
bad "^error: $work/comma_comma.csv:3: 3 fields; the header has 2 \(decimal commas\? write 0.5, not 0,5\)" \
  compare "$work/comma_comma.csv" "$bar" --at 0 --column v=v_x "${never[@]}"
printf 't;v,w\n0;-5\n' >"$work/both.csv"
bad "^error: $work/both.csv:1: the header holds both ',' and ';'" compare "$work/both.csv" "$bar" --at 0 --column v=v_x

# --- runs sample where and when asked: output.times landed on exactly; exact.csv at the reference position of
# the observed particle (h/2, which run.json gives), where Eq. (43) is scored, not at the point the observer names
# (the free end X = 0). The tension front from L/4 reaches X = h/2 at (L/4 - h/2)/c = 6.27 us and X = 0 at
# L/(4c) = 6.60 us: at t = 6.4 us the exact velocity is v0/2 = -2.5 m/s at X = h/2 (sigma = Z |v0|/2) and v0 at X = 0.
"$mpm" run "$bar" --out "$work/sampled" --set 'output.times=[0.0, 6.4e-6, 3.3333e-5, 2e-4]' --set 'output.snapshots=[]' >/dev/null \
  || fail "a run with output.times"
[[ $(cut -d, -f1 "$work/sampled/observers.csv" | tr '\n' ' ') == "t 0 6.4e-06 3.3333e-05 0.0002 " ]] ||
  fail "output.times: observers sampled at $(cut -d, -f1 "$work/sampled/observers.csv" | tr '\n' ' ')"
[[ $(wc -l <"$work/sampled/energy.csv") -eq 5 ]] || fail "output.times: energy.csv not sampled at the same times"
[[ "$(sed -n 3p "$work/sampled/exact.csv")" == "6.4e-06,-2.5,98950745.3231" ]] ||
  fail "exact.csv at t = 6.4 us: $(sed -n 3p "$work/sampled/exact.csv")"
ls "$work/sampled" | grep -q snapshot_ && fail "output.snapshots = []: no snapshot file"
python3 -c "import json, sys; o = json.load(open(sys.argv[1]))['observed'][0]; assert o['name'] == 'A' and abs(o['reference_position'][0] - 0.1333 / 80) < 1e-15, o" \
  "$work/sampled/run.json" || fail "run.json: the observed particle's reference position"
# and mpm compare reads observers.csv as any other CSV, at the particle's reference position
"$mpm" compare "$work/sampled/observers.csv" "$bar" --at 0.00166625 --column A.v_x=v_x >/dev/null || fail "compare observers.csv"
bad "^error: --set\(1\):1: output.every: give output.every or output.times, not both" run "$bar" --out "$work/never" \
  --set output.every=2 --set 'output.times=[1e-5]'
bad "^error: --set\(1\):1: output.times: times must increase" run "$bar" --out "$work/never" --set 'output.times=[2e-5, 1e-5]'
bad "^error: --set\(1\):1: output.times: times must lie in \[0, solver.end_time\]" run "$bar" --out "$work/never" --set 'output.times=[1.0]'
bad "^error: --set\(1\):1: observer\[0\].position: lies outside the body \[0, 0.1333\] on x, where exact = \"dyka_bar\"" \
  run "$bar" --out "$work/never" --set 'observer[0].position=[-0.001]'
[[ -e "$work/never" ]] && fail "a bad run made its output folder"

# --- help: both commands in mpm --help and the usage string, each with its own --help.
"$mpm" --help | grep -q "Usage: mpm exact \[OPTIONS\] SCENE.toml" || fail "mpm --help lacks mpm exact"
"$mpm" --help | grep -q "Usage: mpm compare \[OPTIONS\] RESULT.csv SCENE.toml" || fail "mpm --help lacks mpm compare"
"$mpm" 2>&1 | grep -q "mpm exact SCENE.toml" || fail "the usage string lacks mpm exact"
"$mpm" 2>&1 | grep -q "mpm compare RESULT.csv" || fail "the usage string lacks mpm compare"
"$mpm" exact --help | grep -q "manufactured_large" || fail "mpm exact --help lacks a solution"
"$mpm" compare --help | grep -q "rms_normalised" || fail "mpm compare --help"

echo "cli_exact_compare: $failures failed"
[[ $failures -eq 0 ]]
