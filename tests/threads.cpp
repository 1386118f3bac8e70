// All cores (issue 9, item 2): a run on two threads equals the run on one thread to 1e-12
// relative, for every shape function and integrator, in 1D and in 2D. The scenes have more
// particles than parallel_threshold, so that every particle loop does split into blocks; the only
// difference is the order in which P2G adds the blocks' shares (and the blocks of the survey's sums).
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
  REQUIRE(setup.particles.size() >= mpm::parallel_threshold);
  FinalState<Dim> one, two;
  mpm::io::Scene scene = base;
  scene.control.threads = 1;
  mpm::run_setup<Dim>(scene, setup, one);
  scene.control.threads = 2;
  const mpm::RunSummary summary = mpm::run_setup<Dim>(scene, setup, two);
  CHECK(summary.threads == 2);
  INFO(scene.shape, " + ", scene.integrator, " in ", Dim, "D");
  CHECK(relative_difference<Dim>(one.last.position, two.last.position) <= 1e-12);
  CHECK(relative_difference<Dim>(one.last.velocity, two.last.velocity) <= 1e-12);
  CHECK(relative_difference<Dim>(one.last.stress, two.last.stress) <= 1e-12);
  CHECK(std::abs(one.energy - two.energy) <= 1e-12 * one.energy);
  CHECK(one.energy > 0.0);
}

}  // namespace

TEST_CASE("Threads: two threads give the results of one to 1e-12 relative, every shape and integrator, 1D and 2D") {
  for (const char* shape : {"linear", "ugimp", "lme"})
    for (const char* integrator : {"fe", "npc"}) {
      const std::string method = std::string(shape) + " + " + integrator;
      std::vector<std::string> overrides{std::string("solver.shape=\"") + shape + "\"",
                                         std::string("solver.integrator=\"") + integrator + "\"", "output.snapshots=[]"};
      // The Dyka bar at 2560 cells for 1 us (194 steps): the waves from the impact have run 5 mm.
      std::vector<std::string> bar = overrides;
      bar.insert(bar.end(), {"grid.cells=[2560]", "solver.end_time=1.0e-6"});
      if (std::string(shape) == "ugimp") bar.push_back("grid.margin_max=[1]");
      check_threads_agree<1>(mpm::load_scene(mpm::testing::source_path("scenes/dyka_bar.toml"), bar));
      // The soil block at 0.25 m cells (6400 particles) for 0.05 s of ramped gravity (58 steps): the
      // two ends of the range of shapes and integrators (the transfers are the same for all).
      if (method != "linear + fe" && method != "lme + npc") continue;
      overrides.insert(overrides.end(), {"grid.cells=[40,40]", "solver.end_time=0.05"});
      check_threads_agree<2>(mpm::load_scene(mpm::testing::source_path("scenes/soil_block.toml"), overrides));
    }
}
