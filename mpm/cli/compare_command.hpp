/// \file
/// `mpm compare RESULT.csv SCENE.toml --at X[,Y] --column COL=QUANTITY [--column ...] [--time-column NAME]
///              [--tolerance TOL] [--plot FILE.png] [--set KEY=VALUE]... [--strain small|finite]`
/// scores any CSV with a header line (another code's output: any column names, any sample times) against
/// the exact solution the scene names (mpm/io/exact_solution.hpp), evaluated at the material point --at
/// and at the CSV's own times. It prints CSV, one row per --column:
///   column,quantity,samples,rms,rms_normalised,max_abs,t_of_max
/// rms is Eq. (43) over the N samples, \f$ \sqrt{\tfrac1N \sum_n (c_n - e_n)^2} \f$ (mpm/analysis/rms_error.hpp);
/// rms_normalised divides it by the solution's scale of the quantity (SceneExactSolution::scale: v0 for the
/// Dyka bar's velocity, so the paper's RMS/v0 comes out directly); max_abs is the largest |c_n - e_n| and
/// t_of_max the first sample time at which it occurs.
/// Exit codes: 0 every rms_normalised <= TOL (or no --tolerance given); 1 one is above TOL; 2 a bad input
/// (unknown column, unreadable CSV, no exact solution in the scene; one line on stderr, nothing written);
/// 3 --plot could not be drawn whole (`error: FILE.png: cannot write: ...`; it takes precedence over 1).
/// The CSV is read by io::CsvFile (regular files only, a byte-order mark skipped, lines of at most 1 MiB); the
/// picture is made afresh (never through a symbolic link) by gnuplot, run without a shell (mpm/cli/gnuplot.hpp).
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/analysis/rms_error.hpp"
#include "mpm/cli/exact_command.hpp"
#include "mpm/cli/gnuplot.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// A CSV file's header and the numbers of the columns asked, row by row.
struct CsvColumns {
  std::vector<std::string> header;
  std::map<std::string, std::vector<double>> values;  ///< by column name, one entry per data row
};

/// Reads the columns `wanted` of the CSV file `path` (io::CsvFile: header on the first line that is neither
/// blank nor a # comment). Every data row must have the header's number of fields and a finite number in each
/// column wanted. Returns an empty header with `error` set ("FILE:LINE: ...") on a problem.
inline CsvColumns read_csv_columns(const std::string& path, const std::vector<std::string>& wanted, std::string& error) {
  io::CsvFile file(path);
  if (!file.read_header()) {
    error = file.error().empty() ? path + ": empty; a header line and data rows are needed" : file.error();
    return {};
  }
  CsvColumns csv;
  csv.header = file.header();
  std::vector<std::size_t> index;
  for (const auto& name : wanted) {
    const auto found = std::find(csv.header.begin(), csv.header.end(), name);
    if (std::count(csv.header.begin(), csv.header.end(), name) > 1) {
      error = file.where() + "column '" + name + "' appears more than once in the header: which one is meant?";
      return {};
    }
    if (found == csv.header.end()) {
      std::string names;
      for (const auto& column : csv.header) names += (names.empty() ? "" : ", ") + column;
      error = file.where() + "no column '" + name + "' in the header (" + names + ")";
      return {};
    }
    index.push_back(static_cast<std::size_t>(found - csv.header.begin()));
  }
  for (std::vector<std::string> fields; file.next_row(fields);) {
    if (!csv.values.empty() && csv.values.begin()->second.size() == most_times) {
      error = file.where() + "more than 1000000 rows";
      return {};
    }
    for (size_t k = 0; k < wanted.size(); ++k) {
      const auto value = parse_number(fields[index[k]]);
      if (!value) {
        error = file.where() + wanted[k] + ": '" + fields[index[k]] + "' is not a finite number";
        return {};
      }
      csv.values[wanted[k]].push_back(*value);
    }
  }
  error = file.error();
  if (error.empty() && csv.values.empty()) error = path + ": has a header but no data row";
  return error.empty() ? csv : CsvColumns{};
}

/// The score of one column.
struct ColumnScore {
  std::string column, quantity;
  std::size_t samples = 0;
  double rms = 0.0, rms_normalised = 0.0, max_abs = 0.0, t_of_max = 0.0;
};

/// Scores `computed` (at `times`) against `exact`: Eq. (43) and the largest difference.
inline ColumnScore score_column(const std::vector<double>& times, const std::vector<double>& computed, const std::vector<double>& exact,
                                double scale) {
  ColumnScore score;
  score.samples = computed.size();
  score.rms = rms_error(computed, exact);
  score.rms_normalised = score.rms / scale;
  score.max_abs = -1.0;
  for (std::size_t n = 0; n < computed.size(); ++n)
    if (std::abs(computed[n] - exact[n]) > score.max_abs) score.max_abs = std::abs(computed[n] - exact[n]), score.t_of_max = times[n];
  return score;
}

/// The gnuplot script of --plot: one panel per column, the CSV's values and the exact solution at the same
/// times, the data inline (no other file is read or written but the picture). Every string is a gnuplot
/// single-quoted string; the caller refuses control characters in the picture's path and the column names.
inline std::string compare_plot_script(const std::string& picture, const std::vector<double>& times,
                                       const std::vector<ColumnScore>& scores, const std::vector<std::vector<double>>& computed,
                                       const std::vector<std::vector<double>>& exact) {
  std::ostringstream gp;
  gp.precision(15);
  gp << "set datafile separator ','\nset grid lc rgb '#dddddd'\nset key outside right top\nset lmargin 14\nset xlabel 't (s)'\n"
     << "set terminal pngcairo noenhanced size 1000," << 260 * scores.size() << " font ',10'\nset output "
     << gnuplot_quoted(gnuplot_output_path(picture)) << "\n";
  for (size_t c = 0; c < scores.size(); ++c) {
    gp << "$data" << c << " << EOD\n";
    for (size_t n = 0; n < times.size(); ++n) gp << times[n] << "," << computed[c][n] << "," << exact[c][n] << "\n";
    gp << "EOD\n";
  }
  gp << "set multiplot layout " << scores.size() << ",1\n";
  for (size_t c = 0; c < scores.size(); ++c)
    gp << "set ylabel " << gnuplot_quoted(scores[c].quantity + " (" + io::quantity_unit(scores[c].quantity) + ")") << "\nplot $data" << c
       << " using 1:2 with lines lw 1.5 title " << gnuplot_quoted(scores[c].column) << ", $data" << c
       << " using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'exact'\n";
  gp << "unset multiplot\nunset output\n";
  return gp.str();
}

/// Runs gnuplot on `script`, given on its standard input from an unnamed temporary file, its messages into
/// another; `picture` is made afresh first (create_fresh). True if gnuplot wrote `picture` whole
/// (png_file_complete); `reason` says why not, with the first line of gnuplot's messages.
inline bool draw_with_gnuplot(const std::string& script, const std::string& picture, std::string& reason) {
  std::FILE* input = std::tmpfile();
  std::FILE* log = std::tmpfile();
  const int descriptor = input && log ? create_fresh(picture, reason) : -1;
  if (!input || !log) reason = "no temporary file for gnuplot's script";
  bool drawn = false;
  if (descriptor >= 0 && (::close(descriptor), write_all(fileno(input), script, reason)) && ::lseek(fileno(input), 0, SEEK_SET) == 0) {
    const int status = run_gnuplot("", "", fileno(input), fileno(log));
    drawn = status == 0 && png_file_complete(picture);
    std::string message(512, '\0');
    const ssize_t count = ::pread(fileno(log), &message[0], message.size(), 0);
    message.resize(count > 0 ? static_cast<std::size_t>(count) : 0);
    message = message.substr(0, message.find_first_of("\r\n"));
    reason = (status != 0 ? "gnuplot failed (status " + std::to_string(status) + "; is gnuplot installed? make deps)"
                          : std::string("gnuplot left it incomplete (no PNG end chunk)")) + (message.empty() ? "" : ": " + message);
  }
  if (descriptor >= 0 && !drawn) ::unlink(picture.c_str());  // made here, and not whole: not left to be taken for a picture
  if (input) std::fclose(input);
  if (log) std::fclose(log);
  return drawn;
}

/// What `mpm compare` was asked, besides the scene and the point.
struct CompareRequest {
  std::string result_path, time_column = "t", plot_path;
  std::vector<std::string> column_specs;
  std::optional<double> tolerance;
};

/// `mpm compare`'s parser, its options bound to `options` and `request`.
inline std::unique_ptr<CommandParser> compare_parser(ExactOptions& options, CompareRequest& request) {
  auto app = std::make_unique<CommandParser>(
      "compare",
      "Scores any CSV with a header line (another code's output) against the scene's exact solution (as mpm exact\n"
      "evaluates it) at the material point --at and at the CSV's own sample times, and prints CSV:\n"
      "  column,quantity,samples,rms,rms_normalised,max_abs,t_of_max\n"
      "rms: Eq. (43), sqrt(sum (c_n - e_n)^2 / N) over the N rows, in the quantity's unit; rms_normalised: rms\n"
      "divided by the solution's scale of the quantity: velocity V* (the largest |v_0| or |sigma_0|/Z of the initial\n"
      "data: v0 for the Dyka bar, so the paper's RMS/v0), stress Z V*, displacement V* L/c (dyka_bar); rho g H,\n"
      "rho g H^2/(2M), g H/c (soil_column: base stress, top settlement, wave velocity); Z|V|, |V|, |V|/omega\n"
      "(vibrating_bar); A omega, (lambda + 2G) k A, |A| (manufactured); max_abs: the largest |c_n - e_n|, at t_of_max (s).");
  app->add_option("RESULT.csv", request.result_path, "the CSV to score")->required();
  app->add_option("SCENE.toml", options.scene_path, "the scene file whose exact solution scores it")->required();
  declare_exact_options(*app, options);
  app->add_option("--column", request.column_specs,
                  "COL=QUANTITY: the CSV's column COL holds QUANTITY: u_x, v_x, sigma_xx (2D also u_y, v_y, sigma_yy,\n"
                  "sigma_xy), SI units; repeat for more columns")
      ->type_name("COL=QUANTITY")
      ->required()
      ->allow_extra_args(false);
  app->add_option("--time-column", request.time_column, "the column of the sample times, s")
      ->check(CLI::Validator([](const std::string& text) { return text.empty() ? "empty" : ""; }, ""));
  app->add_option("--tolerance", request.tolerance, "exit 1 when an rms_normalised exceeds TOL (none: no check, exit 0)")
      ->check(number_in(0.0, 1e300));
  app->add_option("--plot", request.plot_path, "draws each column and the exact solution against t into FILE.png (gnuplot)")
      ->type_name("FILE.png");
  app->footer("Exit codes: 0 within the tolerance, 1 above it, 2 a bad input (nothing written), 3 gnuplot failed or\n"
              "an output could not be written (cannot write).");
  return app;
}

/// `mpm compare --help`: the parser's own help.
inline std::string compare_usage() {
  ExactOptions options;
  CompareRequest request;
  return compare_parser(options, request)->help();
}

/// `mpm compare`; returns the exit code.
inline int compare_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  ExactOptions options;
  CompareRequest request;
  if (const auto code = parse_arguments(*compare_parser(options, request), arguments, "compare", out, err)) return *code;
  const std::string &result_path = request.result_path, &time_column = request.time_column, &plot_path = request.plot_path;
  const std::vector<std::string>& column_specs = request.column_specs;
  const std::optional<double>& tolerance = request.tolerance;
  if (options.points.size() > 1) {
    err << "error: --at: give one material point (the one whose history the CSV holds)\n";
    return 2;
  }
  std::vector<std::vector<double>> points;
  try {
    const auto scene = load_exact_scene(options, points, err);
    if (!scene) return 2;
    const std::vector<std::string> quantities = io::exact_quantities(scene->dimension);
    std::vector<std::string> columns{time_column}, asked;
    for (const auto& spec : column_specs) {
      const auto equals = spec.find('=');
      const std::string column = spec.substr(0, equals), quantity = equals == std::string::npos ? "" : spec.substr(equals + 1);
      if (has_control_character(spec)) {
        err << "error: --column: a column name holds a control character (a newline, a tab...)\n";
        return 2;
      }
      if (equals == std::string::npos || column.empty()) {
        err << "error: --column " << spec << ": give COL=QUANTITY, e.g. v=v_x\n";
        return 2;
      }
      if (std::find(quantities.begin(), quantities.end(), quantity) == quantities.end()) {
        std::string allowed;
        for (const auto& name : quantities) allowed += (allowed.empty() ? "" : " | ") + name;
        err << "error: --column " << spec << ": '" << quantity << "' is not a quantity of this " << scene->dimension
            << "D solution; use one of " << allowed << "\n";
        return 2;
      }
      if (column == time_column || std::find(columns.begin(), columns.end(), column) != columns.end()) {
        err << "error: --column " << spec << ": column '" << column << "' is the time column or named twice\n";
        return 2;
      }
      columns.push_back(column);
      asked.push_back(quantity);
    }
    if (has_control_character(plot_path)) {
      err << "error: --plot: the path holds a control character (a newline, a tab...); give another\n";
      return 2;
    }
    if (!plot_path.empty()) {
      const std::filesystem::path folder = std::filesystem::path(plot_path).parent_path();
      std::error_code code;
      if (std::filesystem::path(plot_path).extension() != ".png" || (!folder.empty() && !std::filesystem::is_directory(folder, code)) ||
          std::filesystem::is_directory(plot_path, code)) {
        err << "error: --plot: " << plot_path << ": give a .png file (not a folder) in an existing folder\n";
        return 2;
      }
    }
    std::string problem;
    const CsvColumns csv = read_csv_columns(result_path, columns, problem);
    if (!problem.empty()) {
      err << "error: " << problem << "\n";
      return 2;
    }
    const std::vector<double>& times = csv.values.at(time_column);
    for (size_t n = 0; n < times.size(); ++n)
      if (times[n] < 0.0) {
        err << "error: " << result_path << ": " << time_column << ": the sample times must be >= 0 (row " << n + 1 << ": " << times[n]
            << ")\n";
        return 2;
      }
    if (!times_within_precision(io::SceneExactSolution(*scene, io::StrainMeasure::small), times, result_path, err)) return 2;
    if (!finite_strain_times_fit(*scene, options.strain, times, result_path, err)) return 2;
    const io::SceneExactSolution solution(*scene, options.strain == "finite" ? io::StrainMeasure::finite : io::StrainMeasure::small,
                                          times);
    std::vector<ColumnScore> scores;
    std::vector<std::vector<double>> exact_series, computed_series;
    for (size_t c = 0; c < asked.size(); ++c) {
      const double scale = solution.scale(asked[c]);
      if (!(scale > 0.0)) {
        err << "error: " << options.scene_path << ": the exact solution's scale of " << asked[c]
            << " is 0 (the scene is at rest); rms_normalised has no meaning\n";
        return 2;
      }
      std::vector<double> exact;
      for (double time : times) exact.push_back(solution.at(points[0], time).quantity(asked[c]));
      ColumnScore score = score_column(times, csv.values.at(columns[c + 1]), exact, scale);
      score.column = columns[c + 1], score.quantity = asked[c];
      scores.push_back(score);
      exact_series.push_back(exact);
      computed_series.push_back(csv.values.at(columns[c + 1]));
    }
    std::ostringstream text;
    text.precision(9);
    text << "column,quantity,samples,rms,rms_normalised,max_abs,t_of_max\n";
    bool within = true;
    for (const auto& score : scores) {
      text << score.column << "," << score.quantity << "," << score.samples << "," << score.rms << "," << score.rms_normalised << ","
           << score.max_abs << "," << score.t_of_max << "\n";
      if (tolerance && !(score.rms_normalised <= *tolerance)) within = false;
    }
    out << text.str() << std::flush;
    if (!plot_path.empty()) {
      std::string reason;
      if (!draw_with_gnuplot(compare_plot_script(plot_path, times, scores, computed_series, exact_series), plot_path, reason)) {
        err << "error: " << plot_path << ": cannot write: " << reason << "\n";
        return 3;
      }
      err << "wrote " << plot_path << "\n";
    }
    if (!within) {
      err << "above the tolerance " << *tolerance << ": rms_normalised > tolerance for";
      for (const auto& score : scores)
        if (!(score.rms_normalised <= *tolerance)) err << " " << score.column;
      err << "\n";
      return 1;
    }
    return 0;
  } catch (const SceneError& error) {
    err << error.message() << "\n";
    return 2;
  }
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
}

}  // namespace mpm::cli
