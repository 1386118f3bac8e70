/// \file
/// Observed orders of a study: for each combination of the axes other than the refine axis, the fit of
/// error ~ C N^-p over the refine axis's N, a straight line log e = log C - p log N by least squares (GSL's
/// gsl_fit_linear), with the standard error of p, sqrt(c11) of its covariance. A fit needs 3 points at least
/// (2 give a line with no error estimate): a case that is not `done` or has no finite positive score is left
/// out, and a combination with fewer than 3 points gets a row without p that says why.
#pragma once
#include <doctest/doctest.h>
#include <gsl/gsl_fit.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "mpm/study/cases.hpp"

namespace mpm::study {

/// One fitted order.
struct Fit {
  std::vector<std::size_t> choice;  ///< the combination: per axis its value's index (the refine axis's unused)
  std::string score;                ///< which score: rms_at_t | rms_at_integrator_time
  double p = std::numeric_limits<double>::quiet_NaN(), p_error = p, c = p;
  std::size_t points = 0;
  std::string why;  ///< why there is no p
};

/// The fit of e ~ C N^-p to the points (n, e); fewer than 3 points: no p, `why` says so.
inline Fit fit_order(const std::vector<double>& n, const std::vector<double>& e) {
  Fit fit;
  fit.points = n.size();
  if (n.size() < 3) {
    fit.why = std::to_string(n.size()) + " finite point" + (n.size() == 1 ? "" : "s") + "; a fit needs 3 at least";
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

/// The score `name` of a result, if the case is done and the score is finite and > 0 (a point of a log-log fit).
inline std::optional<double> fit_point(const CaseResult& result, const std::string& name) {
  const auto score = name == "rms_at_t" ? result.score_at_t : result.score_shifted;
  if (result.status != "done" || !score || !(*score > 0.0) || !std::isfinite(*score)) return std::nullopt;
  return score;
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
      for (std::size_t index : groups[combination])
        if (const auto score = fit_point(results[index], name))
          n.push_back(*study.axes[study.refine].values[cases[index].choice[study.refine]].number), e.push_back(*score);
      Fit fit = fit_order(n, e);
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
    results[one.index].status = "done", results[one.index].score_at_t = 1.0 / n, results[one.index].score_shifted = 1.0 / (n * n);
  }
  results[5].status = "stopped";  // lme at 40 cells: no point
  const auto fits = fit_orders(study, cases, results);
  REQUIRE(fits.size() == 4);
  CHECK(fits[0].p == doctest::Approx(1.0));
  CHECK(fits[1].p == doctest::Approx(2.0));
  CHECK(fits[2].choice == std::vector<std::size_t>{0, 1});
  CHECK(fits[2].points == 2);
  CHECK(std::isnan(fits[3].p));
}

}  // namespace mpm::study
