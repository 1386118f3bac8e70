/// \file
/// The fast form of the nodal forces of mpm/transfer/nodal_forces.hpp (its reference): the particles scattered to
/// the nodes on every core (scatter_to_nodes, mpm/fast/scatter.hpp), and in 2D the internal force in components.
#pragma once
#include <doctest/doctest.h>

#include "mpm/core/kernels.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/fast_stencils.hpp"
#include "mpm/fast/random_state.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/nodal_forces.hpp"

namespace mpm::fast {

/// Eqs. (14)-(15) on every core, \f$ \mathbf f_I = \sum_p ( N_{Ip}\, m_p \mathbf b_p - \boldsymbol\sigma_p \nabla
/// N_{Ip}\, V_p ) \f$ (the reference: mpm::add_nodal_forces). In 2D, sigma being symmetric (Eq. (3) of a
/// symmetric strain; set_initial_stress refuses any other),
/// \f$ \boldsymbol\sigma \nabla N = (\sigma_{xx}, \sigma_{yy}) \odot \nabla N + \sigma_{xy} (\partial_y N,
/// \partial_x N) \f$: two products per node, where the matrix-vector product takes four (benchmarks/README.md).
template <int Dim>
void add_nodal_forces(const FastKernels& kernels, const Particles<Dim>& particles, const Stencils<Dim>& stencils,
                      const ParticleBodyForces<Dim>& body_force, GridFields<Dim>& grid) {
  scatter_to_nodes(kernels, stencils, [&](int p, Vector<Dim>* nodal_force) {
    const Matrix<Dim> volume_stress = particles.volume(p) * particles.stress[p];
    const Vector<Dim> weight =  // m_p b_p (per_unit_mass is not filled when every b_p is zero)
        body_force.all_zero ? Vector<Dim>::Zero() : Vector<Dim>(particles.mass[p] * body_force.per_unit_mass[p]);
    const ParticleStencil<Dim> stencil = stencils.of(p);
    if constexpr (Dim == 1) {
      for (int k = 0; k < stencil.count; ++k)
        nodal_force[stencil.node[k]] += stencil.value[k] * weight - volume_stress * stencil.gradient[k];
    } else {
      const Eigen::Array2d diagonal(volume_stress(0, 0), volume_stress(1, 1));
      const double shear = volume_stress(0, 1);
      for (int k = 0; k < stencil.count; ++k) {
        const Eigen::Array2d gradient = stencil.gradient[k].array();
        const Eigen::Array2d sigma_grad_N = diagonal * gradient + shear * gradient.reverse();
        nodal_force[stencil.node[k]] += stencil.value[k] * weight - sigma_grad_N.matrix();
      }
    }
  }, grid.nodal_force);
}

TEST_CASE("Eq. (14), Eq. (15): the fast nodal forces against their reference on random states, 1D and 2D, four shapes, with and without body forces") {
  testing::on_random_states([](auto state) {
    for (const bool with_body_force : {true, false}) {
      auto body_force = state.body_force;
      body_force.all_zero = !with_body_force;
      auto fast = state.fields, reference = state.fields;  // adds into the random forces the state holds
      add_nodal_forces(FastKernels{}, state.particles, state.stencils, body_force, fast);
      add_nodal_forces(ReferenceKernels{}, state.particles, state.stencils, body_force, reference);
      CHECK(testing::relative_difference(reference.nodal_force, fast.nodal_force) <= 1e-12);
      CHECK(testing::relative_difference(state.fields.nodal_force, reference.nodal_force) > 1e-3);
    }
  });
}

}  // namespace mpm::fast
