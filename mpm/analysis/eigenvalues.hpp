/// \file
/// The eigenvalues of a linearised step (mpm/analysis/linearised_step.hpp), declared apart so that their one
/// unit, mpm/analysis/eigenvalues.cpp, includes Eigen's eigensolver and nothing of the solver: an edit of a kernel
/// does not recompile it.
#pragma once
#include <Eigen/Core>

namespace mpm {

/// \f$ \rho(\mathbf S) = \max_j |\lambda_j| \f$ (Eigen's real Schur-based eigensolver, eigenvalues only).
/// Compiled once, in mpm/analysis/eigenvalues.cpp: Eigen's eigensolver costs every file that includes it seconds
/// of compilation.
double spectral_radius(const Eigen::MatrixXd& step);

/// The largest \f$ \Omega = \omega\Delta t \f$ among the modes of a step whose modes all keep their energy
/// (\f$ |\lambda| = 1 \f$, forward Euler): \f$ \lambda + \lambda^{-1} = 2 - \Omega^2 \f$, so \f$ \Omega = \sqrt{2 - 2\,\mathrm{Re}\,\lambda} \f$.
/// Compiled once, in mpm/analysis/eigenvalues.cpp.
double highest_mode_omega_dt(const Eigen::MatrixXd& energy_keeping_step);

}  // namespace mpm
