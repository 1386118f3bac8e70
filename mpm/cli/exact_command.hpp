/// \file
/// `mpm exact SCENE.toml [--set KEY=VALUE]... --at X[,Y] [--at ...] (--times T0:DT:T1 | --times-file FILE)
///            [--strain small|finite]`
/// prints, without running the solver, the exact solution the scene's `exact` key names
/// (mpm/io/exact_solution.hpp) at every material point asked (its reference position, in the scene's
/// coordinates) and every time asked, as CSV in SI units: 1D `t,X,u_x,v_x,sigma_xx`; 2D
/// `t,X,Y,u_x,u_y,v_x,v_y,sigma_xx,sigma_yy,sigma_xy`, one row per time and point (times in the order
/// given, points in the order of --at). Every option is validated before anything is printed.
/// Exit codes: 0 done; 2 a bad scene or option (one line on stderr, nothing printed); 3 stdout failed.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/exact_solution.hpp"
#include "mpm/io/scene.hpp"
#include "mpm/cli/parse_number.hpp"
#include "mpm/io/text_lines.hpp"

namespace mpm::cli {

/// "X" or "X,Y" with `dimension` entries; nullopt for anything else.
inline std::optional<std::vector<double>> parse_point(const std::string& text, int dimension) {
  std::vector<double> point;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) {
    const auto value = parse_number(part);
    if (!value) return std::nullopt;
    point.push_back(*value);
  }
  if (static_cast<int>(point.size()) != dimension || (!text.empty() && text.back() == ',')) return std::nullopt;
  return point;
}

/// The most times `mpm exact` and `mpm compare` take (a bound on the output and the memory).
inline constexpr std::size_t most_times = 1'000'000;

/// `T0:DT:T1`: T0, T0 + DT, ... up to T1 (T1 included when (T1 - T0)/DT is whole to 1e-9), each
/// computed as T0 + k DT. Empty with `error` set when the text is not such a range.
inline std::vector<double> parse_time_range(const std::string& text, std::string& error) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ':');) parts.push_back(part);
  std::vector<std::optional<double>> values;
  for (const auto& part : parts) values.push_back(parse_number(part));
  if (parts.size() != 3 || !values[0] || !values[1] || !values[2] || text.back() == ':') {
    error = "'" + text + "' is not a range T0:DT:T1 of times in seconds (e.g. 0:1e-6:2e-4)";
    return {};
  }
  const double first = *values[0], step = *values[1], last = *values[2];
  if (first < 0.0 || !(step > 0.0) || last < first) {
    error = "'" + text + "': needs 0 <= T0 <= T1 and DT > 0";
    return {};
  }
  const double intervals = std::floor((last - first) / step + 1e-9);
  if (intervals + 1.0 > static_cast<double>(most_times)) {
    error = "'" + text + "' gives " + io::SceneReader::describe(intervals + 1.0) + " times; at most 1000000";
    return {};
  }
  std::vector<double> times;
  for (long k = 0; k <= static_cast<long>(intervals); ++k) times.push_back(first + k * step);
  return times;
}

/// A file of times, one number (seconds, >= 0) per line; blank lines and lines starting with # are skipped,
/// and a first line that is not a number is a header. Empty with `error` ("FILE:LINE: ...") on a problem.
inline std::vector<double> read_times_file(const std::string& path, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot be read: no such file, or no permission";
    return {};
  }
  std::vector<double> times;
  std::string line;
  bool first = true;
  bool too_long = false;
  int number = 1;
  for (; io::read_line(in, line, too_long); ++number) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    const std::string text = line.substr(start, line.find_last_not_of(" \t") - start + 1);
    const auto value = parse_number(text);
    if (!value && first) {
      first = false;
      continue;
    }
    first = false;
    if (!value || *value < 0.0) {
      error = path + ":" + std::to_string(number) + ": '" + text + "' is not a time in seconds >= 0";
      return {};
    }
    if (times.size() == most_times) {
      error = path + ":" + std::to_string(number) + ": more than 1000000 times";
      return {};
    }
    times.push_back(*value);
  }
  if (too_long) error = path + ":" + std::to_string(number) + ": a line longer than 1 MiB (is it a text file?)";
  else if (in.bad()) error = path + ": cannot be read";
  else if (times.empty()) error = path + ": holds no time";
  return times;
}

/// What `mpm exact` and `mpm compare` both read: the scene and its overrides, the points, the strain measure.
struct ExactOptions {
  std::string scene_path;
  std::vector<std::string> overrides, points;
  std::string strain = "small";
};

/// Reads the scene and checks the points and the strain measure against it; on a problem, writes one
/// line to `err` and returns nullopt. \throws nothing but what reading the scene throws (SceneError).
inline std::optional<io::Scene> load_exact_scene(const ExactOptions& options, std::vector<std::vector<double>>& points, std::ostream& err) {
  io::SceneFile file = io::parse_scene_file(options.scene_path);
  for (size_t k = 0; k < options.overrides.size(); ++k) io::apply_override(file, options.overrides[k], static_cast<int>(k) + 1);
  io::Scene scene = io::read_scene(file);
  if (scene.exact == io::ExactKind::none) {
    err << "error: " << options.scene_path << ": exact: the scene names no exact solution (exact = \"none\"); give one of "
        << "dyka_bar, soil_column, vibrating_bar, manufactured_small, manufactured_large (mpm exact --help)\n";
    return std::nullopt;
  }
  if (options.strain != "small" && options.strain != "finite") {
    err << "error: --strain: '" << options.strain << "' is not allowed; use small | finite\n";
    return std::nullopt;
  }
  if (options.strain == "finite" && !io::has_finite_strain_reference(scene.exact)) {
    err << "error: --strain: '" << io::name_of(scene.exact) << "' has no finite-strain reference (soil_column and vibrating_bar have one)\n";
    return std::nullopt;
  }
  if (options.points.empty()) {
    err << "error: --at: missing; give at least one material point, e.g. --at " << (scene.dimension == 1 ? "0.0" : "0.5,9.5") << "\n";
    return std::nullopt;
  }
  if (options.points.size() > 1000) {
    err << "error: --at: at most 1000 points\n";
    return std::nullopt;
  }
  const io::SceneExactSolution bounds(scene, io::StrainMeasure::small);  // cheap for every solution at small strain
  for (const auto& text : options.points) {
    const auto point = parse_point(text, scene.dimension);
    if (!point) {
      err << "error: --at " << text << ": give " << (scene.dimension == 1 ? "X (m)" : "X,Y (m)") << " for this "
          << scene.dimension << "D scene\n";
      return std::nullopt;
    }
    const std::string outside = bounds.outside(*point);
    if (!outside.empty()) {
      err << "error: --at " << text << ": " << outside << "\n";
      return std::nullopt;
    }
    points.push_back(*point);
  }
  return scene;
}

/// The finite-strain vibrating bar keeps the bar's state at each time and steps up to the last: at most
/// 4000 times and SceneExactSolution::most_finite_strain_steps steps. False, with a line on `err`, beyond.
inline bool finite_strain_times_fit(const io::Scene& scene, const std::string& strain, const std::vector<double>& times,
                                    const std::string& option, std::ostream& err) {
  if (strain != "finite" || scene.exact != io::ExactKind::vibrating_bar) return true;
  if (times.size() > 4000) {
    err << "error: " << option << ": at most 4000 times for the finite-strain vibrating bar (it keeps the bar's state at each)\n";
    return false;
  }
  const double last = *std::max_element(times.begin(), times.end());
  if (io::SceneExactSolution::finite_strain_steps(scene, last) > io::SceneExactSolution::most_finite_strain_steps) {
    err << "error: " << option << ": the finite-strain vibrating bar would take "
        << io::SceneReader::describe(io::SceneExactSolution::finite_strain_steps(scene, last)) << " steps to reach t = " << last
        << " s; at most 2e6 (about " << io::SceneReader::describe(io::SceneExactSolution::most_finite_strain_steps /
                                                                  io::SceneExactSolution::finite_strain_steps(scene, 1.0))
        << " s of this bar)\n";
    return false;
  }
  return true;
}

/// Times within a million periods of the solution (SceneExactSolution::period); false, with a line on `err`, beyond.
inline bool times_within_precision(const io::SceneExactSolution& solution, const std::vector<double>& times, const std::string& option,
                                   std::ostream& err) {
  const double last = *std::max_element(times.begin(), times.end());
  if (last <= 1e6 * solution.period()) return true;
  err << "error: " << option << ": t = " << last << " s is more than a million periods (" << solution.period()
      << " s) of the solution: its values would lose their precision\n";
  return false;
}

/// `mpm exact`; returns the exit code.
inline int exact_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  ExactOptions options;
  std::string range, times_file;
  for (size_t k = 0; k < arguments.size(); ++k) {
    const std::string& argument = arguments[k];
    const bool takes_value = argument == "--set" || argument == "--at" || argument == "--times" || argument == "--times-file" ||
                             argument == "--strain";
    if (takes_value && k + 1 >= arguments.size()) {
      err << "error: " << argument << ": needs a value (mpm exact --help)\n";
      return 2;
    }
    if (argument == "--set") options.overrides.push_back(arguments[++k]);
    else if (argument == "--at") options.points.push_back(arguments[++k]);
    else if (argument == "--strain") options.strain = arguments[++k];
    else if (argument == "--times" || argument == "--times-file") {
      if (!range.empty() || !times_file.empty()) {
        err << "error: " << argument << ": give the times once, by --times or by --times-file\n";
        return 2;
      }
      (argument == "--times" ? range : times_file) = arguments[++k];
      if (arguments[k].empty()) {
        err << "error: " << argument << ": empty\n";
        return 2;
      }
    } else if (argument.rfind("-", 0) == 0 || !options.scene_path.empty()) {
      err << "error: " << argument << ": unknown option (mpm exact --help)\n";
      return 2;
    } else {
      options.scene_path = argument;
    }
  }
  if (options.scene_path.empty()) {
    err << "error: exact: no scene file given (mpm exact --help)\n";
    return 2;
  }
  if (range.empty() && times_file.empty()) {
    err << "error: --times: missing; give --times T0:DT:T1 or --times-file FILE\n";
    return 2;
  }
  std::string problem;
  const std::vector<double> times = range.empty() ? read_times_file(times_file, problem) : parse_time_range(range, problem);
  if (!problem.empty()) {
    err << "error: " << (range.empty() ? "--times-file " : "--times ") << problem << "\n";
    return 2;
  }
  std::vector<std::vector<double>> points;
  try {
    const auto scene = load_exact_scene(options, points, err);
    if (!scene) return 2;
    if (!times_within_precision(io::SceneExactSolution(*scene, io::StrainMeasure::small), times, "--times", err)) return 2;
    if (!finite_strain_times_fit(*scene, options.strain, times, "--times", err)) return 2;
    if (static_cast<double>(times.size()) * points.size() > 1e6) {
      err << "error: --times: " << times.size() << " times at " << points.size() << " points: at most 1000000 rows\n";
      return 2;
    }
    const io::SceneExactSolution solution(*scene, options.strain == "finite" ? io::StrainMeasure::finite : io::StrainMeasure::small,
                                          times);
    const std::vector<std::string> quantities = io::exact_quantities(scene->dimension);
    std::ostringstream text;  // all of it first: nothing is printed if an evaluation fails
    text.precision(15);
    text << "t,X" << (scene->dimension == 2 ? ",Y" : "");
    for (const auto& quantity : quantities) text << "," << quantity;
    text << "\n";
    for (double time : times)
      for (const auto& point : points) {
        const io::ExactState state = solution.at(point, time);
        text << time;
        for (double coordinate : point) text << "," << coordinate;
        for (const auto& quantity : quantities) text << "," << state.quantity(quantity) + 0.0;
        text << "\n";
      }
    out << text.str() << std::flush;
    if (!out) {
      err << "failure: the output could not be written\n";
      return 3;
    }
    return 0;
  } catch (const SceneError& error) {
    err << error.message() << "\n";
    return 2;
  }
}

TEST_CASE("mpm exact: numbers, points and time ranges are read whole, or refused") {
  CHECK(parse_number("1e-3") == 1e-3);
  CHECK(!parse_number("1e-3s"));
  CHECK(!parse_number(""));
  CHECK(!parse_number(" 1"));
  CHECK(!parse_number("nan"));
  CHECK(parse_point("0.25,9.5", 2) == std::vector<double>{0.25, 9.5});
  CHECK(!parse_point("0.25", 2));
  CHECK(!parse_point("0.25,", 1));
  CHECK(!parse_point("0.25,1,2", 2));
  std::string error;
  const auto times = parse_time_range("0:0.25:1", error);
  CHECK(error.empty());
  CHECK(times == std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0});
  CHECK(parse_time_range("0:0.3:1", error).size() == 4);  // 0, 0.3, 0.6, 0.9: T1 not on the range
  CHECK(parse_time_range("1e-6:1e-6:3e-6", error).size() == 3);  // (T1 - T0)/DT = 2 to round-off
  CHECK(parse_time_range("0:0:1", error).empty());
  CHECK(error == "'0:0:1': needs 0 <= T0 <= T1 and DT > 0");
  CHECK(parse_time_range("0:1", error).empty());
  CHECK(parse_time_range("0:1e-9:10", error).empty());
  CHECK(error.find("at most 1000000") != std::string::npos);
}

}  // namespace mpm::cli
