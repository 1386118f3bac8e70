/// \file
/// Nodal forces: the internal force of the stresses and the external body force.
///
/// They come from the weak form of the balance of momentum, Eq. (2)
/// \f$ \rho\, D\mathbf v/Dt = \nabla\cdot\boldsymbol\sigma + \rho\mathbf b \f$: Eq. (7),
/// \f$ \int_\Omega \rho(\dot{\mathbf v} - \mathbf b)\cdot\mathbf u^\psi = \int_{\Gamma_t} \mathbf t\cdot\mathbf u^\psi - \int_\Omega \boldsymbol\sigma : \boldsymbol\varepsilon^\psi \f$,
/// with test functions that vanish on the Dirichlet boundary, Eq. (5), and are square integrable
/// with their strains, Eq. (6). The particles are the quadrature points: Eq. (8) turns the inertia
/// term into \f$ \sum_p m_p \mathbf a_p\cdot\mathbf u^\psi_p \f$ (the lumped mass, Eq. 13), Eq. (9) the stress
/// term into \f$ \sum_p V_p \boldsymbol\sigma_p : \boldsymbol\varepsilon^\psi_p \f$ (Eq. 14) and Eq. (10) the body
/// force into \f$ \sum_p m_p \mathbf b\cdot\mathbf u^\psi_p \f$ (Eq. 15).
///
/// Contract: read the particles' m_p, rho_p, sigma_p and the stencils; add into nodal_force.
#pragma once
#include <doctest/doctest.h>

#include "mpm/core/parallel.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// Eq. (14): \f$ \mathbf f_I^{int} = -\sum_p \boldsymbol\sigma_p \nabla N_{Ip}\, \frac{m_p}{\rho_p} \f$,
/// with the particle volume V_p = m_p / rho_p of the current density.
template <int Dim>
void add_internal_force(const Particles<Dim>& particles, const Stencils<Dim>& stencils, GridFields<Dim>& grid) {
  scatter_to_nodes(particles.size(), grid.nodal_force, grid.vector_copies, [&](int p, Vector<Dim>* nodal_force) {
    const Matrix<Dim> volume_stress = particles.volume(p) * particles.stress[p];
    for (int k = stencils.begin(p); k < stencils.end(p); ++k) nodal_force[stencils.node[k]] -= volume_stress * stencils.gradient[k];
  });
}

/// Eq. (15), body-force part: \f$ \mathbf f_I^{ext} = \sum_p N_{Ip}\, m_p \mathbf b \f$ (no tractions in
/// this project's scenes; Eq. (11)'s surface term is not implemented).
template <int Dim>
void add_body_force(const Particles<Dim>& particles, const Stencils<Dim>& stencils, const Vector<Dim>& body_force,
                    GridFields<Dim>& grid) {
  if (body_force.squaredNorm() == 0.0) return;
  scatter_to_nodes(particles.size(), grid.nodal_force, grid.vector_copies, [&](int p, Vector<Dim>* nodal_force) {
    for (int k = stencils.begin(p); k < stencils.end(p); ++k)
      nodal_force[stencils.node[k]] += stencils.value[k] * particles.mass[p] * body_force;
  });
}

TEST_CASE("Eq. (9), Eq. (10), Eqs. (14)-(15): nodal forces on the worked example: the internal force by hand, the body force sums to the weight") {
  testing::WorkedExample example;
  add_internal_force(example.particles, example.stencils, example.fields);
  CHECK(example.fields.nodal_force[0][0] == doctest::Approx(5.0));
  CHECK(example.fields.nodal_force[1][0] == doctest::Approx(-25.0));
  CHECK(example.fields.nodal_force[2][0] == doctest::Approx(20.0));
  example.fields.reset();
  add_body_force(example.particles, example.stencils, Vector<1>(-9.81), example.fields);
  CHECK(example.fields.nodal_force[0][0] == doctest::Approx(-9.81 * 1.5));
  CHECK(example.fields.nodal_force[0][0] + example.fields.nodal_force[1][0] + example.fields.nodal_force[2][0] ==
        doctest::Approx(-9.81 * 6.0));
}

}  // namespace mpm
