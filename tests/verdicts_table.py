#!/usr/bin/env python3
"""verification/verdicts.py on a constructed report: every verdict table read (an escaped bar, a bar left unescaped by
a report written before cells escaped them, a simple claim undecided), the counts, the changed list against a previous
CSV, and exit 2 on an unreadable previous file (nothing written)."""
import csv
import os
import subprocess
import sys
import tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
script = os.path.join(root, "verification", "verdicts.py")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


with tempfile.TemporaryDirectory() as work:
    os.makedirs(os.path.join(work, "report"))
    with open(os.path.join(work, "report", "20_part.md"), "w") as out:
        out.write("### Fig. 1: a figure\n\n"
                  "| claim | measure | holds on | fails on | not compared (stopped, undecided) | verdict |\n"
                  "|---|---|---|---|---|---|\n"
                  "| A falls | \\|e(h/2)\\| < \\|e(h)\\| | a; b | c | d (undecided) | **holds on 2 of 3 (2 hold, 1 fail, 1 undecided, 0 stopped)** |\n"
                  "| B old | |x| < 1 | a | - | e | **holds on all 1; 1 not compared (stopped)** |\n\n"
                  "| claim | measured | verdict |\n|---|---|---|\n"
                  "| C best | 0.1 against 0.1 | **undecided** |\n"
                  "| D bound | 2 | **does not hold** |\n")
    previous = os.path.join(work, "previous.csv")
    with open(previous, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["target", "section", "claim", "rule", "holds", "fails", "undecided", "stopped", "holds_on",
                         "fails_on", "not_compared"])
        writer.writerow(["figures", "Fig. 1: a figure", "A falls", "r", 3, 0, 0, 0, "-", "-", "-"])
        writer.writerow(["figures", "Fig. 1: a figure", "D bound", "r", 0, 1, 0, 0, "-", "-", "-"])
        writer.writerow(["figures", "Fig. 1: a figure", "E gone", "r", 1, 0, 0, 0, "-", "-", "-"])
    run = subprocess.run([sys.executable, script, work, previous], capture_output=True, text=True)
    check(run.returncode == 0, "exit %d: %s" % (run.returncode, run.stderr))
    rows = {row["claim"]: row for row in csv.DictReader(open(os.path.join(work, "verdicts.csv")))}
    check(sorted(rows) == ["A falls", "B old", "C best", "D bound"], "claims read: %s" % sorted(rows))
    counts = lambda claim: tuple(int(rows[claim][k]) for k in ("holds", "fails", "undecided", "stopped"))
    check(counts("A falls") == (2, 1, 1, 0), "A: %s" % (counts("A falls"),))
    check(rows["A falls"]["rule"] == "|e(h/2)| < |e(h)|", "A's rule unescaped: %r" % rows["A falls"]["rule"])
    check(counts("B old") == (1, 0, 0, 1), "B (old words): %s" % (counts("B old"),))
    check(rows["B old"]["rule"] == "|x| < 1", "B's rule joined: %r" % rows["B old"]["rule"])
    check(counts("C best") == (0, 0, 1, 0), "C: %s" % (counts("C best"),))
    check(counts("D bound") == (0, 1, 0, 0), "D: %s" % (counts("D bound"),))
    changed = open(os.path.join(work, "verdicts_changed.md")).read()
    check(changed.startswith("4 verdicts now, 3 before: 1 changed their counts, 2 are new or reworded, 1 are no longer"),
          "changed list: %s" % changed.splitlines()[0])
    check("| A falls | 3 hold, 0 fail, 0 undecided, 0 stopped | 2 hold, 1 fail, 1 undecided, 0 stopped |" in changed,
          "A's change: %s" % changed)
    check("E gone" in changed, "a verdict no longer made is named")
    os.remove(os.path.join(work, "verdicts.csv"))
    run = subprocess.run([sys.executable, script, work, os.path.join(work, "missing.csv")], capture_output=True, text=True)
    check(run.returncode == 2 and "missing.csv" in run.stderr, "missing previous: exit %d, %s" % (run.returncode, run.stderr))
    check(not os.path.exists(os.path.join(work, "verdicts.csv")), "nothing written before the inputs are read")
for failure in failures:
    print("verdicts_table: FAIL: %s" % failure)
print("verdicts_table: %d failures" % len(failures))
sys.exit(1 if failures else 0)
