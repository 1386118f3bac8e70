/// \file
/// The scene's choices of the nodal and particle velocities of the particle updates (mpm/transfer/grid_to_particle.hpp
/// makes each a type): words of a scene, so that the scene reader includes them without the kernels.
#pragma once

namespace mpm {

/// Which nodal velocity moves the particles in the forward-Euler update (paper/09_choices.md, 'The position update of
/// forward Euler'): the scene's word (`solver.fe_position_velocity`), made a type by euler_position_rule().
enum class EulerPositionVelocity {
  updated,  ///< the authors' code: p_I after p_I += dt f_I, i.e. v_I^{k+1} (default)
  start     ///< the literal Eqs. (20)-(21): v_I^k = p_I^k / m_I
};

/// Which nodal velocity enters the position update Eq. (33) of the predictor-corrector (paper/09_choices.md): the
/// scene's word (`solver.npc_position_velocity`), made a type by newmark_position_rule().
enum class NewmarkPositionVelocity {
  projected,  ///< the literal Eq. (33): v_I^k = sum_p N_Ip m_p v_p^k / m_I (default: free fall exact)
  corrected,  ///< the authors' code: v_I^{k+1} from Eq. (30) (an O(dt) position error under a constant force)
  predicted   ///< v_I^{pred} of Eq. (29)
};

/// How the predictor-corrector updates the particle velocity (paper/10_integrator_analysis.md): the scene's word
/// (`solver.npc_velocity`), made a type by newmark_velocity_rule().
enum class NewmarkParticleVelocity {
  eq32,    ///< Eq. (32) as printed: the new acceleration only (the paper's scheme; first order, dissipative)
  average  ///< Eq. (23)'s Newmark average of the old and new accelerations (second order, no numerical damping)
};

}  // namespace mpm
