/// \file
/// The fast layer, whole: the fast forms of the transfers (mpm/fast/fast_*.hpp), each an overload taking
/// fast::FastKernels, found by argument-dependent lookup when an integrator's step() is instantiated with that layer.
/// The reference step (mpm/integrators/, mpm/transfer/, mpm/grid/, mpm/shape/) includes none of it: the layer is bound
/// where a run is instantiated (mpm/run.hpp, mpm/analysis/linearised_step.hpp and the tests), by including this file
/// there.
#pragma once
#include "mpm/fast/fast_grid_to_particle.hpp"
#include "mpm/fast/fast_kernels.hpp"
#include "mpm/fast/fast_nodal_forces.hpp"
#include "mpm/fast/fast_particle_to_grid.hpp"
#include "mpm/fast/fast_stencils.hpp"
#include "mpm/fast/fast_strain_update.hpp"
