/// \file
/// `mpm compare RESULT.csv SCENE.toml`: scores any CSV with a header line (another code's output) against the
/// scene's exact solution at a material point and the CSV's own times, Eq. (43), one row per --column (its
/// --help says each field). Exit codes: 0 within --tolerance, 1 above it, 2 a bad input, 3 --plot not drawn whole.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mpm/analysis/rms_error.hpp"
#include "mpm/cli/exact_command.hpp"
#include "mpm/cli/gnuplot.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// The numbers of the columns `wanted` of the CSV file `path` (io::CsvFile), by name, one per data row: each row
/// with the header's number of fields and a finite number in each column wanted. \throws Refused (`FILE:LINE: ...`).
inline std::map<std::string, std::vector<double>> read_csv_columns(const std::string& path,
                                                                   const std::vector<std::string>& wanted) {
  io::CsvFile file(path);
  if (!file.read_header())
    throw Refused(file.error().empty() ? path + ": empty; a header line and data rows are needed" : file.error());
  const std::vector<std::string>& header = file.header();
  std::vector<std::size_t> index;
  std::string names;
  for (const auto& column : header) names += (names.empty() ? "" : ", ") + column;
  for (const auto& name : wanted) {
    if (std::count(header.begin(), header.end(), name) > 1)
      throw Refused(file.where() + "column '" + name + "' appears more than once in the header: which one is meant?");
    index.push_back(static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin()));
    if (index.back() == header.size())
      throw Refused(file.where() + "no column '" + name + "' in the header (" + names + ")");
  }
  std::map<std::string, std::vector<double>> values;
  for (std::vector<std::string> fields; file.next_row(fields);) {
    if (values[wanted[0]].size() == most_times) throw Refused(file.where() + "more than 1000000 rows");
    for (size_t k = 0; k < wanted.size(); ++k) {
      std::string out_of_range;
      const auto value = parse_number(fields[index[k]], &out_of_range);
      if (!value)
        throw Refused(file.where() + wanted[k] + ": " +
                      (out_of_range.empty() ? "'" + fields[index[k]] + "' is not a finite number" : out_of_range));
      values[wanted[k]].push_back(*value);
    }
  }
  if (!file.error().empty()) throw Refused(file.error());
  if (values.empty()) throw Refused(path + ": has a header but no data row");
  return values;
}

/// The score of one column, with its series.
struct ColumnScore {
  std::string column, quantity;
  std::size_t samples = 0;
  double rms = 0.0, rms_normalised = 0.0, max_abs = 0.0, t_of_max = 0.0;
  std::vector<double> computed, exact;
};

/// Scores `computed` (at `times`) against `exact`: Eq. (43), divided by `scale` too, and the largest difference.
inline ColumnScore score_column(const std::vector<double>& times, const std::vector<double>& computed,
                                const std::vector<double>& exact, double scale) {
  ColumnScore score{"", "", computed.size(), rms_error(computed, exact), 0.0, -1.0, 0.0, computed, exact};
  score.rms_normalised = score.rms / scale;
  for (std::size_t n = 0; n < computed.size(); ++n)
    if (std::abs(computed[n] - exact[n]) > score.max_abs) {
      score.max_abs = std::abs(computed[n] - exact[n]);
      score.t_of_max = times[n];
    }
  return score;
}

/// The gnuplot script of --plot: one panel per column, its values and the exact solution's against t, the data
/// inline (no file read or written but the picture).
inline std::string compare_plot_script(const std::string& picture, const std::vector<double>& times,
                                       const std::vector<ColumnScore>& scores) {
  std::ostringstream gp;
  gp.precision(15);
  gp << gnuplot_preamble;
  for (size_t c = 0; c < scores.size(); ++c) {
    gp << "$data" << c << " << EOD\n";
    for (size_t n = 0; n < times.size(); ++n)
      gp << times[n] << "," << scores[c].computed[n] << "," << scores[c].exact[n] << "\n";
    gp << "EOD\n";
  }
  gp << gnuplot_page(picture, scores.size());
  for (size_t c = 0; c < scores.size(); ++c)
    gp << "set ylabel " << gnuplot_quoted(scores[c].quantity + " (" + io::quantity_unit(scores[c].quantity) + ")")
       << "\nplot $data" << c << " using 1:2 with lines lw 1.5 title " << gnuplot_quoted(scores[c].column) << ", $data"
       << c << " using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'exact'\n";
  return gp.str() + "unset multiplot\nunset output\n";
}

/// What `mpm compare` was asked, besides the scene and the point.
struct CompareRequest {
  std::string result_path, time_column = "t", plot_path;
  std::vector<std::string> column_specs;
  std::optional<double> tolerance;
};

/// The columns and quantities --column names (COL=QUANTITY), each a quantity of the `dimension`D solution and no
/// column twice; and a --plot that can be written (a .png in an existing folder). \throws Refused.
inline std::vector<std::pair<std::string, std::string>> checked_columns(const CompareRequest& request, int dimension) {
  const std::vector<std::string> quantities = io::exact_quantities(dimension);
  std::vector<std::pair<std::string, std::string>> columns;
  std::string allowed;
  for (const auto& name : quantities) allowed += (allowed.empty() ? "" : " | ") + name;
  for (const auto& spec : request.column_specs) {
    const auto equals = spec.find('=');
    const std::string column = spec.substr(0, equals),
                      quantity = equals == std::string::npos ? "" : spec.substr(equals + 1);
    if (has_control_character(spec))
      throw Refused("--column: a column name holds a control character (a newline, a tab...)");
    if (equals == std::string::npos || column.empty())
      throw Refused("--column " + spec + ": give COL=QUANTITY, e.g. v=v_x");
    if (std::count(quantities.begin(), quantities.end(), quantity) == 0)
      throw Refused("--column " + spec + ": '" + quantity + "' is not a quantity of this " + std::to_string(dimension) +
                    "D solution; use one of " + allowed);
    if (column == request.time_column ||
        std::any_of(columns.begin(), columns.end(), [&](auto& c) { return c.first == column; }))
      throw Refused("--column " + spec + ": column '" + column + "' is the time column or named twice");
    columns.emplace_back(column, quantity);
  }
  const std::filesystem::path plot(request.plot_path);
  std::error_code code;
  if (has_control_character(request.plot_path))
    throw Refused("--plot: the path holds a control character (a newline, a tab...); give another");
  if (!request.plot_path.empty() &&
      (plot.extension() != ".png" || std::filesystem::is_directory(plot, code) ||
       (!plot.parent_path().empty() && !std::filesystem::is_directory(plot.parent_path(), code))))
    throw Refused("--plot: " + request.plot_path + ": give a .png file (not a folder) in an existing folder");
  return columns;
}

/// Scores the CSV of `request` against the exact solution of `options`' scene at its point, prints the scores and
/// draws --plot; returns the exit code (1 above the tolerance). \throws Refused, SceneError, OutputFailure.
inline int compare(const ExactOptions& options, const CompareRequest& request, std::ostream& out, std::ostream& err) {
  if (options.points.size() > 1) throw Refused("--at: give one material point (the one whose history the CSV holds)");
  std::vector<std::vector<double>> points;
  const auto scene = load_exact_scene(options, points, err);
  if (!scene) return 2;
  const auto columns = checked_columns(request, scene->dimension);
  std::vector<std::string> wanted{request.time_column};
  for (const auto& column : columns) wanted.push_back(column.first);
  const auto values = read_csv_columns(request.result_path, wanted);
  const std::vector<double>& times = values.at(request.time_column);
  for (size_t n = 0; n < times.size(); ++n)
    if (times[n] < 0.0) {
      std::ostringstream time;
      time << times[n];
      throw Refused(request.result_path + ": " + request.time_column + ": the sample times must be >= 0 (row " +
                    std::to_string(n + 1) + ": " + time.str() + ")");
    }
  if (!times_within_precision(io::SceneExactSolution(*scene, io::StrainMeasure::small), times, request.result_path,
                              err) ||
      !finite_strain_times_fit(*scene, options.strain, times, request.result_path, err))
    return 2;
  const io::SceneExactSolution solution(
      *scene, options.strain == "finite" ? io::StrainMeasure::finite : io::StrainMeasure::small, times);
  std::vector<ColumnScore> scores;
  for (const auto& [column, quantity] : columns) {
    if (!(solution.scale(quantity) > 0.0))
      throw Refused(options.scene_path + ": the exact solution's scale of " + quantity +
                    " is 0 (the scene is at rest); rms_normalised has no meaning");
    std::vector<double> exact;
    for (double time : times) exact.push_back(solution.at(points[0], time).quantity(quantity));
    scores.push_back(score_column(times, values.at(column), exact, solution.scale(quantity)));
    scores.back().column = column;
    scores.back().quantity = quantity;
  }
  std::ostringstream text, above;
  text.precision(9);
  text << "column,quantity,samples,rms,rms_normalised,max_abs,t_of_max\n";
  for (const auto& score : scores) {
    text << score.column << "," << score.quantity << "," << score.samples << "," << score.rms << ","
         << score.rms_normalised << "," << score.max_abs << "," << score.t_of_max << "\n";
    if (request.tolerance && !(score.rms_normalised <= *request.tolerance)) above << " " << score.column;
  }
  out << text.str() << std::flush;
  if (!request.plot_path.empty()) {
    draw_with_gnuplot("", compare_plot_script(request.plot_path, times, scores), {request.plot_path});
    err << "wrote " << request.plot_path << "\n";
  }
  if (above.str().empty()) return 0;
  err << "above the tolerance " << *request.tolerance << ": rms_normalised > tolerance for" << above.str() << "\n";
  return 1;
}

/// `mpm compare`; returns the exit code.
inline int compare_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  ExactOptions options;
  CompareRequest request;
  CommandParser app(
      "compare",
      "Scores any CSV with a header line (another code's output) against the scene's exact solution (as mpm exact\n"
      "evaluates it) at the material point --at and at the CSV's own sample times, and prints CSV:\n"
      "  column,quantity,samples,rms,rms_normalised,max_abs,t_of_max\n"
      "rms: Eq. (43), sqrt(sum (c_n - e_n)^2 / N) over the N rows, in the quantity's unit; rms_normalised: rms\n"
      "divided by the solution's scale of the quantity: velocity V* (the largest |v_0| or |sigma_0|/Z of the initial\n"
      "data: v0 for the Dyka bar, so the paper's RMS/v0), stress Z V*, displacement V* L/c (dyka_bar); rho g H,\n"
      "rho g H^2/(2M), g H/c (soil_column: base stress, top settlement, wave velocity); Z|V|, |V|, |V|/omega\n"
      "(vibrating_bar); A omega, (lambda + 2G) k A, |A| (manufactured); max_abs: the largest |c_n - e_n|, "
      "at t_of_max (s).");
  app.add_option("RESULT.csv", request.result_path, "the CSV to score")->required();
  app.add_option("SCENE.toml", options.scene_path, "the scene file whose exact solution scores it")->required();
  declare_exact_options(app, options);
  app.add_option("--column", request.column_specs,
                 "COL=QUANTITY: the CSV's column COL holds QUANTITY: u_x, v_x, sigma_xx (2D also u_y, v_y, sigma_yy,\n"
                 "sigma_xy), SI units; repeat for more columns")
      ->type_name("COL=QUANTITY")
      ->required()
      ->allow_extra_args(false);
  app.add_option("--time-column", request.time_column, "the column of the sample times, s")
      ->check(CLI::Validator([](const std::string& text) { return text.empty() ? "empty" : ""; }, ""));
  app.add_option("--tolerance", request.tolerance, "exit 1 when an rms_normalised exceeds TOL (none: no check, exit 0)")
      ->check(number_in(0.0, 1e300));
  app.add_option("--plot", request.plot_path,
                 "draws each column and the exact solution against t into FILE.png (gnuplot)")
      ->type_name("FILE.png");
  app.footer(
      "Exit codes: 0 within the tolerance, 1 above it, 2 a bad input (nothing written), 3 gnuplot failed or\n"
      "an output could not be written (cannot write).");
  return run_parsed(app, arguments, out, err, [&] { return compare(options, request, out, err); });
}

TEST_CASE("Eq. (43): mpm compare: a series off by a constant c has rms = max_abs = c, a CSV is read field by field") {
  // exact + c at every sample: every difference is c, so rms = sqrt(N c^2 / N) = c and max_abs = c at the first time.
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0}, exact{1.0, -2.0, 0.5, 4.0};
  std::vector<double> computed;
  for (double value : exact) computed.push_back(value + 0.25);
  const ColumnScore score = score_column(times, computed, exact, 5.0);
  CHECK(score.rms == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(score.rms_normalised == doctest::Approx(0.05).epsilon(1e-14));
  CHECK(score.max_abs == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(score.t_of_max == 0.0);
  // one difference of 3 among four zeros: rms = sqrt(9/4) = 1.5, max at t = 2
  const ColumnScore spike = score_column(times, {1.0, -2.0, 3.5, 4.0}, exact, 1.0);
  CHECK(spike.rms == doctest::Approx(1.5).epsilon(1e-14));
  CHECK(spike.t_of_max == 2.0);
  const std::string path = (std::filesystem::temp_directory_path() / "mpm_compare_test.csv").string();
  std::ofstream(path) << "t,v,w\n0,1,2\n1,1e-310,2\n";
  CHECK(read_csv_columns(path, {"t", "w"}).at("w") == std::vector<double>{2.0, 2.0});
  CHECK_THROWS_WITH_AS(read_csv_columns(path, {"t", "v"}), doctest::Contains(":3: v: '1e-310' is too small"), Refused);
  CHECK_THROWS_WITH_AS(read_csv_columns(path, {"t", "x"}),
                       doctest::Contains(":1: no column 'x' in the header (t, v, w)"), Refused);
  std::filesystem::remove(path);
}

}  // namespace mpm::cli
