// One case of the smooth-data suite: the vibrating bar (scenes/vibrating_bar.toml) run in-process
// with overrides, its particles compared at fixed times with the exact first mode
// (mpm/exact/vibrating_bar.hpp) or, at large amplitude, with the finite-strain reference
// (mpm/exact/vibrating_bar_finite_strain.hpp).
#pragma once
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "mpm/exact/manufactured.hpp"
#include "mpm/exact/vibrating_bar.hpp"
#include "mpm/exact/vibrating_bar_finite_strain.hpp"
#include "mpm/analysis/verdict.hpp"
#include "mpm/run.hpp"
#include "verification/fast_runs.hpp"
#include "verification/dyka_case.hpp"

namespace verification {

/// What a case measured: RMS errors over the particles and the sample times, normalised.
struct SmoothResult {
  double velocity_error = std::numeric_limits<double>::quiet_NaN();  ///< RMS(v_p - v) / velocity scale
  /// The same with v taken at the time the integrator's velocity approximates: forward Euler's particle
  /// velocity at t is v(t + dt/2) (paper/10_integrator_analysis.md), the predictor-corrector's v(t).
  /// NaN where the exact solution exists only at the sample times (the finite-strain bar).
  double velocity_error_own_time = std::numeric_limits<double>::quiet_NaN();
  double stress_error = std::numeric_limits<double>::quiet_NaN();    ///< RMS(sigma_p - sigma) / stress scale
  /// the bands of velocity_error and stress_error: their larger move when scored on the even or the odd particles
  /// alone (mpm::band_of_halves; the one rule of the report, mpm/analysis/verdict.hpp)
  double velocity_band = 0.0, stress_band = 0.0;
  /// what a flat field scores on the velocity: the RMS of the exact velocity about its mean over the particles and the
  /// sample times, / velocity scale (mpm::flat_line_score's rule); a run whose velocity_error is no smaller has failed
  double velocity_flat = std::numeric_limits<double>::quiet_NaN();
  /// how the run ended (mpm/analysis/verdict.hpp): stopped, failed (no better than a flat field), or done
  mpm::Ending ending() const { return failed ? mpm::Ending::stopped : mpm::score_ending(velocity_error, velocity_flat); }
  double energy_ratio = std::numeric_limits<double>::quiet_NaN();    ///< (kinetic + strain) at the end / at t = 0
  double energy_band = 0.0;  ///< its band: the ratio's change over the last step (the end landing a step earlier)
  double initial_mismatch = 0.0;  ///< largest |v_p(0) - exact v(X_p, 0)| / velocity scale: the scene's initial field checked
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;  ///< the run's CPU time, set by the suite (the run is on one thread)
  long steps = 0;
  int particles = 0;
  bool failed = false;
  std::string failure;
};

/// The fraction of the period T at which the bar's particles are compared: T/4, T/2, 3T/4, T.
inline const std::vector<double>& bar_sample_fractions() {
  static const std::vector<double> fractions{0.25, 0.5, 0.75, 1.0};
  return fractions;
}

/// Accumulates the squared errors of every particle at every snapshot, and the energies. exact(particles, p,
/// index, time, own_time) returns the squared velocity error, the squared stress error, the squared
/// velocity error at own_time (time, plus half the next step for a staggered integrator (forward Euler), the
/// step being the one the loop takes next, Eq. (42) from the particles as they are), and the exact velocity (for the
/// flat field's score).
template <int Dim, class Exact>
struct ErrorMonitor : mpm::Monitor<Dim> {
  explicit ErrorMonitor(Exact exact_solution) : exact(std::move(exact_solution)) {}
  bool staggered = false;  ///< forward Euler: the velocity belongs half a step later
  double young_modulus = 0.0, cell_size = 0.0, cfl = 0.0;
  void sample(long step, double, const mpm::Particles<Dim>&, const mpm::Balances<Dim>& balances) override {
    if (step == 0) initial_energy = balances.total();
    previous_energy = step == 0 ? balances.total() : final_energy;
    final_energy = balances.total();
  }
  void snapshot(int index, double time, const mpm::Particles<Dim>& particles) override {
    const double own_time = staggered ? time + 0.5 * mpm::courant_time_step(particles, young_modulus, cell_size, cfl) : time;
    for (int p = 0; p < particles.size(); ++p) {
      const auto [velocity_error, stress_error, own_time_error, exact_velocity] = exact(particles, p, index, time, own_time);
      exact_sum += exact_velocity, exact_squares += exact_velocity.squaredNorm();
      velocity_squares += velocity_error;
      stress_squares += stress_error;
      own_time_squares += own_time_error;
      half_velocity_squares[p % 2] += velocity_error, half_stress_squares[p % 2] += stress_error, ++half_count[p % 2];
      ++count;
    }
  }
  Exact exact;
  double velocity_squares = 0.0, stress_squares = 0.0, own_time_squares = 0.0, initial_energy = 0.0, final_energy = 0.0;
  double previous_energy = 0.0;  ///< the energy a step before the last (the runs sample every step: output.every = 1)
  double half_velocity_squares[2] = {0.0, 0.0}, half_stress_squares[2] = {0.0, 0.0};  ///< even and odd particles
  long count = 0, half_count[2] = {0, 0};
  mpm::Vector<Dim> exact_sum = mpm::Vector<Dim>::Zero();  ///< the exact velocities summed, and their squares
  double exact_squares = 0.0;
};

/// Runs a set-up scene with the monitor, fills the result; SimulationFailure is recorded, not thrown.
template <int Dim, class Exact>
SmoothResult run_and_measure(const mpm::io::Scene& scene, const mpm::Setup<Dim>& setup, ErrorMonitor<Dim, Exact>& monitor,
                             double velocity_scale, double stress_scale) {
  monitor.staggered = scene.integrator == mpm::io::IntegratorKind::fe;
  monitor.young_modulus = scene.young_modulus;
  monitor.cell_size = setup.model.grid.spacing();
  monitor.cfl = scene.control.cfl;
  SmoothResult result;
  result.particles = setup.particles.size();
  const auto start = std::chrono::steady_clock::now();
  mpm::RunSummary summary;
  try {
    summary = run_fast<Dim>(scene, "the smooth suite's scene", setup, monitor, &summary);
  } catch (const mpm::SimulationFailure& failure) {
    result.failed = true;
    result.failure = failure.message();
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.steps = summary.steps;
  if (!result.failed && monitor.count > 0) {
    result.velocity_error = std::sqrt(monitor.velocity_squares / monitor.count) / velocity_scale;
    result.stress_error = std::sqrt(monitor.stress_squares / monitor.count) / stress_scale;
    result.velocity_error_own_time = std::sqrt(monitor.own_time_squares / monitor.count) / velocity_scale;
    result.energy_ratio = monitor.final_energy / monitor.initial_energy;
    result.energy_band = std::abs(monitor.final_energy - monitor.previous_energy) / monitor.initial_energy;
    const mpm::Vector<Dim> mean = monitor.exact_sum / double(monitor.count);
    result.velocity_flat = std::sqrt(std::max(0.0, monitor.exact_squares / monitor.count - mean.squaredNorm())) / velocity_scale;
    if (monitor.half_count[0] > 0 && monitor.half_count[1] > 0) {
      auto half = [&](const double* squares, int k, double scale) { return std::sqrt(squares[k] / monitor.half_count[k]) / scale; };
      result.velocity_band = mpm::band_of_halves(result.velocity_error, half(monitor.half_velocity_squares, 0, velocity_scale),
                                                 half(monitor.half_velocity_squares, 1, velocity_scale));
      result.stress_band = mpm::band_of_halves(result.stress_error, half(monitor.half_stress_squares, 0, stress_scale),
                                               half(monitor.half_stress_squares, 1, stress_scale));
    }
  }
  return result;
}

/// The scene overrides of a method named by its shape and integrator, as the smooth suite names them: the
/// paper's shapes (linear, ugimp, lme: LME gamma 3) and integrators (fe, npc), and today's baselines: the
/// shapes bspline2, bspline3, lme0.8 and lme1.5 (LME at gamma 0.8 and 1.5), the integrators usl and musl
/// (forward Euler with the stress updated last, or modified-last).
inline std::vector<std::string> method_settings(const std::string& shape, const std::string& integrator) {
  const bool small_gamma = shape.rfind("lme", 0) == 0 && shape.size() > 3;
  const bool stress_last = integrator == "usl" || integrator == "musl";
  std::vector<std::string> settings{"solver.shape=\"" + (small_gamma ? std::string("lme") : shape) + "\"",
                                    "solver.integrator=\"" + (stress_last ? std::string("fe") : integrator) + "\""};
  if (shape.rfind("lme", 0) == 0) settings.push_back("solver.lme_gamma=" + (small_gamma ? shape.substr(3) : std::string("3.0")));
  if (stress_last) settings.push_back("solver.stress_update=\"" + integrator + "\"");
  return settings;
}

/// One vibrating-bar case.
struct BarCase {
  std::string shape, integrator;
  int cells = 16, particles_per_cell = 1;
  double cfl = 0.5;
  double amplitude = 1e-6;  ///< V / (omega L): the largest displacement over the bar's length
  std::vector<std::string> settings;  ///< further scene overrides (e.g. solver.npc_velocity)
};

/// The vibrating bar's material and size, read from the scene (the exact solutions get them from there).
struct BarScene {
  std::string path;
  double length = 0.0, young_modulus = 0.0, density = 0.0;
  explicit BarScene(std::string scene_path) : path(std::move(scene_path)) {
    const mpm::io::Scene scene = mpm::load_scene(path, {});
    length = scene.length[0], young_modulus = scene.young_modulus, density = scene.density;
  }
  mpm::exact::VibratingBar mode(double amplitude) const {
    const mpm::exact::VibratingBar unit(length, young_modulus, density, 1.0);
    return mpm::exact::VibratingBar(length, young_modulus, density, amplitude * length * unit.angular_frequency());
  }
  /// The finite-strain reference at the sample times, on `cells` cells.
  mpm::exact::FiniteStrainBar reference(double amplitude, int cells) const {
    const auto linear = mode(amplitude);
    std::vector<double> times;
    for (double fraction : bar_sample_fractions()) times.push_back(fraction * linear.period());
    return mpm::exact::FiniteStrainBar(length, young_modulus, density, linear.velocity_amplitude(), cells, times);
  }
};

/// Runs one bar case: the scene with the case's overrides (its [initial_field] gives the velocity
/// V cos(pi X / 2L), with V set by constants.amplitude_ratio), to one period; the particles compared
/// at T/4, T/2, 3T/4 and T with `reference` (nullptr: the linear first mode).
inline SmoothResult run_bar(const BarScene& bar, const BarCase& c, const mpm::exact::FiniteStrainBar* reference, int threads = 1) {
  const mpm::exact::VibratingBar mode = bar.mode(c.amplitude);
  const double T = mode.period();
  // Room beyond the free end for its largest displacement, plus two cells for the supports.
  const int margin = static_cast<int>(std::ceil(1.2 * c.amplitude * c.cells)) + 2;
  std::vector<std::string> overrides = method_settings(c.shape, c.integrator);
  char end_time[64];
  std::snprintf(end_time, sizeof end_time, "solver.end_time=%.17g", T);
  char amplitude[64];
  std::snprintf(amplitude, sizeof amplitude, "constants.amplitude_ratio=%.17g", c.amplitude);
  overrides.insert(overrides.end(), {amplitude, "grid.cells=[" + std::to_string(c.cells) + "]", "grid.margin_min=[" + std::to_string(margin) + "]",
                                     "body[0].particles_per_cell=[" + std::to_string(c.particles_per_cell) + "]",
                                     "solver.cfl=" + std::to_string(c.cfl), end_time,
                                     "output.every=1", "output.snapshots=[]"});
  overrides.insert(overrides.end(), c.settings.begin(), c.settings.end());
  // Snapshot times exactly at fractions of T (the loop lands on them).
  mpm::io::Scene scene = mpm::load_scene(bar.path, overrides);
  scene.control.snapshot_times.clear();
  for (double fraction : bar_sample_fractions()) scene.control.snapshot_times.push_back(fraction * T);
  scene.control.threads = threads;
  const mpm::Setup<1> setup = mpm::build_setup<1>(scene);
  const double V = mode.velocity_amplitude();
  double mismatch = 0.0;  // the scene's formula against the exact mode, at t = 0
  for (int p = 0; p < setup.particles.size(); ++p)
    mismatch = std::max(mismatch, std::abs(setup.particles.velocity[p][0] - mode.velocity(setup.particles.reference_position[p][0], 0.0)) / V);
  auto exact = [&mode, reference](const mpm::Particles<1>& particles, int p, int index, double time, double own_time) {
    const double X = std::clamp(particles.reference_position[p][0], 0.0, mode.length());
    const double v = reference ? reference->velocity(X, index) : mode.velocity(X, time);
    const double s = reference ? reference->stress(X, index) : mode.stress(X, time);
    const double dv = particles.velocity[p][0] - v, ds = particles.stress[p](0, 0) - s;
    const double dv_own = reference ? std::numeric_limits<double>::quiet_NaN() : particles.velocity[p][0] - mode.velocity(X, own_time);
    return std::tuple<double, double, double, mpm::Vector<1>>{dv * dv, ds * ds, dv_own * dv_own, mpm::Vector<1>(v)};
  };
  ErrorMonitor<1, decltype(exact)> monitor(exact);
  SmoothResult result = run_and_measure<1>(scene, setup, monitor, V, mode.impedance() * V);
  result.initial_mismatch = mismatch;
  return result;
}

/// One case of the 2D manufactured solutions.
struct ManufacturedCase {
  std::string shape, integrator;
  int cells = 16, particles_per_cell = 2;
  double cfl = 0.5;
  bool large = false;  ///< large amplitude (diagonal stretch, rollers) or small (any field, faces fixed)
};

/// The manufactured motions' amplitudes: small A = 1e-6 L; large a_x = 0.04 L, a_y = 0.02 L
/// (largest stretches 1 -+ 0.13 on both axes).
constexpr double manufactured_small = 1e-6, manufactured_large_x = 0.04, manufactured_large_y = 0.02;

/// The fraction of the period 2 pi / omega at which the particles are compared; the run ends at the last.
inline const std::vector<double>& manufactured_sample_fractions() {
  static const std::vector<double> fractions{0.125, 0.25, 0.375, 0.5};
  return fractions;
}

/// Runs one manufactured case of scenes/manufactured_square.toml: the motion's initial velocity,
/// its body force b(x, t) and, at large amplitude, rollers on every face; the particles compared at
/// the sample times with the motion (velocity and in-plane Cauchy stress, RMS over particles).
inline SmoothResult run_manufactured(const std::string& scene_path, const ManufacturedCase& c, int threads = 1) {
  const mpm::io::Scene base = mpm::load_scene(scene_path, {});
  const mpm::exact::ManufacturedMaterial material{base.length[0], base.young_modulus, base.poisson_ratio, base.density};
  const double L = material.length, period = 2.0 * mpm::exact::ManufacturedMaterial::pi / material.angular_frequency();
  const mpm::exact::ManufacturedSmall small(material, manufactured_small * L);
  const mpm::exact::ManufacturedLarge large(material, manufactured_large_x * L, manufactured_large_y * L);
  const std::string n = std::to_string(c.cells), ppc = std::to_string(c.particles_per_cell);
  std::vector<std::string> overrides = method_settings(c.shape, c.integrator);
  overrides.insert(overrides.end(), {"grid.cells=[" + n + ", " + n + "]", "body[0].particles_per_cell=[" + ppc + ", " + ppc + "]",
                                     "solver.cfl=" + std::to_string(c.cfl), "output.every=1", "output.snapshots=[]"});
  char end_time[64];
  std::snprintf(end_time, sizeof end_time, "solver.end_time=%.17g", manufactured_sample_fractions().back() * period);
  overrides.push_back(end_time);
  if (c.large)
    for (int face = 0; face < 4; ++face) overrides.push_back("fixed[" + std::to_string(face) + "].components=[\"" + (face < 2 ? "x" : "y") + "\"]");
  mpm::io::Scene scene = mpm::load_scene(scene_path, overrides);
  for (double fraction : manufactured_sample_fractions()) scene.control.snapshot_times.push_back(fraction * period);
  scene.control.threads = threads;
  mpm::Setup<2> setup = mpm::build_setup<2>(scene);
  auto to_pair = [](const mpm::Vector<2>& v) { return mpm::exact::Pair{v[0], v[1]}; };
  for (int p = 0; p < setup.particles.size(); ++p) {
    const auto X = to_pair(setup.particles.reference_position[p]);
    const auto v = c.large ? large.initial_velocity(X) : small.initial_velocity(X);
    setup.particles.velocity[p] = mpm::Vector<2>(v[0], v[1]);
  }
  setup.model.body_force.field = [&small, &large, large_case = c.large, to_pair](const mpm::Vector<2>& x, const mpm::Vector<2>&, double t) {
    const auto b = large_case ? large.body_force(to_pair(x), t) : small.body_force(to_pair(x), t);
    return mpm::Vector<2>(b[0], b[1]);
  };
  auto exact = [&](const mpm::Particles<2>& particles, int p, int, double time, double own_time) {
    const auto X = to_pair(particles.reference_position[p]);
    const auto v = c.large ? large.velocity(X, time) : small.velocity(X, time);
    const auto v_own = c.large ? large.velocity(X, own_time) : small.velocity(X, own_time);
    const auto s = c.large ? large.stress(X, time) : small.stress(X, time);
    const mpm::Matrix<2>& sigma = particles.stress[p];
    const double dv = (particles.velocity[p] - mpm::Vector<2>(v[0], v[1])).squaredNorm();
    const double ds = (sigma(0, 0) - s.xx) * (sigma(0, 0) - s.xx) + (sigma(1, 1) - s.yy) * (sigma(1, 1) - s.yy) + 2.0 * (sigma(0, 1) - s.xy) * (sigma(0, 1) - s.xy);
    return std::tuple<double, double, double, mpm::Vector<2>>{dv, ds, (particles.velocity[p] - mpm::Vector<2>(v_own[0], v_own[1])).squaredNorm(),
                                                              mpm::Vector<2>(v[0], v[1])};
  };
  ErrorMonitor<2, decltype(exact)> monitor(exact);
  return run_and_measure<2>(scene, setup, monitor, c.large ? large.velocity_scale() : small.velocity_scale(),
                            c.large ? large.stress_scale() : small.stress_scale());
}

}  // namespace verification
