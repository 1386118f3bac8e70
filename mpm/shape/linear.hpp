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

  explicit LinearShape(const Grid<Dim>& grid) : grid_(grid), inverse_h_(1.0 / grid.spacing()) {}

  /// Nodes per particle: the corners of one cell.
  int capacity() const { return 1 << Dim; }

  /// Called once per run before the first step; linear shapes keep no per-particle state.
  void initialise(const Particles<Dim>& /*particles*/) {}

  /// N_I(x_p) and grad N_I(x_p) for the nodes of the cell that contains x_p: per axis the lattice coordinate
  /// \f$ \xi = (x - o)/h \f$, its cell \f$ c = \lfloor \xi \rfloor \f$ (the last cell on the upper face, as Grid::cell_of),
  /// and the hats \f$ 1 - (\xi - c) \f$, \f$ \xi - c \f$ with slopes \f$ \mp 1/h \f$.
  /// \throws ShapeFailure if x_p is outside the grid: \f$ \xi \f$ outside [0, cells] (multiplied by 1/h, not divided
  /// by h as Grid::contains and Grid::cell_of do: the two can differ by a rounding at the edge).
  int evaluate(int particle, const Vector<Dim>& x, int* nodes, double* values, Vector<Dim>* gradients) {
    std::array<AxisFactors<2>, Dim> axes;
    for (int axis = 0; axis < Dim; ++axis) {
      const double xi = (x[axis] - grid_.origin()[axis]) * inverse_h_;
      if (!(xi >= 0.0 && xi <= grid_.cells(axis))) throw ShapeFailure(particle, "particle left the grid");  // also NaN
      const int cell = std::min(static_cast<int>(xi), grid_.cells(axis) - 1);  // xi >= 0: truncation is the floor
      const double local = xi - cell;                                          // in [0, 1]
      axes[axis].first = cell;
      axes[axis].add(1.0 - local, -inverse_h_);  // node cell
      axes[axis].add(local, inverse_h_);         // node cell + 1
    }
    const int count = tensor_product_stencil(grid_, axes, nodes, values, gradients);
    diagnostics_.record(count);
    return count;
  }

  const ShapeDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  Grid<Dim> grid_;
  double inverse_h_;  ///< 1 / h
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
