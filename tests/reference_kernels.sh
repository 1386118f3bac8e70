#!/usr/bin/env bash
# The fast kernels (mpm/fast/, the default) against the reference kernels (mpm/transfer/, solver.kernels =
# "reference"): every shipped scene with every shape function and integrator (USL and MUSL too) for a few steps, once
# on each layer (LME: the reference shape of mpm/shape/lme_reference.hpp against the fast one of mpm/fast/). Every
# column of every CSV the two runs write must agree to 1e-12 of the largest magnitude its quantity reaches in any of
# the run's files (a vector's or a tensor's components taken together: momentum_x with momentum_y, an observer's
# A.sigma_xx with the snapshot's sigma_xx, sigma_yy, ...), less one unit of the
# 12th significant digit (the files' resolution); a quantity of at most 1e-13 in both runs is zero to round-off.
# LME: both runs at solver.lme_newton_tol = 1e-13, to 1e-9 (its Newton iteration stops near round-off). Prints the
# largest relative difference per shape function.
#
#   bash tests/reference_kernels.sh build/bin/mpm
# REFERENCE_KERNELS_QUICK=1 (the sanitized build of make sanitize) runs linear and LME shapes with fe and npc only;
# REFERENCE_KERNELS_SCENES=NAME (a glob) the scenes/NAME.toml alone.
set -u
mpm=$1
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
shapes=(linear ugimp lme bspline2 bspline3) integrators=(fe npc usl musl)
[[ ${REFERENCE_KERNELS_QUICK:-0} == 1 ]] && shapes=(linear lme) integrators=(fe npc)
failures=0 runs=0
for scene in "$root"/scenes/${REFERENCE_KERNELS_SCENES:-*}.toml; do
  # a few steps of each, with a snapshot of every particle at the end
  # (about 1 to 10 steps each: the runs part by round-off, about 1e-14 of a column a step, which grows to 8e-12 in
  # 50 steps of the manufactured solutions and 6e-12 in the 60 steps that bring the colliding disks into contact)
  case $(basename "$scene" .toml) in
    manufactured_*) end=0.002 ;;
    colliding_disks) end=0.2 ;;  # in rigid motion until they touch: a converging velocity field strains them
    *) if grep -q '^dimension = 1' "$scene"; then end=2e-6; else end=0.02; fi ;;
  esac
  few=(--set "solver.end_time=$end" --set "output.snapshots=[$end]")
  [[ $(basename "$scene") == colliding_disks.toml ]] &&
    few+=(--set 'initial_field.velocity=["0.1 - 0.2 * x", "0.1 - 0.2 * y"]')
  dt=$(awk -F= '/^dt[[:space:]]*=/ { gsub(/[[:space:]]|#.*/, "", $2); print $2; exit }' "$scene")
  if [[ -n "$dt" ]]; then
    end=$(awk -v dt="$dt" 'BEGIN { printf "%.6g", 5 * dt }')
    few=(--set "solver.end_time=$end" --set "output.snapshots=[$end]")
  fi
  for shape in "${shapes[@]}"; do
    for integrator in "${integrators[@]}"; do
      method=(--set "solver.shape=\"$shape\"" --set "solver.integrator=\"${integrator/*sl/fe}\"")
      [[ $integrator == *sl ]] && method+=(--set "solver.stress_update=\"$integrator\"")
      [[ $shape == lme ]] && method+=(--set solver.lme_newton_tol=1e-13)
      name="$(basename "$scene" .toml)_${shape}_$integrator"
      for kernels in fast reference; do
        "$mpm" run "$scene" --out "$work/$name-$kernels" "${few[@]}" "${method[@]}" \
          --set "solver.kernels=\"$kernels\"" >/dev/null 2>"$work/$name-$kernels.err"
        echo $? >"$work/$name-$kernels.code"
      done
      runs=$((runs + 1))
      if ! cmp -s "$work/$name-fast.code" "$work/$name-reference.code"; then
        echo "FAIL: $name: exit $(cat "$work/$name-fast.code") (fast), $(cat "$work/$name-reference.code") (reference)"
        failures=$((failures + 1))
      fi
    done
  done
done
python3 - "$work" <<'PY' || failures=$((failures + 1))
import csv, glob, math, os, re, sys
work = sys.argv[1]
largest, largest_raw, failed = {}, {}, 0
for fast in sorted(glob.glob(os.path.join(work, "*-fast"))):
    name = os.path.basename(fast)[: -len("-fast")]
    reference = os.path.join(work, name + "-reference")
    shape = name.split("_")[-2]
    tolerance = 1e-9 if shape == "lme" else 1e-12
    files = sorted(f for f in os.listdir(fast) if f.endswith(".csv"))
    if not files or files != sorted(f for f in os.listdir(reference) if f.endswith(".csv")):
        print(f"FAIL: {name}: the two runs wrote different files"); failed += 1; continue
    # the scale of a column: the largest magnitude its quantity reaches in the run, in any of its files (every
    # particle's snapshot included), a vector's or a tensor's components together (momentum_x with momentum_y,
    # A.sigma_xy with sigma_xx of the snapshot): an observer's column that is round-off itself (the Dyka bar's A
    # before the wave reaches it, 1e-8 Pa) is compared on its quantity's scale, not its own
    quantity = lambda title: re.sub(r"_[xyz]{1,2}$", "", title.split(".")[-1])
    tables, scales = {}, {}
    for file in files:
        rows = [[r for r in csv.reader(l for l in open(os.path.join(run, file)) if not l.startswith("#"))]
                for run in (fast, reference)]
        if len(rows[0]) != len(rows[1]) or not rows[0]:
            print(f"FAIL: {name}/{file}: {len(rows[0])} rows (fast), {len(rows[1])} (reference)"); failed += 1; continue
        header, columns = rows[0][0], {}
        for column, title in enumerate(header):
            try:
                columns[title] = ([float(r[column]) for r in rows[0][1:]], [float(r[column]) for r in rows[1][1:]])
            except (ValueError, IndexError):
                continue
        tables[file] = columns
        for title, (a, b) in columns.items():
            scales[quantity(title)] = max([scales.get(quantity(title), 0.0)] + [abs(x) for x in a])
    for file, columns in tables.items():
        for title, (a, b) in columns.items():
            scale = scales[quantity(title)]
            if scale <= 1e-13 and max((abs(y) for y in b), default=0.0) <= 1e-13:
                continue  # zero to round-off in both runs (the momentum of the colliding disks, 1e-15 kg m/s)
            # less one unit of the 12th significant digit each CSV number is written with (the files' resolution)
            printed = lambda x: 10.0 ** (math.floor(math.log10(abs(x))) - 11) if x else 0.0
            difference = max((max(0.0, abs(x - y) - printed(x)) for x, y in zip(a, b)), default=0.0)
            relative = difference / scale if scale > 0 else difference
            largest[shape] = max(largest.get(shape, 0.0), relative)
            raw = max((abs(x - y) for x, y in zip(a, b)), default=0.0)
            largest_raw[shape] = max(largest_raw.get(shape, 0.0), raw / scale if scale > 0 else raw)
            if relative > tolerance:
                print(f"FAIL: {name}/{file}: column {title}: {relative:.3g} of its quantity's largest magnitude > {tolerance:g}")
                failed += 1
for shape, value in sorted(largest.items()):
    print(f"reference_kernels: {shape}: largest relative difference {value:.3g} beyond the files' 12 digits, "
          f"{largest_raw[shape]:.3g} as printed")
sys.exit(failed > 0)
PY
echo "reference_kernels: $runs scene x shape x integrator cases, each on both layers; $failures failed"
[[ $failures -eq 0 ]]
