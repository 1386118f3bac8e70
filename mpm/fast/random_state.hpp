/// \file
/// Random states on which the doctests of mpm/fast/ compare each fast kernel with its reference: random
/// particles (positions, masses, densities, velocities, accelerations, symmetric stresses and strains, body forces)
/// on a grid of either dimension, their stencils from a given shape function, and random nodal fields.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/grid/grid_fields.hpp"
#include "mpm/loading/body_force.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/shape/bspline.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/ugimp.hpp"

namespace mpm::testing {

/// A random state: `count` particles in the middle of a grid of 12 cells per axis (h = 0.5), at least 3 cells from
/// its edges (the cubic B-spline's reach), in random order, with the stencils of one shape function; nodal fields
/// random on every node, the mass 0 on about one node in five. The 1200 particles by default make max_chunks chunks
/// (chunks_of, mpm/core/parallel.hpp), so the fast scatter adds into its chunks' copies and sums them in chunk order,
/// the path its threads take (on the team where a loop has parallel_work stencil entries: 2D cubic B-splines).
template <int Dim>
struct RandomState {
  static constexpr int dimension = Dim;
  Grid<Dim> grid;
  Particles<Dim> particles;
  Stencils<Dim> stencils;
  GridFields<Dim> fields;
  ParticleBodyForces<Dim> body_force;
};

template <int Dim, class Shape>
RandomState<Dim> random_state(unsigned seed, int count = 1200) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), centred(-1.0, 1.0);
  auto vector = [&](double scale) {
    Vector<Dim> value;
    for (int axis = 0; axis < Dim; ++axis) value[axis] = scale * centred(random);
    return value;
  };
  typename Grid<Dim>::MultiIndex cells;
  cells.fill(12);
  RandomState<Dim> state{Grid<Dim>(Vector<Dim>::Zero(), 0.5, cells), {}, {}, GridFields<Dim>(0), {}};
  for (int p = 0; p < count; ++p) {
    Vector<Dim> x;
    for (int axis = 0; axis < Dim; ++axis) x[axis] = 1.5 + 3.0 * unit(random);
    state.particles.add(x, 0.5 + unit(random), 1.0 + unit(random), vector(2.0), Vector<Dim>::Constant(0.125));
    state.particles.acceleration[p] = vector(30.0);
    const Matrix<Dim> stress = Matrix<Dim>::NullaryExpr([&](int, int) { return 100.0 * centred(random); });
    state.particles.stress[p] = 0.5 * (stress + stress.transpose());
    state.particles.strain[p] = 1e-3 * state.particles.stress[p];
    state.body_force.per_unit_mass.push_back(vector(10.0));
  }
  state.body_force.all_zero = state.body_force.uniform = false;
  Shape shape(state.grid);
  shape.initialise(state.particles);
  state.stencils.resize(count, shape.capacity());
  compute_stencils(shape, state.particles.position, state.stencils);
  const int nodes = state.grid.node_count();
  state.fields = GridFields<Dim>(nodes);
  for (int node = 0; node < nodes; ++node) {
    state.fields.nodal_mass[node] = unit(random) < 0.2 ? 0.0 : 0.5 + unit(random);
    state.fields.nodal_momentum_k[node] = vector(3.0);
    state.fields.nodal_momentum_k1[node] = vector(3.0);
    state.fields.nodal_velocity_k[node] = vector(3.0);
    state.fields.nodal_force[node] = vector(50.0);
  }
  return state;
}

/// The largest entry of |a - b| over the largest entry of |a| (0 when a is all zero and b equals it): how far a
/// fast kernel's field is from its reference's, relative to the field's largest magnitude.
inline double largest_entry(double value) { return std::abs(value); }
template <class Derived>
double largest_entry(const Eigen::MatrixBase<Derived>& value) {
  return value.cwiseAbs().maxCoeff();
}
template <class T>
double relative_difference(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return 1.0;
  double largest = 0.0, difference = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    largest = std::max(largest, largest_entry(a[k]));
    difference = std::max(difference, largest_entry(a[k] - b[k]));
  }
  return largest > 0.0 ? difference / largest : difference;
}

/// Calls check(state) on random states, 1D and 2D, of every shape function a doctest builds cheaply: linear,
/// uGIMP, quadratic and cubic B-splines (the states differ by their seeds too).
template <class Check>
void on_random_states(Check&& check) {
  check(random_state<1, LinearShape<1>>(1));
  check(random_state<1, UgimpShape<1>>(2));
  check(random_state<1, BsplineShape<1, 2>>(3));
  check(random_state<1, BsplineShape<1, 3>>(4));
  check(random_state<2, LinearShape<2>>(5));
  check(random_state<2, UgimpShape<2>>(6));
  check(random_state<2, BsplineShape<2, 2>>(7));
  check(random_state<2, BsplineShape<2, 3>>(8));
}

}  // namespace mpm::testing
