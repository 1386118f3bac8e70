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
#include <unistd.h>

#include "mpm/analysis/ending_label.hpp"
#include "mpm/analysis/rms_error.hpp"
#include "mpm/analysis/verdict.hpp"
#include "mpm/cli/exact_command.hpp"
#include "mpm/cli/gnuplot.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// The numbers of a CSV file's columns by name, one per data row, and the file's line of each row.
struct CsvColumns {
  std::map<std::string, std::vector<double>> values;
  std::vector<int> lines;
};

/// The numbers of the columns `wanted` of the CSV file `path` (io::CsvFile: ',', ';', tab or space separated), by
/// name, one per data row: each row with the header's number of fields and a finite number in each column wanted.
/// \throws Refused (`FILE:LINE: ...`).
inline CsvColumns read_csv_columns(const std::string& path, const std::vector<std::string>& wanted) {
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
  CsvColumns columns;
  std::map<std::string, std::vector<double>>& values = columns.values;
  for (std::vector<std::string> fields; file.next_row(fields);) {
    if (columns.lines.size() == most_times) throw Refused(file.where() + "more than 1000000 rows");
    columns.lines.push_back(file.line());
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
  return columns;
}

/// How far past the scene's end time a sample time may lie, as a fraction of it: round-off of a time written with
/// 7 or more significant digits, or summed step by step.
inline constexpr double end_time_round_off = 1e-6;

/// Refuses sample `times` (read from `path`, one per line of `lines`, in `column`) that are not in [0, `end_time`
/// (1 + end_time_round_off)] or do not increase, naming the first such row. \throws Refused (`FILE:LINE: COLUMN:`).
inline void check_sample_times(const std::vector<double>& times, const std::vector<int>& lines, const std::string& path,
                               const std::string& column, double end_time) {
  const auto said = [](double time) {
    std::ostringstream text;
    text.precision(10);
    text << time << " s";
    return text.str();
  };
  for (std::size_t n = 0; n < times.size(); ++n) {
    const std::string where = path + ":" + std::to_string(lines[n]) + ": " + column + ": " + said(times[n]);
    if (times[n] < 0.0) throw Refused(where + " is before t = 0: the sample times must lie in [0, solver.end_time]");
    if (times[n] > end_time * (1.0 + end_time_round_off))
      throw Refused(where + " is after the scene's solver.end_time = " + said(end_time) +
                    ": times in ms or us? (--scale " + column + "=0.001 converts ms to s; --set solver.end_time=T " +
                    "scores later times)");
    if (n > 0 && times[n] <= times[n - 1])
      throw Refused(where + (times[n] == times[n - 1] ? " repeats the time" : " comes before the time " +
                             said(times[n - 1])) + " of line " + std::to_string(lines[n - 1]) +
                    ": the sample times must increase");
  }
}

/// The score of one column, with its series.
struct ColumnScore {
  std::string column, quantity;
  std::size_t samples = 0;
  double rms = 0.0, rms_normalised = 0.0, max_abs = 0.0, t_of_max = 0.0;
  std::vector<double> computed, exact;
  /// The band of the score's own sampling: Eq. (43) on the even rows alone and on the odd rows alone (the rows as
  /// the CSV numbers them from 0); a difference of two scores inside both of theirs is not resolved by the samples.
  double rms_even = 0.0, rms_odd = 0.0;
  /// Ringing: the total variation of the column over the exact one's at the same times (mpm::total_variation_ratio;
  /// 1 when it follows the exact history, above 1 by twice each overshoot and oscillation, lowered by damping); NaN
  /// when the exact history does not vary there beyond round-off, or there are fewer than two rows.
  double ringing = std::nan("");
  /// Damping: the column's RMS about its own mean over the exact one's (mpm::amplitude_ratio; 1 at full amplitude,
  /// a constant offset too, below 1 damped, above 1 swinging wider), on every row and on the even and the odd rows
  /// alone; NaN where the exact history (on those rows) is flat to round-off.
  double amplitude = std::nan(""), amplitude_even = std::nan(""), amplitude_odd = std::nan("");
  /// What a flat line at the exact history's mean scores (mpm::flat_line_score), in the quantity's unit, and the
  /// ending it gives the column by the report's rule (mpm::score_ending): failed when rms is no smaller, else done.
  double flat_rms = 0.0;
  Ending ending = Ending::done;
  /// The ringing on the even and on the odd rows alone: the band of the ringing's own sampling, as rms_even and
  /// rms_odd are the RMS's (NaN where a half has fewer than two rows or its exact history does not vary)
  double ringing_even = std::nan(""), ringing_odd = std::nan("");
  /// Damping on the plateaus (mpm::plateau_deviations: the largest step beyond and the largest shortfall of the exact
  /// level on the middle half of each run of at least 3 rows where the exact history is constant, in units of its
  /// largest |value|), and the deficit on the even and the odd rows alone (its band); NaN where there is no plateau.
  double plateau_overshoot = std::nan(""), plateau_deficit = std::nan(""), plateau_deficit_even = std::nan(""),
         plateau_deficit_odd = std::nan("");
};

/// Eq. (43) over every other row of `computed` and `exact`, from row `first` (0: the even rows, 1: the odd ones); NaN
/// when there is no row there (one row: no odd row).
inline double rms_of_every_other(const std::vector<double>& computed, const std::vector<double>& exact, std::size_t first) {
  const std::vector<double> some_computed = every_other(computed, first), some_exact = every_other(exact, first);
  return some_computed.empty() ? std::nan("") : rms_error(some_computed, some_exact);
}

/// Ringing of `computed` against `exact` (mpm::total_variation_ratio), the exact history's total variation computed
/// once for both its round-off floor and the ratio: NaN unless it exceeds 1e-12 of the largest |exact| per row.
inline double ringing_of(const std::vector<double>& computed, const std::vector<double>& exact) {
  double largest = 0.0;
  for (double value : exact) largest = std::max(largest, std::abs(value));
  const double exact_variation = total_variation(exact);
  if (!(exact_variation > 1e-12 * static_cast<double>(exact.size()) * largest)) return std::nan("");
  return total_variation(computed) / exact_variation;
}

/// Scores `computed` (at `times`) against `exact`: Eq. (43), divided by `scale` too, and the largest difference;
/// the band of its sampling (even and odd rows), ringing, amplitude, a flat line's score and the ending.
inline ColumnScore score_column(const std::vector<double>& times, const std::vector<double>& computed,
                                const std::vector<double>& exact, double scale) {
  ColumnScore score{"", "", computed.size(), rms_error(computed, exact), 0.0, -1.0, 0.0, computed, exact};
  score.rms_normalised = score.rms / scale;
  score.rms_even = rms_of_every_other(computed, exact, 0);
  score.rms_odd = rms_of_every_other(computed, exact, 1);
  score.ringing = ringing_of(computed, exact);
  score.amplitude = amplitude_ratio(computed, exact);
  score.amplitude_even = amplitude_ratio(every_other(computed, 0), every_other(exact, 0));
  score.amplitude_odd = amplitude_ratio(every_other(computed, 1), every_other(exact, 1));
  score.flat_rms = flat_line_score(exact);
  score.ending = score_ending(score.rms, score.flat_rms);
  score.ringing_even = ringing_of(every_other(computed, 0), every_other(exact, 0));
  score.ringing_odd = ringing_of(every_other(computed, 1), every_other(exact, 1));
  const PlateauDeviations plateaus = plateau_deviations(times, computed, exact);
  score.plateau_overshoot = plateaus.overshoot, score.plateau_deficit = plateaus.deficit;
  score.plateau_deficit_even = plateau_deviations(every_other(times, 0), every_other(computed, 0), every_other(exact, 0)).deficit;
  score.plateau_deficit_odd = plateau_deviations(every_other(times, 1), every_other(computed, 1), every_other(exact, 1)).deficit;
  for (std::size_t n = 0; n < computed.size(); ++n)
    if (std::abs(computed[n] - exact[n]) > score.max_abs) {
      score.max_abs = std::abs(computed[n] - exact[n]);
      score.t_of_max = times[n];
    }
  return score;
}

/// The largest rms_normalised taken for a result in the solution's units: above it, compare warns (unit_warning).
inline constexpr double most_plausible_rms_normalised = 10.0;

/// The warning for `score` when its rms_normalised exceeds most_plausible_rms_normalised ("" otherwise): its
/// values against the solution's as a power of ten (their root mean squares; against the solution's scale where
/// the solution's is below a hundredth of it), the quantity's unit, and the --scale that would bring them to it
/// (mm/s and mm: 1000 times m/s and m).
inline std::string unit_warning(const ColumnScore& score) {
  if (!(score.rms_normalised > most_plausible_rms_normalised)) return "";
  const std::string unit = io::quantity_unit(score.quantity);  // m, m/s or Pa
  double computed = 0.0, exact = 0.0;
  for (std::size_t n = 0; n < score.computed.size(); ++n)
    computed += score.computed[n] * score.computed[n], exact += score.exact[n] * score.exact[n];
  const double scale = score.rms / score.rms_normalised, samples = static_cast<double>(score.computed.size());
  const double reference = std::sqrt(exact / samples) >= 0.01 * scale ? std::sqrt(exact / samples) : scale;
  const double power = std::round(std::log10(std::sqrt(computed / samples) / reference));
  std::ostringstream text;
  text << "warning: column " << score.column << ": rms_normalised " << score.rms_normalised << " is more than "
       << most_plausible_rms_normalised << " times the solution's scale of " << score.quantity << " ("
       << unit << ", SI)";
  if (power >= 1.0 && power <= 300.0)
    text << "; its values are about " << std::pow(10.0, power) << " times the solution's: another unit"
         << (unit == "Pa" ? "" : " (m" + unit + " is 1000 times " + unit + ")") << "? --scale " << score.column << "="
         << std::pow(10.0, -power) << " converts it";
  else
    text << ": another unit, sign, column or point? --scale " << score.column << "=FACTOR converts a unit";
  return text.str() + "\n";
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
       << "\nplot $data" << c << " using 1:3 with lines @exact_style title 'exact', $data" << c << " using 1:2 with lines "
       << gnuplot_curve_style(0, 1) << " title " << gnuplot_quoted(scores[c].column) << "\n";
  return gp.str() + "unset multiplot\nunset output\n";
}

/// What `mpm compare` was asked, besides the scene and the point.
struct CompareRequest {
  std::string result_path, time_column = "t", plot_path;
  std::vector<std::string> column_specs, scale_specs;
  std::optional<double> tolerance;
};

/// A validator of --scale: COL=FACTOR with FACTOR a finite number > 0 (parse_number).
inline CLI::Validator column_factor() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        const auto equals = text.rfind('=');
        const auto factor = equals == std::string::npos ? std::nullopt : parse_number(text.substr(equals + 1));
        if (equals != 0 && factor && *factor > 0.0 && !has_control_character(text)) return "";
        return "give COL=FACTOR with FACTOR a number > 0 (mm/s to m/s: v=0.001), got '" + text + "'";
      },
      "COL=FACTOR");
}

/// The factor of each column --scale names (COL=FACTOR, column_factor), each a --column's or the time column,
/// none twice. \throws Refused.
inline std::map<std::string, double> checked_scales(const CompareRequest& request,
                                                    const std::vector<std::pair<std::string, std::string>>& columns) {
  std::map<std::string, double> scales;
  for (const auto& spec : request.scale_specs) {
    const auto equals = spec.rfind('=');
    const std::string column = spec.substr(0, equals);
    const bool named = column == request.time_column ||
                       std::any_of(columns.begin(), columns.end(), [&](auto& c) { return c.first == column; });
    if (!named) throw Refused("--scale " + spec + ": no --column or --time-column names '" + column + "'");
    if (scales.count(column)) throw Refused("--scale " + spec + ": column '" + column + "' is scaled twice");
    scales[column] = *parse_number(spec.substr(equals + 1));
  }
  return scales;
}

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

/// The header of compare's output: the first ten columns as they were first printed, the damping
/// measure, a flat line's score, the ending, the ringing's halves and the plateaus' deviations appended after them (a
/// reader by position keeps working).
inline constexpr const char* compare_header =
    "column,quantity,samples,rms,rms_normalised,max_abs,t_of_max,rms_even,rms_odd,ringing,amplitude,amplitude_even,"
    "amplitude_odd,flat_rms,ending,ringing_even,ringing_odd,plateau_overshoot,plateau_deficit,plateau_deficit_even,"
    "plateau_deficit_odd";

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
  const auto scales = checked_scales(request, columns);
  auto [values, lines] = read_csv_columns(request.result_path, wanted);
  for (const auto& [column, factor] : scales)
    for (double& value : values.at(column)) value *= factor;
  const std::vector<double>& times = values.at(request.time_column);
  check_sample_times(times, lines, request.result_path, request.time_column, scene->control.end_time);
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
  text << compare_header << "\n";
  for (const auto& score : scores) {
    text << score.column << "," << score.quantity << "," << score.samples << "," << score.rms << ","
         << score.rms_normalised << "," << score.max_abs << "," << score.t_of_max << "," << score.rms_even << ","
         << score.rms_odd << "," << score.ringing << "," << score.amplitude << "," << score.amplitude_even << ","
         << score.amplitude_odd << "," << score.flat_rms << "," << ending_label(score.ending) << "," << score.ringing_even << ","
         << score.ringing_odd << "," << score.plateau_overshoot << "," << score.plateau_deficit << ","
         << score.plateau_deficit_even << "," << score.plateau_deficit_odd << "\n";
    if (request.tolerance && !(score.rms_normalised <= *request.tolerance)) above << " " << score.column;
  }
  out << text.str() << std::flush;
  for (const auto& score : scores) err << unit_warning(score);
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
      "  column,quantity,samples,rms,rms_normalised,max_abs,t_of_max,rms_even,rms_odd,ringing,\n"
      "  amplitude,amplitude_even,amplitude_odd,flat_rms,ending,ringing_even,ringing_odd,\n"
      "  plateau_overshoot,plateau_deficit,plateau_deficit_even,plateau_deficit_odd\n"
      "rms: Eq. (43), sqrt(sum (c_n - e_n)^2 / N) over the N rows, in the quantity's unit; rms_normalised: rms\n"
      "divided by the solution's scale of the quantity: velocity V* (the largest |v_0| or |sigma_0|/Z of the initial\n"
      "data: v0 for the Dyka bar, so the paper's RMS/v0), stress Z V*, displacement V* L/c (dyka_bar); rho g H,\n"
      "rho g H^2/(2M), g H/c (soil_column: base stress, top settlement, wave velocity); Z|V|, |V|, |V|/omega\n"
      "(vibrating_bar); A omega, (lambda + 2G) k A, |A| (manufactured); max_abs: the largest |c_n - e_n|, "
      "at t_of_max (s).\n"
      "rms_even, rms_odd: rms on the even and on the odd rows alone, the band of the CSV's own sampling (a\n"
      "difference of two scores inside it is not resolved); ringing: the total variation of the column over the\n"
      "exact one's at the same times (1: the exact history followed; above 1 by twice each overshoot and\n"
      "oscillation; lowered by damping), nan where the exact history does not vary; both depend on the CSV's\n"
      "sampling: compare codes sampled alike. With one row, rms_odd and ringing are nan.\n"
      "amplitude: the column's RMS about its own mean over the exact one's (1: full amplitude, a constant offset\n"
      "too; below 1: damped, 0.5 at half the swing; above 1: wider), amplitude_even, amplitude_odd the same on the\n"
      "even and the odd rows, nan where the exact history does not vary there; ringing above 1 with amplitude near 1\n"
      "is oscillation, both below 1 damping. flat_rms: what a flat line at the exact mean scores (the quantity's\n"
      "unit); ending: failed when rms >= flat_rms (no approximation at all: a report's comparison of two failed\n"
      "runs is not decided), else done. ringing_even, ringing_odd: the ringing on the even and on the odd rows\n"
      "alone, the band of the ringing's sampling. plateau_overshoot, plateau_deficit: on each run of 3 or more rows\n"
      "where the exact history is constant (a plateau), on its middle half in time, the largest step beyond and the\n"
      "largest shortfall of the exact level along the jump into it, over the largest |exact|: the deficit is the\n"
      "amplitude lost (damping), the overshoot the oscillation's reach; plateau_deficit_even, plateau_deficit_odd:\n"
      "the deficit on the even and the odd rows alone, its band; nan where the exact history has no plateau.");
  app.add_option("RESULT.csv", request.result_path, "the CSV to score")->required();
  app.add_option("SCENE.toml", options.scene_path, "the scene file whose exact solution scores it")->required();
  declare_exact_options(app, options);
  app.add_option("--column", request.column_specs,
                 "COL=QUANTITY: the CSV's column COL holds QUANTITY: u_x, v_x, sigma_xx (2D also u_y, v_y, sigma_yy,\n"
                 "sigma_xy), SI units; repeat for more columns")
      ->type_name("COL=QUANTITY")
      ->required()
      ->allow_extra_args(false);
  app.add_option("--scale", request.scale_specs,
                 "COL=FACTOR: multiplies the column COL (a --column's or the time column) by FACTOR > 0 before\n"
                 "scoring, to SI units: mm/s to m/s v=0.001, ms to s t=0.001; repeat for more columns")
      ->type_name("COL=FACTOR")
      ->check(column_factor())
      ->allow_extra_args(false);
  app.add_option("--time-column", request.time_column,
                 "the column of the sample times, s: increasing, in [0, solver.end_time] (1e-6 of it beyond\n"
                 "allowed for round-off)")
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

TEST_CASE("Eq. (43): mpm compare: a series off by a constant c has rms = max_abs = c, its band, its ringing") {
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
  // Its band: the spike is on an even row (2): rms_even = sqrt(9 / 2), rms_odd = 0; the constant offset scores c on both.
  CHECK(spike.rms_even == doctest::Approx(std::sqrt(4.5)).epsilon(1e-14));
  CHECK(spike.rms_odd == 0.0);
  CHECK(score.rms_even == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(score.rms_odd == doctest::Approx(0.25).epsilon(1e-14));
  // Ringing: the offset series varies as the exact one does (TV 3 + 2.5 + 3.5 = 9): 1; an overshoot of 1 past -2
  // adds 2 x 1 to the exact TV of 9: 11 / 9; a constant exact history: nan.
  CHECK(score.ringing == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(score_column(times, {1.0, -3.0, 0.5, 4.0}, exact, 1.0).ringing == doctest::Approx(11.0 / 9.0).epsilon(1e-14));
  // its halves: even rows {1, 0.5} against {1, 0.5} follow (1); odd rows {-3, 4} against {-2, 4}: 7 / 6
  CHECK(score_column(times, {1.0, -3.0, 0.5, 4.0}, exact, 1.0).ringing_even == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(score_column(times, {1.0, -3.0, 0.5, 4.0}, exact, 1.0).ringing_odd == doctest::Approx(7.0 / 6.0).epsilon(1e-14));
  CHECK(std::isnan(score_column(times, {1.0, 2.0, 1.0, 2.0}, {1.0, 1.0, 1.0, 1.0}, 1.0).ringing));
  CHECK(std::isnan(score_column(times, {1.0, 2.0, 1.0, 2.0}, {1.0, 1.0 + 4e-16, 1.0, 1.0}, 1.0).ringing));  // round-off
  const ColumnScore one = score_column({0.5}, {2.0}, {1.5}, 1.0);  // one row: no odd row, no variation
  CHECK(one.rms_even == doctest::Approx(0.5));
  CHECK(std::isnan(one.rms_odd));
  CHECK(std::isnan(one.ringing));
  CHECK(std::isnan(one.amplitude));
  CHECK(std::isnan(one.plateau_deficit));  // no plateau of 3 rows
  // a jump to 2 held over rows 1-7, damped to 1.5 on its middle half: deficit (2 - 1.5) / 2, on either half's rows too
  const ColumnScore damped = score_column({0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, 1.5, 1.5, 1.5, 1.5, 1.5, 1}, {0, 2, 2, 2, 2, 2, 2, 2}, 1.0);
  CHECK(damped.plateau_deficit == doctest::Approx(0.25));
  CHECK(damped.plateau_overshoot == 0.0);
  CHECK(damped.plateau_deficit_even == doctest::Approx(0.25));
  CHECK(damped.plateau_deficit_odd == doctest::Approx(0.25));
  CHECK(one.flat_rms == 0.0);
  CHECK(one.ending == Ending::done);  // a constant exact history (flat line 0): the failed-score rule does not apply
}

TEST_CASE("mpm compare: damping as amplitude on every row and on each half, a flat line's score, the ending") {
  // A constant offset 0.25 from exact {1, -2, 0.5, 4} (mean 0.875): the same spread, amplitude 1 on every row and
  // on each half; the flat line scores sqrt((0.125^2 + 2.875^2 + 0.375^2 + 3.125^2) / 4) = sqrt(4.546875).
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0}, exact{1.0, -2.0, 0.5, 4.0};
  const ColumnScore offset = score_column(times, {1.25, -1.75, 0.75, 4.25}, exact, 1.0);
  CHECK(offset.amplitude == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(offset.amplitude_even == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(offset.amplitude_odd == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(offset.flat_rms == doctest::Approx(std::sqrt(4.546875)).epsilon(1e-14));
  CHECK(offset.ending == Ending::done);
  // A square wave 0, 1 (rows 0-1 low, 2-3 high, so each half varies too) damped to half its swing about the same
  // mean: amplitude 0.5 everywhere, rms 0.25, flat line 0.5: done. Damped out to its mean: amplitude 0, rms 0.5 =
  // the flat line's: failed (no better than predicting the mean).
  const std::vector<double> t8{0, 1, 2, 3, 4, 5, 6, 7}, square{0, 0, 1, 1, 0, 0, 1, 1};
  const ColumnScore half = score_column(t8, {0.25, 0.25, 0.75, 0.75, 0.25, 0.25, 0.75, 0.75}, square, 1.0);
  CHECK(half.amplitude == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(half.amplitude_even == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(half.amplitude_odd == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(half.rms == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(half.flat_rms == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(half.ending == Ending::done);
  CHECK(half.ringing == doctest::Approx(0.5).epsilon(1e-14));  // damping lowers ringing too
  const ColumnScore flat = score_column(t8, std::vector<double>(8, 0.5), square, 1.0);
  CHECK(flat.amplitude < 1e-15);
  CHECK(flat.ending == Ending::failed);
  // Damped on the odd rows only: the halves tell the damping apart from the sampling (1 even, 0.5 odd).
  const ColumnScore odd = score_column(t8, {0, 0.25, 1, 0.75, 0, 0.25, 1, 0.75}, square, 1.0);
  CHECK(odd.amplitude_even == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(odd.amplitude_odd == doctest::Approx(0.5).epsilon(1e-14));
  // An exact history that alternates row by row is flat on each half: amplitude 1 over all, nan on each half.
  const ColumnScore alternating = score_column({0, 1, 2, 3}, {0, 1, 0, 1}, {0, 1, 0, 1}, 1.0);
  CHECK(alternating.amplitude == 1.0);
  CHECK(std::isnan(alternating.amplitude_even));
  CHECK(std::isnan(alternating.amplitude_odd));
  CHECK(every_other({1, 2, 3, 4, 5}, 1) == std::vector<double>{2, 4});
}

TEST_CASE("mpm compare: a CSV is read field by field, each refusal at its line") {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mpm_compare_test_" + std::to_string(::getpid()) + ".csv")).string();
  std::ofstream(path) << "t,v,w\n0,1,2\n1,1e-310,2\n";
  CHECK(read_csv_columns(path, {"t", "w"}).values.at("w") == std::vector<double>{2.0, 2.0});
  CHECK(read_csv_columns(path, {"t", "w"}).lines == std::vector<int>{2, 3});
  CHECK_THROWS_WITH_AS(read_csv_columns(path, {"t", "v"}), doctest::Contains(":3: v: '1e-310' is too small"), Refused);
  CHECK_THROWS_WITH_AS(read_csv_columns(path, {"t", "x"}),
                       doctest::Contains(":1: no column 'x' in the header (t, v, w)"), Refused);
  std::filesystem::remove(path);
}

TEST_CASE("mpm compare: sample times in [0, end time], increasing, each refusal at its line, a wrong unit warned") {
  const std::vector<int> lines{2, 3, 5};
  CHECK_NOTHROW(check_sample_times({0.0, 1e-4, 2e-4 * (1.0 + 0.9e-6)}, lines, "r.csv", "t", 2e-4));
  const std::vector<std::pair<std::vector<double>, std::string>> refused{
      {{0.0, 1e-4, 2e-4 * (1.0 + 1.1e-6)}, "r.csv:5: t: 0.00020000022 s is after"},
      {{0.0, 1e-4, 1.0}, "r.csv:5: t: 1 s is after the scene's solver.end_time = 0.0002 s: times in ms or us?"},
      {{-1e-9, 1e-4, 2e-4}, "r.csv:2: t: -1e-09 s is before t = 0"},
      {{0.0, 1e-4, 1e-4}, "r.csv:5: t: 0.0001 s repeats the time of line 3: the sample times must increase"},
      {{0.0, 1e-4, 0.5e-4}, "r.csv:5: t: 5e-05 s comes before the time 0.0001 s of line 3"}};
  for (const auto& [times, message] : refused)
    CHECK_THROWS_WITH_AS(check_sample_times(times, lines, "r.csv", "t", 2e-4), doctest::Contains(message.c_str()),
                         Refused);
  // values 1000 times the solution's (mm/s), whose scale is 5: rms_normalised = 999 / 5 = 199.8, a warning, and
  // --scale v=0.001 brings them back (1000 from the values, 1000/1, not from the scale, 1000/5); 10 is not warned.
  ColumnScore score = score_column({0.0, 1.0}, {1000.0, -1000.0}, {1.0, -1.0}, 5.0);
  score.column = "v", score.quantity = "v_x";
  CHECK(score.rms_normalised == doctest::Approx(199.8));
  CHECK(unit_warning(score) ==
        "warning: column v: rms_normalised 199.8 is more than 10 times the solution's scale of v_x (m/s, SI); its "
        "values are about 1000 times the solution's: another unit (mm/s is 1000 times m/s)? --scale v=0.001 converts "
        "it\n");
  score.rms_normalised = 10.0;
  CHECK(unit_warning(score).empty());
  // a stress-free point (the solution 0 at every sample): the values against the scale, 2e7 Pa = 1e6 x 20 Pa
  ColumnScore stress = score_column({0.0, 1.0}, {2e7, -2e7}, {0.0, 0.0}, 20.0);
  stress.column = "s", stress.quantity = "sigma_xx";
  CHECK(unit_warning(stress).find("(Pa, SI); its values are about 1e+06 times the solution's: another unit? --scale "
                                  "s=1e-06 converts it\n") != std::string::npos);
  // values of the solution's size, but of the other sign, far off: no unit suggested
  ColumnScore sign = score_column({0.0, 1.0}, {-100.0, 100.0}, {100.0, -100.0}, 1.0);
  sign.column = "v", sign.quantity = "v_x";
  CHECK(unit_warning(sign).find(": another unit, sign, column or point? --scale v=FACTOR converts a unit\n") !=
        std::string::npos);
  CompareRequest request;
  request.scale_specs = {"v=0.001", "t=1e-3"};
  const std::vector<std::pair<std::string, std::string>> columns{{"v", "v_x"}};
  CHECK(checked_scales(request, columns) == std::map<std::string, double>{{"t", 1e-3}, {"v", 1e-3}});
  request.scale_specs = {"v=2", "v=3"};
  CHECK_THROWS_WITH_AS(checked_scales(request, columns), "--scale v=3: column 'v' is scaled twice", Refused);
  request.scale_specs = {"w=2"};
  CHECK_THROWS_WITH_AS(checked_scales(request, columns), "--scale w=2: no --column or --time-column names 'w'",
                       Refused);
  CHECK(column_factor()("v=1e-3").empty());
  for (const char* wrong : {"v", "=2", "v=0", "v=-1", "v=nan", "v=1e400", "v=x", "v=2=3x"})
    CHECK_MESSAGE(column_factor()(wrong).rfind("give COL=FACTOR with FACTOR a number > 0", 0) == 0, wrong);
}

}  // namespace mpm::cli
