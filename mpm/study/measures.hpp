/// \file
/// What a study measures of one finished run, from the files the run wrote (run.json, observers.csv,
/// energy.csv), as a user could: the status and failure, the steps, the observer's reference position, the
/// relative drift of the total energy, and the observer's velocity moved to the time it approximates; and from
/// `mpm compare`'s output the velocity's score with the band of its own sampling and its ending (verdict.hpp).
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
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"
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

/// One row of `mpm compare`'s output, the numbers the study takes from it: rms, rms_even, rms_odd and flat_rms in the
/// quantity's unit (m/s), rms_normalised over the solution's scale.
struct ComponentScore {
  double rms = 0.0, rms_normalised = 0.0, rms_even = 0.0, rms_odd = 0.0, flat_rms = 0.0;
};

/// The rows `mpm compare` printed, each column found by its header name; nullopt if one is missing or a field is not a
/// finite number (rms_even and rms_odd may be `nan`: a half without a row).
inline std::optional<std::vector<ComponentScore>> compare_rows(const std::string& printed) {
  std::istringstream lines(printed);
  std::string line;
  std::getline(lines, line);
  const auto header = io::csv_fields(line);
  const std::vector<std::string> names{"rms", "rms_normalised", "rms_even", "rms_odd", "flat_rms"};
  std::vector<std::size_t> index;
  for (const auto& name : names) {
    index.push_back(static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin()));
    if (index.back() == header.size()) return std::nullopt;
  }
  std::vector<ComponentScore> rows;
  while (std::getline(lines, line)) {
    const auto fields = io::csv_fields(line);
    double value[5] = {};
    for (std::size_t k = 0; k < names.size(); ++k) {
      const bool half = names[k] == "rms_even" || names[k] == "rms_odd";
      if (index[k] >= fields.size()) return std::nullopt;
      if (half && fields[index[k]] == "nan") value[k] = std::nan("");
      else if (!io::read_finite_number(fields[index[k]], value[k]).empty()) return std::nullopt;
    }
    rows.push_back({value[0], value[1], value[2], value[3], value[4]});
  }
  return rows.empty() ? std::nullopt : std::optional<std::vector<ComponentScore>>(rows);
}

/// The study's score of the velocity from compare's rows (one per component), with the band of its own sampling and
/// its ending, the report's yardstick (mpm/analysis/verdict.hpp): the value sqrt(sum rms_normalised^2); its band
/// mpm::band_of_halves of the same sum on the even and on the odd rows (each row's halves over its own scale,
/// rms / rms_normalised; infinite when a half has no row: one sample resolves nothing); failed when the vector's RMS,
/// sqrt(sum rms^2), is no smaller than a flat line's at the exact mean, sqrt(sum flat_rms^2) (mpm::score_ending).
inline Measured velocity_score(const std::vector<ComponentScore>& rows) {
  double value = 0.0, even = 0.0, odd = 0.0, rms = 0.0, flat = 0.0;
  for (const auto& row : rows) {
    const double scale = row.rms_normalised > 0.0 ? row.rms / row.rms_normalised : 0.0;  // 0: rms 0, every half 0
    value += row.rms_normalised * row.rms_normalised, rms += row.rms * row.rms, flat += row.flat_rms * row.flat_rms;
    if (scale > 0.0) even += std::pow(row.rms_even / scale, 2), odd += std::pow(row.rms_odd / scale, 2);
  }
  Measured score{std::sqrt(value), std::numeric_limits<double>::infinity(), Ending::done};
  if (std::isfinite(even) && std::isfinite(odd)) score.band = band_of_halves(score.value, std::sqrt(even), std::sqrt(odd));
  score.ending = score_ending(std::sqrt(rms), std::sqrt(flat));
  return score;
}

/// The score `mpm compare` printed (velocity_score of its rows); nullopt if none can be read.
inline std::optional<Measured> compare_score(const std::string& printed) {
  const auto rows = compare_rows(printed);
  return rows ? std::optional<Measured>(velocity_score(*rows)) : std::nullopt;
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
  // compare's rows of v_x and v_y, both over the scale 5 m/s: rms 1.5 and 2 m/s, so 0.3 and 0.4, together 0.5; the
  // halves 1, 2 (x) and 2, 2 (y) m/s: sqrt(0.04 + 0.16) and sqrt(0.16 + 0.16), band |sqrt(0.32) - 0.5|; the flat
  // line's 4 and 0 m/s: 2.5 < 4, done; with 1.5 and 2 m/s: 2.5 >= 2.5, failed.
  const std::string header = "column,quantity,samples,rms,rms_normalised,max_abs,t_of_max,rms_even,rms_odd,ringing,amplitude,"
                             "amplitude_even,amplitude_odd,flat_rms,ending\n";
  const auto both = compare_score(header + "A.v_x,v_x,3,1.5,0.3,2,0,1,2,1,1,1,1,4,done\nA.v_y,v_y,3,2,0.4,2,0,2,2,1,1,1,1,0,done\n");
  REQUIRE(both);
  CHECK(both->value == doctest::Approx(0.5));
  CHECK(both->band == doctest::Approx(std::sqrt(0.32) - 0.5));
  CHECK(both->ending == Ending::done);
  CHECK(compare_score(header + "A.v_x,v_x,3,1.5,0.3,2,0,1,2,1,1,1,1,1.5,done\nA.v_y,v_y,3,2,0.4,2,0,2,2,1,1,1,1,2,done\n")->ending ==
        Ending::failed);
  const auto one = compare_score(header + "A.v_x,v_x,1,1,0.2,1,0,1,nan,nan,nan,nan,nan,0,failed\n");  // one row
  REQUIRE(one);
  CHECK(one->band == std::numeric_limits<double>::infinity());
  CHECK(compare_score(header + "A.v_x,v_x,3,0,0,0,0,0,0,1,1,1,1,1,done\n")->band == 0.0);  // exact: every half 0
  CHECK(!compare_score(header));
  CHECK(!compare_score("column,quantity,samples,rms,rms_normalised\nA.v_x,v_x,3,1,0.3\n"));  // no halves, no flat line
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
