/// \file
/// The fast forms of the grid-to-particle transfers of mpm/transfer/grid_to_particle.hpp (their reference): the
/// nodes and then the particles on every core (parallel_for, mpm/core/parallel.hpp).
#pragma once
#include <doctest/doctest.h>

#include "mpm/core/kernels.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/random_state.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/grid_to_particle.hpp"

namespace mpm::fast {

/// Eqs. (19)-(22) and the PIC/FLIP blend on every core (the reference: mpm::forward_euler_particle_update).
template <int Dim>
void forward_euler_particle_update(const FastKernels&, const Stencils<Dim>& stencils, GridFields<Dim>& grid, double dt,
                                   EulerPositionVelocity position_velocity, Particles<Dim>& particles,
                                   double flip_fraction = 1.0) {
  // The nodes first: a_I = f_I / m_I, p_I / m_I, and the velocity that moves the particles.
  parallel_for(grid.size(), 1, [&](int node) {
    const bool has_mass = grid.nodal_mass[node] > 0.0;
    const double mass = grid.nodal_mass[node];
    grid.nodal_acceleration[node] = has_mass ? Vector<Dim>(grid.nodal_force[node] / mass) : Vector<Dim>::Zero();
    grid.projected_velocity[node] = has_mass ? Vector<Dim>(grid.nodal_momentum[node] / mass) : Vector<Dim>::Zero();
    grid.moving_velocity[node] = position_velocity == EulerPositionVelocity::updated ? grid.projected_velocity[node]
                                 : has_mass                                         ? grid.nodal_velocity[node]
                                                                                    : Vector<Dim>::Zero();
  });
  // Then the particles: sums of N_Ip times nodal values.
  const bool blend = flip_fraction != 1.0;
  const Vector<Dim>*nodal_acceleration = grid.nodal_acceleration.data(), *moving_velocity = grid.moving_velocity.data(),
                    *projected_velocity = grid.projected_velocity.data();
  parallel_for(particles.size(), stencils.capacity, [&](int p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> acceleration = Vector<Dim>::Zero(), velocity = Vector<Dim>::Zero();
    Vector<Dim> updated_velocity = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      acceleration += stencil.value[k] * nodal_acceleration[stencil.node[k]];
      velocity += stencil.value[k] * moving_velocity[stencil.node[k]];
    }
    if (blend)
      for (int k = 0; k < stencil.count; ++k)
        updated_velocity += stencil.value[k] * projected_velocity[stencil.node[k]];
    const Vector<Dim> flip_velocity = particles.velocity[p] + dt * acceleration;
    particles.velocity[p] =
        blend ? Vector<Dim>(flip_fraction * flip_velocity + (1.0 - flip_fraction) * updated_velocity) : flip_velocity;
    particles.position[p] += dt * velocity;
  });
}

/// Eqs. (31)-(33), or Eq. (23) for the velocity, on every core (the reference: mpm::newmark_particle_update).
template <int Dim>
void newmark_particle_update(const FastKernels&, const Stencils<Dim>& stencils, GridFields<Dim>& grid,
                             double newmark_gamma, double dt,
                             NewmarkPositionVelocity position_velocity, Particles<Dim>& particles,
                             NewmarkParticleVelocity particle_velocity = NewmarkParticleVelocity::eq32) {
  // The nodes first: a_I = f_I / m_I and the velocity that moves the particles.
  parallel_for(grid.size(), 1, [&](int node) {
    if (grid.nodal_mass[node] <= 0.0) {
      grid.nodal_acceleration[node].setZero();
      grid.moving_velocity[node].setZero();
      return;
    }
    const Vector<Dim> nodal_acceleration_I = grid.nodal_force[node] / grid.nodal_mass[node];
    Vector<Dim> nodal_velocity_I = grid.nodal_velocity[node];
    if (position_velocity == NewmarkPositionVelocity::predicted)
      nodal_velocity_I -= newmark_gamma * dt * nodal_acceleration_I;
    if (position_velocity == NewmarkPositionVelocity::projected)
      nodal_velocity_I = grid.nodal_momentum[node] / grid.nodal_mass[node];
    grid.nodal_acceleration[node] = nodal_acceleration_I;
    grid.moving_velocity[node] = nodal_velocity_I;
  });
  // Then the particles: sums of N_Ip times nodal values.
  const Vector<Dim>*nodal_acceleration = grid.nodal_acceleration.data(), *moving_velocity = grid.moving_velocity.data();
  parallel_for(particles.size(), stencils.capacity, [&](int p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> acceleration = Vector<Dim>::Zero(), velocity = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      acceleration += stencil.value[k] * nodal_acceleration[stencil.node[k]];
      velocity += stencil.value[k] * moving_velocity[stencil.node[k]];
    }
    const Vector<Dim> old_acceleration = particles.acceleration[p];
    particles.acceleration[p] = acceleration;
    particles.velocity[p] += particle_velocity == NewmarkParticleVelocity::eq32
                                 ? Vector<Dim>(dt * acceleration)
                                 : Vector<Dim>(dt * ((1.0 - newmark_gamma) * old_acceleration +
                                                     newmark_gamma * acceleration));
    particles.position[p] += dt * velocity + 0.5 * dt * dt * acceleration;
  });
}

TEST_CASE("Eq. (19), Eq. (20), Eq. (21), Eq. (22), Eq. (23), Eq. (31), Eq. (32), Eq. (33): the fast G2P against its reference on random states, every variant, 1D and 2D, four shapes") {
  testing::on_random_states([](auto state) {
    auto check = [&](auto fast_state, auto reference_state, const auto& update) {
      auto fast_grid = state.fields, reference_grid = state.fields;
      update(FastKernels{}, fast_grid, fast_state);
      update(ReferenceKernels{}, reference_grid, reference_state);
      CHECK(testing::relative_difference(reference_state.velocity, fast_state.velocity) <= 1e-12);
      CHECK(testing::relative_difference(reference_state.position, fast_state.position) <= 1e-12);
      CHECK(testing::relative_difference(reference_state.acceleration, fast_state.acceleration) <= 1e-12);
      CHECK(testing::relative_difference(reference_grid.nodal_acceleration, fast_grid.nodal_acceleration) <= 1e-12);
      CHECK(testing::relative_difference(reference_grid.moving_velocity, fast_grid.moving_velocity) <= 1e-12);
    };
    const double dt = 0.01;
    for (const auto position : {EulerPositionVelocity::updated, EulerPositionVelocity::start})
      for (const double flip_fraction : {1.0, 0.7})
        check(state.particles, state.particles, [&](auto kernels, auto& grid, auto& particles) {
          forward_euler_particle_update(kernels, state.stencils, grid, dt, position, particles, flip_fraction);
        });
    for (const auto position : {NewmarkPositionVelocity::projected, NewmarkPositionVelocity::corrected,
                                NewmarkPositionVelocity::predicted})
      for (const auto velocity : {NewmarkParticleVelocity::eq32, NewmarkParticleVelocity::average})
        check(state.particles, state.particles, [&](auto kernels, auto& grid, auto& particles) {
          newmark_particle_update(kernels, state.stencils, grid, 0.6, dt, position, particles, velocity);
        });
  });
}

}  // namespace mpm::fast
