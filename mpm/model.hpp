/// \file
/// The problem being solved, apart from the particles: background grid, materials, essential
/// boundary conditions and body force. Built once per run from a scene (io/scene_builder.hpp).
#pragma once
#include <vector>

#include "mpm/grid/boundary.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/material/linear_elastic.hpp"

namespace mpm {

template <int Dim>
struct Model {
  Grid<Dim> grid;
  /// The materials of the bodies, Eq. (3): particle p is of materials[particles.material[p]]. The scene's
  /// [material] is materials[0]; each body with a material of its own adds one (io/scene_builder.hpp).
  std::vector<LinearElastic> materials;
  std::vector<FixedDof> fixed;  ///< velocity components held at zero
  BodyForce<Dim> body_force;  ///< b of Eq. (15): gravity ramped by Eq. (44), plus an optional field b(x, X, t)
};

}  // namespace mpm
