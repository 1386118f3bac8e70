/// \file
/// What a study writes into its folder, each file whole (io::OutputFile, atomic: a reader sees the old file or
/// the new one):
///   study.csv   one row per case: its axis values, status, the two scores, energy drift, steps, wall_s, cpu_s, why;
///               then, appended, each score's band and ending (the report's yardstick, mpm/analysis/verdict.hpp)
///   fits.csv    per combination of the other axes and per score: the order p over the refine axis, its standard
///               error, C, the number of points, why there is no p; then, appended, p's band (2 standard errors)
///               and the number of failed cases left out
///   error.png   the two scores against the refine axis, log-log, one curve per combination (a refine axis only)
///   cost.png    the score at the integrator's time against the CPU time of the run, log-log
/// `why` may hold commas: quoted as RFC 4180 says, like every field that needs it. The columns after it were
/// appended later, so that a reader by position finds the earlier ones where they were. The
/// pictures are drawn by gnuplot from study.gp (its data inline, every string quoted by gnuplot_quoted, the key
/// outside the plots), into hidden temporaries renamed over the pictures once complete.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/analysis/ending_label.hpp"
#include "mpm/analysis/verdict.hpp"
#include "mpm/cli/gnuplot.hpp"
#include "mpm/io/output_file.hpp"
#include "mpm/study/fits.hpp"

namespace mpm::study {

/// `text` as a CSV field: quoted (quotes doubled) when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char character : text) quoted += character == '"' ? std::string("\"\"") : std::string(1, character);
  return quoted + "\"";
}

/// A number for a CSV cell, 12 digits; "" for none or a non-finite one.
inline std::string number_cell(std::optional<double> value) {
  if (!value || !std::isfinite(*value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", *value);
  return text;
}

/// The ending of a case's score by the report's rule: stopped when the case is not done (refused, stopped, failed:
/// it did not run to its end), else the score's own (done, or failed when no better than a flat line); none for a
/// done case without a score (no exact solution).
inline std::optional<Ending> case_ending(const CaseResult& result, const std::optional<Measured>& score) {
  if (result.status != "done") return Ending::stopped;
  if (!score) return std::nullopt;
  return score->ending;
}

/// A score's value and band as study.csv's cells, "" for none (and for the infinite band of a one-sample history).
inline std::string value_cell(const std::optional<Measured>& score) { return number_cell(score ? std::optional<double>(score->value) : std::nullopt); }
inline std::string band_cell(const std::optional<Measured>& score) { return number_cell(score ? std::optional<double>(score->band) : std::nullopt); }

/// A score's ending (case_ending) as study.csv's cell, "" for none.
inline std::string ending_cell(const CaseResult& result, const std::optional<Measured>& score) {
  const auto ending = case_ending(result, score);
  return ending ? ending_label(*ending) : "";
}

/// The text of study.csv.
inline std::string study_csv(const Study& study, const std::vector<Case>& cases, const std::vector<CaseResult>& results) {
  std::string text = "case";
  for (const auto& axis : study.axes) text += "," + csv_field(axis.key);
  text += ",status,rms_at_t,rms_at_integrator_time,energy_drift,steps,wall_s,cpu_s,why,rms_at_t_band,"
          "rms_at_integrator_time_band,ending_at_t,ending_at_integrator_time\n";
  for (const auto& one : cases) {
    const CaseResult& result = results[one.index];
    text += std::to_string(one.index);
    for (std::size_t k = 0; k < study.axes.size(); ++k) text += "," + csv_field(study.axes[k].values[one.choice[k]].label);
    const bool ran = result.status != "refused";
    text += "," + result.status + "," + value_cell(result.score_at_t) + "," + value_cell(result.score_shifted) + "," +
            number_cell(result.energy_drift) + "," + number_cell(result.steps) + "," + number_cell(ran ? result.wall_s : std::optional<double>()) +
            "," + number_cell(ran ? result.cpu_s : std::optional<double>()) + "," + csv_field(result.why) + "," +
            band_cell(result.score_at_t) + "," + band_cell(result.score_shifted) + "," + ending_cell(result, result.score_at_t) + "," +
            ending_cell(result, result.score_shifted) + "\n";
  }
  return text;
}

/// The labels of a combination's values on the axes other than the refine axis ("lme fe"); "all cases" for none.
inline std::string combination_label(const Study& study, const std::vector<std::size_t>& choice) {
  std::string label;
  for (std::size_t k = 0; k < study.axes.size(); ++k)
    if (static_cast<int>(k) != study.refine) label += (label.empty() ? "" : " ") + study.axes[k].values[choice[k]].label;
  return label.empty() ? "all cases" : label;
}

/// The text of fits.csv.
inline std::string fits_csv(const Study& study, const std::vector<Fit>& fits) {
  std::string text;
  for (std::size_t k = 0; k < study.axes.size(); ++k)
    if (static_cast<int>(k) != study.refine) text += csv_field(study.axes[k].key) + ",";
  text += "score,p,p_stderr,C,points,why,p_band,failed\n";
  for (const auto& fit : fits) {
    for (std::size_t k = 0; k < study.axes.size(); ++k)
      if (static_cast<int>(k) != study.refine) text += csv_field(study.axes[k].values[fit.choice[k]].label) + ",";
    const Measured order = order_of(fit);
    text += fit.score + "," + number_cell(fit.p) + "," + number_cell(fit.p_error) + "," + number_cell(fit.c) + "," +
            std::to_string(fit.points) + "," + csv_field(fit.why) + "," +
            number_cell(order.ending == Ending::done ? std::optional<double>(order.band) : std::nullopt) + "," +
            std::to_string(fit.failed) + "\n";
  }
  return text;
}

/// One curve of a plot: its title and its points.
struct Curve {
  std::string title;
  std::vector<std::pair<double, double>> points;
};

/// The curves of score `name` against the refine axis's N (`against_cpu`: against the run's CPU time), one per
/// combination of the other axes, finite positive points only (a failed score drawn too: it is a measured error,
/// though no point of a fit); curves without a point left out.
inline std::vector<Curve> score_curves(const Study& study, const std::vector<Case>& cases, const std::vector<CaseResult>& results,
                                       const std::string& name, bool against_cpu) {
  std::vector<Curve> curves;
  std::vector<std::string> titles;
  for (const auto& one : cases) {
    const std::string title = combination_label(study, one.choice);
    std::size_t k = 0;
    while (k < titles.size() && titles[k] != title) ++k;
    if (k == titles.size()) titles.push_back(title), curves.push_back({title, {}});
    const auto score = plot_point(results[one.index], name);
    const double x = against_cpu ? results[one.index].cpu_s : study.refine >= 0 ? *study.axes[study.refine].values[one.choice[study.refine]].number : 0.0;
    if (score && x > 0.0) curves[k].points.emplace_back(x, score->value);
  }
  std::vector<Curve> drawn;
  for (auto& curve : curves)
    if (!curve.points.empty()) drawn.push_back(curve);
  return drawn;
}

/// Tics for a log axis over [low, high] (low > 0): the numbers 1, 1.5, 2, 3, 5, 7 times a power of ten inside it,
/// as gnuplot's `(a, b, ...)`; gnuplot's own would be the decades only, often none inside a study's range.
inline std::string log_tics(double low, double high) {
  std::string tics;
  char text[32];
  for (int power = static_cast<int>(std::floor(std::log10(low))); power <= static_cast<int>(std::ceil(std::log10(high))); ++power)
    for (double mantissa : {1.0, 1.5, 2.0, 3.0, 5.0, 7.0}) {
      const double tic = mantissa * std::pow(10.0, power);
      if (tic >= low * (1 - 1e-9) && tic <= high * (1 + 1e-9)) std::snprintf(text, sizeof text, "%g", tic), tics += (tics.empty() ? "" : ", ") + std::string(text);
    }
  return "(" + tics + ")";
}

/// The gnuplot commands of one log-log panel of `curves` (each its own datablock, named `prefix`k); `x_tics` "":
/// log_tics over the data.
inline std::string panel_script(const std::vector<Curve>& curves, const std::string& prefix, const std::string& title,
                                const std::string& x_label, const std::string& y_label, const std::string& x_tics = "") {
  std::ostringstream gp;
  gp.precision(15);
  for (std::size_t k = 0; k < curves.size(); ++k) {
    gp << "$" << prefix << k << " << EOD\n";
    for (const auto& [x, y] : curves[k].points) gp << x << " " << y << "\n";
    gp << "EOD\n";
  }
  double low[2] = {1e300, 1e300}, high[2] = {0.0, 0.0};
  for (const auto& curve : curves)
    for (const auto& [x, y] : curve.points)
      low[0] = std::min(low[0], x), high[0] = std::max(high[0], x), low[1] = std::min(low[1], y), high[1] = std::max(high[1], y);
  gp << "set xtics " << (x_tics.empty() ? log_tics(low[0], high[0]) : x_tics) << "\nset ytics " << log_tics(low[1], high[1]) << "\n";
  gp << "set title " << cli::gnuplot_quoted(title) << "\nset xlabel " << cli::gnuplot_quoted(x_label) << "\nset ylabel "
     << cli::gnuplot_quoted(y_label) << "\nplot ";
  for (std::size_t k = 0; k < curves.size(); ++k)
    gp << (k ? ", " : "") << "$" << prefix << k << " using 1:2 with linespoints pt " << (k % 13) + 1 << " lw 1.5 title "
       << cli::gnuplot_quoted(curves[k].title);
  gp << "\n";
  return gp.str();
}

/// The whole of study.gp: error.png (when `refine_label` is not empty; its x tics `refine_tics`, the refine axis's
/// values) and cost.png into `error_file` and `cost_file`, names in gnuplot's folder; an empty panel list draws nothing.
inline std::string study_script(const std::vector<Curve>& at_t, const std::vector<Curve>& shifted, const std::vector<Curve>& cost,
                                const std::string& refine_label, const std::string& refine_tics, const std::string& error_file,
                                const std::string& cost_file) {
  const std::string y_label = "RMS of the velocity / its scale (Eq. 43)";
  std::string gp = "set grid lc rgb '#dddddd'\nset logscale xy\nset key outside right top\nset format y '%g'\n"
                   "set autoscale fix\nset offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08\n";  // axes that fit the data
  if (!refine_label.empty() && !(at_t.empty() && shifted.empty())) {
    gp += "set terminal pngcairo noenhanced size 1300,520 font ',10'\nset output " + cli::gnuplot_quoted("./" + error_file) +
          "\nset multiplot layout 1,2\n";
    if (!at_t.empty()) gp += panel_script(at_t, "t", "at the written time t", refine_label, y_label, refine_tics);
    if (!shifted.empty()) gp += panel_script(shifted, "s", "at the time the integrator's velocity approximates", refine_label, y_label, refine_tics);
    gp += "unset multiplot\nunset output\n";
  }
  if (!cost.empty()) {
    gp += "set terminal pngcairo noenhanced size 900,520 font ',10'\nset output " + cli::gnuplot_quoted("./" + cost_file) + "\n";
    gp += panel_script(cost, "c", "error against cost", "CPU time of the run (s)", y_label + ", integrator's time") + "unset output\n";
  }
  return gp;
}

TEST_CASE("study writing: CSV fields quoted where needed, fits and curves per combination, gnuplot strings quoted") {
  CHECK(csv_field("plain") == "plain");
  CHECK(csv_field("a, b \"c\"") == "\"a, b \"\"c\"\"\"");
  CHECK(number_cell(std::nullopt).empty());
  CHECK(number_cell(0.25) == "0.25");
  CHECK(log_tics(0.12, 0.29) == "(0.15, 0.2)");
  CHECK(log_tics(10, 80) == "(10, 15, 20, 30, 50, 70)");
  Study study;
  study.axes.push_back({"grid.cells", {{"[10]", "10", 10.0}, {"[20]", "20", 20.0}}, 1});
  study.axes.push_back({"solver.shape", {{"\"linear\"", "linear", {}}, {"\"it's\"", "it's", {}}}, 2});
  study.refine = 0;
  const auto cases = expand_cases(study);
  std::vector<CaseResult> results(cases.size());
  for (auto& result : results)
    result.status = "done", result.score_at_t = Measured{0.5, 0.01, Ending::done}, result.score_shifted = Measured{0.25, 0.02, Ending::failed},
    result.cpu_s = 0.1;
  results[1].status = "refused", results[1].why = "error: s.toml:3: solver.shape: must be one of a, b";
  results[1].score_at_t = results[1].score_shifted = std::nullopt;
  results[3].score_at_t = results[3].score_shifted = std::nullopt;  // done, no exact solution: no score, no ending
  const std::string csv = study_csv(study, cases, results);
  CHECK(csv.substr(0, csv.find('\n')) == "case,grid.cells,solver.shape,status,rms_at_t,rms_at_integrator_time,energy_drift,steps,wall_s,cpu_s,why,"
                                         "rms_at_t_band,rms_at_integrator_time_band,ending_at_t,ending_at_integrator_time");
  CHECK(csv.find("\n1,10,it's,refused,,,,,,,\"error: s.toml:3: solver.shape: must be one of a, b\",,,stopped,stopped\n") != std::string::npos);
  CHECK(csv.find("\n0,10,linear,done,0.5,0.25,,,0,0.1,,0.01,0.02,done,failed\n") != std::string::npos);
  CHECK(csv.find("\n3,20,it's,done,,,,,0,0.1,,,,,\n") != std::string::npos);
  results[3].score_at_t = Measured{0.5, 0.01, Ending::done}, results[3].score_shifted = Measured{0.25, 0.02, Ending::failed};
  const auto curves = score_curves(study, cases, results, "rms_at_t", false);
  REQUIRE(curves.size() == 2);
  CHECK(curves[1].title == "it's");
  CHECK(curves[1].points.size() == 1);  // its refused case left out
  const std::string gp = study_script(curves, curves, score_curves(study, cases, results, "rms_at_integrator_time", true), "grid.cells",
                                      "(10, 20)", ".error.png.partial", ".cost.png.partial");
  CHECK(gp.find("title 'it''s'") != std::string::npos);
  CHECK(gp.find("set output './.error.png.partial'") != std::string::npos);
  CHECK(gp.find("set key outside") != std::string::npos);
  Fit fit;
  fit.choice = {0, 1}, fit.score = "rms_at_t", fit.points = 1, fit.why = "1 finite point; a fit needs 3 at least";
  CHECK(fits_csv(study, {fit}) ==
        "solver.shape,score,p,p_stderr,C,points,why,p_band,failed\nit's,rms_at_t,,,,1,1 finite point; a fit needs 3 at least,,0\n");
  fit.p = 1.5, fit.p_error = 0.25, fit.c = 2.0, fit.points = 4, fit.failed = 1, fit.why = "";
  CHECK(fits_csv(study, {fit}) == "solver.shape,score,p,p_stderr,C,points,why,p_band,failed\nit's,rms_at_t,1.5,0.25,2,4,,0.5,1\n");
}

}  // namespace mpm::study
