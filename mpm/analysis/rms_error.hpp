/// \file
/// The error measure of the paper, Eq. (43), over the time samples of one observed particle, and beside it the ringing
/// measure of the report's oscillation claims and the amplitude measure of its damping claims.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "mpm/analysis/verdict.hpp"

namespace mpm {

/// Eq. (43): \f$ \mathrm{RMS} = \sqrt{\tfrac1N \sum_{n=1}^N (v_n - \hat v_n)^2} \f$, with N the number
/// of time samples of the velocity of the observed particle (paper/05_time_step_error_gravity.md, Eq. (43)) and \f$ \hat v \f$ the exact one.
inline double rms_error(const std::vector<double>& computed, const std::vector<double>& exact) {
  if (computed.size() != exact.size() || computed.empty()) throw std::invalid_argument("rms_error: sizes differ or are zero");
  double sum = 0.0;
  for (size_t n = 0; n < computed.size(); ++n) sum += (computed[n] - exact[n]) * (computed[n] - exact[n]);
  return std::sqrt(sum / computed.size());
}

TEST_CASE("Eq. (43): RMS error by hand") {
  CHECK(rms_error({1.0, 2.0, 3.0, 4.0}, {1.0, 2.0, 3.0, 4.0}) == 0.0);
  CHECK(rms_error({1.0, -1.0}, {0.0, 0.0}) == doctest::Approx(1.0));
  CHECK(rms_error({3.0, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 4.0}) == doctest::Approx(2.5));  // sqrt(25/4)
  CHECK_THROWS(rms_error({1.0}, {}));
}

/// The total variation of a history, \f$ \sum_n |v_{n+1} - v_n| \f$: the path its value travels (0 for fewer than two
/// samples). Ringing's numerator and denominator, each computed once where both are needed.
inline double total_variation(const std::vector<double>& values) {
  double variation = 0.0;
  for (size_t n = 1; n < values.size(); ++n) variation += std::abs(values[n] - values[n - 1]);
  return variation;
}

/// Ringing: the total variation of a history over the exact one's on the same time samples,
/// \f$ R = \sum_n |v_{n+1} - v_n| \,/\, \sum_n |\hat v_{n+1} - \hat v_n| \f$. A history that follows the exact
/// one's jumps and settles has R = 1 (a jump smeared over several samples, monotone, too); each overshoot of size
/// \f$ \delta \f$ that settles adds \f$ 2\delta \f$ to the numerator, and an oscillation twice its amplitude per
/// half-period. Damping lowers R: a jump that reaches only a fraction of its height counts that fraction, so R is
/// oscillation net of the amplitude lost, and the report gives the plateau deficit beside it. R also depends on the
/// sampling: a history sampled every step counts every small wiggle of a trailing wave that a coarser one misses, so
/// compare R of histories sampled alike. Not an equation of the paper: the yardstick of the report's oscillation
/// claims (paper/08_test_cases.md).
/// \throws std::invalid_argument when the sizes differ, or the exact history does not vary.
inline double total_variation_ratio(const std::vector<double>& computed, const std::vector<double>& exact) {
  if (computed.size() != exact.size() || computed.size() < 2)
    throw std::invalid_argument("total_variation_ratio: sizes differ or are below 2");
  const double exact_variation = total_variation(exact);
  if (!(exact_variation > 0.0)) throw std::invalid_argument("total_variation_ratio: the exact history is constant");
  return total_variation(computed) / exact_variation;
}

TEST_CASE("total_variation_ratio: one jump followed, overshot, rung, smoothed by hand") {
  const std::vector<double> exact{0.0, 0.0, 1.0, 1.0, 1.0, 1.0};                        // TV 1
  CHECK(total_variation_ratio(exact, exact) == 1.0);
  CHECK(total_variation_ratio({0.0, 0.0, 1.2, 1.0, 1.0, 1.0}, exact) == doctest::Approx(1.4));  // overshoot 0.2: + 2 x 0.2
  CHECK(total_variation_ratio({0.0, 0.0, 1.2, 0.8, 1.2, 0.8}, exact) == doctest::Approx(2.4));  // 1.2 + 0.4 + 0.4 + 0.4
  CHECK(total_variation_ratio({0.0, 0.0, 0.9, 0.9, 0.9, 0.9}, exact) == doctest::Approx(0.9));  // damped: below 1
  CHECK(total_variation_ratio({0.0, 0.5, 1.0, 1.0, 1.0, 1.0}, exact) == 1.0);  // the jump smeared, monotone: no ringing
  CHECK_THROWS(total_variation_ratio({1.0, 2.0}, {1.0, 1.0}));
  CHECK_THROWS(total_variation_ratio({1.0}, {1.0}));
  CHECK(total_variation({0.0, 2.0, -1.0, -1.0}) == 5.0);  // 2 + 3 + 0
  CHECK(total_variation({4.0}) == 0.0);
}

/// How far the round-off of a history's own size may move it, as a fraction of its largest |value|: an exact history
/// whose spread about its mean is no larger does not vary, and has no amplitude to compare against.
inline constexpr double flat_round_off = 1e-12;

/// Damping: the amplitude of a history against the exact one's on the same time samples, each the RMS about its own
/// mean (mpm::flat_line_score, what a flat line at the mean scores),
/// \f$ A = \sqrt{\sum_n (v_n - \bar v)^2} \,/\, \sqrt{\sum_n (\hat v_n - \bar{\hat v})^2} \f$. A = 1 at full
/// amplitude (a constant offset too: it moves the mean only), below 1 when the swings are damped (a square wave at
/// half its height: 0.5), above 1 when it rings or overshoots. Beside ringing, which damping lowers, it tells the two
/// apart: ringing above 1 with A near 1 is oscillation; ringing and A both below 1 is damping. NaN when `exact` is
/// empty or flat to round-off (spread at most flat_round_off of its largest |value|). Not an equation of the paper:
/// a yardstick for any code's history (mpm compare). \throws std::invalid_argument when the sizes differ.
inline double amplitude_ratio(const std::vector<double>& computed, const std::vector<double>& exact) {
  if (computed.size() != exact.size()) throw std::invalid_argument("amplitude_ratio: sizes differ");
  double largest = 0.0;
  for (double value : exact) largest = std::max(largest, std::abs(value));
  const double exact_spread = flat_line_score(exact);
  if (exact.empty() || !(exact_spread > flat_round_off * largest)) return std::nan("");
  return flat_line_score(computed) / exact_spread;
}

TEST_CASE("amplitude_ratio: full, offset, damped, overshooting and flat histories by hand") {
  const std::vector<double> square{0.0, 1.0, 0.0, 1.0, 0.0, 1.0};  // spread 0.5 about 0.5
  CHECK(amplitude_ratio(square, square) == 1.0);
  CHECK(amplitude_ratio({3.0, 4.0, 3.0, 4.0, 3.0, 4.0}, square) == doctest::Approx(1.0));           // offset 3
  CHECK(amplitude_ratio({0.25, 0.75, 0.25, 0.75, 0.25, 0.75}, square) == doctest::Approx(0.5));   // half height
  CHECK(amplitude_ratio({0.5, 0.5, 0.5, 0.5, 0.5, 0.5}, square) < 1e-15);  // damped out (round-off of the mean)
  CHECK(amplitude_ratio({-0.5, 1.5, -0.5, 1.5, -0.5, 1.5}, square) == doctest::Approx(2.0));      // twice the swing
  CHECK(std::isnan(amplitude_ratio({1.0, 2.0}, {5.0, 5.0})));                                     // exact flat
  CHECK(std::isnan(amplitude_ratio({1.0, 2.0}, {5.0, 5.0 + 1e-15})));                             // flat to round-off
  CHECK(std::isnan(amplitude_ratio({}, {})));
  CHECK_THROWS(amplitude_ratio({1.0}, {1.0, 2.0}));
}

/// The plateaus' deviations of a history against the exact one's, in units of the exact history's largest |value|.
struct PlateauDeviations {
  double overshoot = std::nan("");  ///< the largest step beyond the exact level, along the jump into the plateau
  double deficit = std::nan("");    ///< damping: the largest shortfall of the level, against that jump (>= 0)
};

/// Damping as the amplitude lost on the plateaus: a plateau is a run of at least `least_samples` samples on which the
/// exact history keeps one value, its direction the sign of the exact jump into it (the first plateau's: of its own
/// value; none where that is 0); on the middle half of each plateau (in time) the signed deviation
/// \f$ d_n = s\,(v_n - \hat v_n) / \max_m |\hat v_m| \f$ gives the overshoot \f$ \max d_n \f$ and the deficit
/// \f$ \max(-d_n) \f$, both at least 0. NaN where the exact history has no plateau with a direction (a smooth
/// history has none: its amplitude is amplitude_ratio's). Not an equation of the paper: the yardstick of the report's
/// damping claims (the Dyka bar's plateau deficit, paper/08_test_cases.md) for any code's history (mpm compare).
/// \throws std::invalid_argument when the sizes differ.
inline PlateauDeviations plateau_deviations(const std::vector<double>& time, const std::vector<double>& computed,
                                            const std::vector<double>& exact, std::size_t least_samples = 3) {
  if (computed.size() != exact.size() || time.size() != exact.size()) throw std::invalid_argument("plateau_deviations: sizes differ");
  double largest = 0.0;
  for (double value : exact) largest = std::max(largest, std::abs(value));
  PlateauDeviations result;
  if (!(largest > 0.0)) return result;
  for (std::size_t first = 0; first < exact.size();) {
    std::size_t last = first;
    while (last + 1 < exact.size() && exact[last + 1] == exact[first]) ++last;
    const double jump = first == 0 ? exact[first] : exact[first] - exact[first - 1];
    const double direction = last - first + 1 < least_samples ? 0.0 : jump > 0.0 ? 1.0 : jump < 0.0 ? -1.0 : 0.0;
    const double quarter = 0.25 * (time[last] - time[first]);
    for (std::size_t n = first; n <= last && direction != 0.0; ++n)
      if (time[n] >= time[first] + quarter && time[n] <= time[last] - quarter) {
        const double deviation = direction * (computed[n] - exact[n]) / largest;
        result.overshoot = std::isnan(result.overshoot) ? std::max(0.0, deviation) : std::max(result.overshoot, deviation);
        result.deficit = std::isnan(result.deficit) ? std::max(0.0, -deviation) : std::max(result.deficit, -deviation);
      }
    first = last + 1;
  }
  return result;
}

TEST_CASE("plateau_deviations: a jump overshot, a damped jump, a smooth history by hand") {
  const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7, 8}, exact{0, 0, 0, 2, 2, 2, 2, 2, 0};
  // the plateau 2 on t = 3..7: its middle half t = 4..6; the first plateau 0 has no direction (its own value is 0)
  const auto over = plateau_deviations(t, {0, 0, 0, 3, 2.5, 2.2, 2.1, 2, 0}, exact);
  CHECK(over.overshoot == doctest::Approx(0.25));  // 2.5 - 2 over the largest |exact| 2
  CHECK(over.deficit == 0.0);
  const auto damped = plateau_deviations(t, {0, 0, 0, 1, 1.5, 1.6, 1.5, 1, 0}, exact);
  CHECK(damped.deficit == doctest::Approx(0.25));  // 2 - 1.5
  CHECK(damped.overshoot == 0.0);
  const auto down = plateau_deviations({0, 1, 2, 3, 4}, {0, -1.5, -1.8, -1.9, 0}, {0, -2, -2, -2, -2});
  CHECK(down.deficit == doctest::Approx(0.1));  // along the jump down: -1.8 falls 0.2 short of -2
  // a half-way sample at a jump (exact 1 between 0 and 2) is no plateau: computed far from it there counts nothing
  CHECK(plateau_deviations({0, 1, 2, 3, 4, 5, 6, 7}, {0, 0, 0, 0.2, 2, 2, 2, 2}, {0, 0, 0, 1, 2, 2, 2, 2}).deficit == 0.0);
  CHECK(std::isnan(plateau_deviations({0, 1, 2}, {0, 1, 2}, {0, 1, 2}).deficit));  // no plateau
  CHECK(std::isnan(plateau_deviations({0, 1, 2}, {1, 1, 1}, {0, 0, 0}).deficit));  // the exact history is 0
  CHECK_THROWS(plateau_deviations({0, 1}, {0}, {0, 1}));
}

}  // namespace mpm
