/// \file
/// From a validated scene to a finished run. The dimension, the shape function, the integrator and the layer of
/// kernels (reference or fast, mpm/core/kernels.hpp) are chosen here, once per run, as template arguments of
/// Simulation; nothing in the time step asks again. An integrator's variants are chosen here once too, as types held
/// by the integrator (std::variant: its step calls the chosen variant's own step).
#pragma once
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "mpm/integrators/forward_euler.hpp"
#include "mpm/integrators/newmark_predictor_corrector.hpp"
#include "mpm/integrators/update_stress_last.hpp"
#include "mpm/io/scene_builder.hpp"
#include "mpm/shape/bspline.hpp"
#include "mpm/fast/fast_layer.hpp"
#include "mpm/fast/lme_fast.hpp"
#include "mpm/shape/lme_reference.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/ugimp.hpp"
#include "mpm/run_api.hpp"
#include "mpm/simulation.hpp"

namespace mpm {

template <int Dim>
Setup<Dim> build_setup(const io::Scene& scene) {
  Setup<Dim> setup;
  setup.model = io::build_model<Dim>(scene);
  setup.particles = io::build_particles<Dim>(scene, setup.model.grid);
  setup.observed = io::observed_particles<Dim>(scene, setup.particles);
  return setup;
}

inline LmeOptions lme_options(const io::Scene& scene) {
  LmeOptions options;
  options.gamma = scene.lme_gamma;
  options.support_tolerance = scene.lme_tol;
  options.newton_tolerance = scene.lme_newton_tol;
  options.max_iterations = scene.lme_max_iterations;
  options.beta_rule = scene.lme_beta;
  options.neighbours = scene.lme_neighbours;
  return options;
}

/// The scene's predictor-corrector, with its variants: each scene word becomes its variant's type here, once per run
/// (mpm/transfer/grid_to_particle.hpp), held as a value of the integrator, so that a variant adds no Simulation.
inline NewmarkPredictorCorrector npc_integrator(const io::Scene& scene) {
  NewmarkPredictorCorrector integrator;
  integrator.newmark_gamma = scene.newmark_gamma;
  integrator.position_velocity = newmark_position_rule(scene.npc_position_velocity);
  integrator.particle_velocity = newmark_velocity_rule(scene.npc_velocity);
  return integrator;
}

/// The scene's forward Euler, with its variants (each a type, as npc_integrator's).
inline ForwardEuler fe_integrator(const io::Scene& scene) {
  ForwardEuler integrator;
  integrator.position_velocity = euler_position_rule(scene.fe_position_velocity);
  integrator.particle_velocity = euler_velocity_rule(scene.flip_fraction);
  return integrator;
}

/// The scene's forward Euler with its stress updated last (`solver.stress_update` = "usl" | "musl"), with its
/// variants (each a type, as npc_integrator's).
inline UpdateStressLast stress_last_integrator(const io::Scene& scene) {
  UpdateStressLast integrator;
  if (scene.stress_update == io::StressUpdate::musl) integrator.stress_velocity = MuslMomentumK1{};
  integrator.position_velocity = euler_position_rule(scene.fe_position_velocity);
  integrator.particle_velocity = euler_velocity_rule(scene.flip_fraction);
  return integrator;
}

/// The LME shape function a layer of kernels runs with: the fast form (mpm/fast/lme_fast.hpp: warm start, cache,
/// Taylor exp) under FastKernels, the reference form of Eqs. (34)-(41) (mpm/shape/lme_reference.hpp) under
/// ReferenceKernels.
template <class Kernels, int Dim>
struct LmeShapeOf {
  using type = LmeShape<Dim>;
};
template <int Dim>
struct LmeShapeOf<ReferenceKernels, Dim> {
  using type = LmeReferenceShape<Dim>;
};
template <class Kernels, int Dim>
using LmeShapeFor = typename LmeShapeOf<Kernels, Dim>::type;

/// Calls visit(shape, integrator) with the scene's shape function and integrator, each built once:
/// the one place where the scene's choice of method becomes a type (its choice of kernels: with_kernels). The
/// integrator's variants (position and particle velocity, USL or MUSL) are types too, held as values of the
/// integrator (std::variant): each adds an instantiation of its own small step, none of Simulation.
template <int Dim, class Kernels = AnalysisKernels, class Visitor>
auto with_method(const io::Scene& scene, const Grid<Dim>& grid, Visitor&& visit) {
  auto with_shape = [&](auto integrator) {
    switch (scene.shape) {
      case io::ShapeKind::ugimp: return visit(UgimpShape<Dim>(grid), integrator);
      case io::ShapeKind::bspline2: return visit(BsplineShape<Dim, 2>(grid), integrator);
      case io::ShapeKind::bspline3: return visit(BsplineShape<Dim, 3>(grid), integrator);
      case io::ShapeKind::lme: return visit(LmeShapeFor<Kernels, Dim>(grid, lme_options(scene)), integrator);
      default: return visit(LinearShape<Dim>(grid), integrator);
    }
  };
  if (scene.integrator == io::IntegratorKind::npc) return with_shape(npc_integrator(scene));
  if (scene.stress_update != io::StressUpdate::usf) return with_shape(stress_last_integrator(scene));
  return with_shape(fe_integrator(scene));
}

/// Calls visit(kernels) with the scene's layer of kernels (`solver.kernels`), ReferenceKernels{} or FastKernels{}:
/// the one place where that choice becomes a type (ReferenceKernels{} alone in the lab build, mpm/core/kernels.hpp).
template <class Visitor>
auto with_kernels(const io::Scene& scene, Visitor&& visit) {
  if constexpr (lab_build) {  // the lab build compiles the reference kernels alone (its scene reader refuses "fast")
    return visit(ReferenceKernels{});
  } else {
    if (scene.kernels == io::KernelsKind::reference) return visit(ReferenceKernels{});
    return visit(FastKernels{});
  }
}

/// Runs the scene's setup with the scene's shape function and integrator on the kernels of `Kernels`.
/// The run's control on a layer of kernels: on the reference kernels every loop of the step runs on one thread (the
/// stencils and the balances too), so that a learner's run is the plain serial loop the reference files show; the
/// results are the same bits on any number of threads either way (mpm/core/parallel.hpp).
template <class Kernels>
RunControl control_on(RunControl control) {
  if constexpr (std::is_same_v<Kernels, ReferenceKernels>) control.threads = 1;
  return control;
}

template <int Dim, class Kernels>
RunSummary run_setup_on(const io::Scene& scene, const Setup<Dim>& setup, Monitor<Dim>& monitor, RunSummary* partial) {
  return with_method<Dim, Kernels>(scene, setup.model.grid, [&](auto shape, auto integrator) {
    Simulation<Dim, decltype(shape), decltype(integrator), Kernels> simulation(setup.model, setup.particles,
                                                                                std::move(shape), integrator,
                                                                                control_on<Kernels>(scene.control));
    try {
      return simulation.run(monitor);
    } catch (...) {  // a failure of the method, a stop signal, an output failure: keep what was done
      if (partial) *partial = simulation.summary();
      throw;
    }
  });
}

/// Runs the scene's setup with the scene's shape function, integrator and kernels (declared in mpm/run_api.hpp).
template <int Dim>
RunSummary run_setup(const io::Scene& scene, const Setup<Dim>& setup, Monitor<Dim>& monitor, RunSummary* partial) {
  return with_kernels(scene, [&](auto kernels) {
    return run_setup_on<Dim, decltype(kernels)>(scene, setup, monitor, partial);
  });
}

// The runs are compiled once, for Dim = 1 and 2, in mpm/run_1d.cpp and mpm/run_2d.cpp (the fast kernels: the library
// mpm of CMakeLists.txt) and mpm/run_reference_1d.cpp and mpm/run_reference_2d.cpp (the reference kernels, and
// run_setup, which takes either: the library mpm_reference), not again in every program and test file that runs a
// scene: each instantiates Simulation for 5 shape functions x 3 integrators (USF, USL/MUSL, NPC).
extern template RunSummary run_setup_on<1, FastKernels>(const io::Scene&, const Setup<1>&, Monitor<1>&, RunSummary*);
extern template RunSummary run_setup_on<2, FastKernels>(const io::Scene&, const Setup<2>&, Monitor<2>&, RunSummary*);
extern template RunSummary run_setup_on<1, ReferenceKernels>(const io::Scene&, const Setup<1>&, Monitor<1>&,
                                                             RunSummary*);
extern template RunSummary run_setup_on<2, ReferenceKernels>(const io::Scene&, const Setup<2>&, Monitor<2>&,
                                                             RunSummary*);

}  // namespace mpm
