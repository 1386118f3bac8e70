"""The one verdict rule of the report, for the scripts that judge (hydrostatic_column.py, authors_code.py).

The same rule as the C++ suites' and `mpm study`'s (mpm/analysis/verdict.hpp), tested on the same constructed cases
(tests/data/verdict_rule_cases.csv, by tests/verdict_rule.py). A compared number carries the half-width of the band
its own measurement resolves and its run's ending: "done", "failed" (it ran to its end, but scored no better than a
flat line) or "stopped". For the claim "a lies below (or above) b":
1. stopped when a run of either number stopped, or both runs failed (or a value is not a number);
2. undecided when |a - b| <= band_a + band_b;
3. otherwise holds when a lies on the claimed side, fails when not (a failed run beside a done one is compared).
"""
import math

OUTCOMES = ("holds", "fails", "undecided", "stopped")


def judge(a, a_band, a_ending, side, b, b_band=0.0, b_ending="done"):
    """The outcome of "a lies on `side` ("below" or "above") of b" by the rule above."""
    for ending in (a_ending, b_ending):
        if ending not in ("done", "failed", "stopped"):
            raise ValueError("unknown ending %r" % ending)
    if side not in ("below", "above"):
        raise ValueError("unknown side %r" % side)
    if "stopped" in (a_ending, b_ending) or (a_ending == "failed" and b_ending == "failed"):
        return "stopped"
    if not (math.isfinite(a) and math.isfinite(b)):
        return "stopped"
    if abs(a - b) <= a_band + b_band:
        return "undecided"
    return "holds" if (a < b if side == "below" else a > b) else "fails"


def counts(outcomes):
    """The four counts of a verdict row, in the report's order: holds, fails, undecided, stopped."""
    return tuple(sum(1 for outcome in outcomes if outcome == name) for name in OUTCOMES)


def verdict_text(outcomes):
    """The verdict's words, as the C++ suites write them (verification/claims.hpp, DomainClaim::verdict)."""
    holds, fails, undecided, stopped = counts(outcomes)
    n = holds + fails
    text = ("undecided on all %d" % undecided if n == 0 and undecided else
            "no samples compared" if n == 0 else "holds on all %d" % n if holds == n else
            "fails on all %d" % n if holds == 0 else "holds on %d of %d" % (holds, n))
    return text + " (%d hold, %d fail, %d undecided, %d stopped)" % (holds, fails, undecided, stopped)
