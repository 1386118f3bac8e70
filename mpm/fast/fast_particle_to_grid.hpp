/// \file
/// The fast forms of the particle-to-grid transfers of mpm/transfer/particle_to_grid.hpp (their reference): the
/// same sums, run on every core by scatter_to_nodes, which gives each chunk of particles its own copy of the
/// fields and adds the copies in chunk order (mpm/fast/scatter.hpp): the same bits on any number of threads.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/fast_stencils.hpp"
#include "mpm/fast/random_state.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/particle_to_grid.hpp"

namespace mpm::fast {

/// Eqs. (13), (21)-(22) on every core: \f$ m_I = \sum_p N_{Ip} m_p \f$, \f$ \mathbf p_I^k = \sum_p N_{Ip} m_p
/// \mathbf v_p^k \f$ (the reference: mpm::nodal_mass_and_momentum).
template <int Dim>
void nodal_mass_and_momentum(const FastKernels& kernels, const Particles<Dim>& particles,
                             const Stencils<Dim>& stencils, GridFields<Dim>& grid) {
  scatter_to_nodes(
      kernels, stencils,
      [&](int p, double* nodal_mass, Vector<Dim>* nodal_momentum) {
        const ParticleStencil<Dim> stencil = stencils.of(p);
        const double mass = particles.mass[p];
        const Vector<Dim> velocity = particles.velocity[p];
        for (int k = 0; k < stencil.count; ++k) {
          const double weighted_mass = stencil.value[k] * mass;  // N_Ip m_p
          nodal_mass[stencil.node[k]] += weighted_mass;
          nodal_momentum[stencil.node[k]] += weighted_mass * velocity;
        }
      },
      grid.nodal_mass, grid.nodal_momentum_k);
}

/// Eqs. (21)-(22) on every core, overwriting nodal_momentum_k1: \f$ \mathbf p_I^{k+1} = \sum_p N_{Ip} m_p
/// \mathbf v_p^{k+1} \f$ (MUSL; the reference: mpm::nodal_momentum_from_particles).
template <int Dim>
void nodal_momentum_from_particles(const FastKernels& kernels, const Particles<Dim>& particles,
                                   const Stencils<Dim>& stencils, GridFields<Dim>& grid) {
  for (Vector<Dim>& momentum : grid.nodal_momentum_k1) momentum.setZero();
  scatter_to_nodes(kernels, stencils, [&](int p, Vector<Dim>* nodal_momentum) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    const double mass = particles.mass[p];
    const Vector<Dim> velocity = particles.velocity[p];
    for (int k = 0; k < stencil.count; ++k) nodal_momentum[stencil.node[k]] += stencil.value[k] * mass * velocity;
  }, grid.nodal_momentum_k1);
}

/// Eqs. (13), (26)-(29) on every core: \f$ m_I \f$, \f$ \mathbf p_I^k \f$ and
/// \f$ \mathbf v_I^{pred} = \sum_p N_{Ip} m_p (\mathbf v_p^k + (1-\gamma)\Delta t\, \mathbf a_p^k) / m_I \f$
/// (the reference: mpm::nodal_mass_and_velocity_predictor).
template <int Dim>
void nodal_mass_and_velocity_predictor(const FastKernels& kernels, const Particles<Dim>& particles,
                                       const Stencils<Dim>& stencils, double newmark_gamma, double dt,
                                       GridFields<Dim>& grid) {
  scatter_to_nodes(
      kernels, stencils,
      [&](int p, double* nodal_mass, Vector<Dim>* nodal_momentum, Vector<Dim>* predicted_velocity) {
        const ParticleStencil<Dim> stencil = stencils.of(p);
        const double mass = particles.mass[p];
        const Vector<Dim> momentum = mass * particles.velocity[p];
        const Vector<Dim> predicted = momentum + (1.0 - newmark_gamma) * dt * mass * particles.acceleration[p];
        for (int k = 0; k < stencil.count; ++k) {
          const int node = stencil.node[k];
          nodal_mass[node] += stencil.value[k] * mass;
          nodal_momentum[node] += stencil.value[k] * momentum;
          predicted_velocity[node] += stencil.value[k] * predicted;  // divided by m_I below
        }
      },
      grid.nodal_mass, grid.nodal_momentum_k, grid.predicted_velocity);
  for (int node = 0; node < grid.size(); ++node) {
    const double mass = grid.nodal_mass[node];
    grid.predicted_velocity[node] =
        mass > 0.0 ? Vector<Dim>(grid.predicted_velocity[node] / mass) : Vector<Dim>::Zero();
  }
}

TEST_CASE("Eq. (13), Eq. (21), Eq. (22), Eq. (26), Eq. (27), Eq. (28), Eq. (29): the fast P2G against its reference on random states, 1D and 2D, four shapes") {
  testing::on_random_states([](auto state) {
    auto fast = state.fields, reference = state.fields;
    fast.reset(), reference.reset();
    nodal_mass_and_momentum(FastKernels{}, state.particles, state.stencils, fast);
    nodal_mass_and_momentum(ReferenceKernels{}, state.particles, state.stencils, reference);
    CHECK(testing::relative_difference(reference.nodal_mass, fast.nodal_mass) <= 1e-12);
    CHECK(testing::relative_difference(reference.nodal_momentum_k, fast.nodal_momentum_k) <= 1e-12);
    // MUSL's projection over whatever the field held, here the random momenta of the state
    fast.nodal_momentum_k1 = reference.nodal_momentum_k1 = state.fields.nodal_momentum_k1;
    nodal_momentum_from_particles(FastKernels{}, state.particles, state.stencils, fast);
    nodal_momentum_from_particles(ReferenceKernels{}, state.particles, state.stencils, reference);
    CHECK(testing::relative_difference(reference.nodal_momentum_k1, fast.nodal_momentum_k1) <= 1e-12);
    fast.reset(), reference.reset();
    nodal_mass_and_velocity_predictor(FastKernels{}, state.particles, state.stencils, 0.6, 0.01, fast);
    nodal_mass_and_velocity_predictor(ReferenceKernels{}, state.particles, state.stencils, 0.6, 0.01, reference);
    CHECK(testing::relative_difference(reference.nodal_mass, fast.nodal_mass) <= 1e-12);
    CHECK(testing::relative_difference(reference.nodal_momentum_k, fast.nodal_momentum_k) <= 1e-12);
    CHECK(testing::relative_difference(reference.predicted_velocity, fast.predicted_velocity) <= 1e-12);
  });
}

TEST_CASE("The fast scatter reads the nodes noted for its own stencils only: noted for particles in order, it scatters others in another order") {
  auto state = testing::random_state<2, LinearShape<2>>(9);
  const Grid<2> grid = state.grid;
  Particles<2> in_order = state.particles;  // the same particles sorted by y: narrow windows, one row band per chunk
  std::vector<int> order(in_order.size());
  for (int p = 0; p < in_order.size(); ++p) order[p] = p;
  auto lower = [&](int a, int b) { return state.particles.position[a][1] < state.particles.position[b][1]; };
  std::sort(order.begin(), order.end(), lower);
  for (int p = 0; p < in_order.size(); ++p) in_order.position[p] = state.particles.position[order[p]];
  LinearShape<2> shape(grid);
  Stencils<2> sorted;
  sorted.resize(in_order.size(), shape.capacity());
  const FastKernels kernels;
  compute_stencils(kernels, shape, in_order.position, sorted);
  REQUIRE(kernels.scratch.reached[1].end - kernels.scratch.reached[1].begin < grid.node_count() / 2);
  GridFields<2> fast(grid.node_count()), reference(grid.node_count());
  nodal_mass_and_momentum(kernels, state.particles, state.stencils, fast);  // the random order's stencils
  nodal_mass_and_momentum(ReferenceKernels{}, state.particles, state.stencils, reference);
  CHECK(testing::relative_difference(reference.nodal_mass, fast.nodal_mass) <= 1e-12);
  CHECK(testing::relative_difference(reference.nodal_momentum_k, fast.nodal_momentum_k) <= 1e-12);
}


}  // namespace mpm::fast
