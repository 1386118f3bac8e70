/// \file
/// What a shape function tells about its own work: stencil sizes and, for LME, Newton iterations.
#pragma once
#include <algorithm>

namespace mpm {

struct ShapeDiagnostics {
  long evaluations = 0;             ///< particle-steps evaluated
  long neighbours_total = 0;        ///< sum of stencil sizes
  int neighbours_max = 0;
  long newton_iterations_total = 0; ///< LME only
  int newton_iterations_max = 0;    ///< LME only

  void record(int neighbours, int newton_iterations = 0) {
    ++evaluations;
    neighbours_total += neighbours;
    neighbours_max = std::max(neighbours_max, neighbours);
    newton_iterations_total += newton_iterations;
    newton_iterations_max = std::max(newton_iterations_max, newton_iterations);
  }
  double neighbours_mean() const { return evaluations ? double(neighbours_total) / evaluations : 0.0; }
  double newton_iterations_mean() const { return evaluations ? double(newton_iterations_total) / evaluations : 0.0; }
};

}  // namespace mpm
