/// \file
/// What a shape function tells about its own work: stencil sizes and, for LME, Newton iterations.
///
/// The fast layer computes the stencils on every core at once, so each thread counts into its own slot
/// (worker_index(), 0 in a serial run; a cache line apart, so that the threads do not slow each other down); the
/// totals add the slots.
#pragma once
#include <algorithm>
#include <array>

#include "mpm/core/worker_index.hpp"

namespace mpm {

class ShapeDiagnostics {
 public:
  void record(int neighbours, int newton_iterations = 0) {
    Slot& slot = slots_[std::min(worker_index(), slot_count - 1)];
    ++slot.evaluations;
    slot.neighbours_total += neighbours;
    slot.neighbours_max = std::max(slot.neighbours_max, neighbours);
    slot.newton_iterations_total += newton_iterations;
    slot.newton_iterations_max = std::max(slot.newton_iterations_max, newton_iterations);
  }
  long evaluations() const { return total(&Slot::evaluations); }                          ///< particle-steps evaluated
  long neighbours_total() const { return total(&Slot::neighbours_total); }                ///< sum of stencil sizes
  int neighbours_max() const { return largest(&Slot::neighbours_max); }
  long newton_iterations_total() const { return total(&Slot::newton_iterations_total); }  ///< LME only
  int newton_iterations_max() const { return largest(&Slot::newton_iterations_max); }     ///< LME only
  double neighbours_mean() const { return evaluations() ? double(neighbours_total()) / evaluations() : 0.0; }
  double newton_iterations_mean() const { return evaluations() ? double(newton_iterations_total()) / evaluations() : 0.0; }

 private:
  struct alignas(64) Slot {
    long evaluations = 0, neighbours_total = 0, newton_iterations_total = 0;
    int neighbours_max = 0, newton_iterations_max = 0;
  };
  static constexpr int slot_count = 64;
  long total(long Slot::*field) const {
    long sum = 0;
    for (const Slot& slot : slots_) sum += slot.*field;
    return sum;
  }
  int largest(int Slot::*field) const {
    int most = 0;
    for (const Slot& slot : slots_) most = std::max(most, slot.*field);
    return most;
  }
  std::array<Slot, slot_count> slots_{};
};

}  // namespace mpm
