/// \file
/// The worked example of the transfer doctests: the state of scenes/worked_example.toml at t = 0, whose first step
/// paper/12_worked_example.md computes by hand, phase by phase, for forward Euler and the predictor-corrector.
///
/// A 1D grid with h = 1 and nodes x = 0, 1, 2, node 2 fixed (the face xmax); linear shape functions; E = 25 Pa,
/// rho_0 = 4 kg/m^3 (c = 2.5 m/s), gravity b = +10 m/s^2 (x points down, towards the support); CFL 0.5, so
/// dt = 0.5 h / c = 0.2 s. Two particles, unstressed and unstrained at t = 0, a_p = 0:
///
/// | p | x_p  | m_p | rho_p | V_p | v_p  | nodes | N_Ip       | grad N_Ip |
/// |---|------|-----|-------|-----|------|-------|------------|-----------|
/// | 0 | 0.25 | 2   | 4     | 0.5 | +1   | 0, 1  | 0.75, 0.25 | -1, +1    |
/// | 1 | 1.5  | 4   | 4     | 1   | -1.5 | 1, 2  | 0.5, 0.5   | -1, +1    |
///
/// By hand (the first step of forward Euler, update stress first):
/// - Eq. (13) and the momentum: m_I = (1.5, 2.5, 2), p_I = (1.5, -2.5, -3); node 2 held: p_2 = 0, v_I^k = (1, -1, 0).
/// - Eq. (16): strain rates p0: (-1)(1) + (1)(-1) = -2, p1: (-1)(-1) + (1)(0) = 1; strains dt rate = (-0.4, 0.2);
///   Eq. (17): rho_p = 4 / 0.6 = 20/3, 4 / 1.2 = 10/3, so V_p = (0.3, 1.2); Eq. (3): sigma_p = E eps = (-10, 5) Pa.
/// - Eq. (14): f^int = (-0.3 (-10)(-1), -0.3 (-10)(1) - 1.2 (5)(-1), -1.2 (5)(1)) = (-3, 9, -6);
///   Eq. (15): f^ext = (0.75 (2)(10), 0.25 (2)(10) + 0.5 (4)(10), 0.5 (4)(10)) = (15, 25, 20);
///   f_I = (12, 34, 14), node 2's 14 a reaction: f_I = (12, 34, 0), a_I = f_I / m_I = (8, 13.6, 0).
/// - Eq. (12): p_I^{k+1} = p_I + dt f_I = (3.9, 4.3, 0), p_I^{k+1} / m_I = (2.6, 1.72, 0).
/// - Eqs. (19)-(22): a_p = (9.4, 6.8), v_p = (2.88, -0.14), x_p = (0.726, 1.672).
///
/// The predictor-corrector's first step: the predictor, Eq. (29), is v_I^k (a_p = 0), so the strains, stresses and
/// forces are forward Euler's; the corrector, Eq. (30), gives v_I^{k+1} = v_I^k + dt a_I / 2 = (1.8, 0.36, 0);
/// Eqs. (31)-(32) give forward Euler's a_p and v_p; Eq. (33) with v_I^k (the default, projected) x_p = (0.538, 1.536),
/// with the corrected v_I^{k+1} x_p = (0.726, 1.672).
#pragma once
#include "mpm/grid/grid_fields.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/shape/linear.hpp"

namespace mpm::testing {

struct WorkedExample {
  static constexpr double young_modulus = 25.0;  ///< Pa
  static constexpr double density = 4.0;         ///< kg/m^3, rho_0 of both particles
  static constexpr double gravity = 10.0;        ///< m/s^2, along +x
  static constexpr double dt = 0.2;              ///< s: CFL 0.5 times h / sqrt(E / rho_0)
  static constexpr int fixed_node = 2;           ///< the face xmax, component x

  Grid<1> grid{Vector<1>(0.0), 1.0, {2}};
  Particles<1> particles;
  Stencils<1> stencils;
  GridFields<1> fields{3};

  WorkedExample() {
    particles.add(Vector<1>(0.25), 2.0, density, Vector<1>(1.0), Vector<1>(0.25));
    particles.add(Vector<1>(1.5), 4.0, density, Vector<1>(-1.5), Vector<1>(0.5));
    LinearShape<1> shape(grid);
    stencils.resize(particles.size(), shape.capacity());
    compute_stencils(shape, particles.position, stencils);
  }

  /// b_p = +10 m/s^2 on both particles (Eq. (15)).
  static ParticleBodyForces<1> body_force() { return {{Vector<1>(gravity), Vector<1>(gravity)}, false, true}; }
};

/// The worked example's grid after its first step's forces (paper/12_worked_example.md): m_I = (1.5, 2.5, 2),
/// f_I = (12, 34, 0) (node 2 held), so a_I = (8, 13.6, 0). Forward Euler's fields: nodal_velocity_k = v_I^k =
/// (1, -1, 0), nodal_momentum_k1 = p_I^{k+1} = p_I + dt f_I = (3.9, 4.3, 0). The predictor-corrector's (gamma = 1/2):
/// nodal_velocity_k1 = the corrected v_I^{k+1} = v_I^k + 0.1 a_I = (1.8, 0.36, 0),
/// nodal_momentum_k = p_I^k = (1.5, -2.5, 0).
inline void worked_example_grid(GridFields<1>& grid, bool predictor_corrector) {
  grid.nodal_mass = {1.5, 2.5, 2.0};
  grid.nodal_force = {Vector<1>(12.0), Vector<1>(34.0), Vector<1>(0.0)};
  if (predictor_corrector) {
    grid.nodal_velocity_k1 = {Vector<1>(1.8), Vector<1>(0.36), Vector<1>(0.0)};
    grid.nodal_momentum_k = {Vector<1>(1.5), Vector<1>(-2.5), Vector<1>(0.0)};
  } else {
    grid.nodal_velocity_k = {Vector<1>(1.0), Vector<1>(-1.0), Vector<1>(0.0)};
    grid.nodal_momentum_k1 = {Vector<1>(3.9), Vector<1>(4.3), Vector<1>(0.0)};
  }
}

}  // namespace mpm::testing
