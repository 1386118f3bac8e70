// Observed orders with their standard errors, and the smooth suite's numbers as report text.
#pragma once
#include <doctest/doctest.h>
#include <gsl/gsl_fit.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"
#include "verification/claims.hpp"

namespace verification::smooth {

/// An observed order p of error ~ C N^-p: GSL's least squares on the logs, its standard error sqrt(c11), and the
/// number of meshes it rests on. NaN when fewer than 3 meshes are left, or when a run of the range stopped (a
/// stopped run is its own outcome, not a point of the fit).
struct OrderFit {
  double order = std::nan(""), error = std::nan("");
  int points = 0;
  int stopped = 0;  ///< runs of the range that stopped
  int failed = 0;   ///< runs of the range whose score failed (no better than a flat field): left out, as `mpm study` leaves them
  bool valid() const { return std::isfinite(order); }
  /// the order with two standard errors as its band (the one rule, mpm/analysis/verdict.hpp); no fit: stopped
  mpm::Measured measured() const {
    return valid() ? mpm::Measured{order, 2.0 * error, mpm::Ending::done} : mpm::Measured{order, 0.0, mpm::Ending::stopped};
  }
  /// "0.93 ± 0.02", or "— (2 stopped in the fitted range)", "— (2 meshes)"; "(1 failed, left out)" after either where
  /// runs of the range failed (the meshes below the range are not counted: the series' text names every stop)
  std::string text() const {
    const std::string left_out = failed ? " (" + std::to_string(failed) + " failed, left out)" : "";
    if (valid()) return number(order, "%.3g") + " ± " + number(error, "%.1g") + left_out;
    return (stopped ? "— (" + std::to_string(stopped) + " stopped in the fitted range)" : "— (" + std::to_string(points) + " meshes)") +
           left_out;
  }
  /// "the order lies on `side` of `threshold`" by the one rule: stopped where a run of the range stopped or too few
  /// meshes ran; fails where runs failed and left fewer than 3 meshes (their scores are no approximation: the series
  /// does not converge); otherwise judged with 2 standard errors as the band.
  mpm::Outcome against(mpm::Side side, double threshold) const {
    if (!valid()) return stopped == 0 && failed > 0 ? mpm::Outcome::fails : mpm::Outcome::stopped;
    return mpm::judge(measured(), side, mpm::threshold(threshold));
  }
};

constexpr int least_meshes = 3;

/// The order over the meshes `cells` with errors `error` (NaN: the run stopped), from `finest_first` cells up.
inline OrderFit fit_order(const std::vector<int>& cells, const std::vector<double>& error, int from_cells) {
  OrderFit fit;
  std::vector<double> x, y;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (cells[k] < from_cells) continue;
    if (!(error[k] > 0.0) || !std::isfinite(error[k])) {
      ++fit.stopped;
      continue;
    }
    x.push_back(std::log(cells[k])), y.push_back(std::log(error[k]));
  }
  fit.points = int(x.size());
  if (fit.stopped > 0 || fit.points < least_meshes) return fit;
  double intercept, slope, c00, c01, c11, sum_squares;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &intercept, &slope, &c00, &c01, &c11, &sum_squares);
  fit.order = -slope;
  fit.error = std::sqrt(c11);
  return fit;
}

TEST_CASE("smooth orders: a fit against its threshold by the one rule, failed runs left out") {
  OrderFit fit;
  fit.order = 0.9, fit.error = 0.1;
  CHECK(fit.against(mpm::Side::above, 0.5) == mpm::Outcome::holds);
  CHECK(fit.against(mpm::Side::above, 0.75) == mpm::Outcome::undecided);  // 0.15 <= 2 s.e.
  CHECK(fit.against(mpm::Side::above, 1.2) == mpm::Outcome::fails);
  OrderFit none;
  none.failed = 2;
  CHECK(none.against(mpm::Side::above, 0.5) == mpm::Outcome::fails);
  none.stopped = 1;
  CHECK(none.against(mpm::Side::above, 0.5) == mpm::Outcome::stopped);
  CHECK(fit_order({8, 16, 32}, {0.4, 0.2, 0.1}, 8).order == doctest::Approx(1.0));
  CHECK(fit_order({8, 16, 32}, {0.4, std::nan(""), 0.1}, 8).stopped == 1);
}

/// An error as report text: "stopped" for NaN.
inline std::string error_text(double value, const char* format = "%.3g") { return std::isfinite(value) ? number(value, format) : std::string("stopped"); }

}  // namespace verification::smooth
