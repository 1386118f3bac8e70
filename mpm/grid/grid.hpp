/// \file
/// The background grid: a uniform Cartesian lattice of square (1D: equal) cells of size h.
///
/// Nodes are numbered with x running fastest. The grid knows geometry only; the nodal fields
/// live in GridFields and the boundary conditions in boundary.hpp.
#pragma once
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

template <int Dim>
class Grid {
 public:
  using MultiIndex = std::array<int, Dim>;

  Grid() = default;
  /// \param origin lower corner; \param spacing cell size h; \param cells cells per axis
  Grid(const Vector<Dim>& origin, double spacing, const MultiIndex& cells)
      : origin_(origin), spacing_(spacing), cells_(cells) {}

  double spacing() const { return spacing_; }
  const Vector<Dim>& origin() const { return origin_; }
  int cells(int axis) const { return cells_[axis]; }
  int nodes_along(int axis) const { return cells_[axis] + 1; }
  Vector<Dim> upper_corner() const {
    Vector<Dim> upper = origin_;
    for (int axis = 0; axis < Dim; ++axis) upper[axis] += spacing_ * cells_[axis];
    return upper;
  }

  int node_count() const {
    int count = 1;
    for (int axis = 0; axis < Dim; ++axis) count *= nodes_along(axis);
    return count;
  }

  /// Flat node number of the node with lattice coordinates (i, j); x runs fastest.
  int node_index(const MultiIndex& lattice) const {
    int index = 0;
    for (int axis = Dim - 1; axis >= 0; --axis) index = index * nodes_along(axis) + lattice[axis];
    return index;
  }

  MultiIndex lattice_of(int node) const {
    MultiIndex lattice{};
    for (int axis = 0; axis < Dim; ++axis) {
      lattice[axis] = node % nodes_along(axis);
      node /= nodes_along(axis);
    }
    return lattice;
  }

  Vector<Dim> node_position(const MultiIndex& lattice) const {
    Vector<Dim> position;
    for (int axis = 0; axis < Dim; ++axis) position[axis] = origin_[axis] + spacing_ * lattice[axis];
    return position;
  }
  Vector<Dim> node_position(int node) const { return node_position(lattice_of(node)); }

  /// True if x lies in the closed box of the grid.
  bool contains(const Vector<Dim>& x) const {
    for (int axis = 0; axis < Dim; ++axis) {
      const double local = (x[axis] - origin_[axis]) / spacing_;
      if (!(local >= 0.0 && local <= cells_[axis])) return false;  // also false for NaN
    }
    return true;
  }

  /// Lattice coordinates of the cell that contains x (x must be inside the grid). A point on an
  /// interior face belongs to the cell above it; a point on the upper face to the last cell.
  MultiIndex cell_of(const Vector<Dim>& x) const {
    MultiIndex cell{};
    for (int axis = 0; axis < Dim; ++axis) {
      const int index = static_cast<int>(std::floor((x[axis] - origin_[axis]) / spacing_));
      cell[axis] = index < 0 ? 0 : (index >= cells_[axis] ? cells_[axis] - 1 : index);
    }
    return cell;
  }

 private:
  Vector<Dim> origin_ = Vector<Dim>::Zero();
  double spacing_ = 1.0;
  MultiIndex cells_{};
};

TEST_CASE("Grid: node numbering round-trips and cells are found at faces") {
  const Grid<2> grid(Vector<2>(-1.0, 2.0), 0.5, {4, 3});
  CHECK(grid.node_count() == 5 * 4);
  for (int node = 0; node < grid.node_count(); ++node) CHECK(grid.node_index(grid.lattice_of(node)) == node);
  CHECK(grid.node_index({1, 2}) == 1 + 2 * 5);
  CHECK(grid.node_position(grid.node_index({4, 3})).isApprox(Vector<2>(1.0, 3.5)));
  CHECK(grid.cell_of(Vector<2>(-1.0, 2.0)) == Grid<2>::MultiIndex{0, 0});
  CHECK(grid.cell_of(Vector<2>(-0.5, 2.49)) == Grid<2>::MultiIndex{1, 0});  // interior face: upper cell
  CHECK(grid.cell_of(Vector<2>(1.0, 3.5)) == Grid<2>::MultiIndex{3, 2});    // upper corner: last cell
  CHECK(grid.contains(Vector<2>(1.0, 3.5)));
  CHECK_FALSE(grid.contains(Vector<2>(1.0 + 1e-12, 3.0)));
  CHECK_FALSE(grid.contains(Vector<2>(std::nan(""), 3.0)));
}

}  // namespace mpm
