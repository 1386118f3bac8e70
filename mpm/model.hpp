/// \file
/// The problem being solved, apart from the particles: background grid, material, essential
/// boundary conditions and body force. Built once per run from a scene (io/scene_builder.hpp).
#pragma once
#include <vector>

#include "mpm/grid/boundary.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/loading/gravity.hpp"
#include "mpm/material/linear_elastic.hpp"

namespace mpm {

template <int Dim>
struct Model {
  Grid<Dim> grid;
  LinearElastic material;
  std::vector<FixedDof> fixed;  ///< velocity components held at zero
  Gravity<Dim> gravity;
};

}  // namespace mpm
