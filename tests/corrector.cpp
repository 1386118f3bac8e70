/// \file
/// When the corrector, Eq. (30), matters (paper/03_predictor_corrector.md, "When Eq. (30) matters"): only when the
/// position update, Eq. (33), reads the corrected nodal velocity. Under the default position update (`projected`,
/// Eq. (33) as printed, v_I^k = p_I^k / m_I) nothing reads the corrector's output, so a run without it gives the
/// same bits; under `corrected` (the authors' code) the particles end elsewhere.
///
/// The step without the corrector is NewmarkPredictorCorrector::step() with its corrector call left out; the same
/// copy with the call in is checked to give the integrator's bits, so that the copy stays the integrator's step.
#include <doctest/doctest.h>

#include "tests/support.hpp"

namespace corrector_test {

/// The predictor-corrector's step as NewmarkPredictorCorrector::step() takes it, with or without Eq. (30).
template <bool with_corrector>
struct NpcCorrectorSwitch : mpm::NewmarkPredictorCorrector {
  template <class Kernels, int Dim, class... Rest>
  void step(const Kernels& kernels, const mpm::Model<Dim>& model, const mpm::Stencils<Dim>& stencils,
            const mpm::ParticleBodyForces<Dim>& body_force, double dt, mpm::Particles<Dim>& particles,
            mpm::GridFields<Dim>& grid, Rest&&...) const {
    grid.reset();
    nodal_mass_and_velocity_predictor(kernels, particles, stencils, newmark_gamma, dt, grid);
    mpm::impose_fixed_velocity(model.fixed, grid.predicted_velocity);
    mpm::impose_fixed_velocity(model.fixed, grid.nodal_momentum_k);
    update_strain_density_stress(kernels, stencils, grid.predicted_velocity, model.materials, dt, particles);
    add_nodal_forces(kernels, particles, stencils, body_force, grid);
    mpm::store_reactions(model.fixed, grid.nodal_force, grid.reaction);
    if (with_corrector) mpm::newmark_corrector(newmark_gamma, dt, grid);
    newmark_g2p(kernels, stencils, grid, newmark_gamma, dt, position_velocity, particle_velocity, particles);
  }
};

/// The particles at the end of `scene` run with linear shape functions and `integrator`.
template <int Dim, class Integrator>
mpm::Particles<Dim> final_particles(const mpm::io::Scene& scene, const Integrator& integrator) {
  const mpm::Setup<Dim> setup = mpm::build_setup<Dim>(scene);
  mpm::Simulation<Dim, mpm::LinearShape<Dim>, Integrator> simulation(
      setup.model, setup.particles, mpm::LinearShape<Dim>(setup.model.grid), integrator, scene.control);
  mpm::Monitor<Dim> quiet;
  simulation.run(quiet);
  return simulation.particles();
}

template <bool with_corrector>
NpcCorrectorSwitch<with_corrector> switched(const mpm::NewmarkPredictorCorrector& options) {
  NpcCorrectorSwitch<with_corrector> integrator;
  static_cast<mpm::NewmarkPredictorCorrector&>(integrator) = options;
  return integrator;
}

template <int Dim>
bool same_bits(const mpm::Particles<Dim>& a, const mpm::Particles<Dim>& b) {
  return a.position == b.position && a.velocity == b.velocity && a.acceleration == b.acceleration &&
         a.stress == b.stress && a.strain == b.strain && a.density == b.density;
}

/// Runs `path` with the predictor-corrector and each position update, with and without the corrector.
template <int Dim>
void check_corrector(const std::string& path, const std::vector<std::string>& settings) {
  for (const char* update : {"projected", "corrected"}) {
    std::vector<std::string> all = settings;
    all.push_back("solver.integrator=\"npc\"");
    all.push_back(std::string("solver.npc_position_velocity=\"") + update + "\"");
    const mpm::io::Scene scene = mpm::load_scene(mpm::testing::source_path(path), all);
    const mpm::NewmarkPredictorCorrector options = mpm::npc_integrator(scene);
    const mpm::Particles<Dim> integrator = final_particles<Dim>(scene, options);
    const mpm::Particles<Dim> copy = final_particles<Dim>(scene, switched<true>(options));
    const mpm::Particles<Dim> without = final_particles<Dim>(scene, switched<false>(options));
    CAPTURE(path);
    CAPTURE(update);
    CHECK(same_bits(copy, integrator));  // the copy is the integrator's step
    if (std::string(update) == "projected") {
      CHECK(same_bits(without, integrator));
    } else {
      CHECK(without.position != integrator.position);
    }
  }
}

}  // namespace corrector_test

TEST_CASE("Eq. (30), Eq. (33): the corrector changes no bit under the default position update, and moves the particles under the corrected one") {
  // The default is Eq. (33) as printed, which README.md and paper/03 say the corrector is inert under.
  CHECK(mpm::load_scene(mpm::testing::source_path("scenes/dyka_bar.toml"), {}).npc_position_velocity ==
        mpm::NewmarkPositionVelocity::projected);
  // The Dyka bar for 150 steps (1D, a wall, a wave); the soil block (2D, walls, ramped gravity) for its first 2 s.
  corrector_test::check_corrector<1>("scenes/dyka_bar.toml", {"solver.end_time=5.0e-5", "output.snapshots=[]"});
  corrector_test::check_corrector<2>("scenes/soil_block.toml", {"solver.end_time=2.0", "output.snapshots=[]"});
}
