/// \file
/// The runs of 1D scenes on the reference kernels (`solver.kernels = "reference"`), compiled once and apart from the
/// fast ones of mpm/run_1d.cpp (mpm/run.hpp declares them extern): Simulation<1, Shape, Integrator,
/// ReferenceKernels> for every shape function and integrator; and run_setup<1>, which runs a scene on the layer
/// its `solver.kernels` names, and so needs both. In the library mpm_reference (CMakeLists.txt): the CLI and the
/// tests link it; the suites of make figures and make studies run the fast layer alone (mpm::run_setup_on with
/// FastKernels) and do not compile these runs.
#include "mpm/run.hpp"

namespace mpm {
template RunSummary run_setup<1>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
template RunSummary run_setup_on<1, ReferenceKernels>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
}  // namespace mpm
