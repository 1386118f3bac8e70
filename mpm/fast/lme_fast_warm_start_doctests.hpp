/// \file
/// The doctests of the fast LME form's warm start, mpm/fast/lme_fast.hpp (which includes this file at its end):
/// Newton's iterations from a warm start and its failures, the predicted start (lme_multiplier_slope and
/// lme_multiplier_curvature) by finite differences and by its order, and the weights moved without exponentials
/// (lme_weights_moved) against exp(). Its equations by hand and its agreement with the reference form are tested in
/// mpm/fast/lme_fast_doctests.hpp.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mpm/fast/lme_fast.hpp"

namespace mpm::testing {

/// The plane of the warm-start tests: an 8 x 8 grid of h = 0.25, Newton to 1e-13, buffers for 64 neighbours, and
/// lambda* h at a point converged from scratch.
struct WarmStartPlane {
  LmeOptions options = [] {
    LmeOptions tight;
    tight.newton_tolerance = 1e-13;
    return tight;
  }();
  const double h = 0.25;
  const Grid<2> plane{Vector<2>(0.0, 0.0), h, {8, 8}};
  const double radius_squared = -std::log(options.support_tolerance) / options.gamma;
  int nodes[64];
  double values[64];
  Vector<2> offsets[64];
  /// lambda* h at `at`, converged from scratch (a fresh shape, lambda = 0).
  Vector<2> multiplier_at(const Vector<2>& at) {
    fast::LmeShape<2> lme(plane, options);
    lme.initialise(1);
    lme.evaluate(0, at, nodes, values, offsets);
    return Vector<2>(lme.lagrange_multiplier(0) * h);
  }
};

}  // namespace mpm::testing

namespace mpm::fast {

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

TEST_CASE_FIXTURE(testing::WarmStartPlane, "LME warm start: d lambda*/dx = 2 beta I - J^-1 by finite differences") {
  const double delta = 1e-5;  // central differences: error ~ delta^2 |d3 lambda / dx3| ~ 1e-9
  for (const Vector<2>& x : {Vector<2>(1.0, 1.0), Vector<2>(0.93, 1.21), Vector<2>(0.1, 1.7), Vector<2>(0.02, 0.05)}) {
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
}

TEST_CASE_FIXTURE(testing::WarmStartPlane, "LME warm start to second order: the third moments by hand, errors of order |u|^2 and |u|^3") {
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
}

TEST_CASE_FIXTURE(testing::WarmStartPlane, "LME warm start: the predicted start saves Newton steps along a slanted path") {
  // The slanted path of the second-order test above, 1e-3 h and 1e-4 h per evaluation: started from the last
  // lambda*, Newton is ~1e-3 (1e-4) from the root and needs two steps to reach 1e-10 (the Newton test above); from the
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

}  // namespace mpm::fast
