/// \file
/// Local maximum-entropy (LME) shape functions of Arroyo & Ortiz (2006): the paper's Eqs. (34)-(41)
/// (paper/04_shape_functions.md), in its order, then the Newton solve that finds the multiplier
/// lambda*, then the shape class.
///
/// At a point x with neighbour nodes I, the LME functions are the least biased (most entropic,
/// Eq. (34)) non-negative partition of unity that reproduces x, biased towards near nodes by the
/// Gaussian prior \f$ e^{-\beta |x - x_I|^2} \f$:
/// \f[
///   N^* = \arg\min \; \beta \sum_I N_I |x - x_I|^2 + \sum_I N_I \log N_I
///   \quad \text{s.t.} \quad N_I \ge 0, \;\; \sum_I N_I = 1, \;\; \sum_I N_I x_I = x .
/// \f]
/// The dual of this problem is the convex, unconstrained minimisation of log Z over the Lagrange
/// multiplier lambda (Eq. (36)); its minimiser gives N by Eq. (35) and grad N by Eq. (41).
/// \f$ \beta = \gamma / h^2 \f$: gamma -> infinity tends to the linear (Delaunay) interpolant, gamma ~ 1
/// smooths over a few cells. The solution exists when x is inside the convex hull of its neighbours.
///
/// Numerics (paper/09_choices.md, 'Newton for the multiplier'). Everything runs in cell units: offsets \f$ \hat l_I = (x - x_I)/h \f$,
/// \f$ \hat\beta = \beta h^2 \f$ (= gamma), \f$ \hat\lambda = \lambda h \f$, so r/h and J/h^2 are dimensionless
/// and the Newton tolerance is relative to h. Exponents are shifted by their maximum before exp.
/// Newton is warm-started from the particle's multiplier of the previous call; its safeguards (a
/// capped step, a line search on the convex log Z where the full step is not certainly safe) are in
/// mpm/shape/lme_newton.hpp, the neighbour search and the bound on the neighbours in
/// mpm/shape/lme_neighbours.hpp. The property tests and their helpers follow the kernels.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/lme_neighbours.hpp"
#include "mpm/shape/lme_newton.hpp"
#include "mpm/shape/shape_diagnostics.hpp"
#include "mpm/shape/shape_properties.hpp"

namespace mpm {

struct LmeOptions {
  double gamma = 3.0;               ///< regularisation, \f$ \gamma = \beta h^2 \f$ (paper/04_shape_functions.md: beta = gamma / h^2)
  double support_tolerance = 1e-6;  ///< the prior \f$ e^{-\beta R^2} \f$ at the support radius R (A\&O06; authors: 1e-5)
  double newton_tolerance = 1e-10;  ///< convergence when \f$ |r| / h \f$ is at most this (paper/04_shape_functions.md)
  int max_iterations = 100;         ///< Newton updates of lambda per evaluation before ShapeFailure
  /// grid_spacing: beta = gamma / h^2 (the paper, A\&O06). mean_neighbour_distance: beta = gamma / hbar^2,
  /// hbar the mean distance from x to its current neighbours (the formula of the authors' LME_Beta on this
  /// project's neighbours, paper/09_choices.md). authors: the same formula on the authors' node patch
  /// (authors_beta_in_cell_units). The neighbours are those within R = h sqrt(-ln(support_tolerance) / gamma)
  /// under every rule (with hbar in R the radius would feed on itself: hbar ~ 2R/3 in 2D makes R grow unless
  /// the patch is capped).
  enum class BetaRule { grid_spacing, mean_neighbour_distance, authors } beta_rule = BetaRule::grid_spacing;
};

// ---- Eqs. (34)-(41) --------------------------------------------------------------------------

/// Eq. (34), Shannon's entropy of the shape functions at a point, which LME maximises (less
/// \f$ \beta \sum_I N_I |x - x_I|^2 \f$) among the non-negative partitions of unity that reproduce x:
/// \f[ H(N_1, \dots, N_n) = -\sum_I N_I \log N_I \qquad (0 \log 0 = 0). \f]
inline double lme_entropy(int count, const double* values) {
  double entropy = 0.0;
  for (int I = 0; I < count; ++I)
    if (values[I] > 0.0) entropy -= values[I] * std::log(values[I]);
  return entropy;
}

/// Eq. (40), in cell units: the exponent of node I,
/// \f[ f_I(x, \lambda) = -\beta |x - x_I|^2 + \lambda \cdot (x - x_I) . \f]
template <int Dim>
inline double lme_exponent(double beta, const Vector<Dim>& lambda, const Vector<Dim>& offset) {
  return -beta * offset.squaredNorm() + lambda.dot(offset);
}

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
    // Estrin's grouping, (1 + t) + t^2 (1/2 + t/6) + t^4 (1/24 + t/120): three products deep instead of five.
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
/// division by S_0: an iteration waits on one division (the inverse) instead of two in a row.
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
/// convex and r = 0 has one solution. (The second pass is a function of its own, lme_covariance, and
/// lme_moments is declared inline, so that GCC inlines it into Newton's loop: benchmarks/README.md.)
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
/// `diameter`: that of the neighbourhood, 2 R / h. (Declared inline, so that GCC inlines it into
/// LmeShape::evaluate: benchmarks/README.md.)
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

/// The authors' beta of the prior of Eq. (36), in cell units (NL-PartSol, commit 1d5da04: src/ShapeFun/LME.c,
/// LME_Beta and LME_Tributary_Nodes; src/MPM/Mesh_Tools.c calls them at each step, src/ShapeFun/Operators.c at
/// each evaluation):
/// \f[ \beta = \frac{\gamma}{\bar h^2}, \qquad \bar h = \frac{1}{|P|} \sum_{I \in P} |x - x_I| , \f]
/// P the nodes of the cell that holds x and of the cells that share a node with it, on the grid (fewer at its
/// edges). In 1D the distances are those on the authors' one-cell-high strip, each node counted at y = +-h/2 (twice,
/// which leaves the mean as it is): \f$ |x - x_I| = \sqrt{(x - x_I)^2 + h^2/4} \f$. The authors' patch also drops
/// the nodes beyond \f$ \sqrt{-\ln 10^{-5} / \beta} \f$ of the last evaluation; on the strip that drops none
/// (\f$ \beta h^2 \le 3.01 \f$ gives at least 1.96 h, the farthest node is at 1.58 h), in 2D it can drop the
/// corners of the 4 x 4 block at a first evaluation, which this rule keeps.
template <int Dim>
double authors_beta_in_cell_units(const Grid<Dim>& grid, const Vector<Dim>& x, double gamma) {
  static_assert(Dim == 1 || Dim == 2, "the authors' patch is defined in 1D (their strip) and 2D");
  const auto cell = grid.cell_of(x);
  std::array<int, 2> first{0, 0}, last{0, 0};  // node lattice range of the patch, per axis
  Vector<Dim> local = (x - grid.origin()) / grid.spacing();
  for (int axis = 0; axis < Dim; ++axis) {
    first[axis] = std::max(cell[axis] - 1, 0);
    last[axis] = std::min(cell[axis] + 1, grid.cells(axis) - 1) + 1;
  }
  const double strip = Dim == 1 ? 0.25 : 0.0;  // (y - y_I)^2 / h^2 on the authors' strip
  double sum = 0.0;
  int count = 0;
  for (int j = first[1]; j <= last[1]; ++j)
    for (int i = first[0]; i <= last[0]; ++i) {
      double squared = (local[0] - i) * (local[0] - i) + strip;
      if (Dim == 2) squared += (local[Dim - 1] - j) * (local[Dim - 1] - j);
      sum += std::sqrt(squared);
      ++count;
    }
  const double mean = sum / count;
  return gamma / (mean * mean);
}

// ---- The shape function ----------------------------------------------------------------------

template <int Dim>
class LmeShape {
 public:
  static constexpr const char* name = "lme";

  /// \throws std::invalid_argument if an option is out of range, or if the support radius
  /// \f$ R = h \sqrt{-\ln(\mathrm{tol}) / \gamma} \f$ is shorter than the cell diagonal \f$ h \sqrt{Dim} \f$: then a
  /// point could lie outside the convex hull of its neighbours, where LME does not exist.
  explicit LmeShape(const Grid<Dim>& grid, const LmeOptions& options = LmeOptions()) : grid_(grid), options_(options) {
    auto refuse = [](const std::string& what) { throw std::invalid_argument("LME: " + what); };
    std::ostringstream value;
    value << "gamma = " << options.gamma << ", support_tolerance = " << options.support_tolerance
          << ", newton_tolerance = " << options.newton_tolerance << ", max_iterations = " << options.max_iterations;
    if (!(options.gamma > 0.0 && std::isfinite(options.gamma))) refuse("gamma must be > 0 (" + value.str() + ")");
    if (!(options.support_tolerance > 0.0 && options.support_tolerance < 1.0))
      refuse("support_tolerance must be in (0, 1) (" + value.str() + ")");
    if (!(options.newton_tolerance > 0.0)) refuse("newton_tolerance must be > 0 (" + value.str() + ")");
    if (options.max_iterations < 1) refuse("max_iterations must be >= 1 (" + value.str() + ")");
    radius_squared_ = -std::log(options.support_tolerance) / options.gamma;  // (R/h)^2
    if (radius_squared_ < Dim) {
      std::ostringstream message;
      message.precision(4);
      message << "support radius R = h sqrt(-ln(support_tolerance)/gamma) = " << std::sqrt(radius_squared_)
              << " h is shorter than the cell diagonal " << std::sqrt(double(Dim))
              << " h, so a point may fall outside the convex hull of its neighbours: gamma = " << options.gamma
              << " is too large for support_tolerance = " << options.support_tolerance << " (need gamma <= "
              << -std::log(options.support_tolerance) / Dim << ", or support_tolerance <= "
              << std::exp(-options.gamma * Dim) << ")";
      refuse(message.str());
    }
    capacity_ = lattice_points_in_ball_bound<Dim>(std::sqrt(radius_squared_));
    diameter_ = 2.0 * std::sqrt(radius_squared_);
    inverse_spacing_ = 1.0 / grid.spacing();
  }

  /// The neighbours are not listed in ascending node order (compute_stencils searches them for the nodes it reaches).
  static constexpr bool nodes_ascending = false;

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
    const int count = lme_neighbours(grid_, radius_squared_, capacity_, particle, x, nodes, offsets);
    const double beta = beta_in_cell_units(x, count, offsets);
    const Vector<Dim> moved = (x - evaluated_at_[particle]) * inverse_spacing_;  // cells, since the last evaluation
    const Vector<Dim> start = predicted_multiplier(particle, moved);
    const LmePartition start_partition = start_weights(particle, moved, count, nodes, offsets, beta, start, values);
    const LmeSolution<Dim> solution = solve_lme_multiplier(count, offsets, beta, start, start_partition, diameter_,
                                                           options_.newton_tolerance, options_.max_iterations, values);
    if (solution.failure) throw not_converged(particle, solution.iterations, solution.moments, solution.failure);
    if (!positive_definite(solution.moments.scaled_hessian)) {
      std::ostringstream cause;
      cause << "LME Hessian J is singular at convergence (x on the edge of the convex hull of its neighbours): det(J)/h^"
            << 2 * Dim << " = " << solution.moments.hessian().determinant();
      throw ShapeFailure(particle, cause.str());
    }
    const Matrix<Dim> inverse_hessian = solution.moments.inverse_hessian();
    const double inverse_sum = 1.0 / solution.moments.weight_sum;  // alongside the inverse, not after it
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

  /// Whether `nodes` are the particle's neighbours at its last evaluation (a loop: std::equal calls memcmp,
  /// whose set-up costs more than comparing a few numbers).
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

  /// beta h^2: gamma, or gamma (h / hbar)^2 under the authors' formula (on this project's neighbours or on the
  /// authors' patch). Then beta varies with x and Eq. (41), which takes beta constant, is not the exact gradient;
  /// the authors' code makes the same approximation.
  double beta_in_cell_units(const Vector<Dim>& x, int count, const Vector<Dim>* offsets) const {
    if (options_.beta_rule == LmeOptions::BetaRule::grid_spacing) return options_.gamma;
    if (options_.beta_rule == LmeOptions::BetaRule::authors)
      return authors_beta_in_cell_units(grid_, x, options_.gamma);
    double mean = 0.0;
    for (int I = 0; I < count; ++I) mean += offsets[I].norm();
    mean /= count;
    return options_.gamma / (mean * mean);
  }

  ShapeFailure not_converged(int particle, int iterations, const LmeMoments<Dim>& moments, const char* why) const {
    std::ostringstream cause;
    cause.precision(3);
    cause << "LME Newton did not converge: " << iterations << " iterations, |r|/h = " << moments.residual().norm()
          << ", gamma = " << options_.gamma << why;
    return ShapeFailure(particle, cause.str());
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

// ---- Tests: helpers, then the equations, then the properties ---------------------------------

namespace testing {

/// Distance, in cells, from x to the nearest sphere |x - x_I| = R around a grid node: crossing one
/// adds or drops a node whose N is about support_tolerance e^{lambda.(x - x_I)}, so N jumps there.
template <int Dim>
double distance_to_lme_support_edge(const Grid<Dim>& grid, const Vector<Dim>& x, double radius) {
  double nearest = 1e300;
  for (int node = 0; node < grid.node_count(); ++node)
    nearest = std::min(nearest, std::abs((x - grid.node_position(node)).norm() - radius));
  return nearest / grid.spacing();
}

/// The shape properties at x, with Newton converged to |r|/h <= 1e-13 (the shape must be built so).
/// Tolerances and why:
///  - sum N - 1: normalised by Z, so rounding only; sum N x_I - x is r, at most 1e-13 h, plus the
///    rounding of the absolute coordinates: 1.1e-13.
///  - sum grad N and sum x_I (x) grad N - I: exact for any r by the form of lme_gradients, so
///    rounding only, about eps (|x|/h) n |J^-1| <~ 1e-14 here: 1e-13.
///  - finite differences (step 1e-6 h): LME is smooth, so the truncation error is ~1e-12; the error
///    of N itself, ~ N_I |x - x_I - r| |r| / (h lambda_min(J)) <~ 4e-13, divided by the step 2e-6 h,
///    dominates: 5e-7. Skipped within 2e-6 h of the grid's edge (the difference would leave it) and
///    within 1e-5 h of a support sphere (N jumps by ~support_tolerance there).
template <int Dim>
void check_lme_properties(LmeShape<Dim>& shape, const Grid<Dim>& grid, const Vector<Dim>& x) {
  REQUIRE(shape.options().newton_tolerance <= 1e-13);
  PropertyTolerances tolerance;
  tolerance.unity = 1.1e-13;
  tolerance.gradient = 1e-13;
  tolerance.finite_difference = 5e-7;
  const double h = grid.spacing();
  const double room = std::min((x - grid.origin()).minCoeff(), (grid.upper_corner() - x).minCoeff()) / h;
  tolerance.check_finite_difference = room > 2e-6 && distance_to_lme_support_edge(grid, x, shape.support_radius()) > 1e-5;
  check_shape_properties(shape, grid, 0, x, tolerance);
}

/// At a node or a cell centre, every neighbour has its mirror image through x, so r(0) = 0: lambda* = 0,
/// \f$ N_I = e^{-\gamma |x - x_I|^2 / h^2} / Z \f$ over the nodes within R, and
/// \f$ \nabla N_I = -N_I J^{-1} (x - x_I) \f$ with \f$ J = \sum_I N_I (x - x_I) \otimes (x - x_I) \f$, all by hand.
/// N is symmetric and grad N antisymmetric through x. The point is reached warm from `start`, where
/// lambda is far from 0, so Newton must bring it back.
/// It stops at |r|/h <= tol, so (cell units, to first order) |lambda h| <= b = tol / lambda_min(J); N_I is
/// then off by at most b m relatively, m the largest |x - x_I|/h; J by about 2 b m |J|; and grad N_I h by
/// at most (N_I / lambda_min) (3 b m |x - x_I|/h + tol). These are the tolerances, plus rounding.
template <int Dim>
void check_lme_symmetric_point(LmeShape<Dim>& lme, const Grid<Dim>& grid, const Vector<Dim>& start, const Vector<Dim>& x,
                               int expected_count) {
  const double h = grid.spacing(), gamma = lme.options().gamma, tol = lme.options().newton_tolerance;
  std::vector<int> nodes(lme.capacity());
  std::vector<double> values(lme.capacity());
  std::vector<Vector<Dim>> gradients(lme.capacity());
  lme.evaluate(0, start, nodes.data(), values.data(), gradients.data());
  REQUIRE(lme.lagrange_multiplier(0).norm() * h > 0.1);
  const int count = lme.evaluate(0, x, nodes.data(), values.data(), gradients.data());
  INFO("x = ", x.transpose());
  REQUIRE(count == expected_count);

  double Z = 0.0, m = 0.0;
  for (int k = 0; k < count; ++k) {
    const Vector<Dim> offset = (x - grid.node_position(nodes[k])) / h;
    Z += std::exp(-gamma * offset.squaredNorm());
    m = std::max(m, offset.norm());
  }
  Matrix<Dim> J = Matrix<Dim>::Zero();
  for (int k = 0; k < count; ++k) {
    const Vector<Dim> offset = (x - grid.node_position(nodes[k])) / h;
    J += std::exp(-gamma * offset.squaredNorm()) / Z * offset * offset.transpose();
  }
  const double trace = J.trace(), lambda_min = 0.5 * trace - std::sqrt(std::max(0.0, 0.25 * trace * trace - J.determinant()));
  const double b = tol / lambda_min;
  CHECK(lme.lagrange_multiplier(0).norm() * h <= b);
  for (int k = 0; k < count; ++k) {
    const Vector<Dim> offset = (x - grid.node_position(nodes[k])) / h;
    const double N = std::exp(-gamma * offset.squaredNorm()) / Z;
    const Vector<Dim> gradient = -N * (J.inverse() * offset) / h;
    INFO("node ", nodes[k], ", N = ", N);
    CHECK(std::abs(values[k] - N) <= N * (b * m + 4e-16));
    CHECK((gradients[k] - gradient).norm() * h <= N / lambda_min * (3.0 * b * m * offset.norm() + tol) + 1e-15);
    int mirrors = 0;  // the node at 2x - x_I has the same N and the opposite gradient
    for (int j = 0; j < count; ++j)
      if (((grid.node_position(nodes[j]) + grid.node_position(nodes[k])) / h - 2.0 * x / h).norm() < 1e-9) {
        ++mirrors;
        CHECK(std::abs(values[j] - values[k]) <= 2.0 * N * (b * m + 4e-16));
        CHECK((gradients[j] + gradients[k]).norm() * h <= 2.0 * N / lambda_min * (3.0 * b * m * offset.norm() + tol) + 2e-15);
      }
    CHECK(mirrors == 1);
  }
}

}  // namespace testing

TEST_CASE("Eq. (35), Eq. (36) by hand: at a node and at a cell centre lambda = 0 and N is the normalised Gaussian prior, grad N by Eq. (41)") {
  // Tolerances: what |r|/h <= 1e-13 allows (testing::check_lme_symmetric_point), a few 1e-13 at most.
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  const double h = 0.5;
  const Grid<1> line(Vector<1>(0.0), h, {10});
  LmeShape<1> lme(line, options);
  lme.initialise(1);
  CHECK(lme.capacity() == 5);  // floor(2 R / h) + 1 with R = 2.146 h
  testing::check_lme_symmetric_point(lme, line, Vector<1>(1.3), Vector<1>(2.5), 5);   // node 5
  testing::check_lme_symmetric_point(lme, line, Vector<1>(1.3), Vector<1>(2.25), 4);  // centre of cell 4

  // 2D: 13 nodes around a node (|k|^2 <= 4.6: 0, 1, 2, 4), 16 around a cell centre, the most possible.
  const Grid<2> plane(Vector<2>(0.0, 0.0), h, {10, 10});
  LmeShape<2> lme2(plane, options);
  lme2.initialise(1);
  CHECK(lme2.capacity() == 16);
  testing::check_lme_symmetric_point(lme2, plane, Vector<2>(1.3, 2.1), Vector<2>(2.5, 2.5), 13);
  testing::check_lme_symmetric_point(lme2, plane, Vector<2>(1.3, 2.1), Vector<2>(2.25, 2.75), 16);
}

TEST_CASE("Eq. (41) against finite differences, and every shape property, in 1D and 2D, near and at the grid edge, on faces and at nodes") {
  LmeOptions options;
  options.newton_tolerance = 1e-13;  // so that finite differences of N can check grad N (see check_lme_properties)
  const Grid<1> line(Vector<1>(-1.0), 0.25, {16});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  for (double gamma : {0.8, 3.0, 5.0, 10.0}) {  // the authors' values, and a sharp one (1D only: 2D needs gamma <= 6.9)
    options.gamma = gamma;
    LmeShape<1> lme(line, options);
    lme.initialise(1);
    for (double x : {-1.0, -1.0 + 1e-9, -1.0 + 2.5e-4, -0.975, -0.9, -0.75, -0.625, -0.6, -0.13, 0.0, 0.37, 1.0, 2.5,
                     2.99, 3.0 - 2.5e-4, 3.0, 1.1, -1.0}) {
      INFO("gamma = ", gamma);
      testing::check_lme_properties(lme, line, Vector<1>(x));
    }
    if (gamma > 6.9) continue;
    LmeShape<2> lme2(plane, options);
    lme2.initialise(1);
    for (const Vector<2>& x : {Vector<2>(0.0, 0.0), Vector<2>(0.0, 1.1), Vector<2>(1e-9, 1.1), Vector<2>(5e-4, 1.1),
                               Vector<2>(0.05, 0.02), Vector<2>(0.5, 0.5), Vector<2>(0.75, 0.25), Vector<2>(1.3, 0.7),
                               Vector<2>(1.0, 0.77), Vector<2>(2.99, 1.98), Vector<2>(3.0, 2.0), Vector<2>(1.61, 2.0),
                               Vector<2>(3.0, 0.3), Vector<2>(1.2, 1e-4), Vector<2>(0.0, 0.0)}) {
      INFO("gamma = ", gamma);
      testing::check_lme_properties(lme2, plane, x);
    }
  }

  // With the default Newton tolerance 1e-10: reproduction is what it guarantees, |sum N x_I - x| <= 1e-10 h;
  // the gradient identities stay exact (rounding only). Finite differences would see N's 1e-10 error / 2e-6.
  LmeShape<2> loose(plane);
  loose.initialise(1);
  testing::PropertyTolerances tolerance;
  tolerance.unity = 1e-10 + 1e-14;
  tolerance.gradient = 1e-13;
  tolerance.check_finite_difference = false;
  for (const Vector<2>& x : {Vector<2>(0.0, 1.1), Vector<2>(0.05, 0.02), Vector<2>(1.3, 0.7), Vector<2>(1.61, 2.0)})
    testing::check_shape_properties(loose, plane, 0, x, tolerance);
}

TEST_CASE("LME tends to the linear shape functions as gamma grows") {
  // For gamma of order 1 or more, max_x max_I |N_lme - N_linear| is attained at the nodes, where lambda = 0
  // and N_I = 1 / sum_J exp(-gamma |x_I - x_J|^2 / h^2): the deviation is 1 - 1/sum ~ 2 Dim e^-gamma. For
  // gamma = 64 that is 3e-28, below what Newton resolves: there N is off by about |r|/h <= 1e-13 (two-node
  // regime: dN = r exactly), so the bound is 2e-13. The radius is held at R = 3h with tol = e^{-9 gamma},
  // so that the cut-off (neglected weights ~ e^{-6 gamma} relative) is never what limits the deviation;
  // with the default tol = 1e-6, gamma is capped by the hull condition R >= h sqrt(Dim) (gamma <= 13.8 in
  // 1D, 6.9 in 2D).
  const Grid<1> line(Vector<1>(0.0), 1.0, {12});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  LinearShape<1> hat(line);
  LinearShape<2> q4(plane);
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  double previous = 2.0, previous2 = 2.0;
  for (double gamma : {1.0, 4.0, 16.0, 64.0}) {
    options.gamma = gamma;
    options.support_tolerance = std::exp(-9.0 * gamma);
    double sum = 0.0, sum2 = 0.0;  // Z at a node, in 1D and 2D
    for (int k = -3; k <= 3; ++k) {
      sum += std::exp(-gamma * k * k);
      for (int m = -3; m <= 3; ++m)
        if (k * k + m * m <= 9) sum2 += std::exp(-gamma * (k * k + m * m));
    }
    LmeShape<1> lme(line, options);
    lme.initialise(1);
    double largest = 0.0;
    for (int k = 0; k <= 4 * 64; ++k) {
      const Vector<1> x(4.0 + k / 64.0);  // cells 4 to 8, nodes and faces included
      const auto a = testing::dense_values(lme, line, 0, x), b = testing::dense_values(hat, line, 0, x);
      for (size_t I = 0; I < a.size(); ++I) largest = std::max(largest, std::abs(a[I] - b[I]));
    }
    LmeShape<2> lme2(plane, options);
    lme2.initialise(1);
    double largest2 = 0.0;
    for (int i = 0; i <= 32; ++i)
      for (int j = 0; j <= 32; ++j) {
        const Vector<2> x(4.0 + i / 16.0, 4.0 + j / 16.0);
        const auto a = testing::dense_values(lme2, plane, 0, x), b = testing::dense_values(q4, plane, 0, x);
        for (size_t I = 0; I < a.size(); ++I) largest2 = std::max(largest2, std::abs(a[I] - b[I]));
      }
    INFO("gamma = ", gamma, ": max |N_lme - N_linear| = ", largest, " (1D), ", largest2, " (2D)");
    CHECK(largest < previous);
    CHECK(largest2 < previous2);
    CHECK(std::abs(largest - (1.0 - 1.0 / sum)) <= 2e-13);
    CHECK(std::abs(largest2 - (1.0 - 1.0 / sum2)) <= 2e-13);
    previous = largest;
    previous2 = largest2;
  }
}

TEST_CASE("LME Newton: few iterations from a warm start, and a clear failure otherwise") {
  // A particle moving by 1e-3 h per call starts Newton about 1e-3 from the root; Newton converges
  // quadratically, e_{k+1} ~ C e_k^2, so two steps reach 1e-10 when C <~ 4. Near the grid edge, or for a
  // sharper gamma, J's small eigenvalue grows C and a third step is sometimes needed (measured: never 4).
  int nodes[64];
  double values[64];
  Vector<1> gradients[64];
  Vector<2> gradients2[64];
  for (double gamma : {3.0, 5.0}) {
    LmeOptions options;
    options.gamma = gamma;
    const double h = 0.1;
    const Grid<1> line(Vector<1>(0.0), h, {20});
    LmeShape<1> interior(line, options), edge(line, options);
    interior.initialise(1);
    edge.initialise(1);
    interior.evaluate(0, Vector<1>(0.5), nodes, values, gradients);
    edge.evaluate(0, Vector<1>(0.3), nodes, values, gradients);
    const long cold = interior.diagnostics().newton_iterations_total(), cold_edge = edge.diagnostics().newton_iterations_total();
    for (int k = 1; k <= 1000; ++k) interior.evaluate(0, Vector<1>(0.5 + k * 1e-3 * h), nodes, values, gradients);  // 10 cells
    for (int k = 1; k <= 2990; ++k) edge.evaluate(0, Vector<1>(0.3 - k * 1e-3 * h), nodes, values, gradients);  // to 0.01 h
    INFO("gamma = ", gamma);
    CHECK(interior.diagnostics().newton_iterations_max() <= (gamma == 3.0 ? 2 : 3));
    CHECK(double(interior.diagnostics().newton_iterations_total() - cold) / 1000 <= (gamma == 3.0 ? 2.0 : 2.1));
    CHECK(edge.diagnostics().newton_iterations_max() <= 3);
    CHECK(double(edge.diagnostics().newton_iterations_total() - cold_edge) / 2990 <= 2.1);

    const Grid<2> plane(Vector<2>(0.0, 0.0), h, {10, 10});
    LmeShape<2> lme2(plane, options);
    lme2.initialise(1);
    lme2.evaluate(0, Vector<2>(0.3, 0.35), nodes, values, gradients2);
    const long cold2 = lme2.diagnostics().newton_iterations_total();
    for (int k = 1; k <= 2000; ++k)  // a slanted path across cells, faces and nodes' neighbourhoods
      lme2.evaluate(0, Vector<2>(0.3 + k * 0.8e-3 * h, 0.35 + k * 0.6e-3 * h), nodes, values, gradients2);
    CHECK(lme2.diagnostics().newton_iterations_max() <= (gamma == 3.0 ? 2 : 3));
    CHECK(double(lme2.diagnostics().newton_iterations_total() - cold2) / 2000 <= (gamma == 3.0 ? 2.0 : 2.1));
  }

  // Cold starts converge even far from the solution: at the grid edge (lambda -> infinity, N -> the
  // nodes on the edge) it takes ~20 steps, each multiplying |r| by about 1/e.
  LmeOptions options;
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  LmeShape<2> cold(plane, options);
  cold.initialise(1);
  cold.evaluate(0, Vector<2>(0.0, 0.0), nodes, values, gradients2);
  CHECK(cold.diagnostics().newton_iterations_max() <= 25);
  // The weak Kronecker property at the corner node: every other node I has offset -k_I with k_I >= 0,
  // k_Ix + k_Iy >= 1, so 1 - N_0 <= -(r_x + r_y) <= sqrt(2) |r| <= sqrt(2) 1e-10 h.
  CHECK(nodes[0] == 0);
  CHECK(values[0] >= 1.0 - std::sqrt(2.0) * 1e-10);

  // Not converging: a point near the edge from a cold start with one iteration allowed. The
  // multiplier is left as it was.
  options.max_iterations = 1;
  LmeShape<2> capped(plane, options);
  capped.initialise(3);
  CHECK_THROWS_WITH_AS(capped.evaluate(2, Vector<2>(0.01, 5.0), nodes, values, gradients2),
                       doctest::Contains("LME Newton did not converge: 1 iterations, |r|/h = "), ShapeFailure);
  CHECK(capped.lagrange_multiplier(2).norm() == 0.0);
  int failed_particle = -1;
  try {
    capped.evaluate(2, Vector<2>(0.01, 5.0), nodes, values, gradients2);
  } catch (const ShapeFailure& failure) {
    failed_particle = failure.particle;
    CHECK(std::string(failure.what()).find("gamma = 3") != std::string::npos);
  }
  CHECK(failed_particle == 2);
  CHECK(capped.evaluate(1, Vector<2>(5.5, 5.5), nodes, values, gradients2) == 16);  // symmetric: 0 iterations needed

  // Outside the grid, including NaN.
  CHECK_THROWS_WITH_AS(capped.evaluate(0, Vector<2>(-1e-12, 5.0), nodes, values, gradients2), "particle left the grid",
                       ShapeFailure);
  CHECK_THROWS_WITH_AS(capped.evaluate(0, Vector<2>(5.0, std::nan("")), nodes, values, gradients2),
                       "particle left the grid", ShapeFailure);
}

TEST_CASE("LME warm start: d lambda*/dx = 2 beta I - J^-1 by finite differences, and the predicted start saves Newton steps") {
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  const double h = 0.25, delta = 1e-5;  // central differences: error ~ delta^2 |d3 lambda / dx3| ~ 1e-9
  const Grid<2> plane(Vector<2>(0.0, 0.0), h, {8, 8});
  const double radius_squared = -std::log(options.support_tolerance) / options.gamma;
  int nodes[64];
  double values[64];
  Vector<2> offsets[64];
  for (const Vector<2>& x : {Vector<2>(1.0, 1.0), Vector<2>(0.93, 1.21), Vector<2>(0.1, 1.7), Vector<2>(0.02, 0.05)}) {
    auto multiplier_at = [&](const Vector<2>& at) {  // lambda* h, converged from scratch
      LmeShape<2> lme(plane, options);
      lme.initialise(1);
      lme.evaluate(0, at, nodes, values, offsets);
      return Vector<2>(lme.lagrange_multiplier(0) * h);
    };
    const Vector<2> lambda = multiplier_at(x);
    const int count = lme_neighbours(plane, radius_squared, 64, 0, x, nodes, offsets);
    const LmePartition z = lme_partition(count, offsets, options.gamma, lambda, values);
    const Matrix<2> slope = lme_multiplier_slope(options.gamma, Matrix<2>(lme_moments(count, offsets, values, z.weight_sum).inverse_hessian()));
    for (int axis = 0; axis < 2; ++axis) {
      const Vector<2> step = Vector<2>::Unit(axis) * delta * h;
      const Vector<2> difference = (multiplier_at(x + step) - multiplier_at(x - step)) / (2.0 * delta);  // per cell moved
      INFO("x = ", x.transpose(), ", axis ", axis, ": finite difference ", difference.transpose(), ", Eq. ", slope.col(axis).transpose());
      CHECK((difference - slope.col(axis)).norm() <= 1e-6 * (1.0 + slope.col(axis).norm()));
    }
  }
  // lme_third_moments by hand. 1D, offsets 0.25 and -0.75 with N = 0.75 and 0.25 (they reproduce x):
  // 0.75 * 0.25^3 + 0.25 * (-0.75)^3 = 0.01171875 - 0.10546875 = -0.09375. 2D, one offset (1, 2) with N = 1:
  // T_0 = 1 * [1 2; 2 4], T_1 = 2 * [1 2; 2 4].
  {
    const Vector<1> line_offsets[2] = {Vector<1>(0.25), Vector<1>(-0.75)};
    const double line_values[2] = {0.75, 0.25};
    CHECK(lme_third_moments<1>(2, line_offsets, line_values)[0](0, 0) == doctest::Approx(-0.09375).epsilon(1e-15));
    const Vector<2> one_offset[1] = {Vector<2>(1.0, 2.0)};
    const double one_value[1] = {1.0};
    const LmeThirdMoments<2> third = lme_third_moments<2>(1, one_offset, one_value);
    Matrix<2> square;
    square << 1.0, 2.0, 2.0, 4.0;
    CHECK(third[0] == square);
    CHECK(third[1] == Matrix<2>(2.0 * square));
  }
  // The second-order start (lme_multiplier_curvature): the slope alone leaves an error of order |u|^2,
  // the curvature term one of order |u|^3. Halving a slanted move u thrice from 0.04 cells, the observed
  // orders are 2 and 3 (within 0.25), and the second-order error is the smaller by a factor 10 at least.
  auto multiplier_at = [&](const Vector<2>& at) {  // lambda* h, converged from scratch
    LmeShape<2> lme(plane, options);
    lme.initialise(1);
    lme.evaluate(0, at, nodes, values, offsets);
    return Vector<2>(lme.lagrange_multiplier(0) * h);
  };
  for (const Vector<2>& x : {Vector<2>(0.93, 1.21), Vector<2>(0.1, 0.3)}) {
    const Vector<2> lambda = multiplier_at(x);
    const int count = lme_neighbours(plane, radius_squared, 64, 0, x, nodes, offsets);
    const LmePartition z = lme_partition(count, offsets, options.gamma, lambda, values);
    const Matrix<2> inverse_hessian = lme_moments(count, offsets, values, z.weight_sum).inverse_hessian();
    lme_values(count, 1.0 / z.weight_sum, values);
    const LmeThirdMoments<2> third = lme_third_moments(count, offsets, values);
    double last_first = 0.0, last_second = 0.0;
    for (double length : {0.04, 0.02, 0.01, 0.005}) {
      const Vector<2> move = length * Vector<2>(0.8, 0.6);  // cells
      const Vector<2> exact = multiplier_at(x + move * h);
      const Vector<2> first = lambda + lme_multiplier_slope(options.gamma, inverse_hessian) * move;
      const Vector<2> second = first + lme_multiplier_curvature(third, inverse_hessian, move);
      const double error_first = (exact - first).norm(), error_second = (exact - second).norm();
      INFO("x = ", x.transpose(), ", |u| = ", length, " cells: error of the slope ", error_first, ", with the curvature ", error_second);
      CHECK(error_second <= 0.1 * error_first);
      if (last_first > 0.0) {
        CHECK(std::log2(last_first / error_first) == doctest::Approx(2.0).epsilon(0.125));
        CHECK(std::log2(last_second / error_second) == doctest::Approx(3.0).epsilon(0.085));
      }
      last_first = error_first;
      last_second = error_second;
    }
  }
  // The slanted path of the test above, 1e-3 h and 1e-4 h per evaluation: started from the last lambda*,
  // Newton is ~1e-3 (1e-4) from the root and needs two steps to reach 1e-10 (the test above); from the
  // predicted start it is ~1e-6 (1e-8) away with the slope alone, and one step was enough (measured:
  // mean 1.0 and 0.9997); with the curvature term ~1e-9 (1e-12) away: still one step at 1e-3 h (mean 1.0),
  // mostly none at 1e-4 h (mean 0.016).
  for (double move : {1e-3, 1e-4}) {
    LmeShape<2> lme(plane, LmeOptions());
    lme.initialise(1);
    lme.evaluate(0, Vector<2>(0.3, 0.35), nodes, values, offsets);
    const long cold = lme.diagnostics().newton_iterations_total();
    const int calls = static_cast<int>(2.0 / move);
    for (int k = 1; k <= calls; ++k) lme.evaluate(0, Vector<2>(0.3 + k * 0.8 * move * h, 0.35 + k * 0.6 * move * h), nodes, values, offsets);
    INFO("move ", move, " h per evaluation");
    CHECK(double(lme.diagnostics().newton_iterations_total() - cold) / calls <= (move == 1e-3 ? 1.0 : 0.05));
  }
}

TEST_CASE("LME options: the hull condition on gamma and the support tolerance, and the authors' beta rule") {
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
  LmeOptions options;
  options.gamma = 7.0;  // R = 1.405 h < sqrt(2) h with tol = 1e-6
  CHECK_THROWS_WITH_AS(LmeShape<2>(plane, options), doctest::Contains("gamma = 7 is too large for support_tolerance = 1e-06"),
                       std::invalid_argument);
  CHECK_NOTHROW(LmeShape<1>(line, options));  // 1D needs only R >= h
  options.support_tolerance = 1e-7;           // R = 1.52 h
  CHECK_NOTHROW(LmeShape<2>(plane, options));
  options = LmeOptions();
  options.gamma = 0.0;
  CHECK_THROWS_AS(LmeShape<1>(line, options), std::invalid_argument);
  options = LmeOptions();
  options.support_tolerance = 1.0;
  CHECK_THROWS_AS(LmeShape<1>(line, options), std::invalid_argument);
  options = LmeOptions();
  options.newton_tolerance = 0.0;
  CHECK_THROWS_AS(LmeShape<1>(line, options), std::invalid_argument);
  options = LmeOptions();
  options.max_iterations = 0;
  CHECK_THROWS_AS(LmeShape<1>(line, options), std::invalid_argument);

  // beta = gamma / hbar^2. In 1D at a cell centre with gamma = 3 the neighbours are at 0.5 h and 1.5 h,
  // so hbar = h and N is the default's (paper/09_choices.md, 'The beta rule'), to rounding. (So it is wherever x has
  // four neighbours, two on each side: their distances add up to 4 h.)
  int nodes[64];
  double values[64], reference[64];
  Vector<1> gradients[64];
  options = LmeOptions();
  options.newton_tolerance = 1e-13;
  LmeShape<1> standard(line, options);
  options.beta_rule = LmeOptions::BetaRule::mean_neighbour_distance;
  LmeShape<1> authors(line, options);
  standard.initialise(1);
  authors.initialise(1);
  REQUIRE(standard.evaluate(0, Vector<1>(4.5), nodes, reference, gradients) == 4);
  REQUIRE(authors.evaluate(0, Vector<1>(4.5), nodes, values, gradients) == 4);
  for (int k = 0; k < 4; ++k) CHECK(values[k] == doctest::Approx(reference[k]).epsilon(1e-14));
  // Elsewhere hbar != h and the functions differ, while every property but the finite-difference one
  // holds (Eq. (41) takes beta constant; under this rule it varies with x, as in the authors' code).
  REQUIRE(standard.evaluate(0, Vector<1>(4.05), nodes, reference, gradients) == 5);  // hbar = 6.05 h / 5
  REQUIRE(authors.evaluate(0, Vector<1>(4.05), nodes, values, gradients) == 5);
  double difference = 0.0;
  for (int k = 0; k < 5; ++k) difference = std::max(difference, std::abs(values[k] - reference[k]));
  CHECK(difference > 0.05);  // beta h^2 = 3 / 1.21^2 = 2.05 instead of 3
  testing::PropertyTolerances tolerance;
  tolerance.unity = 1.1e-13;
  tolerance.gradient = 1e-13;
  tolerance.check_finite_difference = false;
  LmeShape<2> authors2(plane, options);
  authors2.initialise(1);
  for (const Vector<2>& x : {Vector<2>(0.0, 3.3), Vector<2>(4.5, 4.5), Vector<2>(4.2, 7.9), Vector<2>(9.9, 9.95)})
    testing::check_shape_properties(authors2, plane, 0, x, tolerance);
}

TEST_CASE("The authors' beta: gamma / hbar^2 on their strip in 1D and on the 4 x 4 node patch in 2D, by hand") {
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
  // At a cell centre the strip's nodes are at sqrt(0.5^2 + 0.5^2) and sqrt(1.5^2 + 0.5^2), twice each:
  // hbar = (sqrt(2) + sqrt(10)) / 4, so beta h^2 = 48 / (sqrt(2) + sqrt(10))^2 = 3 (3 - sqrt(5)) = 2.292 at gamma 3.
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.5), 3.0) == doctest::Approx(3.0 * (3.0 - std::sqrt(5.0))));
  // At h/4 from the centre, either side: distances sqrt(d^2 + 1/4) for d = 0.25, 0.75, 1.25, 1.75: 2.242.
  const double quarter = (std::sqrt(0.3125) + std::sqrt(0.8125) + std::sqrt(1.8125) + std::sqrt(3.3125)) / 4.0;
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.75), 3.0) == doctest::Approx(3.0 / (quarter * quarter)));
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.25), 3.0) == doctest::Approx(3.0 / (quarter * quarter)));
  // In the end cells no cell lies beyond: three nodes, hbar = (sqrt(2) + sqrt(10) / 2) / 3, beta h^2 = 3.009.
  const double end = (std::sqrt(2.0) + std::sqrt(10.0) / 2.0) / 3.0;
  CHECK(authors_beta_in_cell_units(line, Vector<1>(0.5), 3.0) == doctest::Approx(3.0 / (end * end)));
  CHECK(authors_beta_in_cell_units(line, Vector<1>(9.5), 3.0) == doctest::Approx(3.0 / (end * end)));
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.5), 1.5) == doctest::Approx(1.5 * (3.0 - std::sqrt(5.0))));
  // 2D, a cell centre: 4 nodes at sqrt(2)/2, 8 at sqrt(10)/2, 4 at 3 sqrt(2)/2 (beta h^2 = 1.337 at gamma 3).
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const double centre = (4.0 * std::sqrt(0.5) + 8.0 * std::sqrt(2.5) + 4.0 * std::sqrt(4.5)) / 16.0;
  CHECK(authors_beta_in_cell_units(plane, Vector<2>(4.5, 6.5), 3.0) == doctest::Approx(3.0 / (centre * centre)));
  const double corner = (std::sqrt(0.5) * 4.0 + std::sqrt(2.5) * 4.0 + std::sqrt(4.5)) / 9.0;  // 3 x 3 nodes
  CHECK(authors_beta_in_cell_units(plane, Vector<2>(0.5, 0.5), 3.0) == doctest::Approx(3.0 / (corner * corner)));
  // The shape under the rule is the standard LME at gamma = beta h^2 there (the same four neighbours).
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  options.beta_rule = LmeOptions::BetaRule::authors;
  LmeShape<1> authors(line, options);
  options.beta_rule = LmeOptions::BetaRule::grid_spacing;
  options.gamma = 3.0 * (3.0 - std::sqrt(5.0));
  LmeShape<1> standard(line, options);
  authors.initialise(1);
  standard.initialise(1);
  int nodes[64];
  double values[64], reference[64];
  Vector<1> gradients[64];
  REQUIRE(standard.evaluate(0, Vector<1>(4.5), nodes, reference, gradients) == 4);
  REQUIRE(authors.evaluate(0, Vector<1>(4.5), nodes, values, gradients) == 4);
  for (int k = 0; k < 4; ++k) CHECK(values[k] == doctest::Approx(reference[k]).epsilon(1e-13));
  // By symmetry lambda = 0 there: the two far nodes (1.5 h away) carry 1 / (1 + e^{2 beta h^2}) together,
  // 0.0101 against 0.0025 at beta h^2 = 3.
  double far = 0.0;
  for (int k = 0; k < 4; ++k) far += std::abs(4.5 - nodes[k]) > 1.0 ? values[k] : 0.0;
  CHECK(far == doctest::Approx(1.0 / (1.0 + std::exp(6.0 * (3.0 - std::sqrt(5.0))))));
}

TEST_CASE("Eq. (34): N maximises the entropy less beta U among the partitions of unity that reproduce x") {
  // F(N) = beta sum_I N_I |x - x_I|^2 - H(N) (cell units) is least at the LME functions on the set
  // sum N = 1, sum N x_I = x. Moving along a direction d that keeps both (sum d = 0, sum d x_I = 0)
  // by eps raises F by eps^2/2 sum d_I^2 / N_I to second order (the first order vanishes at the optimum).
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  auto check = [&](auto& shape, const auto& grid, const auto& x, const std::vector<std::pair<int, double>>& move) {
    constexpr int Dim = std::decay_t<decltype(x)>::RowsAtCompileTime;
    std::vector<int> nodes(shape.capacity());
    std::vector<double> N(shape.capacity());
    std::vector<Vector<Dim>> gradients(shape.capacity());
    shape.initialise(1);
    const int count = shape.evaluate(0, x, nodes.data(), N.data(), gradients.data());
    auto F = [&](const std::vector<double>& values) {
      double U = 0.0;
      for (int k = 0; k < count; ++k) U += values[k] * (x - grid.node_position(nodes[k])).squaredNorm();
      return shape.options().gamma * U - lme_entropy(count, values.data());
    };
    std::vector<double> d(count, 0.0);
    for (const auto& [node, weight] : move)
      for (int k = 0; k < count; ++k)
        if (nodes[k] == node) d[k] = weight;
    double smallest = 1.0, curvature = 0.0, sum = 0.0;
    Vector<Dim> moment = Vector<Dim>::Zero();
    for (int k = 0; k < count; ++k) {
      if (d[k] != 0.0) smallest = std::min(smallest, N[k]), curvature += d[k] * d[k] / N[k];
      sum += d[k];
      moment += d[k] * grid.node_position(nodes[k]);
    }
    REQUIRE(sum == 0.0);
    REQUIRE(moment.norm() < 1e-12);
    REQUIRE(curvature > 0.0);
    for (double eps : {1e-3 * smallest, -1e-3 * smallest}) {
      std::vector<double> moved = N;
      for (int k = 0; k < count; ++k) moved[k] += eps * d[k];
      const double rise = F(moved) - F(N);
      CHECK(rise > 0.0);
      CHECK(rise == doctest::Approx(0.5 * eps * eps * curvature).epsilon(0.01));
    }
  };
  LmeShape<1> lme(line, options);
  check(lme, line, Vector<1>(4.3), {{3, 1.0}, {4, -2.0}, {5, 1.0}});  // a second difference
  check(lme, line, Vector<1>(4.3), {{3, 1.0}, {4, -1.0}, {5, -1.0}, {6, 1.0}});  // the neighbours are nodes 3 to 6
  LmeShape<2> lme2(plane, options);
  const int i = 4, j = 5;  // the corners of the cell that contains x: a twist
  check(lme2, plane, Vector<2>(4.3, 5.6),
        {{plane.node_index({i, j}), 1.0}, {plane.node_index({i + 1, j}), -1.0}, {plane.node_index({i, j + 1}), -1.0},
         {plane.node_index({i + 1, j + 1}), 1.0}});
  // By hand: H of a uniform partition of 4 is log 4; 0 log 0 = 0.
  const double uniform[4] = {0.25, 0.25, 0.25, 0.25}, corner[3] = {1.0, 0.0, 0.0};
  CHECK(lme_entropy(4, uniform) == doctest::Approx(std::log(4.0)).epsilon(1e-15));
  CHECK(lme_entropy(3, corner) == 0.0);
}

TEST_CASE("Eq. (37), Eq. (38), Eq. (40): r and J are the gradient and Hessian of log Z (finite differences in lambda), f_I by hand") {
  // Eq. (40) by hand: beta = 3, lambda = (0.5, -1), x - x_I = (1, 2): -3 (1 + 4) + (0.5 - 2) = -16.5.
  CHECK(lme_exponent<2>(3.0, Vector<2>(0.5, -1.0), Vector<2>(1.0, 2.0)) == -16.5);
  // The 16 neighbours of a point, a lambda away from the root: log Z is smooth in lambda, and central
  // differences with step 1e-5 are exact to ~1e-10 (third derivative ~ 1, divided by 6, times step^2).
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const double radius_squared = -std::log(1e-6) / 3.0, beta = 3.0, step = 1e-5;
  int nodes[16];
  Vector<2> offsets[16];
  double w[16];
  const int count = lme_neighbours(plane, radius_squared, 16, 0, Vector<2>(4.4, 5.7), nodes, offsets);
  REQUIRE(count >= 12);
  const Vector<2> lambda(0.3, -0.7);
  auto log_z = [&](const Vector<2>& l) { return lme_partition(count, offsets, beta, l, w).log_z(); };
  auto moments = [&](const Vector<2>& l) {
    const LmePartition z = lme_partition(count, offsets, beta, l, w);
    return lme_moments(count, offsets, w, z.weight_sum);
  };
  const LmeMoments<2> at = moments(lambda);
  for (int k = 0; k < 2; ++k) {
    const Vector<2> e = step * Vector<2>::Unit(k);
    CHECK(at.residual()[k] == doctest::Approx((log_z(lambda + e) - log_z(lambda - e)) / (2.0 * step)).epsilon(1e-8));
    const Vector<2> column = (moments(lambda + e).residual() - moments(lambda - e).residual()) / (2.0 * step);
    CHECK((at.hessian().col(k) - column).norm() <= 1e-8);
  }
  // Eq. (37) as printed, sum p (x - x_I) (x) (x - x_I) - r (x) r, equals the covariance form to rounding.
  const LmePartition z = lme_partition(count, offsets, beta, lambda, w);
  Matrix<2> printed = Matrix<2>::Zero();
  for (int I = 0; I < count; ++I) printed += w[I] / z.weight_sum * offsets[I] * offsets[I].transpose();
  printed -= at.residual() * at.residual().transpose();
  CHECK((printed - at.hessian()).norm() <= 1e-14);
  // Near the root lme_moments takes Eq. (37) as written, in one pass: J equals the covariance by hand.
  LmeShape<2> lme(plane);
  lme.initialise(1);
  int scratch_nodes[16];
  double scratch_values[16];
  Vector<2> scratch_gradients[16];
  lme.evaluate(0, Vector<2>(4.4, 5.7), scratch_nodes, scratch_values, scratch_gradients);
  const Vector<2> near = lme.lagrange_multiplier(0) + Vector<2>(1e-5, -2e-5);  // h = 1: cell units
  const LmeMoments<2> close = moments(near);
  const LmePartition zn = lme_partition(count, offsets, beta, near, w);
  Matrix<2> covariance = Matrix<2>::Zero(), second = Matrix<2>::Zero();
  for (int I = 0; I < count; ++I) {
    covariance += w[I] / zn.weight_sum * (offsets[I] - close.residual()) * (offsets[I] - close.residual()).transpose();
    second += w[I] / zn.weight_sum * offsets[I] * offsets[I].transpose();
  }
  REQUIRE(close.residual().squaredNorm() <= 1e-6 * second.trace());  // the one-pass branch
  REQUIRE(at.residual().squaredNorm() > 1e-6 * printed.trace());       // ... and above, the covariance branch
  CHECK((covariance - close.hessian()).norm() <= 1e-14);
  // The sums behind them: r = S_1 / S_0, and the test |r| <= tol on them, either side of |r|.
  CHECK((close.first / close.weight_sum - close.residual()).norm() == 0.0);
  CHECK(close.converged(1.0001 * close.residual().norm()));
  CHECK(!close.converged(0.9999 * close.residual().norm()));
  CHECK((at.inverse_hessian() * at.hessian() - Matrix<2>::Identity()).norm() <= 1e-13);
}

TEST_CASE("Eq. (36) moved without exponentials: the series weights equal exp()'s to rounding, after a Newton step and after the particle moved") {
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const double radius_squared = -std::log(1e-6) / 3.0, beta = 3.0, diameter = 2.0 * std::sqrt(radius_squared);
  int nodes[16], moved_nodes[16];
  Vector<2> offsets[16], moved_offsets[16];
  double series[16], direct[16];
  const int count = lme_neighbours(plane, radius_squared, 16, 0, Vector<2>(4.4, 5.7), nodes, offsets);
  REQUIRE(count >= 12);
  const Vector<2> lambda(0.3, -0.7);
  // The shape functions of two weight lists: the weights over their sum.
  auto largest_difference = [&](int n, double series_sum, double direct_sum) {
    double worst = 0.0;
    for (int I = 0; I < n; ++I) worst = std::max(worst, std::abs(series[I] / series_sum - direct[I] / direct_sum) / (direct[I] / direct_sum));
    return worst;
  };
  // A Newton step as long as the series allows, |s| D / 2 = 4e-3 (a little less, for the test's own rounding).
  const Vector<2> step = Vector<2>(0.6, -0.8) * (0.999 * 8e-3 / diameter);
  REQUIRE(series_is_exact(step, diameter));
  CHECK_FALSE(series_is_exact(Vector<2>(step * 1.01), diameter));
  lme_partition(count, offsets, beta, lambda, series);
  const double stepped = lme_weights_moved(count, offsets, step, series, series);
  const LmePartition exact = lme_partition(count, offsets, beta, Vector<2>(lambda + step), direct);
  // exp()'s own weights carry the rounding of their exponents, up to beta R^2 = 13.8 in size: about
  // 14 eps = 3e-15 relative. A series of degree 3 would be off by t^4/24 ~ 1e-11: the test tells the degree.
  CHECK(largest_difference(count, stepped, exact.weight_sum) <= 1e-14);
  // The particle moved by delta = (1e-3, -2e-3) cells (the same neighbours), its multiplier to
  // lambda' = lambda + 2 beta delta + (1e-3, 1e-3) (nearly as predicted_multiplier moves it): from its old
  // shape functions, with the slope lambda' - lambda - 2 beta delta = (1e-3, 1e-3).
  const Vector<2> delta(1e-3, -2e-3), moved_lambda = lambda + 2.0 * beta * delta + Vector<2>(1e-3, 1e-3);
  const LmePartition old = lme_partition(count, offsets, beta, lambda, series);
  for (int I = 0; I < count; ++I) series[I] /= old.weight_sum;  // the last N_I
  REQUIRE(lme_neighbours(plane, radius_squared, 16, 0, Vector<2>(4.4 + delta[0], 5.7 + delta[1]), moved_nodes, moved_offsets) == count);
  REQUIRE(std::equal(nodes, nodes + count, moved_nodes));
  const Vector<2> slope = moved_lambda - lambda - 2.0 * beta * delta;
  REQUIRE(series_is_exact(slope, diameter));
  const double moved_sum = lme_weights_moved(count, moved_offsets, slope, series, series);
  const LmePartition moved_exact = lme_partition(count, moved_offsets, beta, moved_lambda, direct);
  CHECK(largest_difference(count, moved_sum, moved_exact.weight_sum) <= 1e-14);
  // Through LmeShape: a particle moved in small steps gives the shape functions of a fresh evaluation
  // (exponentials only) at the same point, to the Newton tolerance.
  LmeShape<2> walked(plane), fresh(plane);
  walked.initialise(1);
  fresh.initialise(1);
  double values[16], reference[16];
  Vector<2> gradients[16];
  Vector<2> at(4.4, 5.7);
  for (int k = 0; k < 200; ++k, at += Vector<2>(2e-4, 1e-4)) walked.evaluate(0, at, nodes, values, gradients);
  const int n = walked.evaluate(0, at, nodes, values, gradients);
  REQUIRE(fresh.evaluate(0, at, moved_nodes, reference, moved_offsets) == n);
  for (int I = 0; I < n; ++I) CHECK(values[I] == doctest::Approx(reference[I]).epsilon(1e-9));
}

TEST_CASE("Eq. (39): grad N_I = N_I (grad f_I - sum_J N_J grad f_J), with the total derivatives of f_I by finite differences") {
  // f_I(x) = -beta |x - x_I|^2 + lambda*(x).(x - x_I), lambda* re-solved at x +- delta. Newton's residual
  // (1e-13 h) over the step (2e-6 h) bounds the error of grad f: about 1e-7 / h.
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  const double h = 0.5, delta = 1e-6 * h;
  const Grid<2> plane(Vector<2>(0.0, 0.0), h, {10, 10});
  LmeShape<2> lme(plane, options);
  lme.initialise(1);
  int nodes[16], nodes_moved[16];
  double N[16], scratch[16];
  Vector<2> gradients[16], scratch_gradients[16];
  const Vector<2> x(2.2, 2.85);
  const double beta = options.gamma / (h * h);
  Vector<2> grad_f[16];
  for (auto& g : grad_f) g.setZero();
  for (int axis = 0; axis < 2; ++axis)
    for (double side : {1.0, -1.0}) {
      const Vector<2> moved = x + side * delta * Vector<2>::Unit(axis);
      const int count = lme.evaluate(0, moved, nodes_moved, scratch, scratch_gradients);
      for (int k = 0; k < count; ++k) {
        const Vector<2> offset = moved - plane.node_position(nodes_moved[k]);
        grad_f[k][axis] += side * (-beta * offset.squaredNorm() + lme.lagrange_multiplier(0).dot(offset)) / (2.0 * delta);
      }
    }
  const int count = lme.evaluate(0, x, nodes, N, gradients);
  Vector<2> mean = Vector<2>::Zero();
  for (int k = 0; k < count; ++k) mean += N[k] * grad_f[k];
  for (int k = 0; k < count; ++k) {
    INFO("node ", nodes[k], ", N = ", N[k]);
    CHECK(nodes[k] == nodes_moved[k]);
    CHECK((gradients[k] - N[k] * (grad_f[k] - mean)).norm() * h <= 1e-6);
  }
}

}  // namespace mpm
