/// \file
/// The time-step loop around one step of an integrator. The paper's algorithm box (paper/03, "One
/// predictor-corrector step as the code runs it", \ref npc_algorithm) has nine steps, which the integrator's step()
/// runs as its numbered phases (\ref fe_algorithm for forward Euler); the time step of Eq. (42) and the stencils come
/// before them, here.
///
/// A Simulation owns the model, the particles, the shape function and the integrator, all chosen
/// once per run as template arguments. run() advances from t = 0 to the end time, each pass of the loop in five parts:
///
///   1. dt by the Courant condition, Eq. (42), or fixed (solver.dt), shortened to land on the next output time;
///   2. the stencils N_Ip, grad N_Ip at x_p^k, computed once and reused by every transfer;
///   3. one step of the integrator (forward Euler, paper/02_mpm_forward_euler.md, or the predictor-corrector, paper/03_predictor_corrector.md);
///   4. one pass over the particles (ParticleSurvey): the balances, the speeds of the next dt, and the
///      health checks: no NaN, no particle off the grid, no unbounded energy growth;
///   5. the observer samples and snapshots.
///
/// The loop knows no files: a Monitor (io/run_writer.hpp) receives the samples. Every pass over the
/// particles runs on RunControl::threads cores (mpm/core/parallel.hpp); on the reference kernels
/// (`solver.kernels = "reference"`) run.hpp's control_on sets one thread, so every loop runs serially. After each
/// named phase of the step
/// (mpm/core/step_phases.hpp) the loop's LoopPhases times it (PhaseTimers) and shows it to a Monitor that
/// watches that step (`mpm trace`).
#pragma once
#include <array>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "mpm/analysis/energy.hpp"
#include "mpm/analysis/particle_survey.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/core/phase_timers.hpp"
#include "mpm/core/errors.hpp"
#include "mpm/core/kernels.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/fast_stencils.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/integrators/time_step.hpp"
#include "mpm/model.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/run_control.hpp"
#include "mpm/shape/shape_diagnostics.hpp"

namespace mpm {

/// The observer of the phases that the loop passes to the integrator's step(): it times each phase and, during a
/// step that the monitor watches, shows it to the monitor (one test of a pointer per phase when none does).
template <int Dim>
struct LoopPhases {
  PhaseTimers timers;
  Monitor<Dim>* watcher = nullptr;          ///< the monitor, while it watches the step; else null
  const Stencils<Dim>* stencils = nullptr;  ///< the loop's stencils, shown to the watcher

  void after(Phase phase, const Particles<Dim>& particles, const GridFields<Dim>& grid) {
    timers.lap(phase);
    if (watcher) watcher->after(phase, particles, grid, *stencils);
  }
};

/// The run of one method: `Kernels` is the layer of the transfers (mpm/core/kernels.hpp): the reference kernels of
/// mpm/transfer/ or, by default, the fast ones of mpm/fast/.
template <int Dim, class Shape, class Integrator, class Kernels = FastKernels>
class Simulation {
 public:
  Simulation(Model<Dim> model, Particles<Dim> particles, Shape shape, Integrator integrator, RunControl control)
      : model_(std::move(model)), particles_(std::move(particles)), shape_(std::move(shape)),
        integrator_(std::move(integrator)), control_(std::move(control)), grid_fields_(model_.grid.node_count()) {
    std::sort(control_.snapshot_times.begin(), control_.snapshot_times.end());
    std::sort(control_.sample_times.begin(), control_.sample_times.end());
  }

  const Particles<Dim>& particles() const { return particles_; }
  const GridFields<Dim>& grid_fields() const { return grid_fields_; }

  RunSummary run(Monitor<Dim>& monitor) {
    wall_start_ = std::chrono::steady_clock::now();
    use_threads(control_.threads);
    shape_.initialise(particles_);
    stencils_.resize(particles_.size(), shape_.capacity());
    body_force_.per_unit_mass.resize(particles_.size());
    ParticleSurvey<Dim> survey = survey_particles(particles_, model_.grid, model_.materials);
    initial_energy_ = survey.balances.total();

    RunSummary& summary = summary_;
    summary = RunSummary{};
    summary.threads = team_threads();
    summary.smallest_time_step = std::numeric_limits<double>::infinity();
    double time = 0.0;
    long step = 0;
    size_t next_snapshot = 0, next_sample = 0;
    if (control_.sample_times.empty()) monitor.sample(step, time, particles_, survey.balances);
    else write_due_samples(step, time, next_sample, survey.balances, monitor);
    write_due_snapshots(time, next_snapshot, monitor);
    LoopPhases<Dim>& phases = phases_;
    phases.stencils = &stencils_;
    phases.timers.restart();

    const bool fixed = control_.fixed_dt > 0.0;
    double anchor = 0.0;  // a fixed step's clock: anchor + n dt, n steps since the last landing, never a drifting sum
    long since_anchor = 0;
    const double first_dt = std::min(control_.end_time, courant_time_step(survey.fastest_speed(), survey.wave_speed(),
                                                                          model_.grid.spacing(), control_.cfl, control_.courant));
    while (time < control_.end_time && (control_.last_step == 0 || step < control_.last_step)) {
      // 1. Time step, Eq. (42) or fixed, landing exactly on output times and on the end time (a fixed step within
      //    1e-9 dt of the target keeps its length); the run fails if it would not end.
      double dt = fixed ? control_.fixed_dt
                        : courant_time_step(survey.fastest_speed(), survey.wave_speed(), model_.grid.spacing(),
                                            control_.cfl, control_.courant);
      check_step_count(step, time);
      if (!fixed) check_courant_step(step, time, dt, first_dt);
      const double target = next_stop(time, next_snapshot, next_sample);
      const bool lands = time + dt * (1.0 + 1e-9) >= target;
      if (lands && !(fixed && std::abs(target - time - dt) <= 1e-9 * dt)) dt = target - time;
      const double next_time = lands ? target : fixed ? anchor + static_cast<double>(since_anchor + 1) * dt : time + dt;
      if (!(next_time > time)) throw SimulationFailure(step, time, -1, "", stalled_cause(dt));
      phases.watcher = monitor.watches(step + 1, time, dt) ? &monitor : nullptr;
      // 2. Stencils at the current positions x_p^k.
      locate_particles(step, time);
      phases.after(Phase::stencils, particles_, grid_fields_);
      // 3. One step of the integrator.
      const double body_force_time = control_.body_force_time == BodyForceTime::step_end ? time + dt : time;
      model_.body_force.evaluate(body_force_time, particles_, body_force_);  // b_p of Eq. (15), at x_p^k
      phases.after(Phase::body_force, particles_, grid_fields_);
      integrator_.step(kernels_, model_, stencils_, body_force_, dt, particles_, grid_fields_, phases);
      time = next_time;
      if (lands) anchor = target, since_anchor = 0;
      else if (fixed) ++since_anchor;
      ++step;
      summary.steps = step;
      summary.final_time = time;
      summary.smallest_time_step = std::min(summary.smallest_time_step, dt);
      summary.largest_time_step = std::max(summary.largest_time_step, dt);
      // 4. Health, from one pass over the particles that also gives the balances and the next dt's speeds.
      survey = survey_particles(particles_, model_.grid, model_.materials);
      const Balances<Dim>& now = survey.balances;
      summary.largest_mass_error = std::max(summary.largest_mass_error, nodal_mass_error(now.mass));
      external_work_ += dt * body_force_power(particles_, body_force_, now.momentum);
      check_health(step, time, survey);
      phases.after(Phase::checks, particles_, grid_fields_);
      // 5. Output.
      const bool last = time >= control_.end_time;
      if (!control_.sample_times.empty()) write_due_samples(step, time, next_sample, now, monitor);
      else if (step % control_.sample_every == 0 || last) monitor.sample(step, time, particles_, now);
      write_due_snapshots(time, next_snapshot, monitor);
      monitor.progress(time, control_.end_time);
      phases.after(Phase::output, particles_, grid_fields_);
    }

    finish_summary();
    return summary;
  }

  /// What the run has done so far; complete after run() returns, partial after it throws.
  const RunSummary& summary() {
    finish_summary();
    return summary_;
  }

 private:
  void finish_summary() {
    if (summary_.steps == 0) summary_.smallest_time_step = 0.0;
    summary_.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
    summary_.particle_steps_per_second =
        summary_.wall_seconds > 0.0 ? double(summary_.steps) * particles_.size() / summary_.wall_seconds : 0.0;
    summary_.shape = shape_.diagnostics();
    summary_.phase_seconds = phases_.timers.seconds;
  }

  /// The next time the loop must land on: the next snapshot time, the next sample time or the end time.
  double next_stop(double time, size_t next_snapshot, size_t next_sample) const {
    double stop = control_.end_time;
    for (size_t k = next_snapshot; k < control_.snapshot_times.size(); ++k)
      if (control_.snapshot_times[k] > time) {
        stop = std::min(stop, control_.snapshot_times[k]);
        break;
      }
    for (size_t k = next_sample; k < control_.sample_times.size(); ++k)
      if (control_.sample_times[k] > time) return std::min(stop, control_.sample_times[k]);
    return stop;
  }

  /// One sample at `time` if a sample time is due (the steps land on them: at most one is due per step,
  /// the times being distinct).
  void write_due_samples(long step, double time, size_t& next_sample, const Balances<Dim>& balances, Monitor<Dim>& monitor) {
    bool due = false;
    while (next_sample < control_.sample_times.size() && control_.sample_times[next_sample] <= time) ++next_sample, due = true;
    if (due) monitor.sample(step, time, particles_, balances);
  }

  /// Relative difference between the grid's total mass and the particles' (0 up to round-off).
  double nodal_mass_error(double particle_mass) const {
    double nodal_mass = 0.0;
    for (double mass : grid_fields_.nodal_mass) nodal_mass += mass;
    return std::abs(nodal_mass - particle_mass) / particle_mass;
  }

  void write_due_snapshots(double time, size_t& next_snapshot, Monitor<Dim>& monitor) {
    while (next_snapshot < control_.snapshot_times.size() && control_.snapshot_times[next_snapshot] <= time) {
      monitor.snapshot(static_cast<int>(next_snapshot), time, particles_);
      ++next_snapshot;
    }
  }

  void locate_particles(long step, double time) {
    try {
      compute_stencils(kernels_, shape_, particles_.position, stencils_);
    } catch (const ShapeFailure& failure) {
      throw SimulationFailure(step, time, particles_.id[failure.particle], position_text(failure.particle), failure.what());
    }
  }

  /// Fails a run about to take one step more than RunControl::max_steps (0: no limit).
  void check_step_count(long step, double time) const {
    if (control_.max_steps <= 0 || step < control_.max_steps) return;
    std::ostringstream cause;
    cause << "the run reached its limit of " << control_.max_steps << " steps before end_time = " << control_.end_time
          << " s (--max-steps N raises it, --force lifts it)";
    throw SimulationFailure(step, time, -1, "", cause.str());
  }

  /// Fails a run whose Courant step `dt` (Eq. (42)) fell below RunControl::smallest_step_fraction of the first one.
  void check_courant_step(long step, double time, double dt, double first_dt) const {
    if (dt >= control_.smallest_step_fraction * first_dt) return;
    std::ostringstream cause;
    cause << "the time step of Eq. (42) fell to " << dt << " s, below " << control_.smallest_step_fraction
          << " of the first step's " << first_dt << " s (the speed C of Eq. (42) grew to "
          << control_.cfl * model_.grid.spacing() / dt << " m/s): the run would not end";
    throw SimulationFailure(step, time, -1, "", cause.str());
  }

  /// Why a step of length `dt` leaves the time where it is.
  static std::string stalled_cause(double dt) {
    std::ostringstream cause;
    cause << "time does not advance: t + dt == t in double precision with dt = " << dt << " s";
    return cause.str();
  }

  /// Names the first unhealthy particle, if the survey found one, then checks the energy.
  void check_health(long step, double time, const ParticleSurvey<Dim>& survey) const {
    for (int p = 0; survey.unhealthy > 0 && p < particles_.size(); ++p) {
      const bool finite = particles_.position[p].allFinite() && particles_.velocity[p].allFinite() &&
                          particles_.stress[p].allFinite() && std::isfinite(particles_.density[p]);
      if (!finite) throw SimulationFailure(step, time, particles_.id[p], position_text(p), "NaN or infinity in the particle state");
      if (!model_.grid.contains(particles_.position[p]))
        throw SimulationFailure(step, time, particles_.id[p], position_text(p), "particle left the grid");
    }
    const Balances<Dim>& now = survey.balances;
    const double bound = initial_energy_ + std::max(external_work_, 0.0);
    if (control_.energy_growth_limit > 0.0 && bound > 0.0 && now.total() > control_.energy_growth_limit * bound) {
      std::ostringstream cause;
      cause << "unstable: energy grew to " << now.total() / bound
            << " times the initial energy plus the work of the body force (limit " << control_.energy_growth_limit << ")";
      throw SimulationFailure(step, time, -1, "", cause.str());
    }
  }

  std::string position_text(int p) const {
    std::ostringstream text;
    text.precision(9);
    text << "(";
    for (int axis = 0; axis < Dim; ++axis) text << (axis ? ", " : "") << particles_.position[p][axis];
    text << ")";
    return text.str();
  }

  Model<Dim> model_;
  Particles<Dim> particles_;
  Shape shape_;
  Integrator integrator_;
  /// The layer of the transfers, one per run: the fast layer holds the workspace of its scatters (ReferenceKernels
  /// holds nothing).
  Kernels kernels_;
  RunControl control_;
  GridFields<Dim> grid_fields_;
  Stencils<Dim> stencils_;
  ParticleBodyForces<Dim> body_force_;  ///< b_p of the current step
  RunSummary summary_;
  LoopPhases<Dim> phases_;  ///< times the phases; shows them to a watching monitor
  std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  double initial_energy_ = 0.0;
  double external_work_ = 0.0;  ///< \f$ \int \sum_p m_p \mathbf b_p \cdot \mathbf v_p \, dt \f$
};

}  // namespace mpm
