#!/usr/bin/env python3
"""`mpm trace` prints the book's worked example (paper/12_worked_example.md): every number of its tables that the
trace prints (nodal m, p, v, f, reactions, a; particle strain, stress, density, a, v, x) is read from its marker
`<!-- worked INTEGRATOR STEP node|particle INDEX QUANTITY -->` and compared, to half a unit of its last printed
digit, with the trace of step 1 of scenes/worked_example.toml after the phase the book's step names. Quantities the
trace does not print (strain rate, volume, f_int, f_ext, forward Euler's particle a) are counted and left out.

Usage: trace_worked_example.py MPM SOURCE_DIR
"""
import re
import subprocess
import sys

mpm, root = sys.argv[1], sys.argv[2]
book = open(f"{root}/paper/12_worked_example.md", encoding="utf-8").read()
markers = re.findall(r"([−\-]?[0-9.]+)<!-- worked (\S+) (\d+) (node|particle) (\d+) (\S+) -->", book)

# The book's step numbers (the code's numbered steps) -> the trace's phase names.
FE = {1: "mass_momentum", 2: "fixed_momentum", 3: "velocity_k", 4: "stress", 5: "forces",
      6: "momentum_balance", 7: "euler_update"}
NPC = {1: "mass_predictor", 2: "mass_predictor", 3: "fixed_predictor", 4: "stress", 5: "stress",
       6: "forces", 7: "corrector", 8: "newmark_update"}
PHASES = {"fe": FE, "npc": NPC, "npc_corrected": NPC}
SETTINGS = {"fe": [], "npc": ["solver.integrator=\"npc\""],
            "npc_corrected": ["solver.integrator=\"npc\"", "solver.npc_position_velocity=\"corrected\""]}
NODE = {"m": "m_I", "p": "p_I_k_x", "v_k": "v_I_k_x", "v_pred": "v_I_pred_x", "f": "f_I_x", "reaction": "r_I_x",
        "p_k1": "p_I_k1_x", "v_k1": "v_I_k1_x", "a": "a_I_x"}
PARTICLE = {"strain": "eps_p_k1_xx", "stress": "sigma_p_k1_xx", "density": "rho_p_k1", "a": "a_p_k1_x",
            "v": "v_p_k1_x", "x": "x_p_k1"}


def trace(integrator):
    """{(phase, at, index): {column: value}} of step 1 traced as CSV."""
    command = [mpm, "trace", f"{root}/scenes/worked_example.toml", "--step", "1"]
    for setting in SETTINGS[integrator]:
        command += ["--set", setting]
    out = subprocess.run(command, capture_output=True, text=True, check=True).stdout
    rows, header = {}, []
    for line in out.splitlines():
        if line.startswith("#") or not line:
            continue
        fields = line.split(",")
        if fields[0] == "phase":
            header = fields
            continue
        rows[(fields[0], fields[2], int(fields[3]))] = dict(zip(header, fields))
    return rows


traces = {name: trace(name) for name in PHASES}
failures, checked, left_out = [], 0, 0
for text, integrator, step, at, index, quantity in markers:
    column = (NODE if at == "node" else PARTICLE).get(quantity)
    row = traces[integrator].get((PHASES[integrator][int(step)], at, int(index)), {})
    if column is None or column not in row:
        left_out += 1
        continue
    want = float(text.replace("−", "-"))
    decimals = len(text.split(".")[1]) if "." in text else 0
    got = float(row[column])
    checked += 1
    if abs(got - want) > 0.5 * 10.0 ** -decimals + 1e-12:
        failures.append(f"{integrator} step {step} {at} {index} {quantity}: book {text}, trace {row[column]}")

print(f"trace_worked_example: {checked} of the book's numbers checked against mpm trace, {left_out} not traced")
for failure in failures:
    print("FAIL:", failure)
if checked < 60:
    print(f"FAIL: only {checked} numbers checked (markers or trace columns lost?)")
    sys.exit(1)
sys.exit(1 if failures else 0)
