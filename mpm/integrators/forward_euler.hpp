/// \file
/// Standard explicit MPM, "forward Euler" (FE), as the authors run it (paper/02_mpm_forward_euler.md): update stress
/// first (USF), FLIP velocity increment, positions moved with the updated nodal momentum.
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

/// Forward Euler (FE), the standard explicit MPM of the paper, Eqs. (12)-(22): one step() per time step,
/// chosen once per run as the Integrator of mpm::Simulation. Its steps are listed with step().
struct ForwardEuler {
  static constexpr const char* name = "fe";
  /// The variants, chosen once per run (mpm/run.hpp), each a type with its own step: the nodal velocity that moves
  /// the particles (EulerMoveWithVelocityK1, the authors' code, or EulerMoveWithVelocityK, the literal Eq. (20)) and
  /// the particle velocity (FlipVelocity, the paper's scheme, or PicFlipBlend, a damping).
  EulerPositionRule position_velocity = EulerMoveWithVelocityK1{};
  EulerVelocityRule particle_velocity = FlipVelocity{};

  /// `Kernels` is the layer every transfer of the step is taken from (mpm/core/kernels.hpp), chosen once per run by
  /// `solver.kernels`: each call below with `kernels` is, for ReferenceKernels, the plain kernel of mpm/transfer/
  /// that its phase names; for FastKernels (the scene's default, `solver.kernels = "fast"`) its fast form in mpm/fast/.
  ///
  /// One step from \f$ t_k \f$ to \f$ t_k + \Delta t \f$. The stencils hold \f$ N_{Ip} \f$ and
  /// \f$ \nabla N_{Ip} \f$ at \f$ \mathbf x_p^k \f$; body_force holds \f$ \mathbf b_p \f$ per particle.
  /// Its numbered phases, as `mpm trace` numbers them; phase 0 resets the nodal fields (GridFields::reset):
  /// 1. P2G: the lumped nodal mass \f$ m_I = \sum_p N_{Ip} m_p \f$, Eq. (13), and the nodal momentum
  ///    \f$ \mathbf p_I = \sum_p N_{Ip} m_p \mathbf v_p \f$, in one pass over the particles (\ref nodal_mass_and_momentum).
  /// 2. Essential boundary conditions: the fixed components of \f$ \mathbf p_I \f$ are set to zero
  ///    (\ref impose_fixed_velocity).
  /// 3. Nodal velocity \f$ \mathbf v_I^k = \mathbf p_I / m_I \f$ (\ref nodal_velocity_from_momentum).
  /// 4. Update stress first (USF): strain rate, Eq. (16); density, Eq. (17); stress, Eq. (3)
  ///    (\ref update_strain_density_stress).
  /// 5. Nodal forces \f$ \mathbf f_I^{k+1} = \mathbf f_I^{int} + \mathbf f_I^{ext} \f$, Eqs. (14)-(15), from the
  ///    stress just updated (\ref add_nodal_forces); the fixed components become reactions (\ref store_reactions).
  /// 6. Momentum balance, Eq. (12): \f$ \mathbf p_I^{k+1} = \mathbf p_I^k + \Delta t\, \mathbf f_I \f$ (\ref update_nodal_momentum).
  /// 7. G2P, Eqs. (19)-(22) (\ref forward_euler_g2p): the nodal rates \f$ \mathbf a_I = \mathbf f_I / m_I \f$ and
  ///    \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$; the position variant's nodal velocity
  ///    \f$ \mathbf v_I \f$ (\f$ \mathbf v_I^{k+1} \f$, or \f$ \mathbf v_I^k \f$ under `start`);
  ///    \f$ \mathbf v_p \mathrel{+}= \Delta t \sum_I N_{Ip} \mathbf a_I \f$,
  ///    \f$ \mathbf x_p \mathrel{+}= \Delta t \sum_I N_{Ip} \mathbf v_I \f$ (\ref forward_euler_particle_update);
  ///    the velocity variant's rule (FLIP: nothing more; the PIC/FLIP blend).
  ///
  /// `observer.after(phase, particles, grid)` is called after each phase, in the order of `phases`: the loop times
  /// them, `mpm trace` prints them; NoPhaseObserver watches nothing.
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
    // 3. Nodal velocity v_I^k = p_I^k / m_I.
    nodal_velocity_from_momentum(grid, grid.nodal_momentum_k, grid.nodal_velocity_k);
    observer.after(Phase::velocity_k, particles, grid);
    // 4. Update stress first: strain rate, Eq. (16); density, Eq. (17); stress, Eq. (3).
    update_strain_density_stress(kernels, stencils, grid.nodal_velocity_k, model.materials, dt, particles);
    observer.after(Phase::stress, particles, grid);
    // 5. Nodal forces, Eqs. (14)-(15); the fixed components become reactions.
    add_nodal_forces(kernels, particles, stencils, body_force, grid);
    store_reactions(model.fixed, grid.nodal_force, grid.reaction);
    observer.after(Phase::forces, particles, grid);
    // 6. Momentum balance, Eq. (12): p_I^{k+1} = p_I^k + dt f_I.
    update_nodal_momentum(dt, grid);
    observer.after(Phase::momentum_balance, particles, grid);
    // 7. G2P, Eqs. (19)-(22): a_I = f_I / m_I, v_I^{k+1} = p_I^{k+1} / m_I; the variant's v_I;
    //    v_p += dt sum N a_I, x_p += dt sum N v_I; the variant's particle velocity (FLIP or the blend).
    forward_euler_g2p(kernels, stencils, grid, dt, position_velocity, particle_velocity, particles);
    observer.after(Phase::euler_update, particles, grid);
  }

  /// The numbered phases of step(), in the order it runs them: phase n is phases[n].
  static constexpr std::array<Phase, 8> phases = {Phase::reset,  Phase::mass_momentum, Phase::fixed_momentum,
                                                  Phase::velocity_k, Phase::stress, Phase::forces,
                                                  Phase::momentum_balance, Phase::euler_update};
};

}  // namespace mpm
