/// \file
/// What the time-step loop needs to know about the particles after every step, gathered in one
/// pass over them: the balances (output, energy check), the two speeds of the next step's
/// Courant condition, Eq. (42), and whether every particle is finite and on the grid.
///
/// (One pass instead of three: each pass over the particles costs about as much as a transfer.)
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/analysis/energy.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/integrators/time_step.hpp"
#include "mpm/material/linear_elastic.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm {

template <int Dim>
struct ParticleSurvey {
  Balances<Dim> balances;
  double fastest_speed_squared = 0.0;                                 ///< \f$ \max_p |\mathbf v_p|^2 \f$
  double stiffest_ratio = 0.0;  ///< \f$ \max_p E_p/\rho_p \f$, E_p the Young's modulus of particle p's material
  int unhealthy = 0;  ///< particles with a NaN or infinity in their state, or off the grid

  /// \f$ \max_p |\mathbf v_p| \f$ (sqrt is monotone: the same number as the max of the norms).
  double fastest_speed() const { return std::sqrt(fastest_speed_squared); }
  /// \f$ \max_p \sqrt{E_p/\rho_p} \f$, bit for bit (sqrt is monotone).
  double wave_speed() const { return std::sqrt(stiffest_ratio); }
};

/// Whether particle p's state is finite and its position on the grid.
template <int Dim>
bool healthy(const Particles<Dim>& particles, const Grid<Dim>& grid, int p) {
  return particles.position[p].allFinite() && particles.velocity[p].allFinite() && particles.stress[p].allFinite() &&
         std::isfinite(particles.density[p]) && grid.contains(particles.position[p]);
}

/// One pass over the particles (on every core): the balances are summed in the order of balances().
template <int Dim>
ParticleSurvey<Dim> survey_particles(const Particles<Dim>& particles, const Grid<Dim>& grid, const std::vector<LinearElastic>& materials) {
  return parallel_sum(
      particles.size(), 4, ParticleSurvey<Dim>(),  // the work of a particle: about that of 4 stencil entries
      [&](int p, ParticleSurvey<Dim>& survey) {
        add_to_balances(particles, p, survey.balances);
        survey.fastest_speed_squared = std::max(survey.fastest_speed_squared, particles.velocity[p].squaredNorm());
        survey.stiffest_ratio = std::max(survey.stiffest_ratio, materials[particles.material[p]].young_modulus / particles.density[p]);
        if (!healthy(particles, grid, p)) ++survey.unhealthy;
      },
      [](ParticleSurvey<Dim>& total, const ParticleSurvey<Dim>& part) {
        total.balances.kinetic += part.balances.kinetic;
        total.balances.strain += part.balances.strain;
        total.balances.momentum += part.balances.momentum;
        total.balances.mass += part.balances.mass;
        total.fastest_speed_squared = std::max(total.fastest_speed_squared, part.fastest_speed_squared);
        total.stiffest_ratio = std::max(total.stiffest_ratio, part.stiffest_ratio);
        total.unhealthy += part.unhealthy;
      });
}

TEST_CASE("Particle survey: the balances and Eq. (42)'s speeds of one pass equal those of their own passes, the same bits on 1 and 2 threads") {
  const Grid<2> grid(Vector<2>(0.0, 0.0), 0.5, {8, 8});
  Particles<2> particles;
  for (int p = 0; p < 5000; ++p) {  // 8 chunks, above parallel_work: the survey runs on the team
    const double s = std::sin(0.37 * p), c = std::cos(1.3 * p);
    particles.add(Vector<2>(2.0 + 1.5 * s, 2.0 + 1.5 * c), 0.1 + 0.01 * (p % 7), 1000.0 * (1.0 + 0.1 * s * c),
                  Vector<2>(s, -3.0 * c), Vector<2>(0.1, 0.1));
    particles.strain[p] << 1e-3 * s, 2e-4 * c, 2e-4 * c, -1e-3 * c;
    particles.stress[p] = 1e6 * particles.strain[p];
  }
  const double E = 1e7, h = grid.spacing();
  const std::vector<LinearElastic> material{LinearElastic{E, 0.0, 1000.0}};
  use_threads(1);
  const ParticleSurvey<2> one = survey_particles(particles, grid, material);
  const Balances<2> sums = balances(particles);  // the plain serial loop: the chunks add in another order
  CHECK(one.balances.kinetic == doctest::Approx(sums.kinetic).epsilon(1e-14));
  CHECK(one.balances.strain == doctest::Approx(sums.strain).epsilon(1e-14));
  CHECK(one.balances.momentum[1] == doctest::Approx(sums.momentum[1]).epsilon(1e-12));
  CHECK(one.balances.mass == doctest::Approx(sums.mass).epsilon(1e-14));
  CHECK(one.unhealthy == 0);
  for (CourantSpeed rule : {CourantSpeed::maximum, CourantSpeed::sum})
    CHECK(courant_time_step(one.fastest_speed(), one.wave_speed(), h, 0.5, rule) == courant_time_step(particles, E, h, 0.5, rule));
  const TeamAlways on_the_team;
  use_threads(2);
  const ParticleSurvey<2> two = survey_particles(particles, grid, material);
  CHECK(two.balances.kinetic == one.balances.kinetic);
  CHECK(two.balances.strain == one.balances.strain);
  CHECK(two.balances.momentum == one.balances.momentum);
  CHECK(two.fastest_speed_squared == one.fastest_speed_squared);
  CHECK(two.stiffest_ratio == one.stiffest_ratio);
  // Two materials: the wave speed is the largest of sqrt(E_p / rho_p) over the particles, here of particle
  // 1000, made of a material 4 times stiffer: twice its speed in the first material.
  particles.material[1000] = 1;
  const std::vector<LinearElastic> two_materials{material[0], LinearElastic{4.0 * E, 0.0, 1000.0}};
  CHECK(survey_particles(particles, grid, two_materials).wave_speed() == doctest::Approx(2.0 * std::sqrt(E / particles.density[1000])));
  particles.velocity[4999][1] = std::nan("");
  particles.position[5] = Vector<2>(-1.0, 1.0);
  CHECK(survey_particles(particles, grid, two_materials).unhealthy == 2);
  use_threads(1);
}

}  // namespace mpm
