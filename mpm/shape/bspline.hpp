/// \file
/// Quadratic and cubic B-spline shape functions on the grid's uniform knots (paper/04_shape_functions.md,
/// "B-splines"): the field's standard cure for grid crossing (Steffen, Kirby and Berzins 2008; de Koster
/// et al. 2020), a baseline beside the paper's uGIMP and LME. Not in the paper: it has no equation number.
///
/// The 1D function of node I is the centred cardinal B-spline of the distance \f$ r = |x - x_I|/h \f$:
/// \f[ S_2(r) = \begin{cases} \tfrac34 - r^2 & r \le \tfrac12 \\ \tfrac12 (\tfrac32 - r)^2 & \tfrac12 \le r \le \tfrac32 \end{cases}
///     \qquad
///     S_3(r) = \begin{cases} \tfrac23 - r^2 + \tfrac12 r^3 & r \le 1 \\ \tfrac16 (2 - r)^3 & 1 \le r \le 2 \end{cases} \f]
/// (\f$ C^1 \f$ and \f$ C^2 \f$: no gradient jump when a particle crosses a face), and in 2D their tensor product.
///
/// At the grid's edge (a wall, or the end of the grid) the functions of the ghost node beyond it,
/// \f$ x_{-1} = 2x_0 - x_1 \f$, are folded onto the two nodes it is the linear extrapolation of:
/// \f$ N_0 \mathrel{+}= 2 N_{-1},\ N_1 \mathrel{-}= N_{-1} \f$ (and alike at the upper edge). Partition of unity and
/// linear reproduction \f$ \sum_I N_I x_I = x \f$ hold up to the edge, every N stays non-negative, and a
/// particle on the edge node interpolates it exactly (quadratic: \f$ N_0 = 1 - \xi,\ N_1 = \xi \f$ for
/// \f$ \xi = (x - x_0)/h \le \tfrac12 \f$, a hat: the boundary-modified B-spline).
#pragma once
#include <doctest/doctest.h>

#include <cmath>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/shape_diagnostics.hpp"
#include "mpm/shape/shape_properties.hpp"
#include "mpm/shape/tensor_product.hpp"

namespace mpm {

/// The cardinal B-spline of degree 2 or 3 at the distance r = |x - x_I| / h (file comment), 0 beyond its support.
inline double bspline_value(int degree, double r) {
  r = std::abs(r);
  if (degree == 2) return r <= 0.5 ? 0.75 - r * r : r <= 1.5 ? 0.5 * (1.5 - r) * (1.5 - r) : 0.0;
  return r <= 1.0 ? 2.0 / 3.0 - r * r + 0.5 * r * r * r : r <= 2.0 ? (2.0 - r) * (2.0 - r) * (2.0 - r) / 6.0 : 0.0;
}

/// \f$ dS/d\delta \f$ of the signed distance \f$ \delta = (x - x_I)/h \f$: \f$ S_2' = -2\delta \f$ or \f$ -(\tfrac32 - |\delta|)\,\mathrm{sgn}\,\delta \f$;
/// \f$ S_3' = (-2|\delta| + \tfrac32 \delta^2)\,\mathrm{sgn}\,\delta \f$ or \f$ -\tfrac12 (2 - |\delta|)^2 \mathrm{sgn}\,\delta \f$.
inline double bspline_derivative(int degree, double delta) {
  const double r = std::abs(delta), sign = delta < 0.0 ? -1.0 : 1.0;
  if (degree == 2) return r <= 0.5 ? -2.0 * delta : r <= 1.5 ? -sign * (1.5 - r) : 0.0;
  return r <= 1.0 ? sign * (-2.0 * r + 1.5 * r * r) : r <= 2.0 ? -sign * 0.5 * (2.0 - r) * (2.0 - r) : 0.0;
}

template <int Dim, int Degree>
class BsplineShape {
  static_assert(Degree == 2 || Degree == 3, "quadratic or cubic");

 public:
  static constexpr const char* name = Degree == 2 ? "bspline2" : "bspline3";

  explicit BsplineShape(const Grid<Dim>& grid) : grid_(grid), inverse_h_(1.0 / grid.spacing()) {}

  /// Nodes per particle: 3 (quadratic) or 4 (cubic) per axis.
  int capacity() const { return Dim == 1 ? Degree + 1 : (Degree + 1) * (Degree + 1); }

  /// Called once per run before the first step; B-splines keep no per-particle state.
  void initialise(const Particles<Dim>& /*particles*/) {}

  /// N_I(x_p) and grad N_I(x_p) for the nodes within the support, ghost nodes folded at the grid's edge.
  /// \throws ShapeFailure if x_p is outside the grid: a lattice coordinate \f$ \xi_a = (x_a - o_a)/h \f$ outside
  /// [0, cells], tested on the coordinate the factors are computed from (multiplied by 1/h: Grid::contains
  /// divides, and its division cost a sixth of the cubic's stencils; the two can differ by a rounding at the edge).
  int evaluate(int particle, const Vector<Dim>& x, int* nodes, double* values, Vector<Dim>* gradients) {
    std::array<double, Dim> xi;
    for (int axis = 0; axis < Dim; ++axis) {
      xi[axis] = (x[axis] - grid_.origin()[axis]) * inverse_h_;
      if (!(xi[axis] >= 0.0 && xi[axis] <= grid_.cells(axis))) throw ShapeFailure(particle, "particle left the grid");  // also NaN
    }
    // Each axis's factors are set by set_axis_factors(); left unset in 2D, where zeroing them per particle cost a
    // sixth of the stencils' time, and zeroed in 1D, where it costs nothing measurable (and spares a false warning).
    std::array<AxisFactors<Degree + 1>, Dim> axes;
    if constexpr (Dim == 1) axes = {};
    for (int axis = 0; axis < Dim; ++axis) set_axis_factors(xi[axis], grid_.cells(axis), axes[axis]);
    const int count = tensor_product_stencil(grid_, axes, nodes, values, gradients);
    diagnostics_.record(count);
    return count;
  }

  /// Writes `factors`, the 1D factors of one axis at the lattice coordinate xi in [0, cells], ghost nodes folded.
  /// The weights are written in place (a copy through a local array, which the compiler moves in 16-byte pieces
  /// after 8-byte stores, stalled each particle on store forwarding). At an edge the ghost is folded there and
  /// dropped: the last node by the count, the first by moving the others down one place in a loop of fixed
  /// length. (Two other forms were slower: shifted by a loop over a variable count, and folded in local arrays
  /// then copied; benchmarks/README.md, "Optimisations tried", has the measurements.)
  void set_axis_factors(double xi, int cells, AxisFactors<Degree + 1>& factors) const {
    // The nodes of the support: xi - 1.5 < i < xi + 1.5 (quadratic), xi - 2 < i < xi + 2 (cubic).
    // (the cubic's cell is the last one on the upper edge, xi = cells, as Grid::cell_of has it)
    // (xi >= 0 inside the grid: truncation is the floor, without a call to floor())
    const int first = Degree == 2 ? static_cast<int>(xi + 0.5) - 1 : std::min(static_cast<int>(xi), cells - 1) - 1;
    const bool ghost_below = first < 0;  // only node -1 can lie in the support of a point inside the grid
    const bool ghost_above = first + Degree > cells;
    cell_weights(xi - (first + 1), factors.value.data(), factors.derivative.data());
    for (int k = 0; k <= Degree; ++k) factors.derivative[k] *= inverse_h_;
    factors.first = first;
    factors.count = Degree + 1;
    if (!ghost_below && !ghost_above) return;  // away from the edges: the weights as they are
    // Fold a ghost node below 0 or above `cells` onto the two nodes next to it (file comment), and drop it.
    double* value = factors.value.data();
    double* derivative = factors.derivative.data();
    if (ghost_below) {
      value[1] += 2.0 * value[0], derivative[1] += 2.0 * derivative[0];
      value[2] -= value[0], derivative[2] -= derivative[0];
    }
    if (ghost_above) {
      value[Degree - 1] += 2.0 * value[Degree], derivative[Degree - 1] += 2.0 * derivative[Degree];
      value[Degree - 2] -= value[Degree], derivative[Degree - 2] -= derivative[Degree];
      --factors.count;  // the last node dropped
    }
    if (ghost_below) {  // the first node dropped: the others move down one place, a loop of fixed length
      for (int k = 0; k < Degree; ++k) value[k] = value[k + 1], derivative[k] = derivative[k + 1];
      ++factors.first;
      --factors.count;
    }
  }

  /// The cardinal B-splines of the Degree + 1 nodes of a support, bspline_value(Degree, xi - node), and their
  /// derivatives in xi, expanded as polynomials of the offset t = xi - (first + 1) from the second node: one
  /// evaluation per node without a branch (a third of the cost of the stencils through bspline_value).
  /// Quadratic, \f$ t \in [-\tfrac12, \tfrac12] \f$: \f$ \tfrac12(\tfrac12 - t)^2,\ \tfrac34 - t^2,\ \tfrac12(\tfrac12 + t)^2 \f$.
  /// Cubic, \f$ t \in [0, 1] \f$: \f$ \tfrac16(1 - t)^3,\ \tfrac16(3t^3 - 6t^2 + 4),\ \tfrac16(-3t^3 + 3t^2 + 3t + 1),\ \tfrac16 t^3 \f$.
  static void cell_weights(double t, double* value, double* derivative) {
    if constexpr (Degree == 2) {
      const double left = 0.5 - t, right = 0.5 + t;
      value[0] = 0.5 * left * left, value[1] = 0.75 - t * t, value[2] = 0.5 * right * right;
      derivative[0] = -left, derivative[1] = -2.0 * t, derivative[2] = right;
    } else {
      constexpr double sixth = 1.0 / 6.0;  // multiplied by, not divided by: a division costs ten multiplications
      const double rest = 1.0 - t, t2 = t * t, t3 = t2 * t;
      value[0] = sixth * rest * rest * rest, value[1] = 0.5 * t3 - t2 + 4.0 * sixth;
      value[2] = 0.5 * (t2 + t - t3) + sixth, value[3] = sixth * t3;
      derivative[0] = -0.5 * rest * rest, derivative[1] = 1.5 * t2 - 2.0 * t;
      derivative[2] = -1.5 * t2 + t + 0.5, derivative[3] = 0.5 * t2;
    }
  }

  const ShapeDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  Grid<Dim> grid_;
  double inverse_h_;  ///< 1 / h
  ShapeDiagnostics diagnostics_;
};

TEST_CASE("B-splines: the cardinal functions by hand, C1 (quadratic) and C2 (cubic) at their knots") {
  CHECK(bspline_value(2, 0.0) == doctest::Approx(0.75));
  CHECK(bspline_value(2, 0.5) == doctest::Approx(0.5));
  CHECK(bspline_value(2, -1.0) == doctest::Approx(0.125));
  CHECK(bspline_value(2, 1.5) == 0.0);
  CHECK(bspline_value(3, 0.0) == doctest::Approx(2.0 / 3.0));
  CHECK(bspline_value(3, 1.0) == doctest::Approx(1.0 / 6.0));
  CHECK(bspline_value(3, -0.5) == doctest::Approx(2.0 / 3.0 - 0.25 + 0.0625));
  CHECK(bspline_value(3, 2.0) == 0.0);
  for (const int degree : {2, 3})
    for (double delta = -2.2; delta <= 2.2; delta += 0.0137) {  // the derivative is the derivative, by central differences
      const double step = 1e-6;
      CHECK(bspline_derivative(degree, delta) ==
            doctest::Approx((bspline_value(degree, delta + step) - bspline_value(degree, delta - step)) / (2.0 * step)).epsilon(1e-6).scale(1.0));
    }
  // continuity of the derivative at the knots (quadratic 0.5, 1.5; cubic 1, 2) and of the cubic's second derivative
  for (double knot : {0.5, 1.5}) CHECK(bspline_derivative(2, knot - 1e-12) == doctest::Approx(bspline_derivative(2, knot + 1e-12)).epsilon(1e-9).scale(1.0));
  for (double knot : {1.0, 2.0}) {
    CHECK(bspline_derivative(3, knot - 1e-12) == doctest::Approx(bspline_derivative(3, knot + 1e-12)).epsilon(1e-9).scale(1.0));
    const double left = (bspline_derivative(3, knot - 1e-6) - bspline_derivative(3, knot - 2e-6)) / 1e-6;
    const double right = (bspline_derivative(3, knot + 2e-6) - bspline_derivative(3, knot + 1e-6)) / 1e-6;
    CHECK(left == doctest::Approx(right).epsilon(1e-4).scale(1.0));
  }
}

TEST_CASE("B-splines: the weights of a support, expanded in the offset, equal the cardinal functions of each node's distance") {
  auto check = [](auto weights, int degree, double low, double high) {
    double value[4], derivative[4];
    for (double t = low; t <= high + 1e-12; t += 0.01) {
      weights(t, value, derivative);
      for (int k = 0; k <= degree; ++k) {  // node first + k lies at distance t + 1 - k from the point
        CHECK(value[k] == doctest::Approx(bspline_value(degree, t + 1.0 - k)).epsilon(1e-14).scale(1.0));
        CHECK(derivative[k] == doctest::Approx(bspline_derivative(degree, t + 1.0 - k)).epsilon(1e-14).scale(1.0));
      }
    }
  };
  check(BsplineShape<1, 2>::cell_weights, 2, -0.5, 0.5);
  check(BsplineShape<1, 3>::cell_weights, 3, 0.0, 1.0);
}

TEST_CASE("B-splines: a particle outside the grid, by a little or NaN, fails, and one on its edge does not") {
  const Grid<2> grid(Vector<2>(-1.0, 0.5), 0.25, {8, 6});  // [-1, 1] x [0.5, 2]
  auto check = [&](auto shape) {
    int nodes[16];
    double values[16];
    Vector<2> gradients[16];
    for (const Vector<2>& on_edge : {Vector<2>(-1.0, 0.5), Vector<2>(1.0, 2.0), Vector<2>(1.0, 1.2), Vector<2>(0.1, 0.5)})
      CHECK_NOTHROW(shape.evaluate(0, on_edge, nodes, values, gradients));
    for (const Vector<2>& outside : {Vector<2>(1.0 + 1e-9, 1.2), Vector<2>(-1.0 - 1e-9, 1.2), Vector<2>(0.1, 2.0 + 1e-9),
                                     Vector<2>(0.1, 0.5 - 1e-9), Vector<2>(0.1, std::nan(""))})
      CHECK_THROWS_AS(shape.evaluate(0, outside, nodes, values, gradients), ShapeFailure);
  };
  check(BsplineShape<2, 2>(grid));
  check(BsplineShape<2, 3>(grid));
}

TEST_CASE("B-splines: the grid's edge by hand: the quadratic's boundary hat, the cubic's folded ghost") {
  const Grid<1> line(Vector<1>(0.0), 0.5, {8});
  BsplineShape<1, 2> quadratic(line);
  int nodes[4];
  double values[4];
  Vector<1> gradients[4];
  // xi = 0.3 (x = 0.15): ghost -1 folded; N_0 = 1 - xi = 0.7, N_1 = xi = 0.3, N_2 = 0 (not in the support at xi < 0.5)
  const int count = quadratic.evaluate(0, Vector<1>(0.15), nodes, values, gradients);
  REQUIRE(count == 2);
  CHECK(nodes[0] == 0);
  CHECK(values[0] == doctest::Approx(0.7).epsilon(1e-14));
  CHECK(values[1] == doctest::Approx(0.3).epsilon(1e-14));
  CHECK(gradients[0][0] == doctest::Approx(-2.0).epsilon(1e-14));  // -1/h
  // at the upper edge node, the particle interpolates it exactly
  REQUIRE(quadratic.evaluate(0, Vector<1>(4.0), nodes, values, gradients) == 2);
  CHECK(nodes[1] == 8);
  CHECK(values[1] == doctest::Approx(1.0).epsilon(1e-14));
  // cubic at xi = 0.25: ghost (1 - 0.25)^3 / 6 = 0.0703125 folded; N_0 = S3(0.25) + 2 ghost, N_1 = S3(0.75) - ghost
  BsplineShape<1, 3> cubic(line);
  REQUIRE(cubic.evaluate(0, Vector<1>(0.125), nodes, values, gradients) == 3);
  CHECK(values[0] == doctest::Approx(2.0 / 3.0 - 0.0625 + 0.5 * 0.015625 + 2.0 * 0.0703125).epsilon(1e-14));
  CHECK(values[1] == doctest::Approx(2.0 / 3.0 - 0.5625 + 0.5 * 0.421875 - 0.0703125).epsilon(1e-14));
  CHECK(values[2] == doctest::Approx(std::pow(0.25, 3) / 6.0).epsilon(1e-14));  // S3(1.75)
  CHECK(values[1] >= 0.0);
}

TEST_CASE("B-splines: every shape property in 1D and 2D, inside, at faces and at the grid's edge") {
  testing::PropertyTolerances tolerance;
  const Grid<1> line(Vector<1>(-1.0), 0.25, {16});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  BsplineShape<1, 2> quadratic(line);
  BsplineShape<1, 3> cubic(line);
  BsplineShape<2, 2> quadratic_2d(plane);
  BsplineShape<2, 3> cubic_2d(plane);
  for (double x : {-1.0, -0.99, -0.875, -0.8, -0.6, -0.13, 0.0, 0.37, 2.7, 2.875, 2.99, 3.0}) {
    // C1 everywhere inside; the folded boundary functions have a kink where the ghost's support ends
    const double xi = (x + 1.0) / 0.25;
    tolerance.check_finite_difference = std::abs(xi - 0.5) > 1e-3 && std::abs(xi - 15.5) > 1e-3 && xi > 1e-3 && xi < 16.0 - 1e-3;
    testing::check_shape_properties(quadratic, line, 0, Vector<1>(x), tolerance);
    tolerance.check_finite_difference = xi > 1e-3 && xi < 16.0 - 1e-3 && std::abs(xi - 1.0) > 1e-3 && std::abs(xi - 15.0) > 1e-3;
    testing::check_shape_properties(cubic, line, 0, Vector<1>(x), tolerance);
  }
  tolerance.check_finite_difference = true;
  for (const Vector<2>& x : {Vector<2>(0.01, 0.02), Vector<2>(1.3, 0.7), Vector<2>(2.99, 1.98), Vector<2>(1.61, 1.99), Vector<2>(0.4, 1.0)}) {
    testing::check_shape_properties(quadratic_2d, plane, 0, x, tolerance);
    testing::check_shape_properties(cubic_2d, plane, 0, x, tolerance);
  }
}

}  // namespace mpm
