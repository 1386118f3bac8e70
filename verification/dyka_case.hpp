// One Dyka-bar case of the verification suite: run scenes/dyka_bar.toml with overrides in-process,
// record v_A(t), and compare it with the exact solution of the appendix (mpm/exact/bar.hpp).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "mpm/analysis/rms_error.hpp"
#include "mpm/analysis/verdict.hpp"
#include "mpm/exact/bar.hpp"
#include "mpm/run.hpp"
#include "verification/dyka_profiles.hpp"
#include "verification/fast_runs.hpp"
#include "verification/parallel.hpp"

namespace verification {

struct DykaResult {
  std::string name;
  std::vector<std::string> overrides;
  std::vector<double> time, velocity, exact;
  double rms = 0.0;            ///< Eq. (43), m/s, against the exact solution at each row's time t
  /// Eq. (43) against the exact solution at the time the integrator's velocity approximates: forward Euler's
  /// row at t holds v(t + dt/2) (paper/10_integrator_analysis.md), the predictor-corrector's v(t)
  double rms_own_time = 0.0;
  double final_energy_ratio = 0.0;  ///< kinetic + strain energy at the end over its initial value
  double smallest_energy_ratio = 0.0, largest_energy_ratio = 0.0;  ///< its least and greatest value over the run
  double largest_energy_step_increase = 0.0;  ///< the largest rise of that ratio in one step (negative: it fell in every step)
  /// the bands of the sampled energy ratios, what each moves by when its sample lands a step earlier or later: the
  /// larger change of the ratio over the steps beside the least and beside the greatest value, and over the last step
  double smallest_energy_band = 0.0, largest_energy_band = 0.0, last_energy_step_change = 0.0;
  double largest_speed = 0.0;  ///< max |v_A|, m/s
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;    ///< CPU time of the thread that ran it (the runs are one thread each)
  /// Plateau deviations, in units of |v0|, on the middle half of every interval where the exact v_A is constant
  /// (the wave has passed A and the next has not come): signed along the exact jump into the plateau, so
  /// `overshoot` is the largest step beyond the exact level and `undershoot` the largest shortfall (both >= 0).
  double overshoot = 0.0, undershoot = 0.0;
  /// The mean shortfall: the mean of the signed deviation, below the exact level along the jump, over the same samples
  /// (/ v0): a pulse that lost amplitude falls short on average, ringing about the exact level averages out.
  double mean_shortfall = 0.0;
  /// Ringing: the total variation of v_A over the exact one's on the same samples (mpm::total_variation_ratio), the
  /// whole history, sampled every step; 1 when v_A follows the exact jumps and settles, above 1 by twice each
  /// overshoot and oscillation, lowered by the amplitude a damped jump loses. 0 for a stopped run (not scored).
  double ringing = 0.0;
  /// The scores of the even rows alone and of the odd rows alone: the band of each score's own sampling
  /// (mpm::band_of_halves); two runs whose scores differ by less than their bands together are not told apart.
  struct Scores {
    double rms = 0.0, ringing = 0.0, overshoot = 0.0, undershoot = 0.0, mean_shortfall = 0.0;
  } even, odd;
  /// What a flat line at the exact history's mean scores (mpm::flat_line_score): a finished run whose RMS is no
  /// smaller has failed (mpm::Ending::failed), it approximates nothing.
  double flat_rms = 0.0;
  /// v and sigma along the bar at the steps nearest to profile_fractions of the end time (dyka_profiles.hpp)
  std::vector<Profile> profiles;
  /// The all-particle space-time norm: the RMS of v_p - v(X_p, t) over every particle and every sample (every step),
  /// with v the exact solution at the particle's reference position; and the same on the even and on the odd samples
  /// alone (its band, mpm::band_of_halves), m/s. Point A's RMS (`rms`) scores one particle of the same field.
  double space_time = 0.0, space_time_even = 0.0, space_time_odd = 0.0;
  /// Every particle's v and sigma_xx at the run's last step (its end time: the run lands on it)
  std::vector<double> final_velocity, final_stress;
  double v0 = 0.0;             ///< the initial velocity of the loaded quarter, m/s (the scene's, -5 unless set)
  double mass_error = 0.0;     ///< largest relative |sum m_I - sum m_p| of the run
  double newton_mean = 0.0, neighbours_mean = 0.0;
  int newton_max = 0;
  long steps = 0;
  int cells = 0;
  bool failed = false;
  std::string failure;  ///< the solver's diagnosis when it failed
};

/// Records the velocity of particle A at every step, the squared errors of every particle against `bar` (the
/// space-time norm, even and odd samples apart) and every particle's v and sigma at the last sample.
struct VelocityRecorder : mpm::Monitor<1> {
  VelocityRecorder(int observed, const mpm::exact::ElasticBar& exact_bar) : particle(observed), bar(exact_bar) {}
  void sample(long, double t, const mpm::Particles<1>& particles, const mpm::Balances<1>& balances) override {
    const int parity = int(time.size() % 2);
    time.push_back(t);
    velocity.push_back(particles.velocity[particle][0]);
    energy.push_back(balances.total());
    profiles.sample(t, particles);
    for (int p = 0; p < particles.size(); ++p) {
      const double error = particles.velocity[p][0] - bar.velocity(particles.reference_position[p][0], t);
      squares[parity] += error * error;
    }
    terms[parity] += particles.size();
    final_velocity.assign(particles.size(), 0.0), final_stress.assign(particles.size(), 0.0);
    for (int p = 0; p < particles.size(); ++p) final_velocity[p] = particles.velocity[p][0], final_stress[p] = particles.stress[p](0, 0);
  }
  /// sqrt(sum / count) of the even (0), odd (1) or all (2) samples' squared errors
  double space_time(int which) const {
    const double sum = which == 2 ? squares[0] + squares[1] : squares[which];
    const double count = which == 2 ? terms[0] + terms[1] : terms[which];
    return count > 0.0 ? std::sqrt(sum / count) : 0.0;
  }
  ProfileCapture profiles;
  int particle;
  const mpm::exact::ElasticBar& bar;
  std::vector<double> time, velocity, energy, final_velocity, final_stress;
  double squares[2] = {0.0, 0.0}, terms[2] = {0.0, 0.0};
};

/// The scene settings that select a shape function on the Dyka bar. Every shape runs on the grid
/// that ends at the fixed end: uGIMP clips its particle domain there (shape/ugimp.hpp), and LME
/// must not get rigid cells beyond the wall: it interpolates nodal values exactly only on the
/// boundary of its nodes' hull, so with rigid nodes beyond the wall the wall gives way (at
/// gamma = 0.8 v_A changes by 0.54 m/s RMS).
/// "lme_authors" is LME under the authors' beta (`solver.lme_beta = "authors"`, paper/09_choices.md, 'The authors'
/// beta'), run as a shape of its own.
inline std::vector<std::string> shape_settings(const std::string& shape) {
  if (shape == "lme_authors") return {"solver.shape=\"lme\"", "solver.lme_beta=\"authors\""};
  return {"solver.shape=\"" + shape + "\""};
}

/// Sets result.overshoot and result.undershoot from its series (see DykaResult). A plateau is a run of samples
/// with one exact value, 0 or +-|v0| (the exact solution's half-way value at a jump is no plateau); its direction
/// is the sign of the exact jump into it (for the first, of its own value).
inline void plateau_deviations(DykaResult& result, double speed) {
  const std::vector<double>& exact = result.exact;
  double shortfall = 0.0;
  int samples = 0;
  for (size_t first = 0; first < exact.size();) {
    size_t last = first;
    while (last + 1 < exact.size() && exact[last + 1] == exact[first]) ++last;
    const double jump = first == 0 ? exact[first] : exact[first] - exact[first - 1];
    const double level = std::abs(exact[first]) / speed;
    const bool plateau = level < 1e-9 || std::abs(level - 1.0) < 1e-9;
    const double direction = !plateau ? 0.0 : jump > 0.0 ? 1.0 : jump < 0.0 ? -1.0 : 0.0;
    const double begin = result.time[first], end = result.time[last], quarter = 0.25 * (end - begin);
    for (size_t n = first; n <= last && direction != 0.0; ++n)
      if (result.time[n] >= begin + quarter && result.time[n] <= end - quarter) {
        const double deviation = direction * (result.velocity[n] - exact[n]) / speed;
        result.overshoot = std::max(result.overshoot, deviation);
        result.undershoot = std::max(result.undershoot, -deviation);
        shortfall -= deviation, ++samples;
      }
    first = last + 1;
  }
  result.mean_shortfall = samples > 0 ? shortfall / samples : 0.0;
}

/// The scores of RMS, ringing and the plateau deviations on the rows n with n % 2 == parity alone.
inline DykaResult::Scores half_scores(const DykaResult& whole, int parity, double speed) {
  DykaResult half;
  half.time = mpm::every_other(whole.time, parity);
  half.velocity = mpm::every_other(whole.velocity, parity);
  half.exact = mpm::every_other(whole.exact, parity);
  if (half.time.size() < 2) return {};
  plateau_deviations(half, speed);
  return {mpm::rms_error(half.velocity, half.exact), mpm::total_variation_ratio(half.velocity, half.exact), half.overshoot,
          half.undershoot, half.mean_shortfall};
}

inline DykaResult run_dyka(const std::string& scene_path, const std::string& name, const std::vector<std::string>& overrides,
                           int threads = 1) {
  DykaResult result;
  result.name = name;
  result.overrides = overrides;
  mpm::io::Scene scene = mpm::load_scene(scene_path, overrides);
  scene.control.threads = threads;
  const mpm::Setup<1> setup = mpm::build_setup<1>(scene);
  result.cells = scene.cells[0];
  // The exact solution of the discrete initial data: v0 on the union of the domains
  // [X_p - l_p, X_p + l_p] of the particles that start with it (L/4 when the cells divide by 4).
  const double length = scene.length[0], v0 = scene.initial_velocities.at(0).velocity[0];
  double loaded = 0.0;
  for (int p = 0; p < setup.particles.size(); ++p)
    if (setup.particles.velocity[p][0] == v0)
      loaded = std::max(loaded, setup.particles.reference_position[p][0] + setup.particles.half_length[p][0]);
  const mpm::exact::ElasticBar bar(length, scene.young_modulus, scene.density, {{0.0, loaded, v0, 0.0}});
  result.v0 = v0;
  VelocityRecorder recorder(setup.observed.at(0), bar);
  for (double fraction : profile_fractions) recorder.profiles.targets.push_back(fraction * scene.control.end_time);
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  mpm::RunSummary summary;
  try {
    summary = run_fast<1>(scene, scene_path, setup, recorder, &summary);
  } catch (const mpm::SimulationFailure& failure) {
    result.failed = true;
    result.failure = failure.message();
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = thread_cpu_seconds() - cpu_start;
  result.steps = summary.steps;
  result.mass_error = summary.largest_mass_error;
  result.newton_mean = summary.shape.newton_iterations_mean();
  result.newton_max = summary.shape.newton_iterations_max();
  result.neighbours_mean = summary.shape.neighbours_mean();
  const double reference_position = setup.particles.reference_position[setup.observed[0]][0];
  result.profiles = recorder.profiles.profiles;
  for (Profile& profile : result.profiles)
    for (double x : profile.position)
      profile.exact_velocity.push_back(bar.velocity(x, profile.time)), profile.exact_stress.push_back(bar.stress(x, profile.time));
  result.time = recorder.time;
  result.velocity = recorder.velocity;
  result.space_time = recorder.space_time(2), result.space_time_even = recorder.space_time(0), result.space_time_odd = recorder.space_time(1);
  result.final_velocity = recorder.final_velocity, result.final_stress = recorder.final_stress;
  for (size_t n = 0; n < result.time.size(); ++n) {
    result.exact.push_back(bar.velocity(reference_position, result.time[n]));
    result.largest_speed = std::max(result.largest_speed, std::abs(result.velocity[n]));
  }
  if (!result.failed) result.rms = mpm::rms_error(result.velocity, result.exact);
  if (!result.failed) plateau_deviations(result, std::abs(v0));
  if (!result.failed) result.ringing = mpm::total_variation_ratio(result.velocity, result.exact);
  if (!result.failed) result.even = half_scores(result, 0, std::abs(v0)), result.odd = half_scores(result, 1, std::abs(v0));
  result.flat_rms = mpm::flat_line_score(result.exact);
  // Forward Euler's velocity of the row at t_n is v(t_n + dt_n / 2), dt_n the step that starts there (the
  // last row takes the step before it); the recorder samples every step.
  std::vector<double> exact_own_time = result.exact;
  if (scene.integrator == mpm::io::IntegratorKind::fe)
    for (size_t n = 0; n < result.time.size(); ++n) {
      const double step = n + 1 < result.time.size() ? result.time[n + 1] - result.time[n] : n > 0 ? result.time[n] - result.time[n - 1] : 0.0;
      exact_own_time[n] = bar.velocity(reference_position, result.time[n] + 0.5 * step);
    }
  if (!result.failed) result.rms_own_time = mpm::rms_error(result.velocity, exact_own_time);
  if (!recorder.energy.empty() && recorder.energy.front() > 0.0) {
    const double initial = recorder.energy.front();
    result.final_energy_ratio = recorder.energy.back() / initial;
    result.smallest_energy_ratio = *std::min_element(recorder.energy.begin(), recorder.energy.end()) / initial;
    result.largest_energy_ratio = *std::max_element(recorder.energy.begin(), recorder.energy.end()) / initial;
    result.largest_energy_step_increase = -1e300;
    for (size_t n = 1; n < recorder.energy.size(); ++n)
      result.largest_energy_step_increase = std::max(result.largest_energy_step_increase, (recorder.energy[n] - recorder.energy[n - 1]) / initial);
    const std::vector<double>& e = recorder.energy;
    auto beside = [&e, initial](std::size_t k) {  // the larger change over the steps into and out of sample k
      return std::max(k > 0 ? std::abs(e[k] - e[k - 1]) : 0.0, k + 1 < e.size() ? std::abs(e[k + 1] - e[k]) : 0.0) / initial;
    };
    result.smallest_energy_band = beside(std::min_element(e.begin(), e.end()) - e.begin());
    result.largest_energy_band = beside(std::max_element(e.begin(), e.end()) - e.begin());
    if (recorder.energy.size() > 1) result.last_energy_step_change = std::abs(recorder.energy.back() - recorder.energy.end()[-2]) / initial;
  }
  return result;
}

/// t, v_A, v_exact: one row per sample, for gnuplot.
inline void write_series(const DykaResult& result, const std::string& path) {
  std::ofstream out(path);
  out << std::setprecision(10) << "t,v_A,v_exact\n";
  for (size_t n = 0; n < result.time.size(); ++n) out << result.time[n] << "," << result.velocity[n] << "," << result.exact[n] << "\n";
}

}  // namespace verification
