// Observed orders of convergence of the Dyka suite, with their standard errors.
#pragma once
#include <gsl/gsl_fit.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace verification {

/// error ~ C N^-order by least squares on the logs (GSL gsl_fit_linear); `standard_error` is sqrt(c11), the
/// slope's standard error from the fit's residuals. No fit (NaN) on fewer than 3 finite, positive errors.
struct OrderFit {
  double order = std::nan("");
  double standard_error = std::nan("");
  int points = 0;
  int first_cells = 0, last_cells = 0;
  bool fitted() const { return std::isfinite(order); }
};

inline OrderFit fit_order(const std::vector<int>& cells, const std::vector<double>& error) {
  OrderFit fit;
  std::vector<double> x, y;
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (error[k] > 0.0 && std::isfinite(error[k])) {
      x.push_back(std::log(cells[k])), y.push_back(std::log(error[k]));
      if (fit.points++ == 0) fit.first_cells = cells[k];
      fit.last_cells = cells[k];
    }
  if (x.size() < 3) return fit;
  double intercept, slope, c00, c01, c11, sum_squares;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &intercept, &slope, &c00, &c01, &c11, &sum_squares);
  fit.order = -slope;
  fit.standard_error = std::sqrt(c11);
  return fit;
}

/// "0.32 ± 0.031 (10-160 cells)": the standard error to 2 significant digits (a small one shows, not 0.00); or "no fit (2 meshes)".
/// `unit` names what was counted ("steps" for a fit over the steps taken).
inline std::string order_text(const OrderFit& fit, const char* unit = "cells") {
  char text[96];
  if (fit.points == 0)
    std::snprintf(text, sizeof text, "no fit (no finished run)");
  else if (!fit.fitted())
    std::snprintf(text, sizeof text, "no fit (%d mesh%s)", fit.points, fit.points == 1 ? "" : "es");
  else
    std::snprintf(text, sizeof text, "%.2f ± %.2g (%d-%d %s)", fit.order, fit.standard_error, fit.first_cells, fit.last_cells, unit);
  return text;
}

}  // namespace verification
