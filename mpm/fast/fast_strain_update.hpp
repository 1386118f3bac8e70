/// \file
/// The fast forms of the stress update of mpm/transfer/strain_update.hpp (their reference): the particles on every
/// core (parallel_for, mpm/core/parallel.hpp), and in 2D the strain rate in components.
#pragma once
#include <doctest/doctest.h>

#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/random_state.hpp"
#include "mpm/material/linear_elastic.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/strain_update.hpp"

namespace mpm::fast {

/// Eq. (16) in components (the reference: mpm::strain_rate). In 2D
/// \f$ \dot\varepsilon_{aa} = \sum_I v_{Ia}\, \partial_a N_I \f$ and
/// \f$ \dot\varepsilon_{xy} = \tfrac12 \sum_I (v_{Iy}\, \partial_x N_I + v_{Ix}\, \partial_y N_I) \f$: the products
/// \f$ \nabla N \odot \mathbf v \f$ and \f$ \nabla N \odot (v_y, v_x) \f$, two per node, where the full velocity
/// gradient takes four (benchmarks/README.md).
template <int Dim>
Matrix<Dim> strain_rate(const Stencils<Dim>& stencils, int p, const std::vector<Vector<Dim>>& nodal_velocity) {
  const ParticleStencil<Dim> stencil = stencils.of(p);
  const Vector<Dim>* velocity = nodal_velocity.data();
  if constexpr (Dim == 1) {
    return stencil_sum<Matrix<1>>(stencil,
                                  [&](int k) { return velocity[stencil.node[k]] * stencil.gradient[k].transpose(); });
  } else {
    Eigen::Array2d diagonal = Eigen::Array2d::Zero(), crossed = Eigen::Array2d::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      const Eigen::Array2d gradient = stencil.gradient[k].array(), v = velocity[stencil.node[k]].array();
      diagonal += gradient * v;
      crossed += gradient * v.reverse();
    }
    Matrix<2> rate;
    rate(0, 0) = diagonal[0], rate(1, 1) = diagonal[1];
    rate(0, 1) = rate(1, 0) = 0.5 * (crossed[0] + crossed[1]);
    return rate;
  }
}

/// Eqs. (16), (17) and (3) on every core: strain, density and stress of each particle (the reference:
/// mpm::update_strain_density_stress).
template <int Dim>
void update_strain_density_stress(const FastKernels&, const Stencils<Dim>& stencils,
                                  const std::vector<Vector<Dim>>& nodal_velocity,
                                  const std::vector<LinearElastic>& materials, double dt, Particles<Dim>& particles) {
  parallel_for(particles.size(), stencils.capacity, [&](int p) {
    const LinearElastic& material = materials[particles.material[p]];
    const Matrix<Dim> rate = fast::strain_rate(stencils, p, nodal_velocity);
    particles.strain[p] += dt * rate;
    particles.density[p] = updated_density(particles.density[p], dt, rate.trace());
    particles.stress[p] = material.stress<Dim>(particles.strain[p]);
    particles.stress_zz[p] = material.stress_zz<Dim>(particles.strain[p]);
  });
}

TEST_CASE("Eq. (16), Eq. (17), Eq. (3): the fast strain rate and stress update against their reference on random states, 1D and 2D, four shapes") {
  testing::on_random_states([](auto state) {
    constexpr int Dim = decltype(state)::dimension;
    const std::vector<LinearElastic> materials{LinearElastic{1e4, 0.3, 1.0}};
    std::vector<Matrix<Dim>> fast_rates, reference_rates;
    for (int p = 0; p < state.particles.size(); ++p) {
      fast_rates.push_back(fast::strain_rate(state.stencils, p, state.fields.nodal_velocity_k));
      reference_rates.push_back(mpm::strain_rate(state.stencils, p, state.fields.nodal_velocity_k));
    }
    CHECK(testing::relative_difference(reference_rates, fast_rates) <= 1e-12);
    auto fast = state.particles, reference = state.particles;
    update_strain_density_stress(FastKernels{}, state.stencils, state.fields.nodal_velocity_k, materials, 1e-3, fast);
    update_strain_density_stress(ReferenceKernels{}, state.stencils, state.fields.nodal_velocity_k, materials, 1e-3,
                                 reference);
    CHECK(testing::relative_difference(reference.strain, fast.strain) <= 1e-12);
    CHECK(testing::relative_difference(reference.density, fast.density) <= 1e-12);
    CHECK(testing::relative_difference(reference.stress, fast.stress) <= 1e-12);
    CHECK(testing::relative_difference(reference.stress_zz, fast.stress_zz) <= 1e-12);
  });
}

}  // namespace mpm::fast
