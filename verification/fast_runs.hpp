// The suites' runs: a scene's setup on the fast kernels (mpm/fast/), the layer the library mpm compiles. The
// reference layer (`solver.kernels = "reference"`, the plain serial loops of mpm/transfer/) is for reading and for
// `mpm run --kernels reference`; tests/reference_kernels.sh shows both agree on every shipped scene. The suites do
// not compile it (the library mpm_reference of CMakeLists.txt), so make figures builds two units fewer.
#pragma once
#include <string>

#include "mpm/run.hpp"

namespace verification {

/// \throws mpm::SceneError naming solver.kernels when `scene` (read from `scene_name`) asks for the reference
/// kernels, which the suites do not compile.
inline void require_fast_kernels(const mpm::io::Scene& scene, const std::string& scene_name) {
  if (scene.kernels != mpm::io::KernelsKind::fast)
    throw mpm::SceneError(scene_name, 0, "solver.kernels",
                          "the verification suites run the fast kernels; run the reference ones with "
                          "`mpm run --kernels reference`");
}

/// Runs `setup` of `scene` on the fast kernels, as mpm::run_setup would.
/// \throws mpm::SceneError as require_fast_kernels(); mpm::SimulationFailure when the method fails (`partial` then
/// holds what was done).
template <int Dim>
mpm::RunSummary run_fast(const mpm::io::Scene& scene, const std::string& scene_name, const mpm::Setup<Dim>& setup,
                         mpm::Monitor<Dim>& monitor, mpm::RunSummary* partial) {
  require_fast_kernels(scene, scene_name);
  return mpm::run_setup_on<Dim, mpm::FastKernels>(scene, setup, monitor, partial);
}

}  // namespace verification
