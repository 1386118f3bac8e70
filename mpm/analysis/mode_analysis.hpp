/// \file
/// One mode of frequency \f$ \omega \f$ through one step of each time integrator: the amplification
/// matrix, its spectral radius, damping ratio, period error and stability limit as functions of
/// \f$ \Omega = \omega\,\Delta t \f$ and Newmark's \f$ \gamma \f$ (paper/10_integrator_analysis.md derives them).
///
/// Linearised about rest, every transfer of the step is linear and the particle stress, velocity and
/// acceleration of a mode of the semi-discrete system \f$ \ddot d = -\omega^2 d \f$ stay in that mode. The
/// state is \f$ \mathbf z = (\omega d, v) \f$, so that \f$ |\mathbf z|^2/2 \f$ is the mode's energy per unit mass:
/// - forward Euler (stress from \f$ v^k \f$, then \f$ v \mathrel{+}= \Delta t\, a \f$):
///   \f$ \omega d' = \omega d + \Omega v,\ v' = v - \Omega\, \omega d' \f$;
/// - the predictor-corrector with Eq. (32) (stress from \f$ v^{pred} = v + (1-\gamma)\Delta t\, a \f$, then \f$ v \mathrel{+}= \Delta t\, a' \f$):
///   \f$ \omega d' = (1 - (1-\gamma)\Omega^2)\, \omega d + \Omega v,\ v' = v - \Omega\, \omega d' \f$;
/// - the predictor-corrector with Eq. (23)'s average (\f$ v \mathrel{+}= \Delta t ((1-\gamma) a + \gamma a') \f$):
///   \f$ \omega d' \f$ as above, \f$ v' = v - (1-\gamma)\Omega\, \omega d - \gamma\Omega\, \omega d' \f$.
///
/// This file shares no code with the step it predicts: the doctests of
/// tests/integrator_modes.cpp run the real step() and compare.
#pragma once
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <string>

namespace mpm {

/// The time integrators of the analysis.
enum class ModeScheme {
  forward_euler,  ///< paper/02_mpm_forward_euler.md
  npc_eq32,       ///< the predictor-corrector as printed, Eq. (32)
  npc_average     ///< the predictor-corrector with the Newmark average of Eq. (23)
};

/// The amplification matrix of one step acting on \f$ (\omega d, v) \f$ (header comment).
/// \f[ A_{FE} = \begin{pmatrix} 1 & \Omega \\ -\Omega & 1-\Omega^2 \end{pmatrix},\quad
///     A_{32} = \begin{pmatrix} q & \Omega \\ -\Omega q & 1-\Omega^2 \end{pmatrix},\quad
///     A_{avg} = \begin{pmatrix} q & \Omega \\ -(1-\gamma)\Omega - \gamma\Omega q & 1-\gamma\Omega^2 \end{pmatrix},\quad
///     q = 1-(1-\gamma)\Omega^2 \f]
inline Eigen::Matrix2d mode_amplification(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  const double Omega = omega_dt, q = 1.0 - (1.0 - newmark_gamma) * Omega * Omega;
  Eigen::Matrix2d amplification;
  switch (scheme) {
    case ModeScheme::forward_euler: amplification << 1.0, Omega, -Omega, 1.0 - Omega * Omega; break;
    case ModeScheme::npc_eq32: amplification << q, Omega, -Omega * q, 1.0 - Omega * Omega; break;
    case ModeScheme::npc_average:
      amplification << q, Omega, -(1.0 - newmark_gamma) * Omega - newmark_gamma * Omega * q, 1.0 - newmark_gamma * Omega * Omega;
      break;
  }
  return amplification;
}

/// The eigenvalues of mode_amplification(): \f$ \lambda = \tfrac12\left(\mathrm{tr} A \pm \sqrt{(\mathrm{tr} A)^2 - 4\det A}\right) \f$.
inline std::pair<std::complex<double>, std::complex<double>> mode_eigenvalues(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  const Eigen::Matrix2d amplification = mode_amplification(scheme, omega_dt, newmark_gamma);
  const double trace = amplification.trace(), determinant = amplification.determinant();
  const std::complex<double> root = std::sqrt(std::complex<double>(trace * trace - 4.0 * determinant, 0.0));
  return {0.5 * (trace + root), 0.5 * (trace - root)};
}

/// Spectral radius \f$ \rho(A) = \max |\lambda| \f$: the step is stable while \f$ \rho \le 1 \f$.
inline double mode_spectral_radius(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  const auto [first, second] = mode_eigenvalues(scheme, omega_dt, newmark_gamma);
  return std::max(std::abs(first), std::abs(second));
}

/// The energy kept per step while the eigenvalues are a complex pair: \f$ |\lambda|^2 = \det A \f$;
/// forward Euler and the average 1, Eq. (32) \f$ 1 - (1-\gamma)\Omega^2 \f$.
inline double mode_energy_per_step(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  return mode_amplification(scheme, omega_dt, newmark_gamma).determinant();
}

/// The numerical phase per step \f$ \bar\Omega = \arg\lambda \f$ of the complex pair \f$ \lambda = r e^{\pm i\bar\Omega} \f$.
inline double mode_phase_per_step(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  return std::abs(std::arg(mode_eigenvalues(scheme, omega_dt, newmark_gamma).first));
}

/// Damping ratio \f$ \bar\xi = -\ln r / \bar\Omega \f$ (Hughes' definition: \f$ \lambda = e^{\bar\Omega(-\bar\xi \pm i)} \f$);
/// Eq. (32): \f$ \bar\xi \approx (1-\gamma)\Omega/2 \f$ for small \f$ \Omega \f$.
inline double mode_damping_ratio(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  const double radius = std::sqrt(mode_energy_per_step(scheme, omega_dt, newmark_gamma));
  return -std::log(radius) / mode_phase_per_step(scheme, omega_dt, newmark_gamma);
}

/// Relative period error \f$ \bar T / T - 1 = \Omega / \bar\Omega - 1 \f$.
inline double mode_period_error(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  return omega_dt / mode_phase_per_step(scheme, omega_dt, newmark_gamma) - 1.0;
}

/// The energy left after one period \f$ 2\pi/\omega \f$ of the exact mode, \f$ (\det A)^{2\pi/\Omega} \approx e^{-2\pi(1-\gamma)\Omega} \f$ for Eq. (32).
inline double mode_energy_per_period(ModeScheme scheme, double omega_dt, double newmark_gamma) {
  return std::pow(mode_energy_per_step(scheme, omega_dt, newmark_gamma), 2.0 * M_PI / omega_dt);
}

/// The largest stable \f$ \Omega = \omega\Delta t \f$: a real 2x2 step is stable iff \f$ |\det A| \le 1 \f$ and
/// \f$ |\mathrm{tr} A| \le 1 + \det A \f$, which gives 2 for forward Euler and the average (any \f$ \gamma \f$),
/// and \f$ 2/\sqrt{3 - 2\gamma} \f$ for Eq. (32).
inline double mode_stability_limit(ModeScheme scheme, double newmark_gamma) {
  return scheme == ModeScheme::npc_eq32 ? 2.0 / std::sqrt(3.0 - 2.0 * newmark_gamma) : 2.0;
}

TEST_CASE("Integrator modes: det A and tr A by hand, the limits from the spectral radius agree with the closed forms") {
  const double Omega = 0.3, gamma = 0.6;
  // Eq. (32): det = 1 - (1 - gamma) Omega^2, tr = 2 - (2 - gamma) Omega^2
  CHECK(mode_amplification(ModeScheme::npc_eq32, Omega, gamma).determinant() == doctest::Approx(1.0 - 0.4 * 0.09).epsilon(1e-14));
  CHECK(mode_amplification(ModeScheme::npc_eq32, Omega, gamma).trace() == doctest::Approx(2.0 - 1.4 * 0.09).epsilon(1e-14));
  // the average and forward Euler: det = 1, tr = 2 - Omega^2 (central differences), for any gamma
  for (const ModeScheme scheme : {ModeScheme::forward_euler, ModeScheme::npc_average}) {
    CHECK(mode_amplification(scheme, Omega, gamma).determinant() == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(mode_amplification(scheme, Omega, gamma).trace() == doctest::Approx(2.0 - 0.09).epsilon(1e-14));
  }
  // the spectral radius crosses 1 at the closed-form limit: bisection on it, to 1e-9
  for (const ModeScheme scheme : {ModeScheme::forward_euler, ModeScheme::npc_eq32, ModeScheme::npc_average})
    for (const double newmark_gamma : {0.5, 0.6, 0.75, 1.0}) {
      double stable = 0.1, unstable = 3.0;
      for (int k = 0; k < 60; ++k) {
        const double middle = 0.5 * (stable + unstable);
        (mode_spectral_radius(scheme, middle, newmark_gamma) <= 1.0 + 1e-12 ? stable : unstable) = middle;
      }
      CHECK(stable == doctest::Approx(mode_stability_limit(scheme, newmark_gamma)).epsilon(1e-5));
    }
  CHECK(mode_stability_limit(ModeScheme::npc_eq32, 0.5) == doctest::Approx(std::sqrt(2.0)));
}

TEST_CASE("Integrator modes: Eq. (32) damps exp(-2 pi (1 - gamma) Omega) per period, the others not at all, periods lengthen at O(Omega^2)") {
  for (const double gamma : {0.5, 0.75}) {
    const double Omega = 0.01;
    CHECK(mode_energy_per_period(ModeScheme::npc_eq32, Omega, gamma) ==
          doctest::Approx(std::exp(-2.0 * M_PI * (1.0 - gamma) * Omega)).epsilon(1e-4));
    CHECK(mode_damping_ratio(ModeScheme::npc_eq32, Omega, gamma) == doctest::Approx((1.0 - gamma) * Omega / 2.0).epsilon(1e-3).scale(0.0));
    CHECK(mode_energy_per_period(ModeScheme::npc_average, Omega, gamma) == doctest::Approx(1.0).epsilon(1e-13));
  }
  CHECK(mode_energy_per_period(ModeScheme::npc_eq32, 0.01, 1.0) == doctest::Approx(1.0).epsilon(1e-13));
  // central differences: cos(Omega_bar) = 1 - Omega^2 / 2, so Omega_bar > Omega: the period shortens by Omega^2 / 24 + O(Omega^4)
  const double Omega = 0.2;
  CHECK(mode_phase_per_step(ModeScheme::forward_euler, Omega, 0.5) == doctest::Approx(std::acos(1.0 - Omega * Omega / 2.0)).epsilon(1e-14));
  CHECK(mode_period_error(ModeScheme::forward_euler, Omega, 0.5) == doctest::Approx(-Omega * Omega / 24.0).epsilon(2e-2).scale(0.0));
  CHECK(mode_period_error(ModeScheme::npc_average, Omega, 0.6) == doctest::Approx(-Omega * Omega / 24.0).epsilon(2e-2).scale(0.0));
  // Eq. (32) at gamma = 1/2: tr = 2 - 3 Omega^2 / 2 and det = 1 - Omega^2 / 2 give cos(Omega_bar) = tr / (2 sqrt(det))
  const double eq32_phase = std::acos((2.0 - 1.5 * Omega * Omega) / (2.0 * std::sqrt(1.0 - 0.5 * Omega * Omega)));
  CHECK(mode_phase_per_step(ModeScheme::npc_eq32, Omega, 0.5) == doctest::Approx(eq32_phase).epsilon(1e-13).scale(0.0));
  // Eq. (32)'s period shortens by (1/24 + (1 - gamma^2)/8) Omega^2 + O(Omega^4): 3.25 times central differences' at gamma = 1/2
  for (const double gamma : {0.5, 0.75})
    CHECK(mode_period_error(ModeScheme::npc_eq32, 0.01, gamma) ==
          doctest::Approx(-(1.0 / 24.0 + (1.0 - gamma * gamma) / 8.0) * 1e-4).epsilon(1e-3).scale(0.0));
}

}  // namespace mpm
