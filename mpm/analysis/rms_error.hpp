/// \file
/// The error measure of the paper, Eq. (43), over the time samples of one observed particle, and the ringing measure
/// of the report's oscillation claims beside it.
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

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
  double variation = 0.0, exact_variation = 0.0;
  for (size_t n = 1; n < computed.size(); ++n) {
    variation += std::abs(computed[n] - computed[n - 1]);
    exact_variation += std::abs(exact[n] - exact[n - 1]);
  }
  if (!(exact_variation > 0.0)) throw std::invalid_argument("total_variation_ratio: the exact history is constant");
  return variation / exact_variation;
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
}

}  // namespace mpm
