/// \file
/// Grid-to-particle transfers (G2P): the particle update of each integrator, Eq. (18) applied.
///
/// Contract: read nodal_mass, nodal_momentum, nodal_velocity, nodal_force and the stencils; write, node by
/// node, the rates the particles interpolate (nodal_acceleration, moving_velocity, projected_velocity: one
/// division by m_I per node, not per particle-node pair), then the particles' x_p, v_p (and a_p for the
/// predictor-corrector). These are the reference kernels, plain serial loops; their fast forms, on every core, are in
/// mpm/fast/fast_grid_to_particle.hpp.
#pragma once
#include <doctest/doctest.h>

#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// Which nodal velocity moves the particles in the forward-Euler update (paper/09_choices.md, 'The position update of forward Euler').
enum class EulerPositionVelocity {
  updated,  ///< the authors' code: p_I after p_I += dt f_I, i.e. v_I^{k+1} (default)
  start     ///< the literal Eqs. (20)-(21): v_I^k = p_I^k / m_I
};

/// Eqs. (19)-(22), forward Euler in momentum form (Eq. (19) and Eq. (20) in velocities, Eq. (21) and Eq. (22) in momenta):
/// \f$ \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t \sum_I N_{Ip} \mathbf f_I / m_I \f$ and
/// \f$ \mathbf x_p^{k+1} = \mathbf x_p^k + \Delta t \sum_I N_{Ip} \mathbf p_I / m_I \f$.
/// Expects nodal_velocity = v_I^k and nodal_momentum = p_I^{k+1} (after update_nodal_momentum).
///
/// With flip_fraction \f$ \alpha < 1 \f$ the velocity is the PIC/FLIP blend of Brackbill's FLIP and
/// Zhu and Bridson (2005), a standard damping of explicit MPM (paper/10_integrator_analysis.md):
/// \f[ \mathbf v_p^{k+1} = \alpha \left(\mathbf v_p^k + \Delta t \sum_I N_{Ip} \frac{\mathbf f_I}{m_I}\right)
///     + (1-\alpha) \sum_I N_{Ip} \frac{\mathbf p_I^{k+1}}{m_I} . \f]
/// \f$ \alpha = 1 \f$ (the paper's scheme) is bit for bit the pure FLIP increment.
template <int Dim>
void forward_euler_particle_update(ReferenceKernels, const Stencils<Dim>& stencils, GridFields<Dim>& grid, double dt,
                                   EulerPositionVelocity position_velocity, Particles<Dim>& particles,
                                   double flip_fraction = 1.0) {
  // The nodes first (Eq. (18)'s nodal values, 0 on nodes without mass): a_I = f_I / m_I, p_I^{k+1} / m_I, and the
  // nodal velocity that moves the particles, p_I^{k+1} / m_I (updated) or v_I^k (start).
  for (int I = 0; I < grid.size(); ++I) {
    const double m_I = grid.nodal_mass[I];
    const bool has_mass = m_I > 0.0;
    grid.nodal_acceleration[I] = has_mass ? Vector<Dim>(grid.nodal_force[I] / m_I) : Vector<Dim>::Zero();
    grid.projected_velocity[I] = has_mass ? Vector<Dim>(grid.nodal_momentum[I] / m_I) : Vector<Dim>::Zero();
    const Vector<Dim>& v_I_k = grid.nodal_velocity[I];
    grid.moving_velocity[I] = position_velocity == EulerPositionVelocity::updated ? grid.projected_velocity[I]
                              : has_mass                                         ? v_I_k
                                                                                 : Vector<Dim>::Zero();
  }
  // Then the particles: Eq. (18), sums of N_Ip times nodal values, and Eqs. (19)-(22).
  const std::vector<Vector<Dim>>& a_I = grid.nodal_acceleration;
  const std::vector<Vector<Dim>>& v_I_moving = grid.moving_velocity;
  const std::vector<Vector<Dim>>& v_I_k1 = grid.projected_velocity;  // p_I^{k+1} / m_I
  for (int p = 0; p < particles.size(); ++p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> a_p = Vector<Dim>::Zero(), v_moving = Vector<Dim>::Zero(), v_pic = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      const int I = stencil.node[k];
      const double N_Ip = stencil.value[k];
      a_p += N_Ip * a_I[I];
      v_moving += N_Ip * v_I_moving[I];
      v_pic += N_Ip * v_I_k1[I];
    }
    const Vector<Dim> v_p_flip = particles.velocity[p] + dt * a_p;  // v_p^k + dt sum_I N_Ip f_I / m_I
    const Vector<Dim> v_p_blend = flip_fraction * v_p_flip + (1.0 - flip_fraction) * v_pic;  // PIC/FLIP
    particles.velocity[p] = flip_fraction == 1.0 ? v_p_flip : v_p_blend;
    particles.position[p] += dt * v_moving;
  }
}

/// Which nodal velocity enters the position update Eq. (33) of the predictor-corrector (paper/09_choices.md).
enum class NewmarkPositionVelocity {
  projected,  ///< the literal Eq. (33): v_I^k = sum_p N_Ip m_p v_p^k / m_I (default: free fall exact)
  corrected,  ///< the authors' code: v_I^{k+1} from Eq. (30) (an O(dt) position error under a constant force)
  predicted   ///< v_I^{pred} of Eq. (29)
};

/// How the predictor-corrector updates the particle velocity (paper/10_integrator_analysis.md).
enum class NewmarkParticleVelocity {
  eq32,    ///< Eq. (32) as printed: the new acceleration only (the paper's scheme; first order, dissipative)
  average  ///< Eq. (23)'s Newmark average of the old and new accelerations (second order, no numerical damping)
};

/// Eqs. (31)-(33), the particle update of the predictor-corrector. Eq. (32) increments v_p with the
/// new acceleration only, not the Newmark average of Eq. (23) (paper/09_choices.md): a first-order,
/// dissipative choice (tests/energy.cpp measures it).
/// \f[ \mathbf a_p^{k+1} = \sum_I N_{Ip} \frac{\mathbf f_I}{m_I}, \qquad
///     \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t \sum_I N_{Ip} \frac{\mathbf f_I}{m_I}, \qquad
///     \mathbf x_p^{k+1} = \mathbf x_p^k + \Delta t \sum_I N_{Ip} \mathbf v_I + \tfrac12 \Delta t^2 \sum_I N_{Ip} \frac{\mathbf f_I}{m_I} \f]
/// With NewmarkParticleVelocity::average the velocity follows Eq. (23) instead,
/// \f$ \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t \left((1-\gamma)\,\mathbf a_p^k + \gamma\, \mathbf a_p^{k+1}\right) \f$,
/// with \f$ \mathbf a_p^k \f$ the acceleration the particle stored in the step before.
/// Expects nodal_velocity = the corrected v_I^{k+1} and nodal_momentum = sum_p N_Ip m_p v_p^k.
template <int Dim>
void newmark_particle_update(ReferenceKernels, const Stencils<Dim>& stencils, GridFields<Dim>& grid,
                             double newmark_gamma, double dt, NewmarkPositionVelocity position_velocity,
                             Particles<Dim>& particles,
                             NewmarkParticleVelocity particle_velocity = NewmarkParticleVelocity::eq32) {
  // The nodes first (0 on nodes without mass): a_I^{k+1} = f_I^{k+1} / m_I and the nodal velocity that moves the
  // particles: v_I^k = p_I^k / m_I (projected), v_I^{k+1} (corrected) or v_I^{pred} = v_I^{k+1} - gamma dt a_I^{k+1}.
  for (int I = 0; I < grid.size(); ++I) {
    const double m_I = grid.nodal_mass[I];
    if (m_I <= 0.0) {
      grid.nodal_acceleration[I].setZero();
      grid.moving_velocity[I].setZero();
      continue;
    }
    const Vector<Dim> a_I_k1 = grid.nodal_force[I] / m_I;
    const Vector<Dim>& v_I_k1 = grid.nodal_velocity[I];
    grid.nodal_acceleration[I] = a_I_k1;
    switch (position_velocity) {
      case NewmarkPositionVelocity::projected: grid.moving_velocity[I] = grid.nodal_momentum[I] / m_I; break;
      case NewmarkPositionVelocity::corrected: grid.moving_velocity[I] = v_I_k1; break;
      case NewmarkPositionVelocity::predicted: grid.moving_velocity[I] = v_I_k1 - newmark_gamma * dt * a_I_k1; break;
    }
  }
  // Then the particles: Eq. (31) for a_p^{k+1}, Eq. (32) (or Eq. (23)) for v_p^{k+1}, Eq. (33) for x_p^{k+1}.
  const std::vector<Vector<Dim>>& a_I_k1 = grid.nodal_acceleration;
  const std::vector<Vector<Dim>>& v_I_moving = grid.moving_velocity;
  for (int p = 0; p < particles.size(); ++p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> a_p_k1 = Vector<Dim>::Zero(), v_moving = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      const int I = stencil.node[k];
      const double N_Ip = stencil.value[k];
      a_p_k1 += N_Ip * a_I_k1[I];
      v_moving += N_Ip * v_I_moving[I];
    }
    const Vector<Dim> a_p_k = particles.acceleration[p];
    particles.acceleration[p] = a_p_k1;
    if (particle_velocity == NewmarkParticleVelocity::eq32)
      particles.velocity[p] += dt * a_p_k1;
    else
      particles.velocity[p] += dt * ((1.0 - newmark_gamma) * a_p_k + newmark_gamma * a_p_k1);
    particles.position[p] += dt * v_moving + 0.5 * dt * dt * a_p_k1;
  }
}

TEST_CASE("Eq. (18), Eq. (19), Eq. (20), Eq. (21), Eq. (22), Eq. (31), Eq. (32), Eq. (33): G2P on the worked example by hand") {
  // a_p = sum N a_I: p0: 0.75 (8) + 0.25 (13.6) = 9.4, p1: 0.5 (13.6) + 0.5 (0) = 6.8; dt = 0.2:
  // v_p = (1 + 1.88, -1.5 + 1.36) = (2.88, -0.14) for both integrators.
  testing::WorkedExample example;
  auto& grid = example.fields;
  const double dt = example.dt;
  testing::worked_example_grid(grid, false);
  Particles<1> euler = example.particles;
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, dt, EulerPositionVelocity::updated, euler);
  // p_I^{k+1} / m_I = (2.6, 1.72, 0):
  // x = (0.25 + 0.2 (0.75 * 2.6 + 0.25 * 1.72), 1.5 + 0.2 (0.5 * 1.72)) = (0.726, 1.672)
  CHECK(euler.velocity[0][0] == doctest::Approx(2.88));
  CHECK(euler.velocity[1][0] == doctest::Approx(-0.14));
  CHECK(euler.position[0][0] == doctest::Approx(0.726));
  CHECK(euler.position[1][0] == doctest::Approx(1.672));
  Particles<1> literal = example.particles;
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, dt, EulerPositionVelocity::start, literal);
  // v_I^k = (1, -1, 0): x = (0.25 + 0.2 (0.75 - 0.25), 1.5 + 0.2 (-0.5)) = (0.35, 1.4)
  CHECK(literal.position[0][0] == doctest::Approx(0.35));
  CHECK(literal.position[1][0] == doctest::Approx(1.4));

  testing::worked_example_grid(grid, true);
  Particles<1> newmark = example.particles;
  newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.5, dt, NewmarkPositionVelocity::corrected,
                          newmark);
  // corrected v_I = (1.8, 0.36, 0): x0 = 0.25 + 0.2 (1.35 + 0.09) + 0.02 (9.4) = 0.726,
  // x1 = 1.5 + 0.2 (0.18) + 0.02 (6.8) = 1.672
  CHECK(newmark.acceleration[0][0] == doctest::Approx(9.4));
  CHECK(newmark.acceleration[1][0] == doctest::Approx(6.8));
  CHECK(newmark.velocity[0][0] == doctest::Approx(2.88));
  CHECK(newmark.velocity[1][0] == doctest::Approx(-0.14));
  CHECK(newmark.position[0][0] == doctest::Approx(0.726));
  CHECK(newmark.position[1][0] == doctest::Approx(1.672));
  Particles<1> predicted = example.particles;
  newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.5, dt, NewmarkPositionVelocity::predicted,
                          predicted);
  // v_I - gamma dt a_I = (1.8 - 0.8, 0.36 - 1.36, 0) = (1, -1, 0): x0 = 0.25 + 0.2 (0.5) + 0.188 = 0.538
  CHECK(predicted.position[0][0] == doctest::Approx(0.538));
  Particles<1> projected = example.particles;
  newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.5, dt, NewmarkPositionVelocity::projected,
                          projected);
  // p_I / m_I = (1, -1, 0): x = (0.25 + 0.1 + 0.188, 1.5 - 0.1 + 0.136) = (0.538, 1.536)
  CHECK(projected.position[0][0] == doctest::Approx(0.538));
  CHECK(projected.position[1][0] == doctest::Approx(1.536));
}

TEST_CASE("Eq. (30), Eq. (33): the position update as printed reads no corrected velocity: Eq. (30) changes no bit") {
  // The worked example's first predictor-corrector step: its grid before the corrector (v_I^pred = (1, -1, 0)) and
  // after it ((1.8, 0.36, 0)). The default update, Eq. (33) with v_I^k = p_I^k / m_I, gives the same bits from both;
  // the authors' corrected one moves particle 0 to 0.726 instead of 0.538.
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, true);
  const std::vector<Vector<1>> corrected = grid.nodal_velocity;
  const std::vector<Vector<1>> predictor{Vector<1>(1.0), Vector<1>(-1.0), Vector<1>(0.0)};
  for (const auto position_velocity : {NewmarkPositionVelocity::projected, NewmarkPositionVelocity::corrected}) {
    Particles<1> before = example.particles, after = example.particles;
    grid.nodal_velocity = predictor;
    newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.5, example.dt, position_velocity, before);
    grid.nodal_velocity = corrected;
    newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.5, example.dt, position_velocity, after);
    CHECK(before.velocity == after.velocity);
    CHECK(before.acceleration == after.acceleration);
    if (position_velocity == NewmarkPositionVelocity::projected) {
      CHECK(before.position == after.position);
    } else {
      CHECK(before.position[0][0] == doctest::Approx(0.538));
      CHECK(after.position[0][0] == doctest::Approx(0.726));
    }
  }
}

TEST_CASE("Eq. (19), Eq. (20), Eq. (31), Eq. (33): G2P skips the nodes without mass, whatever their fields hold") {
  // Node 2 of the worked example emptied, its force, momentum and velocity left huge: particle 1 (N = 0.5, 0.5 on
  // nodes 1, 2) must see node 1 alone: a = 0.5 (34 / 2.5) = 6.8, v = -1.5 + 0.2 (6.8) = -0.14.
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, false);
  grid.nodal_mass[2] = 0.0;
  grid.nodal_force[2] = grid.nodal_velocity[2] = grid.nodal_momentum[2] = Vector<1>(1e6);
  Particles<1> updated = example.particles, start = example.particles, blend = example.particles;
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, 0.2, EulerPositionVelocity::updated,
                                updated);
  CHECK(updated.velocity[1][0] == doctest::Approx(-0.14));
  CHECK(updated.position[1][0] == doctest::Approx(1.672));  // 1.5 + 0.2 (0.5 * 4.3 / 2.5)
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, 0.2, EulerPositionVelocity::start, start);
  CHECK(start.position[1][0] == doctest::Approx(1.4));      // 1.5 + 0.2 (0.5 * -1)
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, 0.2, EulerPositionVelocity::start, blend,
                                0.5);
  CHECK(blend.velocity[1][0] == doctest::Approx(0.36));     // 0.5 (-0.14) + 0.5 (0.5 * 1.72)
  testing::worked_example_grid(grid, true);
  grid.nodal_mass[2] = 0.0;
  grid.nodal_force[2] = grid.nodal_velocity[2] = grid.nodal_momentum[2] = Vector<1>(1e6);
  for (const auto position_velocity : {NewmarkPositionVelocity::projected, NewmarkPositionVelocity::corrected, NewmarkPositionVelocity::predicted}) {
    Particles<1> newmark = example.particles;
    newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.6, 0.2, position_velocity, newmark);
    CHECK(newmark.acceleration[1][0] == doctest::Approx(6.8));
    CHECK(newmark.velocity[1][0] == doctest::Approx(-0.14));
    // projected: 0.5 * -2.5 / 2.5 = -0.5; corrected: 0.5 * 0.36 = 0.18; predicted: 0.5 (0.36 - 0.12 * 13.6) = -0.636;
    // plus 0.02 a = 0.136
    const double moved = position_velocity == NewmarkPositionVelocity::projected ? -0.5
                         : position_velocity == NewmarkPositionVelocity::corrected ? 0.18
                                                                                   : -0.636;
    CHECK(newmark.position[1][0] == doctest::Approx(1.5 + 0.2 * moved + 0.136));
  }
}

TEST_CASE("Eq. (23): the Newmark average of the particle velocity by hand, at gamma = 0.6 (where gamma and 1 - gamma differ)") {
  // The worked example's first step: a_p^k = 0 at t = 0 and a_p^{k+1} = 9.4 for particle 0, so the average gives
  // v = 1 + 0.2 (0.4 (0) + 0.6 (9.4)) = 2.128 (Eq. (32): 2.88; the weights swapped: 1.752).
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, true);
  Particles<1> first = example.particles;
  newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.6, example.dt,
                          NewmarkPositionVelocity::projected, first,
                          NewmarkParticleVelocity::average);
  CHECK(first.velocity[0][0] == doctest::Approx(2.128));
  CHECK(first.acceleration[0][0] == doctest::Approx(9.4));
  // With a_p^k = -3 set by hand (a check of the old acceleration's weight): v = 1 + 0.2 (0.4 (-3) + 0.6 (9.4)) = 1.888.
  Particles<1> particles = example.particles;
  particles.acceleration[0] = Vector<1>(-3.0);
  newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.6, example.dt,
                          NewmarkPositionVelocity::projected, particles,
                          NewmarkParticleVelocity::average);
  CHECK(particles.velocity[0][0] == doctest::Approx(1.888));
  CHECK(particles.acceleration[0][0] == doctest::Approx(9.4));
}

TEST_CASE("Eq. (19), Eq. (20), Eq. (21), Eq. (22): the PIC/FLIP blend of forward Euler by hand, and flip_fraction = 1 bit for bit FLIP") {
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, false);  // p_I^{k+1} / m_I = (2.6, 1.72, 0)
  Particles<1> flip = example.particles, blend = example.particles;
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, 0.2, EulerPositionVelocity::updated, flip,
                                1.0);
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, 0.2, EulerPositionVelocity::updated,
                                blend, 0.8);
  // p0: FLIP 2.88 (above); PIC sum N p_I/m_I = 0.75 * 2.6 + 0.25 * 1.72 = 2.38; blend 0.8 * 2.88 + 0.2 * 2.38 = 2.78
  CHECK(flip.velocity[0][0] == doctest::Approx(2.88));
  CHECK(blend.velocity[0][0] == doctest::Approx(2.78));
  CHECK(blend.position[0][0] == flip.position[0][0]);
  // the PIC part takes the updated p_I / m_I whatever moves the particle: with the literal Eqs. (20)-(21)
  // (positions from v_I^k = 1, -1, 0) the velocity is still 0.8 * 2.88 + 0.2 * 2.38
  Particles<1> literal = example.particles;
  forward_euler_particle_update(ReferenceKernels{}, example.stencils, grid, 0.2, EulerPositionVelocity::start,
                                literal, 0.8);
  CHECK(literal.velocity[0][0] == doctest::Approx(2.78));
}

TEST_CASE("Eq. (33): the position update with the predicted nodal velocity at gamma = 0.6 by hand: v_I - gamma dt a_I") {
  // The worked example's first step at gamma = 0.6: the corrector gives v_I^pred + 0.12 a_I = (1.96, 0.632, 0), and
  // v_I - gamma dt a_I recovers v_I^pred = (1, -1, 0): x0 = 0.25 + 0.2 (0.5) + 0.02 (9.4) = 0.538
  // ((1 - gamma) dt = 0.08 would give (1.32, -0.456, 0) and 0.6132).
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, true);
  grid.nodal_velocity = {Vector<1>(1.96), Vector<1>(0.632), Vector<1>(0.0)};
  newmark_particle_update(ReferenceKernels{}, example.stencils, grid, 0.6, example.dt,
                          NewmarkPositionVelocity::predicted,
                          example.particles);
  CHECK(example.particles.position[0][0] == doctest::Approx(0.538));
}

}  // namespace mpm
