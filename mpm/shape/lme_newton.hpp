/// \file
/// The numerical safeguards of the LME Newton solve (mpm/shape/lme_reference.hpp and its fast form
/// mpm/fast/lme_fast.hpp), apart from the equations: a capped and, if need be, damped Newton step, and the
/// backtracking (Armijo) line search on the convex log Z.
///
/// Everything is in cell units (lambda h, J / h^2), so the numbers below are dimensionless.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/core/types.hpp"

namespace mpm {

/// Whether the Hessian J is symmetric positive definite (it is symmetric by construction).
template <int Dim>
bool positive_definite(const Matrix<Dim>& J) {
  return J(0, 0) > 0.0 && J.determinant() > 0.0;
}

/// The Newton step s, no longer than max(1, |lambda|) (cell units). Far from the solution J can be nearly
/// singular, e.g. at a point on the grid edge, where lambda h grows to ~100, and the full step would throw
/// lambda where every weight but one underflows; the cap lets lambda at most double, or move by 1, per
/// iteration, and the line search does the rest.
template <int Dim>
Vector<Dim> capped_newton_step(const Vector<Dim>& step, const Vector<Dim>& lambda) {
  const double longest_squared = std::max(1.0, lambda.squaredNorm());  // |s| <= max(1, |lambda|), compared squared
  const double length_squared = step.squaredNorm();
  return length_squared > longest_squared ? Vector<Dim>(step * std::sqrt(longest_squared / length_squared)) : step;
}

/// Newton's step for r(lambda) = 0 of Eq. (38) with J of Eq. (37), \f$ s = -J^{-1} r \f$, capped
/// (capped_newton_step). If rounding has left J not positive definite, the step of the authors' damped matrix
/// J + |r| I (dimensionless here, paper/09_choices.md) is used; failing that, steepest descent -r.
template <int Dim>
Vector<Dim> lme_newton_step(const Vector<Dim>& r, Matrix<Dim> J, const Vector<Dim>& lambda) {
  if (!positive_definite(J)) J += r.norm() * Matrix<Dim>::Identity();
  Vector<Dim> step = -r;
  if (positive_definite(J)) {
    const Vector<Dim> newton = -(J.inverse() * r);
    if (newton.allFinite()) step = newton;
  }
  return capped_newton_step(step, lambda);
}

/// Armijo backtracking for a descent step s from lambda with slope r.s < 0: t halves from 1 until
/// trial_log_z(t) = log Z(lambda + t s) <= log_z + 1e-4 t slope + rounding. Returns t, or 0 when 60
/// halvings (t = 1e-18) find no decrease, i.e. rounding hides it. The last trial_log_z called is
/// that of the t returned (it leaves its weights behind).
template <class TrialLogZ>
double armijo_step_length(double log_z, double slope, TrialLogZ trial_log_z) {
  // log Z carries rounding of about eps |log Z|: below that, a decrease cannot be seen.
  const double noise = 16.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::abs(log_z));
  double t = 1.0;
  for (int halving = 0; !(trial_log_z(t) <= log_z + 1e-4 * t * slope + noise); ++halving) {
    if (halving == 60) return 0.0;
    t *= 0.5;
  }
  return t;
}

TEST_CASE("LME Newton safeguards: the capped step, the damped step, Armijo on a convex function") {
  // J = diag(4, 1), r = (2, 1): the Newton step is (-0.5, -1), |s| = 1.118 > 1 = max(1, |lambda| = 0).
  Matrix<2> J;
  J << 4.0, 0.0, 0.0, 1.0;
  const Vector<2> r(2.0, 1.0);
  const Vector<2> capped = lme_newton_step<2>(r, J, Vector<2>::Zero());
  CHECK(capped.norm() == doctest::Approx(1.0));
  CHECK(capped[1] / capped[0] == doctest::Approx(2.0));
  CHECK(lme_newton_step<2>(r, J, Vector<2>(3.0, 4.0)) == Vector<2>(-0.5, -1.0));  // |lambda| = 5: no cap
  // Not positive definite: J + |r| I. J = diag(-1, 1), |r| = sqrt(5): J + sqrt(5) I = diag(1.236, 3.236).
  J << -1.0, 0.0, 0.0, 1.0;
  const Vector<2> damped = lme_newton_step<2>(r, J, Vector<2>(10.0, 0.0));
  CHECK(damped[0] == doctest::Approx(-2.0 / (std::sqrt(5.0) - 1.0)));
  CHECK(damped[1] == doctest::Approx(-1.0 / (std::sqrt(5.0) + 1.0)));
  // Armijo on f(l) = l^4 from l = 1 with the step -1 (slope -4): t = 1 gives f = 0, accepted.
  auto quartic = [](double l) { return l * l * l * l; };
  CHECK(armijo_step_length(1.0, -4.0, [&](double t) { return quartic(1.0 - t); }) == 1.0);
  // With the step -3: t = 1 (f = 16) and t = 1/2 (f = 0.0625 <= 1 - 6e-4) : 1/2.
  CHECK(armijo_step_length(1.0, -12.0, [&](double t) { return quartic(1.0 - 3.0 * t); }) == 0.5);
  // No decrease anywhere along the step: gives up with 0.
  CHECK(armijo_step_length(1.0, -4.0, [](double) { return 2.0; }) == 0.0);
}

}  // namespace mpm
