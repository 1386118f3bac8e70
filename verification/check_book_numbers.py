#!/usr/bin/env python3
"""Checks the numbers that paper/*.md and README.md quote from the runs against results/, so that
none can go stale: `make figures` runs it last, and fails when one differs.

    verification/check_book_numbers.py [RESULTS_DIR] [FILE.md ...]

A quoted number carries, right after it, an HTML comment that says where it comes from (Doxygen and
Markdown viewers show the number and hide the comment):

    0.1718<!-- check dyka_sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 -->
    2.48e-14<!-- check report.md /Mass is conserved.*?largest relative error ([-+0-9.e]+)/ -->

A CSV of RESULTS_DIR/data (or, when not there, of verification/data, which ships with the repository):
the one row whose columns equal every KEY=VALUE (numbers compared as
numbers), the named column; `: COLUMN * FACTOR` scales it first, e.g. `: energy_drift * 100` for a
fraction quoted in per cent. report.md (RESULTS_DIR/report.md): the first group of the regular
expression's first match (across lines). The quoted number must be the source's value rounded to
the digits it shows: 0.1718 stands for anything in [0.17175, 0.17185], 2.48e-14 for [2.475e-14,
2.485e-14]; a leading + or - is part of the number. Prints one line per number that differs or
whose source is missing, naming the file and line; exits 1 if any, 0 otherwise (and says how many
were checked). Defaults: RESULTS_DIR = results, the files = paper/*.md and README.md.
"""
import csv
import glob
import math
import os
import re
import sys

MARK = re.compile(r"([-+]?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?)\s*<!--\s*check\s+(.*?)\s*-->")


def quoted_range(text):
    """The interval of values that `text` (e.g. 0.1718, 2.48e-14, 2) stands for when rounded."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    half = 0.5 * 10.0 ** (-decimals) * 10.0 ** (int(exponent) if exponent else 0)
    value = float(text)
    return value - half * (1 + 1e-9), value + half * (1 + 1e-9)


def same(cell, wanted):
    try:
        return math.isclose(float(cell), float(wanted), rel_tol=1e-12, abs_tol=0.0)
    except ValueError:
        return cell == wanted


def source_value(results, spec):
    """(value, None) or (None, why not)."""
    source, _, rest = spec.partition(" ")
    if source == "report.md":
        match = re.fullmatch(r"/(.*)/", rest.strip())
        if not match:
            return None, "report.md needs /regular expression/ with one group"
        path = os.path.join(results, "report.md")
        if not os.path.isfile(path):
            return None, f"no {path} (run make figures)"
        found = re.search(match.group(1), open(path).read(), re.DOTALL)
        if not found or not found.groups():
            return None, f"/{match.group(1)}/ matches nothing in {path}"
        return found.group(1), None
    keys, _, column = rest.partition(":")
    column, _, factor = column.partition("*")
    column, factor = column.strip(), factor.strip()
    try:
        scale = float(factor) if factor else 1.0
    except ValueError:
        return None, f"the factor after '*' must be a number: {factor}"
    path = os.path.join(results, "data", source)
    shipped = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", source)
    if not os.path.isfile(path) and os.path.isfile(shipped):
        path = shipped  # data that ships with the repository (verification/data: other codes' numbers)
    if not column:
        return None, "no ': column' after the keys"
    if not os.path.isfile(path):
        return None, f"no {path} (run make figures)"
    conditions = [item.split("=", 1) for item in keys.split()]
    if any(len(c) != 2 for c in conditions):
        return None, f"keys must be KEY=VALUE: {keys.strip()}"
    with open(path, newline="") as handle:
        rows = [row for row in csv.DictReader(handle)]
    if rows and column not in rows[0]:
        return None, f"{source} has no column {column}"
    chosen = [row for row in rows if all(k in row and same(row[k], v) for k, v in conditions)]
    if len(chosen) != 1:
        return None, f"{len(chosen)} rows of {source} match {keys.strip()}, not one"
    if not factor:
        return chosen[0][column], None
    try:
        return repr(float(chosen[0][column]) * scale), None
    except ValueError:
        return chosen[0][column], None


def check(results, files):
    problems, checked = [], 0
    for path in files:
        for number, line in enumerate(open(path), 1):
            for match in MARK.finditer(line):
                quoted, spec = match.group(1), match.group(2)
                where = f"{path}:{number}: {quoted}"
                value, why = source_value(results, spec)
                checked += 1
                if why:
                    problems.append(f"{where}: {why}")
                    continue
                try:
                    actual = float(value)
                except ValueError:
                    problems.append(f"{where}: the source gives '{value}', not a number")
                    continue
                low, high = quoted_range(quoted)
                if not (low <= actual <= high):
                    problems.append(f"{where}: the results say {value} ({spec})")
    return problems, checked


def main(arguments):
    results = arguments[0] if arguments else "results"
    files = arguments[1:] or sorted(glob.glob("paper/*.md")) + ["README.md"]
    problems, checked = check(results, files)
    for problem in problems:
        print(f"book numbers: {problem}")
    print(f"book numbers: {checked} quoted numbers checked against {results}/, {len(problems)} differ or lack a source")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
