/// \file
/// The explicit Newmark predictor-corrector (NPC) of the paper, its algorithm's steps 1-9 run as the six numbered
/// phases of step() (paper/03_predictor_corrector.md). Newmark gamma = 1/2 by default; beta is never used. By
/// default the particles move by Eq. (33) as printed, with v_I^k = p_I^k / m_I
/// (`solver.npc_position_velocity = "projected"`), where the authors' code moves them with the corrected v_I^{k+1}
/// (`"corrected"`).
///
/// The corrector, Eq. (30), matters only when the position update reads the corrected velocity: under the default
/// nothing reads its output (Eqs. (31)-(32) read f_I / m_I, Eq. (33) reads p_I^k / m_I, the next step rebuilds the
/// nodes), so with or without it every output is the same to the last bit (tests/corrector.cpp). It stays in the
/// step, inert under the default, rather than skipped: the step is the paper's algorithm, and `"corrected"` and
/// `"predicted"` read it.
///
/// The paper motivates it with Newmark's scheme applied to the particles, Eq. (23) for v_p,
/// Eq. (24) for x_p with its beta, Eq. (25) for a_p, and then builds the explicit predictor and
/// corrector on the grid instead: Eqs. (26)-(30), with the particle update of Eqs. (31)-(33).
#pragma once
#include <array>

#include "mpm/core/kernels.hpp"
#include "mpm/core/step_phases.hpp"
#include "mpm/grid/boundary.hpp"
#include "mpm/grid/nodal_update.hpp"
#include "mpm/model.hpp"
#include "mpm/transfer/grid_to_particle.hpp"
#include "mpm/transfer/nodal_forces.hpp"
#include "mpm/transfer/particle_to_grid.hpp"
#include "mpm/transfer/strain_update.hpp"

namespace mpm {

/// The explicit Newmark predictor-corrector (NPC) of the paper, Eqs. (26)-(33): one step() per time step,
/// chosen once per run as the Integrator of mpm::Simulation. Its steps are listed with step().
struct NewmarkPredictorCorrector {
  static constexpr const char* name = "npc";
  double newmark_gamma = 0.5;
  /// The variants, chosen once per run (mpm/run.hpp), each a type with its own step: the nodal velocity of Eq. (33)
  /// (NewmarkMoveWithVelocityK, Eq. (33) as printed; NewmarkMoveWithVelocityK1, the authors' code;
  /// NewmarkMoveWithVelocityPred) and the particle velocity (Eq32Velocity, the paper's; NewmarkAverageVelocity).
  NewmarkPositionRule position_velocity = NewmarkMoveWithVelocityK{};
  NewmarkVelocityRule particle_velocity = Eq32Velocity{};

  /// `Kernels` is the layer every transfer of the step is taken from (mpm/core/kernels.hpp), chosen once per run by
  /// `solver.kernels`: each call below with `kernels` is, for ReferenceKernels, the plain kernel of mpm/transfer/
  /// that its phase names; for FastKernels (the scene's default, `solver.kernels = "fast"`) its fast form in mpm/fast/.
  ///
  /// One step from \f$ t_k \f$ to \f$ t_k + \Delta t \f$. The stencils hold \f$ N_{Ip} \f$ and
  /// \f$ \nabla N_{Ip} \f$ at \f$ \mathbf x_p^k \f$; body_force holds \f$ \mathbf b_p \f$ per particle.
  /// Its numbered phases, as `mpm trace` numbers them (the paper's algorithm steps they run in brackets); phase 0
  /// resets the nodal fields (GridFields::reset; the paper's step 9, "reset nodal values", ends the step before):
  /// 1. Lumped nodal mass \f$ m_I = \sum_p N_{Ip} m_p \f$, Eq. (13), and the velocity predictor by projection,
  ///    Eqs. (26)-(29),
  ///    \f$ \mathbf v_I^{pred} = \sum_p N_{Ip} m_p
  ///    \left(\mathbf v_p^k + (1-\gamma)\Delta t\, \mathbf a_p^k\right) / m_I \f$,
  ///    in one pass over the particles (\ref nodal_mass_and_velocity_predictor) [steps 1-2].
  /// 2. Essential boundary conditions overwrite the predictor (\ref impose_fixed_velocity) [step 3].
  /// 3. Strain rate with the predicted velocity, Eq. (16), strain increment
  ///    \f$ \Delta t\, \dot{\boldsymbol\varepsilon}_p \f$, density, Eq. (17), and stress, Eq. (3), in one call
  ///    (\ref update_strain_density_stress) [steps 4-5].
  /// 4. New nodal forces \f$ \mathbf f_I^{k+1} \f$, Eqs. (14)-(15) (\ref add_nodal_forces);
  ///    the fixed components become reactions (\ref store_reactions) [step 6].
  /// 5. Corrector, Eq. (30):
  ///    \f$ \mathbf v_I^{k+1} = \mathbf v_I^{pred} + \gamma\,\Delta t\, \mathbf f_I^{k+1} / m_I \f$
  ///    (\ref newmark_corrector) [step 7].
  /// 6. Particle update, Eqs. (31)-(33) (\ref newmark_g2p): the nodal rate
  ///    \f$ \mathbf a_I^{k+1} = \mathbf f_I^{k+1} / m_I \f$; the position variant's nodal velocity
  ///    \f$ \mathbf v_I \f$ (\f$ \mathbf v_I^k = \mathbf p_I^k / m_I \f$ by default); then, particle by particle,
  ///    \f$ \mathbf a_p^{k+1} = \sum_I N_{Ip} \mathbf a_I^{k+1} \f$,
  ///    \f$ \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t\, \mathbf a_p^{k+1} \f$,
  ///    \f$ \mathbf x_p^{k+1} = \mathbf x_p^k + \Delta t \sum_I N_{Ip} \mathbf v_I
  ///    + \tfrac12 \Delta t^2 \mathbf a_p^{k+1} \f$
  ///    (\ref newmark_particle_update); with the velocity variant NewmarkAverageVelocity, Eq. (23)'s
  ///    \f$ \mathbf v_p^{k+1} = \mathbf v_p^k + \Delta t ((1-\gamma) \mathbf a_p^k + \gamma \mathbf a_p^{k+1}) \f$
  ///    instead of Eq. (32) [step 8].
  ///
  /// `observer.after(phase, particles, grid)` is called after each phase, in the order of `phases`: the loop times
  /// them, `mpm trace` prints them.
  template <class Kernels, int Dim, class Observer>
  void step(const Kernels& kernels, const Model<Dim>& model, const Stencils<Dim>& stencils,
            const ParticleBodyForces<Dim>& body_force, double dt, Particles<Dim>& particles, GridFields<Dim>& grid,
            Observer& observer) const {
    // 0. The nodal fields set to zero (the paper's step 9 of the step before).
    grid.reset();
    observer.after(Phase::reset, particles, grid);
    // 1. Lumped nodal mass, Eq. (13), and velocity predictor by projection, Eqs. (26)-(29).
    nodal_mass_and_velocity_predictor(kernels, particles, stencils, newmark_gamma, dt, grid);
    observer.after(Phase::mass_predictor, particles, grid);
    // 2. Essential boundary conditions overwrite the predictor.
    impose_fixed_velocity(model.fixed, grid.predicted_velocity);
    impose_fixed_velocity(model.fixed, grid.nodal_momentum_k);
    observer.after(Phase::fixed_predictor, particles, grid);
    // 3. Strain rate with the predicted velocity, Eq. (16); density, Eq. (17); stress, Eq. (3).
    update_strain_density_stress(kernels, stencils, grid.predicted_velocity, model.materials, dt, particles);
    observer.after(Phase::stress, particles, grid);
    // 4. New nodal forces, Eqs. (14)-(15); the fixed components become reactions.
    add_nodal_forces(kernels, particles, stencils, body_force, grid);
    store_reactions(model.fixed, grid.nodal_force, grid.reaction);
    observer.after(Phase::forces, particles, grid);
    // 5. Corrector, Eq. (30): v_I^{k+1} = v_I^pred + gamma dt f_I / m_I.
    newmark_corrector(newmark_gamma, dt, grid);
    observer.after(Phase::corrector, particles, grid);
    // 6. Particle update, Eqs. (31)-(33): a_I^{k+1} = f_I / m_I; the variant's v_I; a_p^{k+1} = sum N a_I^{k+1},
    //    v_p^{k+1} by the variant's rule (Eq. (32) or Eq. (23)), x_p += dt sum N v_I + dt^2 / 2 a_p^{k+1}.
    newmark_g2p(kernels, stencils, grid, newmark_gamma, dt, position_velocity, particle_velocity, particles);
    observer.after(Phase::newmark_update, particles, grid);
  }

  /// The numbered phases of step(), in the order it runs them: phase n is phases[n].
  static constexpr std::array<Phase, 7> phases = {Phase::reset,  Phase::mass_predictor, Phase::fixed_predictor,
                                                  Phase::stress, Phase::forces,         Phase::corrector,
                                                  Phase::newmark_update};
};

}  // namespace mpm
