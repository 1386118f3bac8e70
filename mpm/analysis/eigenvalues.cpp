/// \file
/// The eigenvalues of a linearised step (declared by mpm/analysis/eigenvalues.hpp), compiled once: Eigen's eigensolver
/// takes seconds to compile. This unit includes nothing of the solver, so an edit of a kernel does not recompile it.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "mpm/analysis/eigenvalues.hpp"

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
