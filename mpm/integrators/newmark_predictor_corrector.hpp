/// \file
/// The explicit Newmark predictor-corrector (NPC) of the paper, its Algorithm steps 1-9, as the
/// authors' code runs it (paper/03_predictor_corrector.md). Newmark gamma = 1/2 by default; beta is never used.
///
/// The paper motivates it with Newmark's scheme applied to the particles, Eq. (23) for v_p,
/// Eq. (24) for x_p with its beta, Eq. (25) for a_p, and then builds the explicit predictor and
/// corrector on the grid instead: Eqs. (26)-(30), with the particle update of Eqs. (31)-(33).
#pragma once
#include "mpm/grid/boundary.hpp"
#include "mpm/grid/nodal_update.hpp"
#include "mpm/model.hpp"
#include "mpm/transfer/grid_to_particle.hpp"
#include "mpm/transfer/nodal_forces.hpp"
#include "mpm/transfer/particle_to_grid.hpp"
#include "mpm/transfer/strain_update.hpp"

namespace mpm {

struct NewmarkPredictorCorrector {
  static constexpr const char* name = "npc";
  double newmark_gamma = 0.5;
  NewmarkPositionVelocity position_velocity = NewmarkPositionVelocity::corrected;

  /// One step from t_k to t_k + dt. The stencils hold N_Ip, grad N_Ip at x_p^k; body_force is b.
  template <int Dim>
  void step(const Model<Dim>& model, const Stencils<Dim>& stencils, const Vector<Dim>& body_force, double dt,
            Particles<Dim>& particles, GridFields<Dim>& grid) const {
    grid.reset();
    // Step 1. Lumped nodal mass, Eq. (13).
    lumped_nodal_mass(particles, stencils, grid);
    // Step 2. Velocity predictor by projection, Eqs. (26)-(29).
    nodal_velocity_predictor(particles, stencils, newmark_gamma, dt, grid);
    // Step 3. Essential boundary conditions overwrite the predictor.
    impose_fixed_velocity(model.fixed, grid.nodal_velocity);
    impose_fixed_velocity(model.fixed, grid.nodal_momentum);
    // Steps 4-5. Strain rate with the predicted velocity, Eq. (16); density, Eq. (17); stress, Eq. (3).
    update_strain_density_stress(stencils, grid.nodal_velocity, model.material, dt, particles);
    // Step 6. New nodal forces, Eqs. (14)-(15); the fixed components become reactions.
    add_internal_force(particles, stencils, grid);
    add_body_force(particles, stencils, body_force, grid);
    store_reactions(model.fixed, grid.nodal_force, grid.reaction);
    // Step 7. Corrector, Eq. (30): v_I += gamma dt f_I / m_I.
    newmark_corrector(newmark_gamma, dt, grid);
    // Step 8. Particle update, Eqs. (31)-(33).
    newmark_particle_update(stencils, grid, newmark_gamma, dt, position_velocity, particles);
    // Step 9. The nodal fields are reset at the start of the next step.
  }
};

}  // namespace mpm
