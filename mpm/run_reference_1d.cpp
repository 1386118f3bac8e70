/// \file
/// The runs of 1D scenes on the reference kernels (`solver.kernels = "reference"`), compiled once and apart from the
/// fast ones of mpm/run_1d.cpp (mpm/run.hpp declares them extern): Simulation<1, Shape, Integrator,
/// ReferenceKernels> for every shape function and integrator.
#include "mpm/run.hpp"

namespace mpm {
template RunSummary run_setup_on<1, ReferenceKernels>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
}  // namespace mpm
