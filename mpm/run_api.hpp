/// \file
/// What a program needs to run a scene, without the kernels: the setup of a scene and the declarations of
/// build_setup() and run_setup(), which mpm/run.hpp defines and the libraries compile once (mpm/run_1d.cpp,
/// mpm/run_2d.cpp, mpm/run_reference_1d.cpp, mpm/run_reference_2d.cpp). The command-line program includes this
/// header, not mpm/run.hpp, so that an edit of a kernel does not recompile it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "mpm/io/scene_budget.hpp"
#include "mpm/io/scene_file.hpp"
#include "mpm/model.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/run_control.hpp"

namespace mpm {

/// Everything a run starts from: the model, the particles and the observed particles.
template <int Dim>
struct Setup {
  Model<Dim> model;
  Particles<Dim> particles;
  std::vector<int> observed;  ///< particle index of each [[observer]]
};

/// The model, the particles and the observed particles of a validated scene (mpm/run.hpp).
template <int Dim>
Setup<Dim> build_setup(const io::Scene& scene);

/// Runs the scene's setup with the scene's shape function, integrator and kernels (mpm/run.hpp).
/// \throws SimulationFailure when the method fails; `partial` then holds what was done (also when the
/// monitor throws).
template <int Dim>
RunSummary run_setup(const io::Scene& scene, const Setup<Dim>& setup, Monitor<Dim>& monitor, RunSummary* partial = nullptr);

extern template Setup<1> build_setup<1>(const io::Scene&);
extern template Setup<2> build_setup<2>(const io::Scene&);
extern template RunSummary run_setup<1>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
extern template RunSummary run_setup<2>(const io::Scene&, const Setup<2>&, Monitor<2>&, RunSummary*);

/// The numbered phases of the step of the scene's integrator, as `mpm trace` numbers them: ForwardEuler::phases (USF),
/// UpdateStressLast::phases (USL, MUSL) or NewmarkPredictorCorrector::phases (defined in mpm/run_1d.cpp).
std::vector<Phase> integrator_phases(io::IntegratorKind integrator, io::StressUpdate stress_update);

/// Reads a scene file, applies `--set` overrides and, when a budget is given, checks the run's
/// estimated size against it (io/scene_budget.hpp). \throws SceneError.
inline io::Scene load_scene(const std::string& path, const std::vector<std::string>& overrides,
                            const std::optional<io::Budget>& budget = std::nullopt) {
  io::SceneFile file = io::parse_scene_file(path);
  for (size_t k = 0; k < overrides.size(); ++k) io::apply_override(file, overrides[k], static_cast<int>(k) + 1);
  io::Scene scene = io::read_scene(file);
  if (budget) io::check_budget(scene, *budget);
  return scene;
}

}  // namespace mpm
