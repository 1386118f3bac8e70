/// \file
/// `mpm shape`'s request and evaluate_request()'s declaration, without the shape functions: mpm/cli/shape_evaluation.hpp
/// defines it and the library compiles it once (mpm/run_1d.cpp, mpm/run_2d.cpp), so that the command-line program
/// includes no kernel.
#pragma once
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace mpm::cli {

/// What `mpm shape` was asked.
struct ShapeRequest {
  int dimension = 1;
  std::string kind;
  double gamma = 3.0, cell_size = 1.0, particle_size = -1.0, tolerance = 1e-6;
  std::vector<std::string> at;  ///< each --at as written
  std::vector<std::vector<double>> points;
};

/// Why an LME support of locality `gamma` and tolerance `tolerance` is refused, "" if it is not: reaching beyond
/// 100 cells, its stencils would hold (2R/h)^dim entries per particle, and below gamma = 1e-16 Newton's iteration
/// fails.
inline std::string lme_support_too_wide(double gamma, double tolerance) {
  if (std::sqrt(-std::log(tolerance) / gamma) + 3.0 <= 103.0) return "";
  const double smallest = -std::log(tolerance) / (100.0 * 100.0),
               digit = std::pow(10.0, std::floor(std::log10(smallest)) - 2);
  std::ostringstream text;
  text << "too small for the support tolerance " << tolerance
       << ": the support would reach beyond 100 cells; give at least " << std::setprecision(3)
       << std::ceil(smallest / digit) * digit;  // rounded up: the value printed is accepted
  return text.str();
}

/// Prints the stencils of the request's points on a grid of its cell size reaching beyond any support around them
/// (mpm/cli/shape_evaluation.hpp).
template <int Dim>
void evaluate_request(const ShapeRequest& request, std::ostream& out);
extern template void evaluate_request<1>(const ShapeRequest&, std::ostream&);
extern template void evaluate_request<2>(const ShapeRequest&, std::ostream&);

}  // namespace mpm::cli
