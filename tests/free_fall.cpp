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
/// Predictor-corrector (paper/03_predictor_corrector.md, a_p^0 = 0): the particle takes a_p^{k+1} = g every
///   step, and the position update of Eq. (33) as printed (v_I^k, `projected`, the default) moves it by
///   dt v^k + dt^2 g/2: x^n = x0 + v0 t + g t^2/2 exactly, for any gamma. The authors' array
///   (`corrected`, v_I^{k+1} = v^k + (1-gamma) dt a_p^k + gamma dt g) moves it by dt v0 + (gamma + 1/2) dt^2 g in
///   the first step and by dt v^k + (3/2) dt^2 g in every later one, so at gamma = 1/2
///   x^n = x0 + v0 t + g t^2/2 + g dt t - g dt^2/2   (n >= 1, gamma = 1/2): an O(dt) offset.
/// Newmark average (Eq. 23, `npc_velocity = "average"`): its first step averages a_p^0 = 0 with g, so
///   v^n = v0 + g t - (1-gamma) g dt and, with the printed Eq. (33), x^n = x0 + v0 t + g t^2/2 - (1-gamma) g dt (t - dt).
/// Forward Euler and Eq. (32): v^n = v0 + g t.
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

template <class Expected, class ExpectedVelocity>
void check_fall(const std::vector<std::string>& settings, Expected expected_offset, ExpectedVelocity velocity_offset) {
  const auto scene = mpm::testing::scene_from_text(falling_particle, settings);
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
    CHECK((recorder.velocity[n] - (v0 + mpm::Vector<2>(0.0, g * t + velocity_offset(g, dt)))).norm() <= 1e-11);
  }
}

}  // namespace

TEST_CASE("Eq. (19), Eq. (20), Eq. (21), Eq. (22): free fall, forward Euler: x^n = x0 + v0 t + g t^2/2 + g dt t/2 to 1e-11 m over 2000 steps") {
  check_fall({"solver.integrator=\"fe\""}, [](double g, double dt, double t) { return 0.5 * g * dt * t; },
             [](double, double) { return 0.0; });
}

TEST_CASE("Eq. (26), Eq. (27), Eq. (28), Eq. (29), Eq. (30), Eq. (31), Eq. (32), Eq. (33): free fall, predictor-corrector with Eq. (33) as printed: x^n = x0 + v0 t + g t^2/2 to 1e-11 m, gamma 0.5 and 0.6") {
  for (const std::string gamma : {"0.5", "0.6"})
    check_fall({"solver.integrator=\"npc\"", "solver.newmark_gamma=" + gamma}, [](double, double, double) { return 0.0; },
               [](double, double) { return 0.0; });
}

TEST_CASE("Eq. (33): free fall, predictor-corrector with the authors' corrected v_I: x^n = x0 + v0 t + g t^2/2 + g dt t - g dt^2/2") {
  check_fall({"solver.integrator=\"npc\"", "solver.npc_position_velocity=\"corrected\""},
             [](double g, double dt, double t) { return g * dt * t - 0.5 * g * dt * dt; }, [](double, double) { return 0.0; });
}

TEST_CASE("Eq. (23): free fall, Newmark average at gamma = 0.6: v^n = v0 + g t - 0.4 g dt from a_p^0 = 0, x^n offset -0.4 g dt (t - dt)") {
  check_fall({"solver.integrator=\"npc\"", "solver.npc_velocity=\"average\"", "solver.newmark_gamma=0.6"},
             [](double g, double dt, double t) { return -0.4 * g * dt * (t - dt); }, [](double g, double dt) { return -0.4 * g * dt; });
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

TEST_CASE("output.times: the run lands on each sample time, samples there only, and falls as it would without them") {
  // Four times off the step's grid (dt = 0.5 ms): the samples are taken exactly there and nowhere else,
  // and the velocity is v0 + g t at each (both integrators add dt g per step, whatever the dt).
  for (const std::string integrator : {"fe", "npc"}) {
    const auto scene = mpm::testing::scene_from_text(
        falling_particle, {"solver.integrator=\"" + integrator + "\"", "output.times=[0.0, 0.12345678, 0.5, 0.99990001]"});
    mpm::testing::Recorder<2> recorder(0);
    const auto summary = mpm::run_setup<2>(scene, mpm::build_setup<2>(scene), recorder);
    REQUIRE(recorder.time == std::vector<double>{0.0, 0.12345678, 0.5, 0.99990001});
    for (size_t n = 0; n < recorder.time.size(); ++n)
      CHECK((recorder.velocity[n] - mpm::Vector<2>(0.5, 2.0 - 9.81 * recorder.time[n])).norm() <= 1e-11);
    CHECK(summary.final_time == 1.0);
    CHECK(summary.steps > 2000);  // 2000 steps of 0.5 ms without the samples: 0.12345678 s is off that grid
  }
}

TEST_CASE("solver.dt: every step is dt, the clock n dt from the last landing, a landing off the grid shortens a step") {
  // dt = 0.25 ms instead of the Courant step's 0.5 ms (--set solver.dt replaces the file's cfl): 4000 steps of
  // exactly dt, sampled at t = n dt to the bit. With a sample time off the grid, 0.1001 s, the step that lands
  // there is 0.1 ms and the clock restarts from it: 400 + 1 + 3599 steps, the last 0.15 ms long.
  const double dt = 2.5e-4;
  const auto scene = mpm::testing::scene_from_text(falling_particle, {"solver.dt=2.5e-4"});
  mpm::testing::Recorder<2> recorder(0);
  const auto summary = mpm::run_setup<2>(scene, mpm::build_setup<2>(scene), recorder);
  CHECK(summary.steps == 4000);
  CHECK(summary.smallest_time_step == dt);
  CHECK(summary.largest_time_step == dt);
  REQUIRE(recorder.time.size() == 4001);
  for (size_t n = 1; n < 4000; ++n) REQUIRE(recorder.time[n] == static_cast<double>(n) * dt);
  CHECK(recorder.time.back() == 1.0);
  CHECK((recorder.velocity.back() - mpm::Vector<2>(0.5, 2.0 - 9.81)).norm() <= 1e-11);  // forward Euler: v0 + g t
  const auto landing =
      mpm::testing::scene_from_text(falling_particle, {"solver.dt=2.5e-4", "output.times=[0.1001, 1.0]"});
  mpm::testing::Recorder<2> landed(0);
  const auto summary_landed = mpm::run_setup<2>(landing, mpm::build_setup<2>(landing), landed);
  CHECK(summary_landed.steps == 4001);
  CHECK(summary_landed.smallest_time_step == doctest::Approx(1e-4).epsilon(1e-9));
  CHECK(summary_landed.largest_time_step == doctest::Approx(dt).epsilon(1e-12));
  CHECK(landed.time == std::vector<double>{0.1001, 1.0});
}

TEST_CASE("A run ends: past RunControl::max_steps, and when the Courant step collapses, it fails naming step and cause") {
  // 2000 Courant steps of 0.5 ms to t = 1 s; a limit of 10 ends the run before its 11th step, at t = 5 ms
  auto limited = mpm::testing::scene_from_text(falling_particle);
  limited.control.max_steps = 10;
  mpm::testing::Recorder<2> recorder(0);
  const auto setup = mpm::build_setup<2>(limited);
  try {
    mpm::run_setup<2>(limited, setup, recorder);
    FAIL("the run went past its limit of 10 steps");
  } catch (const mpm::SimulationFailure& failure) {
    CHECK(failure.step == 10);
    CHECK(failure.time == doctest::Approx(5e-3).epsilon(1e-12));
    CHECK(std::string(failure.what()).find("limit of 10 steps before end_time = 1 s") != std::string::npos);
  }
  // a slow material (c = 1 m/s) and a particle falling at 2 m/s: C = |v| = 2 + 9.81 t and dt = 0.5 h / C, so at a
  // floor of half the first step the run fails once |v| > 4 m/s, at 0.2 s < t < 0.2 s + one step (at most 0.125 s)
  auto slow = mpm::testing::scene_from_text(falling_particle, {"material.young_modulus=1.0", "body[0].velocity=[0.0, -2.0]"});
  slow.control.smallest_step_fraction = 0.5;
  const auto slow_setup = mpm::build_setup<2>(slow);
  try {
    mpm::run_setup<2>(slow, slow_setup, recorder);
    FAIL("the run went on with a time step below half the first");
  } catch (const mpm::SimulationFailure& failure) {
    CHECK(failure.time > (4.0 - 2.0) / 9.81);
    CHECK(failure.time < (4.0 - 2.0) / 9.81 + 0.125);
    CHECK(std::string(failure.what()).find("the time step of Eq. (42) fell to") != std::string::npos);
  }
  slow.control.smallest_step_fraction = 0.4;  // |v| up to 5 m/s, reached after 0.306 s: the run reaches t = 0.25 s
  slow.control.end_time = 0.25;
  CHECK(mpm::run_setup<2>(slow, slow_setup, recorder).final_time == 0.25);
}
