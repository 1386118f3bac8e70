/// \file
/// The eigenvalues of a linearised step (mpm/analysis/linearised_step.hpp declares these functions), compiled once:
/// Eigen's eigensolver takes seconds to compile, and its header comes with the integrators.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "mpm/analysis/linearised_step.hpp"

namespace mpm {

double spectral_radius(const Eigen::MatrixXd& step) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(step, false);
  return solver.eigenvalues().cwiseAbs().maxCoeff();
}

double highest_mode_omega_dt(const Eigen::MatrixXd& energy_keeping_step) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(energy_keeping_step, false);
  double highest = 0.0;
  for (const auto& eigenvalue : solver.eigenvalues())
    highest = std::max(highest, std::sqrt(std::max(0.0, 2.0 - 2.0 * eigenvalue.real())));
  return highest;
}

}  // namespace mpm
