/// \file
/// Writes what a run produces into its output folder:
///   observers.csv        t, then per observer NAME.x, NAME.v_x, NAME.sigma_xx (2D adds y components), then
///                        per observer its displacement since t = 0, NAME.u_x (2D: NAME.u_y), x_p - X_p
///   energy.csv           t,kinetic,strain,total,momentum_x (2D adds momentum_y)
///   snapshot_NNNN.csv    every particle: id, position, velocity, stress, density
///   snapshot_NNNN.vtp    the same as VTK XML polydata, listed with its time in
///   snapshots.pvd        the collection ParaView opens as a time series (mpm/io/vtk_collection.hpp)
///   run.json             the run's status, identity, resolved scene, numbers and units (write_run_json)
/// and shows progress on stderr when stderr is a terminal. Every file goes through OutputFile
/// (mpm/io/output_file.hpp): a file that cannot be opened or written in full (no permission, disk full,
/// a symbolic link in its place) raises OutputFailure naming it.
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mpm/io/json_writer.hpp"
#include "mpm/io/output_file.hpp"
#include "mpm/io/scene.hpp"
#include "mpm/io/scene_keys.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/vtk_collection.hpp"
#include "mpm/simulation.hpp"

namespace mpm::io {

template <int Dim>
class RunWriter : public Monitor<Dim> {
 public:
  RunWriter(const std::string& folder, const Scene& scene, std::vector<int> observed)
      : folder_(folder), scene_(scene), observed_(std::move(observed)),
        observers_(folder + "/observers.csv"), energy_(folder + "/energy.csv"), collection_(folder + "/snapshots.pvd"),
        show_progress_(isatty(fileno(stderr))) {
    observers_ << "t";
    for (const auto& observer : scene.observers) {
      const std::string& name = observer.name;
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << name << "." << axis_name(axis);
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << name << ".v_" << axis_name(axis);
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << name << ".sigma_" << axis_name(axis) << axis_name(axis);
      if (Dim == 2) observers_ << "," << name << ".sigma_xy";
    }
    // The displacements come last, so that the columns before them keep their numbers.
    for (const auto& observer : scene.observers)
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << observer.name << ".u_" << axis_name(axis);
    observers_ << "\n";
    energy_ << "t,kinetic,strain,total,momentum_x" << (Dim == 2 ? ",momentum_y" : "") << "\n";
  }

  /// Closes the CSV histories. \throws OutputFailure if either could not be written in full.
  void finish() {
    observers_.close();
    energy_.close();
  }

  void sample(long, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    observers_ << time;
    for (int p : observed_) {
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.position[p][axis];
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.velocity[p][axis];
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.stress[p](axis, axis);
      if (Dim == 2) observers_ << "," << particles.stress[p](0, Dim - 1);
    }
    for (int p : observed_)
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << particles.position[p][axis] - particles.reference_position[p][axis];
    observers_ << "\n";
    energy_ << time << "," << balances.kinetic << "," << balances.strain << "," << balances.total();
    for (int axis = 0; axis < Dim; ++axis) energy_ << "," << balances.momentum[axis];
    energy_ << "\n";
    observers_.check();
    energy_.check();
  }

  void snapshot(int index, double time, const Particles<Dim>& particles) override {
    char stem[32];
    std::snprintf(stem, sizeof stem, "/snapshot_%04d", index);
    write_csv(folder_ + stem + ".csv", particles);
    write_vtp(folder_ + stem + ".vtp", particles);
    collection_.add(time, std::string(stem + 1) + ".vtp");
  }

  void progress(double time, double end_time) override {
    if (!show_progress_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_progress_ < std::chrono::milliseconds(200) && time < end_time) return;
    last_progress_ = now;
    std::fprintf(stderr, "\r%s: t = %.4g s of %.4g s (%3.0f%%)%s", scene_.title.c_str(), time, end_time,
                 100.0 * time / end_time, time >= end_time ? "\n" : "");
  }

 private:
  void write_csv(const std::string& path, const Particles<Dim>& particles) const {
    OutputFile out(path, OutputFile::Mode::atomic);  // whole or absent, even when the disk fills
    out << "id";
    for (int axis = 0; axis < Dim; ++axis) out << "," << axis_name(axis);
    for (int axis = 0; axis < Dim; ++axis) out << ",v_" << axis_name(axis);
    for (int axis = 0; axis < Dim; ++axis) out << ",sigma_" << axis_name(axis) << axis_name(axis);
    if (Dim == 2) out << ",sigma_xy,sigma_zz";
    out << ",density\n";
    for (int p = 0; p < particles.size(); ++p) {
      out << particles.id[p];
      for (int axis = 0; axis < Dim; ++axis) out << "," << particles.position[p][axis];
      for (int axis = 0; axis < Dim; ++axis) out << "," << particles.velocity[p][axis];
      for (int axis = 0; axis < Dim; ++axis) out << "," << particles.stress[p](axis, axis);
      if (Dim == 2) out << "," << particles.stress[p](0, 1) << "," << particles.stress_zz[p];
      out << "," << particles.density[p] << "\n";
    }
    out.close();
  }

  std::string folder_;
  const Scene& scene_;
  std::vector<int> observed_;
  OutputFile observers_, energy_;
  PvdCollection collection_;
  bool show_progress_;
  std::chrono::steady_clock::time_point last_progress_{};
};

/// The particle an observer follows: the one nearest its material point at t = 0.
struct ObservedParticle {
  std::string name;
  int particle = 0;                       ///< the particle's id (snapshot_NNNN.csv's id)
  std::vector<double> reference_position;  ///< the particle's X (m); its current x is in observers.csv
};

/// Who wrote a run and what it followed: the program's version (git at build time, mpm/cli/version.cmake),
/// its command line, and the particle of each observer.
struct RunIdentity {
  std::string version = "unknown";
  std::vector<std::string> command_line;
  std::vector<ObservedParticle> observed;
};

/// The unit of every column of the CSV files a run writes (NAME: any observer's name), SI. Energies and
/// momentum are per unit cross-section area in 1D (the bar) and per unit thickness in 2D (plane strain).
inline std::vector<std::pair<std::string, std::string>> column_units(int dimension) {
  const bool two = dimension == 2;
  std::vector<std::pair<std::string, std::string>> units{
      {"observers.csv:t", "s"}, {"observers.csv:NAME.x", "m"}, {"observers.csv:NAME.v_x", "m/s"}, {"observers.csv:NAME.sigma_xx", "Pa"},
      {"observers.csv:NAME.u_x", "m"}};
  if (two)
    units.insert(units.end(), {{"observers.csv:NAME.y", "m"}, {"observers.csv:NAME.v_y", "m/s"}, {"observers.csv:NAME.sigma_yy", "Pa"},
                               {"observers.csv:NAME.sigma_xy", "Pa"}, {"observers.csv:NAME.u_y", "m"}});
  const std::string energy = two ? "J/m" : "J/m^2", momentum = two ? "kg/s" : "kg/(m s)";
  units.insert(units.end(), {{"energy.csv:t", "s"}, {"energy.csv:kinetic", energy}, {"energy.csv:strain", energy},
                             {"energy.csv:total", energy}, {"energy.csv:momentum_x", momentum}});
  if (two) units.push_back({"energy.csv:momentum_y", momentum});
  units.insert(units.end(), {{"exact.csv:t", "s"}, {"exact.csv:NAME.v_x", "m/s"}, {"exact.csv:NAME.sigma_xx", "Pa"}});
  if (two)
    units.insert(units.end(), {{"exact.csv:NAME.u_y", "m"}, {"exact.csv:NAME.v_y", "m/s"}, {"exact.csv:NAME.sigma_yy", "Pa"},
                               {"exact.csv:NAME.sigma_xy", "Pa"}});
  units.insert(units.end(), {{"snapshot_NNNN.csv:id", "-"}, {"snapshot_NNNN.csv:x", "m"}, {"snapshot_NNNN.csv:v_x", "m/s"},
                             {"snapshot_NNNN.csv:sigma_xx", "Pa"}});
  if (two)
    units.insert(units.end(), {{"snapshot_NNNN.csv:y", "m"}, {"snapshot_NNNN.csv:v_y", "m/s"}, {"snapshot_NNNN.csv:sigma_yy", "Pa"},
                               {"snapshot_NNNN.csv:sigma_xy", "Pa"}, {"snapshot_NNNN.csv:sigma_zz", "Pa"}});
  units.push_back({"snapshot_NNNN.csv:density", "kg/m^3"});
  return units;
}

/// The unit of every field of run.json but the scene (whose keys' units are "scene_units").
inline const std::vector<std::pair<std::string, std::string>>& run_json_units() {
  static const std::vector<std::pair<std::string, std::string>> units{
      {"status", "running | done | failed | interrupted"}, {"failure", "-"}, {"version", "-"}, {"command_line", "-"}, {"observed", "reference_position: m"}, {"particles", "-"}, {"steps", "-"}, {"final_time", "s"},
      {"smallest_time_step", "s"}, {"largest_time_step", "s"}, {"wall_seconds", "s"}, {"particle_steps_per_second", "1/s"},
      {"largest_mass_error", "- (relative)"}, {"neighbours_mean", "nodes"}, {"neighbours_max", "nodes"},
      {"newton_iterations_mean", "-"}, {"newton_iterations_max", "-"}, {"threads", "-"}, {"phase_seconds", "s"}};
  return units;
}

/// What run.json says of its run: written first as running, rewritten at the end as one of the others.
enum class RunState { running, done, failed, interrupted };

inline const char* run_state_name(RunState state) {
  switch (state) {
    case RunState::running: return "running";
    case RunState::done: return "done";
    case RunState::failed: return "failed";
    case RunState::interrupted: return "interrupted";
  }
  return "failed";
}

/// run.json's members of one kind (name, unit) as an object.
inline void write_units(JsonWriter& json, const std::vector<std::pair<std::string, std::string>>& units) {
  json.begin_object();
  for (const auto& [name, unit] : units) json.key(name).value(unit);
  json.end_object();
}

/// run.json's numbers: the summary of what the run did (zeros while it runs).
inline void write_summary(JsonWriter& json, const RunSummary& summary, int particle_count) {
  json.key("particles").value(particle_count).key("steps").value(summary.steps).key("final_time").value(summary.final_time);
  json.key("smallest_time_step").value(summary.smallest_time_step).key("largest_time_step").value(summary.largest_time_step);
  json.key("wall_seconds").value(summary.wall_seconds).key("particle_steps_per_second").value(summary.particle_steps_per_second);
  json.key("largest_mass_error").value(summary.largest_mass_error);
  json.key("neighbours_mean").value(summary.shape.neighbours_mean()).key("neighbours_max").value(summary.shape.neighbours_max());
  json.key("newton_iterations_mean").value(summary.shape.newton_iterations_mean());
  json.key("newton_iterations_max").value(summary.shape.newton_iterations_max());
  json.key("threads").value(summary.threads).key("phase_seconds").begin_object();
  for (int phase = 0; phase < phase_count; ++phase) json.key(phase_name(phase)).value(summary.phase_seconds[phase]);
  json.end_object();
}

/// run.json: the status (and the failure, or null), the version and command line, the resolved scene, the
/// run's numbers, and the unit of each (its fields, the scene's keys, the CSV files' columns). Written
/// atomically: a reader sees the previous run.json or this one whole. \throws OutputFailure.
inline void write_run_json(const std::string& path, const Scene& scene, const RunSummary& summary, RunState state,
                           const std::string& failure, int particle_count, const RunIdentity& identity = {}) {
  OutputFile out(path, OutputFile::Mode::atomic);
  JsonWriter json(out);
  json.begin_object().key("status").value(run_state_name(state)).key("failure");
  if (failure.empty()) json.raw("null");
  else json.value(failure);
  json.key("version").value(identity.version).key("command_line").array(identity.command_line).key("observed").begin_array();
  for (const ObservedParticle& observed : identity.observed) {
    json.begin_object().key("name").value(observed.name).key("particle").value(observed.particle);
    json.key("reference_position").array(observed.reference_position).end_object();
  }
  json.end_array().key("scene").raw(resolved_json(scene));
  write_summary(json, summary, particle_count);
  json.key("units");
  write_units(json, run_json_units());
  std::vector<std::pair<std::string, std::string>> scene_units;
  for (const SceneKey& key : scene_keys()) scene_units.emplace_back(key.key, key.unit);
  json.key("scene_units");
  write_units(json, scene_units);
  json.key("column_units");
  write_units(json, column_units(scene.dimension));
  json.end_object();
  out.close();
}

TEST_CASE("run.json: its status and failure, strings escaped, every field written has its unit") {
  const std::string path = (std::filesystem::temp_directory_path() / ("mpm_run_json_" + std::to_string(getpid()) + ".json")).string();
  Scene scene;
  scene.dimension = 2;
  RunSummary summary;
  summary.smallest_time_step = std::numeric_limits<double>::infinity();  // no step taken yet
  write_run_json(path, scene, summary, RunState::interrupted, "SIGTERM", 3,
                 {"1.2.3", {"mpm", "run", "it's \"here\""}, {{"A", 7, {0.5, 1.5}}}});
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path.c_str());
  CHECK(text.find("{\n  \"status\": \"interrupted\",\n  \"failure\": \"SIGTERM\",\n  \"version\": \"1.2.3\"") == 0);
  CHECK(text.find("\"smallest_time_step\": null") != std::string::npos);  // inf (no step yet) is not JSON
  CHECK(text.find("\"observed\": [{\"name\": \"A\", \"particle\": 7, \"reference_position\": [0.5, 1.5]}]") != std::string::npos);
  CHECK(text.find("\"command_line\": [\"mpm\", \"run\", \"it's \\\"here\\\"\"]") != std::string::npos);
  // every top-level field of run.json (a line `  "name": `) but the unit tables and the scene is in run_json_units
  std::istringstream lines(text);
  int fields = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  \"", 0) != 0) continue;
    const std::string name = line.substr(3, line.find('"', 3) - 3);
    if (name == "scene" || name == "units" || name == "scene_units" || name == "column_units") continue;
    ++fields;
    CAPTURE(name);
    CHECK(std::any_of(run_json_units().begin(), run_json_units().end(), [&](const auto& unit) { return unit.first == name; }));
  }
  CHECK(fields == static_cast<int>(run_json_units().size()));
  CHECK(text.find("\"energy.csv:kinetic\": \"J/m\"") != std::string::npos);  // 2D: per unit thickness
  CHECK(text.find("\"grid.length\": \"m\"") != std::string::npos);
}

}  // namespace mpm::io
