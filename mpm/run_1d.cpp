/// \file
/// The runs of 1D scenes, compiled once (mpm/run.hpp declares them extern): Simulation<1, Shape,
/// Integrator> for every shape function and integrator, on the fast kernels (mpm/run_reference_1d.cpp: on the
/// reference kernels, and run_setup, which takes either).
#include "mpm/cli/shape_evaluation.hpp"
#include "mpm/run.hpp"
#include "mpm/stability.hpp"

namespace mpm {
template Setup<1> build_setup<1>(const io::Scene&);
#ifdef MPM_LAB  // the lab build: the runs of the reference kernels here, beside the analyses that step them
template RunSummary run_setup<1>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
template RunSummary run_setup_on<1, ReferenceKernels>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
#else
template RunSummary run_setup_on<1, FastKernels>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
#endif
template StabilityLimits stability_limits<1>(const io::Scene&, double);
template bool stable_at<1>(const io::Scene&, double);
template double moved_body_cfl_limit<1>(const io::Scene&, double, double);

std::vector<Phase> integrator_phases(io::IntegratorKind integrator, io::StressUpdate stress_update) {
  auto list = [](const auto& phases) { return std::vector<Phase>(phases.begin(), phases.end()); };
  if (integrator == io::IntegratorKind::npc) return list(NewmarkPredictorCorrector::phases);
  if (stress_update != io::StressUpdate::usf) return list(UpdateStressLast::phases);
  return list(ForwardEuler::phases);
}
}  // namespace mpm

namespace mpm::cli {
template void evaluate_request<1>(const ShapeRequest&, std::ostream&);  // `mpm shape --dim 1`, Fig. 4's tables
}  // namespace mpm::cli
