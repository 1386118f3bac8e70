#!/usr/bin/env python3
"""max |v_ours - v_theirs| / v0 of particle A (column A.v_x of both CSV files, v0 = 5 m/s: the Dyka bar), ours
interpolated linearly at their sample times; their samples after our last one are left out.

    largest_velocity_difference.py OURS.csv THEIRS.csv
"""
import bisect
import csv
import sys

ours, theirs = (list(csv.DictReader(open(path))) for path in sys.argv[1:3])
t = [float(row["t"]) for row in ours]
v = [float(row["A.v_x"]) for row in ours]
worst = 0.0
for row in theirs:
    s = float(row["t"])
    if s > t[-1]:
        break
    k = max(1, min(bisect.bisect_left(t, s), len(t) - 1))
    w = v[k - 1] + (s - t[k - 1]) / (t[k] - t[k - 1]) * (v[k] - v[k - 1])
    worst = max(worst, abs(w - float(row["A.v_x"])) / 5.0)
print(worst)
