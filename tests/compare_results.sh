#!/usr/bin/env bash
# verification/compare_results.py on folders made by hand: a change within the tolerance passes, one
# beyond it fails and is named, and a file that gained a column is reported, not a crash (it was an
# IndexError before the fix).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/old" "$work/new"
fail() { echo "compare_results test: $*"; exit 1; }
printf 'cells,rms,wall_seconds\n10,0.5,1.0\n20,0.25,2.0\n' >"$work/old/sweep.csv"
printf 'cells,rms,wall_seconds\n10,0.5,9.0\n20,0.25000000000001,7.0\n' >"$work/new/sweep.csv"
out=$(python3 "$root/verification/compare_results.py" "$work/old" "$work/new") || fail "a change of 2e-14 (and wall times) should pass: $out"
[[ $out == *"largest relative change 2e-14"* ]] || fail "expected the change 2e-14 (on the column's scale 0.5), got: $out"
printf 'cells,rms,wall_seconds\n10,0.5,1.0\n20,0.2501,2.0\n' >"$work/new/sweep.csv"
out=$(python3 "$root/verification/compare_results.py" "$work/old" "$work/new") && fail "a change of 2e-4 should fail: $out"
[[ $out == *"sweep.csv: largest relative change 0.0002"* ]] || fail "expected the file and its change named, got: $out"
printf 'cells,rms,wall_seconds,meshes\n10,0.5,1.0,1\n20,0.25,2.0,1\n' >"$work/new/sweep.csv"
out=$(python3 "$root/verification/compare_results.py" "$work/old" "$work/new" 2>&1)
status=$?
[[ $status -eq 1 ]] || fail "a file that gained a column should exit 1, got $status: $out"
[[ $out == *"sweep.csv: a row changed length"* ]] || fail "expected 'a row changed length', got: $out"
echo "compare_results test: passed"
