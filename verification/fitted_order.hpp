// The observed order of convergence of a mesh sweep, shared by the suites (make figures).
#pragma once
#include <gsl/gsl_fit.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace verification {

/// Observed order p of error ~ C N^-p over the meshes `cells`, by GSL's least squares on the logs of
/// the finite, positive errors; NaN when fewer than `least_points` of them are left.
inline double fitted_order(const std::vector<int>& cells, const std::vector<double>& error, std::size_t least_points) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (error[k] > 0.0 && std::isfinite(error[k])) x.push_back(std::log(cells[k])), y.push_back(std::log(error[k]));
  if (x.size() < least_points) return std::nan("");
  double intercept, slope, c00, c01, c11, sum_squares;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &intercept, &slope, &c00, &c01, &c11, &sum_squares);
  return -slope;
}

}  // namespace verification
