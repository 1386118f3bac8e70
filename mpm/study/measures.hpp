/// \file
/// What a study measures of one finished run, from the files the run wrote (run.json, observers.csv,
/// energy.csv), as a user could: the status and failure, the steps, the observer's reference position, the
/// relative drift of the total energy, and the observer's velocity moved to the time it approximates.
///
/// Which time a velocity belongs to (paper/10_integrator_analysis.md): forward Euler's velocity written at t
/// approximates v(t + dt/2); the predictor-corrector's Eq. (32) (solver.npc_velocity = "eq32") approximates v(t);
/// the Newmark average ("average") v(t + (gamma - 1/2) dt), gamma = solver.newmark_gamma. dt is the step that
/// follows the row: t_{k+1} - t_k when the run wrote every step (the last row takes the step before it), else
/// the mean step final_time / steps of run.json.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/csv_file.hpp"
#include "mpm/io/output_file.hpp"
#include "mpm/io/scene_file.hpp"

namespace mpm::study {

/// The text after `"KEY": ` in `json` (run.json as mpm writes it: one key per line at the top level), or npos.
inline std::size_t json_value_at(const std::string& json, const std::string& key) {
  const std::string marker = "\"" + key + "\": ";
  const std::size_t at = json.find(marker);
  return at == std::string::npos ? at : at + marker.size();
}

/// A string field of run.json (its escapes \" \\ \n read back); nullopt if absent or null.
inline std::optional<std::string> json_string(const std::string& json, const std::string& key) {
  std::size_t at = json_value_at(json, key);
  if (at == std::string::npos || at >= json.size() || json[at] != '"') return std::nullopt;
  std::string text;
  for (++at; at < json.size() && json[at] != '"'; ++at) {
    if (json[at] == '\\' && at + 1 < json.size()) ++at, text += json[at] == 'n' ? '\n' : json[at] == 't' ? '\t' : json[at];
    else text += json[at];
  }
  return text;
}

/// A number field of run.json; nullopt if absent or not a number (null).
inline std::optional<double> json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json_value_at(json, key);
  if (at == std::string::npos) return std::nullopt;
  const char* start = json.c_str() + at;
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  return end == start || !std::isfinite(value) ? std::nullopt : std::optional<double>(value);
}

/// The reference position of observer `name` in run.json's "observed" list; empty if it is not there.
inline std::vector<double> observer_reference(const std::string& json, const std::string& name) {
  const std::size_t entry = json.find("{\"name\": \"" + name + "\",");
  const std::size_t open = entry == std::string::npos ? entry : json.find("\"reference_position\": [", entry);
  std::vector<double> position;
  if (open == std::string::npos) return position;
  std::istringstream numbers(json.substr(open + 23, json.find(']', open) - open - 23));
  for (std::string field; std::getline(numbers, field, ',');) position.push_back(std::strtod(field.c_str(), nullptr));
  return position;
}

/// The columns `wanted` of the CSV file `path`, one vector each; empty with `error` set if one is missing or a
/// field is not a finite number.
inline std::vector<std::vector<double>> read_columns(const std::string& path, const std::vector<std::string>& wanted, std::string& error) {
  io::CsvFile file(path);
  if (!file.read_header()) return error = file.error().empty() ? path + ": empty" : file.error(), std::vector<std::vector<double>>{};
  std::vector<std::size_t> index;
  for (const auto& name : wanted) {
    const auto found = std::find(file.header().begin(), file.header().end(), name);
    if (found == file.header().end()) return error = path + ": no column " + name, std::vector<std::vector<double>>{};
    index.push_back(static_cast<std::size_t>(found - file.header().begin()));
  }
  std::vector<std::vector<double>> columns(wanted.size());
  for (std::vector<std::string> fields; file.next_row(fields);)
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      double value = 0.0;
      if (!io::read_finite_number(fields[index[k]], value).empty())
        return error = file.where() + wanted[k] + ": not a finite number", std::vector<std::vector<double>>{};
      columns[k].push_back(value);
    }
  if (!file.error().empty()) return error = file.error(), std::vector<std::vector<double>>{};
  return columns;
}

/// The relative drift of the total energy in energy.csv, (E_last - E_first) / |E_first| (/ the largest |E| when
/// the run starts without energy, as under ramped gravity); nullopt with `error` set if it cannot be read.
inline std::optional<double> energy_drift(const std::string& path, std::string& error) {
  const auto columns = read_columns(path, {"total"}, error);
  if (columns.empty() || columns[0].empty()) return std::nullopt;
  const auto& total = columns[0];
  double scale = std::abs(total.front());
  if (scale == 0.0)
    for (double energy : total) scale = std::max(scale, std::abs(energy));
  return scale > 0.0 ? std::optional<double>((total.back() - total.front()) / scale) : std::optional<double>(0.0);
}

/// The fraction of dt by which the velocity of the resolved scene's integrator is shifted: 1/2 for forward Euler,
/// 0 for Eq. (32), gamma - 1/2 for the Newmark average.
inline double velocity_time_shift(const toml::table& resolved) {
  const std::string integrator = resolved["solver"]["integrator"].value_or(std::string("fe"));
  if (integrator == "fe") return 0.5;
  if (resolved["solver"]["npc_velocity"].value_or(std::string("eq32")) == "average")
    return resolved["solver"]["newmark_gamma"].value_or(0.5) - 0.5;
  return 0.0;
}

/// Writes `shifted` (a CSV `t,NAME.v_x[,NAME.v_y]`): the observer's velocities of `observers` at t + fraction dt,
/// dt as the file's comment says. False with `error` set if observers.csv cannot be read. \throws OutputFailure.
inline bool write_shifted(const std::string& observers, const std::string& shifted, const std::vector<std::string>& columns,
                          double fraction, double steps, double final_time, std::string& error) {
  std::vector<std::string> wanted{"t"};
  wanted.insert(wanted.end(), columns.begin(), columns.end());
  const auto values = read_columns(observers, wanted, error);
  if (values.empty()) return false;
  const auto& t = values[0];
  const bool every_step = steps > 0 && t.size() == static_cast<std::size_t>(steps) + 1;
  io::OutputFile out(shifted, io::OutputFile::Mode::atomic);
  out.precision(15);
  out << "t";
  for (const auto& column : columns) out << "," << column;
  out << "\n";
  for (std::size_t n = 0; n < t.size(); ++n) {
    double dt = steps > 0 ? final_time / steps : 0.0;
    if (every_step && t.size() > 1) dt = n + 1 < t.size() ? t[n + 1] - t[n] : t[n] - t[n - 1];
    out << t[n] + fraction * dt;
    for (std::size_t k = 1; k < values.size(); ++k) out << "," << values[k][n];
    out << "\n";
  }
  out.close();
  return true;
}

/// The score `mpm compare` printed (`column,quantity,samples,rms,rms_normalised,...`, one row per velocity
/// component): the rms_normalised of the velocity vector, sqrt of the sum of the components' squares; nullopt
/// if none can be read.
inline std::optional<double> compare_score(const std::string& printed) {
  std::istringstream lines(printed);
  std::string line;
  std::getline(lines, line);
  double sum = 0.0;
  int rows = 0;
  while (std::getline(lines, line)) {
    const auto fields = io::csv_fields(line);
    double value = 0.0;
    if (fields.size() < 5 || !io::read_finite_number(fields[4], value).empty()) return std::nullopt;
    sum += value * value, ++rows;
  }
  return rows ? std::optional<double>(std::sqrt(sum)) : std::nullopt;
}

TEST_CASE("study measures: run.json's fields, the energy drift, the velocity at the time it approximates") {
  const std::string json = "{\n  \"status\": \"failed\",\n  \"failure\": \"unstable: energy \\\"grew\\\"\",\n  \"steps\": 152,\n"
                           "  \"observed\": [{\"name\": \"A\", \"particle\": 0, \"reference_position\": [0.5, 0.25]}],\n"
                           "  \"final_time\": null\n}\n";
  CHECK(json_string(json, "status") == std::optional<std::string>("failed"));
  CHECK(json_string(json, "failure") == std::optional<std::string>("unstable: energy \"grew\""));
  CHECK(json_number(json, "steps") == std::optional<double>(152.0));
  CHECK(!json_number(json, "final_time"));
  CHECK(!json_string(json, "absent"));
  CHECK(observer_reference(json, "A") == std::vector<double>{0.5, 0.25});
  CHECK(observer_reference(json, "B").empty());
  CHECK(velocity_time_shift(toml::parse("[solver]\nintegrator = \"fe\"\n")) == 0.5);
  CHECK(velocity_time_shift(toml::parse("[solver]\nintegrator = \"npc\"\nnpc_velocity = \"eq32\"\n")) == 0.0);
  CHECK(velocity_time_shift(toml::parse("[solver]\nintegrator = \"npc\"\nnpc_velocity = \"average\"\nnewmark_gamma = 0.75\n")) == 0.25);
  CHECK(compare_score("column,quantity,samples,rms,rms_normalised\nA.v_x,v_x,3,1,0.3\nA.v_y,v_y,3,1,0.4\n") == doctest::Approx(0.5));
  CHECK(!compare_score("column,quantity,samples,rms,rms_normalised\n"));
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("mpm_study_measures_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  io::write_file((folder / "energy.csv").string(), "t,kinetic,strain,total\n0,4,0,4\n1,2,1,3\n");
  std::string error;
  CHECK(energy_drift((folder / "energy.csv").string(), error) == std::optional<double>(-0.25));
  io::write_file((folder / "observers.csv").string(), "t,A.x,A.v_x\n0,0,1\n0.1,0,2\n0.3,0,3\n");
  REQUIRE(write_shifted((folder / "observers.csv").string(), (folder / "s.csv").string(), {"A.v_x"}, 0.5, 2, 0.3, error));
  const auto shifted = read_columns((folder / "s.csv").string(), {"t", "A.v_x"}, error);
  REQUIRE(shifted.size() == 2);
  CHECK(shifted[0] == std::vector<double>{0.05, 0.2, 0.4});  // every step written: each row's own next step
  CHECK(shifted[1] == std::vector<double>{1, 2, 3});
  REQUIRE(write_shifted((folder / "observers.csv").string(), (folder / "s.csv").string(), {"A.v_x"}, 0.5, 6, 0.3, error));
  CHECK(read_columns((folder / "s.csv").string(), {"t"}, error)[0][1] == doctest::Approx(0.125));  // the mean step 0.05
  CHECK(!write_shifted((folder / "observers.csv").string(), (folder / "s.csv").string(), {"B.v_x"}, 0.5, 2, 0.3, error));
  CHECK(error.find("no column B.v_x") != std::string::npos);
  fs::remove_all(folder);
}

}  // namespace mpm::study
