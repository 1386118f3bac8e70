/// \file
/// Tensor-product stencils: N_I(x) = prod_a S(x_a - x_{I,a}) and
/// \f$ \partial_a N_I = S'(x_a - x_{I,a}) \prod_{b \ne a} S(x_b - x_{I,b}) \f$.
/// Shared by the linear (Q4) and uGIMP shape functions, which differ only in their 1D factor S.
#pragma once
#include <array>

#include "mpm/grid/grid.hpp"

namespace mpm {

/// The 1D factors of one axis: S and dS/dx of `count` consecutive nodes, the first at lattice index `first`
/// (every tensor-product shape's support on an axis is an interval of nodes); only the first `count` are set.
template <int MaxPerAxis>
struct AxisFactors {
  int first = 0, count = 0;
  std::array<double, MaxPerAxis> value;
  std::array<double, MaxPerAxis> derivative;
  /// Appends node `first + count`.
  void add(double s, double ds) {
    value[count] = s;
    derivative[count] = ds;
    ++count;
  }
};

/// Combines per-axis factors into the stencil of a point; returns the number of nodes written.
/// Nodes in the grid's order, x fastest: \f$ N_{ij} = S^x_i S^y_j \f$,
/// \f$ \nabla N_{ij} = (S'^x_i S^y_j,\ S^x_i S'^y_j) \f$ (in 1D \f$ N_i = S_i \f$, \f$ \nabla N_i = S'_i \f$).
template <int Dim, int MaxPerAxis, std::size_t Axes>
int tensor_product_stencil(const Grid<Dim>& grid, const std::array<AxisFactors<MaxPerAxis>, Axes>& axes, int* __restrict nodes,
                           double* __restrict values, Vector<Dim>* __restrict gradients) {
  static_assert(Axes == Dim && (Dim == 1 || Dim == 2), "one factor per axis, in 1D or 2D");
  const AxisFactors<MaxPerAxis>& x = axes[0];
  if constexpr (Dim == 1) {
    for (int i = 0; i < x.count; ++i) {
      nodes[i] = x.first + i;  // grid.node_index() in 1D
      values[i] = x.value[i];
      gradients[i][0] = x.derivative[i];
    }
    return x.count;
  } else {
    const AxisFactors<MaxPerAxis>& y = axes[1];
    // The counts and the row's factors in locals: the stores below may alias any memory (Eigen's vector
    // stores), and the compiler would reload what it reached through the references after each of them.
    const int x_count = x.count, y_count = y.count, row_length = grid.nodes_along(0);
    int written = 0;
    for (int j = 0; j < y_count; ++j) {
      const int row = (y.first + j) * row_length + x.first;  // grid.node_index({x.first + i, y.first + j}) - i
      const double value_y = y.value[j], derivative_y = y.derivative[j];
      for (int i = 0; i < x_count; ++i, ++written) {
        nodes[written] = row + i;
        values[written] = x.value[i] * value_y;
        gradients[written] = Vector<2>(x.derivative[i] * value_y, x.value[i] * derivative_y);
      }
    }
    return written;
  }
}

}  // namespace mpm
