#!/usr/bin/env python3
"""One visual identity (issue 48): every colour, dash and font of the figures is set in verification/plots/palette.gp,
common.gp and output.gp, and nowhere else.

Checks each figure script in verification/plots/ and the gnuplot that `mpm plot` and `mpm compare --plot` write
(mpm/cli/*.hpp): no colour literal (#rrggbb, a named colour, a numbered line colour or type, a palette of its own), no
terminal or font size of its own below the shared one, the shared style loaded; and each shell script of make
figures and make studies draws through verification/figure.sh (which fails on a gnuplot warning and on a legend
entry without data). Prints each offence as FILE:LINE: what; exits 1 if there is one.

  python3 tests/figure_style.py [REPOSITORY]
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
plots = root / "verification" / "plots"
shared = {"palette.gp", "common.gp", "output.gp"}
colour = re.compile(r"#[0-9a-fA-F]{6}\b|\brgb\s*['\"][a-zA-Z]|\b(lc|linecolor|lt|linetype)\s+[0-9]|palette\s+defined"
                    r"|\btc\s+(lt|ls)\s|\bset\s+style\s+line")
font = re.compile(r"font\s*['\"][^'\"]*,\s*([0-9.]+)")
smallest = 11
offences = []


def offend(path, number, what):
    offences.append(f"{path.relative_to(root)}:{number}: {what}")


def code_of(line):
    """The line without its comment (a # outside quotes)."""
    quote = None
    for k, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#":
            return line[:k]
    return line


for script in sorted(plots.glob("*.gp")):
    text = script.read_text(encoding="utf-8")
    if script.name in shared:
        continue
    if 'load dir."/common.gp"' not in text or 'load dir."/output.gp"' not in text:
        offend(script, 1, "does not load common.gp and output.gp (the shared style and output)")
    for number, line in enumerate(text.splitlines(), 1):
        code = code_of(line)
        if colour.search(code):
            offend(script, number, f"a colour of its own ({colour.search(code).group(0)}): take it from palette.gp")
        if re.search(r"\bset\s+term", code):
            offend(script, number, "a terminal of its own: output.gp sets it")
        for size in font.findall(code):
            if float(size) < smallest:
                offend(script, number, f"font size {size} below the shared {smallest}")

for shell in sorted((root / "verification").glob("*.sh")):
    if shell.name == "figure.sh":
        continue
    for number, line in enumerate(shell.read_text(encoding="utf-8").splitlines(), 1):
        if re.search(r"(^|[;&|(]\s*)gnuplot\s", code_of(line)):
            offend(shell, number, "runs gnuplot itself: draw through draw_figure (verification/figure.sh)")

for header in sorted((root / "mpm" / "cli").glob("*.hpp")):
    for number, line in enumerate(header.read_text(encoding="utf-8").splitlines(), 1):
        code = line.split("//")[0]
        if re.search(r"#[0-9a-fA-F]{6}\b|rgb '[a-z]", code):
            offend(header, number, "a colour of its own in a gnuplot script: take it from the palette (gnuplot_palette)")
        for size in re.findall(r"font ',([0-9.]+)'", code):
            if float(size) < smallest:
                offend(header, number, f"font size {size} below the shared {smallest}")

for offence in offences:
    print(offence)
print(f"figure_style: {len(offences)} offence(s) in {len(list(plots.glob('*.gp')))} figure scripts")
sys.exit(1 if offences else 0)
