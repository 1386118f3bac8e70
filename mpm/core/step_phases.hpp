/// \file
/// The named phases of a time step, each with the paper's equation it computes. An integrator's step() calls
/// `observer.after(phase, particles, grid)` after each of its phases, which it numbers in its `phases` list (phase
/// 0: the reset; the book's tables and `mpm trace` use the same numbers), and knows nothing more about who watches:
/// the loop's stopwatch (PhaseTimers, mpm/core/phase_timers.hpp) and `mpm trace` (mpm/cli/trace_command.hpp) are
/// two such observers.
#pragma once
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

namespace mpm {

/// A phase of the time step, in the order the integrators and the loop (mpm::Simulation) run them.
enum class Phase {
  reset,             ///< the nodal fields set to zero (GridFields::reset)
  mass_momentum,     ///< P2G: \f$ m_I \f$, Eq. (13), and \f$ \mathbf p_I^k = \sum_p N_{Ip} m_p \mathbf v_p^k \f$, Eq. (21)'s
  fixed_momentum,    ///< the fixed components of \f$ \mathbf p_I^k \f$ set to zero, Eq. (5)
  velocity_k,        ///< \f$ \mathbf v_I^k = \mathbf p_I^k / m_I \f$, Eqs. (20)-(21)
  stress,            ///< strain rate, Eq. (16); density, Eq. (17); stress, Eq. (3)
  forces,            ///< \f$ \mathbf f_I \f$, Eqs. (14)-(15); the fixed components moved into reactions
  momentum_balance,  ///< \f$ \mathbf p_I^{k+1} = \mathbf p_I^k + \Delta t\, \mathbf f_I \f$, Eq. (12)
  euler_update,      ///< forward Euler's G2P: Eqs. (18)-(19), (21)-(22) (Eq. (20) under `start`), with (12)'s v_I^{k+1}
  reprojection,      ///< MUSL: \f$ \mathbf p_I^{k+1} = \sum_p N_{Ip} m_p \mathbf v_p^{k+1} \f$, held at the walls
  velocity_k1,       ///< \f$ \mathbf v_I^{k+1} = \mathbf p_I^{k+1} / m_I \f$ (USL, MUSL), Eq. (21)'s
  mass_predictor,    ///< \f$ m_I \f$, Eq. (13), and the predictor \f$ \mathbf v_I^{pred} \f$, Eqs. (26)-(29)
  fixed_predictor,   ///< the fixed components of \f$ \mathbf v_I^{pred} \f$ (and \f$ \mathbf p_I^k \f$) set to zero, Eq. (5)
  corrector,         ///< \f$ \mathbf v_I^{k+1} = \mathbf v_I^{pred} + \gamma \Delta t\, \mathbf f_I / m_I \f$, Eq. (30)
  newmark_update,    ///< the predictor-corrector's particle update, Eqs. (31)-(33)
  stencils,          ///< the loop's: \f$ N_{Ip} \f$ and \f$ \nabla N_{Ip} \f$ at \f$ \mathbf x_p^k \f$
  body_force,        ///< the loop's: \f$ \mathbf b_p \f$ of Eq. (15)
  checks,            ///< the loop's: the balances and the health of the particles
  output             ///< the loop's: samples and snapshots
};
inline constexpr int step_phase_count = 18;

/// What the stopwatch charges a phase to: the parts of the step that run.json's `phase_seconds` names.
enum class TimedPart { stencils, p2g, stress, forces, grid, g2p, checks, output };
inline constexpr int timed_part_count = 8;

/// A phase as a reader sees it: its name, the paper's equations it computes ("-": none), what it does, and the part
/// of the step its time is charged to. This table is the one vocabulary of the step: `mpm trace` prints its equations
/// in each phase's heading, and the book's worked example labels every number with equations of its phase's row
/// (tests/trace_worked_example.py holds the book to it). `of_step`: run inside an integrator's step() (false: by the loop around it).
struct PhaseInfo {
  const char* name;
  const char* equation;
  const char* what;
  TimedPart part;
  bool of_step;
};

/// The description of `phase`.
inline const PhaseInfo& phase_info(Phase phase) {
  static const PhaseInfo table[step_phase_count] = {
      {"reset", "-", "nodal fields set to zero; the particles at t_k", TimedPart::grid, true},
      {"mass_momentum", "(13) (21)", "m_I = sum_p N_Ip m_p and p_I^k = sum_p N_Ip m_p v_p^k", TimedPart::p2g, true},
      {"fixed_momentum", "(5)", "fixed components of p_I^k set to zero", TimedPart::grid, true},
      {"velocity_k", "(20)-(21)", "v_I^k = p_I^k / m_I", TimedPart::grid, true},
      {"stress", "(16) (17) (3)", "strain rate and strain; density; stress", TimedPart::stress, true},
      {"forces", "(14)-(15)", "f_I = f_I^int + f_I^ext; fixed components moved into reactions r_I",
       TimedPart::forces, true},
      {"momentum_balance", "(12)", "p_I^{k+1} = p_I^k + dt f_I", TimedPart::grid, true},
      {"euler_update", "(12) (18)-(19) (21)-(22)",
       "a_I = f_I / m_I; v_I^{k+1} = p_I^{k+1} / m_I; v_p += dt sum_I N_Ip a_I; x_p += dt sum_I N_Ip v_I",
       TimedPart::g2p, true},
      {"reprojection", "-", "MUSL: p_I^{k+1} = sum_p N_Ip m_p v_p^{k+1}, fixed components set to zero",
       TimedPart::p2g, true},
      {"velocity_k1", "(21)", "v_I^{k+1} = p_I^{k+1} / m_I", TimedPart::grid, true},
      {"mass_predictor", "(13) (26)-(29)",
       "m_I = sum_p N_Ip m_p; v_I^pred = sum_p N_Ip m_p (v_p^k + (1 - gamma) dt a_p^k) / m_I; p_I^k", TimedPart::p2g,
       true},
      {"fixed_predictor", "(5)", "fixed components of v_I^pred and p_I^k set to zero", TimedPart::grid, true},
      {"corrector", "(30)", "v_I^{k+1} = v_I^pred + gamma dt f_I / m_I", TimedPart::grid, true},
      {"newmark_update", "(31)-(33)",
       "a_p^{k+1} = sum_I N_Ip f_I / m_I; v_p^{k+1} = v_p^k + dt a_p^{k+1}; "
       "x_p^{k+1} = x_p^k + dt sum_I N_Ip v_I + dt^2 / 2 a_p^{k+1}",
       TimedPart::g2p, true},
      {"stencils", "-", "N_Ip and grad N_Ip at x_p^k", TimedPart::stencils, false},
      {"body_force", "(15)", "b_p", TimedPart::forces, false},
      {"checks", "-", "balances and health of the particles", TimedPart::checks, false},
      {"output", "-", "samples and snapshots", TimedPart::output, false}};
  return table[static_cast<int>(phase)];
}

/// The name run.json gives a part of the step (`phase_seconds`).
inline const char* timed_part_name(int part) {
  static const char* names[timed_part_count] = {"stencils", "p2g", "stress", "forces", "grid", "g2p", "checks",
                                                "output"};
  return names[part];
}

/// An observer that watches nothing: for a step() run outside the loop (tests, the linearised step).
struct NoPhaseObserver {
  template <class Particles, class Fields>
  void after(Phase /*phase*/, const Particles& /*particles*/, const Fields& /*grid*/) {}
};

/// An observer that records the phases in the order step() runs them (the tests of the integrators' numbering).
struct PhaseRecorder {
  std::vector<Phase> seen;
  template <class Particles, class Fields>
  void after(Phase phase, const Particles& /*particles*/, const Fields& /*grid*/) {
    seen.push_back(phase);
  }
};

TEST_CASE("Phases: each named once, with its equation, charged to the part of the step it belongs to") {
  for (int a = 0; a < step_phase_count; ++a)
    for (int b = a + 1; b < step_phase_count; ++b)
      CHECK(std::strcmp(phase_info(Phase(a)).name, phase_info(Phase(b)).name) != 0);
  CHECK(std::strcmp(phase_info(Phase::output).name, "output") == 0);  // the table ends with the enum
  CHECK(std::strcmp(phase_info(Phase::corrector).equation, "(30)") == 0);
  CHECK(std::strcmp(phase_info(Phase::momentum_balance).equation, "(12)") == 0);
  CHECK(phase_info(Phase::mass_momentum).part == TimedPart::p2g);
  CHECK(phase_info(Phase::newmark_update).part == TimedPart::g2p);
  CHECK(phase_info(Phase::velocity_k1).part == TimedPart::grid);
  CHECK(!phase_info(Phase::stencils).of_step);
  CHECK(std::strcmp(timed_part_name(static_cast<int>(TimedPart::g2p)), "g2p") == 0);
}

}  // namespace mpm
