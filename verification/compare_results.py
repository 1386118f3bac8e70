#!/usr/bin/env python3
"""Compares two sets of CSV results (e.g. two `make figures` data folders) number by number.

    verification/compare_results.py OLD_DIR NEW_DIR [--tolerance 1e-10]

For every CSV present in both folders, every numeric cell is compared relative to the largest
magnitude in its column (so that values crossing zero are judged on the column's scale). Columns
whose header names a time of the machine ("wall", "seconds") are skipped: they are not results. Prints
one line per file that differs beyond the tolerance, the largest relative change overall and where;
exits 1 if any file differs beyond the tolerance, is missing, or changes shape.
"""
import csv
import math
import os
import sys


def read(path):
    with open(path, newline="") as handle:
        return [row for row in csv.reader(handle) if row and not row[0].startswith("#")]


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare(old_rows, new_rows):
    """(largest relative change, row, column, problem or None)"""
    if len(old_rows) != len(new_rows):
        return math.inf, -1, -1, f"{len(old_rows)} rows before, {len(new_rows)} now"
    columns = max((len(row) for row in old_rows + new_rows), default=0)  # a file may have gained a column
    scale = [0.0] * columns
    for row in old_rows + new_rows:
        for k, cell in enumerate(row):
            value = number(cell)
            if value is not None and math.isfinite(value):
                scale[k] = max(scale[k], abs(value))
    header = old_rows[0] if old_rows else []
    skip = {k for k, name in enumerate(header) if "wall" in name or "seconds" in name}
    worst, where = 0.0, (-1, -1)
    for r, (a_row, b_row) in enumerate(zip(old_rows, new_rows)):
        if len(a_row) != len(b_row):
            return math.inf, r, -1, "a row changed length"
        for k, (a, b) in enumerate(zip(a_row, b_row)):
            if k in skip:
                continue
            x, y = number(a), number(b)
            if x is None or y is None:
                if a != b:
                    return math.inf, r, k, f"text changed: {a!r} -> {b!r}"
                continue
            if x == y or (math.isnan(x) and math.isnan(y)):
                continue
            change = abs(x - y) / scale[k] if scale[k] > 0 and math.isfinite(x - y) else math.inf
            if change > worst:
                worst, where = change, (r, k)
    return worst, where[0], where[1], None


def main():
    args = sys.argv[1:]
    tolerance = 1e-10
    if "--tolerance" in args:
        at = args.index("--tolerance")
        tolerance = float(args[at + 1])
        del args[at:at + 2]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    old_dir, new_dir = args
    names = sorted(name for name in os.listdir(old_dir) if name.endswith(".csv"))
    failed, overall = False, (0.0, "")
    for name in names:
        new_path = os.path.join(new_dir, name)
        if not os.path.exists(new_path):
            print(f"{name}: missing in {new_dir}")
            failed = True
            continue
        worst, row, column, problem = compare(read(os.path.join(old_dir, name)), read(new_path))
        if problem:
            print(f"{name}: {problem} (row {row}, column {column})")
            failed = True
            continue
        if worst > overall[0]:
            header = read(new_path)[0]
            overall = (worst, f"{name}, row {row}, column {header[column] if column < len(header) else column}")
        if worst > tolerance:
            print(f"{name}: largest relative change {worst:.3g} (row {row}, column {column})")
            failed = True
    print(f"compared {len(names)} files: largest relative change {overall[0]:.3g}" + (f" in {overall[1]}" if overall[1] else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
