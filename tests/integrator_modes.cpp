/// \file
/// The one-mode analysis of mpm/analysis/mode_analysis.hpp against the real step() of each integrator.
///
/// A bar of N cells held at both ends, one particle per cell at the centres, linear shape functions,
/// c = h = 1, started at rest in the shape of its mode j, v_p = V sin(j pi X_p / N). For this body the
/// transfers of the step map the mode onto itself (paper/10_integrator_analysis.md): projection to the nodes
/// multiplies it by cos(kh/2), the strain rate and the nodal force each by 2 sin(kh/2)/h and the
/// interpolation back by cos(kh/2), k = j pi / N, so that it is a mode of frequency omega = (c/h) sin(kh).
/// The energy (kinetic plus strain) of the particles is then |A^n z0|^2 / 2 per unit mass with the 2x2
/// amplification matrix A of the analysis and z0 = (0, V): the step shares no code with it.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "mpm/analysis/mode_analysis.hpp"
#include "mpm/fast/fast_layer.hpp"
#include "tests/support.hpp"
#include "verification/fitted_order.hpp"
#include "verification/smooth_case.hpp"

namespace {

struct ModeHistory {
  std::vector<double> energy;    ///< kinetic + strain energy of the particles after each step, energy[0] at rest
  std::vector<double> velocity;  ///< velocity of the particle at the mode's crest after each step
};

/// Runs `steps` steps of `integrator` with omega dt = Omega on mode `mode` of a bar of `cells` cells.
template <class Integrator>
ModeHistory run_mode(const Integrator& integrator, int cells, int mode, double Omega, int steps) {
  const std::string scene_text = "[grid]\nlength = [" + std::to_string(cells) + ".0]\ncells = [" + std::to_string(cells) +
                                 "]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n[[body]]\nmin = [0.0]\nmax = [" +
                                 std::to_string(cells) + ".0]\n[[fixed]]\nface = \"xmin\"\ncomponents = [\"x\"]\n"
                                 "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[solver]\nend_time = 1.0\n";
  const auto scene = mpm::testing::scene_from_text(scene_text);
  auto setup = mpm::build_setup<1>(scene);
  const double k = mode * M_PI / cells, omega = std::sin(k), amplitude = 1e-9;
  mpm::Particles<1>& particles = setup.particles;
  int crest = 0;
  for (int p = 0; p < particles.size(); ++p) {
    particles.velocity[p][0] = amplitude * std::sin(k * particles.position[p][0]);
    if (std::abs(particles.velocity[p][0]) > std::abs(particles.velocity[crest][0])) crest = p;
  }
  mpm::LinearShape<1> shape(setup.model.grid);
  shape.initialise(particles);
  mpm::Stencils<1> stencils;
  stencils.resize(particles.size(), shape.capacity());
  mpm::ParticleBodyForces<1> no_body_force;
  no_body_force.per_unit_mass.assign(particles.size(), mpm::Vector<1>::Zero());
  mpm::GridFields<1> grid(setup.model.grid.node_count());
  const mpm::FastKernels kernels;
  mpm::NoPhaseObserver observer;
  ModeHistory history;
  auto record = [&] {
    double energy = 0.0;
    for (int p = 0; p < particles.size(); ++p)
      energy += 0.5 * particles.mass[p] * particles.velocity[p].squaredNorm() +
                0.5 * particles.volume(p) * particles.stress[p](0, 0) * particles.strain[p](0, 0);
    history.energy.push_back(energy);
    history.velocity.push_back(particles.velocity[crest][0]);
  };
  record();
  for (int n = 0; n < steps; ++n) {
    mpm::compute_stencils(shape, particles.position, stencils);
    integrator.step(kernels, setup.model, stencils, no_body_force, Omega / omega, particles, grid, observer);
    record();
    if (history.energy.back() > 1e6 * history.energy.front()) break;  // unstable: stop before it leaves the grid
  }
  return history;
}

/// |A^n z0|^2 / |z0|^2 with z0 = (0, 1): the energy ratio the analysis predicts after n steps.
double predicted_energy_ratio(mpm::ModeScheme scheme, double Omega, double gamma, int steps) {
  Eigen::Vector2d state(0.0, 1.0);
  const Eigen::Matrix2d amplification = mpm::mode_amplification(scheme, Omega, gamma);
  for (int n = 0; n < steps; ++n) state = amplification * state;
  return state.squaredNorm();
}

/// The mean spacing of the sign changes of a sampled signal, in samples (linear interpolation between samples).
double half_period_in_steps(const std::vector<double>& signal) {
  std::vector<double> crossings;
  for (size_t n = 1; n < signal.size(); ++n)
    if ((signal[n - 1] > 0.0) != (signal[n] > 0.0)) crossings.push_back(n - 1 + signal[n - 1] / (signal[n - 1] - signal[n]));
  REQUIRE(crossings.size() >= 3);
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

mpm::NewmarkPredictorCorrector predictor_corrector(double gamma, mpm::NewmarkParticleVelocity velocity) {
  mpm::NewmarkPredictorCorrector integrator;
  integrator.newmark_gamma = gamma;
  integrator.particle_velocity = mpm::newmark_velocity_rule(velocity);
  return integrator;
}

}  // namespace

TEST_CASE("Eq. (32): the energy of one mode over one period, the real step against |A^n z0|^2 and exp(-2 pi (1 - gamma) Omega), gamma 1/2, 0.75, 1") {
  const int cells = 64, mode = 1;
  const double Omega = 0.5 * std::sin(M_PI / cells);  // CFL 1/2 on the first mode
  const int period = static_cast<int>(std::lround(2.0 * M_PI / Omega));
  for (const double gamma : {0.5, 0.75, 1.0}) {
    const auto history = run_mode(predictor_corrector(gamma, mpm::NewmarkParticleVelocity::eq32), cells, mode, Omega, period);
    const double measured = history.energy.back() / history.energy.front();
    const double predicted = predicted_energy_ratio(mpm::ModeScheme::npc_eq32, Omega, gamma, period);
    INFO("gamma ", gamma, ": measured ", measured, ", |A^n z0|^2 ", predicted, ", exp(-2 pi (1-gamma) Omega) ",
         std::exp(-2.0 * M_PI * (1.0 - gamma) * Omega));
    CHECK(measured == doctest::Approx(predicted).epsilon(1e-6));
    CHECK(measured == doctest::Approx(mpm::mode_energy_per_period(mpm::ModeScheme::npc_eq32, Omega, gamma)).epsilon(2e-4));
  }
}

TEST_CASE("Eq. (23), Eq. (19), Eq. (20), Eq. (21), Eq. (22): the Newmark average and forward Euler keep one mode's energy over a period to O(Omega^2), gamma 0.6") {
  const int cells = 64, mode = 1;
  const double Omega = 0.5 * std::sin(M_PI / cells);
  const int period = static_cast<int>(std::lround(2.0 * M_PI / Omega));
  mpm::ForwardEuler euler;
  const auto euler_history = run_mode(euler, cells, mode, Omega, period);
  const auto average_history = run_mode(predictor_corrector(0.6, mpm::NewmarkParticleVelocity::average), cells, mode, Omega, period);
  CHECK(euler_history.energy.back() / euler_history.energy.front() ==
        doctest::Approx(predicted_energy_ratio(mpm::ModeScheme::forward_euler, Omega, 0.6, period)).epsilon(1e-6));
  CHECK(average_history.energy.back() / average_history.energy.front() ==
        doctest::Approx(predicted_energy_ratio(mpm::ModeScheme::npc_average, Omega, 0.6, period)).epsilon(1e-6));
  // no damping: within the period the energy of (omega d^n, v^n) swings by O(Omega) (the two are staggered in
  // time, so a cross term Omega omega d v enters), and after the period it is back to O(Omega^2)
  for (const auto* history : {&euler_history, &average_history}) {
    double swing = 0.0;
    for (double energy : history->energy) swing = std::max(swing, std::abs(energy / history->energy.front() - 1.0));
    CHECK(swing <= 1.01 * Omega);
    CHECK(std::abs(history->energy.back() / history->energy.front() - 1.0) <= Omega * Omega);
  }
}

TEST_CASE("Eq. (32), Eq. (23): the period of one mode, from the real step's zero crossings, is 2 pi / Omega_bar steps") {
  const int cells = 16, mode = 4;  // kh = pi / 4: omega = sin(pi / 4)
  const double Omega = 0.6;        // a period error of Omega^2 / 24 = 1.5 % for central differences
  for (const auto& [scheme, velocity, gamma] :
       {std::tuple{mpm::ModeScheme::npc_eq32, mpm::NewmarkParticleVelocity::eq32, 0.5},
        std::tuple{mpm::ModeScheme::npc_eq32, mpm::NewmarkParticleVelocity::eq32, 0.75},
        std::tuple{mpm::ModeScheme::npc_average, mpm::NewmarkParticleVelocity::average, 0.6}}) {
    const auto history = run_mode(predictor_corrector(gamma, velocity), cells, mode, Omega, 200);
    const double predicted = M_PI / mpm::mode_phase_per_step(scheme, Omega, gamma);
    INFO("gamma ", gamma, ": half period ", half_period_in_steps(history.velocity), " steps, predicted ", predicted,
         ", exact mode ", M_PI / Omega);
    CHECK(half_period_in_steps(history.velocity) == doctest::Approx(predicted).epsilon(2e-3));
  }
  mpm::ForwardEuler euler;
  const auto history = run_mode(euler, cells, mode, Omega, 200);
  CHECK(half_period_in_steps(history.velocity) ==
        doctest::Approx(M_PI / mpm::mode_phase_per_step(mpm::ModeScheme::forward_euler, Omega, 0.5)).epsilon(2e-3));
  CHECK(std::abs(half_period_in_steps(history.velocity) / (M_PI / Omega) - 1.0) > 0.01);  // the period error is there
}

TEST_CASE("Eq. (32), Eq. (23), Eq. (19), Eq. (20), Eq. (21), Eq. (22): the highest mode is stable just below the analysis' limit and grows just above it") {
  const int cells = 16, mode = 8;  // kh = pi / 2: omega = c / h, so Omega = CFL
  auto growth = [&](const auto& integrator, double Omega) {
    const auto history = run_mode(integrator, cells, mode, Omega, 3000);
    double largest = 0.0;
    for (double energy : history.energy) largest = std::max(largest, energy / history.energy.front());
    return largest;
  };
  for (const double gamma : {0.5, 0.75}) {
    const double limit = mpm::mode_stability_limit(mpm::ModeScheme::npc_eq32, gamma);
    CHECK(growth(predictor_corrector(gamma, mpm::NewmarkParticleVelocity::eq32), 0.99 * limit) <= 1e3);
    CHECK(growth(predictor_corrector(gamma, mpm::NewmarkParticleVelocity::eq32), 1.01 * limit) >= 1e3);
  }
  CHECK(growth(predictor_corrector(0.6, mpm::NewmarkParticleVelocity::average), 1.99) <= 1e3);
  CHECK(growth(predictor_corrector(0.6, mpm::NewmarkParticleVelocity::average), 2.01) >= 1e3);
  CHECK(growth(mpm::ForwardEuler{}, 1.99) <= 1e3);
  CHECK(growth(mpm::ForwardEuler{}, 2.01) >= 1e3);
}

TEST_CASE("Eq. (23): the Newmark average on the small-amplitude vibrating bar: velocity second order at fixed CFL, the period's energy to O(dt^2)") {
  const verification::BarScene bar(mpm::testing::source_path("scenes/vibrating_bar.toml"));
  std::vector<int> cells{32, 64, 128, 256};
  std::vector<double> average_error, eq32_error;
  for (int n : cells) {
    verification::BarCase average{"linear", "npc", n, 1, 0.5, 1e-6, {"solver.npc_velocity=\"average\""}};
    verification::BarCase eq32{"linear", "npc", n, 1, 0.5, 1e-6, {}};
    const auto result = verification::run_bar(bar, average, nullptr);
    REQUIRE_FALSE(result.failed);
    average_error.push_back(result.velocity_error);
    eq32_error.push_back(verification::run_bar(bar, eq32, nullptr).velocity_error);
    // Omega = CFL sin(pi / 2n) of the first mode (paper/10_integrator_analysis.md): the energy after the period within Omega^2
    const double Omega = 0.5 * std::sin(M_PI / (2.0 * n));
    INFO(n, " cells: energy after one period ", result.energy_ratio, ", Omega^2 ", Omega * Omega);
    CHECK(std::abs(result.energy_ratio - 1.0) <= Omega * Omega);
  }
  const double average_order = verification::fitted_order(cells, average_error, 3);
  const double eq32_order = verification::fitted_order(cells, eq32_error, 3);
  INFO("velocity error ", average_error[0], " -> ", average_error.back(), " (order ", average_order, "); Eq. (32) ", eq32_error[0], " -> ",
       eq32_error.back(), " (order ", eq32_order, ")");
  CHECK(average_order >= 1.8);
  CHECK(eq32_order <= 1.2);
  CHECK(average_error.back() < 0.1 * eq32_error.back());
}

TEST_CASE("Eq. (19), Eq. (20), Eq. (21), Eq. (22): forward Euler's velocity on the vibrating bar: first order against v(t), second against v(t + dt/2)") {
  const verification::BarScene bar(mpm::testing::source_path("scenes/vibrating_bar.toml"));
  std::vector<int> cells{32, 64, 128, 256};
  std::vector<double> at_t, at_own_time;
  for (int n : cells) {
    const auto result = verification::run_bar(bar, verification::BarCase{"linear", "fe", n, 1, 0.5, 1e-6, {}}, nullptr);
    REQUIRE_FALSE(result.failed);
    at_t.push_back(result.velocity_error);
    at_own_time.push_back(result.velocity_error_own_time);
  }
  const double order_t = verification::fitted_order(cells, at_t, 3), order_own = verification::fitted_order(cells, at_own_time, 3);
  INFO("at t: ", at_t[0], " -> ", at_t.back(), " (order ", order_t, "); at t + dt/2: ", at_own_time[0], " -> ", at_own_time.back(), " (order ", order_own, ")");
  CHECK(order_t <= 1.2);
  CHECK(order_own >= 1.8);
  CHECK(at_own_time.back() < 0.1 * at_t.back());
}

TEST_CASE("Eq. (16), Eq. (20), Eq. (23), Eq. (33): each scene's variant words become the integrator's types") {
  auto scene = [](std::vector<std::string> settings) {
    return mpm::load_scene(mpm::testing::source_path("scenes/dyka_bar.toml"), settings);
  };
  const mpm::UpdateStressLast usl = mpm::stress_last_integrator(scene({"solver.stress_update=\"usl\""}));
  const mpm::UpdateStressLast musl = mpm::stress_last_integrator(
      scene({"solver.stress_update=\"musl\"", "solver.fe_position_velocity=\"start\"", "solver.flip_fraction=0.9"}));
  CHECK(std::holds_alternative<mpm::UslMomentumK1>(usl.stress_velocity));
  CHECK(std::holds_alternative<mpm::MuslMomentumK1>(musl.stress_velocity));
  CHECK(std::holds_alternative<mpm::EulerMoveWithVelocityK1>(usl.position_velocity));
  CHECK(std::holds_alternative<mpm::EulerMoveWithVelocityK>(musl.position_velocity));
  CHECK(std::holds_alternative<mpm::FlipVelocity>(usl.particle_velocity));
  CHECK(std::get<mpm::PicFlipBlend>(musl.particle_velocity).flip_fraction == 0.9);
  const mpm::ForwardEuler fe = mpm::fe_integrator(scene({"solver.fe_position_velocity=\"start\""}));
  CHECK(std::holds_alternative<mpm::EulerMoveWithVelocityK>(fe.position_velocity));
  const mpm::NewmarkPredictorCorrector npc = mpm::npc_integrator(
      scene({"solver.npc_position_velocity=\"predicted\"", "solver.npc_velocity=\"average\""}));
  CHECK(std::holds_alternative<mpm::NewmarkMoveWithVelocityPred>(npc.position_velocity));
  CHECK(std::holds_alternative<mpm::NewmarkAverageVelocity>(npc.particle_velocity));
}

TEST_CASE("Eq. (32) against a PIC/FLIP blend: on the smooth first mode NPC damps as forward Euler with flip fraction 1 - 4 (1 - gamma) CFL^2 cos^2(kh/2), 1/2 only at CFL 1/2") {
  // paper/10_integrator_analysis.md, "Eq. (32) against a PIC/FLIP blend": per step Eq. (32) keeps 1 - (1 - gamma) Omega^2
  // of a mode's energy, Omega = CFL sin(kh), and the blend 1 - (1 - alpha) sin^2(kh/2) (linear shapes, 1 ppc); equal for
  // alpha = 1 - 4 (1 - gamma) CFL^2 cos^2(kh/2). The first mode of the bar, kh = pi / 2n, over one period.
  const verification::BarScene bar(mpm::testing::source_path("scenes/vibrating_bar.toml"));
  const int n = 32;
  const double c2 = std::pow(std::cos(M_PI / (4.0 * n)), 2);
  // the decay exponent over the period, -ln(E(T)/E(0)): the per-step losses add up in it
  auto loss = [&](const std::string& integrator, double cfl, std::vector<std::string> settings) {
    const auto result = verification::run_bar(bar, {"linear", integrator, n, 1, cfl, 1e-6, std::move(settings)}, nullptr);
    REQUIRE_FALSE(result.failed);
    return -std::log(result.energy_ratio);
  };
  for (const double cfl : {0.25, 0.5}) {
    const double alpha = 1.0 - 4.0 * 0.5 * cfl * cfl * c2;
    const double npc = loss("npc", cfl, {}), blend = loss("fe", cfl, {"solver.flip_fraction=" + std::to_string(alpha)});
    INFO("CFL ", cfl, ": NPC's decay exponent ", npc, ", FE with flip fraction ", alpha, ": ", blend);
    CHECK(npc > 0.01);
    CHECK(std::abs(blend - npc) <= 0.02 * npc);
  }
  // at CFL 1/4 the 50 % blend is no match: it loses (1 - 0.5) / (1 - alpha) = 4 times as much to leading order
  const double npc = loss("npc", 0.25, {}), half = loss("fe", 0.25, {"solver.flip_fraction=0.5"});
  INFO("CFL 0.25: NPC's decay exponent ", npc, ", the 50 % blend's ", half);
  CHECK(std::abs(half / npc - 4.0 / c2) <= 0.02 * 4.0);
}
