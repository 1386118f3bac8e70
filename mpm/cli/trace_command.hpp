/// \file
/// `mpm trace SCENE.toml --step N`: runs the scene to step N and prints, after each phase of that step of the scene's
/// integrator (mpm/core/step_phases.hpp), every nodal quantity of the nodes that hold mass and every particle
/// quantity, as CSV (one row per node or particle and phase) or as an aligned table. The phases are numbered as the
/// integrator numbers them (its `phases` list; phase 0 the reset). A column's name says its time level:
/// `v_I_k` is \f$ \mathbf v_I^k \f$, `v_I_k1` is \f$ \mathbf v_I^{k+1} \f$, `v_I_pred` the predictor of Eq. (29);
/// the forces and accelerations carry the level of the stress that makes them, `f_I_k1` \f$ \mathbf f_I^{k+1} \f$
/// (update stress first, the predictor-corrector) and `f_I_k` \f$ \mathbf f_I^k \f$ (USL, MUSL), as the book names
/// them, with its two parts beside it: `f_I_k1_ext`, Eq. (15) summed by the trace itself from the step's b_p, and
/// `f_I_k1_int`, the rest of the kernel's force (Eq. (14) when the kernel's Eq. (15) is right: an error in either part
/// of the kernel shows there); a nodal value, once computed, stays in the later phases' rows.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/cli/run_command.hpp"
#include "mpm/cli/trace_tables.hpp"
#include "mpm/cli/trace_diff.hpp"
#include "mpm/run_api.hpp"
#ifndef DOCTEST_CONFIG_DISABLE  // the doctests at the end step the integrators themselves; the command runs scenes (run_setup)
#include "mpm/integrators/forward_euler.hpp"
#include "mpm/integrators/newmark_predictor_corrector.hpp"
#include "mpm/integrators/update_stress_last.hpp"
#include "mpm/shape/linear.hpp"
#endif

namespace mpm::cli {

/// What `mpm trace` was asked to do.
struct TraceRequest {
  std::string scene_path, format = "csv";
  long step = 0;
  std::vector<std::string> overrides;
  TraceComparisonRequest compare;  ///< --diff A.csv B.csv, or the second run: --against, --against-set
};

/// An integrator variant as the trace names it.
struct TraceVariant {
  std::string description;            ///< "forward Euler, update stress first (USF), ..."
  std::string moving = "v_I_k1";       ///< the name of the nodal velocity that moves the particles (G2P)
  std::string stress_last = "v_I_k1";  ///< USL, MUSL: of the velocity of their stress update (`v_I_k1_musl`)
  bool accelerations = false;          ///< the particles carry a_p (the predictor-corrector)
  std::string force_level = "k1";      ///< the time level of f_I, a_I and forward Euler's a_p: `k` for USL, MUSL
  std::vector<Phase> phases = integrator_phases(io::IntegratorKind::fe, io::StressUpdate::usf);  ///< numbered
};

/// A Monitor that watches one step: after each phase of the integrator's step() it copies the nodal fields the
/// phase has computed under their names and writes the rows of the nodes with mass and of every particle.
template <int Dim>
class StepTrace : public Monitor<Dim> {
 public:
  StepTrace(const Model<Dim>& model, long step, TraceVariant variant, bool csv,
            BodyForceTime body_force_time = BodyForceTime::step_end)
      : model_(model), step_(step), names_(std::move(variant)), csv_(csv), body_force_time_(body_force_time) {}

  bool watches(long step, double time, double dt) override {
    if (step != step_) return false;
    time_ = time, dt_ = dt;
    return true;
  }

  void after(Phase phase, const Particles<Dim>& particles, const GridFields<Dim>& grid,
             const Stencils<Dim>& stencils) override {
    if (!phase_info(phase).of_step) return;
    if (phase == Phase::forces) split_forces(particles, grid, stencils);
    capture(phase, grid);
    if (phase == Phase::euler_update) interpolate_acceleration(grid, stencils);
    if (phase == Phase::stress) state_level_ = "k1";
    if (phase == Phase::euler_update || phase == Phase::newmark_update) motion_level_ = "k1";
    blocks_.push_back({phase, node_table(grid), particle_table(particles)});
  }

  bool seen() const { return !blocks_.empty(); }
  double time() const { return time_; }
  double dt() const { return dt_; }
  const std::vector<TraceBlock>& blocks() const { return blocks_; }

 private:
  /// A nodal field captured under a name: `width` numbers per node, the components of a vector or one scalar.
  struct Column {
    std::string name;
    int width;
    bool vector;
    std::vector<double> values;
  };

  /// Forward Euler's particle acceleration \f$ \mathbf a_p = \sum_I N_{Ip} \mathbf a_I \f$, Eqs. (18)-(19), which its
  /// update adds to \f$ \mathbf v_p \f$ times dt and does not store: the same sum, in the same order, as
  /// forward_euler_particle_update.
  void interpolate_acceleration(const GridFields<Dim>& grid, const Stencils<Dim>& stencils) {
    const int particles = static_cast<int>(stencils.count.size());
    acceleration_.assign(particles, Vector<Dim>::Zero());
    for (int p = 0; p < particles; ++p) {
      const ParticleStencil<Dim> stencil = stencils.of(p);
      for (int k = 0; k < stencil.count; ++k)
        acceleration_[p] += stencil.value[k] * grid.nodal_acceleration[stencil.node[k]];
    }
  }

  /// The nodal force's two parts, which the kernel adds into one field: the external force of Eq. (15),
  /// \f$ \mathbf f_I^{ext} = \sum_p N_{Ip}\, m_p \mathbf b_p \f$, summed here from the step's body force (the same
  /// \f$ \mathbf b_p \f$ as the loop's, at the time gravity.evaluate_at names), and the internal force, Eq. (14), as
  /// what the kernel added beyond it, \f$ \mathbf f_I^{int} = \mathbf f_I + \mathbf r_I - \mathbf f_I^{ext} \f$ (the
  /// reactions hold the force of the fixed components): so an edit of the kernel's Eq. (14) shows in `f_I_k1_int`,
  /// and so would an error in its Eq. (15), since the trace sums that part itself. The suffix is the level of the
  /// stress (`f_I_k_ext` under USL and MUSL), not of b_p, which is read where gravity.evaluate_at says.
  void split_forces(const Particles<Dim>& particles, const GridFields<Dim>& grid, const Stencils<Dim>& stencils) {
    ParticleBodyForces<Dim> b_p;
    model_.body_force.evaluate(body_force_time_ == BodyForceTime::step_end ? time_ + dt_ : time_, particles, b_p);
    std::vector<Vector<Dim>> external(grid.size(), Vector<Dim>::Zero()), internal(grid.size(), Vector<Dim>::Zero());
    for (int p = 0; p < particles.size() && !b_p.all_zero; ++p) {
      const ParticleStencil<Dim> stencil = stencils.of(p);
      for (int k = 0; k < stencil.count; ++k)
        external[stencil.node[k]] += stencil.value[k] * particles.mass[p] * b_p.per_unit_mass[p];
    }
    for (int node = 0; node < grid.size(); ++node)
      internal[node] = grid.nodal_force[node] + grid.reaction[node] - external[node];
    keep("f_I_" + names_.force_level + "_ext", external);
    keep("f_I_" + names_.force_level + "_int", internal);
  }

  void capture(Phase phase, const GridFields<Dim>& grid) {
    const bool predictor = phase == Phase::mass_predictor || phase == Phase::fixed_predictor;
    if (phase == Phase::mass_momentum || phase == Phase::mass_predictor) keep("m_I", grid.nodal_mass);
    if (predictor) keep("v_I_pred", grid.predicted_velocity);
    if (predictor || phase == Phase::mass_momentum || phase == Phase::fixed_momentum)
      keep("p_I_k", grid.nodal_momentum_k);
    if (phase == Phase::velocity_k) keep("v_I_k", grid.nodal_velocity_k);
    if (phase == Phase::forces) keep("f_I_" + names_.force_level, grid.nodal_force), keep("r_I", grid.reaction);
    if (phase == Phase::momentum_balance) keep("p_I_k1", grid.nodal_momentum_k1);
    if (phase == Phase::reprojection) keep("p_I_k1_musl", grid.nodal_momentum_k1);
    if (phase == Phase::velocity_k1) keep(names_.stress_last, grid.nodal_velocity_k1);
    if (phase == Phase::corrector) keep("v_I_k1", grid.nodal_velocity_k1);
    if (phase == Phase::euler_update || phase == Phase::newmark_update)
      keep("a_I_" + names_.force_level, grid.nodal_acceleration), keep(names_.moving, grid.moving_velocity);
  }

  void keep(const std::string& name, const std::vector<double>& field) {
    store(name, 1, false, field.data(), field.size());
  }
  void keep(const std::string& name, const std::vector<Vector<Dim>>& field) {
    store(name, Dim, true, field.empty() ? nullptr : field[0].data(), field.size());
  }
  void store(const std::string& name, int width, bool vector, const double* data, size_t nodes) {
    auto column = std::find_if(columns_.begin(), columns_.end(), [&](const Column& c) { return c.name == name; });
    if (column == columns_.end()) column = columns_.insert(columns_.end(), Column{name, width, vector, {}});
    column->values.assign(data, data + width * nodes);
  }

  /// `name` of a scalar, or `name` with the suffix of each component of a vector: `_x` (1D), `_x`, `_y` (2D).
  static void add_names(std::vector<std::string>& header, const std::string& name, bool vector) {
    const char* axes[] = {"_x", "_y"};
    if (!vector) header.push_back(name);
    for (int k = 0; vector && k < Dim; ++k) header.push_back(name + axes[k]);
  }

  /// The fixed components of `node` ("x", "y", "xy"), or "-".
  std::string fixed_text(int node) const {
    std::string text;
    for (const FixedDof& dof : model_.fixed)
      if (dof.node == node && text.find("xy"[dof.component]) == std::string::npos) text += "xy"[dof.component];
    std::sort(text.begin(), text.end());
    return text.empty() ? "-" : text;
  }

  TraceTable node_table(const GridFields<Dim>& grid) const {
    TraceTable table;
    table.header = {"node", "x_I"};
    if (Dim == 2) table.header.push_back("y_I");
    table.header.push_back("fixed");
    for (const Column& column : columns_) add_names(table.header, column.name, column.vector);
    for (int node = 0; node < grid.size(); ++node) {
      if (!(grid.nodal_mass[node] > 0.0)) continue;
      std::vector<std::string> row{std::to_string(node)};
      const Vector<Dim> x = model_.grid.node_position(node);
      for (int axis = 0; axis < Dim; ++axis) row.push_back(trace_number(x[axis], csv_));
      row.push_back(fixed_text(node));
      for (const Column& column : columns_)
        for (int k = 0; k < column.width; ++k)
          row.push_back(trace_number(column.values[node * column.width + k], csv_));
      table.rows.push_back(std::move(row));
    }
    return table;
  }

  TraceTable particle_table(const Particles<Dim>& particles) const;

  const Model<Dim>& model_;
  long step_;
  TraceVariant names_;
  bool csv_;
  BodyForceTime body_force_time_;  ///< when in the step b_p is read (gravity.evaluate_at), for f_I^ext
  double time_ = 0.0, dt_ = 0.0;
  std::string motion_level_ = "k", state_level_ = "k";  ///< the time level of x_p, v_p, a_p and of eps, sigma, rho
  std::vector<Column> columns_;
  std::vector<Vector<Dim>> acceleration_;  ///< forward Euler's a_p, once its update has run
  std::vector<TraceBlock> blocks_;
};

/// The particles' rows: id; mass; position, velocity (and acceleration for the predictor-corrector) at the level of the
/// motion; forward Euler's acceleration, after its update, at the level of the forces; strain, stress and density at
/// the level of the state.
template <int Dim>
TraceTable StepTrace<Dim>::particle_table(const Particles<Dim>& particles) const {
  const bool accelerations = names_.accelerations;
  const std::string motion = "_p_" + motion_level_, state = "_p_" + state_level_;
  TraceTable table;
  table.header = {"particle", "m_p", "x" + motion};
  if (Dim == 2) table.header.push_back("y" + motion);
  add_names(table.header, "v" + motion, true);
  if (accelerations) add_names(table.header, "a" + motion, true);
  const bool interpolated = !accelerations && !acceleration_.empty();
  if (interpolated) add_names(table.header, "a_p_" + names_.force_level, true);
  const std::vector<std::string> tensor = Dim == 1 ? std::vector<std::string>{"_xx"}
                                                   : std::vector<std::string>{"_xx", "_yy", "_xy"};
  for (const auto& name : tensor) table.header.push_back("eps" + state + name);
  for (const auto& name : tensor) table.header.push_back("sigma" + state + name);
  if (Dim == 2) table.header.push_back("sigma" + state + "_zz");
  table.header.push_back("rho" + state);
  for (int p = 0; p < particles.size(); ++p) {
    std::vector<std::string> row{std::to_string(particles.id[p])};
    auto add = [&](double value) { row.push_back(trace_number(value, csv_)); };
    add(particles.mass[p]);
    for (int axis = 0; axis < Dim; ++axis) add(particles.position[p][axis]);
    for (int axis = 0; axis < Dim; ++axis) add(particles.velocity[p][axis]);
    for (int axis = 0; accelerations && axis < Dim; ++axis) add(particles.acceleration[p][axis]);
    for (int axis = 0; interpolated && axis < Dim; ++axis) add(acceleration_[p][axis]);
    for (const Matrix<Dim>* tensor_p : {&particles.strain[p], &particles.stress[p]}) {
      add((*tensor_p)(0, 0));
      if (Dim == 2) add((*tensor_p)(Dim - 1, Dim - 1)), add((*tensor_p)(0, Dim - 1));
    }
    if (Dim == 2) add(particles.stress_zz[p]);
    add(particles.density[p]);
    table.rows.push_back(std::move(row));
  }
  return table;
}

/// How the trace names the scene's integrator and its nodal velocities.
inline TraceVariant trace_variant(const io::Scene& scene) {
  TraceVariant variant;
  std::ostringstream text;
  if (scene.integrator == io::IntegratorKind::npc) {
    const char* moving[] = {"v_I_k", "v_I_k1", "v_I_pred"};  // NewmarkPositionVelocity: projected, corrected, predicted
    const char* position[] = {"projected", "corrected", "predicted"};
    const int choice = static_cast<int>(scene.npc_position_velocity);
    variant.moving = moving[choice];
    variant.accelerations = true;
    variant.phases = integrator_phases(scene.integrator, scene.stress_update);
    text << "predictor-corrector (npc), gamma = " << scene.newmark_gamma << ", position update " << position[choice]
         << " (x_p moves with " << moving[choice] << "), particle velocity "
         << (scene.npc_velocity == NewmarkParticleVelocity::eq32 ? "eq32" : "average");
  } else {
    const bool start = scene.fe_position_velocity == EulerPositionVelocity::start;
    const char* order[] = {"update stress first (usf)", "update stress last (usl)",
                           "modified update stress last (musl)"};
    variant.moving = start ? "v_I_k" : "v_I_k1";
    if (scene.stress_update == io::StressUpdate::musl) variant.stress_last = "v_I_k1_musl";
    if (scene.stress_update != io::StressUpdate::usf) {
      variant.force_level = "k";  // USL, MUSL: the forces of the stress at t_k
      variant.phases = integrator_phases(scene.integrator, scene.stress_update);
    }
    text << "forward Euler (fe), " << order[static_cast<int>(scene.stress_update)] << ", position update "
         << (start ? "start" : "updated") << " (x_p moves with " << variant.moving << "), flip_fraction "
         << scene.flip_fraction;
  }
  variant.description = text.str();
  return variant;
}


/// The number the integrator gives `phase` (its place in the integrator's `phases` list; MUSL's phase 7 is skipped
/// by USL, whose phases 8 and 9 keep their numbers).
inline size_t phase_number(const TraceVariant& variant, Phase phase) {
  return std::find(variant.phases.begin(), variant.phases.end(), phase) - variant.phases.begin();
}

/// The whole trace: a title, then per phase a line naming it and its equations, its nodes and its particles.
template <int Dim>
void print_trace(const StepTrace<Dim>& trace, const TraceRequest& request, const TraceVariant& variant,
                 std::ostream& out) {
  const bool csv = request.format == "csv";
  const char* comment = csv ? "# " : "";
  out << comment << "mpm trace " << request.scene_path << ": step " << request.step
      << " from t_k = " << trace_number(trace.time(), true) << " s to t_k + dt, dt = " << trace_number(trace.dt(), true)
      << " s; " << Dim << "D; " << variant.description << "\n";
  out << comment << "k: the value at t_k; k1: at t_k + dt (f_I, a_I: the level of the stress that makes them);"
      << " nodes without mass left out; a nodal value stays in the rows of the phases after the one that computed it\n";
  for (const TraceBlock& block : trace.blocks()) {
    const PhaseInfo& info = phase_info(block.phase);
    out << (csv ? "# " : "\n") << "phase " << phase_number(variant, block.phase) << " of "
        << variant.phases.size() - 1 << ": " << info.name
        << equations_text(info.equation) << ": " << info.what
        << "\n";
    for (const TraceTable* table : {&block.nodes, &block.particles})
      csv ? print_csv_table(*table, info, out) : print_aligned_table(*table, out);
  }
}

/// Runs the scene to step `request.step` with a StepTrace watching it; prints it. Returns the exit code: 3 when the
/// method fails before. \throws Refused when the run ends before that step.
template <int Dim>
int trace_run(const io::Scene& scene, const TraceRequest& request, std::ostream& out, std::ostream& err) {
  const Setup<Dim> setup = build_setup<Dim>(scene);
  const TraceVariant variant = trace_variant(scene);
  StepTrace<Dim> trace(setup.model, request.step, variant, request.format == "csv", scene.control.body_force_time);
  RunSummary summary;
  try {
    summary = run_setup<Dim>(scene, setup, trace, &summary);
  } catch (const SimulationFailure& failure) {
    err << failure.message() << "\n";
    return 3;
  }
  if (!trace.seen())
    throw Refused("--step: the run ends after step " + std::to_string(summary.steps) + " (t = " +
                  trace_number(summary.final_time, true) + " s, solver.end_time): give a step from 1 to " +
                  std::to_string(summary.steps));
  print_trace(trace, request, variant, out);
  return 0;
}

/// The observer a step() run outside the loop shows a StepTrace (the doctests): the stencils passed along.
template <int Dim>
struct TraceObserver {
  StepTrace<Dim>& trace;
  const Stencils<Dim>& stencils;
  void after(Phase phase, const Particles<Dim>& particles, const GridFields<Dim>& grid) {
    trace.after(phase, particles, grid, stencils);
  }
};

/// `mpm trace`'s parser, its options bound to `request`.
inline std::unique_ptr<CommandParser> trace_parser(TraceRequest& request) {
  auto app = scene_command_parser(
      "trace",
      "Runs a scene to step N and prints, after each phase of that step of its integrator, the phase's equations,\n"
      "every nodal quantity of the nodes that hold mass (m_I, p_I, v_I, f_I with its external and internal parts,\n"
      "a_I, the fixed components, reactions r_I) and every particle quantity (x, v, a, strain, stress, density), as CSV or an aligned table;\n"
      "writes no file. "
      "Column names say the time level: _k at t_k, _k1 at t_k + dt, _pred the predictor; f_I and a_I that of the\n"
      "stress that makes them. The phases are numbered as the integrator numbers them (the book's tables too).\n"
      "Two traces compared (--diff, --against, --against-set): the first value that differs; exit 1 when any does.",
      request.scene_path, request.overrides);
  app->get_option("SCENE.toml")->required(false);  // not with --diff: trace_command requires it
  app->add_option("--step", request.step,
                  "the step to trace, numbered from 1 (the first step goes from t = 0); required, but with --diff")
      ->default_str("")  // no default: check_trace_request requires it
      ->check(whole_in(1, 10000000));
  app->add_option("--format", request.format, "csv: one row per node or particle and phase; table: aligned columns")
      ->check(one_of({"csv", "table"}));
  add_trace_comparison_options(*app, request.compare);
  return app;
}

/// `mpm trace SCENE.toml --step N [--set KEY=VALUE ...] [--format csv|table]`, or two traces compared (trace_diff.hpp).
/// Returns the exit code: 1 for traces that differ, 2 for a bad option, scene or trace file or a step beyond the
/// run's end, 3 when the method fails before the step.
inline int trace_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  TraceRequest request;
  auto app = trace_parser(request);
  return run_parsed(*app, arguments, out, err, [&] {
    if (!request.compare.files.empty()) return diff_trace_files(request.compare, out);
    check_trace_request(request.scene_path, request.step, request.compare, *app);
    auto trace = [&](const std::string& path, const std::vector<std::string>& overrides, std::ostream& to) {
      io::Budget budget;
      budget.force = true;  // only --step steps run: end_time / dt does not bound the work
      io::Scene scene = load_scene(path, overrides, budget);
      scene.control.last_step = request.step;
      return scene.dimension == 1 ? trace_run<1>(scene, request, to, err) : trace_run<2>(scene, request, to, err);
    };
    if (!request.compare.runs()) return trace(request.scene_path, request.overrides, out);
    return compare_trace_runs(request.scene_path, request.overrides, request.compare, trace, out);
  });
}

// These doctests step the integrators themselves, which only the tests include (the command-line program compiles
// no kernel: its runs are the library's).
#ifndef DOCTEST_CONFIG_DISABLE
TEST_CASE("Integrators: step() runs its phases in the order of its numbered list, which the trace prints") {
  auto run = [](const auto& integrator) {
    testing::WorkedExample example;
    Model<1> model;
    model.grid = example.grid;
    model.materials = {LinearElastic{example.young_modulus, 0.0, example.density}};
    PhaseRecorder recorder;
    integrator.step(FastKernels{}, model, example.stencils, testing::WorkedExample::body_force(), example.dt,
                    example.particles, example.fields, recorder);
    return recorder.seen;
  };
  auto list = [](const auto& phases) { return std::vector<Phase>(phases.begin(), phases.end()); };
  CHECK(run(ForwardEuler()) == list(ForwardEuler::phases));
  CHECK(run(NewmarkPredictorCorrector()) == list(NewmarkPredictorCorrector::phases));
  UpdateStressLast usl, musl;
  musl.stress_velocity = MuslMomentumK1{};
  CHECK(run(musl) == list(UpdateStressLast::phases));
  std::vector<Phase> usl_phases = list(UpdateStressLast::phases);
  usl_phases.erase(usl_phases.begin() + 7);  // USL skips MUSL's reprojection
  CHECK(usl_phases[7] == Phase::velocity_k1);
  CHECK(run(usl) == usl_phases);
  TraceVariant variant;  // forward Euler's, unless the scene says otherwise
  CHECK(phase_number(variant, Phase::forces) == 5);
  variant.phases = list(NewmarkPredictorCorrector::phases);
  CHECK(phase_number(variant, Phase::corrector) == 5);
  variant.phases = list(UpdateStressLast::phases);
  CHECK(phase_number(variant, Phase::stress) == 9);
}

TEST_CASE("mpm trace: the phases of one forward-Euler step on two particles by hand, each value under its name") {
  // h = 1, nodes x = 0, 1, 2, linear shapes; particle 0 at 0.5 (m = 2, v = 1), particle 1 at 1.25 (m = 4, v = -2);
  // node 2 held. P2G, Eq. (13): m_I = (1, 1 + 3, 1) = (1, 4, 1); p_I^k = (1, 1 - 6, -2) = (1, -5, -2), node 2 held: 0.
  Model<1> model;
  model.grid = Grid<1>(Vector<1>(0.0), 1.0, {2});
  model.materials = {LinearElastic{100.0, 0.0, 4.0}};
  model.fixed = {FixedDof{2, 0}};
  Particles<1> particles;
  particles.add(Vector<1>(0.5), 2.0, 4.0, Vector<1>(1.0), Vector<1>(0.25));
  particles.add(Vector<1>(1.25), 4.0, 4.0, Vector<1>(-2.0), Vector<1>(0.25));
  LinearShape<1> shape(model.grid);
  Stencils<1> stencils;
  stencils.resize(particles.size(), shape.capacity());
  compute_stencils(shape, particles.position, stencils);
  GridFields<1> grid(3);
  ParticleBodyForces<1> body_force;
  body_force.per_unit_mass.assign(2, Vector<1>::Zero());
  StepTrace<1> trace(model, 1, TraceVariant{}, true);
  REQUIRE(trace.watches(1, 0.0, 0.1));
  TraceObserver<1> observer{trace, stencils};
  ForwardEuler().step(FastKernels{}, model, stencils, body_force, 0.1, particles, grid, observer);
  const auto& blocks = trace.blocks();
  REQUIRE(blocks.size() == 8);
  CHECK(blocks[0].phase == Phase::reset);
  CHECK(blocks[0].nodes.rows.empty());  // no node holds mass after the reset
  CHECK(blocks[0].particles.header[2] == "x_p_k");
  const TraceTable& p2g = blocks[1].nodes;
  CHECK(p2g.header == std::vector<std::string>{"node", "x_I", "fixed", "m_I", "p_I_k_x"});
  CHECK(p2g.rows[1] == std::vector<std::string>{"1", "1", "-", "4", "-5"});
  CHECK(p2g.rows[2] == std::vector<std::string>{"2", "2", "x", "1", "-2"});
  CHECK(blocks[2].nodes.rows[2].back() == "0");  // the fixed component held
  CHECK(blocks[3].nodes.rows[1][5] == "-1.25");           // v_I^k = p_I^k / m_I = -5 / 4
  CHECK(blocks[4].particles.header[4] == "eps_p_k1_xx");  // after the stress update
  const TraceTable& balance = blocks[6].nodes;  // Eq. (12): p_I^{k+1} = p_I^k + dt f_I, each under its name
  CHECK(balance.header == std::vector<std::string>{"node", "x_I", "fixed", "m_I", "p_I_k_x", "v_I_k_x", "f_I_k1_ext_x",
                                                   "f_I_k1_int_x", "f_I_k1_x", "r_I_x", "p_I_k1_x"});
  for (const auto& row : balance.rows)
    CHECK(std::stod(row[10]) == doctest::Approx(std::stod(row[4]) + 0.1 * std::stod(row[8])));
  CHECK(std::stod(balance.rows[1][8]) != 0.0);
  const TraceTable& last = blocks[7].nodes;
  CHECK(last.header.back() == "v_I_k1_x");
  CHECK(blocks[7].particles.header[2] == "x_p_k1");
  // Forward Euler's a_p^{k+1}, which its update does not store: v_p^{k+1} = v_p^k + dt a_p^{k+1} (FLIP).
  REQUIRE(blocks[7].particles.header[4] == "a_p_k1_x");
  CHECK(blocks[6].particles.header[4] != "a_p_k1_x");  // none before the update
  for (int p = 0; p < 2; ++p) {
    const double v_k = std::stod(blocks[0].particles.rows[p][3]), v_k1 = std::stod(blocks[7].particles.rows[p][3]);
    CHECK(std::stod(blocks[7].particles.rows[p][4]) == doctest::Approx((v_k1 - v_k) / 0.1));
  }
  CHECK(std::stod(blocks[7].particles.rows[1][4]) != 0.0);
  CHECK(!StepTrace<1>(model, 2, TraceVariant{}, true).watches(1, 0.0, 0.1));
  CHECK(equations_text("(30)") == ", Eq. (30)");
  CHECK(equations_text("(16) (17) (3)") == ", Eqs. (16) (17) (3)");
  CHECK(equations_text("-").empty());
}

TEST_CASE("mpm trace: Eq. (14), Eq. (15): the nodal force apart, f_I^ext = sum_p N_Ip m_p b_p and f_I^int, the rest") {
  // The worked example (paper/12): weight b = 10 on m_p = (2, 4) at x_p = (0.25, 1.5), h = 1: f^ext = (0.75 * 20,
  // 0.25 * 20 + 0.5 * 40, 0.5 * 40) = (15, 25, 20); after the stress update f^int = (-3, 9, -6) (nodal_forces.hpp's
  // doctest); node 2 is held, so its f_I = 0 and its r_I = 20 - 6 = 14, of which the split keeps both parts.
  testing::WorkedExample example;
  Model<1> model;
  model.grid = example.grid;
  model.materials = {LinearElastic{example.young_modulus, 0.0, example.density}};
  model.fixed = {FixedDof{2, 0}};
  model.body_force.gravity.acceleration = Vector<1>(testing::WorkedExample::gravity);
  StepTrace<1> trace(model, 1, TraceVariant{}, true);
  REQUIRE(trace.watches(1, 0.0, example.dt));
  TraceObserver<1> observer{trace, example.stencils};
  ForwardEuler().step(FastKernels{}, model, example.stencils, testing::WorkedExample::body_force(), example.dt,
                      example.particles, example.fields, observer);
  const TraceTable& forces = trace.blocks()[5].nodes;
  REQUIRE(forces.header == std::vector<std::string>{"node", "x_I", "fixed", "m_I", "p_I_k_x", "v_I_k_x", "f_I_k1_ext_x",
                                                    "f_I_k1_int_x", "f_I_k1_x", "r_I_x"});
  const double external[3] = {15.0, 25.0, 20.0}, internal[3] = {-3.0, 9.0, -6.0}, total[3] = {12.0, 34.0, 0.0};
  for (int node = 0; node < 3; ++node) {
    CHECK(std::stod(forces.rows[node][6]) == doctest::Approx(external[node]));
    CHECK(std::stod(forces.rows[node][7]) == doctest::Approx(internal[node]));
    CHECK(std::stod(forces.rows[node][8]) == doctest::Approx(total[node]));
  }
  CHECK(std::stod(forces.rows[2][9]) == doctest::Approx(14.0));
  // Gravity ramped by Eq. (44) over T = 1 s and read at the step's end (gravity.evaluate_at's default), as the loop
  // reads it: b = 10 g(0.2 s) = 10 (1 - cos(0.4 pi)) / 2; the external part scales with it, the internal one does not.
  testing::WorkedExample ramped;
  model.body_force.gravity.ramp_period = 1.0;
  const double b = testing::WorkedExample::gravity * gravity_ramp(ramped.dt, 1.0);
  StepTrace<1> ramped_trace(model, 1, TraceVariant{}, true, BodyForceTime::step_end);
  REQUIRE(ramped_trace.watches(1, 0.0, ramped.dt));
  TraceObserver<1> ramped_observer{ramped_trace, ramped.stencils};
  const ParticleBodyForces<1> ramped_b{{Vector<1>(b), Vector<1>(b)}, false, true};
  ForwardEuler().step(FastKernels{}, model, ramped.stencils, ramped_b, ramped.dt, ramped.particles, ramped.fields,
                      ramped_observer);
  const TraceTable& ramped_forces = ramped_trace.blocks()[5].nodes;
  for (int node = 0; node < 3; ++node) {
    CHECK(std::stod(ramped_forces.rows[node][6]) == doctest::Approx(external[node] * b / 10.0));
    CHECK(std::stod(ramped_forces.rows[node][7]) == doctest::Approx(internal[node]));
  }
}

TEST_CASE("mpm trace: a scene run to step 2 and no further, its t_k the first dt, a step beyond the end refused") {
  // 2 particles of 0.5 kg at 0.5 m/s on 2 cells, no force: a rigid translation, every dt the same,
  // dt = 0.5 h / max(c, |v|) = 0.25 s (c = 1 m/s, h = 0.5 m): 4 steps to t = 1 s.
  const std::string text =
      "dimension = 1\n[grid]\nlength = [1.0]\ncells = [2]\nmargin_max = [2]\n[material]\nyoung_modulus = 1.0\n"
      "density = 1.0\n[[body]]\nmin = [0.0]\nmax = [1.0]\nvelocity = [0.5]\n[solver]\nend_time = 1.0\n";
  io::Scene scene = io::read_scene(io::parse_scene_text(text, "t.toml"));
  scene.control.last_step = 2;
  const Setup<1> setup = build_setup<1>(scene);
  StepTrace<1> trace(setup.model, 2, trace_variant(scene), true);
  const RunSummary summary = run_setup<1>(scene, setup, trace);
  CHECK(summary.steps == 2);
  REQUIRE(trace.seen());
  CHECK(trace.time() == doctest::Approx(0.25));
  CHECK(trace.dt() == doctest::Approx(0.25));
  CHECK(trace.blocks()[1].nodes.rows[0][3] == "0.125");  // m_0 = N_0(0.375 m) 0.5 kg = 0.25 * 0.5 kg
  TraceRequest request;
  request.step = 100;
  scene.control.last_step = 100;
  std::ostringstream out, err;
  std::string refusal;
  try {
    trace_run<1>(scene, request, out, err);
  } catch (const Refused& refused) {
    refusal = refused.what();
  }
  CHECK(refusal.rfind("--step: the run ends after step 4 (t = 1 s", 0) == 0);
  CHECK(out.str().empty());
  // USL: the forces of the stress at t_k, f_I^k, and forward Euler's a_p^k after the update, its phase 8 v_I^{k+1}.
  scene.stress_update = io::StressUpdate::usl;
  scene.control.last_step = 1;
  const TraceVariant usl = trace_variant(scene);
  StepTrace<1> usl_trace(setup.model, 1, usl, true);
  run_setup<1>(scene, setup, usl_trace);
  const auto& blocks = usl_trace.blocks();
  REQUIRE(blocks.size() == 9);
  CHECK(blocks[4].nodes.header.back() == "r_I_x");
  CHECK(blocks[4].nodes.header[blocks[4].nodes.header.size() - 2] == "f_I_k_x");
  CHECK(blocks[4].nodes.header[blocks[4].nodes.header.size() - 3] == "f_I_k_int_x");  // its parts at its level
  CHECK(blocks[4].nodes.header[blocks[4].nodes.header.size() - 4] == "f_I_k_ext_x");
  CHECK(blocks[6].particles.header[4] == "a_p_k_x");
  CHECK(phase_number(usl, blocks[7].phase) == 8);
}

#endif  // DOCTEST_CONFIG_DISABLE

}  // namespace mpm::cli
