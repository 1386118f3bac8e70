// One soil-block case of the verification suite (paper section 3.2, paper/08_test_cases.md): run a scene of
// scenes/soil_block*.toml with overrides in-process and record
//   - the vertical displacement u_y(t) = y(t) - Y of the observed top particle at every sample,
//   - every particle (position, reference position, stress) at the scene's snapshot times,
//   - the total nodal mass against the total particle mass, every step (RunSummary::largest_mass_error),
//   - the cell crossings: how many particles were, at some sample, in a cell other than their initial one.
// The comparison with the exact column is soil_measures.hpp.
#pragma once
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "mpm/run.hpp"
#include "verification/fast_runs.hpp"
#include "verification/parallel.hpp"

namespace verification {

/// One particle at one snapshot time; stresses in Pa (tension positive).
struct ParticleState {
  double x, y;                      ///< current position
  double reference_x, reference_y;  ///< X, Y: the position at t = 0
  double sigma_xx, sigma_yy, sigma_xy;
};

struct SoilSnapshot {
  double time = 0.0;
  std::vector<ParticleState> particles;
};

struct SoilResult {
  std::string name;
  std::vector<std::string> overrides;
  mpm::io::Scene scene;                ///< the resolved settings of the run
  double reference_height = 0.0;       ///< Y of the observed particle
  double reference_x = 0.0;            ///< X of the observed particle
  std::vector<double> time, displacement;  ///< samples of u_y = y - Y of the observed particle
  /// at the same samples: kinetic + strain energy, and the potential energy of full gravity,
  /// sum_p m_p g (y_p - Y_p); their sum is conserved once the ramp is over (J per metre of thickness)
  std::vector<double> kinetic_plus_strain, gravity_potential;
  std::vector<SoilSnapshot> snapshots;
  double particle_mass = 0.0;          ///< sum of m_p
  double largest_mass_mismatch = 0.0;  ///< max over steps of |sum_I m_I - sum_p m_p| / sum_p m_p (the solver's own)
  long steps = 0;
  double wall_seconds = 0.0;    ///< the whole case: set-up, run and recording
  double solver_seconds = 0.0;  ///< the time-step loop alone (RunSummary)
  double cpu_seconds = 0.0;     ///< CPU time of the thread that ran it (the run and its recording; one thread per case)
  double newton_mean = 0.0;     ///< LME: Newton iterations per particle-step on average (0 for other shapes)
  int newton_max = 0;           ///< LME: the most in one particle-step
  double neighbours_mean = 0.0; ///< nodes per particle-step on average
  int particles_crossed = 0;    ///< particles that were in a cell other than their initial one at some sample
  double first_crossing = -1.0; ///< the time of the first sample with such a particle (-1: none)
  bool failed = false;
  std::string failure;  ///< the solver's diagnosis when it failed
};

/// Records the observed particle, the energies and the snapshots.
struct SoilRecorder : mpm::Monitor<2> {
  SoilRecorder(SoilResult& result_, int observed_, double gravity_) : result(result_), observed(observed_), gravity(gravity_) {}

  void sample(long, double t, const mpm::Particles<2>& particles, const mpm::Balances<2>& sums) override {
    result.time.push_back(t);
    result.displacement.push_back(particles.position[observed][1] - particles.reference_position[observed][1]);
    double potential = 0.0;
    for (int p = 0; p < particles.size(); ++p)
      potential += particles.mass[p] * gravity * (particles.position[p][1] - particles.reference_position[p][1]);
    result.kinetic_plus_strain.push_back(sums.total());
    result.gravity_potential.push_back(potential);
    count_crossings(t, particles);
  }

  /// The cell of a position on the scene's grid (its origin and spacing; the margins do not move the cells' faces).
  std::array<long, 2> cell_of(const mpm::Vector<2>& x) const {
    const auto& scene = result.scene;
    return {static_cast<long>(std::floor((x[0] - scene.origin[0]) / scene.spacing)),
            static_cast<long>(std::floor((x[1] - scene.origin[1]) / scene.spacing))};
  }

  /// Marks every particle that is in a cell other than the one of its reference position (at t = 0).
  void count_crossings(double t, const mpm::Particles<2>& particles) {
    crossed.resize(particles.size(), false);
    for (int p = 0; p < particles.size(); ++p) {
      if (crossed[p] || cell_of(particles.position[p]) == cell_of(particles.reference_position[p])) continue;
      crossed[p] = true;
      ++result.particles_crossed;
      if (result.first_crossing < 0.0) result.first_crossing = t;
    }
  }

  void snapshot(int, double t, const mpm::Particles<2>& particles) override {
    SoilSnapshot snap;
    snap.time = t;
    for (int p = 0; p < particles.size(); ++p)
      snap.particles.push_back({particles.position[p][0], particles.position[p][1], particles.reference_position[p][0],
                                particles.reference_position[p][1], particles.stress[p](0, 0), particles.stress[p](1, 1),
                                particles.stress[p](0, 1)});
    result.snapshots.push_back(snap);
  }

  SoilResult& result;
  int observed;
  double gravity;  ///< |g| at full strength, m/s^2
  std::vector<bool> crossed;  ///< per particle: has it left its initial cell at a sample
};

/// Runs the scene at `scene_path` with `overrides` (mpm run --set syntax). A SimulationFailure
/// (NaN, a particle off the grid, unbounded energy growth) is caught and recorded, with what was
/// recorded up to it; a SceneError propagates (a wrong case list is a bug of the suite).
inline SoilResult run_soil_case(const std::string& scene_path, const std::string& name,
                                const std::vector<std::string>& overrides, int threads = 1) {
  SoilResult result;
  result.name = name;
  result.overrides = overrides;
  result.scene = mpm::load_scene(scene_path, overrides);
  result.scene.control.threads = threads;
  const mpm::Setup<2> setup = mpm::build_setup<2>(result.scene);
  const int observed = setup.observed.at(0);
  result.reference_x = setup.particles.reference_position[observed][0];
  result.reference_height = setup.particles.reference_position[observed][1];
  for (double m : setup.particles.mass) result.particle_mass += m;
  SoilRecorder recorder(result, observed, std::abs(result.scene.gravity[1]));
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  mpm::RunSummary summary;
  try {
    summary = run_fast<2>(result.scene, scene_path, setup, recorder, &summary);
  } catch (const mpm::SimulationFailure& failure) {
    result.failed = true;
    result.failure = failure.message();
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = thread_cpu_seconds() - cpu_start;
  result.steps = summary.steps;
  result.largest_mass_mismatch = summary.largest_mass_error;
  result.solver_seconds = summary.wall_seconds;
  result.newton_mean = summary.shape.newton_iterations_mean();
  result.newton_max = summary.shape.newton_iterations_max();
  result.neighbours_mean = summary.shape.neighbours_mean();
  return result;
}

}  // namespace verification
