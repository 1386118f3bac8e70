/// \file
/// The fast forms of the grid-to-particle transfers of mpm/transfer/grid_to_particle.hpp (their reference): the
/// node loops and the particle loops on every core (parallel_for, mpm/core/parallel.hpp). The variants' node loops
/// (the nodal velocity that moves the particles) are the reference file's, run here by for_each_node.
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

/// A loop over the nodes on every core (the reference: mpm::for_each_node, serial). Each node writes its own fields,
/// so the bits do not depend on the threads.
template <class Body>
void for_each_node(const FastKernels&, int nodes, Body&& body) {
  parallel_for(nodes, 1, body);
}

/// Eqs. (19)-(22), forward Euler's particle loop with FLIP's increment, on every core (the reference:
/// mpm::forward_euler_particle_update).
template <int Dim>
void forward_euler_particle_update(const FastKernels&, const Stencils<Dim>& stencils, const std::vector<Vector<Dim>>& a_I,
                           const std::vector<Vector<Dim>>& v_I, double dt, Particles<Dim>& particles) {
  const Vector<Dim>*nodal_acceleration = a_I.data(), *moving_velocity = v_I.data();
  parallel_for(particles.size(), stencils.capacity, [&](int p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> acceleration = Vector<Dim>::Zero(), velocity = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      acceleration += stencil.value[k] * nodal_acceleration[stencil.node[k]];
      velocity += stencil.value[k] * moving_velocity[stencil.node[k]];
    }
    particles.velocity[p] += dt * acceleration;
    particles.position[p] += dt * velocity;
  });
}

/// The PIC/FLIP blend on every core (the reference: mpm::pic_flip_blend).
template <int Dim>
void pic_flip_blend(const FastKernels&, const Stencils<Dim>& stencils, double flip_fraction,
                    const std::vector<Vector<Dim>>& v_I_k1, Particles<Dim>& particles) {
  const Vector<Dim>* updated_velocity = v_I_k1.data();
  parallel_for(particles.size(), stencils.capacity, [&](int p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> pic_velocity = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) pic_velocity += stencil.value[k] * updated_velocity[stencil.node[k]];
    const Vector<Dim> flip_velocity = particles.velocity[p];
    particles.velocity[p] = flip_fraction * flip_velocity + (1.0 - flip_fraction) * pic_velocity;
  });
}

/// Eqs. (31)-(33) with the particle-velocity rule `Rule` (Eq. (32) or Eq. (23)) on every core (the reference:
/// mpm::newmark_particle_update).
template <class Rule, int Dim>
void newmark_particle_update(const FastKernels&, const Stencils<Dim>& stencils, const std::vector<Vector<Dim>>& a_I_k1,
                             const std::vector<Vector<Dim>>& v_I, double newmark_gamma, double dt, Rule,
                             Particles<Dim>& particles) {
  const Vector<Dim>*nodal_acceleration = a_I_k1.data(), *moving_velocity = v_I.data();
  parallel_for(particles.size(), stencils.capacity, [&](int p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> acceleration = Vector<Dim>::Zero(), velocity = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      acceleration += stencil.value[k] * nodal_acceleration[stencil.node[k]];
      velocity += stencil.value[k] * moving_velocity[stencil.node[k]];
    }
    const Vector<Dim> old_acceleration = particles.acceleration[p];
    particles.acceleration[p] = acceleration;
    particles.velocity[p] = Rule::velocity(particles.velocity[p], old_acceleration, acceleration, newmark_gamma, dt);
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
          forward_euler_g2p(kernels, state.stencils, grid, dt, euler_position_rule(position),
                            euler_velocity_rule(flip_fraction), particles);
        });
    for (const auto position : {NewmarkPositionVelocity::projected, NewmarkPositionVelocity::corrected,
                                NewmarkPositionVelocity::predicted})
      for (const auto velocity : {NewmarkParticleVelocity::eq32, NewmarkParticleVelocity::average})
        check(state.particles, state.particles, [&](auto kernels, auto& grid, auto& particles) {
          newmark_g2p(kernels, state.stencils, grid, 0.6, dt, newmark_position_rule(position),
                      newmark_velocity_rule(velocity), particles);
        });
  });
}

}  // namespace mpm::fast
