/// \file
/// `mpm exact SCENE.toml --at X[,Y]... (--times T0:DT:T1 | --times-file FILE) [--set KEY=VALUE]... [--strain S]`:
/// the scene's exact solution (mpm/io/exact_solution.hpp) at every point and time asked, as CSV, without running
/// the solver. Every option is validated first. Exit codes: 0 done; 2 a bad scene or option; 3 stdout failed.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "mpm/cli/options.hpp"
#include "mpm/io/csv_file.hpp"
#include "mpm/io/exact_solution.hpp"

namespace mpm::cli {

/// The numbers of `text` separated by `separator`, each read whole (parse_number); nullopt if one is not a number.
inline std::optional<std::vector<double>> parse_numbers(const std::string& text, char separator) {
  std::vector<double> values;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);) {
    const auto value = parse_number(part);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  if (!text.empty() && text.back() == separator) return std::nullopt;
  return values;
}

/// "X" or "X,Y" with `dimension` entries; nullopt for anything else.
inline std::optional<std::vector<double>> parse_point(const std::string& text, int dimension) {
  auto point = parse_numbers(text, ',');
  if (point && static_cast<int>(point->size()) != dimension) return std::nullopt;
  return point;
}

/// The most times `mpm exact` and `mpm compare` take (a bound on the output and the memory).
inline constexpr std::size_t most_times = 1'000'000;

/// `T0:DT:T1`: T0 + k DT for k = 0, 1, ... up to T1 (included when (T1 - T0)/DT is whole to 1e-9).
/// Empty with `error` set when the text is not such a range.
inline std::vector<double> parse_time_range(const std::string& text, std::string& error) {
  const auto values = parse_numbers(text, ':');
  if (!values || values->size() != 3) {
    error = "'" + text + "' is not a range T0:DT:T1 of times in seconds (e.g. 0:1e-6:2e-4)";
    return {};
  }
  const double first = (*values)[0], step = (*values)[1], last = (*values)[2];
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

/// A file of times, one number (seconds, >= 0) per line; blank lines and # comments are skipped, and a first line
/// that is not a number is a header. Empty with `error` ("FILE:LINE: ...") on a problem.
inline std::vector<double> read_times_file(const std::string& path, std::string& error) {
  io::CsvFile file(path);
  std::vector<double> times;
  bool first = true;
  for (std::string text; file.next_line(text); first = false) {
    const auto value = parse_number(text);
    if (!value && first) continue;
    const bool time = value && *value >= 0.0;
    if (!time || times.size() == most_times) {
      error = file.where() + (time ? "more than 1000000 times" : "'" + text + "' is not a time in seconds >= 0");
      return {};
    }
    times.push_back(*value);
  }
  error = file.error();
  if (error.empty() && times.empty()) error = path + ": holds no time";
  return error.empty() ? times : std::vector<double>{};
}

/// What `mpm exact` and `mpm compare` both read: the scene and its overrides, the points, the strain measure.
struct ExactOptions {
  std::string scene_path;
  std::vector<std::string> overrides, points;
  std::string strain = "small";
};

/// Reads the scene and checks the strain measure and the points against it; on a problem, writes one line to `err`
/// and returns nullopt. \throws SceneError for a bad scene, or one that names no exact solution.
inline std::optional<io::Scene> load_exact_scene(const ExactOptions& options, std::vector<std::vector<double>>& points,
                                                 std::ostream& err) {
  io::SceneFile file = io::parse_scene_file(options.scene_path);
  for (size_t k = 0; k < options.overrides.size(); ++k)
    io::apply_override(file, options.overrides[k], static_cast<int>(k) + 1);
  io::Scene scene = io::read_scene(file);
  const io::SceneExactSolution bounds(scene, io::StrainMeasure::small);  // cheap for every solution at small strain
  const std::string where = scene.dimension == 1 ? "X (m) for this 1D scene" : "X,Y (m) for this 2D scene";
  std::string problem;
  if (options.strain == "finite" && !io::has_finite_strain_reference(scene.exact))
    problem = "--strain: '" + io::name_of(scene.exact) +
              "' has no finite-strain reference (soil_column and "
              "vibrating_bar have one)";
  else if (options.points.size() > 1000)
    problem = "--at: at most 1000 points";
  for (size_t k = 0; k < options.points.size() && problem.empty(); ++k) {
    const auto point = parse_point(options.points[k], scene.dimension);
    const std::string why = point ? bounds.outside(*point) : "give " + where;
    if (!why.empty()) problem = "--at " + options.points[k] + ": " + why;
    if (point) points.push_back(*point);
  }
  if (problem.empty()) return scene;
  err << "error: " << problem << "\n";
  return std::nullopt;
}

/// The finite-strain vibrating bar keeps the bar's state at each time and steps up to the last: at most 4000 times
/// and SceneExactSolution::most_finite_strain_steps steps. False, with a line on `err`, beyond.
inline bool finite_strain_times_fit(const io::Scene& scene, const std::string& strain, const std::vector<double>& times,
                                    const std::string& option, std::ostream& err) {
  if (strain != "finite" || scene.exact != io::ExactKind::vibrating_bar) return true;
  using Solution = io::SceneExactSolution;
  const double last = *std::max_element(times.begin(), times.end()), steps = Solution::finite_strain_steps(scene, last);
  if (times.size() > 4000)
    err << "error: " << option
        << ": at most 4000 times for the finite-strain vibrating bar (it keeps the bar's state at each)\n";
  else if (steps > Solution::most_finite_strain_steps)
    err << "error: " << option << ": the finite-strain vibrating bar would take " << io::SceneReader::describe(steps)
        << " steps to reach t = " << last << " s; at most 2e6 (about "
        << io::SceneReader::describe(Solution::most_finite_strain_steps / Solution::finite_strain_steps(scene, 1.0))
        << " s of this bar)\n";
  return times.size() <= 4000 && steps <= Solution::most_finite_strain_steps;
}

/// Times within a million periods of the solution (SceneExactSolution::period); false, with a line on `err`, beyond.
inline bool times_within_precision(const io::SceneExactSolution& solution, const std::vector<double>& times,
                                   const std::string& option, std::ostream& err) {
  const double last = *std::max_element(times.begin(), times.end());
  if (last <= 1e6 * solution.period()) return true;
  err << "error: " << option << ": t = " << last << " s is more than a million periods (" << solution.period()
      << " s) of the solution: its values would lose their precision\n";
  return false;
}

/// Declares the options `mpm exact` and `mpm compare` share: --set, --at, --strain.
inline void declare_exact_options(CLI::App& app, ExactOptions& options) {
  app.add_option("--set", options.overrides, "overrides a scene key with a TOML value, as for mpm run; repeat for more")
      ->allow_extra_args(false)
      ->type_name("KEY=VALUE");
  app.add_option("--at", options.points, "a material point of the body, by its reference position X[,Y] (m)")
      ->type_name("X[,Y]")
      ->required()
      ->allow_extra_args(false);
  app.add_option("--strain", options.strain,
                 "small: the small-strain solution; finite: the finite-strain reference of the solver's\n"
                 "updated-Lagrangian model (soil_column, vibrating_bar)")
      ->check(one_of({"small", "finite"}));
}

/// The solutions `mpm exact` evaluates, for its help.
inline const char* exact_solutions =
    "The solutions (scene key `exact`; SI units; L = grid.length, E, nu, rho of [material]; README's key table):\n"
    "    dyka_bar            1D bar [origin, origin + L] free at xmin, fixed at xmax (appendix A.1-A.19); its\n"
    "                        piecewise-constant initial velocity from body.velocity, [initial_field] and\n"
    "                        [[initial_velocity]] (later boxes win), initial stress (default 0) from [initial_field]\n"
    "    soil_column         2D column on a roller base (paper/07_exact_column.md), H the top of its bodies above the\n"
    "                        origin, g = -gravity.acceleration[1] ramped over gravity.ramp_period (Eq. 44; 0: none)\n"
    "    vibrating_bar       dyka_bar's bar in mode n = exact_parameters.mode (default 1), v(X, 0) = V cos((2n - 1)\n"
    "                        pi X / 2L) with V = exact_parameters.velocity_amplitude (m/s, required)\n"
    "    manufactured_small  2D square, faces held, u = A sin(omega t) (sin kX sin kY, sin 2kX sin kY), k = pi/L; A =\n"
    "                        exact_parameters.displacement_amplitude (m, required, |A| pi/L < 0.01)\n"
    "    manufactured_large  2D square on rollers, each axis stretched at finite strain; [a_x, a_y] =\n"
    "                        exact_parameters.displacement_amplitude (m, required)\n"
    "  --strain finite: soil_column's static settlement at logarithmic strain (v = 0); vibrating_bar's sigma =\n"
    "  E ln(stretch) by finite differences (512 cells, at most 4000 times).\n";

/// `mpm exact`'s parser, its options bound to `options` and to the times asked (`range` or `times_file`).
inline std::unique_ptr<CommandParser> exact_parser(ExactOptions& options, std::string& range, std::string& times_file) {
  auto app = std::make_unique<CommandParser>(
      "exact",
      "Prints, without running the solver, the exact solution the scene's `exact` key names at every material\n"
      "point and time asked, as CSV in SI units, one row per time and point:\n"
      "  1D  t,X,u_x,v_x,sigma_xx           2D  t,X,Y,u_x,u_y,v_x,v_y,sigma_xx,sigma_yy,sigma_xy\n"
      "t (s), X, Y: the point's reference position (m, the scene's coordinates), u: displacement since t = 0 (m),\n"
      "v: velocity (m/s), sigma: Cauchy stress (Pa, tension > 0).");
  app->add_option("SCENE.toml", options.scene_path, "the scene file")->required();
  declare_exact_options(*app, options);
  const auto not_empty = CLI::Validator([](const std::string& text) { return text.empty() ? "empty" : ""; }, "");
  auto* times = app->add_option("--times", range, "the times T0, T0 + DT, ... <= T1 (s): T0:DT:T1")->check(not_empty);
  auto* file = app->add_option("--times-file", times_file,
                               "one time (s) per line; # comments and a first header line are skipped")
                   ->check(not_empty);
  times->excludes(file);
  app->footer(exact_solutions);
  return app;
}

/// `mpm exact --help`: the parser's own help.
inline std::string exact_usage() {
  ExactOptions options;
  std::string range, times_file;
  return exact_parser(options, range, times_file)->help();
}

/// `mpm exact`: the rows for every time (in the order given) and point (in the order of --at); returns the exit code.
inline int exact_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  ExactOptions options;
  std::string range, times_file, problem;
  if (const auto code = parse_arguments(*exact_parser(options, range, times_file), arguments, "exact", out, err))
    return *code;
  if (range.empty() && times_file.empty()) {
    err << "error: --times: missing; give --times T0:DT:T1 or --times-file FILE\n";
    return 2;
  }
  const std::vector<double> times =
      range.empty() ? read_times_file(times_file, problem) : parse_time_range(range, problem);
  if (!problem.empty()) {
    err << "error: " << (range.empty() ? "--times-file " : "--times ") << problem << "\n";
    return 2;
  }
  try {
    std::vector<std::vector<double>> points;
    const auto scene = load_exact_scene(options, points, err);
    if (!scene ||
        !times_within_precision(io::SceneExactSolution(*scene, io::StrainMeasure::small), times, "--times", err) ||
        !finite_strain_times_fit(*scene, options.strain, times, "--times", err))
      return 2;
    if (static_cast<double>(times.size()) * points.size() > 1e6) {
      err << "error: --times: " << times.size() << " times at " << points.size() << " points: at most 1000000 rows\n";
      return 2;
    }
    const auto strain = options.strain == "finite" ? io::StrainMeasure::finite : io::StrainMeasure::small;
    const io::SceneExactSolution solution(*scene, strain, times);
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
    out << text.str();  // main() checks standard output when the command ends
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
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mpm_times_test_" + std::to_string(::getpid()) + ".txt")).string();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  REQUIRE(file);
  std::fputs("\xEF\xBB\xBF" "1e-5\r\n# a comment\n\n 2e-5 \n", file);  // a spreadsheet's byte-order mark and line ends
  std::fclose(file);
  error.clear();
  CHECK(read_times_file(path, error) == std::vector<double>{1e-5, 2e-5});  // the first time kept, not taken for a header
  CHECK(error.empty());
  std::filesystem::remove(path);
  CHECK(read_times_file(std::filesystem::temp_directory_path().string(), error).empty());
  CHECK(error.find(": is a folder, not a regular file") != std::string::npos);
}

}  // namespace mpm::cli
