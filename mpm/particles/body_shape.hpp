/// \file
/// The shape of a body: which of the particles seeded in its box of whole cells it keeps.
///
/// A body is seeded as a box of whole cells (mpm/particles/seeding.hpp) and cut by its shape: a particle
/// is kept when its position lies in the shape, and keeps the mass of its share of the cell, so a curved
/// boundary is resolved to the particle spacing, as in Sulsky, Chen and Schreyer (1994).
///   box      the whole box [min, max]
///   ellipse  the ellipse inscribed in the box: centre (min + max)/2, semi-axes (max - min)/2 (a disk in a square box)
///   polygon  a simple polygon given by its vertices (even-odd rule: a point is inside when a ray from it
///            crosses the boundary an odd number of times)
#pragma once
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <vector>

namespace mpm {

struct BodyShape {
  enum class Kind { box, ellipse, polygon, file };  ///< file: a body's particles read from a file, all kept
  Kind kind = Kind::box;
  std::array<double, 2> min{}, max{};                  ///< the box; its second entries unused in 1D
  std::vector<std::array<double, 2>> vertices;         ///< polygon only, in order around it

  /// True if the point (x, y) lies in the shape (y ignored in 1D, where every shape is the box).
  bool holds(double x, double y) const {
    switch (kind) {
      case Kind::box:
      case Kind::file:
        return true;  // the seeds lie in the box by construction
      case Kind::ellipse: {
        const double u = (2.0 * x - min[0] - max[0]) / (max[0] - min[0]), w = (2.0 * y - min[1] - max[1]) / (max[1] - min[1]);
        return u * u + w * w <= 1.0;
      }
      case Kind::polygon: {
        bool inside = false;
        for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
          const auto& a = vertices[i];
          const auto& b = vertices[j];
          if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) inside = !inside;
        }
        return inside;
      }
    }
    return false;
  }
};

TEST_CASE("BodyShape: the ellipse inscribed in its box and a polygon, by hand") {
  BodyShape disk{BodyShape::Kind::ellipse, {0.05, 0.05}, {0.45, 0.45}, {}};  // radius 0.2 about (0.25, 0.25)
  CHECK(disk.holds(0.25, 0.25));
  CHECK(disk.holds(0.25 + 0.199, 0.25));
  CHECK(!disk.holds(0.25 + 0.201, 0.25));
  CHECK(disk.holds(0.25 + 0.14, 0.25 + 0.14));   // 0.14 sqrt 2 = 0.198 < 0.2
  CHECK(!disk.holds(0.25 + 0.145, 0.25 + 0.145));  // 0.205 > 0.2: inside the box, outside the disk
  BodyShape ellipse{BodyShape::Kind::ellipse, {0.0, 0.0}, {4.0, 2.0}, {}};  // semi-axes 2 and 1 about (2, 1)
  CHECK(ellipse.holds(3.9, 1.0));
  CHECK(!ellipse.holds(2.0 + 1.5, 1.0 + 0.7));  // (1.5/2)^2 + 0.7^2 = 1.0525
  CHECK(ellipse.holds(2.0 + 1.5, 1.0 + 0.6));   // 0.5625 + 0.36 = 0.9225
  // An L-shaped polygon: the unit square without its upper-right quarter.
  BodyShape l_shape{BodyShape::Kind::polygon, {0.0, 0.0}, {1.0, 1.0}, {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.5}, {0.5, 0.5}, {0.5, 1.0}, {0.0, 1.0}}};
  CHECK(l_shape.holds(0.25, 0.75));
  CHECK(l_shape.holds(0.75, 0.25));
  CHECK(!l_shape.holds(0.75, 0.75));
  CHECK(!l_shape.holds(1.25, 0.25));
  BodyShape box{BodyShape::Kind::box, {0.0, 0.0}, {1.0, 1.0}, {}};
  CHECK(box.holds(0.99, 0.01));
}

}  // namespace mpm
