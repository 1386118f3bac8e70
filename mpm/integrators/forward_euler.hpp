/// \file
/// Standard explicit MPM, "forward Euler" (FE), as the authors run it (paper/02_mpm_forward_euler.md): update stress
/// first (USF), FLIP velocity increment, positions moved with the updated nodal momentum.
#pragma once
#include "mpm/grid/boundary.hpp"
#include "mpm/grid/nodal_update.hpp"
#include "mpm/model.hpp"
#include "mpm/transfer/grid_to_particle.hpp"
#include "mpm/transfer/nodal_forces.hpp"
#include "mpm/transfer/particle_to_grid.hpp"
#include "mpm/transfer/strain_update.hpp"

namespace mpm {

struct ForwardEuler {
  static constexpr const char* name = "fe";
  EulerPositionVelocity position_velocity = EulerPositionVelocity::updated;

  /// One step from t_k to t_k + dt. The stencils hold N_Ip, grad N_Ip at x_p^k; body_force is b.
  template <int Dim>
  void step(const Model<Dim>& model, const Stencils<Dim>& stencils, const Vector<Dim>& body_force, double dt,
            Particles<Dim>& particles, GridFields<Dim>& grid) const {
    grid.reset();
    // 1. P2G: lumped mass, Eq. (13), and momentum p_I = sum_p N_Ip m_p v_p.
    lumped_nodal_mass(particles, stencils, grid);
    nodal_momentum(particles, stencils, grid);
    // 2. Essential boundary conditions on the momentum.
    impose_fixed_velocity(model.fixed, grid.nodal_momentum);
    // 3. Nodal velocity v_I^k = p_I / m_I.
    nodal_velocity_from_momentum(grid);
    // 4. Update stress first: strain rate, Eq. (16); density, Eq. (17); stress, Eq. (3).
    update_strain_density_stress(stencils, grid.nodal_velocity, model.material, dt, particles);
    // 5. Nodal forces, Eqs. (14)-(15); the fixed components become reactions.
    add_internal_force(particles, stencils, grid);
    add_body_force(particles, stencils, body_force, grid);
    store_reactions(model.fixed, grid.nodal_force, grid.reaction);
    // 6. Momentum balance, Eq. (12): p_I += dt f_I.
    update_nodal_momentum(dt, grid);
    // 7. G2P, Eqs. (19)-(22): v_p += dt sum N f/m, x_p += dt sum N p/m.
    forward_euler_particle_update(stencils, grid, dt, position_velocity, particles);
  }
};

}  // namespace mpm
