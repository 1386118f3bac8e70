/// \file
/// The largest stable CFL of a method, from the spectral radius of its own linearised step
/// (mpm/analysis/linearised_step.hpp) on a uniform body, beside the limit that the one-mode analysis
/// (mpm/analysis/mode_analysis.hpp) predicts from the highest mode (paper/10_integrator_analysis.md).
/// `mpm stability` prints it; `mpm run` warns with it.
#pragma once
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "mpm/analysis/linearised_step.hpp"
#include "mpm/analysis/mode_analysis.hpp"
#include "mpm/run.hpp"
#include "mpm/stability_api.hpp"

namespace mpm {

/// The step of a stability body at a CFL number: \f$ \Delta t = \mathrm{CFL}\, h / c \f$, c of its (one) material.
template <int Dim>
double stability_time_step(const Setup<Dim>& setup, double cfl) {
  return cfl * setup.model.grid.spacing() / std::sqrt(setup.model.materials[0].young_modulus / setup.model.materials[0].density);
}

/// A step is stable when the spectral radius of its linearised step is at most 1 + this.
inline constexpr double stable_radius_tolerance = 1e-6;

/// The spectral radius of the scene's linearised step on `setup` at `cfl`.
template <int Dim>
double step_radius(const io::Scene& scene, const Setup<Dim>& setup, double cfl) {
  return with_method<Dim>(scene, setup.model.grid, [&](auto shape, auto integrator) {
    return spectral_radius(linearised_step_matrix(setup.model, setup.particles, shape, integrator, stability_time_step(setup, cfl)));
  });
}

/// Whether the scene's linearised step on `setup` is stable at `cfl`: \f$ \rho(\mathbf S) \le 1 + 10^{-6} \f$.
template <int Dim>
bool stable_step(const io::Scene& scene, const Setup<Dim>& setup, double cfl) {
  return step_radius(scene, setup, cfl) <= 1.0 + stable_radius_tolerance;
}

/// The largest CFL at which `stable` holds, by bisection of [low, high] (stable at low, not at high) to `relative_tolerance`.
template <class Stable>
double bisected_cfl_limit(Stable stable, double low, double high, double relative_tolerance) {
  while (high - low > relative_tolerance * high) {
    const double middle = 0.5 * (low + high);
    (stable(middle) ? low : high) = middle;
  }
  return low;
}

/// The limits of the scene's method on the scene's body (built by stability_scene()); the CFL limit by
/// bisection to `relative_tolerance`.
template <int Dim>
StabilityLimits stability_limits(const io::Scene& scene, double relative_tolerance) {
  use_threads(1);
  const Setup<Dim> setup = build_setup<Dim>(scene);
  StabilityLimits limits;
  limits.particles = setup.particles.size();
  limits.unknowns = limits.particles * linearised_states_per_particle<Dim>();
  // The highest mode, from forward Euler's energy-keeping step at CFL 0.1 with the scene's shape function.
  io::Scene plain = scene;
  plain.integrator = io::IntegratorKind::fe;
  plain.flip_fraction = 1.0;
  plain.stress_update = io::StressUpdate::usf;
  const double probe_cfl = 0.1;
  limits.highest_mode = with_method<Dim>(plain, setup.model.grid, [&](auto shape, auto integrator) {
    return highest_mode_omega_dt(linearised_step_matrix(setup.model, setup.particles, shape, integrator, stability_time_step(setup, probe_cfl)));
  }) / probe_cfl;
  const bool fe = scene.integrator == io::IntegratorKind::fe;
  const bool analysed = !fe || (scene.flip_fraction == 1.0 && scene.stress_update == io::StressUpdate::usf);
  const ModeScheme scheme = fe                                                     ? ModeScheme::forward_euler
                            : scene.npc_velocity == NewmarkParticleVelocity::average ? ModeScheme::npc_average
                                                                                     : ModeScheme::npc_eq32;
  limits.cfl_limit_from_modes = analysed ? mode_stability_limit(scheme, scene.newmark_gamma) / limits.highest_mode
                                         : std::numeric_limits<double>::quiet_NaN();
  // Bisection on the spectral radius, in a bracket around the prediction when it holds one.
  auto stable = [&](double cfl) { return stable_step(scene, setup, cfl); };
  double low = 0.02, high = 4.0;
  if (analysed && stable(0.98 * limits.cfl_limit_from_modes) && !stable(1.02 * limits.cfl_limit_from_modes)) {
    low = 0.98 * limits.cfl_limit_from_modes;
    high = 1.02 * limits.cfl_limit_from_modes;
  } else if (!stable(low)) {
    limits.cfl_limit = 0.0;
    return limits;
  } else {
    bool high_is_stable = stable(high);
    while (high_is_stable && high < 1e3) low = high, high *= 2.0, high_is_stable = stable(high);  // widen until unstable
    if (high_is_stable) {
      limits.cfl_limit = std::numeric_limits<double>::infinity();
      return limits;
    }
  }
  limits.cfl_limit = bisected_cfl_limit(stable, low, high, relative_tolerance);
  return limits;
}

/// The CFL limit of a scene's own linearised step, its body with its walls and free ends as they are, about rest with
/// every particle moved by `shift` h along x (0: the scene's rest state): the largest CFL in [0.02, 4] with
/// \f$ \rho(\mathbf S) \le 1 + 10^{-6} \f$, by bisection to `relative_tolerance`; 0 if the step is unstable at 0.02, inf if
/// stable at 4. The step is linearised in the velocities, strains and accelerations, not in the positions, so a small
/// shift shows what a particle's first move does to the step: a node can enter its support with a vanishing mass (the
/// quadratic B-spline's node 1.5 h beyond a free end, paper/08_test_cases.md, "In the stability map").
template <int Dim>
double moved_body_cfl_limit(const io::Scene& scene, double shift, double relative_tolerance) {
  use_threads(1);
  Setup<Dim> setup = build_setup<Dim>(scene);
  for (Vector<Dim>& position : setup.particles.position) position[0] += shift * setup.model.grid.spacing();
  auto stable = [&](double cfl) { return stable_step(scene, setup, cfl); };
  const double low = 0.02, high = 4.0;
  if (!stable(low)) return 0.0;
  if (stable(high)) return std::numeric_limits<double>::infinity();
  return bisected_cfl_limit(stable, low, high, relative_tolerance);
}

/// Whether the scene's method is stable on the scene's body at `cfl`: the spectral radius of its linearised step
/// at \f$ \Delta t = \mathrm{CFL}\, h / c \f$ is at most \f$ 1 + 10^{-6} \f$, the test stability_limits() bisects on.
template <int Dim>
bool stable_at(const io::Scene& scene, double cfl) {
  use_threads(1);
  return stable_step(scene, build_setup<Dim>(scene), cfl);
}

}  // namespace mpm
