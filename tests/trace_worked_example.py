#!/usr/bin/env python3
"""`mpm trace` prints the book's worked example (paper/12_worked_example.md): every number of its tables is read
from its marker `<!-- worked INTEGRATOR PHASE node|particle INDEX QUANTITY -->` and compared, to half a unit of its
last printed digit, with the trace of step 1 of scenes/worked_example.toml after the phase of that number (the
book's phase numbers are the trace's: `# phase N of M: NAME`). A number fails when its phase, row or column is not
in the trace, except the quantities of NOT_TRACED, each left out for the reason it gives. The book and the trace
speak one vocabulary: each equation a row of the book's tables is labelled with, `| 7 | (18)-(19) | ...`, is one of
those the trace's heading of that phase names (`# phase 7 of 7: euler_update, Eqs. (12) (18)-(19) (21)-(22): ...`,
from the phase table of mpm/core/step_phases.hpp).

Usage: trace_worked_example.py MPM SOURCE_DIR
"""
import re
import subprocess
import sys

mpm, root = sys.argv[1], sys.argv[2]
book = open(f"{root}/paper/12_worked_example.md", encoding="utf-8").read()
markers = re.findall(r"([−\-]?[0-9.]+)<!-- worked (\S+) (\d+) (node|particle) (\d+) (\S+) -->", book)

SETTINGS = {"fe": [], "npc": ["solver.integrator=\"npc\""],
            "npc_corrected": ["solver.integrator=\"npc\"", "solver.npc_position_velocity=\"corrected\""]}
NODE = {"m": "m_I", "p": "p_I_k_x", "v_k": "v_I_k_x", "v_pred": "v_I_pred_x", "f": "f_I_k1_x", "reaction": "r_I_x",
        "p_k1": "p_I_k1_x", "v_k1": "v_I_k1_x", "a": "a_I_k1_x"}
PARTICLE = {"strain": "eps_p_k1_xx", "stress": "sigma_p_k1_xx", "density": "rho_p_k1", "a": "a_p_k1_x",
            "v": "v_p_k1_x", "x": "x_p_k1"}
# The book's quantities that the trace cannot print, and why; the transfer doctests check them.
NOT_TRACED = {
    "strain_rate": "not stored: the stress update adds dt times it to the strain (eps_p_k1) in the same pass",
    "volume": "not stored: m_p / rho_p, both printed",
    "f_int": "not stored: the force kernel sums f_int and f_ext into f_I in one pass over the particles",
    "f_ext": "not stored: the force kernel sums f_int and f_ext into f_I in one pass over the particles",
}


def numbers_of(label):
    """The equation numbers of a label: "(12), (21)" -> {12, 21}; "(18)-(19)" -> {18, 19}; "(26)-(29)" -> 26..29."""
    numbers = set()
    for first, last in re.findall(r"\((\d+)\)(?:-\((\d+)\))?", label):
        numbers.update(range(int(first), int(last or first) + 1))
    return numbers


equations = {}  # (integrator, phase number): the equation numbers the trace's heading of that phase names


def trace(integrator):
    """({phase number: phase name}, {(phase name, at, index): {column: value}}) of step 1 traced as CSV."""
    command = [mpm, "trace", f"{root}/scenes/worked_example.toml", "--step", "1"]
    for setting in SETTINGS[integrator]:
        command += ["--set", setting]
    out = subprocess.run(command, capture_output=True, text=True, check=True).stdout
    names, rows, header = {}, {}, []
    for line in out.splitlines():
        numbered = re.match(r"# phase (\d+) of \d+: ([a-z_0-9]+)(?:, Eqs?\. ([^:]*))?:", line)
        if numbered:
            names[int(numbered.group(1))] = numbered.group(2)
            equations[(integrator, int(numbered.group(1)))] = numbers_of(numbered.group(3) or "")
        if line.startswith("#") or not line:
            continue
        fields = line.split(",")
        if fields[0] == "phase":
            header = fields
            continue
        rows[(fields[0], fields[2], int(fields[3]))] = dict(zip(header, fields))
    return names, rows


traces = {name: trace(name) for name in SETTINGS}
failures, checked, left_out = [], {name: 0 for name in SETTINGS}, 0
for text, integrator, phase, at, index, quantity in markers:
    where = f"{integrator} phase {phase} {at} {index} {quantity}"
    if quantity in NOT_TRACED:
        left_out += 1
        continue
    if integrator not in traces:
        failures.append(f"{where}: no such integrator in this test")
        continue
    names, rows = traces[integrator]
    column = (NODE if at == "node" else PARTICLE).get(quantity)
    row = rows.get((names.get(int(phase), "?"), at, int(index)))
    if column is None or row is None or column not in row:
        failures.append(f"{where}: book {text}, not in the trace (phase {names.get(int(phase), 'missing')}, "
                        f"column {column})")
        continue
    want = float(text.replace("−", "-"))
    decimals = len(text.split(".")[1]) if "." in text else 0
    checked[integrator] += 1
    if abs(float(row[column]) - want) > 0.5 * 10.0 ** -decimals + 1e-12:
        failures.append(f"{where}: book {text}, trace {row[column]}")

labels = 0
for line in book.splitlines():  # each table row: | phase | equation | quantity | values with their markers |
    row = re.match(r"\| (\d+) \| ([^|]*) \|.*?<!-- worked (\S+) ", line)
    if not row or not row.group(2).strip():
        continue
    phase, label, integrator = int(row.group(1)), row.group(2).strip(), row.group(3)
    labels += 1
    named = equations.get((integrator, phase))
    if named is None:
        failures.append(f"{integrator} phase {phase}: labelled {label} in the book, no such phase in the trace")
    elif not numbers_of(label) <= named:
        failures.append(f"{integrator} phase {phase}: the book labels a row {label}, the trace's heading names "
                        f"{sorted(named)} (mpm/core/step_phases.hpp's table)")
if labels == 0:
    failures.append("no labelled row of the book's tables read")

print(f"trace_worked_example: {labels} equation labels of the book's rows found among the trace's phase headings")
print(f"trace_worked_example: {sum(checked.values())} of the book's numbers checked against mpm trace "
      f"({', '.join(f'{k} {v}' for k, v in checked.items())}), {left_out} not traced ({', '.join(NOT_TRACED)})")
for failure in failures:
    print("FAIL:", failure)
for integrator, count in checked.items():
    if count == 0:
        print(f"FAIL: no number of {integrator} checked (markers lost?)")
        failures.append(integrator)
sys.exit(1 if failures else 0)
