// Where a method leaves its no-crossing error as the amplitude of the motion grows (the smooth bar's and the Dyka
// bar's grid-crossing sweeps): the onset, and "later" by the one rule.
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "mpm/analysis/verdict.hpp"
#include "verification/claims.hpp"

namespace verification {

/// Where a method leaves its no-crossing error: the first U/h of the sweep at which its velocity error exceeds twice its
/// value at the smallest U/h (NaN: none does up to the largest), or the U/h at which a run stopped first (`stopped`: the
/// onset is then not measured, and a comparison of it is stopped, the one rule's own outcome).
struct Onset {
  double ratio = std::nan("");
  bool stopped = false;
};
/// The onset as text: "0.5", "> 2" (none up to `largest`, the sweep's largest U/h), "stopped at 0.5".
inline std::string onset_text(const Onset& onset, double largest) {
  if (onset.stopped) return "stopped at " + number(onset.ratio, "%g");
  return std::isfinite(onset.ratio) ? number(onset.ratio, "%g") : "> " + number(largest, "%g");
}
/// "a leaves its no-crossing error later than b" on the sweep's grid of U/h (NaN: no onset up to the largest, the
/// latest): stopped when either onset is not measured, undecided when both fall on the same U/h (the sweep does not
/// resolve them), otherwise holds or fails.
inline mpm::Outcome later(const Onset& a, const Onset& b) {
  if (a.stopped || b.stopped) return mpm::Outcome::stopped;
  const bool a_none = !std::isfinite(a.ratio), b_none = !std::isfinite(b.ratio);
  if (a_none == b_none && (a_none || a.ratio == b.ratio)) return mpm::Outcome::undecided;
  return a_none || (!b_none && a.ratio > b.ratio) ? mpm::Outcome::holds : mpm::Outcome::fails;
}

TEST_CASE("crossing onset: later by the one rule, a stop its own outcome, a tie on the sweep's grid undecided") {
  const double none = std::nan("");
  CHECK(later({1.5, false}, {0.5, false}) == mpm::Outcome::holds);
  CHECK(later({0.5, false}, {1.5, false}) == mpm::Outcome::fails);
  CHECK(later({none, false}, {1.5, false}) == mpm::Outcome::holds);
  CHECK(later({1.5, false}, {none, false}) == mpm::Outcome::fails);
  CHECK(later({1.5, false}, {1.5, false}) == mpm::Outcome::undecided);
  CHECK(later({none, false}, {none, false}) == mpm::Outcome::undecided);
  CHECK(later({1.5, false}, {0.5, true}) == mpm::Outcome::stopped);
}

}  // namespace verification
