/// \file
/// Particle-to-grid transfers (P2G): the nodal mass, momentum and the Newmark velocity predictor.
///
/// Contract: read the particles' m_p, v_p, a_p and the step's stencils; write nodal_mass,
/// nodal_momentum_k (nodal_momentum_k1: MUSL's projection of v_p^{k+1}) and a nodal velocity (nodal_velocity_k or the
/// predictor's predicted_velocity). Fields are accumulated into zeroed arrays (GridFields::reset).
/// These are the reference kernels, plain serial loops; their fast forms, on every core, are in
/// mpm/fast/fast_particle_to_grid.hpp.
#pragma once
#include <doctest/doctest.h>

#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// P2G of forward Euler, in one pass over the particles and their stencil nodes: the lumped mass of Eq. (13),
/// \f$ m_I = \sum_J m_{IJ} = \sum_p N_{Ip}\, m_p \f$ (by the partition of unity), and the nodal momentum of
/// Eqs. (21)-(22), \f$ \mathbf p_I^k = \sum_p N_{Ip}\, m_p \mathbf v_p^k \f$. Adds into the zeroed fields.
template <int Dim>
void nodal_mass_and_momentum(ReferenceKernels, const Particles<Dim>& particles, const Stencils<Dim>& stencils,
                             GridFields<Dim>& grid) {
  std::vector<double>& m_I = grid.nodal_mass;
  std::vector<Vector<Dim>>& p_I_k = grid.nodal_momentum_k;
  for (int p = 0; p < particles.size(); ++p) {
    const double m_p = particles.mass[p];
    const Vector<Dim>& v_p_k = particles.velocity[p];
    const ParticleStencil<Dim> stencil = stencils.of(p);
    for (int k = 0; k < stencil.count; ++k) {
      const int I = stencil.node[k];
      const double N_Ip = stencil.value[k];
      m_I[I] += N_Ip * m_p;
      p_I_k[I] += N_Ip * m_p * v_p_k;
    }
  }
}

/// The nodal momentum alone, projected afresh from the particles' updated velocities:
/// \f$ \mathbf p_I^{k+1} = \sum_p N_{Ip}\, m_p \mathbf v_p^{k+1} \f$ (Eqs. (21)-(22)), overwriting what
/// nodal_momentum_k1 held. MUSL projects the updated particle velocities again with it
/// (mpm/integrators/update_stress_last.hpp).
template <int Dim>
void nodal_momentum_from_particles(ReferenceKernels, const Particles<Dim>& particles, const Stencils<Dim>& stencils,
                                   GridFields<Dim>& grid) {
  std::vector<Vector<Dim>>& p_I_k1 = grid.nodal_momentum_k1;
  for (Vector<Dim>& momentum : p_I_k1) momentum.setZero();
  for (int p = 0; p < particles.size(); ++p) {
    const double m_p = particles.mass[p];
    const Vector<Dim>& v_p_k1 = particles.velocity[p];
    const ParticleStencil<Dim> stencil = stencils.of(p);
    for (int k = 0; k < stencil.count; ++k) p_I_k1[stencil.node[k]] += stencil.value[k] * m_p * v_p_k1;
  }
}

/// \f$ \mathbf v_I = \mathbf p_I / m_I \f$ on nodes that carry mass; 0 elsewhere: forward Euler's
/// \f$ \mathbf v_I^k \f$ (nodal_velocity_k) from \f$ \mathbf p_I^k \f$ (nodal_momentum_k), USL's and MUSL's
/// \f$ \mathbf v_I^{k+1} \f$ (nodal_velocity_k1) from \f$ \mathbf p_I^{k+1} \f$ (nodal_momentum_k1: Eq. (12)'s, or
/// MUSL's projected again) (one kernel for both layers: a loop over the nodes, no particles).
template <int Dim>
void nodal_velocity_from_momentum(const GridFields<Dim>& grid, const std::vector<Vector<Dim>>& p_I,
                                  std::vector<Vector<Dim>>& v_I) {
  for (int node = 0; node < grid.size(); ++node)
    v_I[node] = grid.nodal_mass[node] > 0.0 ? Vector<Dim>(p_I[node] / grid.nodal_mass[node]) : Vector<Dim>::Zero();
}

/// P2G of the predictor-corrector, in one pass over the particles and their stencil nodes: the lumped mass of
/// Eq. (13) and Eqs. (27)-(29), the Newmark velocity predictor built by mass-weighted projection: Eq. (26)'s
/// \f$ \mathbf v_I^k + (1-\gamma)\Delta t\, \mathbf a_I^k \f$ with both nodal terms projected from the particles
/// by Eq. (27), which is Eq. (28), gathered into
/// \f[ \mathbf v_I^{pred} = \frac{1}{m_I}\sum_p N_{Ip}\, m_p \left(\mathbf v_p^k + (1-\gamma)\Delta t\,
///     \mathbf a_p^k\right) . \f]
/// Also leaves \f$ \mathbf p_I^k = \sum_p N_{Ip} m_p \mathbf v_p^k \f$ in nodal_momentum_k (the projected
/// velocity p_I^k/m_I of the literal reading of Eq. (33)). Adds into the zeroed fields.
template <int Dim>
void nodal_mass_and_velocity_predictor(ReferenceKernels, const Particles<Dim>& particles,
                                       const Stencils<Dim>& stencils, double newmark_gamma, double dt,
                                       GridFields<Dim>& grid) {
  std::vector<double>& m_I = grid.nodal_mass;
  std::vector<Vector<Dim>>& p_I_k = grid.nodal_momentum_k;
  std::vector<Vector<Dim>>& v_I_pred = grid.predicted_velocity;
  for (int p = 0; p < particles.size(); ++p) {
    const double m_p = particles.mass[p];
    const Vector<Dim>& v_p_k = particles.velocity[p];
    const Vector<Dim>& a_p_k = particles.acceleration[p];
    const Vector<Dim> predicted_momentum = m_p * v_p_k + (1.0 - newmark_gamma) * dt * m_p * a_p_k;
    const ParticleStencil<Dim> stencil = stencils.of(p);
    for (int k = 0; k < stencil.count; ++k) {
      const int I = stencil.node[k];
      const double N_Ip = stencil.value[k];
      m_I[I] += N_Ip * m_p;
      p_I_k[I] += N_Ip * (m_p * v_p_k);
      v_I_pred[I] += N_Ip * predicted_momentum;  // divided by m_I below
    }
  }
  for (int I = 0; I < grid.size(); ++I)
    v_I_pred[I] = m_I[I] > 0.0 ? Vector<Dim>(v_I_pred[I] / m_I[I]) : Vector<Dim>::Zero();
}

TEST_CASE("Eq. (8), Eq. (13), Eq. (21), Eq. (22), Eq. (26), Eq. (27), Eq. (28), Eq. (29): P2G on the worked example: nodal mass, momentum, velocity and predictor by hand") {
  // The first step of scenes/worked_example.toml (paper/12_worked_example.md): m_I = (0.75 * 2, 0.25 * 2 + 0.5 * 4,
  // 0.5 * 4) = (1.5, 2.5, 2); p_I = (0.75 * 2 * 1, 0.25 * 2 * 1 + 0.5 * 4 * -1.5, 0.5 * 4 * -1.5) = (1.5, -2.5, -3),
  // so v_I = (1, -1, -1.5) before the wall holds node 2.
  testing::WorkedExample example;
  auto& grid = example.fields;
  nodal_mass_and_momentum(ReferenceKernels{}, example.particles, example.stencils, grid);
  CHECK(grid.nodal_mass[0] == doctest::Approx(1.5));
  CHECK(grid.nodal_mass[1] == doctest::Approx(2.5));
  CHECK(grid.nodal_mass[2] == doctest::Approx(2.0));
  nodal_velocity_from_momentum(grid, grid.nodal_momentum_k, grid.nodal_velocity_k);
  CHECK(grid.nodal_momentum_k[1][0] == doctest::Approx(-2.5));
  CHECK(grid.nodal_velocity_k[0][0] == doctest::Approx(1.0));
  CHECK(grid.nodal_velocity_k[1][0] == doctest::Approx(-1.0));
  CHECK(grid.nodal_velocity_k[2][0] == doctest::Approx(-1.5));
  // The momentum alone, projected afresh over whatever the field held (MUSL's second projection): the same p_I.
  for (auto& momentum : grid.nodal_momentum_k1) momentum.setConstant(99.0);
  nodal_momentum_from_particles(ReferenceKernels{}, example.particles, example.stencils, grid);
  CHECK(grid.nodal_momentum_k1[0][0] == doctest::Approx(1.5));
  CHECK(grid.nodal_momentum_k1[1][0] == doctest::Approx(-2.5));
  CHECK(grid.nodal_momentum_k1[2][0] == doctest::Approx(-3.0));

  // The predictor of the first step: a_p = 0 at t = 0, so v_I^pred is the projected p_I / m_I, bit for bit.
  const std::vector<Vector<1>> projected = grid.nodal_velocity_k;
  grid.reset();
  nodal_mass_and_velocity_predictor(ReferenceKernels{}, example.particles, example.stencils, 0.5, example.dt, grid);
  for (int node = 0; node < 3; ++node) CHECK(grid.predicted_velocity[node][0] == projected[node][0]);
  // With the accelerations the first step leaves, a_p = (9.4, 6.8) (Eq. (31)), on the particles as they are at
  // t = 0 (a check of the weights, not a state of the run): (1 - gamma) dt = 0.1, v_p + 0.1 a_p = (1.94, -0.82);
  // node 1 gets (0.25 * 2 * 1.94 + 0.5 * 4 * -0.82) / 2.5 = (0.97 - 1.64) / 2.5 = -0.268.
  example.particles.acceleration = {Vector<1>(9.4), Vector<1>(6.8)};
  grid.reset();
  nodal_mass_and_velocity_predictor(ReferenceKernels{}, example.particles, example.stencils, 0.5, example.dt, grid);
  CHECK(grid.nodal_mass[1] == doctest::Approx(2.5));
  CHECK(grid.predicted_velocity[0][0] == doctest::Approx(1.94));
  CHECK(grid.predicted_velocity[1][0] == doctest::Approx(-0.268));
  CHECK(grid.predicted_velocity[2][0] == doctest::Approx(-0.82));
  CHECK(grid.nodal_momentum_k[1][0] == doctest::Approx(-2.5));
}

TEST_CASE("Eq. (26), Eq. (28), Eq. (29): the predictor at gamma = 0.6 by hand: (1 - gamma) dt a_p, not gamma dt a_p") {
  // At gamma = 1/2 the two weights are equal; at 0.6 they differ. The worked example with a_p = (9.4, 6.8) as above,
  // dt = 0.2, so (1 - gamma) dt = 0.08: v_0 + 0.08 a_0 = 1.752 and v_1 + 0.08 a_1 = -0.956 (gamma dt = 0.12 would
  // give 2.128 and -0.684). By hand: node 0: 1.752; node 1: (0.5 * 1.752 + 2 * -0.956) / 2.5 = (0.876 - 1.912) / 2.5
  // = -0.4144; node 2: -0.956.
  testing::WorkedExample example;
  example.particles.acceleration = {Vector<1>(9.4), Vector<1>(6.8)};
  auto& grid = example.fields;
  nodal_mass_and_velocity_predictor(ReferenceKernels{}, example.particles, example.stencils, 0.6, example.dt, grid);
  CHECK(grid.predicted_velocity[0][0] == doctest::Approx(1.752));
  CHECK(grid.predicted_velocity[1][0] == doctest::Approx(-0.4144));
  CHECK(grid.predicted_velocity[2][0] == doctest::Approx(-0.956));
  // The momentum left beside it is the projected p_I of v_p^k alone: (1.5, -2.5, -3).
  CHECK(grid.nodal_momentum_k[0][0] == doctest::Approx(1.5));
  CHECK(grid.nodal_momentum_k[2][0] == doctest::Approx(-3.0));
}

}  // namespace mpm
