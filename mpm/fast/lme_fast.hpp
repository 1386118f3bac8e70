/// \file
/// The fast form of the local max-ent (LME) shape functions, the run's default: the same Eqs. (35)-(41) and
/// Newton's solve of Eq. (38) as the reference form, mpm/shape/lme_reference.hpp (read that first), arranged to
/// cost less per evaluation and tested against it on random particle positions (mpm/fast/lme_fast_doctests.hpp,
/// and its warm start in mpm/fast/lme_fast_warm_start_doctests.hpp).
/// What differs from the reference:
/// - Newton is warm-started from the particle's multiplier of its previous evaluation, moved to x to second order
///   (lme_multiplier_slope, lme_multiplier_curvature, from the third moments of the offsets);
/// - the particle's last shape functions, kept per particle, serve as the weights of Eq. (36) at that start, and a
///   short Newton step moves the weights by the Taylor series of exp() (lme_weights_moved), without exponentials;
/// - r and J are held as sums of unnormalised weights (LmeMoments), J in one pass near the root and as the
///   covariance of the offsets far from it (lme_moments);
/// - the line search is skipped where the full step certainly passes it (full_step_is_safe);
/// - the offsets (x - x_I)/h are written where the gradients will go.
/// The options, the beta rules and the neighbour search are shared with the reference (mpm/shape/lme_options.hpp,
/// mpm/shape/lme_neighbours.hpp), as are Newton's safeguards (mpm/shape/lme_newton.hpp).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/lme_neighbours.hpp"
#include "mpm/shape/lme_newton.hpp"
#include "mpm/shape/lme_options.hpp"
#include "mpm/shape/lme_reference.hpp"
#include "mpm/shape/shape_diagnostics.hpp"

namespace mpm::fast {

// ---- Eqs. (35)-(38), (41) in sums of weights, and the warm start ---------------------------------

/// Z and the shifted weights \f$ w_I = e^{f_I - m} \f$, \f$ m = \max_I f_I \f$ (so \f$ 0 < w_I \le 1 \f$ and
/// \f$ \sum_I w_I \ge 1 \f$: nothing overflows, and underflow only hits weights below 1e-308).
struct LmePartition {
  double largest;     ///< m, the largest exponent
  double weight_sum;  ///< \f$ \sum_I w_I = Z e^{-m} \f$
  /// \f$ \log Z = m + \log \sum_I w_I \f$ (only the line search needs it).
  double log_z() const { return largest + std::log(weight_sum); }
};

/// Eq. (36), the partition function, stably:
/// \f[ Z(x, \lambda) = \sum_I \exp\left[ -\beta |x - x_I|^2 + \lambda \cdot (x - x_I) \right] . \f]
/// Writes the shifted weights w_I to `weights`.
template <int Dim>
LmePartition lme_partition(int count, const Vector<Dim>* offsets, double beta, const Vector<Dim>& lambda,
                           double* weights) {
  double largest = -std::numeric_limits<double>::infinity();
  for (int I = 0; I < count; ++I) {
    weights[I] = lme_exponent(beta, lambda, offsets[I]);
    largest = std::max(largest, weights[I]);
  }
  double sum = 0.0;
  for (int I = 0; I < count; ++I) {
    weights[I] = std::exp(weights[I] - largest);
    sum += weights[I];
  }
  return {largest, sum};
}

/// Eq. (36) after every exponent of Eq. (40) has moved by a linear function of its offset,
/// \f$ f_I \leftarrow f_I + t_I + c \f$ with \f$ t_I = \mathbf a \cdot (\mathbf x - \mathbf x_I) \f$ (cell units) and c the
/// same for every node, which cancels from the N_I of Eq. (35) and from r and J: \f$ w_I \leftarrow w_I e^{t_I} \f$,
/// without exponentials, \f$ e^{t} \f$ being its Taylor polynomial of degree 5,
/// \f[ e^{t} \approx 1 + t + \tfrac{t^2}{2} + \tfrac{t^3}{6} + \tfrac{t^4}{24} + \tfrac{t^5}{120} , \qquad
///     \text{relative remainder} \le \tfrac{t^6}{720} e^{|t|} < 6 \cdot 10^{-18} \text{ for } |t| \le 4 \cdot 10^{-3} , \f]
/// below the rounding of exp() itself and of the exponent it would be given (about 1e-15 relative).
/// Call only when series_is_exact(a, D): then \f$ |t_I| \le |\mathbf a| D / 2 \le 4 \cdot 10^{-3} \f$ for every
/// neighbour (\f$ |\mathbf x - \mathbf x_I| \le R = D/2 \f$). Reads `before`, writes `after` (they may be the same
/// array); returns the new \f$ \sum_I w_I \f$. Two uses:
/// - a Newton step \f$ \boldsymbol\lambda \leftarrow \boldsymbol\lambda + \mathbf s \f$: \f$ \mathbf a = \mathbf s \f$, c = 0;
/// - the particle moved by \f$ \boldsymbol\delta \f$ cells since its last shape functions, and its multiplier
///   from \f$ \boldsymbol\lambda \f$ to the start \f$ \boldsymbol\lambda' \f$: with beta constant,
///   \f$ f_I(\mathbf x + \boldsymbol\delta h, \boldsymbol\lambda') - f_I(\mathbf x, \boldsymbol\lambda)
///   = (\boldsymbol\lambda' - \boldsymbol\lambda - 2\beta\boldsymbol\delta) \cdot (\mathbf x + \boldsymbol\delta h - \mathbf x_I)/h + c \f$
///   (expand \f$ |\mathbf d + \boldsymbol\delta|^2 \f$ in Eq. (40)), so the last N_I serve as weights.
template <int Dim>
double lme_weights_moved(int count, const Vector<Dim>* offsets, const Vector<Dim>& exponent_slope, const double* before,
                         double* after) {
  double sum = 0.0;
  for (int I = 0; I < count; ++I) {
    const double t = exponent_slope.dot(offsets[I]), t2 = t * t;
    // Estrin's grouping, (1 + t) + t^2 (1/2 + t/6) + t^4 (1/24 + t/120).
    after[I] = before[I] * ((1.0 + t) + t2 * ((1.0 / 2.0 + t * (1.0 / 6.0)) + t2 * (1.0 / 24.0 + t * (1.0 / 120.0))));
    sum += after[I];
  }
  return sum;
}

/// Whether lme_weights_moved is exact to rounding for the slope a: \f$ |\mathbf a| D / 2 \le 4 \cdot 10^{-3} \f$,
/// D the neighbourhood's diameter (2 R / h), tested on squares.
template <int Dim>
bool series_is_exact(const Vector<Dim>& exponent_slope, double diameter) {
  return exponent_slope.squaredNorm() * (diameter * diameter) <= 6.4e-5;
}

/// The gradient r and Hessian J of log Z with respect to lambda (Eqs. (37)-(38)), from the weights of
/// lme_partition, held as sums of the weights: \f$ S_0 = \sum_I w_I \f$, \f$ S_1 = \sum_I w_I (x - x_I) \f$ and
/// \f$ S_0^2 J \f$, so that \f$ r = S_1 / S_0 \f$. In this form Newton's test \f$ |r| \le \f$ tol
/// (\f$ |S_1|^2 \le \mathrm{tol}^2 S_0^2 \f$) and its step \f$ -J^{-1} r = -S_0 (S_0^2 J)^{-1} S_1 \f$ need no
/// division by S_0.
template <int Dim>
struct LmeMoments {
  double weight_sum;           ///< \f$ S_0 = \sum_I w_I \f$
  Vector<Dim> first;           ///< \f$ S_1 = \sum_I w_I (x - x_I) \f$
  Matrix<Dim> scaled_hessian;  ///< \f$ S_0^2 J \f$
  Vector<Dim> residual() const { return first / weight_sum; }                        ///< r, Eq. (38)
  Matrix<Dim> hessian() const { return scaled_hessian / (weight_sum * weight_sum); }  ///< J, Eq. (37)
  /// \f$ J^{-1} \f$, as \f$ S_0^2 (S_0^2 J)^{-1} \f$.
  Matrix<Dim> inverse_hessian() const { return (weight_sum * weight_sum) * scaled_hessian.inverse(); }
  /// Whether \f$ |r| \le \f$ `tolerance`, as \f$ |S_1|^2 \le \mathrm{tol}^2 S_0^2 \f$.
  bool converged(double tolerance) const {
    return first.squaredNorm() <= (tolerance * tolerance) * (weight_sum * weight_sum);
  }
};

/// Eq. (37) without its cancellation, for lme_moments far from the solution, as LmeMoments holds it
/// (times \f$ S_0 \f$ here, \f$ S_0^2 \f$ there): the spread of the offsets about their mean r (`residual`) under the
/// weights,
/// \f[ S_0 J = \sum_I w_I (x - x_I - r) \otimes (x - x_I - r) . \f]
template <int Dim>
Matrix<Dim> lme_covariance(int count, const Vector<Dim>* offsets, const double* weights, const Vector<Dim>& residual) {
  Matrix<Dim> spread = Matrix<Dim>::Zero();
  for (int I = 0; I < count; ++I) {
    const Vector<Dim> centred = offsets[I] - residual;
    spread += weights[I] * centred * centred.transpose();
  }
  return spread;
}

/// Eqs. (37) and (38), with \f$ p_I = w_I / \sum_J w_J \f$ the shape functions of Eq. (35) at this lambda:
/// \f[ r(x, \lambda) = \frac{\partial \log Z}{\partial \lambda} = \sum_I p_I (x - x_I), \qquad
///     J(x, \lambda) = \frac{\partial r}{\partial \lambda} = \sum_I p_I (x - x_I) \otimes (x - x_I) - r \otimes r . \f]
/// Returned as sums (LmeMoments): with \f$ S_2 = \sum_I w_I (x - x_I) \otimes (x - x_I) \f$, Eq. (37) times \f$ S_0^2 \f$ is
/// \f$ S_0^2 J = S_0 S_2 - S_1 \otimes S_1 \f$.
/// Near the solution (\f$ |r|^2 \le 10^{-6} \operatorname{tr} \sum_I p_I (x - x_I) \otimes (x - x_I) \f$, i.e. almost
/// always from a warm start) J is Eq. (37) as written, in the same pass as r: subtracting the tiny
/// \f$ r \otimes r \f$ loses nothing. Elsewhere J is computed as the covariance of the offsets under p,
/// \f$ J = \sum_I p_I (x - x_I - r) \otimes (x - x_I - r) \f$, which is Eq. (37) without its cancellation
/// (far from the solution, with nearly all weight on one node, Eq. (37) as written can round to 0 or
/// below). J is symmetric and positive definite when the neighbours span the space, so log Z is
/// convex and r = 0 has one solution.
template <int Dim>
inline LmeMoments<Dim> lme_moments(int count, const Vector<Dim>* offsets, const double* weights, double weight_sum) {
  Vector<Dim> first = Vector<Dim>::Zero();
  Matrix<Dim> second = Matrix<Dim>::Zero();
  for (int I = 0; I < count; ++I) {
    first += weights[I] * offsets[I];
    second += weights[I] * offsets[I] * offsets[I].transpose();
  }
  // |r|^2 <= 1e-6 tr(S_2 / S_0), multiplied by S_0^2: Eq. (37) as written.
  if (first.squaredNorm() <= 1e-6 * second.trace() * weight_sum)
    return {weight_sum, first, weight_sum * second - first * first.transpose()};
  return {weight_sum, first, weight_sum * lme_covariance(count, offsets, weights, Vector<Dim>(first / weight_sum))};  // far from it
}

/// Eq. (35): the shape functions at the converged multiplier, in place of the weights,
/// \f[ N_I^*(x) = \frac{\exp\left[ -\beta |x - x_I|^2 + \lambda^* \cdot (x - x_I) \right]}{Z(x, \lambda^*)} , \f]
/// the weights times `inverse_sum`, \f$ 1 / \sum_I w_I \f$.
inline void lme_values(int count, double inverse_sum, double* weights) {
  for (int I = 0; I < count; ++I) weights[I] *= inverse_sum;
}

/// Eq. (41), the gradients at the converged multiplier, with the undamped J of Eq. (37) and beta
/// constant in space: Eq. (39), \f$ \nabla N_I = N_I (\nabla f_I - \sum_J N_J \nabla f_J) \f$ with the total
/// derivatives of Eq. (40)'s \f$ f_I \f$ (\f$ d\lambda^*/dx \f$ from r = 0), becomes
/// \f[ \nabla N_I^* = -N_I^* \, (J^*)^{-1} (x - x_I) . \f]
/// Evaluated as \f$ -N_I (J^*)^{-1} (x - x_I - r) \f$: at convergence r = 0 and this is Eq. (41) itself,
/// while for the residual \f$ |r| \le \f$ tol h that Newton leaves it keeps \f$ \sum_I \nabla N_I = 0 \f$ and
/// \f$ \sum_I x_I \otimes \nabla N_I = I \f$ exact up to rounding (they would otherwise be off by
/// \f$ |J^{-1} r| \f$). Cell units in, physical out: `offsets` are (x - x_I)/h, J is in cell units, and
/// the results (written over `offsets`) are in 1/length. `inverse_hessian`: \f$ (J^*)^{-1} \f$, in cell units;
/// `inverse_spacing`: 1/h.
template <int Dim>
void lme_gradients(int count, const double* values, const Matrix<Dim>& inverse_hessian, const Vector<Dim>& residual,
                   double inverse_spacing, Vector<Dim>* offsets_then_gradients) {
  const Matrix<Dim> per_length = inverse_hessian * inverse_spacing;
  for (int I = 0; I < count; ++I) {
    const Vector<Dim> offset = offsets_then_gradients[I];
    offsets_then_gradients[I] = -values[I] * (per_length * (offset - residual));
  }
}

/// How lambda* moves with x, for the warm start of the next step (cell units, J in cell units too).
/// Differentiating r(x, lambda*(x)) = 0 of Eq. (38), with \f$ \partial r / \partial x = I - 2\beta J \f$ and
/// \f$ \partial r / \partial \lambda = J \f$ (Eq. (37)):
/// \f[ \frac{d\lambda^*}{dx} = 2\beta I - J^{-1} , \qquad
///     \lambda^*(x + \Delta x) \approx \lambda^*(x) + (2\beta I - J^{-1}) \, \Delta x , \f]
/// which leaves Newton an error of order \f$ |\Delta x|^2 \f$ instead of \f$ |\Delta x| \f$ (beta constant;
/// under the authors' beta rule it is a little less accurate, and still only a starting point).
template <int Dim>
Matrix<Dim> lme_multiplier_slope(double beta, const Matrix<Dim>& inverse_hessian) {
  return 2.0 * beta * Matrix<Dim>::Identity() - inverse_hessian;
}

/// The third moments of the offsets under the shape functions, one matrix per axis a,
/// \f$ T_a = \sum_I N_I \, (x - x_I)_a \, (x - x_I) \otimes (x - x_I) \f$ (cell units): what
/// lme_multiplier_curvature needs of the point where N was evaluated.
template <int Dim>
using LmeThirdMoments = std::array<Matrix<Dim>, static_cast<size_t>(Dim)>;

/// The third moments T_a of LmeThirdMoments, from the shape functions `values` (N_I) and the `offsets`
/// (x - x_I)/h of the point where they were evaluated.
template <int Dim>
LmeThirdMoments<Dim> lme_third_moments(int count, const Vector<Dim>* offsets, const double* values) {
  LmeThirdMoments<Dim> third;
  for (Matrix<Dim>& T : third) T.setZero();
  for (int I = 0; I < count; ++I) {
    const Matrix<Dim> weighted_square = values[I] * offsets[I] * offsets[I].transpose();
    for (int a = 0; a < Dim; ++a) third[a] += offsets[I][a] * weighted_square;
  }
  return third;
}

/// How the slope of lme_multiplier_slope itself moves with x: the second-order term of the warm start
/// (cell units). Along a move u, with \f$ v = J^{-1} u \f$ and r = 0, Eq. (40)'s exponents change by
/// \f$ df_I = \lambda \cdot u - (x - x_I) \cdot v \f$ (the first term is the same for every node and cancels), so
/// \f$ dN_I = -N_I \, (x - x_I) \cdot v \f$ and Eq. (37) gives
/// \f$ dJ[u] = -\sum_I N_I \, ((x - x_I) \cdot v) \, (x - x_I) \otimes (x - x_I) \f$; then
/// \f$ d(2\beta I - J^{-1})[u] = J^{-1} \, dJ[u] \, J^{-1} \f$ and
/// \f[ \lambda^*(x + u) \approx \lambda^*(x) + (2\beta I - J^{-1}) \, u - \tfrac12 J^{-1} t , \qquad
///     t_a = \sum_I N_I \left( (x - x_I) \cdot v \right)^2 (x - x_I)_a = v^T T_a v , \f]
/// which leaves Newton an error of order \f$ |u|^3 \f$ instead of \f$ |u|^2 \f$. Returns the last term, from the
/// third moments T (lme_third_moments) and J^-1 where N was evaluated. (beta constant; under the
/// authors' beta rule it is, like the slope, only a good start.)
template <int Dim>
Vector<Dim> lme_multiplier_curvature(const LmeThirdMoments<Dim>& third, const Matrix<Dim>& inverse_hessian,
                                     const Vector<Dim>& move) {
  const Vector<Dim> v = inverse_hessian * move;
  Vector<Dim> t;
  for (int a = 0; a < Dim; ++a) t[a] = v.dot(third[a] * v);
  return -0.5 * (inverse_hessian * t);
}

/// The Newton step of lme_newton_step from r and J as sums of the weights (LmeMoments): \f$ S_0 \f$
/// (`weight_sum`), \f$ S_1 = S_0 r \f$ (`first`) and \f$ S_0^2 J \f$ (`scaled_hessian`), the step being
/// \f$ -S_0 (S_0^2 J)^{-1} S_1 \f$, capped (capped_newton_step); where that matrix is not positive definite or
/// the step not finite, lme_newton_step on r and J themselves (damped, or steepest descent).
template <int Dim>
Vector<Dim> safeguarded_newton_step(double weight_sum, const Vector<Dim>& first, const Matrix<Dim>& scaled_hessian,
                                    const Vector<Dim>& lambda) {
  const Vector<Dim> step = -weight_sum * (scaled_hessian.inverse() * first);
  if (!positive_definite(scaled_hessian) || !step.allFinite())  // rare
    return lme_newton_step(Vector<Dim>(first / weight_sum), Matrix<Dim>(scaled_hessian / (weight_sum * weight_sum)),
                           lambda);
  return capped_newton_step(step, lambda);
}

/// Whether the full Newton step s certainly passes the line search of armijo_step_length, which can then be
/// skipped (and log Z not computed): when |s| D <= 1/2, D the diameter of the neighbourhood (2 R / h). Why:
/// along s, log Z(lambda + t s) has second derivative s^T J s and a third derivative bounded by
/// |s| D e^{2 |s| D} s^T J s (the weights move by at most e^{t |s| D}), so with s = -J^{-1} r,
/// log Z(lambda + s) - log Z(lambda) <= -(1/2 - |s| D e^{2|s|D} / 6) r.J^{-1} r <= -0.27 r.J^{-1} r, which
/// passes Armijo's -1e-4 r.J^{-1} r. Warm-started Newton (the particle moved a little since the last
/// step) is almost always there. Tested as \f$ |s|^2 D^2 \le 1/4 \f$.
template <int Dim>
bool full_step_is_safe(const Vector<Dim>& step, double diameter) {
  return step.squaredNorm() * (diameter * diameter) <= 0.25;
}

// ---- The Newton solve for lambda* ------------------------------------------------------------

/// Where Newton stopped: lambda (cell units), the partition and moments there, the iterations.
template <int Dim>
struct LmeSolution {
  Vector<Dim> lambda;
  LmePartition partition;
  LmeMoments<Dim> moments;
  int iterations = 0;
  const char* failure = nullptr;  ///< why it did not converge, or nullptr
};

/// Newton on r(lambda) = 0, Eq. (38), with J of Eq. (37), from `lambda`: lambda <- lambda + t s with
/// s = -J^{-1} r (safeguarded_newton_step). t = 1 where the full step is certainly safe (full_step_is_safe:
/// near the root, i.e. almost always from a warm start); elsewhere t halves from 1 until log Z has dropped
/// by at least 1e-4 of the first-order prediction t r.s (armijo_step_length). A step so small that
/// exp() is its Taylor series to rounding (series_is_exact) updates the weights without exponentials
/// (lme_weights_moved). Stops when |r| <= tolerance; leaves the weights of the last lambda in
/// `weights`. `start`: the weights at `lambda`, already in `weights` (lme_partition, or the particle's
/// last shape functions moved by lme_weights_moved, whose shift m is unknown: NaN).
/// `diameter`: that of the neighbourhood, 2 R / h.
template <int Dim>
inline LmeSolution<Dim> solve_lme_multiplier(int count, const Vector<Dim>* offsets, double beta, Vector<Dim> lambda,
                                      const LmePartition& start, double diameter, double tolerance, int max_iterations,
                                      double* weights) {
  LmeSolution<Dim> at{lambda, start, {}, 0, nullptr};
  at.moments = lme_moments(count, offsets, weights, at.partition.weight_sum);
  while (!at.moments.converged(tolerance)) {
    if (at.iterations == max_iterations) {
      at.failure = "";
      return at;
    }
    const Vector<Dim> step =
        safeguarded_newton_step(at.moments.weight_sum, at.moments.first, at.moments.scaled_hessian, at.lambda);
    double t = 1.0;
    if (series_is_exact(step, diameter)) {
      at.partition.weight_sum = lme_weights_moved(count, offsets, step, weights, weights);
    } else if (full_step_is_safe(step, diameter)) {
      at.partition = lme_partition(count, offsets, beta, Vector<Dim>(at.lambda + step), weights);
    } else {
      // The line search compares log Z along the step: weights from the series start have no known
      // shift m (NaN), so they are computed afresh first.
      if (std::isnan(at.partition.largest)) at.partition = lme_partition(count, offsets, beta, at.lambda, weights);
      const double log_z = at.partition.log_z();
      t = armijo_step_length(log_z, at.moments.residual().dot(step), [&](double trial) {
        at.partition = lme_partition(count, offsets, beta, Vector<Dim>(at.lambda + trial * step), weights);
        return at.partition.log_z();
      });
      if (t == 0.0) {
        at.failure = " (line search found no decrease of log Z)";
        return at;
      }
    }
    at.lambda += t * step;
    at.moments = lme_moments(count, offsets, weights, at.partition.weight_sum);
    ++at.iterations;
  }
  return at;
}


// ---- The shape function ----------------------------------------------------------------------

template <int Dim>
class LmeShape {
 public:
  static constexpr const char* name = "lme";

  /// \throws std::invalid_argument for options out of range or a support radius too short (lme_radius_squared).
  explicit LmeShape(const Grid<Dim>& grid, const LmeOptions& options = LmeOptions()) : grid_(grid), options_(options) {
    radius_squared_ = lme_radius_squared<Dim>(options);  // (R/h)^2
    capacity_ = lme_support_capacity<Dim>(options, radius_squared_);
    diameter_ = 2.0 * std::sqrt(radius_squared_);
    inverse_spacing_ = 1.0 / grid.spacing();
  }

  /// An upper bound of the neighbours of any point: the most lattice points a ball of radius R can
  /// hold, wherever its centre (computed once, in the constructor).
  int capacity() const { return capacity_; }
  /// R, the support radius (length units).
  double support_radius() const { return std::sqrt(radius_squared_) * grid_.spacing(); }
  const LmeOptions& options() const { return options_; }

  /// Sizes the per-particle multipliers, lambda = 0 for every particle.
  void initialise(const Particles<Dim>& particles) { initialise(particles.size()); }
  void initialise(int particle_count) {
    lambda_.assign(particle_count, Vector<Dim>::Zero());
    inverse_hessian_.assign(particle_count, Matrix<Dim>::Zero());
    beta_.assign(particle_count, 0.0);
    LmeThirdMoments<Dim> none;
    for (Matrix<Dim>& T : none) T.setZero();
    third_moments_.assign(particle_count, none);
    evaluated_at_.assign(particle_count, Vector<Dim>::Zero());
    last_count_.assign(particle_count, 0);
    last_nodes_.assign(static_cast<size_t>(particle_count) * capacity_, -1);
    last_values_.assign(static_cast<size_t>(particle_count) * capacity_, 0.0);
  }

  /// The particle's lambda (1/length) of its last successful evaluation: Eqs. (35)-(36).
  Vector<Dim> lagrange_multiplier(int particle) const { return lambda_[particle] * inverse_spacing_; }

  /// N_I(x) and grad N_I(x) for every node within the support radius of x: the neighbours, lambda*
  /// by Newton from the particle's last multiplier moved to x (predicted_multiplier) and the weights
  /// there (start_weights), then Eq. (35) and Eq. (41).
  /// \throws ShapeFailure if x is outside the grid, or if Newton does not converge; the
  /// particle's multiplier is then left as it was.
  int evaluate(int particle, const Vector<Dim>& x, int* nodes, double* values, Vector<Dim>* gradients) {
    if (!grid_.contains(x)) throw ShapeFailure(particle, "particle left the grid");
    Vector<Dim>* offsets = gradients;  // the offsets (x - x_I)/h live where the gradients will go
    const int count = lme_support(options_, grid_, radius_squared_, capacity_, particle, x, nodes, offsets);
    const double beta = lme_beta_in_cell_units(options_, grid_, x, count, offsets);
    const Vector<Dim> moved = (x - evaluated_at_[particle]) * inverse_spacing_;  // cells, since the last evaluation
    const Vector<Dim> start = predicted_multiplier(particle, moved);
    const LmePartition start_partition = start_weights(particle, moved, count, nodes, offsets, beta, start, values);
    const LmeSolution<Dim> solution = solve_lme_multiplier(count, offsets, beta, start, start_partition, diameter_,
                                                           options_.newton_tolerance, options_.max_iterations, values);
    if (solution.failure)
      throw lme_not_converged(particle, solution.iterations, solution.moments.residual().norm(), options_.gamma,
                              solution.failure);
    if (!positive_definite(solution.moments.scaled_hessian))
      throw lme_singular_hessian(particle, Dim, solution.moments.hessian().determinant());
    const Matrix<Dim> inverse_hessian = solution.moments.inverse_hessian();
    const double inverse_sum = 1.0 / solution.moments.weight_sum;
    lme_values(count, inverse_sum, values);
    third_moments_[particle] = lme_third_moments(count, offsets, values);  // before the gradients overwrite the offsets
    lme_gradients(count, values, inverse_hessian, Vector<Dim>(solution.moments.first * inverse_sum), inverse_spacing_, gradients);
    lambda_[particle] = solution.lambda;
    inverse_hessian_[particle] = inverse_hessian;
    beta_[particle] = beta;
    evaluated_at_[particle] = x;
    remember_shape_functions(particle, count, nodes, values);
    diagnostics_.record(count, solution.iterations);
    return count;
  }

  const ShapeDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  /// Newton's start, lambda h: the particle's last lambda*, moved to x along lme_multiplier_slope and
  /// lme_multiplier_curvature when that change is a step Newton would take in full (full_step_is_safe);
  /// otherwise the last lambda* as it is (a long jump, as between the points of a test, or the first
  /// evaluation, where J^-1 is 0). `moved`: the particle's move since its last evaluation, in cells.
  Vector<Dim> predicted_multiplier(int particle, const Vector<Dim>& moved) const {
    const Matrix<Dim>& inverse_hessian = inverse_hessian_[particle];
    const Vector<Dim> change = lme_multiplier_slope(beta_[particle], inverse_hessian) * moved +
                               lme_multiplier_curvature(third_moments_[particle], inverse_hessian, moved);
    const Vector<Dim>& last = lambda_[particle];
    return full_step_is_safe(change, diameter_) ? Vector<Dim>(last + change) : last;
  }

  /// Eq. (36) at Newton's start, into `weights`: the particle's last shape functions moved to x and
  /// `start` by lme_weights_moved, without exponentials, when it has the same neighbours, beta is
  /// constant and the move is within the series' reach (particles move a small fraction of a cell per
  /// step); by lme_partition otherwise (the first evaluation, a neighbour gained or lost, a long jump).
  LmePartition start_weights(int particle, const Vector<Dim>& moved, int count, const int* nodes, const Vector<Dim>* offsets,
                             double beta, const Vector<Dim>& start, double* weights) const {
    const size_t first = static_cast<size_t>(particle) * capacity_;
    if (options_.beta_rule == LmeOptions::BetaRule::grid_spacing && same_neighbours(particle, count, nodes)) {
      const Vector<Dim> slope = start - lambda_[particle] - 2.0 * beta * moved;  // moved: delta
      if (series_is_exact(slope, diameter_)) {
        return {std::numeric_limits<double>::quiet_NaN(), lme_weights_moved(count, offsets, slope, &last_values_[first], weights)};
      }
    }
    return lme_partition(count, offsets, beta, start, weights);
  }

  /// Whether `nodes` are the particle's neighbours at its last evaluation.
  bool same_neighbours(int particle, int count, const int* nodes) const {
    if (last_count_[particle] != count) return false;
    const int* last = &last_nodes_[static_cast<size_t>(particle) * capacity_];
    for (int I = 0; I < count; ++I)
      if (nodes[I] != last[I]) return false;
    return true;
  }

  /// Keeps the particle's neighbours and shape functions for start_weights at its next evaluation.
  void remember_shape_functions(int particle, int count, const int* nodes, const double* values) {
    const size_t first = static_cast<size_t>(particle) * capacity_;
    last_count_[particle] = count;
    std::copy(nodes, nodes + count, &last_nodes_[first]);
    std::copy(values, values + count, &last_values_[first]);
  }

  Grid<Dim> grid_;
  LmeOptions options_;
  double radius_squared_ = 0.0;  ///< (R/h)^2 = -ln(tol)/gamma
  double diameter_ = 0.0;        ///< 2R/h, the neighbourhood's diameter (Newton's full_step_is_safe)
  double inverse_spacing_ = 0.0;  ///< 1/h: multiplied by, where cell units meet lengths
  int capacity_ = 0;
  std::vector<Vector<Dim>> lambda_;  ///< per particle, lambda h (cell units): the warm start
  std::vector<Matrix<Dim>> inverse_hessian_;   ///< per particle, J^-1 (cell units) where it was last evaluated
  std::vector<double> beta_;                   ///< per particle, beta h^2 there
  std::vector<LmeThirdMoments<Dim>> third_moments_;  ///< per particle, T_a there (lme_third_moments)
  std::vector<Vector<Dim>> evaluated_at_;      ///< per particle, where it was last evaluated
  std::vector<int> last_count_;                ///< per particle, its neighbours there (0: none yet)
  std::vector<int> last_nodes_;                ///< per particle, capacity() slots: those neighbours
  std::vector<double> last_values_;            ///< per particle, capacity() slots: its N_I there
  ShapeDiagnostics diagnostics_;
};

}  // namespace mpm::fast

namespace mpm {
using fast::LmeShape;  // the run's LME shape functions: the fast form
}  // namespace mpm

#include "mpm/fast/lme_fast_doctests.hpp"
#include "mpm/fast/lme_fast_warm_start_doctests.hpp"
