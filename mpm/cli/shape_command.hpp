/// \file
/// `mpm shape --dim 2 --kind lme --gamma 3 --at 0.3,0.7 [--at ...]`: a shape function on an unbounded uniform grid
/// (made large enough around the points that no stencil meets its edge), for teaching and Fig. 4: CSV, one row
/// per node of each point's stencil.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/cli/shape_request.hpp"

namespace mpm::cli {

/// Reads each --at ("X" or "X,Y": every comma separates two numbers) into the request's points and checks what
/// the options cannot check alone: the LME support, uGIMP's particle size, a grid of at most 10^8 nodes whose
/// coordinates lie within 10^6 cells of 0. \throws Refused naming the option.
inline void check_shape_request(ShapeRequest& request) {
  for (const std::string& text : request.at) {
    request.points.emplace_back();
    for (std::size_t start = 0, comma = 0; comma != std::string::npos; start = comma + 1) {
      comma = text.find(',', start);
      std::string out_of_range;
      const auto coordinate = parse_number(text.substr(start, comma - start), &out_of_range);
      if (!coordinate)
        throw Refused("--at: " +
                      (out_of_range.empty() ? "'" + text + "' is not X or X,Y of finite numbers" : out_of_range));
      request.points.back().push_back(*coordinate);
    }
  }
  if (request.kind == "lme" && request.gamma > -std::log(request.tolerance) / request.dimension)
    throw Refused("--gamma: too large for --tol: the support must reach the corners of a cell, gamma <= -ln(tol)/dim");
  if (request.kind == "ugimp" && request.particle_size > request.cell_size)
    throw Refused("--particle-size: must not exceed the cell size");
  for (const auto& point : request.points)
    if (static_cast<int>(point.size()) != request.dimension)
      throw Refused("--at: each point needs --dim coordinates, comma-separated");
  if (request.kind == "lme" && !lme_support_too_wide(request.gamma, request.tolerance).empty())
    throw Refused("--gamma: " + lme_support_too_wide(request.gamma, request.tolerance));
  const double reach = std::sqrt(-std::log(request.tolerance) / request.gamma) + 3.0;  // cells, as evaluate_request
  double nodes = 1.0;
  for (int axis = 0; axis < request.dimension; ++axis) {
    double lower = 0.0, upper = 0.0;
    for (const auto& point : request.points) {
      if (std::abs(point[axis]) > 1e6 * request.cell_size)
        throw Refused("--at: coordinates must lie within 10^6 cell sizes of 0");
      lower = std::min(lower, point[axis]);
      upper = std::max(upper, point[axis]);
    }
    nodes *= (upper - lower) / request.cell_size + 2.0 * reach + 3.0;
  }
  if (nodes > 1e8) throw Refused("--at: the points lie too far apart for one grid of at most 10^8 nodes");
}

/// `mpm shape`; returns the exit code (3 when the shape function fails at a point).
inline int shape_command(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  ShapeRequest request;
  CommandParser app(
      "shape",
      "Evaluates a shape function on an unbounded uniform grid (nodes at integer multiples of the cell size) "
      "and prints\n"
      "CSV, one row per node of each point's stencil: point,node_x[,node_y],N,dN_dx[,dN_dy]; point counts "
      "the --at from 0.");
  app.add_option("--dim", request.dimension, "dimension")->check(whole_in(1, 2));
  app.add_option("--kind", request.kind, "shape function")
      ->required()
      ->check(one_of({"linear", "ugimp", "lme", "bspline2", "bspline3"}));
  app.add_option("--at", request.at, "a point X (1D) or X,Y (2D); repeat for more")
      ->type_name("X[,Y]")
      ->required()
      ->allow_extra_args(false);
  app.add_option("--gamma", request.gamma, "LME locality gamma, <= -ln(tol)/dim")->check(positive());
  app.add_option("--cell-size", request.cell_size, "cell size h")->check(positive());
  app.add_option("--particle-size", request.particle_size, "uGIMP particle length 2 l_p, <= h (-1: h/2)")
      ->check(number_where("number > 0", [](double x) { return x > 0.0 || x == -1.0; }));
  app.add_option("--tol", request.tolerance, "LME support tolerance")
      ->check(number_where("number in (0, 1)", [](double x) { return x > 0.0 && x < 1.0; }));
  return run_parsed(app, arguments, out, err, [&] {
    check_shape_request(request);
    try {
      request.dimension == 1 ? evaluate_request<1>(request, out) : evaluate_request<2>(request, out);
    } catch (const ShapeFailure& failure) {
      err << "failure: point " << failure.particle << ": " << failure.what() << "\n";
      return 3;
    }
    return 0;
  });
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
  // not numbers, or not finite, or out of reach: refused with exit 2
  CHECK(shape_command({"--dim", "2x", "--kind", "linear", "--at", "0.1,0.2"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "0.5,"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "nan"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "1e300"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--cell-size", "inf", "--at", "0"}, out, err) == 2);
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--tol", "0", "--at", "0"}, out, err) == 2);
  std::ostringstream wide;
  CHECK(shape_command({"--dim", "1", "--kind", "lme", "--gamma", "1e-9", "--at", "0"}, out, wide) == 2);
  CHECK(wide.str() ==
        "error: --gamma: too small for the support tolerance 1e-06: the support would reach beyond 100 cells; "
        "give at least 0.00139\n");
  std::ostringstream tiny;
  CHECK(shape_command({"--dim", "1", "--kind", "linear", "--at", "1e-310"}, out, tiny) == 2);
  CHECK(tiny.str().rfind("error: --at: '1e-310' is too small", 0) == 0);
}

}  // namespace mpm::cli
