/// \file
/// The explicit time step, Eq. (42), recomputed every step before anything else.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "mpm/particles/particles.hpp"
#include "mpm/run_control.hpp"

namespace mpm {

/// Eq. (42): \f$ \Delta t = \mathrm{CFL}\, h / C_{el} \f$ with
/// \f$ C_{el} = \max\{\max_p |\mathbf v_p|,\ \max_p \sqrt{E/\rho_p}\} \f$ (or their sum).
/// Given the two speeds: fastest_particle = \f$ \max_p |\mathbf v_p| \f$, wave_speed = \f$ \max_p \sqrt{E/\rho_p} \f$.
inline double courant_time_step(double fastest_particle, double wave_speed, double cell_size, double cfl,
                                CourantSpeed rule = CourantSpeed::maximum) {
  const double speed = rule == CourantSpeed::maximum ? std::max(fastest_particle, wave_speed)
                                                     : wave_speed + fastest_particle;
  return cfl * cell_size / speed;
}

/// From the particles. (The time-step loop takes the two speeds from its survey pass instead:
/// mpm/analysis/particle_survey.hpp.)
template <int Dim>
double courant_time_step(const Particles<Dim>& particles, double young_modulus, double cell_size, double cfl,
                         CourantSpeed rule = CourantSpeed::maximum) {
  double fastest_particle = 0.0, wave_speed = 0.0;
  for (int p = 0; p < particles.size(); ++p) {
    fastest_particle = std::max(fastest_particle, particles.velocity[p].norm());
    wave_speed = std::max(wave_speed, std::sqrt(young_modulus / particles.density[p]));
  }
  return courant_time_step(fastest_particle, wave_speed, cell_size, cfl, rule);
}

TEST_CASE("Eq. (42): Courant time step: the Dyka bar at 40 cells") {
  Particles<1> bar;
  bar.add(Vector<1>(0.0), 1.0, 7833.0, Vector<1>(-5.0), Vector<1>(0.0));
  const double h = 0.1333 / 40, c = std::sqrt(200e9 / 7833.0);  // c = 5053.0 m/s
  CHECK(courant_time_step(bar, 200e9, h, 0.5) == doctest::Approx(0.5 * h / c).epsilon(1e-14));
  // As ratios: doctest's Approx compares within 1e-5 of max(1, |x|), far wider than a time step of 3e-7 s.
  CHECK(courant_time_step(bar, 200e9, h, 0.5, CourantSpeed::sum) / (0.5 * h / (c + 5.0)) == doctest::Approx(1.0).epsilon(1e-14));
  bar.velocity[0] = Vector<1>(1e4);  // faster than sound: the particle speed governs
  CHECK(courant_time_step(bar, 200e9, h, 0.5) / (0.5 * h / 1e4) == doctest::Approx(1.0).epsilon(1e-14));
}

}  // namespace mpm
