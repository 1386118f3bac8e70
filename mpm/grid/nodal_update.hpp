/// \file
/// Updates of the nodal fields in time: the momentum balance Eq. (12) integrated explicitly.
#pragma once
#include <doctest/doctest.h>

#include "mpm/grid/grid_fields.hpp"

namespace mpm {

/// Eq. (12) with forward Euler: \f$ \mathbf p_I^{k+1} = \mathbf p_I^k + \Delta t\, \mathbf f_I \f$ on nodes with
/// mass (nodal_momentum_k1 from nodal_momentum_k); \f$ \mathbf p_I^{k+1} = \mathbf p_I^k \f$ on the others.
template <int Dim>
void update_nodal_momentum(double dt, GridFields<Dim>& grid) {
  const std::vector<Vector<Dim>>& p_I_k = grid.nodal_momentum_k;
  std::vector<Vector<Dim>>& p_I_k1 = grid.nodal_momentum_k1;
  for (int node = 0; node < grid.size(); ++node)
    p_I_k1[node] = grid.nodal_mass[node] > 0.0 ? Vector<Dim>(p_I_k[node] + dt * grid.nodal_force[node]) : p_I_k[node];
}

/// Eq. (30), the Newmark corrector:
/// \f$ \mathbf v_I^{k+1} = \mathbf v_I^{pred} + \gamma\,\Delta t\, \mathbf f_I / m_I \f$ (nodal_velocity_k1 from
/// predicted_velocity; on nodes without mass \f$ \mathbf v_I^{k+1} = \mathbf v_I^{pred} = 0 \f$).
template <int Dim>
void newmark_corrector(double newmark_gamma, double dt, GridFields<Dim>& grid) {
  const std::vector<Vector<Dim>>& v_I_pred = grid.predicted_velocity;
  std::vector<Vector<Dim>>& v_I_k1 = grid.nodal_velocity_k1;
  for (int I = 0; I < grid.size(); ++I) {
    const double m_I = grid.nodal_mass[I];
    v_I_k1[I] = m_I > 0.0 ? Vector<Dim>(v_I_pred[I] + newmark_gamma * dt * grid.nodal_force[I] / m_I) : v_I_pred[I];
  }
}

TEST_CASE("Eq. (12), Eq. (30): nodal updates: the momentum balance and the corrector by hand, massless nodes untouched") {
  GridFields<1> grid(2);
  grid.nodal_mass = {2.0, 0.0};
  grid.nodal_momentum_k = {Vector<1>(1.0), Vector<1>(0.0)};
  grid.predicted_velocity = {Vector<1>(0.5), Vector<1>(0.0)};
  grid.nodal_force = {Vector<1>(4.0), Vector<1>(7.0)};
  update_nodal_momentum(0.1, grid);
  CHECK(grid.nodal_momentum_k1[0][0] == doctest::Approx(1.4));
  CHECK(grid.nodal_momentum_k1[1][0] == 0.0);
  CHECK(grid.nodal_momentum_k[0][0] == 1.0);  // p_I^k kept beside p_I^{k+1}
  newmark_corrector(0.5, 0.1, grid);
  CHECK(grid.nodal_velocity_k1[0][0] == doctest::Approx(0.5 + 0.5 * 0.1 * 4.0 / 2.0));
  CHECK(grid.nodal_velocity_k1[1][0] == 0.0);
  CHECK(grid.predicted_velocity[0][0] == 0.5);  // v_I^pred kept beside v_I^{k+1}
}

TEST_CASE("Eq. (12): p_I += dt f_I on every node with mass, the first and the last too, massless nodes untouched") {
  GridFields<1> grid(3);
  grid.nodal_mass = {2.0, 0.0, 1.0};
  grid.nodal_momentum_k = {Vector<1>(1.0), Vector<1>(0.0), Vector<1>(2.0)};
  grid.nodal_force = {Vector<1>(4.0), Vector<1>(7.0), Vector<1>(-3.0)};
  update_nodal_momentum(0.1, grid);
  CHECK(grid.nodal_momentum_k1[0][0] == doctest::Approx(1.4));
  CHECK(grid.nodal_momentum_k1[1][0] == 0.0);
  CHECK(grid.nodal_momentum_k1[2][0] == doctest::Approx(1.7));  // 2 + 0.1 (-3)
}

TEST_CASE("Eq. (30): the corrector at gamma = 0.6 by hand: gamma dt f_I / m_I, not (1 - gamma) dt f_I / m_I") {
  // At gamma = 1/2 the two weights are equal; at 0.6: 0.5 + 0.6*0.1*4/2 = 0.62 (not 0.5 + 0.4*0.1*4/2 = 0.58),
  // and -1 + 0.6*0.1*(-3)/0.5 = -1.36 on the second node.
  GridFields<1> grid(3);
  grid.nodal_mass = {2.0, 0.5, 0.0};
  grid.predicted_velocity = {Vector<1>(0.5), Vector<1>(-1.0), Vector<1>(0.0)};
  grid.nodal_force = {Vector<1>(4.0), Vector<1>(-3.0), Vector<1>(7.0)};
  newmark_corrector(0.6, 0.1, grid);
  CHECK(grid.nodal_velocity_k1[0][0] == doctest::Approx(0.62));
  CHECK(grid.nodal_velocity_k1[1][0] == doctest::Approx(-1.36));
  CHECK(grid.nodal_velocity_k1[2][0] == 0.0);
}

}  // namespace mpm
