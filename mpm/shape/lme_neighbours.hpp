/// \file
/// The neighbours of a point for the local max-ent shape functions (mpm/shape/lme_reference.hpp): every grid
/// node within the support radius R, and a bound on how many there can be.
///
/// Everything is in cell units: R/h and the offsets (x - x_I)/h.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/shape/lme_options.hpp"

namespace mpm {

/// The most lattice points within `radius` (cell units) of any centre, bounded from above:
/// centres are taken in [0, 1/2]^Dim of a cell (the lattice's mirror symmetries give the rest),
/// covered by 32^Dim small boxes, and a box counts every point within `radius` of some centre in
/// it. The relative slack 1e-12 covers the rounding of the test in lme_neighbours().
template <int Dim>
int lattice_points_in_ball_bound(double radius) {
  const int divisions = 32, reach = static_cast<int>(std::ceil(radius)) + 1;
  const double limit = radius * radius * (1.0 + 1e-12), width = 0.5 / divisions;
  int most = 0;
  std::array<int, Dim> box{};
  while (true) {
    int count = 0;
    std::array<int, Dim> k;
    k.fill(-reach);
    while (true) {
      double distance_squared = 0.0;  // from lattice point k to the box of centres
      for (int axis = 0; axis < Dim; ++axis) {
        const double low = box[axis] * width, high = low + width;
        const double gap = k[axis] < low ? low - k[axis] : (k[axis] > high ? k[axis] - high : 0.0);
        distance_squared += gap * gap;
      }
      if (distance_squared <= limit) ++count;
      int axis = 0;
      while (axis < Dim && ++k[axis] > reach) k[axis] = -reach, ++axis;
      if (axis == Dim) break;
    }
    most = std::max(most, count);
    int axis = 0;
    while (axis < Dim && ++box[axis] == divisions) box[axis] = 0, ++axis;
    if (axis == Dim) return most;
  }
}

/// Every node within R of x: writes its number and its offset (x - x_I)/h, returns how many.
/// Searches only the lattice box [x - R, x + R] clipped to the grid. When R >= h sqrt(Dim) (lme_radius_squared
/// requires it), the corners of the cell that contains x are always among the neighbours, so x is
/// inside their convex hull. \throws ShapeFailure if there are more than `capacity`.
template <int Dim>
inline int lme_neighbours(const Grid<Dim>& grid, double radius_squared, int capacity, int particle, const Vector<Dim>& x,
                   int* nodes, Vector<Dim>* offsets) {
  const double radius = std::sqrt(radius_squared);
  const Vector<Dim> xi = (x - grid.origin()) / grid.spacing();  // x in lattice coordinates
  typename Grid<Dim>::MultiIndex lower{}, upper{}, k{};
  for (int axis = 0; axis < Dim; ++axis) {
    lower[axis] = std::max(0, static_cast<int>(std::ceil(xi[axis] - radius)));
    upper[axis] = std::min(grid.cells(axis), static_cast<int>(std::floor(xi[axis] + radius)));
  }
  k = lower;
  int count = 0;
  while (true) {
    Vector<Dim> offset;
    for (int axis = 0; axis < Dim; ++axis) offset[axis] = xi[axis] - k[axis];
    if (offset.squaredNorm() <= radius_squared) {
      if (count == capacity) throw ShapeFailure(particle, "LME: more neighbours than capacity() (internal error)");
      nodes[count] = grid.node_index(k);
      offsets[count] = offset;
      ++count;
    }
    int axis = 0;  // odometer over the box
    while (axis < Dim && ++k[axis] > upper[axis]) k[axis] = lower[axis], ++axis;
    if (axis == Dim) return count;
  }
}

/// The authors' neighbours (NL-PartSol 1d5da04, src/ShapeFun/LME.c, LME_Tributary_Nodes, line 536): the nodes of the
/// cell that holds x and of every cell that shares a node with it, the \f$ 4^{Dim} \f$ node patch around x's cell
/// (fewer at the grid's edges), whatever R. Their code then drops the nodes beyond
/// \f$ \sqrt{-\ln 10^{-5} / \beta} \f$ of the step before; past the first step that drops none of the patch (2.5-2.9 h
/// on the soil block), which this rule keeps whole. Writes each node's number and offset (x - x_I)/h, returns how many.
/// \throws ShapeFailure if there are more than `capacity` (at least \f$ 4^{Dim} \f$ is needed).
template <int Dim>
inline int lme_patch_neighbours(const Grid<Dim>& grid, int capacity, int particle, const Vector<Dim>& x, int* nodes,
                                Vector<Dim>* offsets) {
  const Vector<Dim> xi = (x - grid.origin()) / grid.spacing();
  const auto cell = grid.cell_of(x);
  typename Grid<Dim>::MultiIndex lower{}, upper{}, k{};
  for (int axis = 0; axis < Dim; ++axis)
    lower[axis] = std::max(0, cell[axis] - 1), upper[axis] = std::min(grid.cells(axis), cell[axis] + 2);
  k = lower;
  int count = 0;
  while (true) {
    if (count == capacity) throw ShapeFailure(particle, "LME: more neighbours than capacity() (internal error)");
    for (int axis = 0; axis < Dim; ++axis) offsets[count][axis] = xi[axis] - k[axis];
    nodes[count++] = grid.node_index(k);
    int axis = 0;
    while (axis < Dim && ++k[axis] > upper[axis]) k[axis] = lower[axis], ++axis;
    if (axis == Dim) return count;
  }
}

/// The neighbours under the options' rule (LmeOptions::neighbours): within R, or the authors' patch.
template <int Dim>
inline int lme_support(const LmeOptions& options, const Grid<Dim>& grid, double radius_squared, int capacity, int particle,
                       const Vector<Dim>& x, int* nodes, Vector<Dim>* offsets) {
  if (options.neighbours == LmeOptions::Neighbours::authors_patch)
    return lme_patch_neighbours(grid, capacity, particle, x, nodes, offsets);
  return lme_neighbours(grid, radius_squared, capacity, particle, x, nodes, offsets);
}
/// An upper bound of the neighbours of any point under the options' rule: the lattice points of a ball of radius R,
/// or the 4^Dim nodes of the authors' patch.
template <int Dim>
inline int lme_support_capacity(const LmeOptions& options, double radius_squared) {
  if (options.neighbours == LmeOptions::Neighbours::authors_patch) return Dim == 1 ? 4 : 16;
  return lattice_points_in_ball_bound<Dim>(std::sqrt(radius_squared));
}

TEST_CASE("LME neighbours, the authors' patch: the 4 x 4 nodes around the cell, 3 x 3 in a corner cell, by hand") {
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {5, 5});
  int nodes[16];
  Vector<2> offsets[16];
  REQUIRE(lme_patch_neighbours(plane, 16, 0, Vector<2>(2.25, 2.75), nodes, offsets) == 16);
  CHECK(offsets[0][0] == 1.25);   // node (1, 1): the first, x - 1
  CHECK(offsets[0][1] == 1.75);
  CHECK(offsets[15][0] == -1.75);  // node (4, 4)
  CHECK(nodes[15] == plane.node_index({4, 4}));
  CHECK(lme_patch_neighbours(plane, 16, 0, Vector<2>(0.5, 0.5), nodes, offsets) == 9);  // nodes 0-2 on each axis
  CHECK(lme_patch_neighbours(plane, 16, 0, Vector<2>(4.5, 2.5), nodes, offsets) == 12);  // 3 x 4 at the side
  CHECK_THROWS_AS(lme_patch_neighbours(plane, 15, 3, Vector<2>(2.5, 2.5), nodes, offsets), ShapeFailure);
  // the options' rule: at a cell centre with gamma 3 and tol 1e-5, R = 1.96 h holds 12 nodes (not the patch's corners
  // at 2.12 h), the authors' patch all 16
  LmeOptions options;
  options.support_tolerance = 1e-5;
  const double radius_squared = lme_radius_squared<2>(options);
  CHECK(lme_support(options, plane, radius_squared, 16, 0, Vector<2>(2.5, 2.5), nodes, offsets) == 12);
  options.neighbours = LmeOptions::Neighbours::authors_patch;
  CHECK(lme_support_capacity<2>(options, radius_squared) == 16);
  CHECK(lme_support(options, plane, radius_squared, 16, 0, Vector<2>(2.5, 2.5), nodes, offsets) == 16);
}

TEST_CASE("LME neighbours: every node within R and no other, the lattice bound is reached and never exceeded") {
  // By hand: R = 1.5 h around x = 2.25 h on a line: nodes 1, 2, 3 (offsets 1.25, 0.25, -0.75); node 0
  // (2.25) and node 4 (1.75) are beyond R.
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
  int nodes[8];
  Vector<1> offsets[8];
  REQUIRE(lme_neighbours(line, 2.25, 8, 0, Vector<1>(2.25), nodes, offsets) == 3);
  CHECK(nodes[0] == 1);
  CHECK(nodes[2] == 3);
  CHECK(offsets[0][0] == 1.25);
  CHECK(offsets[2][0] == -0.75);
  CHECK(lattice_points_in_ball_bound<1>(1.5) == 4);  // x halfway between nodes: nodes at 0.5, 0.5, 1.5 and 1.5 h
  // 2D, R = 2.146 (gamma 3, tol 1e-6): at most 16 nodes (a cell centre), never more along a sweep of points.
  const double radius_squared = -std::log(1e-6) / 3.0;
  const int bound = lattice_points_in_ball_bound<2>(std::sqrt(radius_squared));
  CHECK(bound == 16);
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  std::array<int, 32> many;
  std::array<Vector<2>, 32> far;
  int most = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j)
      most = std::max(most, lme_neighbours(plane, radius_squared, 32, 0, Vector<2>(4.0 + i / 40.0, 4.0 + j / 40.0),
                                           many.data(), far.data()));
  CHECK(most == bound);
  CHECK_THROWS_AS(lme_neighbours(plane, radius_squared, 15, 7, Vector<2>(4.5, 4.5), many.data(), far.data()), ShapeFailure);
}

}  // namespace mpm
