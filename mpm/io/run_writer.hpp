/// \file
/// Writes what a run produces into its output folder:
///   observers.csv        t, then per observer NAME.x, NAME.v_x, NAME.sigma_xx (2D adds y components), then
///                        per observer its displacement since t = 0, NAME.u_x (2D: NAME.u_y), x_p - X_p
///   energy.csv           t,kinetic,strain,total,momentum_x (2D adds momentum_y)
///   snapshot_NNNN.csv    every particle: id, position, velocity, stress, density
///   snapshot_NNNN.vtk    the same as legacy VTK polydata
///   snapshot_NNNN.vtp    the same as VTK XML polydata, listed with its time in
///   snapshots.pvd        the collection ParaView opens as a time series (mpm/io/vtk_collection.hpp)
/// and shows progress on stderr when stderr is a terminal. Every stream is checked: a file that
/// cannot be opened or written (no permission, disk full) raises OutputFailure naming it.
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mpm/io/scene.hpp"
#include "mpm/io/scene_keys.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/vtk_collection.hpp"
#include "mpm/simulation.hpp"

namespace mpm::io {

/// \throws OutputFailure if `out` failed (opening, writing or flushing `path`).
inline void check_written(const std::ostream& out, const std::string& path) {
  if (!out) throw OutputFailure(path, errno != 0 ? std::strerror(errno) : "the stream failed");
}

/// Flushes and closes `out`, then checks it: a full disk shows only when the buffer is written.
inline void close_checked(std::ofstream& out, const std::string& path) {
  if (out.is_open()) out.close();
  check_written(out, path);
}

template <int Dim>
class RunWriter : public Monitor<Dim> {
 public:
  RunWriter(const std::string& folder, const Scene& scene, std::vector<int> observed)
      : folder_(folder), scene_(scene), observed_(std::move(observed)),
        observers_(folder + "/observers.csv"), energy_(folder + "/energy.csv"), collection_(folder + "/snapshots.pvd"),
        show_progress_(isatty(fileno(stderr))) {
    observers_ << std::setprecision(12) << "t";
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
    energy_ << std::setprecision(12) << "t,kinetic,strain,total,momentum_x" << (Dim == 2 ? ",momentum_y" : "") << "\n";
    for (auto [stream, name] : {std::pair{&observers_, "/observers.csv"}, {&energy_, "/energy.csv"}}) {
      if (!*stream) errno = 0, stream->clear(), stream->open(folder_ + name);  // again, for the reason in errno
      check_written(*stream, folder_ + name);
    }
  }

  /// Closes the CSV histories. \throws OutputFailure if either could not be written in full.
  void finish() {
    close_checked(observers_, folder_ + "/observers.csv");
    close_checked(energy_, folder_ + "/energy.csv");
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
    check_written(observers_, folder_ + "/observers.csv");
    check_written(energy_, folder_ + "/energy.csv");
  }

  void snapshot(int index, double time, const Particles<Dim>& particles) override {
    char stem[32];
    std::snprintf(stem, sizeof stem, "/snapshot_%04d", index);
    write_csv(folder_ + stem + ".csv", particles);
    write_vtk(folder_ + stem + ".vtk", time, particles);
    if (!write_vtp(folder_ + stem + ".vtp", particles))
      throw OutputFailure(folder_ + stem + ".vtp", errno != 0 ? std::strerror(errno) : "the stream failed");
    if (!collection_.add(time, std::string(stem + 1) + ".vtp"))
      throw OutputFailure(folder_ + "/snapshots.pvd", errno != 0 ? std::strerror(errno) : "the stream failed");
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
    std::ofstream out(path);
    out << std::setprecision(12) << "id";
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
    close_checked(out, path);
  }

  void write_vtk(const std::string& path, double time, const Particles<Dim>& particles) const {
    std::ofstream out(path);
    const int count = particles.size();
    out << std::setprecision(12) << "# vtk DataFile Version 3.0\n" << scene_.title << " t = " << time
        << "\nASCII\nDATASET POLYDATA\nPOINTS " << count << " double\n";
    for (int p = 0; p < count; ++p) {
      const auto& x = particles.position[p];
      out << x[0] << " " << (Dim == 2 ? x[Dim - 1] : 0.0) << " 0\n";
    }
    out << "VERTICES " << count << " " << 2 * count << "\n";
    for (int p = 0; p < count; ++p) out << "1 " << p << "\n";
    out << "POINT_DATA " << count << "\nVECTORS velocity double\n";
    for (int p = 0; p < count; ++p) {
      const auto& v = particles.velocity[p];
      out << v[0] << " " << (Dim == 2 ? v[Dim - 1] : 0.0) << " 0\n";
    }
    out << "TENSORS stress double\n";
    for (int p = 0; p < count; ++p) {
      const auto& s = particles.stress[p];
      const double xy = Dim == 2 ? s(0, Dim - 1) : 0.0, yy = Dim == 2 ? s(Dim - 1, Dim - 1) : 0.0;
      out << s(0, 0) << " " << xy << " 0\n" << xy << " " << yy << " 0\n0 0 " << particles.stress_zz[p] << "\n";
    }
    out << "SCALARS density double 1\nLOOKUP_TABLE default\n";
    for (int p = 0; p < count; ++p) out << particles.density[p] << "\n";
    out << "SCALARS id int 1\nLOOKUP_TABLE default\n";
    for (int p = 0; p < count; ++p) out << particles.id[p] << "\n";
    close_checked(out, path);
  }

  std::string folder_;
  const Scene& scene_;
  std::vector<int> observed_;
  std::ofstream observers_, energy_;
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

/// `text` as a JSON string, quoted and escaped.
inline std::string json_string(const std::string& text) {
  std::string json = "\"";
  for (unsigned char character : text) {
    if (character == '"' || character == '\\') json += std::string("\\") + static_cast<char>(character);
    else if (character == '\n') json += "\\n";
    else if (character < 0x20 || character == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", character);
      json += escaped;
    } else json += static_cast<char>(character);
  }
  return json + "\"";
}

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
      {"status", "-"}, {"version", "-"}, {"command_line", "-"}, {"observed", "reference_position: m"}, {"particles", "-"}, {"steps", "-"}, {"final_time", "s"},
      {"smallest_time_step", "s"}, {"largest_time_step", "s"}, {"wall_seconds", "s"}, {"particle_steps_per_second", "1/s"},
      {"largest_mass_error", "- (relative)"}, {"neighbours_mean", "nodes"}, {"neighbours_max", "nodes"},
      {"newton_iterations_mean", "-"}, {"newton_iterations_max", "-"}, {"threads", "-"}, {"phase_seconds", "s"}};
  return units;
}

/// run.json: the version and command line, the resolved scene, the run's numbers, and the unit of each
/// (its fields, the scene's keys, the CSV files' columns). \throws OutputFailure if it cannot be written.
inline void write_run_json(const std::string& path, const Scene& scene, const RunSummary& summary,
                           const std::string& status, int particle_count, const RunIdentity& identity = {}) {
  std::ofstream out(path);
  out << std::setprecision(12) << "{\n"
      << "  \"status\": " << json_string(status) << ",\n"
      << "  \"version\": " << json_string(identity.version) << ",\n"
      << "  \"command_line\": [";
  for (size_t k = 0; k < identity.command_line.size(); ++k) out << (k ? ", " : "") << json_string(identity.command_line[k]);
  out << "],\n  \"observed\": [";
  for (size_t k = 0; k < identity.observed.size(); ++k) {
    const ObservedParticle& observed = identity.observed[k];
    out << (k ? ", " : "") << "{\"name\": " << json_string(observed.name) << ", \"particle\": " << observed.particle
        << ", \"reference_position\": [";
    for (size_t axis = 0; axis < observed.reference_position.size(); ++axis) out << (axis ? ", " : "") << observed.reference_position[axis];
    out << "]}";
  }
  out << "],\n"
      << "  \"scene\": " << resolved_json(scene) << ",\n"
      << "  \"particles\": " << particle_count << ",\n"
      << "  \"steps\": " << summary.steps << ",\n"
      << "  \"final_time\": " << summary.final_time << ",\n"
      << "  \"smallest_time_step\": " << summary.smallest_time_step << ",\n"
      << "  \"largest_time_step\": " << summary.largest_time_step << ",\n"
      << "  \"wall_seconds\": " << summary.wall_seconds << ",\n"
      << "  \"particle_steps_per_second\": " << summary.particle_steps_per_second << ",\n"
      << "  \"largest_mass_error\": " << summary.largest_mass_error << ",\n"
      << "  \"neighbours_mean\": " << summary.shape.neighbours_mean() << ",\n"
      << "  \"neighbours_max\": " << summary.shape.neighbours_max() << ",\n"
      << "  \"newton_iterations_mean\": " << summary.shape.newton_iterations_mean() << ",\n"
      << "  \"newton_iterations_max\": " << summary.shape.newton_iterations_max() << ",\n"
      << "  \"threads\": " << summary.threads << ",\n"
      << "  \"phase_seconds\": {";
  for (int phase = 0; phase < phase_count; ++phase)
    out << (phase ? ", " : "") << "\"" << phase_name(phase) << "\": " << summary.phase_seconds[phase];
  out << "},\n  \"units\": {";
  for (size_t k = 0; k < run_json_units().size(); ++k)
    out << (k ? ", " : "") << json_string(run_json_units()[k].first) << ": " << json_string(run_json_units()[k].second);
  out << "},\n  \"scene_units\": {";
  for (size_t k = 0; k < scene_keys().size(); ++k)
    out << (k ? ", " : "") << json_string(scene_keys()[k].key) << ": " << json_string(scene_keys()[k].unit);
  out << "},\n  \"column_units\": {";
  const auto columns = column_units(scene.dimension);
  for (size_t k = 0; k < columns.size(); ++k) out << (k ? ", " : "") << json_string(columns[k].first) << ": " << json_string(columns[k].second);
  out << "}\n"
      << "}\n";
  close_checked(out, path);
}

TEST_CASE("run.json: strings escaped, every field written has its unit") {
  CHECK(json_string("failed: \"x\"\n\\") == "\"failed: \\\"x\\\"\\n\\\\\"");
  CHECK(json_string(std::string("a\tb")) == "\"a\\u0009b\"");
  const std::string path = (std::filesystem::temp_directory_path() / ("mpm_run_json_" + std::to_string(getpid()) + ".json")).string();
  Scene scene;
  scene.dimension = 2;
  write_run_json(path, scene, RunSummary{}, "done", 3, {"1.2.3", {"mpm", "run", "it's \"here\""}, {{"A", 7, {0.5, 1.5}}}});
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path.c_str());
  CHECK(text.find("\"version\": \"1.2.3\"") != std::string::npos);
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
