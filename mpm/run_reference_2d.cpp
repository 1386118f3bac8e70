/// \file
/// The runs of 2D scenes on the reference kernels (`solver.kernels = "reference"`), compiled once and apart from the
/// fast ones of mpm/run_2d.cpp (mpm/run.hpp declares them extern): Simulation<2, Shape, Integrator,
/// ReferenceKernels> for every shape function and integrator.
#include "mpm/run.hpp"

namespace mpm {
template RunSummary run_setup_on<2, ReferenceKernels>(const io::Scene&, const Setup<2>&, Monitor<2>&, RunSummary*);
}  // namespace mpm
