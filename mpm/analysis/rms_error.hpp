/// \file
/// The error measure of the paper, Eq. (43), over the time samples of one observed particle.
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

}  // namespace mpm
