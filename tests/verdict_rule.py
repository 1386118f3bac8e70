#!/usr/bin/env python3
"""verification/verdict_rule.py on the constructed cases the C++ rule is tested on (tests/data/verdict_rule_cases.csv)."""
import csv
import os
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(root, "verification"))
import verdict_rule  # noqa: E402

failures, cases = 0, 0
with open(os.path.join(root, "tests", "data", "verdict_rule_cases.csv"), newline="") as handle:
    for row in csv.DictReader(handle):
        cases += 1
        got = verdict_rule.judge(float(row["a"]), float(row["a_band"]), row["a_ending"], row["side"],
                                 float(row["b"]), float(row["b_band"]), row["b_ending"])
        if got != row["outcome"]:
            failures += 1
            print("verdict_rule.py: %s: %s, expected %s" % (row["case"], got, row["outcome"]))
expected_counts = (1, 1, 1, 2)
got_counts = verdict_rule.counts(["holds", "fails", "undecided", "stopped", "stopped"])
if got_counts != expected_counts:
    failures += 1
    print("verdict_rule.py: counts %s, expected %s" % (got_counts, expected_counts))
if verdict_rule.verdict_text(["holds", "fails", "stopped"]) != "holds on 1 of 2 (1 hold, 1 fail, 0 undecided, 1 stopped)":
    failures += 1
    print("verdict_rule.py: verdict_text: %s" % verdict_rule.verdict_text(["holds", "fails", "stopped"]))
print("verdict_rule.py: %d cases, %d failures" % (cases, failures))
sys.exit(1 if failures or cases < 14 else 0)
