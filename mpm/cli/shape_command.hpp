/// \file
/// `mpm shape`: a shape function evaluated on an unbounded uniform grid, for teaching and Fig. 4.
///
///   mpm shape --dim 2 --kind lme --gamma 3 [--cell-size 1] [--particle-size 0.5] --at 0.3,0.7 [--at ...]
///
/// prints `point,node_x,N,dN_dx` (1D) or `point,node_x,node_y,N,dN_dx,dN_dy` (2D), one row per node
/// of each point's stencil; `point` counts the --at arguments from 0. The grid is made large enough
/// around the points that no stencil meets its edge, which is what "unbounded" means here.
/// `--particle-size` is the uGIMP particle length 2 l_p (default half the cell size).
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"

#include "mpm/shape/bspline.hpp"
#include "mpm/shape/lme.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/ugimp.hpp"

namespace mpm::cli {

struct ShapeRequest {
  int dimension = 1;
  std::string kind;
  double gamma = 3.0, cell_size = 1.0, particle_size = -1.0, tolerance = 1e-6;
  std::vector<std::vector<double>> points;
};

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

template <int Dim>
void evaluate_request(const ShapeRequest& request, std::ostream& out) {
  const double h = request.cell_size;
  const double reach = h * (std::sqrt(-std::log(request.tolerance) / request.gamma) + 3.0);  // beyond any support
  Vector<Dim> lower, upper;
  lower.setConstant(1e300);
  upper.setConstant(-1e300);
  Particles<Dim> particles;
  const double particle_size = request.particle_size > 0.0 ? request.particle_size : 0.5 * h;
  for (const auto& point : request.points) {
    Vector<Dim> x;
    for (int axis = 0; axis < Dim; ++axis) x[axis] = point[axis];
    lower = lower.cwiseMin(x);
    upper = upper.cwiseMax(x);
    particles.add(x, 1.0, 1.0, Vector<Dim>::Zero(), Vector<Dim>::Constant(0.5 * particle_size));
  }
  Vector<Dim> origin;
  std::array<int, Dim> cells{};
  for (int axis = 0; axis < Dim; ++axis) {
    const int first = static_cast<int>(std::floor((lower[axis] - reach) / h));
    const int last = static_cast<int>(std::ceil((upper[axis] + reach) / h));
    origin[axis] = first * h;
    cells[axis] = last - first;
  }
  const Grid<Dim> grid(origin, h, cells);
  if (request.kind == "linear") {
    LinearShape<Dim> shape(grid);
    print_stencils(shape, grid, particles, out);
  } else if (request.kind == "ugimp") {
    UgimpShape<Dim> shape(grid);
    print_stencils(shape, grid, particles, out);
  } else if (request.kind == "bspline2") {
    BsplineShape<Dim, 2> shape(grid);
    print_stencils(shape, grid, particles, out);
  } else if (request.kind == "bspline3") {
    BsplineShape<Dim, 3> shape(grid);
    print_stencils(shape, grid, particles, out);
  } else {
    LmeOptions options;
    options.gamma = request.gamma;
    options.support_tolerance = request.tolerance;
    LmeShape<Dim> shape(grid, options);
    print_stencils(shape, grid, particles, out);
  }
}

/// `mpm shape`'s parser, its options bound to `request` and to `points` (each --at as written).
inline std::unique_ptr<CommandParser> shape_parser(ShapeRequest& request, std::vector<std::string>& points) {
  auto app = std::make_unique<CommandParser>(
      "shape",
      "Evaluates a shape function on an unbounded uniform grid (nodes at integer multiples of the cell size) and prints\n"
      "CSV, one row per node of each point's stencil: point,node_x[,node_y],N,dN_dx[,dN_dy]; point counts the --at from 0.");
  app->add_option("--dim", request.dimension, "dimension")->check(whole_in(1, 2));
  app->add_option("--kind", request.kind, "shape function")->required()->check(one_of({"linear", "ugimp", "lme", "bspline2", "bspline3"}));
  app->add_option("--at", points, "a point X (1D) or X,Y (2D); repeat for more")->type_name("X[,Y]")->required()->allow_extra_args(false);
  app->add_option("--gamma", request.gamma, "LME locality gamma, <= -ln(tol)/dim")->check(positive());
  app->add_option("--cell-size", request.cell_size, "cell size h")->check(positive());
  app->add_option("--particle-size", request.particle_size, "uGIMP particle length 2 l_p, <= h (-1: h/2)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            const auto number = parse_number(text);
            return number && (*number > 0.0 || *number == -1.0) ? "" : "must be a number > 0, got '" + text + "'";
          },
          "NUMBER > 0"));
  app->add_option("--tol", request.tolerance, "LME support tolerance")->check(number_in(0.0, 1.0, true));
  return app;
}

/// `mpm shape --help`: the parser's own help.
inline std::string shape_usage() {
  ShapeRequest request;
  std::vector<std::string> points;
  return shape_parser(request, points)->help();
}

/// "X" or "X,Y" as numbers; false if a part is not a finite number ("0.5," is refused: every comma separates two).
inline bool read_point(const std::string& text, std::vector<double>& point) {
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    const auto coordinate = parse_number(text.substr(start, comma - start));
    if (!coordinate) return false;
    point.push_back(*coordinate);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

/// Parses the options and prints the CSV; returns the exit code (2 with a message on bad input).
inline int shape_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  ShapeRequest request;
  std::vector<std::string> points;
  if (const auto code = parse_arguments(*shape_parser(request, points), arguments, "shape", out, err)) return *code;
  auto fail = [&](const std::string& option, const std::string& what) {
    err << "error: " << option << ": " << what << "\n";
    return 2;
  };
  for (const std::string& text : points) {
    request.points.emplace_back();
    if (!read_point(text, request.points.back())) return fail("--at", "'" + text + "' is not X or X,Y of finite numbers");
  }
  if (request.dimension != 1 && request.dimension != 2) return fail("--dim", "must be 1 or 2");
  if (request.kind != "linear" && request.kind != "ugimp" && request.kind != "lme" && request.kind != "bspline2" && request.kind != "bspline3")
    return fail("--kind", "must be linear, ugimp, lme, bspline2 or bspline3");
  if (!(request.tolerance > 0.0)) return fail("--tol", "must be in (0, 1)");
  if (request.kind == "lme" && request.gamma > -std::log(request.tolerance) / request.dimension)
    return fail("--gamma", "too large for --tol: the support must reach the corners of a cell, gamma <= -ln(tol)/dim");
  if (request.kind == "ugimp" && request.particle_size > request.cell_size)
    return fail("--particle-size", "must not exceed the cell size");
  if (request.points.empty()) return fail("--at", "give at least one point");
  for (const auto& point : request.points)
    if (static_cast<int>(point.size()) != request.dimension) return fail("--at", "each point needs --dim coordinates, comma-separated");
  // The grid around the points must be indexable: coordinates within 10^6 cells of 0, supports
  // within 100 cells, and at most 10^8 nodes in all.
  const double reach = std::sqrt(-std::log(request.tolerance) / request.gamma) + 3.0;  // cells, as evaluate_request
  if (request.kind == "lme" && reach > 103.0) return fail("--gamma", "too small for --tol: the support would reach beyond 100 cells");
  double nodes = 1.0;
  for (int axis = 0; axis < request.dimension; ++axis) {
    double lower = 0.0, upper = 0.0;
    for (const auto& point : request.points) {
      if (std::abs(point[axis]) > 1e6 * request.cell_size) return fail("--at", "coordinates must lie within 10^6 cell sizes of 0");
      lower = std::min(lower, point[axis]), upper = std::max(upper, point[axis]);
    }
    nodes *= (upper - lower) / request.cell_size + 2.0 * reach + 3.0;
  }
  if (nodes > 1e8) return fail("--at", "the points lie too far apart for one grid of at most 10^8 nodes");
  try {
    request.dimension == 1 ? evaluate_request<1>(request, out) : evaluate_request<2>(request, out);
  } catch (const ShapeFailure& failure) {
    err << "failure: point " << failure.particle << ": " << failure.what() << "\n";
    return 3;
  }
  return 0;
}

TEST_CASE("mpm shape: the linear hat in 1D and Q4 in 2D by hand, and bad options") {
  std::ostringstream out, err;
  REQUIRE(shape_command({"--dim", "1", "--kind", "linear", "--at", "0.25", "--cell-size", "0.5"}, out, err) == 0);
  CHECK(out.str() == "point,node_x,N,dN_dx\n0,0,0.5,-2\n0,0.5,0.5,2\n");
  std::ostringstream out2;
  REQUIRE(shape_command({"--dim", "2", "--kind", "linear", "--at", "0.25,0.5"}, out2, err) == 0);
  CHECK(out2.str().rfind("point,node_x,node_y,N,dN_dx,dN_dy\n0,0,0,0.375,-0.5,-0.75\n", 0) == 0);
  CHECK(shape_command({"--dim", "3", "--kind", "linear", "--at", "0"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "lme", "--gamma", "20", "--at", "0"}, out, err) == 2);
  CHECK(shape_command({"--dim", "2", "--kind", "linear", "--at", "0.1"}, out, err) == 2);
  // not numbers, or not finite, or out of reach: refused with exit 2 (issue 11)
  CHECK(shape_command({"--dim", "2x", "--kind", "linear", "--at", "0.1,0.2"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "0.5,"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "nan"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "1e300"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "lme", "--gamma", "1e-9", "--at", "0"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--cell-size", "inf", "--at", "0"}, out, err) == 2);
}

}  // namespace mpm::cli
