/// \file
/// Linear shape functions: the 1D hat and its tensor product, the bilinear Q4 of a 2D cell (paper/04_shape_functions.md).
///
/// \f$ S(\Delta) = 1 - |\Delta|/h \f$ for \f$ |\Delta| \le h \f$, so a particle sees the 2^Dim nodes of its cell.
/// grad N jumps when a particle crosses a cell face: the source of grid-crossing noise (Fig. 6).
#pragma once
#include <doctest/doctest.h>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/shape_diagnostics.hpp"
#include "mpm/shape/shape_properties.hpp"
#include "mpm/shape/tensor_product.hpp"

namespace mpm {

template <int Dim>
class LinearShape {
 public:
  static constexpr const char* name = "linear";

  explicit LinearShape(const Grid<Dim>& grid) : grid_(grid) {}

  /// The stencil lists its nodes in ascending order (the tensor product, x fastest).
  static constexpr bool nodes_ascending = true;

  /// Nodes per particle: the corners of one cell.
  int capacity() const { return 1 << Dim; }

  /// Called once per run before the first step; linear shapes keep no per-particle state.
  void initialise(const Particles<Dim>& /*particles*/) {}

  /// N_I(x_p) and grad N_I(x_p) for the nodes of the cell that contains x_p.
  /// \throws ShapeFailure if x_p is outside the grid.
  int evaluate(int particle, const Vector<Dim>& x, int* nodes, double* values, Vector<Dim>* gradients) {
    if (!grid_.contains(x)) throw ShapeFailure(particle, "particle left the grid");
    const double h = grid_.spacing();
    const auto cell = grid_.cell_of(x);
    std::array<AxisFactors<2>, Dim> axes;
    for (int axis = 0; axis < Dim; ++axis) {
      const double xi = (x[axis] - grid_.origin()[axis]) / h - cell[axis];  // local coordinate in [0, 1]
      axes[axis].add(cell[axis], 1.0 - xi, -1.0 / h);
      axes[axis].add(cell[axis] + 1, xi, 1.0 / h);
    }
    const int count = tensor_product_stencil(grid_, axes, nodes, values, gradients);
    diagnostics_.record(count);
    return count;
  }

  const ShapeDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  Grid<Dim> grid_;
  ShapeDiagnostics diagnostics_;
};

TEST_CASE("Linear shape functions: values by hand, and every property in 1D and 2D") {
  const Grid<1> line(Vector<1>(-1.0), 0.25, {16});
  LinearShape<1> hat(line);
  int nodes[2];
  double values[2];
  Vector<1> gradients[2];
  REQUIRE(hat.evaluate(0, Vector<1>(-0.4375), nodes, values, gradients) == 2);  // a quarter into cell 2
  CHECK(nodes[0] == 2);
  CHECK(values[0] == doctest::Approx(0.75).epsilon(1e-15));
  CHECK(values[1] == doctest::Approx(0.25).epsilon(1e-15));
  CHECK(gradients[0][0] == doctest::Approx(-4.0));
  CHECK_THROWS_AS(hat.evaluate(0, Vector<1>(3.01), nodes, values, gradients), ShapeFailure);

  testing::PropertyTolerances tolerance;
  for (double x : {-1.0, -0.99, -0.6, -0.13, 0.0, 0.37, 2.99, 3.0}) {
    tolerance.check_finite_difference = std::abs(x / 0.25 - std::round(x / 0.25)) > 1e-3;  // not at a kink
    testing::check_shape_properties(hat, line, 0, Vector<1>(x), tolerance);
  }

  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  LinearShape<2> q4(plane);
  for (const Vector<2>& x : {Vector<2>(0.01, 0.02), Vector<2>(1.3, 0.7), Vector<2>(2.99, 1.98), Vector<2>(1.61, 1.99)}) {
    tolerance.check_finite_difference = true;
    testing::check_shape_properties(q4, plane, 0, x, tolerance);
  }
}

}  // namespace mpm
