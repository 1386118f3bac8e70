/// \file
/// The numerical safeguards of the LME Newton solve (mpm/shape/lme.hpp), apart from the equations:
/// a capped and, if need be, damped Newton step; the test for when the full step is safe; and the
/// backtracking (Armijo) line search on the convex log Z for when it is not.
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

/// The Newton step -J^{-1} r, no longer than max(1, |lambda|), from r and J as sums of the weights
/// (LmeMoments in mpm/shape/lme.hpp): \f$ S_0 \f$ (`weight_sum`), \f$ S_1 = S_0 r \f$ (`first`) and
/// \f$ S_0^2 J \f$ (`scaled_hessian`), the step being \f$ -S_0 (S_0^2 J)^{-1} S_1 \f$. Far from the solution J can be nearly
/// singular, e.g. a warm start with lambda h ~ 100 left by a point at the grid edge, and the full
/// step would throw lambda where every weight but one underflows; the cap lets lambda at most double,
/// or move by 1, per iteration, and the line search does the rest. If rounding has left J not
/// positive definite, the step of the authors' damped matrix J + |r| I (dimensionless here,
/// paper/09_choices.md) is used; failing that, steepest descent -r.
template <int Dim>
Vector<Dim> safeguarded_newton_step(double weight_sum, const Vector<Dim>& first, const Matrix<Dim>& scaled_hessian,
                                    const Vector<Dim>& lambda) {
  Vector<Dim> step = -weight_sum * (scaled_hessian.inverse() * first);
  if (!positive_definite(scaled_hessian) || !step.allFinite()) {  // rare: r and J themselves
    const Vector<Dim> r = first / weight_sum;
    Matrix<Dim> J = scaled_hessian / (weight_sum * weight_sum);
    if (!positive_definite(J)) J += r.norm() * Matrix<Dim>::Identity();
    step = -r;
    if (positive_definite(J)) {
      const Vector<Dim> newton = -(J.inverse() * r);
      if (newton.allFinite()) step = newton;
    }
  }
  const double longest_squared = std::max(1.0, lambda.squaredNorm());  // |s| <= max(1, |lambda|), compared squared
  const double length_squared = step.squaredNorm();
  return length_squared > longest_squared ? Vector<Dim>(step * std::sqrt(longest_squared / length_squared)) : step;
}

/// Whether the full Newton step s certainly passes the line search below, which can then be skipped
/// (and log Z not computed): when |s| D <= 1/2, D the diameter of the neighbourhood (2 R / h). Why:
/// along s, log Z(lambda + t s) has second derivative s^T J s and a third derivative bounded by
/// |s| D e^{2 |s| D} s^T J s (the weights move by at most e^{t |s| D}), so with s = -J^{-1} r,
/// log Z(lambda + s) - log Z(lambda) <= -(1/2 - |s| D e^{2|s|D} / 6) r.J^{-1} r <= -0.27 r.J^{-1} r, which
/// passes Armijo's -1e-4 r.J^{-1} r. Warm-started Newton (the particle moved a little since the last
/// step) is almost always there: one exp per neighbour and iteration, no log. Tested as
/// \f$ |s|^2 D^2 \le 1/4 \f$: a square root would lengthen the chain of dependent operations that
/// each evaluation is.
template <int Dim>
bool full_step_is_safe(const Vector<Dim>& step, double diameter) {
  return step.squaredNorm() * (diameter * diameter) <= 0.25;
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
  const Vector<2> capped = safeguarded_newton_step<2>(1.0, r, J, Vector<2>::Zero());
  CHECK(capped.norm() == doctest::Approx(1.0));
  CHECK(capped[1] / capped[0] == doctest::Approx(2.0));
  CHECK(safeguarded_newton_step<2>(1.0, r, J, Vector<2>(3.0, 4.0)) == Vector<2>(-0.5, -1.0));  // |lambda| = 5: no cap
  // The same r and J as sums with S_0 = 4: S_1 = 4 r, S_0^2 J = 16 J.
  CHECK(safeguarded_newton_step<2>(4.0, Vector<2>(4.0 * r), Matrix<2>(16.0 * J), Vector<2>(3.0, 4.0)) == Vector<2>(-0.5, -1.0));
  // Not positive definite: J + |r| I. J = diag(-1, 1), |r| = sqrt(5): J + sqrt(5) I = diag(1.236, 3.236).
  J << -1.0, 0.0, 0.0, 1.0;
  const Vector<2> damped = safeguarded_newton_step<2>(1.0, r, J, Vector<2>(10.0, 0.0));
  CHECK(damped[0] == doctest::Approx(-2.0 / (std::sqrt(5.0) - 1.0)));
  CHECK(damped[1] == doctest::Approx(-1.0 / (std::sqrt(5.0) + 1.0)));
  // Armijo on f(l) = l^4 from l = 1 with the step -1 (slope -4): t = 1 gives f = 0, accepted.
  auto quartic = [](double l) { return l * l * l * l; };
  CHECK(armijo_step_length(1.0, -4.0, [&](double t) { return quartic(1.0 - t); }) == 1.0);
  // With the step -3: t = 1 (f = 16) and t = 1/2 (f = 0.0625 <= 1 - 6e-4) : 1/2.
  CHECK(armijo_step_length(1.0, -12.0, [&](double t) { return quartic(1.0 - 3.0 * t); }) == 0.5);
  // No decrease anywhere along the step: gives up with 0.
  CHECK(armijo_step_length(1.0, -4.0, [](double) { return 2.0; }) == 0.0);
  CHECK(full_step_is_safe(Vector<2>(0.06, 0.08), 4.0));   // |s| D = 0.4
  CHECK(!full_step_is_safe(Vector<2>(0.12, 0.16), 4.0));  // |s| D = 0.8
}

}  // namespace mpm
