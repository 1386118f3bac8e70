/// \file
/// The body force per unit mass b of Eq. (15): uniform gravity ramped by Eq. (44), plus an
/// optional field b(x, X, t) of the current position x, the reference position X and time t
/// (a manufactured solution's load, a smooth body force of a scene).
///
/// Once per step, evaluate() writes b_p for every particle into a particle array, which the
/// nodal body force, Eq. (15), and the work balance then read. Whether a field is present is
/// asked once per step, never per particle; without one, every b_p is the same gravity vector.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "mpm/loading/gravity.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm {

/// b(x, X, t), per unit mass: current position x, reference position X (the position at t = 0), time t.
template <int Dim>
using BodyForceField = std::function<Vector<Dim>(const Vector<Dim>& position, const Vector<Dim>& reference_position, double time)>;

/// b_p, the body force per unit mass at every particle for one step.
template <int Dim>
struct ParticleBodyForces {
  std::vector<Vector<Dim>> per_unit_mass;  ///< b_p
  bool all_zero = true;                    ///< every b_p is zero: Eq. (15) adds nothing this step
  bool uniform = true;                     ///< every b_p is the same vector (gravity alone)
};

template <int Dim>
struct BodyForce {
  Gravity<Dim> gravity;       ///< uniform, ramped in time by Eq. (44)
  BodyForceField<Dim> field;  ///< added to gravity; empty: none

  /// \f$ \mathbf b_p = \mathbf g(t) + \mathbf b(\mathbf x_p, \mathbf X_p, t) \f$ at every particle, into `out`
  /// (sized here once; no allocation after the first call).
  void evaluate(double time, const Particles<Dim>& particles, ParticleBodyForces<Dim>& out) const {
    const Vector<Dim> uniform = gravity.at(time);
    out.per_unit_mass.resize(particles.size());
    out.all_zero = !field && uniform.squaredNorm() == 0.0;
    out.uniform = !field;
    if (out.all_zero) return;
    if (!field) {
      std::fill(out.per_unit_mass.begin(), out.per_unit_mass.end(), uniform);
      return;
    }
    for (int p = 0; p < particles.size(); ++p)
      out.per_unit_mass[p] = uniform + field(particles.position[p], particles.reference_position[p], time);
  }
};

/// The power of the body force on the particles, \f$ P = \sum_p m_p\, \mathbf b_p \cdot \mathbf v_p \f$,
/// whose time integral is the external work of the energy balance; \f$ \mathbf b \cdot \sum_p m_p \mathbf v_p \f$
/// with the total momentum when b is uniform.
template <int Dim>
double body_force_power(const Particles<Dim>& particles, const ParticleBodyForces<Dim>& body_force, const Vector<Dim>& momentum) {
  if (body_force.all_zero) return 0.0;
  if (body_force.uniform) return body_force.per_unit_mass.empty() ? 0.0 : body_force.per_unit_mass[0].dot(momentum);
  double power = 0.0;
  for (int p = 0; p < particles.size(); ++p) power += particles.mass[p] * body_force.per_unit_mass[p].dot(particles.velocity[p]);
  return power;
}

TEST_CASE("Body force: gravity alone is uniform, a field adds b(x, X, t) per particle, the power by hand") {
  Particles<2> particles;
  particles.add(Vector<2>(1.0, 2.0), 2.0, 1.0, Vector<2>(1.0, 0.0), Vector<2>(0.5, 0.5));
  particles.add(Vector<2>(3.0, 0.0), 4.0, 1.0, Vector<2>(0.0, -1.0), Vector<2>(0.5, 0.5));
  particles.position[1] = Vector<2>(3.5, 0.0);  // moved from X = (3, 0)
  auto momentum = [](const Particles<2>& all) { return Vector<2>(all.mass[0] * all.velocity[0] + all.mass[1] * all.velocity[1]); };
  BodyForce<2> body_force;
  ParticleBodyForces<2> b;
  body_force.evaluate(0.3, particles, b);
  CHECK(b.all_zero);
  CHECK(body_force_power(particles, b, momentum(particles)) == 0.0);

  body_force.gravity.acceleration = Vector<2>(0.0, -10.0);
  body_force.evaluate(0.3, particles, b);
  REQUIRE(!b.all_zero);
  CHECK(b.per_unit_mass[0] == Vector<2>(0.0, -10.0));
  CHECK(b.per_unit_mass[1] == Vector<2>(0.0, -10.0));
  CHECK(body_force_power(particles, b, momentum(particles)) == doctest::Approx(4.0 * 10.0));  // m_1 |g| |v_1|, falling

  // b = (t x, X): at t = 0.5, particle 1 has x = 3.5 and X = 3.
  body_force.field = [](const Vector<2>& x, const Vector<2>& reference, double t) { return Vector<2>(t * x[0], reference[0]); };
  body_force.evaluate(0.5, particles, b);
  CHECK(b.per_unit_mass[0][0] == doctest::Approx(0.5));
  CHECK(b.per_unit_mass[0][1] == doctest::Approx(-10.0 + 1.0));
  CHECK(b.per_unit_mass[1][0] == doctest::Approx(1.75));
  CHECK(b.per_unit_mass[1][1] == doctest::Approx(-10.0 + 3.0));
  // P = 2 (0.5, -9) . (1, 0) + 4 (1.75, -7) . (0, -1) = 1 + 28
  CHECK(body_force_power(particles, b, momentum(particles)) == doctest::Approx(29.0));
}

}  // namespace mpm
