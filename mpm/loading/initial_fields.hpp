/// \file
/// Smooth initial conditions: a particle's initial velocity and initial stress given as functions
/// of its position at t = 0 (a vibration mode, a manufactured solution), applied once after seeding.
///
/// The material is in total-strain form, Eq. (3) (sigma = D : epsilon), so an initial stress is
/// stored as the strain that carries it, epsilon_p = D^{-1} sigma_p; the strain energy of the
/// balances then counts it. The density stays rho_0: the seeded configuration is the reference one.
#pragma once
#include <doctest/doctest.h>

#include <functional>
#include <stdexcept>

#include "mpm/material/linear_elastic.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm {

/// v_0(X), the initial velocity at the position X.
template <int Dim>
using InitialVelocityField = std::function<Vector<Dim>(const Vector<Dim>& position)>;
/// sigma_0(X), the initial in-plane stress (symmetric) at the position X.
template <int Dim>
using InitialStressField = std::function<Matrix<Dim>(const Vector<Dim>& position)>;

/// \f$ \mathbf v_p = \mathbf v_0(\mathbf X_p) \f$ for every particle.
template <int Dim>
void set_initial_velocity(const InitialVelocityField<Dim>& velocity, Particles<Dim>& particles) {
  for (int p = 0; p < particles.size(); ++p) particles.velocity[p] = velocity(particles.reference_position[p]);
}

/// \f$ \boldsymbol\sigma_p = \boldsymbol\sigma_0(\mathbf X_p) \f$, with \f$ \boldsymbol\varepsilon_p = \mathbf D^{-1} \boldsymbol\sigma_p \f$
/// and \f$ \sigma_{zz,p} \f$ from Eq. (3), for every particle.
/// \throws std::invalid_argument if a stress is not symmetric: the solver relies on it (the internal force of
/// mpm/transfer/nodal_forces.hpp reads sigma_xy alone). A scene gives three components, so it cannot be.
template <int Dim>
void set_initial_stress(const InitialStressField<Dim>& stress, const std::vector<LinearElastic>& materials, Particles<Dim>& particles) {
  for (int p = 0; p < particles.size(); ++p) {
    const LinearElastic& material = materials[particles.material[p]];
    const Matrix<Dim> initial = stress(particles.reference_position[p]);
    if (initial != initial.transpose()) throw std::invalid_argument("set_initial_stress: the initial stress is not symmetric");
    particles.strain[p] = material.strain<Dim>(initial);
    particles.stress[p] = material.stress<Dim>(particles.strain[p]);
    particles.stress_zz[p] = material.stress_zz<Dim>(particles.strain[p]);
  }
}

TEST_CASE("Initial fields: the first mode's velocity and a prestress, set per particle") {
  Particles<1> bar;
  for (double x : {0.25, 0.75}) bar.add(Vector<1>(x), 1.0, 1.0, Vector<1>(0.0), Vector<1>(0.25));
  const double pi = 3.14159265358979323846;
  set_initial_velocity<1>([&](const Vector<1>& x) { return Vector<1>(2.0 * std::cos(0.5 * pi * x[0])); }, bar);
  CHECK(bar.velocity[0][0] == doctest::Approx(2.0 * 0.92387953251));  // cos(pi/8)
  CHECK(bar.velocity[1][0] == doctest::Approx(2.0 * 0.38268343237));  // cos(3 pi/8)

  Particles<2> block;
  block.add(Vector<2>(1.0, 2.0), 1.0, 1.0, Vector<2>::Zero(), Vector<2>(0.5, 0.5));
  const LinearElastic soil{5e6, 0.3, 6000.0};
  set_initial_stress<2>([](const Vector<2>& x) { return Matrix<2>((Matrix<2>() << -x[1], 0.5, 0.5, -3.0).finished() * 1e4); }, {soil}, block);
  CHECK(block.stress[0](0, 0) == doctest::Approx(-2e4));
  CHECK(block.stress[0](0, 1) == doctest::Approx(0.5e4));
  CHECK(block.stress[0](1, 1) == doctest::Approx(-3e4));
  CHECK(block.stress_zz[0] == doctest::Approx(0.3 * (-5e4)));  // plane strain: nu (sigma_xx + sigma_yy)
  CHECK(block.strain[0](0, 1) == doctest::Approx(0.5e4 * 1.3 / 5e6));  // sigma_xy / 2G, 2G = E / 1.3
  // A stress that is not symmetric is refused (the internal force reads sigma_xy alone).
  CHECK_THROWS_AS(set_initial_stress<2>([](const Vector<2>&) { return Matrix<2>((Matrix<2>() << -1.0, 0.5, 0.4, -3.0).finished()); },
                                        {soil}, block),
                  std::invalid_argument);
}

}  // namespace mpm
