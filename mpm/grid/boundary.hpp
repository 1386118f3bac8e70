/// \file
/// Essential boundary conditions: velocity components held at zero on the nodes of a grid face.
///
/// As in the authors' code (paper/02_mpm_forward_euler.md, 'Essential boundary conditions'): the prescribed component is overwritten on the nodal
/// velocity (or momentum), and after the forces are assembled the same component of the nodal
/// force is stored as the reaction and set to zero, so that a_I = 0 and the node stays fixed.
#pragma once
#include <doctest/doctest.h>

#include <vector>

#include "mpm/grid/grid.hpp"

namespace mpm {

/// One constrained degree of freedom: component `component` of node `node`.
struct FixedDof {
  int node;
  int component;
};

/// A plane of nodes normal to an axis: the nodes whose lattice coordinate along `axis` is `layer`.
/// A scene's face "xmax" is the layer at origin + length, which lies inside the grid when a
/// margin extends the grid beyond it.
struct Face {
  int axis;
  int layer;
};

/// The degrees of freedom of every node on `face` for each of `components`.
template <int Dim>
std::vector<FixedDof> fixed_dofs_on_face(const Grid<Dim>& grid, Face face, const std::vector<int>& components) {
  std::vector<FixedDof> dofs;
  for (int node = 0; node < grid.node_count(); ++node) {
    if (grid.lattice_of(node)[face.axis] != face.layer) continue;
    for (int component : components) dofs.push_back({node, component});
  }
  return dofs;
}

/// Holds the prescribed components of a nodal velocity (or momentum) field at zero.
template <int Dim>
void impose_fixed_velocity(const std::vector<FixedDof>& fixed, std::vector<Vector<Dim>>& nodal_field) {
  for (const FixedDof& dof : fixed) nodal_field[dof.node][dof.component] = 0.0;
}

/// Moves the force on each fixed degree of freedom into the reactions and zeroes it.
template <int Dim>
void store_reactions(const std::vector<FixedDof>& fixed, std::vector<Vector<Dim>>& nodal_force,
                     std::vector<Vector<Dim>>& reaction) {
  for (const FixedDof& dof : fixed) {
    reaction[dof.node][dof.component] = nodal_force[dof.node][dof.component];
    nodal_force[dof.node][dof.component] = 0.0;
  }
}

TEST_CASE("Boundary: a face yields one dof per node and component, reactions take the force") {
  const Grid<2> grid(Vector<2>::Zero(), 1.0, {3, 2});
  const auto bottom = fixed_dofs_on_face(grid, Face{1, 0}, {1});
  CHECK(bottom.size() == 4);
  for (const auto& dof : bottom) CHECK(grid.node_position(dof.node)[1] == 0.0);
  const auto right = fixed_dofs_on_face(grid, Face{0, 3}, {0, 1});
  CHECK(right.size() == 6);
  for (const auto& dof : right) CHECK(grid.node_position(dof.node)[0] == 3.0);

  std::vector<Vector<2>> force(grid.node_count(), Vector<2>(2.0, -3.0)), reaction(grid.node_count(), Vector<2>::Zero());
  store_reactions(bottom, force, reaction);
  CHECK(force[1] == Vector<2>(2.0, 0.0));
  CHECK(reaction[1] == Vector<2>(0.0, -3.0));
  CHECK(force[grid.node_index({1, 1})] == Vector<2>(2.0, -3.0));
}

}  // namespace mpm
