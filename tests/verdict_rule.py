#!/usr/bin/env python3
"""verification/verdict_rule.py on the constructed cases the C++ rule is tested on (tests/data/verdict_rule_cases.csv),
and authors_code.py's use of it on a constructed table (a holding gap, an undecided one, two failed histories)."""
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
# none decided, one within its band: "undecided on all 1", not "no samples compared" (C++: claims.hpp's doctest)
if not verdict_rule.verdict_text(["undecided", "stopped"]).startswith("undecided on all 1 ("):
    failures += 1
    print("verdict_rule.py: verdict_text: %s" % verdict_rule.verdict_text(["undecided", "stopped"]))
# The scripts that judge by it: authors_code.py on a constructed table (a gap within 1 % beyond its band, one within
# its band of 1 %, one between two failed histories: holds, undecided, stopped).
import subprocess  # noqa: E402
import tempfile  # noqa: E402
with tempfile.TemporaryDirectory() as work:
    table, report = os.path.join(work, "table.csv"), os.path.join(work, "report.md")
    with open(table, "w") as out:
        out.write("shape,integrator,cells,their_grid,ours_rms_over_v0,theirs_rms_over_v0,rms_gap_percent,"
                  "ours_on_their_grid_rms_over_v0,max_dv_over_v0,ours_even,ours_odd,theirs_even,theirs_odd,"
                  "rms_gap_band_percent,ours_ending,theirs_ending\n"
                  "linear,fe,40,strip,0.17,0.17,0.20,0.17,0.001,0.17,0.17,0.17,0.17,0.1,done,done\n"
                  "linear,fe,80,strip,0.17,0.17,0.95,0.17,0.001,0.17,0.17,0.17,0.17,0.1,done,done\n"
                  "linear,fe,160,strip,0.6,0.7,16.67,0.6,0.1,0.6,0.6,0.7,0.7,0.1,failed,failed\n")
    run = subprocess.run([sys.executable, os.path.join(root, "verification", "authors_code.py"), table, report],
                         capture_output=True, text=True)
    written = open(report).read() if run.returncode == 0 else run.stderr
    if "**holds on all 1 (1 hold, 0 fail, 1 undecided, 1 stopped)**" not in written:
        failures += 1
        print("verdict_rule.py: authors_code.py on a constructed table: %s" % written[-400:])
print("verdict_rule.py: %d cases, %d failures" % (cases, failures))
sys.exit(1 if failures or cases < 14 else 0)
