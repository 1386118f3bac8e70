/// \file
/// Observed orders of a study: for each combination of the axes other than the refine axis, the fit of
/// error ~ C N^-p over the refine axis's N, a straight line log e = log C - p log N by least squares (GSL's
/// gsl_fit_linear), with the standard error of p, sqrt(c11) of its covariance. A fit needs 3 points at least
/// (2 give a line with no error estimate): a case that is not `done`, has no finite positive score, or whose score
/// failed (no better than a flat line at the exact mean: it approximates nothing, mpm/analysis/verdict.hpp) is left
/// out, counted when it failed, and a combination with fewer than 3 points gets a row without p that says why. The
/// order's band is two standard errors (order_of): an order is compared with mpm::judge, undecided within it.
#pragma once
#include <doctest/doctest.h>
#include <gsl/gsl_fit.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"
#include "mpm/study/cases.hpp"

namespace mpm::study {

/// One fitted order.
struct Fit {
  std::vector<std::size_t> choice;  ///< the combination: per axis its value's index (the refine axis's unused)
  std::string score;                ///< which score: rms_at_t | rms_at_integrator_time
  double p = std::numeric_limits<double>::quiet_NaN(), p_error = p, c = p;
  std::size_t points = 0;
  std::size_t failed = 0;  ///< the combination's cases left out because their score failed (no better than a flat line)
  std::string why;         ///< why there is no p
};

/// The order of `fit` as a measured number: p, its band two standard errors (p_error), done; stopped without p.
inline Measured order_of(const Fit& fit) {
  if (!std::isfinite(fit.p)) return {fit.p, 0.0, Ending::stopped};
  return {fit.p, 2.0 * fit.p_error, Ending::done};
}

/// The fit of e ~ C N^-p to the points (n, e), `failed` cases left out beside them; fewer than 3 points: no p, `why`
/// says so (and how many failed).
inline Fit fit_order(const std::vector<double>& n, const std::vector<double>& e, std::size_t failed = 0) {
  Fit fit;
  fit.points = n.size(), fit.failed = failed;
  if (n.size() < 3) {
    fit.why = std::to_string(n.size()) + " finite point" + (n.size() == 1 ? "" : "s") +
              (failed ? " (" + std::to_string(failed) + " failed: no better than a flat line, left out)" : "") +
              "; a fit needs 3 at least";
    return fit;
  }
  std::vector<double> x, y;
  for (std::size_t k = 0; k < n.size(); ++k) x.push_back(std::log(n[k])), y.push_back(std::log(e[k]));
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sum_squares = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sum_squares);
  fit.p = -c1, fit.p_error = std::sqrt(cov11), fit.c = std::exp(c0);
  if (!std::isfinite(fit.p)) fit.why = "the refine axis takes one value only among the points";
  return fit;
}

/// The score `name` of a result, if the case is done and the score is finite and > 0 (a point of a log-log plot),
/// whatever its ending.
inline std::optional<Measured> plot_point(const CaseResult& result, const std::string& name) {
  const auto score = name == "rms_at_t" ? result.score_at_t : result.score_shifted;
  if (result.status != "done" || !score || !(score->value > 0.0) || !std::isfinite(score->value)) return std::nullopt;
  return score;
}

/// The score `name` of a result as a point of a fit: a plot_point whose ending is done (a failed score is no point).
inline std::optional<double> fit_point(const CaseResult& result, const std::string& name) {
  const auto score = plot_point(result, name);
  if (!score || score->ending != Ending::done) return std::nullopt;
  return score->value;
}

/// The fits of `study` (with a refine axis): per combination of the other axes, in the cases' order, each score.
inline std::vector<Fit> fit_orders(const Study& study, const std::vector<Case>& cases, const std::vector<CaseResult>& results) {
  std::map<std::vector<std::size_t>, std::vector<std::size_t>> groups;  // combination -> its cases
  std::vector<std::vector<std::size_t>> order;
  for (const auto& one : cases) {
    auto combination = one.choice;
    combination[study.refine] = 0;
    if (groups.find(combination) == groups.end()) order.push_back(combination);
    groups[combination].push_back(one.index);
  }
  std::vector<Fit> fits;
  for (const auto& combination : order)
    for (const std::string name : {"rms_at_t", "rms_at_integrator_time"}) {
      std::vector<double> n, e;
      std::size_t failed = 0;
      for (std::size_t index : groups[combination]) {
        if (const auto score = fit_point(results[index], name))
          n.push_back(*study.axes[study.refine].values[cases[index].choice[study.refine]].number), e.push_back(*score);
        else if (const auto plotted = plot_point(results[index], name)) failed += plotted->ending == Ending::failed;
      }
      Fit fit = fit_order(n, e, failed);
      fit.choice = combination, fit.score = name;
      fits.push_back(fit);
    }
  return fits;
}

TEST_CASE("study fits: the order of e = C N^-p with its standard error, none on fewer than 3 points") {
  const Fit exact = fit_order({10, 20, 40, 80}, {2.0, 0.5, 0.125, 0.03125});  // e = 200 N^-2
  CHECK(exact.p == doctest::Approx(2.0));
  CHECK(exact.p_error == doctest::Approx(0.0).epsilon(1e-9));
  CHECK(exact.c == doctest::Approx(200.0));
  CHECK(exact.points == 4);
  const Fit noisy = fit_order({10, 20, 40}, {1.0, 0.6, 0.2});
  CHECK(noisy.p_error > 0.1);
  const Fit two = fit_order({10, 20}, {1.0, 0.5});
  CHECK(std::isnan(two.p));
  CHECK(two.why == "2 finite points; a fit needs 3 at least");
  Study study;
  study.axes.push_back({"grid.cells", {{"[10]", "10", 10.0}, {"[20]", "20", 20.0}, {"[40]", "40", 40.0}}, 1});
  study.axes.push_back({"solver.shape", {{"\"linear\"", "linear", {}}, {"\"lme\"", "lme", {}}}, 2});
  study.refine = 0;
  const auto cases = expand_cases(study);
  std::vector<CaseResult> results(cases.size());
  for (const auto& one : cases) {
    const double n = *study.axes[0].values[one.choice[0]].number;
    results[one.index].status = "done";
    results[one.index].score_at_t = Measured{1.0 / n, 0.0, Ending::done};
    results[one.index].score_shifted = Measured{1.0 / (n * n), 0.0, Ending::done};
  }
  results[5].status = "stopped";  // lme at 40 cells: no point
  auto fits = fit_orders(study, cases, results);
  REQUIRE(fits.size() == 4);
  CHECK(fits[0].p == doctest::Approx(1.0));
  CHECK(fits[1].p == doctest::Approx(2.0));
  CHECK(fits[2].choice == std::vector<std::size_t>{0, 1});
  CHECK(fits[2].points == 2);
  CHECK(fits[2].failed == 0);
  CHECK(std::isnan(fits[3].p));
  results[2].score_shifted->ending = Ending::failed;  // linear at 20 cells at the integrator's time: no point, counted
  fits = fit_orders(study, cases, results);
  CHECK(fits[0].points == 3);
  CHECK(fits[1].points == 2);
  CHECK(fits[1].failed == 1);
  CHECK(fits[1].why == "2 finite points (1 failed: no better than a flat line, left out); a fit needs 3 at least");
  CHECK(plot_point(results[2], "rms_at_integrator_time"));  // still drawn
  CHECK(!fit_point(results[2], "rms_at_integrator_time"));
}

TEST_CASE("study fits: an order's band is two standard errors, and it is judged by the one rule") {
  Fit fit;
  fit.p = 1.9, fit.p_error = 0.06;
  CHECK(order_of(fit).band == doctest::Approx(0.12));
  CHECK(judge(order_of(fit), Side::below, threshold(2.0)) == Outcome::undecided);  // 0.1 <= 0.12
  fit.p_error = 0.04;
  CHECK(judge(order_of(fit), Side::below, threshold(2.0)) == Outcome::holds);  // 0.1 > 0.08
  CHECK(judge(order_of(Fit{}), Side::below, threshold(2.0)) == Outcome::stopped);  // no p
}

}  // namespace mpm::study
