/// \file
/// Exact solution of the vibrating bar: a mode (the first by default) of a linear elastic bar free at X = 0 and
/// fixed at X = L, the smooth oracle of the smooth-data suite (verification/smooth_suite.cpp). It
/// shares no code with the solver.
///
/// The bar obeys the wave equation \f$ \rho\, u_{tt} = E\, u_{XX} \f$ in the reference coordinate X,
/// with \f$ \sigma(0, t) = E u_X(0, t) = 0 \f$ (free end) and \f$ u(L, t) = 0 \f$ (fixed end). Its mode n
/// has the wave number \f$ k = (2n - 1)\pi / (2L) \f$ and the angular frequency \f$ \omega = c k \f$,
/// \f$ c = \sqrt{E/\rho} \f$, so the period is \f$ T = 2\pi/\omega = 4L/((2n - 1)c) \f$ (4L/c for the first). Started from rest
/// (\f$ u = 0 \f$, \f$ \sigma = 0 \f$) with the velocity \f$ v(X, 0) = V \cos kX \f$:
/// \f[ u = \frac{V}{\omega} \cos kX \,\sin\omega t, \qquad v = V \cos kX \,\cos\omega t, \qquad
///     \sigma = -Z V \sin kX \,\sin\omega t, \f]
/// with the impedance \f$ Z = \rho c = E k / \omega \f$. The energy per unit area,
/// \f$ \int_0^L (\tfrac12\rho v^2 + \sigma^2/2E)\, dX = \rho V^2 L / 4 \f$, is constant.
///
/// This is small-strain (linear) elasticity: the solver's finite-strain behaviour at large
/// amplitude, \f$ \sigma = E \ln\lambda \f$, is matched by FiniteStrainBar (vibrating_bar_finite_strain.hpp).
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

namespace mpm::exact {

/// Mode n of the bar [0, L], free at X = 0, fixed at X = L, started with v = V cos((2n - 1) pi X / 2L).
class VibratingBar {
 public:
  /// length L (m), Young's modulus E (Pa), density rho (kg/m^3), velocity amplitude V (m/s), mode n >= 1.
  VibratingBar(double length, double young_modulus, double density, double velocity_amplitude, int mode = 1)
      : length_(length), young_modulus_(young_modulus), density_(density), amplitude_(velocity_amplitude), mode_(mode) {
    if (!(length_ > 0.0) || !(young_modulus_ > 0.0) || !(density_ > 0.0) || !std::isfinite(amplitude_) || mode_ < 1)
      throw std::invalid_argument("VibratingBar: length, Young's modulus and density must be positive, V finite, mode >= 1");
  }

  double length() const { return length_; }
  double velocity_amplitude() const { return amplitude_; }
  /// \f$ c = \sqrt{E/\rho} \f$
  double wave_speed() const { return std::sqrt(young_modulus_ / density_); }
  int mode() const { return mode_; }
  /// \f$ k = (2n - 1)\pi / (2L) \f$
  double wave_number() const { return (2.0 * mode_ - 1.0) * 0.5 * pi / length_; }
  /// \f$ \omega = c k \f$
  double angular_frequency() const { return wave_speed() * wave_number(); }
  /// \f$ T = 2\pi/\omega = 4L/((2n - 1)c) \f$
  double period() const { return 4.0 * length_ / ((2.0 * mode_ - 1.0) * wave_speed()); }
  /// \f$ Z = \rho c \f$: the stress amplitude is Z V.
  double impedance() const { return density_ * wave_speed(); }
  /// \f$ U = V/\omega \f$, the largest displacement (at the free end).
  double displacement_amplitude() const { return amplitude_ / angular_frequency(); }
  /// \f$ \rho V^2 L / 4 \f$, the kinetic plus strain energy per unit area, J/m^2 (any mode: \f$ \sin 2kL = 0 \f$).
  double energy() const { return 0.25 * density_ * amplitude_ * amplitude_ * length_; }

  /// \f$ u(X, t) = (V/\omega) \cos kX \sin\omega t \f$, m.
  double displacement(double reference_position, double time) const {
    return displacement_amplitude() * std::cos(wave_number() * checked(reference_position)) * std::sin(angular_frequency() * time);
  }
  /// \f$ v(X, t) = V \cos kX \cos\omega t \f$, m/s.
  double velocity(double reference_position, double time) const {
    return amplitude_ * std::cos(wave_number() * checked(reference_position)) * std::cos(angular_frequency() * time);
  }
  /// \f$ \sigma(X, t) = -Z V \sin kX \sin\omega t \f$, Pa (tension positive).
  double stress(double reference_position, double time) const {
    return -impedance() * amplitude_ * std::sin(wave_number() * checked(reference_position)) * std::sin(angular_frequency() * time);
  }

 private:
  static constexpr double pi = 3.14159265358979323846;
  double length_, young_modulus_, density_, amplitude_;
  int mode_;

  double checked(double x) const {
    if (!(x >= -1e-12 * length_ && x <= length_ * (1.0 + 1e-12)))
      throw std::domain_error("VibratingBar: X lies outside the bar [0, L]");
    return x;
  }
};

// Steel as in the Dyka bar: L = 0.1333 m, E = 200 GPa, rho = 7833 kg/m^3, V = 5 m/s. The expected
// values are derived by hand from the closed forms in the file comment, or are differences of the
// displacement (finite differences), never the formula under test read back.

TEST_CASE("exact::VibratingBar: period, amplitudes and values derived by hand") {
  const VibratingBar bar(0.1333, 200e9, 7833.0, 5.0);
  const double c = std::sqrt(200e9 / 7833.0);  // 5053.019 m/s
  CHECK(bar.wave_speed() == doctest::Approx(5053.019).epsilon(1e-6));
  CHECK(bar.period() == doctest::Approx(4.0 * 0.1333 / c).epsilon(1e-14));
  CHECK(bar.period() == doctest::Approx(1.05521e-4).epsilon(1e-5));
  CHECK(bar.impedance() == doctest::Approx(std::sqrt(200e9 * 7833.0)).epsilon(1e-14));
  // At X = L/3, t = T/8: kX = pi/6, omega t = pi/4, so v = V (sqrt 3 / 2)(sqrt 2 / 2) = V sqrt(6)/4,
  // sigma = -Z V (1/2)(sqrt 2 / 2), u = (V/omega)(sqrt 3 / 2)(sqrt 2 / 2) with V/omega = 2 L V / (c pi).
  const double X = 0.1333 / 3.0, t = bar.period() / 8.0, Z = bar.impedance();
  CHECK(bar.velocity(X, t) == doctest::Approx(5.0 * std::sqrt(6.0) / 4.0).epsilon(1e-12).scale(0.0));
  CHECK(bar.stress(X, t) == doctest::Approx(-Z * 5.0 * std::sqrt(2.0) / 4.0).epsilon(1e-12));
  CHECK(bar.displacement(X, t) == doctest::Approx(5.0 * 2.0 * 0.1333 / (c * 3.14159265358979) * std::sqrt(6.0) / 4.0).epsilon(1e-12).scale(0.0));
  // The initial data: v = V cos(pi X / 2L), no stress, no displacement; half a period later v = -V cos kX.
  CHECK(bar.velocity(0.0, 0.0) == 5.0);
  CHECK(bar.stress(0.05, 0.0) == 0.0);
  CHECK(bar.displacement(0.05, 0.0) == 0.0);
  CHECK(bar.velocity(0.0, 0.5 * bar.period()) == doctest::Approx(-5.0).epsilon(1e-14));
  CHECK_THROWS_AS(bar.velocity(0.2, 0.0), std::domain_error);
  CHECK_THROWS_AS(VibratingBar(0.1333, -1.0, 7833.0, 5.0), std::invalid_argument);
}

TEST_CASE("exact::VibratingBar: the second mode, by hand") {
  // n = 2: k = 3 pi / (2L), omega = 3 pi c / (2L), T = 4L / (3c). At X = L/9, t = T/8: kX = pi/6, omega t = pi/4,
  // v = V (sqrt 3 / 2)(sqrt 2 / 2); at X = L/3 (kX = pi/2, a node of v), sigma = -Z V sin(pi/4) at t = T/8.
  const double L = 0.1333, c = std::sqrt(200e9 / 7833.0);
  const VibratingBar bar(L, 200e9, 7833.0, 5.0, 2);
  CHECK(bar.period() == doctest::Approx(4.0 * L / (3.0 * c)).epsilon(1e-14));
  const double t = bar.period() / 8.0;
  CHECK(bar.velocity(L / 9.0, t) == doctest::Approx(5.0 * std::sqrt(6.0) / 4.0).epsilon(1e-12));
  CHECK(std::abs(bar.velocity(L / 3.0, t)) <= 1e-12 * 5.0);
  CHECK(bar.stress(L / 3.0, t) == doctest::Approx(-bar.impedance() * 5.0 * std::sqrt(0.5)).epsilon(1e-12));
  CHECK(std::abs(bar.velocity(L, t)) <= 1e-12 * 5.0);  // still fixed at X = L: cos(3 pi / 2) = 0
  CHECK_THROWS_AS(VibratingBar(L, 200e9, 7833.0, 5.0, 0), std::invalid_argument);
}

TEST_CASE("exact::VibratingBar: wave equation, v = u_t and sigma = E u_X by finite differences, free and fixed ends") {
  const double E = 200e9, rho = 7833.0, L = 0.1333;
  const VibratingBar bar(L, E, rho, 5.0);
  const double T = bar.period(), dX = 1e-4 * L, dt = 1e-4 * T;
  for (double X : {0.1 * L, 0.37 * L, 0.8 * L})
    for (double t : {0.13 * T, 0.61 * T}) {
      const double u_tt = (bar.displacement(X, t + dt) - 2.0 * bar.displacement(X, t) + bar.displacement(X, t - dt)) / (dt * dt);
      const double u_XX = (bar.displacement(X + dX, t) - 2.0 * bar.displacement(X, t) + bar.displacement(X - dX, t)) / (dX * dX);
      CHECK(rho * u_tt == doctest::Approx(E * u_XX).epsilon(1e-5));
      const double u_t = (bar.displacement(X, t + dt) - bar.displacement(X, t - dt)) / (2.0 * dt);
      const double u_X = (bar.displacement(X + dX, t) - bar.displacement(X - dX, t)) / (2.0 * dX);
      CHECK(bar.velocity(X, t) == doctest::Approx(u_t).epsilon(1e-6));
      CHECK(bar.stress(X, t) == doctest::Approx(E * u_X).epsilon(1e-6));
    }
  for (double t : {0.1 * T, 0.3 * T, 0.77 * T}) {
    CHECK(std::abs(bar.stress(0.0, t)) <= 1e-12 * bar.impedance() * 5.0);  // free end
    CHECK(std::abs(bar.velocity(L, t)) <= 1e-12 * 5.0);                    // fixed end
    CHECK(std::abs(bar.displacement(L, t)) <= 1e-12 * bar.displacement_amplitude());
  }
}

TEST_CASE("exact::VibratingBar: kinetic plus strain energy is rho V^2 L / 4 at every time (Simpson's rule)") {
  const double E = 200e9, rho = 7833.0, L = 0.1333;
  const VibratingBar bar(L, E, rho, 5.0);
  CHECK(bar.energy() == doctest::Approx(7833.0 * 25.0 * 0.1333 / 4.0).epsilon(1e-14));
  const int intervals = 200;  // even
  for (double t : {0.0, 0.1 * bar.period(), 0.25 * bar.period(), 0.7 * bar.period()}) {
    double energy = 0.0;
    for (int i = 0; i <= intervals; ++i) {
      const double X = L * i / intervals, weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      const double v = bar.velocity(X, t), s = bar.stress(X, t);
      energy += weight * (0.5 * rho * v * v + 0.5 * s * s / E);
    }
    energy *= L / intervals / 3.0;
    CHECK(energy == doctest::Approx(bar.energy()).epsilon(1e-9));
  }
}

}  // namespace mpm::exact
