/// \file
/// Compiles the doctests that sit beside the kernels of grid/, particles/, material/, transfer/,
/// integrators/, loading/ and analysis/ into the test program.
#include "mpm/analysis/energy.hpp"
#include "mpm/analysis/rms_error.hpp"
#include "mpm/grid/boundary.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/grid/nodal_update.hpp"
#include "mpm/integrators/forward_euler.hpp"
#include "mpm/integrators/newmark_predictor_corrector.hpp"
#include "mpm/integrators/time_step.hpp"
#include "mpm/loading/gravity.hpp"
#include "mpm/material/linear_elastic.hpp"
#include "mpm/particles/seeding.hpp"
#include "mpm/transfer/grid_to_particle.hpp"
#include "mpm/transfer/nodal_forces.hpp"
#include "mpm/transfer/particle_to_grid.hpp"
#include "mpm/transfer/strain_update.hpp"
