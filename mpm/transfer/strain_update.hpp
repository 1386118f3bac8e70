/// \file
/// Particle state from the nodal velocities: strain rate, strain, density, stress (forward Euler's phase 4, the
/// predictor-corrector's phase 3: the "update stress first" order of both integrators).
///
/// The small-strain kinematics of Eq. (1), \f$ \boldsymbol\varepsilon = \nabla^s \mathbf u \f$, are
/// integrated in time from the velocity gradient (Eq. 16) rather than from displacements, and mass
/// conservation, Eq. (4), \f$ \dot\rho + \rho\,\nabla\cdot\mathbf v = 0 \f$, becomes the density update Eq. (17).
/// Integrated on the moving particles, the strain is the time integral of the rate of deformation,
/// which is the logarithmic strain ln(lambda) only while the principal axes of stretch do not rotate
/// (a uniaxial stretch, a confined column: the doctest below), not under rotation or simple shear. The
/// soil block is such a confined column: its settlement converges to the finite-strain column, not the
/// small-strain one (report).
///
/// Contract: read a nodal velocity (the integrator's: v_I^k, v_I^{pred} or v_I^{k+1}) and the stencils; write the particles' epsilon_p, rho_p, sigma_p. These are the
/// reference kernels, plain serial loops; their fast forms are in mpm/fast/fast_strain_update.hpp.
#pragma once
#include <doctest/doctest.h>

#include <cmath>

#include <vector>

#include "mpm/core/kernels.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/material/linear_elastic.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/transfer/worked_example.hpp"

namespace mpm {

/// Eq. (16), the rate of deformation of particle p from the nodal velocities \f$ \mathbf v_I \f$:
/// \f[ \dot{\boldsymbol\varepsilon}_p = \tfrac12 \sum_I \left[\nabla N_{Ip} \otimes \mathbf v_I
///     + \mathbf v_I \otimes \nabla N_{Ip}\right] , \f]
/// the symmetric part of the velocity gradient \f$ \sum_I \mathbf v_I \otimes \nabla N_{Ip} \f$.
template <int Dim>
Matrix<Dim> strain_rate(const Stencils<Dim>& stencils, int p, const std::vector<Vector<Dim>>& v_I) {
  const ParticleStencil<Dim> stencil = stencils.of(p);
  Matrix<Dim> velocity_gradient = Matrix<Dim>::Zero();
  for (int k = 0; k < stencil.count; ++k) velocity_gradient += v_I[stencil.node[k]] * stencil.gradient[k].transpose();
  return 0.5 * (velocity_gradient + velocity_gradient.transpose());
}

/// Eq. (17) discretised as the authors do (paper/09_choices.md, 'The density update'): \f$ \rho_p^{k+1} = \rho_p^k / (1 + \Delta t\,\mathrm{tr}\,\dot{\boldsymbol\varepsilon}_p) \f$.
inline double updated_density(double density, double dt, double volumetric_strain_rate) {
  return density / (1.0 + dt * volumetric_strain_rate);
}

/// Forward Euler's phase 4, the predictor-corrector's phase 3, particle by particle: the strain rate of Eq. (16)
/// from the nodal velocity v_I the integrator passes (\f$ \mathbf v_I^k \f$, \f$ \mathbf v_I^{pred} \f$ or
/// \f$ \mathbf v_I^{k+1} \f$), the strain \f$ \boldsymbol\varepsilon_p^{k+1} = \boldsymbol\varepsilon_p^k +
/// \Delta t\,\dot{\boldsymbol\varepsilon}_p \f$, the density by Eq. (17), \f$ \rho_p^{k+1} = \rho_p^k /
/// (1 + \Delta t\,\mathrm{tr}\,\dot{\boldsymbol\varepsilon}_p) \f$, and the stress by Hooke's law, Eq. (3),
/// \f$ \boldsymbol\sigma_p^{k+1} = \mathbf D\, \boldsymbol\varepsilon_p^{k+1} \f$ of the particle's own material.
template <int Dim>
void update_strain_density_stress(ReferenceKernels, const Stencils<Dim>& stencils, const std::vector<Vector<Dim>>& v_I,
                                  const std::vector<LinearElastic>& materials, double dt, Particles<Dim>& particles) {
  for (int p = 0; p < particles.size(); ++p) {
    const LinearElastic& material = materials[particles.material[p]];
    const Matrix<Dim> rate = strain_rate(stencils, p, v_I);
    particles.strain[p] += dt * rate;
    particles.density[p] = updated_density(particles.density[p], dt, rate.trace());
    particles.stress[p] = material.stress<Dim>(particles.strain[p]);
    particles.stress_zz[p] = material.stress_zz<Dim>(particles.strain[p]);
  }
}

TEST_CASE("Eq. (3): each particle's stress by its own material: two bodies, E = 25 and 75 Pa, the same strain") {
  // The worked example's first step, the second particle of material 1: the nodal velocities v_I^k = (1, -1, 0)
  // give particle 0 the strain -0.4 (stress -10 Pa at E = 25) and particle 1 0.2: 5 Pa at E = 25, 15 at 75.
  testing::WorkedExample example;
  example.particles.material[1] = 1;
  const std::vector<Vector<1>> nodal_velocity{Vector<1>(1.0), Vector<1>(-1.0), Vector<1>(0.0)};
  const std::vector<LinearElastic> materials{LinearElastic{25.0, 0.0, 4.0}, LinearElastic{75.0, 0.0, 4.0}};
  update_strain_density_stress(ReferenceKernels{}, example.stencils, nodal_velocity, materials, example.dt,
                               example.particles);
  CHECK(example.particles.stress[0](0, 0) == doctest::Approx(-10.0));
  CHECK(example.particles.stress[1](0, 0) == doctest::Approx(15.0));
}

TEST_CASE("Eq. (16), Eq. (17), Eq. (1), Eq. (4), Eq. (3): strain rate, density and stress: the worked example and a 2D shear") {
  // The first step of scenes/worked_example.toml (paper/12_worked_example.md), node 2 held: v_I^k = (1, -1, 0).
  // Strain rates -1 (1) + 1 (-1) = -2 and -1 (-1) + 1 (0) = 1; dt = 0.2: strains -0.4 and 0.2 (from 0 at t = 0),
  // stresses E eps = 25 (-0.4, 0.2) = (-10, 5) Pa, densities 4 / (1 - 0.4) = 20/3 and 4 / 1.2 = 10/3, volumes 0.3, 1.2.
  testing::WorkedExample example;
  const std::vector<Vector<1>> nodal_velocity{Vector<1>(1.0), Vector<1>(-1.0), Vector<1>(0.0)};
  CHECK(strain_rate(example.stencils, 0, nodal_velocity)(0, 0) == doctest::Approx(-2.0));
  CHECK(strain_rate(example.stencils, 1, nodal_velocity)(0, 0) == doctest::Approx(1.0));
  const std::vector<LinearElastic> material{LinearElastic{example.young_modulus, 0.0, example.density}};
  update_strain_density_stress(ReferenceKernels{}, example.stencils, nodal_velocity, material, example.dt,
                               example.particles);
  CHECK(example.particles.strain[0](0, 0) == doctest::Approx(-0.4));
  CHECK(example.particles.strain[1](0, 0) == doctest::Approx(0.2));
  CHECK(example.particles.stress[0](0, 0) == doctest::Approx(-10.0));
  CHECK(example.particles.stress[1](0, 0) == doctest::Approx(5.0));
  CHECK(example.particles.density[0] == doctest::Approx(20.0 / 3.0));  // compression: denser
  CHECK(example.particles.density[1] == doctest::Approx(10.0 / 3.0));
  CHECK(example.particles.volume(0) == doctest::Approx(0.3));
  CHECK(example.particles.volume(1) == doctest::Approx(1.2));
  // The same rates once more: the strain accumulates (-0.8, 0.4), the stress is E times the total strain (-20, 10),
  // the density is divided again: 20/3 / 0.6 = 100/9.
  update_strain_density_stress(ReferenceKernels{}, example.stencils, nodal_velocity, material, example.dt,
                               example.particles);
  CHECK(example.particles.strain[0](0, 0) == doctest::Approx(-0.8));
  CHECK(example.particles.stress[0](0, 0) == doctest::Approx(-20.0));
  CHECK(example.particles.stress[1](0, 0) == doctest::Approx(10.0));
  CHECK(example.particles.density[0] == doctest::Approx(100.0 / 9.0));

  // 2D: nodal velocities v = (y, 0) sampled at the corners of a unit cell give pure shear,
  // grad v = [[0, 1], [0, 0]], so the strain rate is [[0, 1/2], [1/2, 0]] anywhere in the cell.
  const Grid<2> grid(Vector<2>::Zero(), 1.0, {1, 1});
  LinearShape<2> q4(grid);
  Stencils<2> stencils;
  stencils.resize(1, q4.capacity());
  compute_stencils(q4, std::vector<Vector<2>>{Vector<2>(0.3, 0.8)}, stencils);
  std::vector<Vector<2>> shear(4);
  for (int node = 0; node < 4; ++node) shear[node] = Vector<2>(grid.node_position(node)[1], 0.0);
  const Matrix<2> rate = strain_rate(stencils, 0, shear);
  CHECK(rate(0, 1) == doctest::Approx(0.5));
  CHECK(rate(1, 0) == doctest::Approx(0.5));
  CHECK(rate(0, 0) == doctest::Approx(0.0));
  CHECK(rate(1, 1) == doctest::Approx(0.0));
  // A general linear field v = (x + 2y, 5x - 3y), which Q4 reproduces: grad v = [[1, 2], [5, -3]], whose
  // symmetric part is [[1, 3.5], [3.5, -3]] (each entry distinct: a swapped or dropped term shows).
  std::vector<Vector<2>> linear_field(4);
  for (int node = 0; node < 4; ++node) {
    const Vector<2> x = grid.node_position(node);
    linear_field[node] = Vector<2>(x[0] + 2.0 * x[1], 5.0 * x[0] - 3.0 * x[1]);
  }
  const Matrix<2> general = strain_rate(stencils, 0, linear_field);
  CHECK(general(0, 0) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(general(1, 1) == doctest::Approx(-3.0).epsilon(1e-14));
  CHECK(general(0, 1) == doctest::Approx(3.5).epsilon(1e-14));
  CHECK(general(1, 0) == doctest::Approx(3.5).epsilon(1e-14));
}

TEST_CASE("Eq. (17): rho / (1 + x), x = dt tr(eps_dot): positive for any expansion, in compression only while x > -1, it differs from rho e^{-x} by rho x^2 / 2, first order") {
  // 1/(1+x) = 1 - x + x^2 - ..., e^{-x} = 1 - x + x^2/2 - ...: the x^2 terms differ, so the two agree to
  // first order only: (1/(1+x) - e^{-x}) / x^2 = 1/2 - 5x/6 + ... -> 1/2.
  for (const double x : {1e-2, -1e-2, 1e-3}) {
    const double difference = updated_density(3.0, 1.0, x) - 3.0 * std::exp(-x);
    CHECK(difference / (3.0 * x * x) == doctest::Approx(0.5).epsilon(2.0 * std::abs(x)));
  }
  CHECK(updated_density(3.0, 0.5, 2e6) == doctest::Approx(3.0 / (1.0 + 1e6)));  // expansion: always > 0
  CHECK(updated_density(3.0, 0.5, 2e6) > 0.0);
  CHECK(updated_density(3.0, 0.5, -1.0) == doctest::Approx(6.0));  // x = -0.5: compression, twice as dense
  CHECK(updated_density(3.0, 0.5, -3.0) == doctest::Approx(-6.0));  // x = -1.5: past the limit, negative
}

TEST_CASE("Eq. (16), Eq. (17): a uniaxial stretch v = r x on moving particles: the accumulated strain is ln(lambda), not lambda - 1, rho lambda = rho_0 exactly") {
  // Two particles move with v = r x (r = 1/s, reproduced exactly by linear shape functions) for T = 0.5 s
  // in steps of 1e-4 s: their distance grows by (1 + r dt) a step, lambda = (1.0001)^5000 = 1.64866, so
  // ln(lambda) = 5000 ln(1.0001) = 0.499975 and lambda - 1 = 0.6487. The strain adds r dt a step: 0.5.
  // The density is divided by (1 + r dt) a step, as the distance is multiplied: rho lambda = rho_0.
  const double r = 1.0, dt = 1e-4;
  const Grid<1> grid(Vector<1>(0.0), 1.0, {2});
  LinearShape<1> shape(grid);
  Particles<1> particles;
  particles.add(Vector<1>(0.5), 1.0, 4.0, Vector<1>(0.5 * r), Vector<1>(0.25));
  particles.add(Vector<1>(0.7), 1.0, 4.0, Vector<1>(0.7 * r), Vector<1>(0.25));
  Stencils<1> stencils;
  stencils.resize(particles.size(), shape.capacity());
  const std::vector<Vector<1>> nodal_velocity{Vector<1>(0.0), Vector<1>(r), Vector<1>(2.0 * r)};
  for (int step = 0; step < 5000; ++step) {
    compute_stencils(shape, particles.position, stencils);
    update_strain_density_stress(ReferenceKernels{}, stencils, nodal_velocity, {LinearElastic{100.0, 0.0, 4.0}}, dt,
                                 particles);
    for (int p = 0; p < 2; ++p) particles.position[p][0] += dt * r * particles.position[p][0];
  }
  const double stretch = (particles.position[1][0] - particles.position[0][0]) / 0.2;
  CHECK(stretch == doctest::Approx(std::pow(1.0001, 5000)).epsilon(1e-12));
  CHECK(particles.strain[0](0, 0) == doctest::Approx(0.5).epsilon(1e-12));
  CHECK(particles.stress[0](0, 0) == doctest::Approx(100.0 * 0.5).epsilon(1e-12));  // E times the total strain
  CHECK(std::abs(particles.strain[0](0, 0) - std::log(stretch)) < 3e-5);  // 0.5 - 0.499975
  CHECK(std::abs(particles.strain[0](0, 0) - (stretch - 1.0)) > 0.14);    // 0.6487 - 0.5
  CHECK(particles.density[1] * stretch == doctest::Approx(4.0).epsilon(1e-12));
}

}  // namespace mpm
