/// \file
/// Tensor-product stencils: N_I(x) = prod_a S(x_a - x_{I,a}) and
/// \f$ \partial_a N_I = S'(x_a - x_{I,a}) \prod_{b \ne a} S(x_b - x_{I,b}) \f$.
/// Shared by the linear (Q4) and uGIMP shape functions, which differ only in their 1D factor S.
#pragma once
#include <array>

#include "mpm/grid/grid.hpp"

namespace mpm {

/// The 1D factors of one axis: lattice index of each node, S and dS/dx.
template <int MaxPerAxis>
struct AxisFactors {
  int count = 0;
  std::array<int, MaxPerAxis> lattice{};
  std::array<double, MaxPerAxis> value{};
  std::array<double, MaxPerAxis> derivative{};
  void add(int index, double s, double ds) {
    lattice[count] = index;
    value[count] = s;
    derivative[count] = ds;
    ++count;
  }
};

/// Combines per-axis factors into the stencil of a point; returns the number of nodes written.
template <int Dim, int MaxPerAxis, std::size_t Axes>
int tensor_product_stencil(const Grid<Dim>& grid, const std::array<AxisFactors<MaxPerAxis>, Axes>& axes, int* nodes,
                           double* values, Vector<Dim>* gradients) {
  static_assert(Axes == Dim, "one factor per axis");
  std::array<int, Dim> digit{};
  int written = 0;
  while (true) {
    typename Grid<Dim>::MultiIndex lattice{};
    double value = 1.0;
    Vector<Dim> gradient = Vector<Dim>::Ones();
    for (int axis = 0; axis < Dim; ++axis) {
      const auto& factor = axes[axis];
      lattice[axis] = factor.lattice[digit[axis]];
      value *= factor.value[digit[axis]];
      for (int other = 0; other < Dim; ++other)
        gradient[other] *= (other == axis) ? factor.derivative[digit[axis]] : factor.value[digit[axis]];
    }
    nodes[written] = grid.node_index(lattice);
    values[written] = value;
    gradients[written] = gradient;
    ++written;
    int axis = 0;  // odometer over the per-axis digits
    while (axis < Dim && ++digit[axis] == axes[axis].count) digit[axis++] = 0;
    if (axis == Dim) return written;
  }
}

}  // namespace mpm
