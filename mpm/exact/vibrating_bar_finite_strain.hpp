/// \file
/// The vibrating bar at finite strain, as the solver models it: the reference of the large-
/// amplitude cases of the smooth-data suite. It shares no code with the solver.
///
/// Why a second reference. The solver accumulates the strain from the velocity gradient on the
/// current configuration, \f$ \varepsilon \mathrel{+}= \Delta t\, \partial v/\partial x \f$ (Eq. 16), updates
/// the density by Eq. (17) and applies Hooke's law, Eq. (3). In 1D, with the stretch
/// \f$ \lambda = \partial x/\partial X \f$, this is \f$ \varepsilon = \int \dot\lambda/\lambda\,dt = \ln\lambda \f$,
/// \f$ \rho = \rho_0/\lambda \f$ and \f$ \sigma = E\ln\lambda \f$; the momentum balance on the current
/// configuration, \f$ \rho\, \dot v = \partial\sigma/\partial x \f$, is \f$ \rho_0\, \dot v = \partial\sigma/\partial X \f$
/// in the reference coordinate (\f$ \partial/\partial x = \lambda^{-1}\partial/\partial X \f$). So the bar obeys
/// \f[ \rho_0\, u_{tt} = \frac{\partial}{\partial X}\, E \ln(1 + u_X), \qquad \sigma(0,t) = 0, \quad u(L,t) = 0, \f]
/// a nonlinear wave equation with no closed-form solution. When \f$ V/\omega \ll L \f$ it is the
/// linear one of VibratingBar; at \f$ V/\omega = 0.05 L \f$ (largest strain 0.079) its characteristic
/// speed \f$ c\lambda^{-1/2} \f$ varies by about 4 %, and a shock forms only after several periods.
///
/// Method (chosen to share nothing with MPM). A Lagrangian finite-difference solve on a uniform
/// grid of N cells in X: displacement and velocity at the nodes \f$ X_i = i\,\Delta X \f$, stretch and
/// stress at the cell centres; the free end's node takes the mirror stress \f$ \sigma_{-1/2} = -\sigma_{1/2} \f$
/// (\f$ \sigma \f$ is odd about a free end), the fixed end's node is held. Velocity Verlet in time
/// (second order, symmetric, so the step may change between output times), with
/// \f$ \Delta t = 0.9\, \Delta X \sqrt{0.8\,\rho_0/E} \f$ (stable while every stretch exceeds 0.8; a smaller one throws). Second order in \f$ \Delta X \f$:
/// the doctests measure the observed order. Values between grid points are interpolated linearly.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "mpm/exact/vibrating_bar.hpp"

namespace mpm::exact {

/// The bar [0, L], free at X = 0 and fixed at X = L, started unstressed with v = V cos(pi X / 2L),
/// with \f$ \sigma = E \ln\lambda \f$; solved once, at construction, up to the given output times.
class FiniteStrainBar {
 public:
  /// mode n >= 1: the initial velocity is \f$ V\cos((2n - 1)\pi X / 2L) \f$, the shape of VibratingBar's mode n.
  FiniteStrainBar(double length, double young_modulus, double density, double velocity_amplitude, int cells,
                  std::vector<double> output_times, int mode = 1)
      : length_(length), young_modulus_(young_modulus), density_(density), cells_(cells), mode_(mode), times_(std::move(output_times)) {
    if (!(length_ > 0.0) || !(young_modulus_ > 0.0) || !(density_ > 0.0) || cells_ < 2 || !std::isfinite(velocity_amplitude) || mode_ < 1)
      throw std::invalid_argument("FiniteStrainBar: length, modulus and density must be positive, cells >= 2, mode >= 1");
    if (!std::is_sorted(times_.begin(), times_.end()) || (!times_.empty() && times_.front() < 0.0))
      throw std::invalid_argument("FiniteStrainBar: output times must be sorted and >= 0");
    solve(velocity_amplitude);
  }

  const std::vector<double>& output_times() const { return times_; }

  /// v(X, t_k) at the k-th output time, m/s.
  double velocity(double reference_position, int output) const { return at_nodes(velocities_.at(output), reference_position); }
  /// u(X, t_k), m.
  double displacement(double reference_position, int output) const { return at_nodes(displacements_.at(output), reference_position); }
  /// \f$ \sigma(X, t_k) = E \ln\lambda \f$, Pa (the solver's Cauchy stress; tension positive).
  double stress(double reference_position, int output) const {
    const std::vector<double>& s = stresses_.at(output);
    const double dX = length_ / cells_, position = checked(reference_position) / dX - 0.5;  // in cell-centre units
    if (position <= 0.0) return s[0] * (position + 0.5) / 0.5;  // sigma(0) = 0 at the free end
    const int j = std::min(static_cast<int>(position), cells_ - 2);
    const double w = position - j;  // w > 1 extrapolates over the last half cell
    return (1.0 - w) * s[j] + w * s[j + 1];
  }
  /// Kinetic plus strain energy per unit area at the k-th output time, with the strain energy
  /// \f$ W(\lambda) = E(\lambda\ln\lambda - \lambda + 1) \f$ per reference volume (\f$ W' = E\ln\lambda \f$), J/m^2.
  double energy(int output) const { return energies_.at(output); }

 private:
  double length_, young_modulus_, density_;
  int cells_, mode_;
  std::vector<double> times_, energies_;
  std::vector<std::vector<double>> velocities_, displacements_, stresses_;

  double checked(double x) const {
    if (!(x >= -1e-12 * length_ && x <= length_ * (1.0 + 1e-12)))
      throw std::domain_error("FiniteStrainBar: X lies outside the bar [0, L]");
    return std::clamp(x, 0.0, length_);
  }

  double at_nodes(const std::vector<double>& values, double x) const {
    const double position = checked(x) / (length_ / cells_);
    const int i = std::min(static_cast<int>(position), cells_ - 1);
    const double w = position - i;
    return (1.0 - w) * values[i] + w * values[i + 1];
  }

  void solve(double amplitude) {
    constexpr double pi = 3.14159265358979323846;
    const int n = cells_;
    const double dX = length_ / n, nodal_mass = density_ * dX;
    std::vector<double> u(n + 1, 0.0), v(n + 1), a(n + 1, 0.0), stress(n, 0.0);
    for (int i = 0; i <= n; ++i) v[i] = amplitude * std::cos((2.0 * mode_ - 1.0) * 0.5 * pi * i * dX / length_);
    v[n] = 0.0;
    constexpr double smallest_stretch = 0.8;
    auto accelerations = [&] {
      for (int j = 0; j < n; ++j) {
        const double stretch = 1.0 + (u[j + 1] - u[j]) / dX;
        if (!(stretch > smallest_stretch)) throw std::runtime_error("FiniteStrainBar: stretch fell below 0.8 (amplitude too large for this reference)");
        stress[j] = young_modulus_ * std::log(stretch);
      }
      a[0] = 2.0 * stress[0] / nodal_mass;  // mirror stress -sigma_{1/2} beyond the free end
      for (int i = 1; i < n; ++i) a[i] = (stress[i] - stress[i - 1]) / nodal_mass;
      a[n] = 0.0;  // fixed end
    };
    auto record = [&] {
      velocities_.push_back(v);
      displacements_.push_back(u);
      stresses_.push_back(stress);
      double energy = 0.0;
      for (int i = 0; i <= n; ++i) energy += 0.5 * density_ * v[i] * v[i] * dX * (i == 0 || i == n ? 0.5 : 1.0);
      for (int j = 0; j < n; ++j) {
        const double stretch = 1.0 + (u[j + 1] - u[j]) / dX;
        energy += young_modulus_ * (stretch * std::log(stretch) - stretch + 1.0) * dX;
      }
      energies_.push_back(energy);
    };
    accelerations();
    const double largest_step = 0.9 * dX * std::sqrt(density_ * smallest_stretch / young_modulus_);
    double time = 0.0;
    for (double target : times_) {
      const long steps = static_cast<long>(std::ceil((target - time) / largest_step - 1e-12));
      const double dt = steps > 0 ? (target - time) / steps : 0.0;
      for (long step = 0; step < steps; ++step) {  // velocity Verlet
        for (int i = 0; i <= n; ++i) v[i] += 0.5 * dt * a[i];
        for (int i = 0; i <= n; ++i) u[i] += dt * v[i];
        accelerations();
        for (int i = 0; i <= n; ++i) v[i] += 0.5 * dt * a[i];
      }
      time = target;
      record();
    }
  }
};

// Steel bar of the Dyka test: L = 0.1333 m, E = 200 GPa, rho = 7833 kg/m^3.

TEST_CASE("exact::FiniteStrainBar: at small amplitude it is the closed-form first mode (VibratingBar)") {
  const double L = 0.1333, E = 200e9, rho = 7833.0;
  const VibratingBar linear(L, E, rho, 1.0);
  const double V = 1e-6 * L * linear.angular_frequency();  // V/omega = 1e-6 L
  const VibratingBar mode(L, E, rho, V);
  const double T = mode.period();
  const FiniteStrainBar bar(L, E, rho, V, 256, {0.125 * T, 0.5 * T, 0.8 * T});
  for (int k = 0; k < 3; ++k)
    for (double X : {0.0, 0.1 * L, 0.5 * L, 0.93 * L, L}) {
      const double t = bar.output_times()[k];
      // second order with k dX = pi/512: relative error ~ (k dX)^2 ~ 1e-5
      CHECK(std::abs(bar.velocity(X, k) - mode.velocity(X, t)) <= 1e-4 * V);
      CHECK(std::abs(bar.stress(X, k) - mode.stress(X, t)) <= 1e-4 * mode.impedance() * V);
      CHECK(std::abs(bar.displacement(X, k) - mode.displacement(X, t)) <= 1e-4 * mode.displacement_amplitude());
    }
  // The second mode (k dX = 3 pi / 512: relative error ~ 1e-4), against the closed form's mode 2.
  const VibratingBar second(L, E, rho, V, 2);
  const FiniteStrainBar bar2(L, E, rho, V, 256, {0.3 * second.period()}, 2);
  for (double X : {0.0, 0.2 * L, 0.5 * L, 0.93 * L})
    CHECK(std::abs(bar2.velocity(X, 0) - second.velocity(X, 0.3 * second.period())) <= 1e-3 * V);
}

TEST_CASE("exact::FiniteStrainBar: observed order 2 under refinement at large amplitude, energy conserved, ends held") {
  const double L = 0.1333, E = 200e9, rho = 7833.0;
  const VibratingBar mode(L, E, rho, 1.0);
  const double V = 0.05 * L * mode.angular_frequency(), T = mode.period();  // V/omega = 0.05 L
  const double mode_velocity_zero = 0.0;  // the linear mode's v(0, T/4) = V cos(pi/2)
  const std::vector<double> times{0.25 * T, 0.5 * T};
  const FiniteStrainBar coarse(L, E, rho, V, 64, times), medium(L, E, rho, V, 128, times), fine(L, E, rho, V, 256, times);
  // Self-convergence: the differences between successive meshes fall like dX^p.
  double velocity_coarse = 0.0, velocity_fine = 0.0, stress_coarse = 0.0, stress_fine = 0.0;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i <= 40; ++i) {
      const double X = L * i / 40.0;
      velocity_coarse = std::max(velocity_coarse, std::abs(coarse.velocity(X, k) - medium.velocity(X, k)));
      velocity_fine = std::max(velocity_fine, std::abs(medium.velocity(X, k) - fine.velocity(X, k)));
      stress_coarse = std::max(stress_coarse, std::abs(coarse.stress(X, k) - medium.stress(X, k)));
      stress_fine = std::max(stress_fine, std::abs(medium.stress(X, k) - fine.stress(X, k)));
    }
  const double velocity_order = std::log2(velocity_coarse / velocity_fine), stress_order = std::log2(stress_coarse / stress_fine);
  CHECK(velocity_order > 1.8);
  CHECK(velocity_order < 2.3);
  CHECK(stress_order > 1.8);
  CHECK(stress_order < 2.3);
  CHECK(velocity_fine < 1e-3 * V);  // the 256-cell reference is within ~1e-4 V of the limit
  // The finite-strain solution differs from the linear one by far more than its own error: at
  // t = T/4 the linear free end is at rest, the finite-strain one moves at about -0.02 V.
  CHECK(std::abs(fine.velocity(0.0, 0) - mode_velocity_zero) > 100.0 * velocity_fine);
  // Energy rho V^2 L / 4 (no strain at t = 0), conserved to the scheme's error.
  for (int k = 0; k < 2; ++k) CHECK(fine.energy(k) == doctest::Approx(0.25 * rho * V * V * L).epsilon(1e-4));
  for (int k = 0; k < 2; ++k) {
    CHECK(fine.velocity(L, k) == 0.0);
    CHECK(fine.displacement(L, k) == 0.0);
    CHECK(fine.stress(0.0, k) == 0.0);
  }
  CHECK_THROWS_AS(fine.velocity(1.1 * L, 0), std::domain_error);
}

}  // namespace mpm::exact
