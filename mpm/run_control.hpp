/// \file
/// What a run is told and what it tells: RunControl (the time stepping, the outputs' times, the threads), RunSummary
/// and the Monitor that receives the samples (mpm/io/run_writer.hpp). The types of the time-step loop
/// (mpm/simulation.hpp) that a program and the scene reader need without the kernels.
#pragma once
#include <array>
#include <vector>

#include "mpm/analysis/energy.hpp"
#include "mpm/core/step_phases.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/shape/shape_diagnostics.hpp"

namespace mpm {

/// How the speeds of Eq. (42) are combined.
enum class CourantSpeed {
  maximum,  ///< Eq. (42) as printed: C = max{ max_p |v_p|, max_p sqrt(E/rho_p) } (default)
  sum       ///< the authors' code: C = c + max_p |v_p| (paper/09_choices.md, 'The Courant speed')
};

/// When the body force of a step is evaluated (paper/09_choices.md, 'When gravity is evaluated').
enum class BodyForceTime { step_end, step_start };

struct RunControl {
  double cfl = 0.5;
  double fixed_dt = 0.0;  ///< solver.dt: every step this long (s), cfl unused; 0: the Courant step of Eq. (42)
  CourantSpeed courant = CourantSpeed::maximum;
  double end_time = 0.0;
  std::vector<double> snapshot_times;  ///< times at which every particle is written
  int sample_every = 1;                ///< observers sampled every n steps and at the end (when sample_times is empty)
  /// times at which the observers are sampled instead, each landed on by the step before it (increasing)
  std::vector<double> sample_times;
  BodyForceTime body_force_time = BodyForceTime::step_end;
  /// The run stops (exit code 3) when the kinetic plus strain energy exceeds this factor times
  /// the initial energy plus the work done by the body force: the signature of an instability.
  double energy_growth_limit = 10.0;
  int threads = 0;  ///< cores the particle loops run on; 0: all (the results are the same bits on any number)
  long last_step = 0;  ///< the run stops after this step, before end_time (`mpm trace`); 0: at end_time
  /// The run fails (exit code 3) before a step past this many (`mpm run --max-steps`, output landings counted);
  /// 0: no limit (`--force`, and the programs of verification/).
  long max_steps = 0;
  /// The run fails when a Courant step of Eq. (42) falls below this fraction of the first step's (no longer than
  /// end_time): a particle a million times faster than at t = 0 (the wave speed bounds the step from above) is an
  /// instability, and the run would no longer end. Our choice; the paper sets no such floor.
  double smallest_step_fraction = 1e-6;
};

struct RunSummary {
  long steps = 0;
  double final_time = 0.0;
  double smallest_time_step = 0.0, largest_time_step = 0.0;
  double wall_seconds = 0.0;
  double particle_steps_per_second = 0.0;
  /// largest |sum_I m_I - sum_p m_p| / sum_p m_p over the steps: Eq. (13) with the partition of unity
  double largest_mass_error = 0.0;
  ShapeDiagnostics shape;
  int threads = 1;                                ///< cores the particle loops ran on
  std::array<double, timed_part_count> phase_seconds{};  ///< wall seconds per TimedPart, summed over the steps
};

/// Receives what a run produces; implemented by the writers of io/ and by tests.
template <int Dim>
struct Monitor {
  virtual ~Monitor() = default;
  virtual void sample(long /*step*/, double /*time*/, const Particles<Dim>& /*particles*/, const Balances<Dim>& /*balances*/) {}
  virtual void snapshot(int /*index*/, double /*time*/, const Particles<Dim>& /*particles*/) {}
  virtual void progress(double /*time*/, double /*end_time*/) {}
  /// True if the monitor watches the phases of step `step` (numbered from 1), which goes from `time` to `time` + `dt`;
  /// asked once before each step.
  virtual bool watches(long /*step*/, double /*time*/, double /*dt*/) { return false; }
  /// After each phase of a watched step, the loop's own phases (stencils, body_force, checks, output) too;
  /// `stencils` holds the step's \f$ N_{Ip} \f$ and \f$ \nabla N_{Ip} \f$ at \f$ \mathbf x_p^k \f$.
  virtual void after(Phase /*phase*/, const Particles<Dim>& /*particles*/, const GridFields<Dim>& /*grid*/,
                     const Stencils<Dim>& /*stencils*/) {}
};

}  // namespace mpm
