#!/usr/bin/env python3
"""`make mutants`: would the tests catch a wrong kernel? Each mutant of tests/mutants/mutants.tsv (a
flipped sign, a dropped or changed factor, gamma <-> 1 - gamma, swapped indices, an off-by-one in a
loop over a stencil, a quantity at the wrong time level) is applied to a copy of the source tree, the
copy is rebuilt and the tests are run; the mutant is killed when a test fails (or crashes, or hangs),
and survives when every test passes.

    tests/mutants/run.py [--build-dir build] [--jobs 2] [--only ID,ID,... | --sample N]

Two stages, so that about a hundred mutants run in minutes on two cores:
  1. the doctests of the mutated header and of the headers it includes, compiled as a program of their
     own (CMake target header_probe: one translation unit, built in seconds; for a header of mpm/cli/,
     header_probe_library, linked with the libraries that compile the runs), in --jobs copies of the
     tree side by side;
  2. a mutant that survives them is run against the whole of mpm_tests (every doctest and the
     whole-method tests of tests/: free fall, momentum, energy, the Dyka bar, the soil block), rebuilt
     with the solver's library in one copy.
Before any mutant, every header's probe and mpm_tests must pass unmutated (else nothing is counted).

The list's columns, tab-separated, `\\n` and `\\t` written as escapes:
  id, equations (labels, space-separated: "26 29", "A.19"), file, original text (found exactly once in
  the file), replacement, what the mutant does, and for a mutant known to survive the reason it is
  equivalent (empty otherwise).

Writes results/mutants/mutants.csv (one row per mutant: its fate, the stage and the test that killed
it) and results/mutants/summary.md; `make docs` shows each equation's mutants on its page of tests.
With --only, runs those mutants, and with --sample N every k-th of those without a note of equivalence
(about N; CI runs a sample, .ci/run), and prints their fates, writing nothing to results/. The whole
list is checked first either way: a mutant whose original text is no longer in its file fails the run.
Exit status: 0 when every mutant is killed or noted equivalent (and every equivalent one survives);
1 when one survives without a note, a noted one is killed, or a baseline fails; 2 for a broken list.
"""
import argparse
import concurrent.futures
import csv
import os
import re
import shutil
import subprocess
import sys
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LIST = os.path.join(ROOT, "tests", "mutants", "mutants.tsv")
COPIED = ["CMakeLists.txt", "README.md", "mpm", "tests", "verification", "scenes"]
BUILD_TIMEOUT = 900  # s; a build that takes longer is an error of the run, not a fate
TEST_TIMEOUT = 300   # s; a test program that takes longer is killed, and so is its mutant


class Mutant:
    def __init__(self, fields, line):
        if len(fields) not in (6, 7):
            raise ValueError(f"line {line}: {len(fields)} columns, want 6 or 7")
        unescape = lambda text: text.replace("\\n", "\n").replace("\\t", "\t")
        self.id, equations, self.file = fields[0], fields[1], fields[2]
        self.original, self.replacement = unescape(fields[3]), unescape(fields[4])
        self.what = fields[5]
        self.equivalent = fields[6] if len(fields) == 7 else ""
        self.equations = equations.split()
        self.line = line
        self.fate, self.stage, self.killed_by, self.seconds = "", "", "", 0.0


def read_list():
    mutants, errors = [], []
    with open(LIST) as handle:
        for number, text in enumerate(handle, 1):
            text = text.rstrip("\n")
            if not text or text.startswith("#"):
                continue
            try:
                mutants.append(Mutant(text.split("\t"), number))
            except ValueError as error:
                errors.append(f"{LIST}:{error}")
    seen = set()
    for m in mutants:
        where = f"{LIST}:{m.line}: {m.id}"
        if m.id in seen:
            errors.append(f"{where}: id used twice")
        seen.add(m.id)
        if not m.equations or not all(re.fullmatch(r"(A\.)?[0-9]{1,2}", e) for e in m.equations):
            errors.append(f"{where}: equations must be labels such as 26 or A.19")
        path = os.path.join(ROOT, m.file)
        if not os.path.isfile(path):
            errors.append(f"{where}: no file {m.file}")
            continue
        count = open(path).read().count(m.original)
        if count != 1:
            errors.append(f"{where}: the original text occurs {count} times in {m.file}, not once")
        if m.original == m.replacement:
            errors.append(f"{where}: the replacement equals the original")
    return mutants, errors


def run(command, cwd=None, timeout=None):
    """(exit code, output, seconds); exit code None on a timeout."""
    start = time.time()
    try:
        done = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                              text=True, errors="replace")
        return done.returncode, done.stdout, time.time() - start
    except subprocess.TimeoutExpired as expired:
        output = expired.stdout or ""
        if isinstance(output, bytes):
            output = output.decode(errors="replace")
        return None, output, time.time() - start


def first_failure(output):
    """The name of the first test case doctest reports as failing."""
    match = re.search(r"^TEST CASE:\s+(.*)$", output, re.MULTILINE)
    return match.group(1).strip() if match else ""


class Copy:
    """A copy of the source tree with its own build folder."""

    def __init__(self, work, index):
        self.tree = os.path.join(work, f"tree{index}")
        self.build = os.path.join(work, f"build{index}")
        self.lock = threading.Lock()

    def make(self):
        # Afresh, tree and build folder: objects left by an earlier run may have been compiled from a mutant.
        shutil.rmtree(self.tree, ignore_errors=True)
        shutil.rmtree(self.build, ignore_errors=True)
        os.makedirs(self.tree)
        for name in COPIED:
            source = os.path.join(ROOT, name)
            if os.path.isdir(source):
                shutil.copytree(source, os.path.join(self.tree, name))
            else:
                shutil.copy2(source, os.path.join(self.tree, name))
        os.makedirs(self.build, exist_ok=True)
        self.write_probe("mpm/grid/nodal_update.hpp")
        code, output, _ = run(["cmake", "-S", self.tree, "-B", self.build, "-DCMAKE_BUILD_TYPE=Release"])
        if code != 0:
            raise RuntimeError(f"configuring {self.build} failed:\n{output}")

    def write_probe(self, header):
        path = os.path.join(self.build, "header_probe.cpp")
        text = ("// Written by tests/mutants/run.py: the doctests of one header and of those it includes\n"
                "// (doctest's main is tests/doctest_main.cpp).\n#include <doctest/doctest.h>\n\n"
                f'#include "{header}"\n')
        if not os.path.exists(path) or open(path).read() != text:
            with open(path, "w") as handle:
                handle.write(text)

    def apply(self, mutant):
        path = os.path.join(self.tree, mutant.file)
        text = open(path).read()
        with open(path, "w") as handle:
            handle.write(text.replace(mutant.original, mutant.replacement, 1))

    def restore(self, mutant):
        # A fresh modification time (copyfile, not copy2), so that the next build sees the change back.
        shutil.copyfile(os.path.join(ROOT, mutant.file), os.path.join(self.tree, mutant.file))

    def build_target(self, target, jobs=1):
        return run(["cmake", "--build", self.build, "--target", target, "-j", str(jobs)], timeout=BUILD_TIMEOUT)

    def probe(self, header):
        """(exit code of the probe or 'build' when it does not build, output)."""
        self.write_probe(header)
        # The commands' doctests run scenes and stability analyses, compiled in the libraries: their probe links them.
        target = "header_probe_library" if header.startswith("mpm/cli/") else "header_probe"
        code, output, _ = self.build_target(target)
        if code != 0:
            return "build", output
        code, output, _ = run([os.path.join(self.build, "bin", target), "--abort-after=1"], timeout=TEST_TIMEOUT)
        return code, output


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--only", default="")
    parser.add_argument("--sample", type=int, default=0)
    options = parser.parse_args()
    start = time.time()

    mutants, errors = read_list()
    if errors:
        print("\n".join(errors), file=sys.stderr)
        return 2
    if options.only:
        wanted = options.only.split(",")
        unknown = [w for w in wanted if w not in {m.id for m in mutants}]
        if unknown:
            print(f"mutants: no mutant {', '.join(unknown)} in {LIST}", file=sys.stderr)
            return 2
        mutants = [m for m in mutants if m.id in wanted]
    elif options.sample > 0:
        candidates = [m for m in mutants if not m.equivalent]
        every = max(1, -(-len(candidates) // options.sample))
        mutants = candidates[::every]
    jobs = max(1, options.jobs)
    work = os.path.join(ROOT, options.build_dir, "mutants")
    copies = [Copy(work, i) for i in range(jobs)]
    print(f"mutants: {len(mutants)} mutants, {jobs} copies of the tree in {work}", flush=True)
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        list(pool.map(Copy.make, copies))

    # Stage 1. Each header's probe must pass unmutated; then each mutant against its header's probe.
    headers = sorted({m.file for m in mutants})
    free = list(copies)
    free_lock = threading.Condition()

    def on_a_copy(task):
        with free_lock:
            while not free:
                free_lock.wait()
            copy = free.pop()
        try:
            return task(copy)
        finally:
            with free_lock:
                free.append(copy)
                free_lock.notify()

    def baseline(header):
        code, output = on_a_copy(lambda copy: copy.probe(header))
        return header, code, output

    broken = False
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        for header, code, output in pool.map(baseline, headers):
            if code != 0:
                print(f"mutants: the doctests of {header} fail or do not build unmutated:\n{output[-3000:]}", file=sys.stderr)
                broken = True
    if broken:
        return 1
    print(f"mutants: the unmutated doctests of {len(headers)} headers pass ({time.time() - start:.0f} s)", flush=True)

    done_count = [0]

    def stage_one(mutant):
        def task(copy):
            began = time.time()
            copy.apply(mutant)
            try:
                code, output = copy.probe(mutant.file)
            finally:
                copy.restore(mutant)
            mutant.seconds = time.time() - began
            if code == "build":
                mutant.fate, mutant.killed_by = "does not compile", output[-2000:]
            elif code != 0:
                mutant.fate, mutant.stage = "killed", "own doctests"
                mutant.killed_by = first_failure(output) or ("timeout" if code is None else f"exit {code}")
        on_a_copy(task)
        done_count[0] += 1
        print(f"mutants: {mutant.id} ({mutant.file}): {mutant.fate or 'survives its doctests'} "
              f"({mutant.seconds:.0f} s; {done_count[0]} of {len(mutants)})", flush=True)

    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        list(pool.map(stage_one, mutants))

    # Stage 2. The survivors against the whole test program, in the first copy.
    survivors = [m for m in mutants if not m.fate]
    if survivors:
        copy = copies[0]
        code, output, _ = copy.build_target("mpm_tests", jobs)
        test_program = os.path.join(copy.build, "bin", "mpm_tests")
        if code == 0:
            code, output, _ = run([test_program, "--abort-after=1"], timeout=TEST_TIMEOUT)
        if code != 0:
            print(f"mutants: mpm_tests fails or does not build unmutated:\n{output[-3000:]}", file=sys.stderr)
            return 1
        print(f"mutants: mpm_tests passes unmutated; {len(survivors)} mutants left for it ({time.time() - start:.0f} s)",
              flush=True)
        for mutant in survivors:
            began = time.time()
            copy.apply(mutant)
            try:
                code, output, _ = copy.build_target("mpm_tests", jobs)
                if code != 0:
                    mutant.fate, mutant.killed_by = "does not compile", output[-2000:]
                else:
                    code, output, _ = run([test_program, "--abort-after=1"], timeout=TEST_TIMEOUT)
                    if code == 0:
                        mutant.fate, mutant.stage = "survived", "mpm_tests"
                    else:
                        mutant.fate, mutant.stage = "killed", "mpm_tests"
                        mutant.killed_by = first_failure(output) or ("timeout" if code is None else f"exit {code}")
            finally:
                copy.restore(mutant)
            mutant.seconds += time.time() - began
            print(f"mutants: {mutant.id}: {mutant.fate} by mpm_tests ({time.time() - began:.0f} s)", flush=True)

    elapsed = time.time() - start
    problems = []
    for m in mutants:
        if m.fate == "does not compile":
            problems.append(f"{m.id}: does not compile (fix the list): {m.killed_by[-600:]}")
        elif m.fate == "survived" and not m.equivalent:
            problems.append(f"{m.id}: survived every test, and the list gives no reason it is equivalent "
                            f"({m.file}: {m.what})")
        elif m.fate == "killed" and m.equivalent:
            problems.append(f"{m.id}: noted as equivalent, yet killed by {m.killed_by}: the note is wrong")
    killed = sum(m.fate == "killed" for m in mutants)
    equivalent = sum(m.fate == "survived" and bool(m.equivalent) for m in mutants)
    line = (f"mutants: {len(mutants)} mutants: {killed} killed ({sum(m.stage == 'own doctests' for m in mutants)} by "
            f"their header's doctests, {sum(m.stage == 'mpm_tests' and m.fate == 'killed' for m in mutants)} by mpm_tests), "
            f"{sum(m.fate == 'survived' for m in mutants)} survived ({equivalent} noted equivalent), in {elapsed:.0f} s "
            f"on {jobs} copies")
    print(line)
    for problem in problems:
        print(f"mutants: PROBLEM: {problem}", file=sys.stderr)

    if not options.only and not options.sample:
        out = os.path.join(ROOT, "results", "mutants")
        os.makedirs(out, exist_ok=True)
        with open(os.path.join(out, "mutants.csv"), "w", newline="") as handle:
            writer = csv.writer(handle)
            writer.writerow(["id", "equations", "file", "what", "fate", "stage", "killed_by", "equivalent", "seconds"])
            for m in mutants:
                writer.writerow([m.id, " ".join(m.equations), m.file, m.what, m.fate, m.stage,
                                 m.killed_by if m.fate == "killed" else "", m.equivalent, f"{m.seconds:.1f}"])
        with open(os.path.join(out, "summary.md"), "w") as handle:
            handle.write(f"# Mutants\n\nGenerated by `make mutants` on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} "
                         f"in {elapsed:.0f} s with {jobs} copies of the tree on {os.cpu_count()} cores, from "
                         f"tests/mutants/mutants.tsv.\n\n{line.replace('mutants: ', '', 1)}.\n\n")
            handle.write("| id | equations | file | mutant | fate | killed by |\n|---|---|---|---|---|---|\n")
            for m in mutants:
                fate = m.fate + (f" (equivalent: {m.equivalent})" if m.equivalent else "")
                handle.write(f"| {m.id} | {', '.join(m.equations)} | {m.file} | {m.what} | {fate} | "
                             f"{(m.killed_by if m.fate == 'killed' else '').replace('|', '/')} |\n")
        print(f"mutants: wrote {out}/mutants.csv and summary.md")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
