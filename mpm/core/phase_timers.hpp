/// \file
/// The solver's own stopwatch: wall time spent in each phase of the time step, summed over a run
/// (written to run.json; `make bench` charts the shares).
#pragma once
#include <array>
#include <chrono>

namespace mpm {

/// The phases of a step, in the order the loop runs them.
enum class Phase { stencils, p2g, stress, forces, grid, g2p, checks, output };
inline constexpr int phase_count = 8;
inline const char* phase_name(int phase) {
  static const char* names[phase_count] = {"stencils", "p2g", "stress", "forces", "grid", "g2p", "checks", "output"};
  return names[phase];
}

struct PhaseTimers {
  using Clock = std::chrono::steady_clock;
  std::array<double, phase_count> seconds{};  ///< wall seconds per phase
  Clock::time_point last = Clock::now();

  /// Starts timing from now (what came before counts for no phase).
  void restart() { last = Clock::now(); }
  /// Adds the time since the last lap (or restart) to `phase`.
  void lap(Phase phase) {
    const Clock::time_point now = Clock::now();
    seconds[static_cast<int>(phase)] += std::chrono::duration<double>(now - last).count();
    last = now;
  }
};

}  // namespace mpm
