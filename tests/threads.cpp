// All cores: a run on two or three threads gives the bits of the run on one thread, for every shape
// function and integrator, in 1D and in 2D (the particle loops add their chunks' sums in chunk order,
// mpm/core/parallel.hpp). The scenes have enough particles that every particle loop is cut into
// at least max_chunks chunks and is worth running on the team.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "tests/support.hpp"

namespace {

template <int Dim>
struct FinalState : mpm::Monitor<Dim> {
  void sample(long, double, const mpm::Particles<Dim>& particles, const mpm::Balances<Dim>& sums) override {
    last = particles;
    energy = sums.total();
  }
  mpm::Particles<Dim> last;
  double energy = 0.0;
};

/// Largest |a - b| / (largest |a| over the particles), per field: relative to the field's scale.
template <int Dim, class Field>
double relative_difference(const Field& a, const Field& b) {
  double difference = 0.0, scale = 0.0;
  for (size_t p = 0; p < a.size(); ++p) {
    difference = std::max(difference, (a[p] - b[p]).cwiseAbs().maxCoeff());
    scale = std::max(scale, a[p].cwiseAbs().maxCoeff());
  }
  return scale > 0.0 ? difference / scale : difference;
}

template <int Dim>
void check_threads_agree(const mpm::io::Scene& base) {
  const mpm::Setup<Dim> setup = mpm::build_setup<Dim>(base);
  REQUIRE(mpm::chunks_of(setup.particles.size()) >= mpm::max_chunks);
  REQUIRE((long(setup.particles.size()) << Dim) >= mpm::parallel_work);  // even the linear transfers (2^Dim nodes)
  mpm::io::Scene scene = base;
  INFO(mpm::io::name_of(scene.shape), " + ", mpm::io::name_of(scene.integrator), ", stress update ", mpm::io::name_of(scene.stress_update), ", in ", Dim, "D");
  FinalState<Dim> one;
  scene.control.threads = 1;
  mpm::run_setup<Dim>(scene, setup, one);
  CHECK(one.energy > 0.0);
  const mpm::TeamAlways on_the_team;  // every loop on the team, whatever the machine's load
  for (int threads : {2, 3}) {
    FinalState<Dim> many;
    scene.control.threads = threads;
    const mpm::RunSummary summary = mpm::run_setup<Dim>(scene, setup, many);
    CHECK(summary.threads == threads);
    CHECK(relative_difference<Dim>(one.last.position, many.last.position) == 0.0);
    CHECK(relative_difference<Dim>(one.last.velocity, many.last.velocity) == 0.0);
    CHECK(relative_difference<Dim>(one.last.stress, many.last.stress) == 0.0);
    CHECK(many.energy == one.energy);
  }
}

}  // namespace

TEST_CASE("Threads: two and three threads give the bits of one, every shape and integrator, 1D and 2D") {
  for (const char* shape : {"linear", "ugimp", "lme", "bspline2", "bspline3"})
    for (const char* integrator : {"fe", "npc", "usl", "musl"}) {
      const std::string method = std::string(shape) + " + " + integrator;
      const bool stress_last = method.find("usl") != std::string::npos;  // usl, musl: forward Euler, the stress updated last
      if (stress_last && std::string(shape) != "linear" && std::string(shape) != "bspline2") continue;
      std::vector<std::string> overrides{std::string("solver.shape=\"") + shape + "\"", "output.snapshots=[]"};
      overrides.push_back(std::string("solver.integrator=\"") + (stress_last ? "fe" : integrator) + "\"");
      if (stress_last) overrides.push_back(std::string("solver.stress_update=\"") + integrator + "\"");
      // The Dyka bar at 8192 cells for 0.32 us (about 200 steps): the waves from the impact have run 1.6 mm.
      std::vector<std::string> bar = overrides;
      bar.insert(bar.end(), {"grid.cells=[8192]", "solver.end_time=0.32e-6"});
      check_threads_agree<1>(mpm::load_scene(mpm::testing::source_path("scenes/dyka_bar.toml"), bar));
      // The soil block at 0.25 m cells (6400 particles) for 0.05 s of ramped gravity (58 steps): the
      // two ends of the range of shapes and integrators (the transfers are the same for all).
      if (method != "linear + fe" && method != "lme + npc") continue;
      std::vector<std::string> block = overrides;
      block.insert(block.end(), {"grid.cells=[40,40]", "solver.end_time=0.05"});
      check_threads_agree<2>(mpm::load_scene(mpm::testing::source_path("scenes/soil_block.toml"), block));
      // At 64 x 64 cells (16384 particles) for 10 steps: 16 chunks of 1024 particles, each chunk beyond the
      // first with its copy of the nodes it reaches.
      overrides.insert(overrides.end(), {"grid.cells=[64,64]", "solver.end_time=5.4e-3"});
      check_threads_agree<2>(mpm::load_scene(mpm::testing::source_path("scenes/soil_block.toml"), overrides));
    }
}
