/// \file
/// A free bar (no supports, no gravity) keeps its total momentum to round-off.
///
/// Why it must: the velocity increment of every integrator is sum_I N_Ip f_I / m_I, so the change of
/// total momentum is sum_p m_p sum_I N_Ip f_I / m_I dt = sum_I f_I dt (m_I = sum_p N_Ip m_p), and
/// sum_I f_I^int = -sum_p V_p sigma_p sum_I grad N_Ip = 0 by the partition of unity.
#include <doctest/doctest.h>

#include "tests/support.hpp"

namespace {

const char* free_bar = R"(
dimension = 1
[grid]
origin = [0.0]
length = [1.0]
cells = [20]
margin_min = [4]
margin_max = [4]
[material]
young_modulus = 1.0e4
density = 1.0
[[body]]
min = [0.0]
max = [1.0]
particles_per_cell = [2]
velocity = [0.0]
[[initial_velocity]]
min = [0.0]
max = [0.3]
velocity = [3.0]
[[initial_velocity]]
min = [0.6]
max = [1.0]
velocity = [-1.0]
[solver]
cfl = 0.5
end_time = 0.05
)";

void check_momentum(const std::string& shape, const std::string& integrator, const std::string& stress_update = "usf") {
  const auto scene = mpm::testing::scene_from_text(
      free_bar, {"solver.shape=\"" + shape + "\"", "solver.integrator=\"" + integrator + "\"",
                 "solver.stress_update=\"" + stress_update + "\""});
  const auto setup = mpm::build_setup<1>(scene);
  mpm::testing::Recorder<1> recorder(0);
  mpm::run_setup<1>(scene, setup, recorder);
  const double initial = recorder.balances.front().momentum[0];  // 0.3*3 - 0.4*1 = 0.5 kg m/s
  CHECK(initial == doctest::Approx(0.5));
  double largest_drift = 0.0;
  for (const auto& sums : recorder.balances) largest_drift = std::max(largest_drift, std::abs(sums.momentum[0] - initial));
  INFO(shape, " + ", integrator, " ", stress_update, ": largest momentum drift ", largest_drift);
  CHECK(largest_drift <= 1e-13);  // |sum m v| ~ 1.3; 100 steps of round-off
}

}  // namespace

TEST_CASE("Eq. (2), Eq. (12): free bar, linear shape functions: momentum constant to round-off, FE and NPC") {
  check_momentum("linear", "fe");
  check_momentum("linear", "npc");
}

TEST_CASE("Eq. (2), Eq. (12): free bar, uGIMP and LME: momentum constant to round-off, FE and NPC") {
  check_momentum("ugimp", "fe");
  check_momentum("ugimp", "npc");
  check_momentum("lme", "fe");
  check_momentum("lme", "npc");
}

TEST_CASE("Eq. (2), Eq. (12): free bar, USL (cubic B-splines) and MUSL (linear, cubic B-splines): momentum constant to round-off") {
  check_momentum("bspline3", "fe", "usl");
  check_momentum("linear", "fe", "musl");
  check_momentum("bspline3", "fe", "musl");
}

TEST_CASE("Free bar, linear USL: the run stops with energy growth, where USF and MUSL keep the momentum (paper/11_stress_update.md)") {
  const auto scene = mpm::testing::scene_from_text(
      free_bar, {"solver.shape=\"linear\"", "solver.integrator=\"fe\"", "solver.stress_update=\"usl\""});
  const auto setup = mpm::build_setup<1>(scene);
  mpm::testing::Recorder<1> recorder(0);
  std::string failure;
  try {
    mpm::run_setup<1>(scene, setup, recorder);
  } catch (const mpm::SimulationFailure& what) {
    failure = what.what();
  }
  CHECK(failure.find("unstable: energy grew") != std::string::npos);
}
