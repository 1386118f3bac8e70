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
/// Contract: read the particles' m_p, rho_p, sigma_p and the stencils; add into nodal_force. This is the reference
/// kernel, a plain serial loop; its fast form is in mpm/fast/fast_nodal_forces.hpp.
#pragma once
#include <doctest/doctest.h>

#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// Eqs. (14)-(15), in one pass over the particles and their stencil nodes: the internal force of the stresses,
/// Eq. (14),
/// \f$ \mathbf f_I^{int} = -\sum_p \boldsymbol\sigma_p \nabla N_{Ip}\, \frac{m_p}{\rho_p} \f$, with the particle
/// volume V_p = m_p / rho_p of the current density, and the body-force part of Eq. (15),
/// \f$ \mathbf f_I^{ext} = \sum_p N_{Ip}\, m_p \mathbf b_p \f$, with b_p the body force per unit mass at each
/// particle (loading/body_force.hpp; no tractions in this project's scenes; Eq. (11)'s surface term is
/// not implemented):
/// \f[ \mathbf f_I = \sum_p \left( N_{Ip}\, m_p \mathbf b_p - \boldsymbol\sigma_p \nabla N_{Ip}\, V_p \right) . \f]
template <int Dim>
void add_nodal_forces(ReferenceKernels, const Particles<Dim>& particles, const Stencils<Dim>& stencils,
                      const ParticleBodyForces<Dim>& body_force, GridFields<Dim>& grid) {
  std::vector<Vector<Dim>>& f_I = grid.nodal_force;
  for (int p = 0; p < particles.size(); ++p) {
    const Matrix<Dim> V_p_sigma_p = particles.volume(p) * particles.stress[p];
    const Vector<Dim> m_p_b_p =  // (per_unit_mass is not filled when every b_p is zero)
        body_force.all_zero ? Vector<Dim>::Zero() : Vector<Dim>(particles.mass[p] * body_force.per_unit_mass[p]);
    const ParticleStencil<Dim> stencil = stencils.of(p);
    for (int k = 0; k < stencil.count; ++k) {
      const double N_Ip = stencil.value[k];
      const Vector<Dim>& grad_N_Ip = stencil.gradient[k];
      f_I[stencil.node[k]] += N_Ip * m_p_b_p - V_p_sigma_p * grad_N_Ip;
    }
  }
}

TEST_CASE("Eq. (9), Eq. (10), Eq. (14), Eq. (15): nodal forces on the worked example: the internal force by hand, the body force sums to the weight") {
  // At t = 0 (no stress yet) the nodal forces are the weight alone, b = 10:
  // (0.75 * 2 * 10, 0.25 * 2 * 10 + 0.5 * 4 * 10, 0.5 * 4 * 10) = (15, 25, 20), summing to (2 + 4) 10 = 60.
  testing::WorkedExample example;
  const ParticleBodyForces<1> gravity = testing::WorkedExample::body_force();
  add_nodal_forces(ReferenceKernels{}, example.particles, example.stencils, gravity, example.fields);
  CHECK(example.fields.nodal_force[0][0] == doctest::Approx(15.0));
  CHECK(example.fields.nodal_force[1][0] == doctest::Approx(25.0));
  CHECK(example.fields.nodal_force[0][0] + example.fields.nodal_force[1][0] + example.fields.nodal_force[2][0] ==
        doctest::Approx(60.0));
  // The first step's state after the stress update (strain_update.hpp's doctest, v_I^k = (1, -1, 0)): strains
  // (-0.4, 0.2), sigma = E eps = (-10, 5) Pa, rho = 4 / (1 + eps) = (20/3, 10/3), V = (0.3, 1.2).
  // f^int = -sigma V grad N: (-(-10)(0.3)(-1), -(-10)(0.3)(1) - (5)(1.2)(-1), -(5)(1.2)(1)) = (-3, 9, -6);
  // with the weight, f_I = (12, 34, 14); node 2 is held, its 14 becomes the reaction.
  const double strain[2] = {-0.4, 0.2};
  for (int p = 0; p < 2; ++p) {
    example.particles.strain[p](0, 0) = strain[p];
    example.particles.stress[p](0, 0) = example.young_modulus * strain[p];
    example.particles.density[p] = example.density / (1.0 + strain[p]);
  }
  example.fields.reset();
  const ParticleBodyForces<1> none{{Vector<1>(0.0), Vector<1>(0.0)}, true, true};
  add_nodal_forces(ReferenceKernels{}, example.particles, example.stencils, none, example.fields);
  CHECK(example.fields.nodal_force[0][0] == doctest::Approx(-3.0));
  CHECK(example.fields.nodal_force[1][0] == doctest::Approx(9.0));
  CHECK(example.fields.nodal_force[2][0] == doctest::Approx(-6.0));
  example.fields.reset();
  add_nodal_forces(ReferenceKernels{}, example.particles, example.stencils, gravity, example.fields);
  CHECK(example.fields.nodal_force[0][0] == doctest::Approx(12.0));
  CHECK(example.fields.nodal_force[1][0] == doctest::Approx(34.0));
  CHECK(example.fields.nodal_force[2][0] == doctest::Approx(14.0));
  // A different b_p per particle, (3, -2): (0.75 * 2 * 3, 0.25 * 2 * 3 - 0.5 * 4 * 2, -0.5 * 4 * 2) = (4.5, -2.5, -4),
  // plus the internal force: (1.5, 6.5, -10); the body forces still sum to sum_p m_p b_p = 6 - 8 = -2.
  example.fields.reset();
  const ParticleBodyForces<1> field{{Vector<1>(3.0), Vector<1>(-2.0)}, false, false};
  add_nodal_forces(ReferenceKernels{}, example.particles, example.stencils, field, example.fields);
  CHECK(example.fields.nodal_force[0][0] == doctest::Approx(-3.0 + 4.5));
  CHECK(example.fields.nodal_force[1][0] == doctest::Approx(9.0 - 2.5));
  CHECK(example.fields.nodal_force[2][0] == doctest::Approx(-6.0 - 4.0));
  CHECK(example.fields.nodal_force[0][0] + example.fields.nodal_force[1][0] + example.fields.nodal_force[2][0] ==
        doctest::Approx(example.particles.mass[0] * 3.0 - example.particles.mass[1] * 2.0));
}

TEST_CASE("Eq. (14): the internal force in 2D by hand, with a shear stress: f_I = -V_p sigma_p grad N_Ip") {
  // One particle of volume 1 (m = 2, rho = 2) at (0.25, 0.5) in the unit cell, sigma = [[2, 7], [7, 3]].
  // Node (0, 0): grad N = (-(1 - 0.5), -(1 - 0.25)) = (-0.5, -0.75), sigma grad N = (-1 - 5.25, -3.5 - 2.25),
  // so f = (6.25, 5.75). Node (1, 1): grad N = (0.5, 0.25), sigma grad N = (1 + 1.75, 3.5 + 0.75): f = (-2.75, -4.25).
  const Grid<2> grid(Vector<2>::Zero(), 1.0, {1, 1});
  LinearShape<2> q4(grid);
  Particles<2> particles;
  particles.add(Vector<2>(0.25, 0.5), 2.0, 2.0, Vector<2>::Zero(), Vector<2>(0.25, 0.25));
  particles.stress[0] << 2.0, 7.0, 7.0, 3.0;
  Stencils<2> stencils;
  stencils.resize(1, q4.capacity());
  compute_stencils(q4, particles.position, stencils);
  GridFields<2> fields(grid.node_count());
  const ParticleBodyForces<2> none{{Vector<2>::Zero()}, true, true};
  add_nodal_forces(ReferenceKernels{}, particles, stencils, none, fields);
  const int lower = grid.node_index({0, 0}), upper = grid.node_index({1, 1});
  CHECK(fields.nodal_force[lower][0] == doctest::Approx(6.25).epsilon(1e-14));
  CHECK(fields.nodal_force[lower][1] == doctest::Approx(5.75).epsilon(1e-14));
  CHECK(fields.nodal_force[upper][0] == doctest::Approx(-2.75).epsilon(1e-14));
  CHECK(fields.nodal_force[upper][1] == doctest::Approx(-4.25).epsilon(1e-14));
}

}  // namespace mpm
