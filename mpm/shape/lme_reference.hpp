/// \file
/// Local maximum-entropy (LME) shape functions of Arroyo & Ortiz (2006), the reference form: the paper's
/// Eqs. (34)-(41) (paper/04_shape_functions.md) in its order, then Newton's solve of Eq. (38) for the multiplier
/// lambda*, then the shape class, each written as the page reads. The run's default is the fast form of the same
/// functions (mpm/fast/lme_fast.hpp), tested against this one.
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
/// Everything runs in cell units (paper/09_choices.md, 'Newton for the multiplier'): offsets
/// \f$ (x - x_I)/h \f$, \f$ \beta h^2 \f$ (= gamma), \f$ \lambda h \f$, so r/h and J/h^2 are dimensionless and the
/// Newton tolerance is relative to h. Newton starts from lambda = 0 at every evaluation. The options, the support
/// radius and the beta rules are in mpm/shape/lme_options.hpp, the neighbour search in mpm/shape/lme_neighbours.hpp,
/// Newton's safeguards (a capped or damped step, a line search on the convex log Z) in mpm/shape/lme_newton.hpp.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/lme_neighbours.hpp"
#include "mpm/shape/lme_newton.hpp"
#include "mpm/shape/lme_options.hpp"
#include "mpm/shape/shape_diagnostics.hpp"
#include "mpm/shape/shape_properties.hpp"

namespace mpm {

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
double lme_exponent(double beta, const Vector<Dim>& lambda, const Vector<Dim>& offset) {
  return -beta * offset.squaredNorm() + lambda.dot(offset);
}

/// Eq. (36), the logarithm of the partition function,
/// \f[ \log Z(x, \lambda) = \log \sum_I e^{f_I(x, \lambda)} = m + \log \sum_I e^{f_I - m} , \qquad m = \max_I f_I , \f]
/// the exponents shifted by their largest so that no exponential overflows.
template <int Dim>
double lme_log_partition(int count, const Vector<Dim>* offsets, double beta, const Vector<Dim>& lambda) {
  double largest = -std::numeric_limits<double>::infinity();
  for (int I = 0; I < count; ++I) largest = std::max(largest, lme_exponent(beta, lambda, offsets[I]));
  double sum = 0.0;
  for (int I = 0; I < count; ++I) sum += std::exp(lme_exponent(beta, lambda, offsets[I]) - largest);
  return largest + std::log(sum);
}

/// Eq. (35), the shape functions at the multiplier lambda (lambda* once Newton has converged):
/// \f[ N_I(x, \lambda) = \frac{e^{f_I(x, \lambda)}}{Z(x, \lambda)} = e^{f_I(x, \lambda) - \log Z(x, \lambda)} . \f]
template <int Dim>
void lme_shape_values(int count, const Vector<Dim>* offsets, double beta, const Vector<Dim>& lambda, double* values) {
  const double log_z = lme_log_partition(count, offsets, beta, lambda);
  for (int I = 0; I < count; ++I) values[I] = std::exp(lme_exponent(beta, lambda, offsets[I]) - log_z);
}

/// Eq. (38), the gradient of log Z with respect to lambda, whose root is lambda*:
/// \f[ r(x, \lambda) = \frac{\partial \log Z}{\partial \lambda} = \sum_I N_I(x, \lambda) \, (x - x_I) . \f]
template <int Dim>
Vector<Dim> lme_residual(int count, const Vector<Dim>* offsets, const double* values) {
  Vector<Dim> r = Vector<Dim>::Zero();
  for (int I = 0; I < count; ++I) r += values[I] * offsets[I];
  return r;
}

/// Eq. (37), the Hessian of log Z with respect to lambda,
/// \f[ J(x, \lambda) = \frac{\partial r}{\partial \lambda} = \sum_I N_I (x - x_I) \otimes (x - x_I) - r \otimes r
///     = \sum_I N_I (x - x_I - r) \otimes (x - x_I - r) , \f]
/// summed in the second form (the covariance of the offsets under N), equal to the first since
/// \f$ \sum_I N_I = 1 \f$ and \f$ \sum_I N_I (x - x_I) = r \f$, without its cancellation far from the root.
/// J is symmetric positive definite when the neighbours span the space: log Z is convex, r = 0 has one root.
template <int Dim>
Matrix<Dim> lme_hessian(int count, const Vector<Dim>* offsets, const double* values, const Vector<Dim>& r) {
  Matrix<Dim> J = Matrix<Dim>::Zero();
  for (int I = 0; I < count; ++I) J += values[I] * (offsets[I] - r) * (offsets[I] - r).transpose();
  return J;
}

/// Eq. (41), the gradients at the converged multiplier, with beta constant in space: Eq. (39),
/// \f$ \nabla N_I = N_I (\nabla f_I - \sum_J N_J \nabla f_J) \f$ with the total derivatives of Eq. (40)'s
/// \f$ f_I \f$ (\f$ d\lambda^*/dx \f$ from r = 0), becomes
/// \f[ \nabla N_I^* = -N_I^* \, (J^*)^{-1} (x - x_I) , \f]
/// evaluated as \f$ -N_I (J^*)^{-1} (x - x_I - r) / h \f$ (`offsets` in cells, the gradients per length): at r = 0
/// this is Eq. (41), and for the residual \f$ |r| \le \f$ tol that Newton leaves it keeps
/// \f$ \sum_I \nabla N_I = 0 \f$ and \f$ \sum_I x_I \otimes \nabla N_I = I \f$ exact to rounding.
template <int Dim>
void lme_shape_gradients(int count, const Vector<Dim>* offsets, const double* values, const Matrix<Dim>& J,
                         const Vector<Dim>& r, double h, Vector<Dim>* gradients) {
  const Matrix<Dim> J_inverse = J.inverse();
  for (int I = 0; I < count; ++I) gradients[I] = -values[I] * (J_inverse * (offsets[I] - r)) / h;
}

/// Where Newton stopped: lambda* (cell units), r and J there, the updates it took, and why it failed (or nullptr).
template <int Dim>
struct LmeNewtonSolve {
  Vector<Dim> lambda;
  Vector<Dim> r;
  Matrix<Dim> J;
  int iterations = 0;
  const char* failure = nullptr;
};

/// Newton's method on Eq. (38), \f$ r(x, \lambda) = 0 \f$, with J of Eq. (37), from \f$ \lambda = 0 \f$:
/// \f[ \lambda \leftarrow \lambda + t \, s , \qquad s = -J^{-1} r , \f]
/// s capped (or damped, or steepest descent where J is not positive definite: lme_newton_step) and t halved
/// from 1 until log Z of Eq. (36) has dropped by at least 1e-4 of t r.s (armijo_step_length). Stops when
/// \f$ |r| \le \f$ `tolerance` and leaves Eq. (35)'s N at the last lambda in `values`.
template <int Dim>
LmeNewtonSolve<Dim> solve_lme_newton(int count, const Vector<Dim>* offsets, double beta, double tolerance,
                                     int max_iterations, double* values) {
  LmeNewtonSolve<Dim> at{Vector<Dim>::Zero(), {}, {}, 0, nullptr};
  for (;; ++at.iterations) {
    lme_shape_values(count, offsets, beta, at.lambda, values);
    at.r = lme_residual(count, offsets, values);
    at.J = lme_hessian(count, offsets, values, at.r);
    if (at.r.norm() <= tolerance) return at;
    if (at.iterations == max_iterations) {
      at.failure = "";
      return at;
    }
    const Vector<Dim> s = lme_newton_step(at.r, at.J, at.lambda);
    auto log_z_along_s = [&](double trial) {
      return lme_log_partition(count, offsets, beta, Vector<Dim>(at.lambda + trial * s));
    };
    const double t = armijo_step_length(log_z_along_s(0.0), at.r.dot(s), log_z_along_s);
    if (t == 0.0) {
      at.failure = " (line search found no decrease of log Z)";
      return at;
    }
    at.lambda += t * s;
  }
}

/// The LME shape functions of Eqs. (35) and (41) at any point of the grid, each evaluation on its own: the
/// neighbours within R, beta by the options' rule, lambda* by solve_lme_newton from 0. It keeps nothing of a
/// particle between evaluations (the fast form's LmeShape starts Newton from the last one).
template <int Dim>
class LmeReferenceShape {
 public:
  static constexpr const char* name = "lme";
  /// \throws std::invalid_argument for options out of range or a support radius too short (lme_radius_squared).
  explicit LmeReferenceShape(const Grid<Dim>& grid, const LmeOptions& options = LmeOptions())
      : grid_(grid), options_(options), radius_squared_(lme_radius_squared<Dim>(options)),
        capacity_(lme_support_capacity<Dim>(options, radius_squared_)) {}

  /// An upper bound of the neighbours of any point: the most lattice points a ball of radius R can hold.
  int capacity() const { return capacity_; }
  /// R, the support radius (length units).
  double support_radius() const { return std::sqrt(radius_squared_) * grid_.spacing(); }
  const LmeOptions& options() const { return options_; }
  /// Nothing to size: no particle carries anything from one evaluation to the next.
  void initialise(const Particles<Dim>& /*particles*/) {}
  void initialise(int /*particle_count*/) {}

  /// N_I(x) and grad N_I(x) for every node within the support radius of x, Eqs. (35) and (41); returns how many.
  /// \throws ShapeFailure if x is outside the grid, if Newton does not converge, or if J is singular there.
  int evaluate(int particle, const Vector<Dim>& x, int* nodes, double* values, Vector<Dim>* gradients) {
    if (!grid_.contains(x)) throw ShapeFailure(particle, "particle left the grid");
    std::vector<Vector<Dim>> offsets(capacity_);  // (x - x_I)/h
    const int count = lme_support(options_, grid_, radius_squared_, capacity_, particle, x, nodes, offsets.data());
    const double beta = lme_beta_in_cell_units(options_, grid_, x, count, offsets.data());
    const LmeNewtonSolve<Dim> solve =
        solve_lme_newton(count, offsets.data(), beta, options_.newton_tolerance, options_.max_iterations, values);
    if (solve.failure)
      throw lme_not_converged(particle, solve.iterations, solve.r.norm(), options_.gamma, solve.failure);
    if (!positive_definite(solve.J)) throw lme_singular_hessian(particle, Dim, solve.J.determinant());
    lme_shape_gradients(count, offsets.data(), values, solve.J, solve.r, grid_.spacing(), gradients);
    diagnostics_.record(count, solve.iterations);
    return count;
  }

  const ShapeDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  Grid<Dim> grid_;
  LmeOptions options_;
  double radius_squared_;  ///< (R/h)^2 = -ln(tol)/gamma
  int capacity_;
  ShapeDiagnostics diagnostics_;
};

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

/// The shape properties at x of either LME form, with Newton converged to |r|/h <= 1e-13 (the shape must be
/// built so). Tolerances and why:
///  - sum N - 1: normalised by Z, so rounding only; sum N x_I - x is r, at most 1e-13 h, plus the
///    rounding of the absolute coordinates: 1.1e-13.
///  - sum grad N and sum x_I (x) grad N - I: exact for any r by the form of Eq. (41) used, so
///    rounding only, about eps (|x|/h) n |J^-1| <~ 1e-14 here: 1e-13.
///  - finite differences (step 1e-6 h): LME is smooth, so the truncation error is ~1e-12; the error
///    of N itself, ~ N_I |x - x_I - r| |r| / (h lambda_min(J)) <~ 4e-13, divided by the step 2e-6 h,
///    dominates: 5e-7. Skipped within 2e-6 h of the grid's edge (the difference would leave it) and
///    within 1e-5 h of a support sphere (N jumps by ~support_tolerance there).
template <int Dim, class Shape>
void check_lme_properties(Shape& shape, const Grid<Dim>& grid, const Vector<Dim>& x) {
  REQUIRE(shape.options().newton_tolerance <= 1e-13);
  PropertyTolerances tolerance;
  tolerance.unity = 1.1e-13;
  tolerance.gradient = 1e-13;
  tolerance.finite_difference = 5e-7;
  const double h = grid.spacing();
  const double room = std::min((x - grid.origin()).minCoeff(), (grid.upper_corner() - x).minCoeff()) / h;
  tolerance.check_finite_difference =
      room > 2e-6 && distance_to_lme_support_edge(grid, x, shape.support_radius()) > 1e-5;
  check_shape_properties(shape, grid, 0, x, tolerance);
}

}  // namespace testing

TEST_CASE("LME reference, 1D by hand: at a cell centre N is the normalised prior, grad N = -N (x - x_I) / (J h)") {
  // gamma = 3, h = 0.5, x at the centre of cell 4: the neighbours within R = 2.146 h are at +-0.5 h and +-1.5 h.
  // By symmetry r(0) = 0, so Newton stops at lambda = 0 with no update: N_I = e^{-3 d_I^2} / Z,
  // Z = 2 e^{-0.75} + 2 e^{-6.75}, and J = sum N_I d_I^2 = 2 (0.25 e^{-0.75} + 2.25 e^{-6.75}) / Z.
  LmeOptions options;
  const Grid<1> line(Vector<1>(0.0), 0.5, {10});
  LmeReferenceShape<1> lme(line, options);
  CHECK(lme.capacity() == 5);  // floor(2 R / h) + 1
  int nodes[5];
  double N[5];
  Vector<1> gradients[5];
  REQUIRE(lme.evaluate(0, Vector<1>(2.25), nodes, N, gradients) == 4);
  const double Z = 2.0 * std::exp(-0.75) + 2.0 * std::exp(-6.75);
  const double J = 2.0 * (0.25 * std::exp(-0.75) + 2.25 * std::exp(-6.75)) / Z;
  for (int k = 0; k < 4; ++k) {
    const double d = (2.25 - 0.5 * nodes[k]) / 0.5;
    CHECK(N[k] == doctest::Approx(std::exp(-3.0 * d * d) / Z).epsilon(1e-14));
    CHECK(gradients[k][0] == doctest::Approx(-N[k] * d / (J * 0.5)).epsilon(1e-13));
  }
  CHECK(lme.diagnostics().newton_iterations_max() == 0);
  // Off the centre, x = 2.35 (4.7 cells: the nodes 3 to 6 are within R). Newton must move
  // lambda; at its root r = sum N_I d_I = 0, which the values by hand of Eq. (35) confirm at the lambda found.
  REQUIRE(lme.evaluate(0, Vector<1>(2.35), nodes, N, gradients) == 4);
  double r = 0.0;
  for (int k = 0; k < 4; ++k) r += N[k] * (2.35 - 0.5 * nodes[k]) / 0.5;
  CHECK(std::abs(r) <= 1e-10);
  CHECK(lme.diagnostics().newton_iterations_max() >= 1);
}

TEST_CASE("LME reference: partition of unity, linear reproduction and grad N by finite differences, 1D and 2D") {
  LmeOptions options;
  options.newton_tolerance = 1e-13;  // so that finite differences of N can check grad N (check_lme_properties)
  const Grid<1> line(Vector<1>(-1.0), 0.25, {16});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  for (double gamma : {0.8, 3.0, 5.0, 10.0}) {  // the authors' values, and a sharp one (1D only: 2D needs gamma <= 6.9)
    options.gamma = gamma;
    LmeReferenceShape<1> lme(line, options);
    for (double x : {-1.0, -1.0 + 2.5e-4, -0.9, -0.625, -0.13, 0.0, 0.37, 1.1, 2.99, 3.0}) {
      INFO("gamma = ", gamma, ", x = ", x);
      testing::check_lme_properties(lme, line, Vector<1>(x));
    }
    if (gamma > 6.9) continue;
    LmeReferenceShape<2> lme2(plane, options);
    for (const Vector<2>& x : {Vector<2>(0.0, 0.0), Vector<2>(5e-4, 1.1), Vector<2>(0.05, 0.02), Vector<2>(0.75, 0.25),
                               Vector<2>(1.3, 0.7), Vector<2>(2.99, 1.98), Vector<2>(3.0, 2.0), Vector<2>(1.2, 1e-4)}) {
      INFO("gamma = ", gamma, ", x = ", x.transpose());
      testing::check_lme_properties(lme2, plane, x);
    }
  }
  // Outside the grid, and one update allowed where Newton needs several: a ShapeFailure naming both.
  options.gamma = 3.0;
  LmeReferenceShape<2> lme2(plane, options);
  int nodes[64];
  double values[64];
  Vector<2> gradients[64];
  CHECK_THROWS_WITH_AS(lme2.evaluate(0, Vector<2>(-1e-12, 1.0), nodes, values, gradients), "particle left the grid",
                       ShapeFailure);
  options.max_iterations = 1;
  LmeReferenceShape<2> capped(plane, options);
  CHECK_THROWS_WITH_AS(capped.evaluate(2, Vector<2>(0.005, 1.0), nodes, values, gradients),
                       doctest::Contains("LME Newton did not converge: 1 iterations, |r|/h = "), ShapeFailure);
  CHECK(capped.evaluate(1, Vector<2>(1.25, 1.25), nodes, values, gradients) == 16);  // a cell centre: no update needed
}

TEST_CASE("Eq. (37), Eq. (38): r and J are the gradient and Hessian of log Z of Eq. (36), by finite differences") {
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const double radius_squared = -std::log(1e-6) / 3.0, beta = 3.0, step = 1e-5;
  int nodes[16];
  Vector<2> offsets[16];
  double N[16];
  const int count = lme_neighbours(plane, radius_squared, 16, 0, Vector<2>(4.4, 5.7), nodes, offsets);
  REQUIRE(count >= 12);
  const Vector<2> lambda(0.3, -0.7);
  auto log_z = [&](const Vector<2>& l) { return lme_log_partition(count, offsets, beta, l); };
  auto residual = [&](const Vector<2>& l) {
    lme_shape_values(count, offsets, beta, l, N);
    return lme_residual(count, offsets, N);
  };
  const Vector<2> r = residual(lambda);
  const Matrix<2> J = lme_hessian(count, offsets, N, r);
  double sum = 0.0;
  for (int I = 0; I < count; ++I) sum += N[I];
  CHECK(sum == doctest::Approx(1.0).epsilon(1e-15));  // Eq. (35) is a partition of unity at any lambda
  for (int k = 0; k < 2; ++k) {
    const Vector<2> e = step * Vector<2>::Unit(k);
    CHECK(r[k] == doctest::Approx((log_z(lambda + e) - log_z(lambda - e)) / (2.0 * step)).epsilon(1e-8));
    CHECK((J.col(k) - (residual(lambda + e) - residual(lambda - e)) / (2.0 * step)).norm() <= 1e-8);
  }
  // Eq. (40) by hand: beta = 3, lambda = (0.5, -1), x - x_I = (1, 2): -3 (1 + 4) + (0.5 - 2) = -16.5; and
  // Eq. (34): H of a uniform partition of 4 is log 4, 0 log 0 = 0.
  CHECK(lme_exponent<2>(3.0, Vector<2>(0.5, -1.0), Vector<2>(1.0, 2.0)) == -16.5);
  const double uniform[4] = {0.25, 0.25, 0.25, 0.25}, corner[3] = {1.0, 0.0, 0.0};
  CHECK(lme_entropy(4, uniform) == doctest::Approx(std::log(4.0)).epsilon(1e-15));
  CHECK(lme_entropy(3, corner) == 0.0);
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
  LmeReferenceShape<1> lme(line, options);
  check(lme, line, Vector<1>(4.3), {{3, 1.0}, {4, -2.0}, {5, 1.0}});  // a second difference
  check(lme, line, Vector<1>(4.3), {{3, 1.0}, {4, -1.0}, {5, -1.0}, {6, 1.0}});  // the neighbours are nodes 3 to 6
  LmeReferenceShape<2> lme2(plane, options);
  const int i = 4, j = 5;  // the corners of the cell that contains x: a twist
  check(lme2, plane, Vector<2>(4.3, 5.6),
        {{plane.node_index({i, j}), 1.0}, {plane.node_index({i + 1, j}), -1.0}, {plane.node_index({i, j + 1}), -1.0},
         {plane.node_index({i + 1, j + 1}), 1.0}});
}

}  // namespace mpm
