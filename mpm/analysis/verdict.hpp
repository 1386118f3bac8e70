/// \file
/// The one rule by which every comparison of the report and of `mpm study` is decided: a compared number carries the
/// band of its own measurement, and its run's ending; a comparison holds, fails, is undecided (inside the band) or is
/// not compared (a run stopped, or every run of it failed). The Python scripts that judge (verification/verdict_rule.py)
/// implement the same rule; both are tested on the same constructed cases, tests/data/verdict_rule_cases.csv.
/// Not an equation of the paper: the report's yardstick (paper/08_test_cases.md, "How a verdict is decided").
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace mpm {

/// How the run behind a measured number ended.
enum class Ending {
  done,     ///< it ran to its end and scored better than a flat line (see failed_score)
  failed,   ///< it ran to its end, but its error is no smaller than a flat line's: no approximation at all
  stopped,  ///< it stopped before its end (the solver's own diagnosis: energy growth, NaN, a particle left the grid)
};

/// One measured number: its value, the half-width of the band its own measurement resolves (e.g. the largest move of
/// an RMS when scored on the even or the odd samples alone), and how its run ended.
struct Measured {
  double value = 0.0;
  double band = 0.0;
  Ending ending = Ending::done;
};

/// The outcome of one comparison.
enum class Outcome { holds, fails, undecided, stopped };

inline const char* outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::holds: return "holds";
    case Outcome::fails: return "fails";
    case Outcome::undecided: return "undecided";
    case Outcome::stopped: return "stopped";
  }
  return "stopped";
}

/// Which side of the other number the claim puts the first: "a < b" is below, "a > b" above.
enum class Side { below, above };

/// The rule, for the claim "a lies on `side` of b" (b a threshold: band 0, done):
/// 1. stopped when a run of either number stopped, or when both runs failed (two failed runs are not compared: the
///    difference of two non-approximations says nothing about either method);
/// 2. undecided when \f$ |a - b| \le \delta_a + \delta_b \f$, the two bands together;
/// 3. otherwise holds when a lies on the claimed side, fails when not. A failed run beside a done one is compared:
///    its error is large, and the comparison says so.
inline Outcome judge(const Measured& a, Side side, const Measured& b) {
  if (a.ending == Ending::stopped || b.ending == Ending::stopped) return Outcome::stopped;
  if (a.ending == Ending::failed && b.ending == Ending::failed) return Outcome::stopped;
  if (!std::isfinite(a.value) || !std::isfinite(b.value)) return Outcome::stopped;
  if (std::abs(a.value - b.value) <= a.band + b.band) return Outcome::undecided;
  return (side == Side::below ? a.value < b.value : a.value > b.value) ? Outcome::holds : Outcome::fails;
}

/// "a lies within [low, high]": both edges judged by the rule; fails when a lies beyond either edge by more than its
/// band, undecided when it lies within its band of an edge, stopped as judge says. An infinite edge is no edge (an
/// open range, "a > 10": judge would take an infinite threshold for a run that stopped).
inline Outcome judge_within(const Measured& a, double low, double high) {
  if (a.ending == Ending::stopped || !std::isfinite(a.value)) return Outcome::stopped;
  const Outcome above = std::isinf(low) ? Outcome::holds : judge(a, Side::above, {low, 0.0, Ending::done});
  const Outcome below = std::isinf(high) ? Outcome::holds : judge(a, Side::below, {high, 0.0, Ending::done});
  if (above == Outcome::stopped || below == Outcome::stopped) return Outcome::stopped;
  if (above == Outcome::fails || below == Outcome::fails) return Outcome::fails;
  if (above == Outcome::undecided || below == Outcome::undecided) return Outcome::undecided;
  return Outcome::holds;
}

/// A threshold: a fixed number, no band, no run behind it.
inline Measured threshold(double value) { return {value, 0.0, Ending::done}; }

/// The ratio a / b with its band to first order, \f$ \delta_r = |r| (\delta_a / |a| + \delta_b / |b|) \f$; stopped if
/// either stopped or both failed (judge's first branch: the ratio of two failed runs is not compared against any
/// bound), done if one failed (it is still compared, and loses).
inline Measured ratio(const Measured& a, const Measured& b) {
  Measured r{a.value / b.value, 0.0, Ending::done};
  r.band = std::abs(r.value) * (a.band / std::abs(a.value) + b.band / std::abs(b.value));
  const bool both_failed = a.ending == Ending::failed && b.ending == Ending::failed;
  if (a.ending == Ending::stopped || b.ending == Ending::stopped || both_failed) r.ending = Ending::stopped;
  return r;
}

/// The band of a score from the same score on two halves of the samples (even and odd rows): the larger move of
/// either half from the whole, \f$ \max(|s_e - s|, |s_o - s|) \f$.
inline double band_of_halves(double whole, double even, double odd) {
  return std::max(std::abs(even - whole), std::abs(odd - whole));
}

/// Every other value of `values`, from index `first` (0: the even rows or particles, 1: the odd ones): the halves a
/// score is taken on again for its band.
inline std::vector<double> every_other(const std::vector<double>& values, std::size_t first) {
  std::vector<double> some;
  for (std::size_t n = first; n < values.size(); n += 2) some.push_back(values[n]);
  return some;
}

/// A run's score fails when it is no smaller than a flat line's: the RMS about the exact history's mean,
/// \f$ \sqrt{\tfrac1N \sum_n (\hat v_n - \bar{\hat v})^2} \f$, what predicting the mean at every sample scores.
inline double flat_line_score(const std::vector<double>& exact) {
  if (exact.empty()) return 0.0;
  double mean = 0.0, sum = 0.0;
  for (double v : exact) mean += v / exact.size();
  for (double v : exact) sum += (v - mean) * (v - mean);
  return std::sqrt(sum / exact.size());
}

/// The ending of a run that finished with score `rms` against an exact history whose flat line scores `flat`. Where
/// the exact history is constant (flat 0) the rule does not apply: the flat line is then the exact history itself, and
/// a run's round-off would fail it; its RMS alone says how far it strays.
inline Ending score_ending(double rms, double flat) { return flat > 0.0 && rms >= flat ? Ending::failed : Ending::done; }

TEST_CASE("verdict rule: each branch by hand") {
  const Measured a{1.0, 0.1, Ending::done}, b{1.5, 0.1, Ending::done};
  CHECK(judge(a, Side::below, b) == Outcome::holds);
  CHECK(judge(a, Side::above, b) == Outcome::fails);
  CHECK(judge({1.0, 0.3, Ending::done}, Side::below, {1.5, 0.2, Ending::done}) == Outcome::undecided);  // 0.5 <= 0.5
  CHECK(judge({1.0, 0.3, Ending::done}, Side::below, {1.51, 0.2, Ending::done}) == Outcome::holds);
  CHECK(judge({1.0, 0.0, Ending::stopped}, Side::below, b) == Outcome::stopped);
  CHECK(judge({9.0, 0.0, Ending::failed}, Side::below, b) == Outcome::fails);   // a failed run beside a done one
  CHECK(judge({9.0, 0.0, Ending::failed}, Side::below, {1.0, 0.0, Ending::failed}) == Outcome::stopped);
  CHECK(judge({std::nan(""), 0.0, Ending::done}, Side::below, b) == Outcome::stopped);
  CHECK(judge(a, Side::below, threshold(1.0)) == Outcome::undecided);  // on the threshold within its band
  CHECK(std::string(outcome_name(Outcome::undecided)) == "undecided");
  CHECK(judge_within({1.0, 0.1, Ending::done}, 0.8, 1.3) == Outcome::holds);
  CHECK(judge_within({1.25, 0.1, Ending::done}, 0.8, 1.3) == Outcome::undecided);  // within its band of the upper edge
  CHECK(judge_within({1.5, 0.1, Ending::done}, 0.8, 1.3) == Outcome::fails);
  CHECK(judge_within({0.5, 0.1, Ending::done}, 0.8, 1.3) == Outcome::fails);
  CHECK(judge_within({1.0, 0.1, Ending::stopped}, 0.8, 1.3) == Outcome::stopped);
  CHECK(judge_within({12.0, 0.1, Ending::done}, 10.0, HUGE_VAL) == Outcome::holds);  // an open range: one edge
  CHECK(judge_within({9.0, 0.1, Ending::done}, 10.0, HUGE_VAL) == Outcome::fails);
  CHECK(judge_within({9.0, 0.1, Ending::done}, -HUGE_VAL, 10.0) == Outcome::holds);
  CHECK(judge_within({std::nan(""), 0.1, Ending::done}, 10.0, HUGE_VAL) == Outcome::stopped);
}

TEST_CASE("verdict rule: a ratio's band and ending, a band from halves, a flat line's score") {
  const Measured r = ratio({2.0, 0.2, Ending::done}, {4.0, 0.2, Ending::done});
  CHECK(r.value == doctest::Approx(0.5));
  CHECK(r.band == doctest::Approx(0.5 * (0.1 + 0.05)));
  CHECK(ratio({2.0, 0.0, Ending::failed}, {4.0, 0.0, Ending::done}).ending == Ending::done);
  CHECK(ratio({2.0, 0.0, Ending::failed}, {4.0, 0.0, Ending::failed}).ending == Ending::stopped);
  CHECK(judge(ratio({2.0, 0.0, Ending::failed}, {4.0, 0.0, Ending::failed}), Side::below, threshold(1.0)) == Outcome::stopped);
  CHECK(ratio({2.0, 0.0, Ending::done}, {4.0, 0.0, Ending::stopped}).ending == Ending::stopped);
  CHECK(band_of_halves(1.0, 1.1, 0.95) == doctest::Approx(0.1));
  CHECK(every_other({1.0, 2.0, 3.0, 4.0, 5.0}, 0) == std::vector<double>{1.0, 3.0, 5.0});
  CHECK(every_other({1.0, 2.0, 3.0, 4.0, 5.0}, 1) == std::vector<double>{2.0, 4.0});
  CHECK(flat_line_score({0.0, 1.0, 0.0, 1.0}) == doctest::Approx(0.5));  // a square wave of height 1
  CHECK(score_ending(0.5, 0.5) == Ending::failed);
  CHECK(score_ending(0.49, 0.5) == Ending::done);
  CHECK(score_ending(1e-15, 0.0) == Ending::done);  // a constant exact history: the rule does not apply
}

}  // namespace mpm
