#!/usr/bin/env python3
"""The authors' code beside this project on the soil block: a part of `make studies`.

    verification/authors_soil.py MPM SCENE.toml DATA_DIR OUT.csv REPORT.md

DATA_DIR holds the top particle's settlement histories of the authors' code (NL-PartSol 1d5da04, GraMS), written by
verification/data/nl_partsol_soil_case.py and read by nl_partsol_soil_history.py (how each was made:
verification/data/other_codes.csv): nl_partsol_soil_{lme_pce,ugimp_pce,q4_pce,q4_fe}.csv, columns t, top.u_y, top.v_y.
For each, this project runs SCENE.toml (scenes/soil_block.toml) with `mpm run` under the authors' settings and with
one of them undone at a time, interpolates its u_y linearly at their sample times and writes, per run, the largest
|u_y(theirs) - u_y(ours)| over their history and the difference at their last sample, both over their settlement
there, to OUT.csv, and the table and the verdict (the one rule, verification/verdict_rule.py) to REPORT.md. Beside
OUT.csv, for each case's run under their settings, authors_soil_CASE.csv (t, theirs, ours, difference: their u_y, ours
at their sample times, theirs - ours), the histories the figure authors_soil draws (verification/plots/authors_soil.gp,
drawn by make_studies.sh; its line in REPORT.md).
Exits 2 on a missing or unreadable input, 1 when a run of this project fails.
"""
import bisect
import csv
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import verdict_rule  # noqa: E402

# The authors' settings (their code, src/ paths at 1d5da04): gravity read at the step's start (compute_ExternalForces.c,
# the curve indexed by the step), the step from the largest signed velocity added to c (Formulations/Courant.c: our
# courant = "sum"), every step sampled; their PCE moves the particles with the corrected nodal velocity
# (MPM/Update_Lagrangian.c: npc_position_velocity = "corrected"); their LME takes beta = gamma / hbar^2 on their node
# patch (lme_beta = "authors") and the whole 4 x 4 node patch as neighbours (lme_neighbours = "authors_patch"); their
# uGIMP keeps the particle domains of the bottom row whole, which a fixed node row below the base reproduces here.
COMMON = ['output.every=1', 'output.snapshots=[]', 'gravity.evaluate_at="step_start"', 'solver.courant="sum"']
CORRECTED = ['solver.npc_position_velocity="corrected"']
LME = ['solver.shape="lme"', 'solver.lme_beta="authors"']
PATCH = ['solver.lme_neighbours="authors_patch"']
ROW_BELOW = ['grid.margin_min=[0,1]']
# case: (their history, label, [(variant, what it undoes, overrides, primary)])
CASES = [
    ("lme_pce", "LME γ = 3 + PCE (NPC)", [
        ("their settings", "-", COMMON + CORRECTED + LME + PATCH, True),
        ("this project's support", "the neighbours: the nodes within R = 2.15 h (13 of the 16)", COMMON + CORRECTED + LME, False),
        ("the shipped scene", "every setting: this project's defaults", ['output.every=1', 'output.snapshots=[]'], False)]),
    ("ugimp_pce", "uGIMP + PCE (NPC)", [
        ("their settings", "-", COMMON + CORRECTED + ['solver.shape="ugimp"'] + ROW_BELOW, True),
        ("clipped at the base", "the row below the base: the bottom particles' domains clipped at the grid's edge",
         COMMON + CORRECTED + ['solver.shape="ugimp"'], False),
        ("the shipped scene", "every setting", ['output.every=1', 'output.snapshots=[]', 'solver.shape="ugimp"'], False)]),
    ("q4_pce", "linear (Q4) + PCE (NPC)", [
        ("their settings", "-", COMMON + CORRECTED + ['solver.shape="linear"'], True),
        ("the shipped scene", "every setting", ['output.every=1', 'output.snapshots=[]', 'solver.shape="linear"'], False)]),
    ("q4_fe", "linear (Q4) + FE", [
        ("their settings", "-", COMMON + ['solver.shape="linear"', 'solver.integrator="fe"'], True),
        ("the shipped scene", "every setting",
         ['output.every=1', 'output.snapshots=[]', 'solver.shape="linear"', 'solver.integrator="fe"'], False)]),
]
TOLERANCE = 0.1  # % of their settlement: the verdict's bound
END_TIME = 20.0  # s, the scene's


def history(path, time_column, value_column):
    rows = list(csv.DictReader(open(path, newline="")))
    return [float(r[time_column]) for r in rows], [float(r[value_column]) for r in rows]


def ours(mpm, scene, overrides, end, folder):
    """This project's top particle u_y(t), run to `end` (their last sample) with `overrides`."""
    command = [mpm, "run", scene, "--out", folder, "--set", "solver.end_time=%.17g" % end]
    for setting in overrides:
        command += ["--set", setting]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return history(os.path.join(folder, "observers.csv"), "t", "top.u_y")


def differences(theirs, mine):
    """|theirs - ours| at each of their samples, ours interpolated linearly at their times."""
    t_ours, u_ours = mine
    out = []
    for t, u in zip(*theirs):
        k = min(max(bisect.bisect_left(t_ours, t), 1), len(t_ours) - 1)
        w = (t - t_ours[k - 1]) / (t_ours[k] - t_ours[k - 1])
        out.append(u - (u_ours[k - 1] + w * (u_ours[k] - u_ours[k - 1])))
    return out


def keep_history(path, t, u, d):
    """Their u_y, ours at their sample times and theirs - ours (d), one row per sample of theirs."""
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["t", "theirs", "ours", "difference"])
        for row in zip(t, u, d):
            writer.writerow(["%.12g" % row[0], "%.12g" % row[1], "%.12g" % (row[1] - row[2]), "%.6g" % row[2]])


def main():
    if len(sys.argv) != 6:
        sys.exit("usage: authors_soil.py MPM SCENE.toml DATA_DIR OUT.csv REPORT.md")
    mpm, scene, data, out_csv, report = sys.argv[1:]
    try:
        theirs = {name: history(os.path.join(data, "nl_partsol_soil_%s.csv" % name), "t", "top.u_y") for name, _, _ in CASES}
    except (OSError, KeyError, ValueError) as error:
        print("authors_soil.py: %s" % error, file=sys.stderr)
        sys.exit(2)
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for name, label, variants in CASES:
            t, u = theirs[name]
            for k, (variant, undoes, overrides, primary) in enumerate(variants):
                try:
                    d = differences((t, u), ours(mpm, scene, overrides, t[-1], os.path.join(scratch, "%s_%d" % (name, k))))
                except subprocess.CalledProcessError as error:
                    print("authors_soil.py: %s, %s: mpm run failed (%s)" % (label, variant, error), file=sys.stderr)
                    sys.exit(1)
                if primary:  # the histories under their settings, for the figure
                    kept = os.path.join(os.path.dirname(os.path.abspath(out_csv)), "authors_soil_%s.csv" % name)
                    keep_history(kept, t, u, d)
                largest = max(abs(x) for x in d)
                halves = [max(abs(x) for x in d[first::2]) for first in (0, 1)]
                rows.append({"case": name, "label": label, "variant": variant, "undoes": undoes, "primary": primary,
                             "their_end_time": t[-1], "their_settlement": -u[-1],
                             "largest_difference": largest, "largest_percent": 100.0 * largest / abs(u[-1]),
                             "band_percent": 100.0 * max(abs(h - largest) for h in halves) / abs(u[-1]),
                             "end_difference": d[-1], "end_percent": 100.0 * d[-1] / abs(u[-1])})
    fields = ["case", "variant", "their_end_time", "their_settlement", "largest_difference", "largest_percent",
              "band_percent", "end_difference", "end_percent"]
    with open(out_csv, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(fields)
        for r in rows:
            # the variant as one word (their_settings, this_projects_support, ...): a book's check marker selects rows by it
            writer.writerow([r[k].replace(" ", "_").replace("'", "") if isinstance(r[k], str) else "%.6g" % r[k] for k in fields])
    write_report(report, rows)


def write_report(path, rows):
    primary = [r for r in rows if r["primary"]]
    # a run of theirs that stopped before 20 s is its own outcome (the one rule, 3): stopped, its agreement up to the stop
    # in the table
    ending = lambda r: "stopped" if r["their_end_time"] < END_TIME - 1e-9 else "done"
    outcome = lambda r: verdict_rule.judge(r["largest_percent"], r["band_percent"], ending(r), "below", TOLERANCE)
    outcomes = [outcome(r) for r in primary]
    places = lambda which: "; ".join("%s (%.2g %% ± %.1g)" % (r["label"], r["largest_percent"], r["band_percent"])
                                     for r, o in zip(primary, outcomes) if o == which) or "-"
    with open(path, "w") as out:
        out.write("## The authors' code on the soil block (NL-PartSol 1d5da04)\n\n")
        out.write("The top particle's settlement u_y at (4.5, 9.5) m after every step of the authors' code (GraMS built from "
                  "their repository and run on an input written from `scenes/soil_block.toml` by "
                  "`verification/data/nl_partsol_soil_case.py`; their histories in `verification/data/`, each one's making in "
                  "`other_codes.csv`) beside this project's under their settings: gravity read at the step's start, the step "
                  "from c plus the largest signed velocity, their PCE's particle position from the corrected velocity, their LME "
                  "β and their whole 4 x 4 node patch as LME's neighbours (`solver.lme_neighbours = \"authors_patch\"`), and for "
                  "uGIMP a fixed node row below the base (their bottom particles' domains are not clipped). Each further row "
                  "undoes one setting, which says what that setting accounts for (the shipped scene: all of them). Differences: ours interpolated linearly at "
                  "their sample times, the largest over their history and the one at their last sample, over their settlement "
                  "there; band: the largest difference's move on their even or odd samples alone. Their linear (Q4) runs stop "
                  "early (the table's end; their particle search looks only in the cells the particle's velocity points to, "
                  "and their log ends \"GP 6 is not in the neighbours of 3\"): the table compares them up to there, the "
                  "verdict counts them as stopped (the one rule).\n\n")
        out.write("| case | this project's run | setting undone | their end (s) | their settlement (m) | largest difference | "
                  "at their end |\n|---|---|---|---|---|---|---|\n")
        for r in rows:
            out.write("| %s | %s | %s | %.2f | %.6f | %.3g m (%.2g %%) | %.3g m (%.2g %%) |\n" % (
                r["label"], r["variant"], r["undoes"], r["their_end_time"], r["their_settlement"], r["largest_difference"],
                r["largest_percent"], r["end_difference"], r["end_percent"]))
        out.write("\n| claim | measure | holds on | fails on | not compared (stopped, undecided) | verdict |\n"
                  "|---|---|---|---|---|---|\n")
        out.write("| Under the authors' settings the two codes agree on the soil block's settlement within %g %% | the largest "
                  "difference over their history / their settlement < %g %% beyond its band, by the one rule | %s | %s | %s | "
                  "**%s** |\n\n" % (TOLERANCE, TOLERANCE, places("holds"), places("fails"),
                                    "; ".join("%s (%s)" % (r["label"], "undecided" if o == "undecided" else
                                                           "their run stopped at %.2f s" % r["their_end_time"])
                                              for r, o in zip(primary, outcomes) if o in ("undecided", "stopped")) or "-",
                                    verdict_rule.verdict_text(outcomes)))
        out.write("![authors_soil](figures/authors_soil.png)\n\n"
                  "The figure sets the top particle's settlement of both codes side by side for each case, ours under their "
                  "settings (the table's first row of each case), and below, theirs minus ours at their sample times; its "
                  "largest magnitude is the table's largest difference. Their linear (Q4) runs stop near 8.5 s (a cross on "
                  "the strip above the data), ours was run to their stop.\n\n")


main()
