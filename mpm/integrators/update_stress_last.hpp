/// \file
/// Forward Euler with the stress updated last: USL and MUSL (Sulsky, Zhou and Schreyer 1995; paper/11_stress_update.md),
/// today's two standard alternatives to the update-stress-first order (USF) of the paper's forward Euler
/// (mpm/integrators/forward_euler.hpp).
///
/// All three share the kernels and differ only in which nodal velocity the strain rate, Eq. (16), is taken from:
/// - USF: \f$ \mathbf v_I^k = \mathbf p_I^k / m_I \f$, before the forces (the stress that makes the forces is new);
/// - USL: \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$, after the momentum balance (the forces come from the old stress);
/// - MUSL: \f$ \mathbf v_I^{k+1} = \sum_p N_{Ip} m_p \mathbf v_p^{k+1} / m_I \f$, the updated particle velocities projected
///   to the nodes again (one more particle-to-grid pass), which filters what FLIP leaves on the particles.
/// The stencils of every step are those of \f$ \mathbf x_p^k \f$, computed once per step for all its transfers,
/// as in USF; the particles move before their strain is updated.
#pragma once
#include <doctest/doctest.h>

#include <array>
#include <variant>

#include "mpm/core/kernels.hpp"
#include "mpm/core/step_phases.hpp"
#include "mpm/grid/boundary.hpp"
#include "mpm/grid/nodal_update.hpp"
#include "mpm/model.hpp"
#include "mpm/transfer/grid_to_particle.hpp"
#include "mpm/transfer/nodal_forces.hpp"
#include "mpm/transfer/particle_to_grid.hpp"
#include "mpm/transfer/strain_update.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// USL's nodal momentum of the stress update: \f$ \mathbf p_I^{k+1} \f$ of the momentum balance as it stands, so
/// \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$; no phase of its own (USL skips phase 7).
struct UslMomentumK1 {
  template <class Kernels, int Dim, class Observer>
  void operator()(const Kernels&, const Model<Dim>&, const Stencils<Dim>&, Particles<Dim>&, GridFields<Dim>&,
                  Observer&) const {}
};

/// MUSL's nodal momentum of the stress update, phase 7: the updated particle velocities projected to the nodes again,
/// \f$ \mathbf p_I^{k+1} = \sum_p N_{Ip} m_p \mathbf v_p^{k+1} \f$ (\ref nodal_momentum_from_particles), held at
/// the walls (\ref impose_fixed_velocity).
struct MuslMomentumK1 {
  template <class Kernels, int Dim, class Observer>
  void operator()(const Kernels& kernels, const Model<Dim>& model, const Stencils<Dim>& stencils, Particles<Dim>& particles,
                  GridFields<Dim>& grid, Observer& observer) const {
    nodal_momentum_from_particles(kernels, particles, stencils, grid);
    impose_fixed_velocity(model.fixed, grid.nodal_momentum_k1);
    observer.after(Phase::reprojection, particles, grid);
  }
};

/// Where USL and MUSL take the nodal velocity of the stress update from, one type each, chosen once per run.
using StressLastVelocity = std::variant<UslMomentumK1, MuslMomentumK1>;

/// Forward Euler, update stress last (USL) or modified update stress last (MUSL): one step() per time step,
/// chosen once per run as the Integrator of mpm::Simulation (`solver.stress_update`). The options of the
/// paper's forward Euler (the position update's velocity, the PIC/FLIP blend) apply unchanged.
struct UpdateStressLast {
  static constexpr const char* name = "fe";
  StressLastVelocity stress_velocity = UslMomentumK1{};                ///< USL or MUSL
  EulerPositionRule position_velocity = EulerMoveWithVelocityK1{};  ///< as forward Euler's (ForwardEuler)
  EulerVelocityRule particle_velocity = FlipVelocity{};             ///< as forward Euler's (ForwardEuler)

  /// `Kernels` is the layer every transfer of the step is taken from (mpm/core/kernels.hpp), chosen once per run by
  /// `solver.kernels`: each call below with `kernels` is, for ReferenceKernels, the plain kernel of mpm/transfer/
  /// that its phase names; for FastKernels (the scene's default, `solver.kernels = "fast"`) its fast form in mpm/fast/.
  ///
  /// One step from \f$ t_k \f$ to \f$ t_k + \Delta t \f$, the stencils at \f$ \mathbf x_p^k \f$. Its numbered
  /// phases, as `mpm trace` numbers them; phase 0 resets the nodal fields (GridFields::reset):
  /// 1. P2G: \f$ m_I = \sum_p N_{Ip} m_p \f$, Eq. (13), and \f$ \mathbf p_I = \sum_p N_{Ip} m_p \mathbf v_p \f$
  ///    (\ref nodal_mass_and_momentum).
  /// 2. Essential boundary conditions on \f$ \mathbf p_I \f$ (\ref impose_fixed_velocity).
  /// 3. \f$ \mathbf v_I^k = \mathbf p_I / m_I \f$ (\ref nodal_velocity_from_momentum).
  /// 4. Nodal forces \f$ \mathbf f_I^k \f$ from the stress of the step before, Eqs. (14)-(15); reactions
  ///    (\ref add_nodal_forces, \ref store_reactions).
  /// 5. Momentum balance, Eq. (12): \f$ \mathbf p_I \mathrel{+}= \Delta t\, \mathbf f_I^k \f$
  ///    (\ref update_nodal_momentum).
  /// 6. G2P, Eqs. (19)-(22), as forward Euler's with its variants (\ref forward_euler_g2p).
  /// 7. MUSL only (MuslMomentumK1; USL's UslMomentumK1 skips it):
  ///    \f$ \mathbf p_I = \sum_p N_{Ip} m_p \mathbf v_p^{k+1} \f$
  ///    (\ref nodal_momentum_from_particles), and the boundary conditions again.
  /// 8. \f$ \mathbf v_I^{k+1} = \mathbf p_I / m_I \f$ (\ref nodal_velocity_from_momentum).
  /// 9. Update stress last: strain rate, Eq. (16); density, Eq. (17); stress, Eq. (3)
  ///    (\ref update_strain_density_stress).
  ///
  /// `observer.after(phase, particles, grid)` is called after each phase, in the order of `phases` (USL without
  /// phase 7).
  template <class Kernels, int Dim, class Observer>
  void step(const Kernels& kernels, const Model<Dim>& model, const Stencils<Dim>& stencils,
            const ParticleBodyForces<Dim>& body_force, double dt, Particles<Dim>& particles, GridFields<Dim>& grid,
            Observer& observer) const {
    // 0. The nodal fields set to zero.
    grid.reset();
    observer.after(Phase::reset, particles, grid);
    // 1. P2G: lumped mass, Eq. (13), and momentum p_I^k = sum_p N_Ip m_p v_p^k.
    nodal_mass_and_momentum(kernels, particles, stencils, grid);
    observer.after(Phase::mass_momentum, particles, grid);
    // 2. Essential boundary conditions on the momentum.
    impose_fixed_velocity(model.fixed, grid.nodal_momentum_k);
    observer.after(Phase::fixed_momentum, particles, grid);
    // 3. v_I^k = p_I^k / m_I.
    nodal_velocity_from_momentum(grid, grid.nodal_momentum_k, grid.nodal_velocity_k);
    observer.after(Phase::velocity_k, particles, grid);
    // 4. Nodal forces from the stress of the step before, Eqs. (14)-(15); the fixed components become reactions.
    add_nodal_forces(kernels, particles, stencils, body_force, grid);
    store_reactions(model.fixed, grid.nodal_force, grid.reaction);
    observer.after(Phase::forces, particles, grid);
    // 5. Momentum balance, Eq. (12): p_I^{k+1} = p_I^k + dt f_I.
    update_nodal_momentum(dt, grid);
    observer.after(Phase::momentum_balance, particles, grid);
    // 6. G2P, Eqs. (19)-(22), as forward Euler's: v_p += dt sum N a_I, x_p += dt sum N v_I (the variants').
    forward_euler_g2p(kernels, stencils, grid, dt, position_velocity, particle_velocity, particles);
    observer.after(Phase::euler_update, particles, grid);
    // 7. MUSL: the new particle velocities projected to the nodes again, and held at the walls (USL: nothing).
    std::visit([&](const auto& p_I_k1) { p_I_k1(kernels, model, stencils, particles, grid, observer); },
               stress_velocity);
    // 8. v_I^{k+1} = p_I^{k+1} / m_I.
    nodal_velocity_from_momentum(grid, grid.nodal_momentum_k1, grid.nodal_velocity_k1);
    observer.after(Phase::velocity_k1, particles, grid);
    // 9. Update stress last: Eq. (16), Eq. (17), Eq. (3).
    update_strain_density_stress(kernels, stencils, grid.nodal_velocity_k1, model.materials, dt, particles);
    observer.after(Phase::stress, particles, grid);
  }

  /// The numbered phases of step(), in the order it runs them: phase n is phases[n] (USL skips phase 7).
  static constexpr std::array<Phase, 10> phases = {
      Phase::reset,  Phase::mass_momentum, Phase::fixed_momentum, Phase::velocity_k,  Phase::forces,
      Phase::momentum_balance, Phase::euler_update, Phase::reprojection, Phase::velocity_k1, Phase::stress};
};

TEST_CASE("USL, MUSL: one step of the worked example by hand, node 2 fixed: each stress from its own nodal velocity") {
  // The first step of scenes/worked_example.toml (mpm/transfer/worked_example.hpp), E = 25 Pa, dt = 0.2, b = 10,
  // node 2 held: p_I = (1.5, -2.5, 0), v_I^k = (1, -1, 0); no stress yet, so f_I is the weight (15, 25, 20), node 2's
  // a reaction; p_I^{k+1} = (4.5, 2.5, 0), v_I^{k+1} = (3, 1, 0), a_I = (10, 10, 0). G2P: v_0 = 1 + 0.2 (10) = 3,
  // v_1 = -1.5 + 0.2 (0.5 * 10) = -0.5; x_0 = 0.25 + 0.2 (0.75 * 3 + 0.25 * 1) = 0.75, x_1 = 1.5 + 0.2 (0.5 * 1) = 1.6.
  // USL: strain rates from v_I^{k+1}: 1 - 3 = -2 and -1, so sigma = 25 * 0.2 * rate = (-10, -5).
  // MUSL: p_I = (0.75 * 2 * 3, 0.25 * 2 * 3 + 0.5 * 4 * -0.5, held) = (4.5, 0.5, 0), v_I = (3, 0.2, 0): rates -2.8 and
  // -0.2, sigma = (-14, -1). (USF takes v_I^k: rates -2 and 1, sigma = (-10, 5), paper/12_worked_example.md.)
  auto step = [](const StressLastVelocity& velocity) {
    testing::WorkedExample example;
    Model<1> model;
    model.grid = example.grid;
    model.materials = {LinearElastic{example.young_modulus, 0.0, example.density}};
    model.fixed = {FixedDof{2, 0}};
    const ParticleBodyForces<1> body_force = testing::WorkedExample::body_force();
    NoPhaseObserver observer;
    UpdateStressLast integrator;
    integrator.stress_velocity = velocity;
    integrator.step(ReferenceKernels{}, model, example.stencils, body_force, example.dt, example.particles, example.fields,
                    observer);
    return example.particles;
  };
  const StressLastVelocity both[] = {UslMomentumK1{}, MuslMomentumK1{}};
  for (const StressLastVelocity& velocity : both) {
    const Particles<1> particles = step(velocity);
    CHECK(particles.velocity[0][0] == doctest::Approx(3.0));
    CHECK(particles.velocity[1][0] == doctest::Approx(-0.5));
    CHECK(particles.position[0][0] == doctest::Approx(0.75));
    CHECK(particles.position[1][0] == doctest::Approx(1.6));
  }
  const Particles<1> usl = step(UslMomentumK1{});
  CHECK(usl.stress[0](0, 0) == doctest::Approx(-10.0));
  CHECK(usl.stress[1](0, 0) == doctest::Approx(-5.0));
  const Particles<1> musl = step(MuslMomentumK1{});
  CHECK(musl.stress[0](0, 0) == doctest::Approx(-14.0));
  CHECK(musl.stress[1](0, 0) == doctest::Approx(-1.0));
}

}  // namespace mpm
