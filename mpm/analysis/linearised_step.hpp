/// \file
/// The code's own step, linearised about rest: the matrix \f$ \mathbf S \f$ with
/// \f$ \mathbf z^{k+1} = \mathbf S\, \mathbf z^k \f$ for the particle state
/// \f$ \mathbf z = (\mathbf v_p, \boldsymbol\varepsilon_p, \mathbf a_p)_p \f$ (the stress is Hooke's law of the strain, Eq. (3)), built column by column by applying the real
/// Integrator::step() to unit perturbations of a body at rest (paper/10_integrator_analysis.md).
///
/// About rest every term of the step is linear in \f$ \mathbf z \f$ except two that multiply a perturbation by
/// another (the volume \f$ m_p/\rho_p \f$ of Eq. (17) times the stress of the strain, the moved positions of the next
/// stencils): central differences \f$ (\mathbf S(\epsilon \mathbf e_j) - \mathbf S(-\epsilon \mathbf e_j)) / 2\epsilon \f$
/// cancel the first; the stencils stay at the rest positions, which is the linearisation of the second.
/// The step is stable while the spectral radius \f$ \rho(\mathbf S) \le 1 \f$.
///
/// The unknowns are measured in the body's own units (state_scales()): in SI units a steel bar's
/// \f$ \mathbf S \f$ spans 22 orders of magnitude and the eigensolver's round-off alone gives a spectral radius of 2.2
/// at CFL 0.1; \f$ \mathbf D^{-1} \mathbf S \mathbf D \f$ has the same eigenvalues and no such spread.
#pragma once
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "mpm/analysis/eigenvalues.hpp"
#include "mpm/core/step_phases.hpp"
#include "mpm/fast/fast_layer.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/model.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/integrators/forward_euler.hpp"
#include "mpm/integrators/newmark_predictor_corrector.hpp"
#include "mpm/integrators/update_stress_last.hpp"
#include "mpm/shape/linear.hpp"

namespace mpm {

/// Unknowns per particle of the linearised step: v (Dim), the in-plane strain (Dim (Dim + 1) / 2) and a (Dim).
template <int Dim>
constexpr int linearised_states_per_particle() {
  return Dim + Dim * (Dim + 1) / 2 + Dim;
}

namespace detail {

/// The unit of each unknown of a particle (the diagonal of \f$ \mathbf D \f$): velocity \f$ c \f$, strain 1,
/// acceleration \f$ c^2 / h \f$, with \f$ c = \max \sqrt{E/\rho_0} \f$ over the materials and h the grid spacing.
template <int Dim>
Eigen::VectorXd state_scales(const Model<Dim>& model) {
  double wave_speed = 0.0;
  for (const LinearElastic& material : model.materials)
    wave_speed = std::max(wave_speed, std::sqrt(material.young_modulus / material.density));
  Eigen::VectorXd scales = Eigen::VectorXd::Ones(linearised_states_per_particle<Dim>());
  scales.head(Dim).setConstant(wave_speed);
  scales.tail(Dim).setConstant(wave_speed * wave_speed / model.grid.spacing());
  return scales;
}

/// Adds amount to unknown `state` of the particle state (its layout: linearised_states_per_particle()).
template <int Dim>
void perturb_state(Particles<Dim>& particles, int state, double amount) {
  const int per_particle = linearised_states_per_particle<Dim>(), p = state / per_particle;
  int local = state % per_particle;
  if (local < Dim) {
    particles.velocity[p][local] += amount;
    return;
  }
  local -= Dim;
  if (local < Dim * (Dim + 1) / 2) {
    const int row = local < Dim ? local : 0, column = local < Dim ? local : 1;  // xx, yy, then xy
    particles.strain[p](row, column) += amount;
    if (row != column) particles.strain[p](column, row) += amount;
    return;
  }
  particles.acceleration[p][local - Dim * (Dim + 1) / 2] += amount;
}

/// The particle state as one vector, in the layout of perturb_state().
template <int Dim>
Eigen::VectorXd state_vector(const Particles<Dim>& particles) {
  const int per_particle = linearised_states_per_particle<Dim>();
  Eigen::VectorXd state(particles.size() * per_particle);
  for (int p = 0; p < particles.size(); ++p) {
    int k = p * per_particle;
    for (int axis = 0; axis < Dim; ++axis) state[k++] = particles.velocity[p][axis];
    for (int axis = 0; axis < Dim; ++axis) state[k++] = particles.strain[p](axis, axis);
    if (Dim == 2) state[k++] = particles.strain[p](0, Dim - 1);
    for (int axis = 0; axis < Dim; ++axis) state[k++] = particles.acceleration[p][axis];
  }
  return state;
}

}  // namespace detail

/// The linearised step matrix of `integrator` with time step dt, for the body `rest` (at rest:
/// zero velocity, stress and acceleration), its stencils from `shape` at the rest positions and no body force;
/// in the units of detail::state_scales(), i.e. \f$ \mathbf D^{-1} \mathbf S \mathbf D \f$.
template <int Dim, class Shape, class Integrator>
Eigen::MatrixXd linearised_step_matrix(const Model<Dim>& model, const Particles<Dim>& rest, Shape& shape,
                                       const Integrator& integrator, double dt) {
  Particles<Dim> particles = rest;
  shape.initialise(particles);
  Stencils<Dim> stencils;
  stencils.resize(particles.size(), shape.capacity());
  compute_stencils(shape, particles.position, stencils);
  ParticleBodyForces<Dim> no_body_force;
  no_body_force.per_unit_mass.assign(particles.size(), Vector<Dim>::Zero());
  GridFields<Dim> grid(model.grid.node_count());
  const AnalysisKernels kernels;  // one for every step below (the fast layer's: the workspace of its scatters)
  NoPhaseObserver observer;
  const int size = particles.size() * linearised_states_per_particle<Dim>();
  const double perturbation = 1e-6;
  const Eigen::VectorXd unit = detail::state_scales(model).replicate(particles.size(), 1);
  Eigen::MatrixXd step(size, size);
  for (int column = 0; column < size; ++column) {
    Eigen::VectorXd response[2];
    for (int side = 0; side < 2; ++side) {
      particles = rest;
      detail::perturb_state(particles, column, (side == 0 ? perturbation : -perturbation) * unit[column]);
      for (int p = 0; p < particles.size(); ++p) {  // the stress of the strain, Eq. (3): read by the forces of USL and MUSL
        const LinearElastic& material = model.materials[particles.material[p]];
        particles.stress[p] = material.stress<Dim>(particles.strain[p]);
        particles.stress_zz[p] = material.stress_zz<Dim>(particles.strain[p]);
      }
      integrator.step(kernels, model, stencils, no_body_force, dt, particles, grid, observer);
      response[side] = detail::state_vector(particles);
    }
    step.col(column) = (response[0] - response[1]).cwiseQuotient(unit) / (2.0 * perturbation);
  }
  return step;
}

// spectral_radius and highest_mode_omega_dt: mpm/analysis/eigenvalues.hpp

TEST_CASE("Linearised step: a bar of 4 cells held at both ends, its highest mode and the limits by hand") {
  // Linear shapes, one particle per cell at the centres, c = h = 1: the modes sin(j pi x / 4) have
  // omega = sin(j pi / 4) (paper/10_integrator_analysis.md), the highest omega = 1 at j = 2, so Omega = dt.
  Model<1> model;
  model.grid = Grid<1>(Vector<1>(0.0), 1.0, {4});
  model.materials = {LinearElastic{1.0, 0.0, 1.0}};
  model.fixed = {{0, 0}, {4, 0}};
  Particles<1> bar;
  for (int cell = 0; cell < 4; ++cell) bar.add(Vector<1>(cell + 0.5), 1.0, 1.0, Vector<1>::Zero(), Vector<1>(0.5));
  LinearShape<1> shape(model.grid);
  const ForwardEuler euler;
  CHECK(highest_mode_omega_dt(linearised_step_matrix(model, bar, shape, euler, 0.3)) == doctest::Approx(0.3).epsilon(1e-9).scale(0.0));
  // 4 particles x (v, eps, a) unknowns; forward Euler's limit Omega < 2, Eq. (32)'s sqrt(2) at gamma = 1/2
  CHECK(linearised_step_matrix(model, bar, shape, euler, 0.3).rows() == 12);
  CHECK(spectral_radius(linearised_step_matrix(model, bar, shape, euler, 1.99)) <= 1.0 + 1e-9);
  CHECK(spectral_radius(linearised_step_matrix(model, bar, shape, euler, 2.01)) > 1.1);
  NewmarkPredictorCorrector predictor_corrector;
  CHECK(spectral_radius(linearised_step_matrix(model, bar, shape, predictor_corrector, 1.40)) <= 1.0 + 1e-9);
  CHECK(spectral_radius(linearised_step_matrix(model, bar, shape, predictor_corrector, 1.43)) > 1.0 + 1e-3);
}

TEST_CASE("Linearised step: a steel bar in SI units, free at one end, is as stable as the same bar in units of c and h") {
  // 40 cells of h = L/40 with L = 0.1333 m, E = 200 GPa, rho = 7833 kg/m^3 (the Dyka bar), held at x = L: the
  // predictor-corrector at CFL 0.1 is stable and at CFL 1.5 is not, in SI units as in units where c = h = 1.
  // Unscaled, the eigensolver's round-off made the SI bar's radius 2.2 at CFL 0.1.
  for (const bool si : {true, false}) {
    const double length = si ? 0.1333 : 40.0, young_modulus = si ? 200e9 : 1.0, density = si ? 7833.0 : 1.0;
    Model<1> model;
    model.grid = Grid<1>(Vector<1>(0.0), length / 40.0, {40});
    model.materials = {LinearElastic{young_modulus, 0.0, density}};
    model.fixed = {{40, 0}};
    const double h = model.grid.spacing(), c = std::sqrt(young_modulus / density);
    Particles<1> bar;
    for (int cell = 0; cell < 40; ++cell)
      bar.add(Vector<1>((cell + 0.5) * h), density * h, density, Vector<1>::Zero(), Vector<1>(0.5 * h));
    LinearShape<1> shape(model.grid);
    const NewmarkPredictorCorrector predictor_corrector;
    CHECK(spectral_radius(linearised_step_matrix(model, bar, shape, predictor_corrector, 0.1 * h / c)) <= 1.0 + 1e-6);
    CHECK(spectral_radius(linearised_step_matrix(model, bar, shape, predictor_corrector, 1.5 * h / c)) > 1.1);
  }
}

TEST_CASE("USL, MUSL: stability limits by hand: USL at CFL 1/sqrt(2) from the strain that no particle velocity carries, MUSL at 2 as USF") {
  // Linear shapes, one particle per cell at the centres, E = rho = h = 1 (c = 1), 64 cells held at both ends.
  // The strain eps_p = (-1)^p, at rest, gives nodal forces f_I = sigma_I - sigma_{I-1} = 2 (-1)^I, which the particles
  // do not feel (N_Ip = 1/2 averages them to 0). USL takes the strain rate from v_I^{k+1} = dt f_I / m_I, so
  // eps^{k+1} = (1 - 4 dt^2) eps: it grows beyond dt = 1/sqrt(2) (at the walls the mode is not exact; 64 cells
  // come within 1e-3 of the long bar). USF and MUSL take the nodal velocity from the particles', which do not carry
  // it: their limit is forward Euler's dt = 2 (the highest mode the particles see, omega = 1).
  const int cells = 64;
  Model<1> model;
  model.grid = Grid<1>(Vector<1>(0.0), 1.0, {cells});
  model.materials = {LinearElastic{1.0, 0.0, 1.0}};
  model.fixed = {{0, 0}, {cells, 0}};
  Particles<1> bar;
  for (int cell = 0; cell < cells; ++cell) bar.add(Vector<1>(cell + 0.5), 1.0, 1.0, Vector<1>::Zero(), Vector<1>(0.5));
  LinearShape<1> shape(model.grid);
  UpdateStressLast usl, musl;
  musl.stress_velocity = MuslMomentumK1{};
  auto radius = [&](const UpdateStressLast& integrator, double dt) { return spectral_radius(linearised_step_matrix(model, bar, shape, integrator, dt)); };
  CHECK(radius(usl, 0.700) <= 1.0 + 1e-9);
  CHECK(radius(usl, 0.714) > 1.0 + 1e-3);
  CHECK(radius(musl, 1.99) <= 1.0 + 1e-9);
  CHECK(radius(musl, 2.01) > 1.0 + 1e-3);
}

}  // namespace mpm
