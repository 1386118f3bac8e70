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
#include "mpm/particles/particles.hpp"

namespace mpm {

/// Where particles sit inside a cell.
enum class Placement {
  uniform,  ///< centres of the ppc^Dim sub-cells, at (j + 1/2) h / ppc (default)
  gauss     ///< Gauss points of the cell (2 per axis: h/2 (1 -+ 1/sqrt 3)), as in the authors' LME/Q4 block
};

/// Adds the particles of the box [box_min, box_max] (on grid lines) to `particles`.
template <int Dim>
void fill_box(const Grid<Dim>& grid, const Vector<Dim>& box_min, const Vector<Dim>& box_max,
              const typename Grid<Dim>::MultiIndex& particles_per_cell, double density, const Vector<Dim>& velocity,
              Placement placement, Particles<Dim>& particles) {
  const double h = grid.spacing();
  std::array<int, Dim> first{}, count{};
  int per_cell = 1;
  for (int axis = 0; axis < Dim; ++axis) {
    first[axis] = static_cast<int>(std::lround((box_min[axis] - grid.origin()[axis]) / h));
    count[axis] = static_cast<int>(std::lround((box_max[axis] - box_min[axis]) / h)) * particles_per_cell[axis];
    per_cell *= particles_per_cell[axis];
  }
  const double particle_mass = density * std::pow(h, Dim) / per_cell;
  Vector<Dim> half_length;
  for (int axis = 0; axis < Dim; ++axis) half_length[axis] = 0.5 * h / particles_per_cell[axis];

  std::array<int, Dim> index{};  // odometer over particle rows, x fastest
  while (true) {
    Vector<Dim> x;
    for (int axis = 0; axis < Dim; ++axis) {
      const int ppc = particles_per_cell[axis];
      const int cell = first[axis] + index[axis] / ppc, slot = index[axis] % ppc;
      double offset = (slot + 0.5) / ppc;  // fraction of the cell
      if (placement == Placement::gauss && ppc == 2) offset = 0.5 + (slot == 0 ? -0.5 : 0.5) / std::sqrt(3.0);
      x[axis] = grid.origin()[axis] + (cell + offset) * h;
    }
    particles.add(x, particle_mass, density, velocity, half_length);
    int axis = 0;
    while (axis < Dim && ++index[axis] == count[axis]) index[axis++] = 0;
    if (axis == Dim) return;
  }
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
}

}  // namespace mpm
