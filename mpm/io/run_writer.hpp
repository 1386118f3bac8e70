/// \file
/// What a run writes into its folder, every file through OutputFile (mpm/io/output_file.hpp): grid.csv (the grid
/// lines `mpm plot` draws), observers.csv and energy.csv at each sample, snapshot_NNNN.csv and .vtp (VTK XML
/// polydata, listed with its time in snapshots.pvd,
/// the time series ParaView opens) at each snapshot, and run.json (write_run_json).
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mpm/io/output_file.hpp"
#include "mpm/io/scene.hpp"
#include "mpm/io/scene_keys.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/stop_signals.hpp"
#include "mpm/run_control.hpp"

namespace mpm::io {

/// Writes a particle's state columns: position, velocity, diagonal stress (2D adds sigma_xy).
template <int Dim>
void write_state(std::ostream& out, const Particles<Dim>& particles, int p) {
  for (int axis = 0; axis < Dim; ++axis) out << "," << particles.position[p][axis];
  for (int axis = 0; axis < Dim; ++axis) out << "," << particles.velocity[p][axis];
  for (int axis = 0; axis < Dim; ++axis) out << "," << particles.stress[p](axis, axis);
  if (Dim == 2) out << "," << particles.stress[p](0, 1);
}

/// The names of write_state's columns, each after `prefix` ("NAME." in observers.csv).
template <int Dim>
void write_state_names(std::ostream& out, const std::string& prefix) {
  for (int axis = 0; axis < Dim; ++axis) out << "," << prefix << axis_name(axis);
  for (int axis = 0; axis < Dim; ++axis) out << "," << prefix << "v_" << axis_name(axis);
  for (int axis = 0; axis < Dim; ++axis) out << "," << prefix << "sigma_" << axis_name(axis) << axis_name(axis);
  if (Dim == 2) out << "," << prefix << "sigma_xy";
}

/// Writes every particle as a vertex of a VTK XML PolyData file (ASCII) with its velocity, stress (3x3, plane
/// strain sigma_zz included), density and id. \throws OutputFailure.
template <int Dim>
void write_vtp(const std::string& path, const Particles<Dim>& particles) {
  OutputFile out(path, OutputFile::Mode::atomic);
  const int count = particles.size();
  const auto vector3 = [&](const auto& v) { out << v[0] << " " << (Dim == 2 ? v[Dim - 1] : 0.0) << " 0\n"; };
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << count << "\" NumberOfVerts=\"" << count
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "<PointData Vectors=\"velocity\" Tensors=\"stress\" Scalars=\"density\">\n"
      << "<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) vector3(particles.velocity[p]);
  out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"9\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) {
    const auto& s = particles.stress[p];
    const double xy = Dim == 2 ? s(0, Dim - 1) : 0.0, yy = Dim == 2 ? s(Dim - 1, Dim - 1) : 0.0;
    out << s(0, 0) << " " << xy << " 0 " << xy << " " << yy << " 0 0 0 " << particles.stress_zz[p] << "\n";
  }
  out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"density\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << particles.density[p] << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"id\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << particles.id[p] << "\n";
  out << "</DataArray>\n</PointData>\n<Points>\n"
      << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) vector3(particles.position[p]);
  out << "</DataArray>\n</Points>\n<Verts>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << p << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (int p = 0; p < count; ++p) out << p + 1 << "\n";
  out << "</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  out.close();
}

/// The run's writer: the CSV histories, the snapshots and their collection, progress on a terminal, and the end
/// of the run between two steps after a stop signal (Interrupted).
template <int Dim>
class RunWriter : public Monitor<Dim> {
 public:
  RunWriter(const std::string& folder, const Scene& scene, std::vector<int> observed)
      : folder_(folder), scene_(scene), observed_(std::move(observed)), observers_(folder + "/observers.csv"),
        energy_(folder + "/energy.csv"), show_progress_(isatty(fileno(stderr))) {
    observers_ << "t";
    for (const auto& observer : scene.observers) write_state_names<Dim>(observers_, observer.name + ".");
    for (const auto& observer : scene.observers)  // last, so that the columns before keep their numbers
      for (int axis = 0; axis < Dim; ++axis) observers_ << "," << observer.name << ".u_" << axis_name(axis);
    observers_ << "\n";
    energy_ << "t,kinetic,strain,total,momentum_x" << (Dim == 2 ? ",momentum_y" : "") << "\n";
    snapshots_.precision(17);
    write_file(folder + "/grid.csv", grid_csv(scene));
  }

  /// grid.csv, what `mpm plot` draws the grid lines from: per axis the first and last grid line (m, margins
  /// included) and the cells between them, `x_min,x_max,x_cells[,y_min,y_max,y_cells]`, one row.
  static std::string grid_csv(const Scene& scene) {
    std::ostringstream header, row;
    row.precision(17);
    for (int axis = 0; axis < Dim; ++axis) {
      const std::string name = axis_name(axis);
      header << (axis ? "," : "") << name << "_min," << name << "_max," << name << "_cells";
      row << (axis ? "," : "") << scene.origin[axis] - scene.margin_min[axis] * scene.spacing << ","
          << scene.origin[axis] + scene.length[axis] + scene.margin_max[axis] * scene.spacing << ","
          << scene.margin_min[axis] + scene.cells[axis] + scene.margin_max[axis];
    }
    return header.str() + "\n" + row.str() + "\n";
  }

  /// Closes the CSV histories. \throws OutputFailure if either could not be written in full.
  void finish() {
    observers_.close();
    energy_.close();
  }

  /// A row of observers.csv (each observer's state, then its displacement x_p - X_p) and of energy.csv.
  void sample(long, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    observers_ << time;
    for (int p : observed_) write_state(observers_, particles, p);
    for (int p : observed_)
      for (int axis = 0; axis < Dim; ++axis)
        observers_ << "," << particles.position[p][axis] - particles.reference_position[p][axis];
    observers_ << "\n";
    energy_ << time << "," << balances.kinetic << "," << balances.strain << "," << balances.total();
    for (int axis = 0; axis < Dim; ++axis) energy_ << "," << balances.momentum[axis];
    energy_ << "\n";
    observers_.check();
    energy_.check();
  }

  /// snapshot_NNNN.csv and .vtp, each whole or absent, and snapshots.pvd rewritten to list them all.
  void snapshot(int index, double time, const Particles<Dim>& particles) override {
    char name[32];
    std::snprintf(name, sizeof name, "snapshot_%04d", index);
    OutputFile csv(folder_ + "/" + name + ".csv", OutputFile::Mode::atomic);
    csv << "id";
    write_state_names<Dim>(csv, "");
    csv << (Dim == 2 ? ",sigma_zz" : "") << ",density\n";
    for (int p = 0; p < particles.size(); ++p) {
      csv << particles.id[p];
      write_state(csv, particles, p);
      if (Dim == 2) csv << "," << particles.stress_zz[p];
      csv << "," << particles.density[p] << "\n";
    }
    csv.close();
    write_vtp(folder_ + "/" + name + ".vtp", particles);
    snapshots_ << "  <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << name << ".vtp\"/>\n";
    write_file(folder_ + "/snapshots.pvd",
               "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<Collection>\n" + snapshots_.str() + "</Collection>\n</VTKFile>\n");
  }

  /// Shows progress on a terminal (at most 5 times a second); \throws Interrupted after a stop signal.
  void progress(double time, double end_time) override {
    const auto now = show_progress_ ? std::chrono::steady_clock::now() : last_progress_;
    if (show_progress_ && (now - last_progress_ >= std::chrono::milliseconds(200) || time >= end_time)) {
      last_progress_ = now;
      std::fprintf(stderr, "\r%s: t = %.4g s of %.4g s (%3.0f%%)%s", scene_.title.c_str(), time, end_time,
                   100.0 * time / end_time, time >= end_time ? "\n" : "");
    }
    stop_if_signalled();
  }

 private:
  std::string folder_;
  const Scene& scene_;
  std::vector<int> observed_;
  OutputFile observers_, energy_;
  std::ostringstream snapshots_;  ///< the DataSet lines of snapshots.pvd
  bool show_progress_;
  std::chrono::steady_clock::time_point last_progress_{};
};

/// `text` as a JSON string, quoted and escaped; a byte that is not UTF-8 (a path's 0xff) as U+FFFD.
inline std::string json_string(const std::string& text) {
  std::string json = "\"";
  const auto byte = [&](std::size_t at) { return at < text.size() ? static_cast<unsigned char>(text[at]) : 0; };
  for (std::size_t at = 0; at < text.size(); ++at) {
    const unsigned char lead = byte(at);
    std::size_t length = lead < 0x80 ? 1 : lead < 0xc2 ? 0 : lead < 0xe0 ? 2 : lead < 0xf0 ? 3 : lead <= 0xf4 ? 4 : 0;
    for (std::size_t k = 1; k < length; ++k)
      if (byte(at + k) >> 6 != 0x2) length = 0;
    if (length > 1) {
      json.append(text, at, length);
      at += length - 1;
    } else if (length == 0) json += "\\ufffd";
    else if (lead == '"' || lead == '\\') json += std::string("\\") + static_cast<char>(lead);
    else if (lead == '\n') json += "\\n";
    else if (lead < 0x20 || lead == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", lead);
      json += escaped;
    } else json += static_cast<char>(lead);
  }
  return json + "\"";
}

/// A number as JSON: 12 significant digits (the run's CSV files' precision); null if not finite.
inline std::string json_number(double number) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", number);
  return std::isfinite(number) ? text : "null";
}

/// `values` as a JSON array on one line, each written by `to_json`.
template <class T, class ToJson>
std::string json_array(const std::vector<T>& values, ToJson to_json) {
  std::string json = "[";
  for (const T& value : values) json += (json.size() > 1 ? ", " : "") + to_json(value);
  return json + "]";
}

/// Members (name, a value already JSON) as a JSON object: on one line, or (top) one member a line.
inline std::string json_object(const std::vector<std::pair<std::string, std::string>>& members, bool top = false) {
  std::string json = "{", separator = top ? "\n  " : "";
  for (const auto& [name, value] : members) {
    json += separator + json_string(name) + ": " + value;
    separator = top ? ",\n  " : ", ";
  }
  return json + (top ? "\n}\n" : "}");
}

/// Pairs of names and units as a JSON object of strings.
inline std::string json_units(const std::vector<std::pair<std::string, std::string>>& units) {
  std::vector<std::pair<std::string, std::string>> members;
  for (const auto& [name, unit] : units) members.emplace_back(name, json_string(unit));
  return json_object(members);
}

/// The particle an observer follows: the one nearest its material point at t = 0.
struct ObservedParticle {
  std::string name;
  int particle = 0;                        ///< the particle's id (snapshot_NNNN.csv's id)
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
  const std::string energy = two ? "J/m" : "J/m^2", momentum = two ? "kg/s" : "kg/(m s)";
  std::vector<std::pair<std::string, std::string>> units{
      {"observers.csv:t", "s"}, {"observers.csv:NAME.x", "m"}, {"observers.csv:NAME.v_x", "m/s"},
      {"observers.csv:NAME.sigma_xx", "Pa"}, {"observers.csv:NAME.u_x", "m"}};
  if (two)
    units.insert(units.end(), {{"observers.csv:NAME.y", "m"}, {"observers.csv:NAME.v_y", "m/s"},
                               {"observers.csv:NAME.sigma_yy", "Pa"}, {"observers.csv:NAME.sigma_xy", "Pa"},
                               {"observers.csv:NAME.u_y", "m"}});
  units.insert(units.end(), {{"energy.csv:t", "s"}, {"energy.csv:kinetic", energy}, {"energy.csv:strain", energy},
                             {"energy.csv:total", energy}, {"energy.csv:momentum_x", momentum}});
  if (two) units.push_back({"energy.csv:momentum_y", momentum});
  units.insert(units.end(), {{"exact.csv:t", "s"}, {"exact.csv:NAME.v_x", "m/s"}, {"exact.csv:NAME.sigma_xx", "Pa"}});
  units.insert(units.end(), {{"exact_NNNN.csv:id", "-"}, {"exact_NNNN.csv:X", "m"}, {"exact_NNNN.csv:u_x", "m"},
                             {"exact_NNNN.csv:v_x", "m/s"}, {"exact_NNNN.csv:sigma_xx", "Pa"},
                             {"grid.csv:x_min", "m"}, {"grid.csv:x_max", "m"}, {"grid.csv:x_cells", "-"}});
  if (two)
    units.insert(units.end(), {{"exact_NNNN.csv:Y", "m"}, {"exact_NNNN.csv:u_y", "m"}, {"exact_NNNN.csv:v_y", "m/s"},
                               {"exact_NNNN.csv:sigma_yy", "Pa"}, {"exact_NNNN.csv:sigma_xy", "Pa"},
                               {"grid.csv:y_min", "m"}, {"grid.csv:y_max", "m"}, {"grid.csv:y_cells", "-"}});
  if (two)
    units.insert(units.end(), {{"exact.csv:NAME.u_y", "m"}, {"exact.csv:NAME.v_y", "m/s"},
                               {"exact.csv:NAME.sigma_yy", "Pa"}, {"exact.csv:NAME.sigma_xy", "Pa"}});
  units.insert(units.end(), {{"snapshot_NNNN.csv:id", "-"}, {"snapshot_NNNN.csv:x", "m"},
                             {"snapshot_NNNN.csv:v_x", "m/s"}, {"snapshot_NNNN.csv:sigma_xx", "Pa"}});
  if (two)
    units.insert(units.end(), {{"snapshot_NNNN.csv:y", "m"}, {"snapshot_NNNN.csv:v_y", "m/s"},
                               {"snapshot_NNNN.csv:sigma_yy", "Pa"}, {"snapshot_NNNN.csv:sigma_xy", "Pa"},
                               {"snapshot_NNNN.csv:sigma_zz", "Pa"}});
  units.push_back({"snapshot_NNNN.csv:density", "kg/m^3"});
  return units;
}

/// What run.json says of its run: clearing while an earlier run's files are removed, then running, rewritten at the
/// end as done, failed or interrupted. A folder whose process was killed outright keeps clearing or running.
enum class RunState { clearing, running, done, failed, interrupted };

/// run.json: the status (and the failure, or null), the version and command line, the resolved scene, the run's
/// numbers (zeros while it runs), and the unit of each. Written atomically. \throws OutputFailure.
inline void write_run_json(const std::string& path, const Scene& scene, const RunSummary& summary, RunState state,
                           const std::string& failure, int particle_count, const RunIdentity& identity = {}) {
  const char* states[] = {"clearing", "running", "done", "failed", "interrupted"};
  const auto observed = json_array(identity.observed, [](const ObservedParticle& observed) {
    return json_object({{"name", json_string(observed.name)}, {"particle", std::to_string(observed.particle)},
                        {"reference_position", json_array(observed.reference_position, json_number)}});
  });
  std::vector<std::pair<std::string, std::string>> phases, scene_units, members, units;
  for (int part = 0; part < timed_part_count; ++part)
    phases.emplace_back(timed_part_name(part), json_number(summary.phase_seconds[part]));
  for (const SceneKey& key : scene_keys()) scene_units.emplace_back(key.key, key.unit);
  const ShapeDiagnostics& shape = summary.shape;
  struct Field {
    std::string name, unit, json;  ///< unit "": none (the scene's are in scene_units)
  };
  for (const Field& field : std::vector<Field>{
           {"status", "clearing | running | done | failed | interrupted", json_string(states[static_cast<int>(state)])},
           {"failure", "-", failure.empty() ? "null" : json_string(failure)},
           {"version", "-", json_string(identity.version)},
           {"command_line", "-", json_array(identity.command_line, json_string)},
           {"observed", "reference_position: m", observed},
           {"scene", "", resolved_json(scene)},
           {"particles", "-", std::to_string(particle_count)},
           {"steps", "-", std::to_string(summary.steps)},
           {"final_time", "s", json_number(summary.final_time)},
           {"smallest_time_step", "s", json_number(summary.smallest_time_step)},
           {"largest_time_step", "s", json_number(summary.largest_time_step)},
           {"wall_seconds", "s", json_number(summary.wall_seconds)},
           {"particle_steps_per_second", "1/s", json_number(summary.particle_steps_per_second)},
           {"largest_mass_error", "- (relative)", json_number(summary.largest_mass_error)},
           {"neighbours_mean", "nodes", json_number(shape.neighbours_mean())},
           {"neighbours_max", "nodes", std::to_string(shape.neighbours_max())},
           {"newton_iterations_mean", "-", json_number(shape.newton_iterations_mean())},
           {"newton_iterations_max", "-", std::to_string(shape.newton_iterations_max())},
           {"threads", "-", std::to_string(summary.threads)},
           {"phase_seconds", "s", json_object(phases)}}) {
    members.emplace_back(field.name, field.json);
    if (!field.unit.empty()) units.emplace_back(field.name, field.unit);
  }
  members.insert(members.end(), {{"units", json_units(units)}, {"scene_units", json_units(scene_units)},
                                 {"column_units", json_units(column_units(scene.dimension))}});
  write_file(path, json_object(members, true));
}

TEST_CASE("run.json: its status and failure, strings escaped, every field written has its unit") {
  CHECK(json_string("failed: \"x\"\n\\\t") == "\"failed: \\\"x\\\"\\n\\\\\\u0009\"");
  CHECK(json_string("jl\xff") == "\"jl\\ufffd\"");                 // not UTF-8
  CHECK(json_string("\xc3\xa9t\xc3") == "\"\xc3\xa9t\\ufffd\"");  // kept, and a sequence cut short
  const auto path = (std::filesystem::temp_directory_path() / ("mpm_run_json_" + std::to_string(getpid()))).string();
  Scene scene;
  scene.dimension = 2;
  RunSummary summary;
  summary.smallest_time_step = std::numeric_limits<double>::infinity();  // no step taken yet
  write_run_json(path, scene, summary, RunState::interrupted, "SIGTERM", 3,
                 {"1.2.3", {"mpm", "run", "it's \"here\""}, {{"A", 7, {0.5, 1e-300}}}});
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path.c_str());
  CHECK(text.find("{\n  \"status\": \"interrupted\",\n  \"failure\": \"SIGTERM\",\n  \"version\": \"1.2.3\"") == 0);
  CHECK(text.find("\"smallest_time_step\": null") != std::string::npos);  // inf (no step yet) is not JSON
  CHECK(text.find("\"observed\": [{\"name\": \"A\", \"particle\": 7, \"reference_position\": [0.5, 1e-300]}]") !=
        std::string::npos);
  CHECK(text.find("\"command_line\": [\"mpm\", \"run\", \"it's \\\"here\\\"\"]") != std::string::npos);
  CHECK(text.find("\"phase_seconds\": {\"") != std::string::npos);
  CHECK(text.rfind("\n}\n") == text.size() - 3);
  CHECK(text.find("\"units\": {\"status\": \"clearing | running | done | failed | interrupted\", \"failure\": \"-\"") !=
        std::string::npos);
  CHECK(text.find("\"energy.csv:kinetic\": \"J/m\"") != std::string::npos);  // 2D: per unit thickness
  CHECK(text.find("\"grid.length\": \"m\"") != std::string::npos);
}

}  // namespace mpm::io
