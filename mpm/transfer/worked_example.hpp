/// \file
/// The worked example of the transfer doctests, small enough to check every number by hand.
///
/// A 1D grid with h = 1 and nodes x = 0, 1, 2; linear shape functions; two particles:
///
/// | p | x_p  | m_p | rho_p | V_p | v_p | sigma_p | nodes | N_Ip       | grad N_Ip |
/// |---|------|-----|-------|-----|-----|---------|-------|------------|-----------|
/// | 0 | 0.25 | 2   | 4     | 0.5 | +1  | +10     | 0, 1  | 0.75, 0.25 | -1, +1    |
/// | 1 | 1.5  | 4   | 4     | 1   | -1  | -20     | 1, 2  | 0.5, 0.5   | -1, +1    |
///
/// By hand: m_I = (1.5, 2.5, 2); p_I = (1.5, -1.5, -2); v_I = (1, -0.6, -1);
/// strain rates (Eq. 16): p0: 1(-1) + (-0.6)(1) = -1.6, p1: (-0.6)(-1) + (-1)(1) = -0.4;
/// internal forces (Eq. 14): f_0 = -0.5(10)(-1) = 5, f_1 = -0.5(10)(1) - 1(-20)(-1) = -25, f_2 = -1(-20)(1) = 20.
#pragma once
#include "mpm/grid/grid_fields.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/particles/stencils.hpp"
#include "mpm/shape/linear.hpp"

namespace mpm::testing {

struct WorkedExample {
  Grid<1> grid{Vector<1>(0.0), 1.0, {2}};
  Particles<1> particles;
  Stencils<1> stencils;
  GridFields<1> fields{3};

  WorkedExample() {
    particles.add(Vector<1>(0.25), 2.0, 4.0, Vector<1>(1.0), Vector<1>(0.5));
    particles.add(Vector<1>(1.5), 4.0, 4.0, Vector<1>(-1.0), Vector<1>(0.5));
    particles.stress[0](0, 0) = 10.0;
    particles.stress[1](0, 0) = -20.0;
    LinearShape<1> shape(grid);
    stencils.resize(particles.size(), shape.capacity());
    compute_stencils(shape, particles.position, stencils);
  }
};

}  // namespace mpm::testing
