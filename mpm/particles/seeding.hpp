/// \file
/// Filling a body with particles: an axis-aligned box of whole grid cells, each cell holding
/// ppc_x (x ppc_y) particles at the centres of a uniform subdivision (paper/09_choices.md, 'Particle placement and point A').
///
/// Each particle gets the mass of its share of the cell, m_p = rho_0 h^Dim / (ppc_x ppc_y) (per
/// unit area in 1D, per unit thickness in 2D), and the half-length l_p = h / (2 ppc) per axis.
#pragma once
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/body_shape.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm {

/// Where particles sit inside a cell.
enum class Placement {
  uniform,  ///< centres of the ppc^Dim sub-cells, at (j + 1/2) h / ppc (default)
  gauss     ///< Gauss points of the cell (2 per axis: h/2 (1 -+ 1/sqrt 3)), as in the authors' LME/Q4 block
};

/// Calls `visit(x)` for the position x of every particle seeded in the box [box_min, box_max] of whole cells
/// of the grid whose lines lie at grid_origin + k h, x fastest; stops early when `visit` returns false.
/// Returns false if it was stopped.
template <int Dim, class Visit>
bool for_each_seed(const Vector<Dim>& grid_origin, double h, const Vector<Dim>& box_min, const Vector<Dim>& box_max,
                   const std::array<int, Dim>& particles_per_cell, Placement placement, Visit visit) {
  std::array<long, Dim> first{}, count{};
  for (int axis = 0; axis < Dim; ++axis) {
    first[axis] = std::lround((box_min[axis] - grid_origin[axis]) / h);
    count[axis] = std::lround((box_max[axis] - box_min[axis]) / h) * particles_per_cell[axis];
  }
  std::array<long, Dim> index{};  // odometer over particle rows, x fastest
  while (true) {
    Vector<Dim> x;
    for (int axis = 0; axis < Dim; ++axis) {
      const int ppc = particles_per_cell[axis];
      const long cell = first[axis] + index[axis] / ppc, slot = index[axis] % ppc;
      double offset = (slot + 0.5) / ppc;  // fraction of the cell
      if (placement == Placement::gauss && ppc == 2) offset = 0.5 + (slot == 0 ? -0.5 : 0.5) / std::sqrt(3.0);
      x[axis] = grid_origin[axis] + (cell + offset) * h;
    }
    if (!visit(x)) return false;
    int axis = 0;
    while (axis < Dim && ++index[axis] == count[axis]) index[axis++] = 0;
    if (axis == Dim) return true;
  }
}

/// Adds the particles of the box [box_min, box_max] (on grid lines) that lie in `shape` (by default the
/// whole box, mpm/particles/body_shape.hpp) to `particles`; returns how many.
template <int Dim>
int fill_box(const Grid<Dim>& grid, const Vector<Dim>& box_min, const Vector<Dim>& box_max,
             const typename Grid<Dim>::MultiIndex& particles_per_cell, double density, const Vector<Dim>& velocity,
             Placement placement, Particles<Dim>& particles, const BodyShape& shape = BodyShape{}) {
  const double h = grid.spacing();
  int per_cell = 1;
  for (int axis = 0; axis < Dim; ++axis) per_cell *= particles_per_cell[axis];
  const double particle_mass = density * std::pow(h, Dim) / per_cell;
  Vector<Dim> half_length;
  for (int axis = 0; axis < Dim; ++axis) half_length[axis] = 0.5 * h / particles_per_cell[axis];
  std::array<int, Dim> per_axis{};
  for (int axis = 0; axis < Dim; ++axis) per_axis[axis] = particles_per_cell[axis];
  int added = 0;
  for_each_seed<Dim>(grid.origin(), h, box_min, box_max, per_axis, placement, [&](const Vector<Dim>& x) {
    if (shape.holds(x[0], x[Dim - 1])) particles.add(x, particle_mass, density, velocity, half_length), ++added;
    return true;
  });
  return added;
}

TEST_CASE("Seeding: positions, masses and half-lengths of a 2x2-per-cell block and a 1D bar") {
  const Grid<2> grid(Vector<2>(0.0, 0.0), 2.0, {5, 5});
  Particles<2> block;
  fill_box(grid, Vector<2>(0.0, 0.0), Vector<2>(10.0, 10.0), {2, 2}, 6000.0, Vector<2>(0.0, 0.0), Placement::uniform, block);
  REQUIRE(block.size() == 100);
  CHECK(block.position[0].isApprox(Vector<2>(0.5, 0.5)));
  CHECK(block.position[99].isApprox(Vector<2>(9.5, 9.5)));
  double mass = 0.0;
  for (double m : block.mass) mass += m;
  CHECK(mass == doctest::Approx(6000.0 * 100.0));  // rho W H, per unit thickness
  CHECK(block.half_length[0].isApprox(Vector<2>(0.5, 0.5)));

  Particles<2> gauss;
  fill_box(grid, Vector<2>(0.0, 8.0), Vector<2>(2.0, 10.0), {2, 2}, 6000.0, Vector<2>(0.0, 0.0), Placement::gauss, gauss);
  CHECK(gauss.position[3][1] == doctest::Approx(9.57735).epsilon(1e-6));  // 9 + 1/sqrt(3), paper/09_choices.md

  const Grid<1> line(Vector<1>(-0.1), 0.1, {5});
  Particles<1> bar;
  fill_box(line, Vector<1>(0.0), Vector<1>(0.4), {2}, 10.0, Vector<1>(1.0), Placement::uniform, bar);
  REQUIRE(bar.size() == 8);
  CHECK(bar.position[0][0] == doctest::Approx(0.025));
  CHECK(bar.position[7][0] == doctest::Approx(0.375));
  CHECK(bar.mass[0] == doctest::Approx(0.5));
  CHECK(bar.half_length[0][0] == doctest::Approx(0.025));

  // A disk of radius 0.2 about (0.25, 0.25) in its box of 8 x 8 cells of 0.05 m, 2 x 2 particles per cell:
  // the seeds are 0.0625 + 0.025 k; counted by hand (a Python loop over the 16 x 16 seeds): 208 lie in the disk.
  const Grid<2> square(Vector<2>(0.0, 0.0), 0.05, {20, 20});
  Particles<2> disk;
  const BodyShape circle{BodyShape::Kind::ellipse, {0.05, 0.05}, {0.45, 0.45}, {}};
  CHECK(fill_box(square, Vector<2>(0.05, 0.05), Vector<2>(0.45, 0.45), {2, 2}, 1000.0, Vector<2>(0.1, 0.1), Placement::uniform, disk, circle) == 208);
  REQUIRE(disk.size() == 208);
  CHECK(disk.mass[0] == doctest::Approx(1000.0 * 0.05 * 0.05 / 4.0));  // its share of the cell, as in a box
  for (int p = 0; p < disk.size(); ++p) CHECK((disk.position[p] - Vector<2>(0.25, 0.25)).norm() <= 0.2);
}

}  // namespace mpm
