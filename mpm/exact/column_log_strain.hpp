/// \file
/// Static settlement of the soil column as the solver models it at finite strain: the reference
/// against which the MPM block converges, beside the small-strain solution of paper/07_exact_column.md
/// (column.hpp), which is the paper's. It shares no code with the solver.
///
/// Why a second reference. The solver is updated Lagrangian: it accumulates the strain from the
/// velocity gradient on the current configuration, \f$ \varepsilon \mathrel{+}= \Delta t\, \partial v/\partial y \f$
/// (Eq. 16), updates the density by Eq. (17) and applies Hooke's law, Eq. (3), to that strain. For a
/// laterally confined column (or nu = 0) with stretch \f$ \lambda = \partial y / \partial Y \f$ this is
/// \f$ \varepsilon = \int \dot\lambda/\lambda\, dt = \ln\lambda \f$ (the logarithmic strain),
/// \f$ \rho = \rho_0/\lambda \f$ and \f$ \sigma = M \ln\lambda \f$, with M the constrained modulus.
/// Equilibrium on the current configuration, \f$ \partial\sigma/\partial y = \rho g \f$, becomes
/// \f$ \partial\sigma/\partial Y = \rho\lambda g = \rho_0 g \f$ in the reference coordinate Y, so the
/// stress is the small-strain one, \f$ \sigma(Y) = -\rho_0 g (H - Y) \f$ (the column is statically
/// determinate), but the stretch is \f$ \lambda(Y) = e^{\sigma/M} = e^{-a (H - Y)} \f$ with
/// \f$ a = \rho_0 g / M \f$, and the displacement
/// \f[ u(Y) = \int_0^Y (\lambda - 1)\, dY' = \frac{e^{-a(H - Y)} - e^{-aH}}{a} - Y. \f]
/// Expanded in a it is \f$ -a(HY - Y^2/2) + O(a^2) \f$, the small-strain static solution of paper/07_exact_column.md;
/// at the top the two differ by about \f$ aH/3 \f$ relative: 3.8 % for the soil block (aH = 0.118).
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mpm::exact {

/// The statically loaded column 0 <= Y <= H (base fixed, top free) with logarithmic strain.
class SoilColumnLogStrain {
 public:
  /// constrained_modulus M (E for nu = 0), initial density rho_0, gravity magnitude g > 0 acting downward.
  SoilColumnLogStrain(double height, double constrained_modulus, double density, double gravity)
      : height_(height), constrained_modulus_(constrained_modulus), density_(density), gravity_(gravity) {
    if (!(height_ > 0.0) || !(constrained_modulus_ > 0.0) || !(density_ > 0.0) || !(gravity_ > 0.0))
      throw std::invalid_argument("SoilColumnLogStrain: height, modulus, density and gravity must be positive");
  }

  /// \f$ a = \rho_0 g / M \f$, the strain per metre of overburden (1/m).
  double strain_gradient() const { return density_ * gravity_ / constrained_modulus_; }

  /// Cauchy stress at reference height Y: \f$ \sigma(Y) = -\rho_0 g (H - Y) \f$ (tension positive).
  double stress(double reference_height) const { return -density_ * gravity_ * (height_ - checked(reference_height)); }

  /// Stretch \f$ \lambda(Y) = \partial y/\partial Y = e^{\sigma(Y)/M} \f$.
  double stretch(double reference_height) const { return std::exp(stress(reference_height) / constrained_modulus_); }

  /// Displacement (upward positive) of the point at reference height Y:
  /// \f$ u(Y) = \left(e^{-a(H - Y)} - e^{-aH}\right)/a - Y \f$.
  double displacement(double reference_height) const {
    const double y = checked(reference_height), a = strain_gradient();
    return (std::exp(-a * (height_ - y)) - std::exp(-a * height_)) / a - y;
  }

 private:
  double height_, constrained_modulus_, density_, gravity_;

  double checked(double y) const {
    if (!(y >= -1e-12 * height_ && y <= height_ * (1.0 + 1e-12)))
      throw std::domain_error("SoilColumnLogStrain: height " + std::to_string(y) + " m lies outside the column");
    return y;
  }
};

// Expected values below are derived by hand or computed independently (Python's math.exp), never
// by the code under test. Soil block: H = 10 m, M = E = 5 MPa, rho_0 = 6000 kg/m^3, g = 9.81 m/s^2.

TEST_CASE("exact::SoilColumnLogStrain: values of the soil block (nu = 0 and nu = 0.3 with lateral rollers)") {
  const SoilColumnLogStrain column(10.0, 5e6, 6000.0, 9.81);
  CHECK(column.strain_gradient() == doctest::Approx(0.011772).epsilon(1e-12));
  // (1 - exp(-0.11772)) / 0.011772 - 10 = -0.566167375933 (Python); small strain gives -0.5886.
  CHECK(column.displacement(10.0) == doctest::Approx(-0.566167375933).epsilon(1e-10));
  // (exp(-0.011772 * 0.5) - exp(-0.11772)) / 0.011772 - 9.5 = -0.564698758773 (Python).
  CHECK(column.displacement(9.5) == doctest::Approx(-0.564698758773).epsilon(1e-10));
  CHECK(column.displacement(0.0) == 0.0);
  CHECK(column.stress(0.0) == doctest::Approx(-588600.0).epsilon(1e-14));
  CHECK(column.stress(10.0) == 0.0);
  CHECK(column.stretch(0.0) == doctest::Approx(std::exp(-0.11772)).epsilon(1e-14));
  // nu = 0.3: M = 5e6 * 0.7 / (1.3 * 0.4) = 6.730769e6 Pa; u(H) = -0.424773970973 (Python), small strain -0.437246.
  const SoilColumnLogStrain confined(10.0, 5e6 * 0.7 / (1.3 * 0.4), 6000.0, 9.81);
  CHECK(confined.displacement(10.0) == doctest::Approx(-0.424773970973).epsilon(1e-10));
  CHECK_THROWS_AS(column.displacement(10.5), std::domain_error);
  CHECK_THROWS_AS(SoilColumnLogStrain(10.0, 0.0, 6000.0, 9.81), std::invalid_argument);
}

TEST_CASE("exact::SoilColumnLogStrain: small strain limit and du/dY = lambda - 1") {
  // A stiff column (a H = 1e-6): the settlement is the small-strain rho g (H Y - Y^2/2)/M to O(a H).
  const double stiff_modulus = 6000.0 * 9.81 * 10.0 / 1e-6;
  const SoilColumnLogStrain stiff(10.0, stiff_modulus, 6000.0, 9.81);
  for (double y : {1.0, 5.0, 10.0}) {
    const double small_strain = -(6000.0 * 9.81 / stiff_modulus) * (10.0 * y - 0.5 * y * y);
    CHECK(stiff.displacement(y) == doctest::Approx(small_strain).epsilon(1e-5));
  }
  // The soil block: the top settles aH/3 = 3.9 % less than at small strain, to first order in aH.
  const SoilColumnLogStrain column(10.0, 5e6, 6000.0, 9.81);
  CHECK(column.displacement(10.0) / -0.5886 == doctest::Approx(1.0 - 0.11772 / 3.0).epsilon(2e-3));
  // du/dY = lambda - 1, by central differences (error O(step^2) ~ 1e-10).
  const double step = 1e-4;
  for (double y : {0.5, 3.0, 9.0}) {
    const double slope = (column.displacement(y + step) - column.displacement(y - step)) / (2.0 * step);
    CHECK(slope == doctest::Approx(column.stretch(y) - 1.0).epsilon(1e-7));
  }
}

}  // namespace mpm::exact
