#!/usr/bin/env python3
"""Checks the numbers that paper/*.md and README.md quote from the runs against results/, so that
none can go stale: `make figures` and `make studies` run it last (--target), and fail when one differs.

    verification/check_book_numbers.py [RESULTS_DIR] [FILE.md ...]

A quoted number carries, right after it, an HTML comment that says where it comes from (Doxygen and
Markdown viewers show the number and hide the comment):

    0.1718<!-- check dyka_sweep.csv shape=linear integrator=fe cells=40 : rms_over_v0 -->
    2.48e-14<!-- check report.md /Mass is conserved.*?largest relative error ([-+0-9.e]+)/ -->

A CSV of RESULTS_DIR/data (made by `make figures`), of RESULTS_DIR/studies/data (made by `make studies`) or,
when in neither, of verification/data (which ships with the repository): the one row whose columns equal every
KEY=VALUE (numbers compared as numbers), in the first of these files that has one, the named column; `: COLUMN *
FACTOR` scales it first, e.g. `: energy_drift * 100` for a fraction quoted in per cent. report.md: the first group
of the regular expression's first match (across lines) in make figures' sections (RESULTS_DIR/report/*.md), else
in make studies' (RESULTS_DIR/studies/report/*.md), else in RESULTS_DIR/report.md. The quoted number must be the
source's value rounded to the digits it shows: 0.1718 stands for anything in [0.17175, 0.17185], 2.48e-14 for
[2.475e-14, 2.485e-14]; a leading + or - is part of the number. Prints one line per number that differs or whose
source is missing, naming the file and line; exits 1 if any, 0 otherwise (and says how many were checked).

    --target figures|studies   check only the numbers this target's runs make (and those of verification/data); a
                               number whose source the other target makes is left to it, and so is a missing source
                               while the other target has not run yet (its report/00_made.md absent): counted, not
                               failed; so is every report.md expression then, since it may match in this target's
                               sections what it means in the other's (the next target's run checks it).

Defaults: RESULTS_DIR = results, the files = paper/*.md and README.md.
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


TARGET_DIRS = (("figures", ""), ("studies", "studies"))


def has_run(results, target):
    """True if `target` (figures, studies) has written its sections into `results`."""
    return os.path.isfile(os.path.join(results, dict(TARGET_DIRS)[target], "report", "00_made.md"))


def report_source(results, expression):
    """(value, None, target) from the first target's sections the expression matches, or report.md; else why not."""
    places = [(target, sorted(glob.glob(os.path.join(results, sub, "report", "*.md")))) for target, sub in TARGET_DIRS]
    places.append((None, [os.path.join(results, "report.md")]))
    for target, paths in places:
        text = "".join(open(path).read() for path in paths if os.path.isfile(path))
        found = re.search(expression, text, re.DOTALL)
        if found and found.groups():
            return found.group(1), None, target
    return None, f"/{expression}/ matches nothing in {results}/report.md (run make figures, make studies)", None


def csv_source(results, source, keys, column):
    """(cell, None, target) from the first CSV of `source` with one row matching `keys`; else (None, why, None)."""
    shipped = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", source)
    places = [(os.path.join(results, sub, "data", source), target) for target, sub in TARGET_DIRS]
    places = [(path, target) for path, target in places + [(shipped, "shipped")] if os.path.isfile(path)]
    if not places:
        return None, f"no {os.path.join(results, 'data', source)} (run make figures, make studies)", None
    conditions = [item.split("=", 1) for item in keys.split()]
    if any(len(c) != 2 for c in conditions):
        return None, f"keys must be KEY=VALUE: {keys.strip()}", None
    why = None
    for path, target in places:
        with open(path, newline="") as handle:
            rows = [row for row in csv.DictReader(handle)]
        if rows and column not in rows[0]:
            return None, f"{source} has no column {column}", None
        chosen = [row for row in rows if all(k in row and same(row[k], v) for k, v in conditions)]
        if len(chosen) == 1:
            return chosen[0][column], None, target
        why = why or f"{len(chosen)} rows of {source} match {keys.strip()}, not one"
    return None, why, None


def source_value(results, spec):
    """(value, None, target) or (None, why not, None); target: figures, studies or shipped (who made the source)."""
    source, _, rest = spec.partition(" ")
    if source == "report.md":
        match = re.fullmatch(r"/(.*)/", rest.strip())
        if not match:
            return None, "report.md needs /regular expression/ with one group", None
        return report_source(results, match.group(1))
    keys, _, column = rest.partition(":")
    column, _, factor = column.partition("*")
    column, factor = column.strip(), factor.strip()
    try:
        scale = float(factor) if factor else 1.0
    except ValueError:
        return None, f"the factor after '*' must be a number: {factor}", None
    if not column:
        return None, "no ': column' after the keys", None
    value, why, target = csv_source(results, source, keys, column)
    if why or not factor:
        return value, why, target
    try:
        return repr(float(value) * scale), None, target
    except ValueError:
        return value, None, target


def check(results, files, target=None):
    """(problems, checked, left): `target` set, the numbers another target makes are left to it (counted in left)."""
    problems, checked, left = [], 0, 0
    other = {"figures": "studies", "studies": "figures"}.get(target)
    for path in files:
        for number, line in enumerate(open(path), 1):
            for match in MARK.finditer(line):
                quoted, spec = match.group(1), match.group(2)
                where = f"{path}:{number}: {quoted}"
                # A report.md expression may match in either target's sections (the same claim can be made in both),
                # and it is meant for the first that has one: before the other target has run, it is left to the check
                # that follows both (counted, not checked), so that one target alone never checks it on the wrong part.
                if target and spec.split(" ", 1)[0] == "report.md" and not has_run(results, other):
                    left += 1
                    continue
                value, why, made_by = source_value(results, spec)
                if target and (made_by == other or (why and not has_run(results, other))):
                    left += 1
                    continue
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
    return problems, checked, left


def main(arguments):
    target = None
    if arguments[:1] == ["--target"]:
        if len(arguments) < 2 or arguments[1] not in ("figures", "studies"):
            print("book numbers: --target needs figures or studies")
            return 2
        target, arguments = arguments[1], arguments[2:]
    results = arguments[0] if arguments else "results"
    files = arguments[1:] or sorted(glob.glob("paper/*.md")) + ["README.md"]
    problems, checked, left = check(results, files, target)
    for problem in problems:
        print(f"book numbers: {problem}")
    print(f"book numbers: {checked} quoted numbers checked against {results}/, {len(problems)} differ or lack a source"
          + (f"; {left} left to make {'studies' if target == 'figures' else 'figures'}" if target else ""))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
