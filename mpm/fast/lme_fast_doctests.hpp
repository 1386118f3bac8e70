/// \file
/// The doctests of the fast LME form, mpm/fast/lme_fast.hpp (which includes this file at its end): its equations
/// by hand and by finite differences, and its agreement with the reference form of mpm/shape/lme_reference.hpp on
/// random particle paths. Its warm start, its Newton iterations and its weights moved without exponentials are
/// tested in mpm/fast/lme_fast_warm_start_doctests.hpp.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "mpm/fast/lme_fast.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/lme_reference.hpp"
#include "mpm/shape/shape_properties.hpp"

namespace mpm::testing {

/// At a node or a cell centre, every neighbour has its mirror image through x, so r(0) = 0: lambda* = 0,
/// \f$ N_I = e^{-\gamma |x - x_I|^2 / h^2} / Z \f$ over the nodes within R, and
/// \f$ \nabla N_I = -N_I J^{-1} (x - x_I) \f$ with \f$ J = \sum_I N_I (x - x_I) \otimes (x - x_I) \f$, all by hand.
/// N is symmetric and grad N antisymmetric through x. The point is reached warm from `start`, where
/// lambda is far from 0, so Newton must bring it back.
/// It stops at |r|/h <= tol, so (cell units, to first order) |lambda h| <= b = tol / lambda_min(J); N_I is
/// then off by at most b m relatively, m the largest |x - x_I|/h; J by about 2 b m |J|; and grad N_I h by
/// at most (N_I / lambda_min) (3 b m |x - x_I|/h + tol). These are the tolerances, plus rounding.
template <int Dim, class Shape>
void check_lme_symmetric_point(Shape& lme, const Grid<Dim>& grid, const Vector<Dim>& start, const Vector<Dim>& x,
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

/// The largest difference between the fast and the reference LME forms along random particle paths in `grid`:
/// `particles` particles from uniform random points (the first two from the grid's lower and upper corners), each
/// then evaluated at `steps` points a random move of at most 0.05 h per axis apart (kept inside the grid: a move
/// beyond its edge stops there), as a run moves them: the fast form warm-starts Newton from each particle's last evaluation, the reference from 0. Returns
/// \f$ \max |N_I - N_I^{ref}| \f$ and \f$ \max |\nabla N_I - \nabla N_I^{ref}| h \f$, the larger; the two list the same nodes.
template <int Dim>
double largest_lme_form_difference(const Grid<Dim>& grid, const LmeOptions& options, std::mt19937& random,
                                   int particles = 12, int steps = 40) {
  fast::LmeShape<Dim> fast(grid, options);
  LmeReferenceShape<Dim> reference(grid, options);
  fast.initialise(particles);
  const int capacity = fast.capacity();
  REQUIRE(reference.capacity() == capacity);
  std::vector<int> nodes(capacity), reference_nodes(capacity);
  std::vector<double> N(capacity), reference_N(capacity);
  std::vector<Vector<Dim>> gradients(capacity), reference_gradients(capacity);
  std::uniform_real_distribution<double> unit(0.0, 1.0), move(-0.05, 0.05);
  const Vector<Dim> lower = grid.origin(), upper = grid.upper_corner();
  const double h = grid.spacing();
  double largest = 0.0;
  for (int p = 0; p < particles; ++p) {
    Vector<Dim> x;
    for (int axis = 0; axis < Dim; ++axis) x[axis] = lower[axis] + unit(random) * (upper[axis] - lower[axis]);
    if (p == 0) x = lower;  // two paths from the grid's corners, where lambda h is large and J nearly singular
    if (p == 1) x = upper;
    for (int step = 0; step < steps; ++step) {
      const int count = fast.evaluate(p, x, nodes.data(), N.data(), gradients.data());
      const int reference_count =
          reference.evaluate(p, x, reference_nodes.data(), reference_N.data(), reference_gradients.data());
      REQUIRE(reference_count == count);
      for (int k = 0; k < count; ++k) {
        REQUIRE(nodes[k] == reference_nodes[k]);
        largest = std::max(largest, std::abs(N[k] - reference_N[k]));
        largest = std::max(largest, (gradients[k] - reference_gradients[k]).norm() * h);
      }
      for (int axis = 0; axis < Dim; ++axis)
        x[axis] = std::min(upper[axis], std::max(lower[axis], x[axis] + move(random) * h));
    }
  }
  return largest;
}

}  // namespace mpm::testing

namespace mpm::fast {

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

TEST_CASE("LME beta rule mean_neighbour_distance: the default's N at a cell centre, every property elsewhere") {
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
  // beta = gamma / hbar^2. In 1D at a cell centre with gamma = 3 the neighbours are at 0.5 h and 1.5 h,
  // so hbar = h and N is the default's (paper/09_choices.md, 'The beta rule'), to rounding. (So it is wherever x has
  // four neighbours, two on each side: their distances add up to 4 h.)
  int nodes[64];
  double values[64], reference[64];
  Vector<1> gradients[64];
  LmeOptions options;
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

TEST_CASE("LME under the authors' beta rule is the standard LME at gamma = beta h^2 there, by hand") {
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
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

TEST_CASE("The fast LME form agrees with the reference on random particle paths: 1D and 2D, gamma 0.8, 1.5, 3, every beta rule, both neighbour sets") {
  // Both converged to |r|/h <= 1e-13 at every point, the fast form warm-started along each path, the reference
  // from lambda = 0: N and grad N h agree to 1e-9 (the largest difference measured over these paths: 1.6e-12).
  LmeOptions options;
  options.newton_tolerance = 1e-13;
  const Grid<1> line(Vector<1>(-1.0), 0.25, {16});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  std::mt19937 random(32);
  for (const auto neighbours : {LmeOptions::Neighbours::support_radius, LmeOptions::Neighbours::authors_patch})
  for (const auto rule : {LmeOptions::BetaRule::grid_spacing, LmeOptions::BetaRule::mean_neighbour_distance,
                          LmeOptions::BetaRule::authors})
    for (double gamma : {0.8, 1.5, 3.0}) {
      options.beta_rule = rule;
      options.neighbours = neighbours;
      options.gamma = gamma;
      INFO("gamma = ", gamma, ", beta rule ", static_cast<int>(rule), ", neighbours ", static_cast<int>(neighbours));
      const double difference = std::max(testing::largest_lme_form_difference(line, options, random),
                                         testing::largest_lme_form_difference(plane, options, random));
      CHECK(difference <= 1e-9);
    }
}

}  // namespace mpm::fast
