/// \file
/// What `mpm shape` computes (evaluate_request, declared in mpm/cli/shape_request.hpp and compiled once by the library:
/// mpm/run_1d.cpp, mpm/run_2d.cpp), without its options (mpm/cli/shape_command.hpp parses them): a shape function on an
/// unbounded uniform grid, made large enough around the points that no stencil meets its edge; CSV, one row per node
/// of each point's stencil. verification/shape_tables.cpp writes Fig. 4's tables with it.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/shape_request.hpp"
#include "mpm/fast/lme_fast.hpp"
#include "mpm/shape/bspline.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/ugimp.hpp"

namespace mpm::cli {

/// Prints `point,node_x[,node_y],N,dN_dx[,dN_dy]`, one row per node of each particle's stencil.
template <int Dim, class Shape>
void print_stencils(Shape& shape, const Grid<Dim>& grid, const Particles<Dim>& particles, std::ostream& out) {
  shape.initialise(particles);
  std::vector<int> nodes(shape.capacity());
  std::vector<double> values(shape.capacity());
  std::vector<Vector<Dim>> gradients(shape.capacity());
  out << "point";
  for (int axis = 0; axis < Dim; ++axis) out << ",node_" << axis_name(axis);
  out << ",N";
  for (int axis = 0; axis < Dim; ++axis) out << ",dN_d" << axis_name(axis);
  out << "\n" << std::setprecision(15);
  for (int p = 0; p < particles.size(); ++p) {
    const int count = shape.evaluate(p, particles.position[p], nodes.data(), values.data(), gradients.data());
    for (int k = 0; k < count; ++k) {
      const Vector<Dim> node = grid.node_position(nodes[k]);
      out << p;
      for (int axis = 0; axis < Dim; ++axis) out << "," << std::round(node[axis] / grid.spacing()) * grid.spacing();
      out << "," << values[k];
      for (int axis = 0; axis < Dim; ++axis) out << "," << gradients[k][axis];
      out << "\n";
    }
  }
}

/// Prints the stencils of the request's points on a grid of its cell size reaching beyond any support around them.
template <int Dim>
void evaluate_request(const ShapeRequest& request, std::ostream& out) {
  const double h = request.cell_size;
  const double reach = h * (std::sqrt(-std::log(request.tolerance) / request.gamma) + 3.0);  // beyond any support
  Vector<Dim> lower = Vector<Dim>::Constant(1e300), upper = Vector<Dim>::Constant(-1e300);
  Particles<Dim> particles;
  const double particle_size = request.particle_size > 0.0 ? request.particle_size : 0.5 * h;
  for (const auto& point : request.points) {
    const Vector<Dim> x = Eigen::Map<const Vector<Dim>>(point.data());
    lower = lower.cwiseMin(x);
    upper = upper.cwiseMax(x);
    particles.add(x, 1.0, 1.0, Vector<Dim>::Zero(), Vector<Dim>::Constant(0.5 * particle_size));
  }
  Vector<Dim> origin;
  std::array<int, Dim> cells{};
  for (int axis = 0; axis < Dim; ++axis) {
    const int first = static_cast<int>(std::floor((lower[axis] - reach) / h));
    origin[axis] = first * h;
    cells[axis] = static_cast<int>(std::ceil((upper[axis] + reach) / h)) - first;
  }
  const Grid<Dim> grid(origin, h, cells);
  LmeOptions lme;
  lme.gamma = request.gamma;
  lme.support_tolerance = request.tolerance;
  auto print = [&](auto shape) { print_stencils(shape, grid, particles, out); };
  if (request.kind == "linear") return print(LinearShape<Dim>(grid));
  if (request.kind == "ugimp") return print(UgimpShape<Dim>(grid));
  if (request.kind == "bspline2") return print(BsplineShape<Dim, 2>(grid));
  if (request.kind == "bspline3") return print(BsplineShape<Dim, 3>(grid));
  print(LmeShape<Dim>(grid, lme));
}

}  // namespace mpm::cli
