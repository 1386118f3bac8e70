/// \file
/// Grid-to-particle transfers (G2P): the particle update of each integrator, Eq. (18) applied, and its variants.
///
/// Contract: read nodal_mass, nodal_momentum_k or nodal_momentum_k1, nodal_velocity_k (forward Euler) or nodal_velocity_k1 (the
/// predictor-corrector's corrected one), nodal_force and the stencils; write, node by
/// node, the rates the particles interpolate (nodal_acceleration, nodal_velocity_k1 = forward Euler's
/// v_I^{k+1}, moving_velocity: one division by m_I per node, not per particle-node pair), then the particles' x_p,
/// v_p (and a_p for the predictor-corrector).
///
/// Each variant of an integrator's update is a type of its own, chosen once per run (mpm/run.hpp) and held by the
/// integrator in a std::variant: the nodal velocity that moves the particles (a small node loop of its own) and the
/// rule of the particle velocity (FLIP or the PIC/FLIP blend; Eq. (32) or Eq. (23)'s average). The particle loops
/// interpolate the nodal arrays they are given and know no variant. These are the reference kernels, plain serial
/// loops; their fast forms, on every core, are in mpm/fast/fast_grid_to_particle.hpp.
#pragma once
#include <doctest/doctest.h>

#include <variant>
#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/velocity_choices.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// A loop over the nodes on the reference kernels: plain and serial (the fast layer's runs on every core).
template <class Body>
void for_each_node(ReferenceKernels, int nodes, Body&& body) {
  for (int I = 0; I < nodes; ++I) body(I);
}

/// Eq. (18)'s nodal rates of forward Euler's G2P, 0 on nodes without mass: \f$ \mathbf a_I = \mathbf f_I / m_I \f$
/// (nodal_acceleration) and \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$ (nodal_velocity_k1), after
/// update_nodal_momentum.
template <class Kernels, int Dim>
void euler_nodal_rates(const Kernels& kernels, GridFields<Dim>& grid) {
  for_each_node(kernels, grid.size(), [&](int I) {
    const double m_I = grid.nodal_mass[I];
    const bool has_mass = m_I > 0.0;
    grid.nodal_acceleration[I] = has_mass ? Vector<Dim>(grid.nodal_force[I] / m_I) : Vector<Dim>::Zero();
    grid.nodal_velocity_k1[I] = has_mass ? Vector<Dim>(grid.nodal_momentum_k1[I] / m_I) : Vector<Dim>::Zero();
  });
}

/// Eq. (31)'s nodal rate of the predictor-corrector, 0 on nodes without mass:
/// \f$ \mathbf a_I^{k+1} = \mathbf f_I^{k+1} / m_I \f$ (nodal_acceleration).
template <class Kernels, int Dim>
void newmark_nodal_acceleration(const Kernels& kernels, GridFields<Dim>& grid) {
  for_each_node(kernels, grid.size(), [&](int I) {
    const double m_I = grid.nodal_mass[I];
    grid.nodal_acceleration[I] = m_I > 0.0 ? Vector<Dim>(grid.nodal_force[I] / m_I) : Vector<Dim>::Zero();
  });
}

/// Forward Euler's `updated` position velocity (the authors' code), Eqs. (21)-(22): the particles move with
/// \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$ (moving_velocity), after euler_nodal_rates().
struct EulerMoveWithVelocityK1 {
  template <class Kernels, int Dim>
  void operator()(const Kernels& kernels, GridFields<Dim>& grid) const {
    for_each_node(kernels, grid.size(), [&](int I) {
      const Vector<Dim>& v_I_k1 = grid.nodal_velocity_k1[I];  // 0 without mass
      grid.moving_velocity[I] = v_I_k1;
    });
  }
};

/// Forward Euler's `start` position velocity, the literal Eq. (20): the particles move with
/// \f$ \mathbf v_I^k = \mathbf p_I^k / m_I \f$ (moving_velocity; 0 on nodes without mass).
struct EulerMoveWithVelocityK {
  template <class Kernels, int Dim>
  void operator()(const Kernels& kernels, GridFields<Dim>& grid) const {
    for_each_node(kernels, grid.size(), [&](int I) {
      const Vector<Dim>& v_I_k = grid.nodal_velocity_k[I];
      grid.moving_velocity[I] = grid.nodal_mass[I] > 0.0 ? v_I_k : Vector<Dim>::Zero();
    });
  }
};

/// The predictor-corrector's `projected` position velocity, Eq. (33) as printed: the particles move with
/// \f$ \mathbf v_I^k = \mathbf p_I^k / m_I \f$ (moving_velocity; 0 on nodes without mass).
struct NewmarkMoveWithVelocityK {
  template <class Kernels, int Dim>
  void operator()(const Kernels& kernels, GridFields<Dim>& grid, double /*newmark_gamma*/, double /*dt*/) const {
    for_each_node(kernels, grid.size(), [&](int I) {
      const double m_I = grid.nodal_mass[I];
      grid.moving_velocity[I] = m_I > 0.0 ? Vector<Dim>(grid.nodal_momentum_k[I] / m_I) : Vector<Dim>::Zero();
    });
  }
};

/// The predictor-corrector's `corrected` position velocity (the authors' code): the particles move with the
/// corrected \f$ \mathbf v_I^{k+1} \f$ of Eq. (30) (moving_velocity; 0 on nodes without mass).
struct NewmarkMoveWithVelocityK1 {
  template <class Kernels, int Dim>
  void operator()(const Kernels& kernels, GridFields<Dim>& grid, double /*newmark_gamma*/, double /*dt*/) const {
    for_each_node(kernels, grid.size(), [&](int I) {
      const Vector<Dim>& v_I_k1 = grid.nodal_velocity_k1[I];
      grid.moving_velocity[I] = grid.nodal_mass[I] > 0.0 ? v_I_k1 : Vector<Dim>::Zero();
    });
  }
};

/// The predictor-corrector's `predicted` position velocity: the particles move with the predictor of Eq. (29),
/// recovered from the corrector as \f$ \mathbf v_I^{pred} = \mathbf v_I^{k+1} - \gamma \Delta t\, \mathbf a_I^{k+1} \f$
/// (moving_velocity; 0 on nodes without mass), after newmark_nodal_acceleration(). Equal to predicted_velocity up to
/// round-off; recovered, as since this variant was added, so that its runs keep their bits.
struct NewmarkMoveWithVelocityPred {
  template <class Kernels, int Dim>
  void operator()(const Kernels& kernels, GridFields<Dim>& grid, double newmark_gamma, double dt) const {
    for_each_node(kernels, grid.size(), [&](int I) {
      const Vector<Dim>& v_I_k1 = grid.nodal_velocity_k1[I];
      const Vector<Dim>& a_I_k1 = grid.nodal_acceleration[I];
      grid.moving_velocity[I] =
          grid.nodal_mass[I] > 0.0 ? Vector<Dim>(v_I_k1 - newmark_gamma * dt * a_I_k1) : Vector<Dim>::Zero();
    });
  }
};

/// The particle-velocity rule of Eq. (32) as printed:
/// \f$ \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t\, \mathbf a_p^{k+1} \f$.
struct Eq32Velocity {
  template <int Dim>
  static Vector<Dim> velocity(const Vector<Dim>& v_p_k, const Vector<Dim>& /*a_p_k*/, const Vector<Dim>& a_p_k1,
                              double /*newmark_gamma*/, double dt) {
    return v_p_k + dt * a_p_k1;
  }
};

/// The particle-velocity rule of Eq. (23), Newmark's average:
/// \f$ \mathbf v_p^{k+1} = \mathbf v_p^k
///     + \Delta t \left((1-\gamma)\,\mathbf a_p^k + \gamma\, \mathbf a_p^{k+1}\right) \f$.
struct NewmarkAverageVelocity {
  template <int Dim>
  static Vector<Dim> velocity(const Vector<Dim>& v_p_k, const Vector<Dim>& a_p_k, const Vector<Dim>& a_p_k1,
                              double newmark_gamma, double dt) {
    return v_p_k + dt * ((1.0 - newmark_gamma) * a_p_k + newmark_gamma * a_p_k1);
  }
};

/// Eqs. (19)-(22), forward Euler's particle loop in momentum form (Eq. (19) and Eq. (20) in velocities, Eq. (21) and
/// Eq. (22) in momenta), with FLIP's velocity increment:
/// \f$ \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t \sum_I N_{Ip} \mathbf a_I \f$ and
/// \f$ \mathbf x_p^{k+1} = \mathbf x_p^k + \Delta t \sum_I N_{Ip} \mathbf v_I \f$, with
/// \f$ \mathbf a_I = \mathbf f_I / m_I \f$ and \f$ \mathbf v_I \f$ the nodal velocity the variant chose.
template <int Dim>
void forward_euler_particle_update(ReferenceKernels, const Stencils<Dim>& stencils, const std::vector<Vector<Dim>>& a_I,
                           const std::vector<Vector<Dim>>& v_I, double dt, Particles<Dim>& particles) {
  for (int p = 0; p < particles.size(); ++p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> a_p = Vector<Dim>::Zero(), v_moving = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      const int I = stencil.node[k];
      const double N_Ip = stencil.value[k];
      a_p += N_Ip * a_I[I];
      v_moving += N_Ip * v_I[I];
    }
    particles.velocity[p] += dt * a_p;  // v_p^k + dt sum_I N_Ip f_I / m_I
    particles.position[p] += dt * v_moving;
  }
}

/// The PIC/FLIP blend of Brackbill's FLIP and Zhu and Bridson (2005), a standard damping of explicit MPM
/// (paper/10_integrator_analysis.md), after forward_euler_particle_update() gave the FLIP velocity:
/// \f[ \mathbf v_p^{k+1} = \alpha\, \mathbf v_p^{FLIP} + (1-\alpha) \sum_I N_{Ip} \mathbf v_I^{k+1}, \qquad
///     \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I . \f]
template <int Dim>
void pic_flip_blend(ReferenceKernels, const Stencils<Dim>& stencils, double flip_fraction,
                    const std::vector<Vector<Dim>>& v_I_k1, Particles<Dim>& particles) {
  for (int p = 0; p < particles.size(); ++p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> v_pic = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) v_pic += stencil.value[k] * v_I_k1[stencil.node[k]];
    const Vector<Dim> v_p_flip = particles.velocity[p];
    particles.velocity[p] = flip_fraction * v_p_flip + (1.0 - flip_fraction) * v_pic;
  }
}

/// Eqs. (31)-(33), the predictor-corrector's particle loop, with the particle-velocity rule `Rule`
/// (Eq32Velocity or NewmarkAverageVelocity):
/// \f[ \mathbf a_p^{k+1} = \sum_I N_{Ip} \mathbf a_I^{k+1}, \qquad
///     \mathbf v_p^{k+1} = \mathrm{Rule}(\mathbf v_p^k, \mathbf a_p^k, \mathbf a_p^{k+1}), \qquad
///     \mathbf x_p^{k+1} = \mathbf x_p^k + \Delta t \sum_I N_{Ip} \mathbf v_I
///     + \tfrac12 \Delta t^2 \mathbf a_p^{k+1} \f]
/// with \f$ \mathbf a_p^k \f$ the acceleration the particle stored in the step before and \f$ \mathbf v_I \f$ the
/// nodal velocity the variant chose.
template <class Rule, int Dim>
void newmark_particle_update(ReferenceKernels, const Stencils<Dim>& stencils, const std::vector<Vector<Dim>>& a_I_k1,
                             const std::vector<Vector<Dim>>& v_I, double newmark_gamma, double dt, Rule,
                             Particles<Dim>& particles) {
  for (int p = 0; p < particles.size(); ++p) {
    const ParticleStencil<Dim> stencil = stencils.of(p);
    Vector<Dim> a_p_k1 = Vector<Dim>::Zero(), v_moving = Vector<Dim>::Zero();
    for (int k = 0; k < stencil.count; ++k) {
      const int I = stencil.node[k];
      const double N_Ip = stencil.value[k];
      a_p_k1 += N_Ip * a_I_k1[I];
      v_moving += N_Ip * v_I[I];
    }
    const Vector<Dim> a_p_k = particles.acceleration[p];
    particles.acceleration[p] = a_p_k1;
    particles.velocity[p] = Rule::velocity(particles.velocity[p], a_p_k, a_p_k1, newmark_gamma, dt);
    particles.position[p] += dt * v_moving + 0.5 * dt * dt * a_p_k1;
  }
}

/// Forward Euler's FLIP velocity (the paper's scheme, flip_fraction = 1): the particle loop's increment, no more.
struct FlipVelocity {
  template <class Kernels, int Dim>
  void operator()(const Kernels&, const Stencils<Dim>&, const GridFields<Dim>&, Particles<Dim>&) const {}
};

/// Forward Euler's PIC/FLIP blend with \f$ \alpha \f$ = flip_fraction below 1 (pic_flip_blend()).
struct PicFlipBlend {
  double flip_fraction;
  template <class Kernels, int Dim>
  void operator()(const Kernels& kernels, const Stencils<Dim>& stencils, const GridFields<Dim>& grid,
                  Particles<Dim>& particles) const {
    pic_flip_blend(kernels, stencils, flip_fraction, grid.nodal_velocity_k1, particles);
  }
};

/// The variants of forward Euler's G2P and of the predictor-corrector's, one type each, held by the integrator.
using EulerPositionRule = std::variant<EulerMoveWithVelocityK1, EulerMoveWithVelocityK>;
using EulerVelocityRule = std::variant<FlipVelocity, PicFlipBlend>;
using NewmarkPositionRule =
    std::variant<NewmarkMoveWithVelocityK, NewmarkMoveWithVelocityK1, NewmarkMoveWithVelocityPred>;
using NewmarkVelocityRule = std::variant<Eq32Velocity, NewmarkAverageVelocity>;

/// The type of a scene's word `solver.fe_position_velocity`.
inline EulerPositionRule euler_position_rule(EulerPositionVelocity word) {
  if (word == EulerPositionVelocity::start) return EulerMoveWithVelocityK{};
  return EulerMoveWithVelocityK1{};
}

/// The type of a scene's `solver.flip_fraction`: FLIP at 1 (bit for bit the pure increment), the blend below.
inline EulerVelocityRule euler_velocity_rule(double flip_fraction) {
  if (flip_fraction == 1.0) return FlipVelocity{};
  return PicFlipBlend{flip_fraction};
}

/// The type of a scene's word `solver.npc_position_velocity`.
inline NewmarkPositionRule newmark_position_rule(NewmarkPositionVelocity word) {
  if (word == NewmarkPositionVelocity::corrected) return NewmarkMoveWithVelocityK1{};
  if (word == NewmarkPositionVelocity::predicted) return NewmarkMoveWithVelocityPred{};
  return NewmarkMoveWithVelocityK{};
}

/// The type of a scene's word `solver.npc_velocity`.
inline NewmarkVelocityRule newmark_velocity_rule(NewmarkParticleVelocity word) {
  if (word == NewmarkParticleVelocity::average) return NewmarkAverageVelocity{};
  return Eq32Velocity{};
}

/// Forward Euler's G2P, Eqs. (19)-(22), the variants' steps in order: the nodal rates
/// \f$ \mathbf a_I = \mathbf f_I / m_I \f$ and \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$
/// (\ref euler_nodal_rates); the nodal velocity the position variant moves the particles with (its own node loop);
/// the particle loop (\ref forward_euler_particle_update); the velocity variant's rule (FLIP: nothing; the blend:
/// \ref pic_flip_blend). Expects nodal_velocity_k = v_I^k and nodal_momentum_k1 = p_I^{k+1} (after
/// update_nodal_momentum).
template <class Kernels, int Dim>
void forward_euler_g2p(const Kernels& kernels, const Stencils<Dim>& stencils, GridFields<Dim>& grid, double dt,
                       const EulerPositionRule& position_velocity, const EulerVelocityRule& particle_velocity,
                       Particles<Dim>& particles) {
  euler_nodal_rates(kernels, grid);
  std::visit([&](const auto& v_I) { v_I(kernels, grid); }, position_velocity);
  forward_euler_particle_update(kernels, stencils, grid.nodal_acceleration, grid.moving_velocity, dt, particles);
  std::visit([&](const auto& rule) { rule(kernels, stencils, grid, particles); }, particle_velocity);
}

/// The predictor-corrector's G2P, Eqs. (31)-(33), the variants' steps in order: the nodal rate
/// \f$ \mathbf a_I^{k+1} = \mathbf f_I^{k+1} / m_I \f$ (\ref newmark_nodal_acceleration); the nodal velocity the
/// position variant moves the particles with (its own node loop); the particle loop with the velocity variant's rule
/// (\ref newmark_particle_update). Expects nodal_velocity_k1 = the corrected v_I^{k+1} and nodal_momentum_k =
/// sum_p N_Ip m_p v_p^k.
template <class Kernels, int Dim>
void newmark_g2p(const Kernels& kernels, const Stencils<Dim>& stencils, GridFields<Dim>& grid, double newmark_gamma,
                 double dt, const NewmarkPositionRule& position_velocity, const NewmarkVelocityRule& particle_velocity,
                 Particles<Dim>& particles) {
  newmark_nodal_acceleration(kernels, grid);
  std::visit([&](const auto& v_I) { v_I(kernels, grid, newmark_gamma, dt); }, position_velocity);
  std::visit(
      [&](auto rule) {
        newmark_particle_update(kernels, stencils, grid.nodal_acceleration, grid.moving_velocity, newmark_gamma, dt,
                                rule, particles);
      },
      particle_velocity);
}

TEST_CASE("Eq. (18), Eq. (19), Eq. (20), Eq. (21), Eq. (22), Eq. (31), Eq. (32), Eq. (33): G2P on the worked example by hand") {
  // a_p = sum N a_I: p0: 0.75 (8) + 0.25 (13.6) = 9.4, p1: 0.5 (13.6) + 0.5 (0) = 6.8; dt = 0.2:
  // v_p = (1 + 1.88, -1.5 + 1.36) = (2.88, -0.14) for both integrators.
  testing::WorkedExample example;
  auto& grid = example.fields;
  const double dt = example.dt;
  testing::worked_example_grid(grid, false);
  Particles<1> euler = example.particles;
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, dt, EulerMoveWithVelocityK1{}, FlipVelocity{}, euler);
  // p_I^{k+1} / m_I = (2.6, 1.72, 0):
  // x = (0.25 + 0.2 (0.75 * 2.6 + 0.25 * 1.72), 1.5 + 0.2 (0.5 * 1.72)) = (0.726, 1.672)
  CHECK(euler.velocity[0][0] == doctest::Approx(2.88));
  CHECK(euler.velocity[1][0] == doctest::Approx(-0.14));
  CHECK(euler.position[0][0] == doctest::Approx(0.726));
  CHECK(euler.position[1][0] == doctest::Approx(1.672));
  Particles<1> literal = example.particles;
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, dt, EulerMoveWithVelocityK{}, FlipVelocity{}, literal);
  // v_I^k = (1, -1, 0): x = (0.25 + 0.2 (0.75 - 0.25), 1.5 + 0.2 (-0.5)) = (0.35, 1.4)
  CHECK(literal.position[0][0] == doctest::Approx(0.35));
  CHECK(literal.position[1][0] == doctest::Approx(1.4));

  testing::worked_example_grid(grid, true);
  Particles<1> newmark = example.particles;
  newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.5, dt, NewmarkMoveWithVelocityK1{}, Eq32Velocity{},
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
  newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.5, dt, NewmarkMoveWithVelocityPred{}, Eq32Velocity{},
              predicted);
  // v_I - gamma dt a_I = (1.8 - 0.8, 0.36 - 1.36, 0) = (1, -1, 0): x0 = 0.25 + 0.2 (0.5) + 0.188 = 0.538
  CHECK(predicted.position[0][0] == doctest::Approx(0.538));
  Particles<1> projected = example.particles;
  newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.5, dt, NewmarkMoveWithVelocityK{}, Eq32Velocity{},
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
  const std::vector<Vector<1>> corrected = grid.nodal_velocity_k1;
  const std::vector<Vector<1>> predictor{Vector<1>(1.0), Vector<1>(-1.0), Vector<1>(0.0)};
  for (const auto word : {NewmarkPositionVelocity::projected, NewmarkPositionVelocity::corrected}) {
    Particles<1> before = example.particles, after = example.particles;
    grid.nodal_velocity_k1 = predictor;  // as if Eq. (30) had added nothing
    newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.5, example.dt, newmark_position_rule(word),
                Eq32Velocity{}, before);
    grid.nodal_velocity_k1 = corrected;
    newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.5, example.dt, newmark_position_rule(word),
                Eq32Velocity{}, after);
    CHECK(before.velocity == after.velocity);
    CHECK(before.acceleration == after.acceleration);
    if (word == NewmarkPositionVelocity::projected) {
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
  grid.nodal_force[2] = grid.nodal_velocity_k[2] = grid.nodal_velocity_k1[2] = grid.nodal_momentum_k1[2] = Vector<1>(1e6);
  Particles<1> updated = example.particles, start = example.particles, blend = example.particles;
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, 0.2, EulerMoveWithVelocityK1{}, FlipVelocity{},
                    updated);
  CHECK(updated.velocity[1][0] == doctest::Approx(-0.14));
  CHECK(updated.position[1][0] == doctest::Approx(1.672));  // 1.5 + 0.2 (0.5 * 4.3 / 2.5)
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, 0.2, EulerMoveWithVelocityK{}, FlipVelocity{}, start);
  CHECK(start.position[1][0] == doctest::Approx(1.4));      // 1.5 + 0.2 (0.5 * -1)
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, 0.2, EulerMoveWithVelocityK{}, PicFlipBlend{0.5},
                    blend);
  CHECK(blend.velocity[1][0] == doctest::Approx(0.36));     // 0.5 (-0.14) + 0.5 (0.5 * 1.72)
  testing::worked_example_grid(grid, true);
  grid.nodal_mass[2] = 0.0;
  grid.nodal_force[2] = grid.nodal_velocity_k1[2] = grid.nodal_momentum_k[2] = Vector<1>(1e6);
  for (const auto word : {NewmarkPositionVelocity::projected, NewmarkPositionVelocity::corrected,
                          NewmarkPositionVelocity::predicted}) {
    Particles<1> newmark = example.particles;
    newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.6, 0.2, newmark_position_rule(word), Eq32Velocity{},
                newmark);
    CHECK(newmark.acceleration[1][0] == doctest::Approx(6.8));
    CHECK(newmark.velocity[1][0] == doctest::Approx(-0.14));
    // projected: 0.5 * -2.5 / 2.5 = -0.5; corrected: 0.5 * 0.36 = 0.18; predicted: 0.5 (0.36 - 0.12 * 13.6) = -0.636;
    // plus 0.02 a = 0.136
    const double moved = word == NewmarkPositionVelocity::projected   ? -0.5
                         : word == NewmarkPositionVelocity::corrected ? 0.18
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
  newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.6, example.dt, NewmarkMoveWithVelocityK{},
              NewmarkAverageVelocity{}, first);
  CHECK(first.velocity[0][0] == doctest::Approx(2.128));
  CHECK(first.acceleration[0][0] == doctest::Approx(9.4));
  // With a_p^k = -3 set by hand (a check of the old acceleration's weight): v = 1 + 0.2 (0.4 (-3) + 0.6 (9.4)) = 1.888.
  Particles<1> particles = example.particles;
  particles.acceleration[0] = Vector<1>(-3.0);
  newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.6, example.dt, NewmarkMoveWithVelocityK{},
              NewmarkAverageVelocity{}, particles);
  CHECK(particles.velocity[0][0] == doctest::Approx(1.888));
  CHECK(particles.acceleration[0][0] == doctest::Approx(9.4));
}

TEST_CASE("Eq. (19), Eq. (20), Eq. (21), Eq. (22): the PIC/FLIP blend of forward Euler by hand, and flip_fraction = 1 bit for bit FLIP") {
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, false);  // p_I^{k+1} / m_I = (2.6, 1.72, 0)
  Particles<1> flip = example.particles, blend = example.particles;
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, 0.2, EulerMoveWithVelocityK1{}, FlipVelocity{}, flip);
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, 0.2, EulerMoveWithVelocityK1{}, PicFlipBlend{0.8},
                    blend);
  // p0: FLIP 2.88 (above); PIC sum N p_I/m_I = 0.75 * 2.6 + 0.25 * 1.72 = 2.38; blend 0.8 * 2.88 + 0.2 * 2.38 = 2.78
  CHECK(flip.velocity[0][0] == doctest::Approx(2.88));
  CHECK(blend.velocity[0][0] == doctest::Approx(2.78));
  CHECK(blend.position[0][0] == flip.position[0][0]);
  // the PIC part takes the updated p_I / m_I whatever moves the particle: with the literal Eqs. (20)-(21)
  // (positions from v_I^k = 1, -1, 0) the velocity is still 0.8 * 2.88 + 0.2 * 2.38
  Particles<1> literal = example.particles;
  forward_euler_g2p(ReferenceKernels{}, example.stencils, grid, 0.2, EulerMoveWithVelocityK{}, PicFlipBlend{0.8},
                    literal);
  CHECK(literal.velocity[0][0] == doctest::Approx(2.78));
}

TEST_CASE("Eq. (33): the position update with the predicted nodal velocity at gamma = 0.6 by hand: v_I - gamma dt a_I") {
  // The worked example's first step at gamma = 0.6: the corrector gives v_I^pred + 0.12 a_I = (1.96, 0.632, 0), and
  // v_I - gamma dt a_I recovers v_I^pred = (1, -1, 0): x0 = 0.25 + 0.2 (0.5) + 0.02 (9.4) = 0.538
  // ((1 - gamma) dt = 0.08 would give (1.32, -0.456, 0) and 0.6132).
  testing::WorkedExample example;
  auto& grid = example.fields;
  testing::worked_example_grid(grid, true);
  grid.nodal_velocity_k1 = {Vector<1>(1.96), Vector<1>(0.632), Vector<1>(0.0)};
  newmark_g2p(ReferenceKernels{}, example.stencils, grid, 0.6, example.dt, NewmarkMoveWithVelocityPred{},
              Eq32Velocity{}, example.particles);
  CHECK(example.particles.position[0][0] == doctest::Approx(0.538));
}

TEST_CASE("Eq. (20), Eq. (22), Eq. (23), Eq. (32), Eq. (33): each scene word becomes its variant's type") {
  CHECK(std::holds_alternative<EulerMoveWithVelocityK1>(euler_position_rule(EulerPositionVelocity::updated)));
  CHECK(std::holds_alternative<EulerMoveWithVelocityK>(euler_position_rule(EulerPositionVelocity::start)));
  CHECK(std::holds_alternative<FlipVelocity>(euler_velocity_rule(1.0)));
  CHECK(std::get<PicFlipBlend>(euler_velocity_rule(0.9)).flip_fraction == 0.9);
  CHECK(std::holds_alternative<NewmarkMoveWithVelocityK>(newmark_position_rule(NewmarkPositionVelocity::projected)));
  CHECK(std::holds_alternative<NewmarkMoveWithVelocityK1>(newmark_position_rule(NewmarkPositionVelocity::corrected)));
  CHECK(std::holds_alternative<NewmarkMoveWithVelocityPred>(newmark_position_rule(NewmarkPositionVelocity::predicted)));
  CHECK(std::holds_alternative<Eq32Velocity>(newmark_velocity_rule(NewmarkParticleVelocity::eq32)));
  CHECK(std::holds_alternative<NewmarkAverageVelocity>(newmark_velocity_rule(NewmarkParticleVelocity::average)));
}

}  // namespace mpm
