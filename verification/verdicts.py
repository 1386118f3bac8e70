#!/usr/bin/env python3
"""Every verdict of the report as data, and the verdicts that changed since the report this one replaces.

    verification/verdicts.py RESULTS PREVIOUS.csv

Reads the verdict tables of RESULTS/report/*.md (`make figures`) and RESULTS/studies/report/*.md (`make studies`), the
tables the suites and the judging scripts write, and writes RESULTS/verdicts.csv: one row per verdict (target,
section, claim, rule, holds, fails, undecided, stopped, holds_on, fails_on, not_compared). Then compares it with
PREVIOUS.csv (the verdicts of the report this one replaces, verification/data/verdicts_81964fb.csv, made by make figures and make studies at commit 81964fb) and writes
RESULTS/verdicts_changed.md: each claim whose counts changed, each new one and each one no longer made. A target not
run yet contributes no rows. Exits 2 on an unreadable input.
"""
import csv
import glob
import os
import re
import sys

FIELDS = ["target", "section", "claim", "rule", "holds", "fails", "undecided", "stopped", "holds_on", "fails_on",
          "not_compared"]
DOMAIN_HEADER = "| claim | measure | holds on | fails on | not compared (stopped, undecided) | verdict |"
SIMPLE_HEADER = "| claim | measured | verdict |"
PLACES_HEADER = "| claim | holds on | fails on | verdict |"  # authors_code.py before it wrote the domain table


def cells(line, width=None):
    """The cells of a Markdown table row, split at the bars that are not escaped (\\|), the escapes undone. Given the
    table's `width`, a row with more cells (a report written before cells escaped their bars: a bar in its second
    cell, the rule) has its second cell rejoined at those bars."""
    inner = line.strip()[1:-1] if line.strip().endswith("|") else line.strip()[1:]
    raw = re.split(r"(?<!\\)\|", inner)
    if width and len(raw) > width:
        extra = len(raw) - width
        raw = [raw[0], "|".join(raw[1:extra + 2])] + raw[extra + 2:]
    return [cell.strip().replace("\\|", "|") for cell in raw]


def counts(verdict):
    """(holds, fails, undecided, stopped) of a domain verdict: the four counts the suites write, or, in a report
    written before they did, the words "holds on k of n; u undecided (...); s not compared (stopped)"."""
    verdict = verdict.strip("*")
    found = re.search(r"\((\d+) hold, (\d+) fail, (\d+) undecided, (\d+) stopped\)", verdict)
    if found:
        return tuple(int(x) for x in found.groups())
    holds = fails = 0
    if (m := re.match(r"holds on all (\d+)", verdict)):
        holds = int(m.group(1))
    elif (m := re.match(r"fails on all (\d+)", verdict)):
        fails = int(m.group(1))
    elif (m := re.match(r"holds on (\d+) of (\d+)", verdict)):
        holds, fails = int(m.group(1)), int(m.group(2)) - int(m.group(1))
    elif not verdict.startswith("no samples"):
        raise ValueError("unknown verdict %r" % verdict)
    undecided = re.search(r"(\d+) undecided", verdict)
    stopped = re.search(r"(\d+) not compared \(stopped\)", verdict)
    return holds, fails, int(undecided.group(1)) if undecided else 0, int(stopped.group(1)) if stopped else 0


def read_section_file(path, target):
    """The verdict rows of one report section file."""
    rows, section, header = [], "", None
    for line in open(path, encoding="utf-8"):
        line = line.rstrip("\n")
        if line.startswith("#"):
            section, header = line.lstrip("#").strip(), None
        elif line.startswith("| claim"):
            header = line.strip()
        elif not line.startswith("|"):
            header = None
        elif header and not line.startswith("|---"):
            c = cells(line, len(cells(header)))
            if header == DOMAIN_HEADER and len(c) == 6:
                holds, fails, undecided, stopped = counts(c[5])
                rows.append(dict(target=target, section=section, claim=c[0], rule=c[1], holds=holds, fails=fails,
                                 undecided=undecided, stopped=stopped, holds_on=c[2], fails_on=c[3], not_compared=c[4]))
            elif header == PLACES_HEADER and len(c) == 4:
                holds, fails, undecided, stopped = counts(c[3])
                rows.append(dict(target=target, section=section, claim=c[0], rule="as the claim states", holds=holds,
                                 fails=fails, undecided=undecided, stopped=stopped, holds_on=c[1], fails_on=c[2],
                                 not_compared="-"))
            elif header == SIMPLE_HEADER and len(c) == 3:
                word = c[2].strip("*")
                if word not in ("holds", "does not hold", "undecided", "stopped"):
                    raise ValueError("%s: unknown verdict %r" % (path, c[2]))
                holds = word == "holds"
                rows.append(dict(target=target, section=section, claim=c[0], rule="as the claim states", holds=int(holds),
                                 fails=int(word == "does not hold"), undecided=int(word == "undecided"),
                                 stopped=int(word == "stopped"), holds_on=c[1] if holds else "-",
                                 fails_on=c[1] if word == "does not hold" else "-",
                                 not_compared=c[1] if word in ("undecided", "stopped") else "-"))
    return rows


def read_verdicts(results):
    rows = []
    for target, folder in (("figures", "report"), ("studies", os.path.join("studies", "report"))):
        for path in sorted(glob.glob(os.path.join(results, folder, "*.md"))):
            rows += read_section_file(path, target)
    return rows


def key(row):
    return row["target"], row["section"], row["claim"]


def changes(previous, current):
    """Markdown lines naming the verdicts that changed, appeared or went."""
    before = {key(row): row for row in previous}
    after = {key(row): row for row in current}
    count = lambda row: "%s hold, %s fail, %s undecided, %s stopped" % (row["holds"], row["fails"], row["undecided"],
                                                                       row["stopped"])
    changed = [k for k in after if k in before and count(after[k]) != count(before[k])]
    added = [k for k in after if k not in before]
    gone = [k for k in before if k not in after]
    lines = ["%d verdicts now, %d before: %d changed their counts, %d are new or reworded, %d are no longer made "
             "(or were reworded)." % (len(after), len(before), len(changed), len(added), len(gone)), ""]
    # a verdict decided on CPU times moves with the machine's load between two reports of one code: marked so
    timed = lambda row: "yes" if re.search(r"CPU|error-cost|faster|timing", row["claim"] + " " + row["rule"]) else "no"
    escape = lambda text: text.replace("|", "\\|")
    if changed:
        lines += ["| target | section | claim | before | now | decided on CPU times |", "|---|---|---|---|---|---|"]
        lines += ["| %s | %s | %s | %s | %s | %s |" % (k[0], escape(k[1]), escape(k[2]), count(before[k]), count(after[k]),
                                                     timed(after[k])) for k in changed]
        lines.append("")
    for title, which, rows in (("New or reworded", added, after), ("No longer made, or reworded", gone, before)):
        if which:
            lines += ["%s:" % title, ""] + ["- %s / %s: %s (%s)" % (k[0], k[1], k[2], count(rows[k])) for k in which]
            lines.append("")
    return lines


def main(arguments):
    if len(arguments) != 2:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    results, previous_path = arguments
    try:
        current = read_verdicts(results)
        previous = list(csv.DictReader(open(previous_path, newline="", encoding="utf-8")))
        for row in previous:
            missing = [field for field in FIELDS if field not in row]
            if missing:
                raise ValueError("%s: no column %s" % (previous_path, ", ".join(missing)))
    except (OSError, ValueError) as error:
        print("verdicts.py: %s" % error, file=sys.stderr)
        return 2
    with open(os.path.join(results, "verdicts.csv"), "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(current)
    with open(os.path.join(results, "verdicts_changed.md"), "w", encoding="utf-8") as handle:
        handle.write("\n".join(changes(previous, current)) + "\n")
    print("verdicts: %d verdicts in %s" % (len(current), os.path.join(results, "verdicts.csv")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
