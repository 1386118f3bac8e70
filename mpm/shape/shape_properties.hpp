/// \file
/// The properties every shape function of the method must have, as doctest checks shared by the
/// doctests of linear.hpp, ugimp.hpp and both LME forms. At a point x with stencil {I}:
///   partition of unity      sum_I N_I = 1
///   linear reproduction     sum_I N_I x_I = x
///   gradient of unity       sum_I grad N_I = 0
///   gradient of x           sum_I x_I (x) grad N_I = identity
///   non-negativity          N_I >= 0
///   consistency             grad N_I = central finite differences of N_I
/// Tolerances are relative to the cell size h (lengths scaled by h, gradients by 1/h).
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "mpm/grid/grid.hpp"

namespace mpm::testing {

struct PropertyTolerances {
  double unity = 1e-13;          ///< |sum N - 1|, and |sum N x_I - x| / h
  double gradient = 1e-12;       ///< |sum grad N| h, and |sum x_I (x) grad N - I|
  double finite_difference = 1e-6;  ///< |grad N - FD| h
  bool check_finite_difference = true;
};

/// The dense vector of N_I over all nodes of the grid at x (0 off the stencil).
template <int Dim, class Shape>
std::vector<double> dense_values(Shape& shape, const Grid<Dim>& grid, int particle, const Vector<Dim>& x) {
  const int capacity = shape.capacity();
  std::vector<int> nodes(capacity);
  std::vector<double> values(capacity);
  std::vector<Vector<Dim>> gradients(capacity);
  std::vector<double> dense(grid.node_count(), 0.0);
  const int count = shape.evaluate(particle, x, nodes.data(), values.data(), gradients.data());
  for (int k = 0; k < count; ++k) dense[nodes[k]] += values[k];
  return dense;
}

template <int Dim, class Shape>
void check_shape_properties(Shape& shape, const Grid<Dim>& grid, int particle, const Vector<Dim>& x,
                            const PropertyTolerances& tolerance) {
  const double h = grid.spacing();
  const int capacity = shape.capacity();
  std::vector<int> nodes(capacity);
  std::vector<double> values(capacity);
  std::vector<Vector<Dim>> gradients(capacity);
  const int count = shape.evaluate(particle, x, nodes.data(), values.data(), gradients.data());
  REQUIRE(count > 0);
  REQUIRE(count <= capacity);

  double sum = 0.0;
  Vector<Dim> reproduced = Vector<Dim>::Zero(), gradient_sum = Vector<Dim>::Zero();
  Matrix<Dim> gradient_of_x = Matrix<Dim>::Zero();
  for (int k = 0; k < count; ++k) {
    const Vector<Dim> node_x = grid.node_position(nodes[k]);
    CHECK(values[k] >= -1e-15);
    sum += values[k];
    reproduced += values[k] * node_x;
    gradient_sum += gradients[k];
    gradient_of_x += node_x * gradients[k].transpose();
  }
  INFO("point x = ", x.transpose(), ", stencil size ", count);
  CHECK(std::abs(sum - 1.0) <= tolerance.unity);
  CHECK((reproduced - x).norm() / h <= tolerance.unity);
  CHECK(gradient_sum.norm() * h <= tolerance.gradient);
  CHECK((gradient_of_x - Matrix<Dim>::Identity()).norm() <= tolerance.gradient);

  if (!tolerance.check_finite_difference) return;
  const double step = 1e-6 * h;
  for (int axis = 0; axis < Dim; ++axis) {
    Vector<Dim> forward = x, backward = x;
    forward[axis] += step;
    backward[axis] -= step;
    const auto plus = dense_values(shape, grid, particle, forward);
    const auto minus = dense_values(shape, grid, particle, backward);
    for (int k = 0; k < count; ++k) {
      const double finite_difference = (plus[nodes[k]] - minus[nodes[k]]) / (2.0 * step);
      CHECK(std::abs(gradients[k][axis] - finite_difference) * h <= tolerance.finite_difference);
    }
  }
  dense_values(shape, grid, particle, x);  // leave any warm-start state at x
}

}  // namespace mpm::testing
