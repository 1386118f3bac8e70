/// \file
/// Global balances of the particle system, for output and for the checks of a run.
#pragma once
#include <doctest/doctest.h>

#include "mpm/particles/particles.hpp"

namespace mpm {

template <int Dim>
struct Balances {
  double kinetic = 0.0;  ///< \f$ \sum_p \tfrac12 m_p |\mathbf v_p|^2 \f$
  double strain = 0.0;   ///< \f$ \sum_p \tfrac12 V_p\, \boldsymbol\sigma_p : \boldsymbol\varepsilon_p \f$ (plane strain: eps_zz = 0)
  Vector<Dim> momentum = Vector<Dim>::Zero();  ///< \f$ \sum_p m_p \mathbf v_p \f$
  double mass = 0.0;
  double total() const { return kinetic + strain; }
};

/// Adds particle p's share to the balances.
template <int Dim>
void add_to_balances(const Particles<Dim>& particles, int p, Balances<Dim>& sum) {
  sum.kinetic += 0.5 * particles.mass[p] * particles.velocity[p].squaredNorm();
  sum.strain += 0.5 * particles.volume(p) * (particles.stress[p].array() * particles.strain[p].array()).sum();
  sum.momentum += particles.mass[p] * particles.velocity[p];
  sum.mass += particles.mass[p];
}

template <int Dim>
Balances<Dim> balances(const Particles<Dim>& particles) {
  Balances<Dim> sum;
  for (int p = 0; p < particles.size(); ++p) add_to_balances(particles, p, sum);
  return sum;
}

TEST_CASE("Balances: kinetic and strain energy and momentum by hand") {
  Particles<1> particles;
  particles.add(Vector<1>(0.0), 2.0, 4.0, Vector<1>(3.0), Vector<1>(0.5));
  particles.strain[0](0, 0) = 0.01;
  particles.stress[0](0, 0) = 100.0;
  const auto sum = balances(particles);
  CHECK(sum.kinetic == doctest::Approx(9.0));
  CHECK(sum.strain == doctest::Approx(0.5 * 0.5 * 100.0 * 0.01));
  CHECK(sum.momentum[0] == doctest::Approx(6.0));
}

}  // namespace mpm
