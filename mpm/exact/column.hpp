/// \file
/// Exact solution of the 1D soil column under self-weight with the gravity ramp of Eq. (44)
/// (paper/07_exact_column.md): the oracle of the soil-block test. It shares no code with the solver.
///
/// Method. The column \f$ 0 \le y \le H \f$ (base fixed, top free, displacement u positive upward)
/// obeys \f$ \rho u_{tt} = M u_{yy} - \rho g(t) \f$ from rest. Its modes are \f$ \sin(k_n y) \f$ with
/// \f$ k_n = (2n-1)\pi/(2H) \f$ and \f$ \omega_n = c k_n \f$; expanding the uniform load in them gives
/// \f$ u = \sum_n q_n(t) \sin(k_n y) \f$, \f$ q_n = -\frac{2}{H k_n} Y_n \f$, where each \f$ Y_n \f$ is a
/// forced oscillator \f$ \ddot Y + \omega_n^2 Y = g(t) \f$ solved in closed form (Duhamel, below).
/// The series is summed in "mode-acceleration" form: the quasi-static part
/// \f$ Y_n \approx g(t)/\omega_n^2 \f$ of every mode is summed exactly (it is the static solution scaled
/// by \f$ g(t)/g \f$) and only the remainder \f$ Y_n - g(t)/\omega_n^2 \f$ goes through the truncated series.
/// For the smooth ramp that remainder decays like \f$ n^{-4} \f$, so 200 modes give the base stress to
/// about 1e-7 relative, where the plain series (terms \f$ \sim n^{-2} \f$) would still be off by 1e-3.
/// The plain truncated series is also provided (modal_sum_*) for comparison.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm::exact {

/// 1D soil column: base y = 0 fixed, top y = H free, self-weight ramped by Eq. (44).
class SoilColumn {
 public:
  /// base y=0 fixed, top y=H free; constrained_modulus M (E for nu=0); gravity magnitude g>0 acting downward,
  /// ramped by eq (44) with period T (T<=0: constant gravity from t=0); modes = number of series terms.
  SoilColumn(double height, double constrained_modulus, double density, double gravity, double ramp_period,
             int modes = 200)
      : height_(height),
        constrained_modulus_(constrained_modulus),
        density_(density),
        gravity_(gravity),
        ramp_period_(ramp_period),
        modes_(modes) {
    if (!(height_ > 0.0) || !(constrained_modulus_ > 0.0) || !(density_ > 0.0) || !(gravity_ > 0.0) ||
        !std::isfinite(ramp_period_))
      throw std::invalid_argument("SoilColumn: height, modulus, density and gravity must be positive");
    if (modes_ < 1) throw std::invalid_argument("SoilColumn: at least one mode is needed");
  }

  /// paper/07_exact_column.md: \f$ c = \sqrt{M/\rho} \f$, the speed of compression waves in the column.
  double wave_speed() const { return std::sqrt(constrained_modulus_ / density_); }

  /// Eq. (44): \f$ g(t) = \tfrac12 g \left(\sin(2\pi t/T - \pi/2) + 1\right) \f$ for \f$ 0 \le t \le T/2 \f$,
  /// \f$ g(t) = g \f$ for \f$ t > T/2 \f$. No load before t = 0. For \f$ T \le 0 \f$, \f$ g(t) = g \f$ from t = 0.
  double gravity_at(double time) const {
    if (time < 0.0) return 0.0;
    if (ramp_period_ <= 0.0 || time > 0.5 * ramp_period_) return gravity_;
    return 0.5 * gravity_ * (std::sin(2.0 * pi * time / ramp_period_ - 0.5 * pi) + 1.0);
  }

  /// paper/07_exact_column.md, static solution: \f$ u(y) = -\frac{\rho g}{M}\left(H y - \frac{y^2}{2}\right) \f$ (upward positive).
  double static_displacement(double y) const {
    const double height_coordinate = checked_height(y);
    return -(density_ * gravity_ / constrained_modulus_) *
           (height_ * height_coordinate - 0.5 * height_coordinate * height_coordinate);
  }

  /// paper/07_exact_column.md, static solution: \f$ \sigma_{yy}(y) = -\rho g (H - y) \f$ (tension positive).
  double static_stress(double y) const { return -density_ * gravity_ * (height_ - checked_height(y)); }

  /// paper/07_exact_column.md: \f$ u(y,t) = \sum_n q_n(t) \sin(k_n y) \f$, summed in mode-acceleration form
  /// \f[ u(y,t) = \frac{g(t)}{g}\, u_{\mathrm{static}}(y)
  ///     - \sum_{n=1}^{N} \frac{2}{H k_n} \left( Y_n(t) - \frac{g(t)}{\omega_n^2} \right) \sin(k_n y), \f]
  /// which is the same series, because \f$ -\sum_n \frac{2 g}{H k_n \omega_n^2} \sin(k_n y) = u_{\mathrm{static}}(y) \f$.
  double displacement(double y, double time) const {
    const double height_coordinate = checked_height(y);
    const double load = gravity_at(time);
    double dynamic_part = 0.0;
    for (int n = 1; n <= modes_; ++n) {
      const double omega = angular_frequency(n), wavenumber_n = wavenumber(n);
      dynamic_part += -(2.0 / (height_ * wavenumber_n)) * (modal_response(n, time) - load / (omega * omega)) *
                      std::sin(wavenumber_n * height_coordinate);
    }
    return (load / gravity_) * static_displacement(height_coordinate) + dynamic_part;
  }

  /// The time derivative of Eq. (44), \f$ \dot g(t) = \tfrac12 g\,\Omega \sin\Omega t \f$ for \f$ 0 < t < T/2 \f$
  /// (\f$ \Omega = 2\pi/T \f$), 0 otherwise.
  double gravity_rate(double time) const {
    if (time <= 0.0 || ramp_period_ <= 0.0 || time >= 0.5 * ramp_period_) return 0.0;
    const double Omega = 2.0 * pi / ramp_period_;
    return 0.5 * gravity_ * Omega * std::sin(Omega * time);
  }

  /// paper/07_exact_column.md: the velocity \f$ v = \partial u/\partial t \f$ of the mode-acceleration sum above,
  /// \f[ v(y,t) = \frac{\dot g(t)}{g}\, u_{\mathrm{static}}(y)
  ///     - \sum_{n=1}^{N} \frac{2}{H k_n} \left( \dot Y_n(t) - \frac{\dot g(t)}{\omega_n^2} \right) \sin(k_n y). \f]
  double velocity(double y, double time) const {
    const double height_coordinate = checked_height(y);
    const double load_rate = gravity_rate(time);
    double dynamic_part = 0.0;
    for (int n = 1; n <= modes_; ++n) {
      const double omega = angular_frequency(n), wavenumber_n = wavenumber(n);
      dynamic_part += -(2.0 / (height_ * wavenumber_n)) * (modal_response_rate(n, time) - load_rate / (omega * omega)) *
                      std::sin(wavenumber_n * height_coordinate);
    }
    return (load_rate / gravity_) * static_displacement(height_coordinate) + dynamic_part;
  }

  /// paper/07_exact_column.md: \f$ \sigma_{yy}(y,t) = M \sum_n q_n(t)\, k_n \cos(k_n y) \f$, in mode-acceleration form
  /// \f[ \sigma_{yy}(y,t) = \frac{g(t)}{g}\, \sigma_{\mathrm{static}}(y)
  ///     - \frac{2M}{H} \sum_{n=1}^{N} \left( Y_n(t) - \frac{g(t)}{\omega_n^2} \right) \cos(k_n y). \f]
  double stress(double y, double time) const {
    const double height_coordinate = checked_height(y);
    const double load = gravity_at(time);
    double dynamic_part = 0.0;
    for (int n = 1; n <= modes_; ++n) {
      const double omega = angular_frequency(n);
      dynamic_part += -(2.0 * constrained_modulus_ / height_) * (modal_response(n, time) - load / (omega * omega)) *
                      std::cos(wavenumber(n) * height_coordinate);
    }
    return (load / gravity_) * static_stress(height_coordinate) + dynamic_part;
  }

  /// paper/07_exact_column.md: the wavenumber of mode n (n = 1, 2, ...), \f$ k_n = \frac{(2n-1)\pi}{2H} \f$,
  /// so that \f$ \sin(k_n y) \f$ vanishes at the base and has zero slope (zero stress) at the top.
  double wavenumber(int n) const { return (2.0 * n - 1.0) * pi / (2.0 * height_); }

  /// paper/07_exact_column.md: \f$ \omega_n = c\, k_n \f$.
  double angular_frequency(int n) const { return wave_speed() * wavenumber(n); }

  /// paper/07_exact_column.md: the modal response \f$ Y_n(t) \f$, solution of \f$ \ddot Y + \omega_n^2 Y = g(t) \f$,
  /// \f$ Y(0) = \dot Y(0) = 0 \f$. With \f$ \Omega = 2\pi/T \f$ and \f$ g(t) = \tfrac12 g (1 - \cos\Omega t) \f$:
  /// \f[ Y(t) = \frac{g}{2}\left[\frac{1 - \cos\omega t}{\omega^2} - \frac{\cos\Omega t - \cos\omega t}{\omega^2 - \Omega^2}\right],
  ///     \quad t \le T/2, \f]
  /// \f[ Y(t) = \frac{g}{\omega^2} + \left(Y(\tfrac T2) - \frac{g}{\omega^2}\right)\cos\omega(t - \tfrac T2)
  ///     + \frac{\dot Y(\tfrac T2)}{\omega} \sin\omega(t - \tfrac T2), \quad t > T/2, \f]
  /// and, for constant gravity (\f$ T \le 0 \f$), \f$ Y(t) = g (1 - \cos\omega t)/\omega^2 \f$. Zero for t <= 0.
  double modal_response(int n, double time) const {
    if (time <= 0.0) return 0.0;
    const double omega = angular_frequency(n);
    if (ramp_period_ <= 0.0) return gravity_ * one_minus_cos_over_square(omega, time);
    const double ramp_end = 0.5 * ramp_period_;
    if (time <= ramp_end) return ramp_response(omega, time);
    return free_vibration_after_ramp(omega, time - ramp_end, ramp_response(omega, ramp_end),
                                     ramp_response_rate(omega, ramp_end));
  }

  /// paper/07_exact_column.md: \f$ \dot Y_n(t) \f$, the time derivative of modal_response:
  /// \f$ \dot Y = \frac{g}{2}\left[\frac{\sin\omega t}{\omega} + \frac{\Omega\sin\Omega t - \omega\sin\omega t}{\omega^2 - \Omega^2}\right] \f$
  /// for \f$ t \le T/2 \f$, the derivative of the free vibration after it, \f$ g \sin(\omega t)/\omega \f$ for \f$ T \le 0 \f$.
  double modal_response_rate(int n, double time) const {
    if (time <= 0.0) return 0.0;
    const double omega = angular_frequency(n);
    if (ramp_period_ <= 0.0) return gravity_ * std::sin(omega * time) / omega;
    const double ramp_end = 0.5 * ramp_period_;
    if (time <= ramp_end) return ramp_response_rate(omega, time);
    const double after = time - ramp_end;
    const double start_value = ramp_response(omega, ramp_end), start_rate = ramp_response_rate(omega, ramp_end);
    const double static_value = gravity_ / (omega * omega);
    return -omega * (start_value - static_value) * std::sin(omega * after) + start_rate * std::cos(omega * after);
  }

  /// paper/07_exact_column.md, static check: the static solution as the modal series,
  /// \f$ \sum_{n=1}^{N} -\frac{2 g}{H c^2 k_n^3} \sin(k_n y) \;\to\; -\frac{g}{c^2}\left(H y - \frac{y^2}{2}\right) \f$.
  double modal_static_displacement(double y) const {
    const double height_coordinate = checked_height(y), c = wave_speed();
    double sum = 0.0;
    for (int n = 1; n <= modes_; ++n) {
      const double wavenumber_n = wavenumber(n);
      sum += -2.0 * gravity_ / (height_ * c * c * wavenumber_n * wavenumber_n * wavenumber_n) *
             std::sin(wavenumber_n * height_coordinate);
    }
    return sum;
  }

  /// paper/07_exact_column.md, the plain truncated series \f$ u = \sum_{n=1}^{N} q_n(t)\sin(k_n y) \f$,
  /// \f$ q_n = -\frac{2}{H k_n} Y_n(t) \f$, with N = terms (no mode acceleration).
  double modal_sum_displacement(double y, double time, int terms) const {
    const double height_coordinate = checked_height(y);
    double sum = 0.0;
    for (int n = 1; n <= terms; ++n)
      sum += modal_amplitude(n, time) * std::sin(wavenumber(n) * height_coordinate);
    return sum;
  }

  /// paper/07_exact_column.md, the plain truncated series \f$ \sigma_{yy} = M \sum_{n=1}^{N} q_n(t)\, k_n \cos(k_n y) \f$, N = terms.
  double modal_sum_stress(double y, double time, int terms) const {
    const double height_coordinate = checked_height(y);
    double sum = 0.0;
    for (int n = 1; n <= terms; ++n)
      sum += modal_amplitude(n, time) * wavenumber(n) * std::cos(wavenumber(n) * height_coordinate);
    return constrained_modulus_ * sum;
  }

 private:
  static constexpr double pi = 3.14159265358979323846;

  double height_;
  double constrained_modulus_;
  double density_;
  double gravity_;
  double ramp_period_;
  int modes_;

  double checked_height(double y) const {
    const double tolerance = 1e-12 * height_;
    if (!(y >= -tolerance && y <= height_ + tolerance))
      throw std::domain_error("SoilColumn: height " + std::to_string(y) + " m lies outside the column [0, " +
                              std::to_string(height_) + "] m");
    return std::min(std::max(y, 0.0), height_);
  }

  /// paper/07_exact_column.md: \f$ q_n(t) = -\frac{2}{H k_n} Y_n(t) \f$, the projection of the uniform load on mode n.
  double modal_amplitude(int n, double time) const {
    return -(2.0 / (height_ * wavenumber(n))) * modal_response(n, time);
  }

  /// \f$ \operatorname{sinc} x = \sin x / x \f$, with its Taylor series \f$ 1 - x^2/6 \f$ near 0.
  static double sinc(double x) {
    if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
    return std::sin(x) / x;
  }

  /// \f$ (1 - \cos\omega t)/\omega^2 = 2\sin^2(\omega t/2)/\omega^2 \f$, free of cancellation at small \f$ \omega t \f$.
  static double one_minus_cos_over_square(double omega, double time) {
    const double half_sine = std::sin(0.5 * omega * time);
    return 2.0 * half_sine * half_sine / (omega * omega);
  }

  /// The resonant quotient \f$ h(t) = \frac{\cos\Omega t - \cos\omega t}{\omega^2 - \Omega^2} \f$ in product form,
  /// \f$ h = \frac{2}{\omega + \Omega} \sin\frac{(\omega+\Omega)t}{2} \cdot \frac{t}{2}\operatorname{sinc}\frac{(\omega-\Omega)t}{2} \f$.
  /// The product form is exact for every \f$ \omega \f$ and continuous through resonance \f$ \omega = \Omega \f$,
  /// where it becomes the limit \f$ h = t \sin(\Omega t)/(2\Omega) \f$; no perturbation is needed.
  double resonant_quotient(double omega, double time) const {
    const double ramp_frequency = 2.0 * pi / ramp_period_;
    const double sum = omega + ramp_frequency, difference = omega - ramp_frequency;
    return (2.0 / sum) * std::sin(0.5 * sum * time) * 0.5 * time * sinc(0.5 * difference * time);
  }

  /// \f$ \dot h(t) = \frac{t}{2}\cos\frac{(\omega+\Omega)t}{2}\operatorname{sinc}\frac{(\omega-\Omega)t}{2}
  ///     + \frac{1}{\omega+\Omega}\sin\frac{(\omega+\Omega)t}{2}\cos\frac{(\omega-\Omega)t}{2} \f$,
  /// the time derivative of resonant_quotient, also continuous through resonance.
  double resonant_quotient_rate(double omega, double time) const {
    const double ramp_frequency = 2.0 * pi / ramp_period_;
    const double sum = omega + ramp_frequency, difference = omega - ramp_frequency;
    return 0.5 * time * std::cos(0.5 * sum * time) * sinc(0.5 * difference * time) +
           std::sin(0.5 * sum * time) * std::cos(0.5 * difference * time) / sum;
  }

  /// paper/07_exact_column.md, during the ramp: \f$ Y(t) = \frac{g}{2}\left[\frac{1 - \cos\omega t}{\omega^2} - h(t)\right] \f$.
  double ramp_response(double omega, double time) const {
    return 0.5 * gravity_ * (one_minus_cos_over_square(omega, time) - resonant_quotient(omega, time));
  }

  /// paper/07_exact_column.md, during the ramp: \f$ \dot Y(t) = \frac{g}{2}\left[\frac{\sin\omega t}{\omega} - \dot h(t)\right] \f$.
  double ramp_response_rate(double omega, double time) const {
    return 0.5 * gravity_ * (std::sin(omega * time) / omega - resonant_quotient_rate(omega, time));
  }

  /// paper/07_exact_column.md, after the ramp (constant g): oscillation about \f$ g/\omega^2 \f$ started from the end-of-ramp state,
  /// \f$ Y = \frac{g}{\omega^2} + \left(Y_e - \frac{g}{\omega^2}\right)\cos\omega s + \frac{\dot Y_e}{\omega}\sin\omega s \f$,
  /// \f$ s = t - T/2 \f$.
  double free_vibration_after_ramp(double omega, double after, double start_value, double start_rate) const {
    const double static_value = gravity_ / (omega * omega);
    return static_value + (start_value - static_value) * std::cos(omega * after) +
           (start_rate / omega) * std::sin(omega * after);
  }
};

// ---------------------------------------------------------------------------------------------------
// Tests. Every expected value below is derived by hand in the comments or printed in paper/07_exact_column.md,
// never produced by the code under test. Soil block of paper/08_test_cases.md: E = M = 5 MPa (nu = 0), rho = 6000,
// H = 10 m, g = 9.81, T = 20 s.
// ---------------------------------------------------------------------------------------------------

TEST_CASE("exact::SoilColumn: closed-form static solution and wave speed (paper/07_exact_column.md)") {
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0);
  // c = sqrt(5e6 / 6000) = 28.8675 m/s, T1 = 4H/c = 1.3856 s.
  CHECK(column.wave_speed() == doctest::Approx(28.8675).epsilon(1e-5));
  CHECK(4.0 * 10.0 / column.wave_speed() == doctest::Approx(1.386).epsilon(1e-3));
  // rho g H^2 / (2M) = 6000 * 9.81 * 100 / 1e7 = 0.5886 m.
  CHECK(column.static_displacement(10.0) == doctest::Approx(-0.58860).epsilon(1e-12));
  CHECK(column.static_displacement(0.0) == 0.0);
  CHECK(column.static_displacement(9.57735) == doctest::Approx(-0.58755).epsilon(1e-5));  // paper/07_exact_column.md
  // rho g H = 588.6 kPa at the base, 0 at the top, half-way: rho g H / 2.
  CHECK(column.static_stress(0.0) == doctest::Approx(-588600.0).epsilon(1e-12));
  CHECK(column.static_stress(10.0) == 0.0);
  CHECK(column.static_stress(5.0) == doctest::Approx(-294300.0).epsilon(1e-12));
  CHECK_THROWS_AS(column.displacement(10.5, 1.0), std::domain_error);
  CHECK_THROWS_AS(SoilColumn(10.0, 5e6, 6000.0, -9.81, 20.0), std::invalid_argument);
  CHECK_THROWS_AS(SoilColumn(10.0, 5e6, 6000.0, 9.81, 20.0, 0), std::invalid_argument);
}

TEST_CASE("Eq. (44): exact::SoilColumn: its gravity ramp") {
  const double g = 9.81, period = 20.0;
  const SoilColumn column(10.0, 5e6, 6000.0, g, period);
  CHECK(column.gravity_at(0.0) == doctest::Approx(0.0).scale(1e-14));      // sin(-pi/2) + 1 = 0
  CHECK(column.gravity_at(period / 4.0) == doctest::Approx(g / 2.0));        // sin(0) + 1 = 1
  CHECK(column.gravity_at(period / 2.0) == doctest::Approx(g));              // sin(pi/2) + 1 = 2
  CHECK(column.gravity_at(period / 8.0) == doctest::Approx(0.5 * g * (1.0 - std::sqrt(0.5))));  // 1 - cos(pi/4)
  CHECK(column.gravity_at(0.75 * period) == g);
  CHECK(column.gravity_at(100.0) == g);
  CHECK(column.gravity_at(-1.0) == 0.0);
  // Zero slope at both ends (largest slope in between: g pi / T): one-sided differences are O(step).
  const double step = 1e-4 * period, largest_slope = g * 3.14159265358979 / period;
  CHECK(std::abs((column.gravity_at(step) - column.gravity_at(0.0)) / step) < 1e-3 * largest_slope);
  CHECK(std::abs((column.gravity_at(period / 2.0) - column.gravity_at(period / 2.0 - step)) / step) <
        1e-3 * largest_slope);
  CHECK((column.gravity_at(period / 2.0 + step) - column.gravity_at(period / 2.0)) / step == doctest::Approx(0.0));
  // The steepest point is the middle of the ramp, slope g pi / T.
  CHECK((column.gravity_at(period / 4.0 + step) - column.gravity_at(period / 4.0 - step)) / (2.0 * step) ==
        doctest::Approx(largest_slope).epsilon(1e-6));
  const SoilColumn constant(10.0, 5e6, 6000.0, g, 0.0);  // T <= 0: full gravity from t = 0
  CHECK(constant.gravity_at(0.0) == g);
  CHECK(constant.gravity_at(3.0) == g);
}

TEST_CASE("exact::SoilColumn: the modal series of the static solution is the closed form (paper/07_exact_column.md)") {
  // sum_n -2g/(H c^2 k_n^3) sin(k_n y) = -(g/c^2)(H y - y^2/2); terms ~ n^-3, so 2000 terms reach 1e-6 relative.
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0, 2000);
  for (double y : {0.5, 1.0, 2.0, 3.7, 5.0, 7.5, 9.0, 9.57735, 10.0}) {
    INFO("y = " << y);
    const double closed_form = -(6000.0 * 9.81 / 5e6) * (10.0 * y - 0.5 * y * y);
    CHECK(column.modal_static_displacement(y) == doctest::Approx(closed_form).epsilon(1e-6));
  }
}

TEST_CASE("exact::SoilColumn: after the ramp the solution oscillates about the static one") {
  // For t > T/2 every Y_n oscillates about g/omega_n^2 with a period dividing T1 = 4H/c (omega_n = (2n-1) omega_1),
  // so the mean over one T1 is the static solution. 4000 equally spaced samples integrate every mode up to
  // n = 200 (frequency 399/T1) exactly.
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0);
  const double first_period = 4.0 * 10.0 / column.wave_speed();
  const int samples = 4000;
  for (double y : {2.5, 5.0, 9.57735, 10.0}) {
    double mean_displacement = 0.0, mean_stress = 0.0;
    for (int i = 0; i < samples; ++i) {
      const double time = 12.0 + first_period * i / samples;
      mean_displacement += column.displacement(y, time) / samples;
      mean_stress += column.stress(y, time) / samples;
    }
    const double closed_displacement = -(6000.0 * 9.81 / 5e6) * (10.0 * y - 0.5 * y * y);
    const double closed_stress = -6000.0 * 9.81 * (10.0 - y);
    INFO("y = " << y);
    CHECK(mean_displacement == doctest::Approx(closed_displacement).epsilon(1e-6));
    CHECK(mean_stress == doctest::Approx(closed_stress).epsilon(1e-6));
  }
}

TEST_CASE("exact::SoilColumn: values of the table in paper/07_exact_column.md") {
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0);
  struct Row { double time, top_displacement; };
  const std::vector<Row> top{{2.5, -0.0857}, {5.0, -0.2932}, {7.5, -0.5022}, {10.0, -0.5904},
                             {12.5, -0.5905}, {15.0, -0.5881}, {20.0, -0.5876}};
  for (const Row& row : top) {
    INFO("t = " << row.time);
    CHECK(std::abs(column.displacement(10.0, row.time) - row.top_displacement) <= 0.5e-4 + 1e-9);
  }
  // Base stress (kPa) as printed by an earlier reading (paper/07_exact_column.md). Those digits are reproduced by the PLAIN series cut at 400 terms
  // (checked below). That series converges like 1/n^2 at the base, its tail adds about
  // rho g(t) H (8/pi^2)/(4N): 0.3 kPa at t = 10 s, so the converged values lie 0.05-0.3 kPa below the
  // printed ones. The oracle returns the converged value; the tolerance 0.35 kPa covers that.
  struct StressRow { double time, base_stress_kpa; };
  const std::vector<StressRow> base{{2.5, -85.7}, {5.0, -293.3}, {7.5, -502.0}, {10.0, -589.7}};
  for (const StressRow& row : base) {
    INFO("t = " << row.time);
    CHECK(std::abs(column.modal_sum_stress(0.0, row.time, 400) / 1e3 - row.base_stress_kpa) <= 0.05 + 1e-6);
    const double converged = column.stress(0.0, row.time) / 1e3;
    CHECK(std::abs(converged - row.base_stress_kpa) <= 0.35);
    CHECK(converged < row.base_stress_kpa + 0.05);  // the tail only adds compression
  }
}

TEST_CASE("exact::SoilColumn: mode-accelerated sum equals the plain modal series") {
  // The plain series with 20000 terms has a tail below rho g H (8/pi^2)/(4 * 20000) = 6 Pa in the base stress
  // and below 1e-8 m in the displacement; the accelerated sum with 200 modes must agree within those bounds.
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0);
  for (double time : {1.0, 5.0, 9.9, 10.3, 14.2, 20.0}) {
    for (double y : {0.0, 3.0, 7.0, 10.0}) {
      INFO("t = " << time << ", y = " << y);
      CHECK(std::abs(column.displacement(y, time) - column.modal_sum_displacement(y, time, 20000)) <= 1e-8);
      CHECK(std::abs(column.stress(y, time) - column.modal_sum_stress(y, time, 20000)) <= 10.0);
    }
  }
}

TEST_CASE("exact::SoilColumn: after the ramp u_top stays in [-0.5909, -0.5863] m (paper/07_exact_column.md)") {
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0);
  double lowest = 0.0, highest = -1.0;
  for (int i = 0; i <= 2000; ++i) {
    const double top = column.displacement(10.0, 10.0 + 0.005 * i);
    lowest = std::min(lowest, top);
    highest = std::max(highest, top);
  }
  CHECK(lowest >= -0.5909);
  CHECK(highest <= -0.5863);
  CHECK(lowest < -0.5900);   // and it does oscillate, by about +-2.3 mm (paper/07_exact_column.md)
  CHECK(highest > -0.5870);
}

TEST_CASE("exact::SoilColumn: the velocity is the time derivative of the displacement (central differences)") {
  // The soil block (H = 10 m, M = 5 MPa, rho = 6000 kg/m^3, g = 9.81, T = 20 s), during and after the ramp,
  // and under constant gravity (the top falls freely at first: v(H, t) = -g t while t < H/c = 0.35 s).
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, 20.0), constant(10.0, 5e6, 6000.0, 9.81, 0.0);
  const double dt = 1e-5;
  for (double y : {2.0, 7.5, 10.0})
    for (double t : {1.3, 6.0, 12.7, 17.1}) {
      const double rate = (column.displacement(y, t + dt) - column.displacement(y, t - dt)) / (2.0 * dt);
      CHECK(column.velocity(y, t) == doctest::Approx(rate).epsilon(1e-5).scale(1e-6));
    }
  CHECK(constant.velocity(10.0, 0.1) == doctest::Approx(-0.981).epsilon(1e-3));
  CHECK(column.velocity(0.0, 5.0) == 0.0);  // the base is held
  CHECK(column.gravity_rate(5.0) == doctest::Approx(0.5 * 9.81 * (3.14159265358979 / 10.0)).epsilon(1e-12));  // sin(pi/2) = 1
  CHECK(column.gravity_rate(11.0) == 0.0);
}

TEST_CASE("exact::SoilColumn: free fall of the top before the base is felt") {
  // The base is felt at height y only when the wave from it arrives, at t = y/c. Before that the material
  // falls freely: for the top, t < H/c = 0.3464 s, u(H,t) = -int_0^t int_0^s g(r) dr ds.
  // Ramp: g(t) = (g/2)(1 - cos Omega t)  =>  u = -(g/2)(t^2/2 - (1 - cos Omega t)/Omega^2).
  // Constant gravity: u = -g t^2 / 2.
  const double g = 9.81, period = 20.0, omega_ramp = 2.0 * 3.14159265358979323846 / period;
  const SoilColumn ramped(10.0, 5e6, 6000.0, g, period);
  const SoilColumn constant(10.0, 5e6, 6000.0, g, 0.0);
  for (double time : {0.1, 0.2, 0.3}) {
    INFO("t = " << time);
    const double ramped_fall = -0.5 * g * (0.5 * time * time - (1.0 - std::cos(omega_ramp * time)) / (omega_ramp * omega_ramp));
    CHECK(ramped.displacement(10.0, time) == doctest::Approx(ramped_fall).epsilon(1e-6));
    CHECK(constant.displacement(10.0, time) == doctest::Approx(-0.5 * g * time * time).epsilon(1e-5));
  }
}

TEST_CASE("exact::SoilColumn: constant gravity, twice the static solution at T1/2 and back to rest at T1") {
  // Y_n = g (1 - cos omega_n t)/omega_n^2 with omega_n = (2n-1) omega_1. At t = T1/2 = pi/omega_1 every
  // cos(omega_n t) = -1, so u = 2 u_static; at t = T1 every cos = 1, so u = 0 and the column is at rest.
  const SoilColumn column(10.0, 5e6, 6000.0, 9.81, -1.0);
  const double first_period = 4.0 * 10.0 / column.wave_speed();
  for (double y : {1.0, 4.0, 8.0, 10.0}) {
    INFO("y = " << y);
    const double closed_form = -(6000.0 * 9.81 / 5e6) * (10.0 * y - 0.5 * y * y);
    CHECK(column.displacement(y, 0.5 * first_period) == doctest::Approx(2.0 * closed_form).epsilon(1e-5));
    CHECK(std::abs(column.displacement(y, first_period)) <= 1e-5 * std::abs(closed_form));
    CHECK(std::abs(column.displacement(y, 3.0 * first_period)) <= 1e-5 * std::abs(closed_form));
  }
  // Stress at mid-height at T1/2: twice the static value (series of the step load: 1/n^2 terms, hence 1e-2).
  CHECK(column.stress(5.0, 0.5 * first_period) == doctest::Approx(2.0 * -6000.0 * 9.81 * 5.0).epsilon(1e-2));
}

TEST_CASE("exact::SoilColumn: modal responses agree with a Runge-Kutta integration, also at resonance") {
  // Integrate Y'' + omega_n^2 Y = g(t) from rest with classical RK4 and compare with the closed form.
  // Resonant case: T = T1 = 4H/c makes Omega = 2 pi / T equal to omega_1.
  const double height = 10.0, modulus = 5e6, density = 6000.0, g = 9.81;
  const double first_period = 4.0 * height / std::sqrt(modulus / density);
  for (double period : {20.0, first_period, 3.0 * first_period}) {  // generic, resonant with mode 1, with mode 2
    const SoilColumn column(height, modulus, density, g, period);
    for (int n : {1, 2, 5}) {
      const double omega = column.angular_frequency(n);
      const auto load = [&](double t) { return column.gravity_at(t); };
      double value = 0.0, rate = 0.0, time = 0.0;
      const double step = 2e-4, end = 1.2 * period;
      const int steps = static_cast<int>(std::round(end / step));
      double largest = 0.0, largest_error = 0.0, largest_rate_error = 0.0;
      for (int i = 0; i < steps; ++i) {
        const double k1_value = rate, k1_rate = load(time) - omega * omega * value;
        const double k2_value = rate + 0.5 * step * k1_rate,
                     k2_rate = load(time + 0.5 * step) - omega * omega * (value + 0.5 * step * k1_value);
        const double k3_value = rate + 0.5 * step * k2_rate,
                     k3_rate = load(time + 0.5 * step) - omega * omega * (value + 0.5 * step * k2_value);
        const double k4_value = rate + step * k3_rate,
                     k4_rate = load(time + step) - omega * omega * (value + step * k3_value);
        value += step / 6.0 * (k1_value + 2.0 * k2_value + 2.0 * k3_value + k4_value);
        rate += step / 6.0 * (k1_rate + 2.0 * k2_rate + 2.0 * k3_rate + k4_rate);
        time = (i + 1) * step;
        largest = std::max(largest, std::abs(value));
        largest_error = std::max(largest_error, std::abs(value - column.modal_response(n, time)));
        largest_rate_error = std::max(largest_rate_error, std::abs(rate - column.modal_response_rate(n, time)));
      }
      INFO("T = " << period << ", mode " << n);
      CHECK(largest_error <= 1e-6 * largest);
      CHECK(largest_rate_error <= 1e-6 * largest * omega);
    }
  }
  // Continuity through resonance: T a hair away from T1 gives the same response.
  const SoilColumn resonant(height, modulus, density, g, first_period);
  const SoilColumn nearby(height, modulus, density, g, first_period * (1.0 + 1e-9));
  for (double time : {0.1, 0.3, 0.5 * first_period, 0.7 * first_period}) {
    CHECK(nearby.modal_response(1, time) == doctest::Approx(resonant.modal_response(1, time)).epsilon(1e-7));
    CHECK(nearby.displacement(10.0, time) == doctest::Approx(resonant.displacement(10.0, time)).epsilon(1e-7));
  }
}

}  // namespace mpm::exact
