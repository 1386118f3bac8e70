/// \file
/// The solver's own stopwatch: wall time spent in each part of the time step, summed over a run (written to
/// run.json as `phase_seconds`; `make bench` charts the shares). It times the named phases of
/// mpm/core/step_phases.hpp, each charged to its TimedPart; the integrators know nothing of it.
#pragma once
#include <doctest/doctest.h>

#include <array>
#include <chrono>

#include "mpm/core/step_phases.hpp"

namespace mpm {

struct PhaseTimers {
  using Clock = std::chrono::steady_clock;
  std::array<double, timed_part_count> seconds{};  ///< wall seconds per TimedPart
  Clock::time_point last = Clock::now();

  /// Starts timing from now (what came before counts for no part).
  void restart() { last = Clock::now(); }
  /// Adds the time since the last lap (or restart) to the part of the step `phase` belongs to.
  void lap(Phase phase) {
    const Clock::time_point now = Clock::now();
    seconds[static_cast<int>(phase_info(phase).part)] += std::chrono::duration<double>(now - last).count();
    last = now;
  }
};

TEST_CASE("PhaseTimers: a phase's time goes to its part of the step and nowhere else") {
  PhaseTimers timers;
  timers.restart();
  const PhaseTimers::Clock::time_point start = PhaseTimers::Clock::now();
  while (PhaseTimers::Clock::now() == start) {
  }
  timers.lap(Phase::corrector);  // charged to "grid"
  for (int part = 0; part < timed_part_count; ++part)
    CHECK((timers.seconds[part] > 0.0) == (part == static_cast<int>(TimedPart::grid)));
}

}  // namespace mpm
