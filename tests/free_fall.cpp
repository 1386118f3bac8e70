/// \file
/// One particle falling freely: the integrators against the exact discrete result.
///
/// A single particle with a uniform velocity field has zero strain rate (sum_I grad N_I = 0), so
/// no stress and no internal force: every node it touches has a_I = g. With a constant dt
/// (the Courant step is set by the wave speed c = 1000 m/s >> |v|):
///
/// Forward Euler (paper/02_mpm_forward_euler.md): v_I^k = v_p^k, p_I^{k+1}/m_I = v_p^k + dt g, hence
///   v^{k+1} = v^k + dt g,  x^{k+1} = x^k + dt (v^k + dt g)   (semi-implicit Euler), so
///   x^n = x0 + v0 t + g t^2/2 + g dt t/2,  t = n dt.
/// Predictor-corrector (paper/03_predictor_corrector.md, gamma = 1/2, a_p^0 = 0): step 0 moves x by dt v0 + dt^2 g; later
///   steps by dt v^k + (3/2) dt^2 g (predictor adds (1-gamma) dt a_p = dt g/2, corrector dt g/2, and
///   Eq. (33) adds dt^2 g/2), so
///   x^n = x0 + v0 t + g t^2/2 + g dt t - g dt^2/2   (n >= 1).
/// Both: v^n = v0 + g t. The continuum limit x0 + v0 t + g t^2/2 is met to O(dt).
#include <doctest/doctest.h>

#include "tests/support.hpp"

namespace {

const char* falling_particle = R"(
dimension = 2
[grid]
origin = [0.0, 0.0]
length = [4.0, 8.0]
cells = [4, 8]
[material]
young_modulus = 1.0e6
density = 1.0
[[body]]
min = [1.0, 6.0]
max = [2.0, 7.0]
velocity = [0.5, 2.0]
[gravity]
acceleration = [0.0, -9.81]
[solver]
cfl = 0.5
end_time = 1.0
)";

template <class Expected>
void check_fall(const std::string& integrator, Expected expected_offset) {
  const auto scene = mpm::testing::scene_from_text(falling_particle, {"solver.integrator=\"" + integrator + "\""});
  const auto setup = mpm::build_setup<2>(scene);
  mpm::testing::Recorder<2> recorder(0);
  const auto summary = mpm::run_setup<2>(scene, setup, recorder);
  const double dt = 0.5 * 1.0 / 1000.0, g = -9.81;
  const mpm::Vector<2> x0(1.5, 6.5), v0(0.5, 2.0);
  REQUIRE(summary.steps == 2000);
  for (size_t n = 1; n < recorder.time.size(); ++n) {
    const double t = recorder.time[n];
    REQUIRE(t == doctest::Approx(n * dt).epsilon(1e-12));
    const mpm::Vector<2> exact = x0 + v0 * t + mpm::Vector<2>(0.0, 0.5 * g * t * t + expected_offset(g, dt, t));
    CHECK((recorder.position[n] - exact).norm() <= 1e-11);
    CHECK((recorder.velocity[n] - (v0 + mpm::Vector<2>(0.0, g * t))).norm() <= 1e-11);
  }
}

}  // namespace

TEST_CASE("Eq. (19), Eq. (20), Eq. (21), Eq. (22): free fall, forward Euler: x^n = x0 + v0 t + g t^2/2 + g dt t/2 to 1e-11 m over 2000 steps") {
  check_fall("fe", [](double g, double dt, double t) { return 0.5 * g * dt * t; });
}

TEST_CASE("Eq. (26), Eq. (27), Eq. (28), Eq. (29), Eq. (30), Eq. (31), Eq. (32), Eq. (33): free fall, predictor-corrector: x^n = x0 + v0 t + g t^2/2 + g dt t - g dt^2/2 to 1e-11 m") {
  check_fall("npc", [](double g, double dt, double t) { return g * dt * t - 0.5 * g * dt * dt; });
}

TEST_CASE("Free fall under a [body_force] formula of X and t: the same fall as under [gravity], to the last bit") {
  // b = (0, -g X / 1.5 + 0 t) at the particle's X = 1.5 is gravity; the particle moves in x, so a
  // formula of the current x instead of X would not be.
  for (const std::string integrator : {"fe", "npc"}) {
    const auto with_gravity = mpm::testing::scene_from_text(falling_particle, {"solver.integrator=\"" + integrator + "\""});
    const auto with_field = mpm::testing::scene_from_text(
        falling_particle, {"solver.integrator=\"" + integrator + "\"", "gravity.acceleration=[0.0, 0.0]", "constants.g=9.81",
                           "body_force.acceleration=[\"0\", \"-g * X / 1.5 + 0 * t\"]"});
    mpm::testing::Recorder<2> gravity_fall(0), field_fall(0);
    mpm::run_setup<2>(with_gravity, mpm::build_setup<2>(with_gravity), gravity_fall);
    mpm::run_setup<2>(with_field, mpm::build_setup<2>(with_field), field_fall);
    REQUIRE(field_fall.position.size() == gravity_fall.position.size());
    for (size_t n = 0; n < gravity_fall.position.size(); ++n) {
      CHECK(field_fall.position[n] == gravity_fall.position[n]);
      CHECK(field_fall.velocity[n] == gravity_fall.velocity[n]);
    }
    CHECK(field_fall.position.back()[1] < 6.5 - 2.0);  // it did fall: 6.5 + 2 t - g t^2 / 2 = 3.6 m at t = 1 s
  }
}
