/// \file
/// The runs of 2D scenes, compiled once (mpm/run.hpp declares them extern): Simulation<2, Shape,
/// Integrator> for every shape function and integrator, on the fast kernels (mpm/run_reference_2d.cpp: on the
/// reference kernels, and run_setup<2>, which runs a scene on the layer it names).
#include "mpm/cli/shape_evaluation.hpp"
#include "mpm/run.hpp"
#include "mpm/stability.hpp"

namespace mpm {
template Setup<2> build_setup<2>(const io::Scene&);
#ifdef MPM_LAB  // the lab build: the runs of the reference kernels here, beside the analyses that step them
template RunSummary run_setup<2>(const io::Scene&, const Setup<2>&, Monitor<2>&, RunSummary*);
template RunSummary run_setup_on<2, ReferenceKernels>(const io::Scene&, const Setup<2>&, Monitor<2>&, RunSummary*);
#else
template RunSummary run_setup_on<2, FastKernels>(const io::Scene&, const Setup<2>&, Monitor<2>&, RunSummary*);
#endif
template StabilityLimits stability_limits<2>(const io::Scene&, double);
template bool stable_at<2>(const io::Scene&, double);
}  // namespace mpm

namespace mpm::cli {
template void evaluate_request<2>(const ShapeRequest&, std::ostream&);  // `mpm shape --dim 2`, Fig. 4's tables
}  // namespace mpm::cli
