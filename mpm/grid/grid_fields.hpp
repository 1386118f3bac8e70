/// \file
/// Nodal fields, rebuilt from the particles every step: reset() zeroes them at the start of each step.
/// Allocated once per run: reset() only zeroes them, so the time step allocates nothing.
#pragma once
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

template <int Dim>
struct GridFields {
  std::vector<double> nodal_mass;              ///< m_I, Eq. (13) lumped
  std::vector<Vector<Dim>> nodal_momentum_k;   ///< p_I^k = sum_p N_Ip m_p v_p^k, Eqs. (21)-(22)
  /// p_I^{k+1}: forward Euler's momentum balance, Eq. (12), then MUSL's projection of v_p^{k+1}
  std::vector<Vector<Dim>> nodal_momentum_k1;
  std::vector<Vector<Dim>> nodal_velocity_k;   ///< forward Euler (USF, USL, MUSL): v_I^k = p_I^k / m_I
  std::vector<Vector<Dim>> predicted_velocity; ///< the predictor-corrector: v_I^{pred}, Eqs. (26)-(29)
  std::vector<Vector<Dim>> nodal_force;        ///< f_I = f_I^int + f_I^ext, Eqs. (14)-(15)
  std::vector<Vector<Dim>> reaction;           ///< force taken by the fixed degrees of freedom
  /// Formed once per node before G2P (mpm/transfer/grid_to_particle.hpp), 0 on nodes without mass, so that the
  /// particle loops multiply by N_Ip instead of dividing by m_I for every particle-node pair:
  std::vector<Vector<Dim>> nodal_acceleration;  ///< a_I = f_I / m_I
  std::vector<Vector<Dim>> moving_velocity;     ///< the nodal velocity that moves the particles (the integrator's choice)
  /// v_I^{k+1}: forward Euler's p_I^{k+1} / m_I (the PIC part of its PIC/FLIP blend), then USL's and MUSL's velocity of
  /// the stress update (MUSL's from the momentum projected again); the predictor-corrector's corrected one, Eq. (30)
  std::vector<Vector<Dim>> nodal_velocity_k1;

  explicit GridFields(int node_count = 0)
      : nodal_mass(node_count, 0.0),
        nodal_momentum_k(node_count, Vector<Dim>::Zero()),
        nodal_momentum_k1(node_count, Vector<Dim>::Zero()),
        nodal_velocity_k(node_count, Vector<Dim>::Zero()),
        predicted_velocity(node_count, Vector<Dim>::Zero()),
        nodal_force(node_count, Vector<Dim>::Zero()),
        reaction(node_count, Vector<Dim>::Zero()),
        nodal_acceleration(node_count, Vector<Dim>::Zero()),
        moving_velocity(node_count, Vector<Dim>::Zero()),
        nodal_velocity_k1(node_count, Vector<Dim>::Zero()) {}

  int size() const { return static_cast<int>(nodal_mass.size()); }

  void reset() {
    for (int node = 0; node < size(); ++node) {
      nodal_mass[node] = 0.0;
      nodal_momentum_k[node].setZero();
      predicted_velocity[node].setZero();  // summed over the particles (p_I^{k+1}, v_I^k, v_I^{k+1} are assigned whole)
      nodal_force[node].setZero();
      reaction[node].setZero();
    }
  }
};

}  // namespace mpm
