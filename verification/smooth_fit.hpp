// Observed orders with their standard errors, and the smooth suite's numbers as report text.
#pragma once
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
  bool valid() const { return std::isfinite(order); }
  /// the order with two standard errors as its band (the one rule, mpm/analysis/verdict.hpp); no fit: stopped
  mpm::Measured measured() const {
    return valid() ? mpm::Measured{order, 2.0 * error, mpm::Ending::done} : mpm::Measured{order, 0.0, mpm::Ending::stopped};
  }
  /// "0.93 ± 0.02", or "— (2 stopped)", "— (2 meshes)"
  std::string text() const {
    if (valid()) return number(order, "%.3g") + " ± " + number(error, "%.1g");
    return stopped ? "— (" + std::to_string(stopped) + " stopped)" : "— (" + std::to_string(points) + " meshes)";
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

/// Whether fitted orders resolve `threshold`: +1 if every one is above it by more than 2 standard errors, -1 if one is
/// below it by more than 2 (or is no fit), 0 (undecided) otherwise.
inline int orders_against(std::initializer_list<OrderFit> fits, double threshold) {
  int side = 1;
  for (const OrderFit& fit : fits) {
    if (!fit.valid() || fit.order + 2.0 * fit.error < threshold) return -1;
    if (fit.order - 2.0 * fit.error <= threshold) side = 0;
  }
  return side;
}

/// Adds a sample of an order claim: stopped where a run of the series stopped (the one rule: its own outcome; a hard
/// claim counts it as failing), holds where `other` holds and the orders resolve their threshold from above, fails
/// where `other` fails or an order lies below it, undecided (orders within 2 s.e. of it) otherwise.
inline void add_orders(DomainClaim& claim, const std::string& where, double value, int side, bool other, bool stopped) {
  if (stopped) {
    claim.add_stopped(where);
    return;
  }
  if (other && side == 0)
    claim.add_undecided(where + " — an order within 2 s.e. of the threshold", value);
  else
    claim.add(where, value, other && side > 0);
}

/// An error as report text: "stopped" for NaN.
inline std::string error_text(double value, const char* format = "%.3g") { return std::isfinite(value) ? number(value, format) : std::string("stopped"); }

}  // namespace verification::smooth
