/// \file
/// Body force per unit mass: gravity, ramped in time by Eq. (44).
#pragma once
#include <doctest/doctest.h>

#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

/// Eq. (44), the smooth gravity ramp over the first half of the period T:
/// \f[ \frac{g(t)}{g} = \begin{cases} \tfrac12\left(\sin(2\pi t/T - \pi/2) + 1\right) & t \le T/2 \\ 1 & t > T/2 \end{cases} \f]
/// T <= 0 means no ramp: full gravity from t = 0.
inline double gravity_ramp(double time, double ramp_period) {
  if (ramp_period <= 0.0 || time > 0.5 * ramp_period) return 1.0;
  constexpr double pi = 3.14159265358979323846;
  return 0.5 * (std::sin(2.0 * pi * time / ramp_period - 0.5 * pi) + 1.0);
}

template <int Dim>
struct Gravity {
  Vector<Dim> acceleration = Vector<Dim>::Zero();  ///< b at full strength, m/s^2
  double ramp_period = 0.0;                        ///< T of Eq. (44), s

  /// b(t), the body force per unit mass of Eq. (15).
  Vector<Dim> at(double time) const { return gravity_ramp(time, ramp_period) * acceleration; }
};

TEST_CASE("Eq. (44): gravity ramp: end values, midpoint, smooth start and end") {
  const double period = 20.0;
  CHECK(gravity_ramp(0.0, period) == doctest::Approx(0.0));
  CHECK(gravity_ramp(5.0, period) == doctest::Approx(0.5));   // t = T/4
  CHECK(gravity_ramp(10.0, period) == doctest::Approx(1.0));  // t = T/2
  CHECK(gravity_ramp(15.0, period) == 1.0);
  CHECK(gravity_ramp(2.5, period) == doctest::Approx(0.5 * (1.0 - std::cos(2.0 * 3.14159265358979 * 2.5 / 20.0))));
  const double dt = 1e-4;  // zero slope at both ends of the ramp: g' = O(dt) there
  CHECK(gravity_ramp(dt, period) / dt < 1e-3);
  CHECK((gravity_ramp(10.0, period) - gravity_ramp(10.0 - dt, period)) / dt < 1e-3);
  CHECK(gravity_ramp(0.0, 0.0) == 1.0);
}

}  // namespace mpm
