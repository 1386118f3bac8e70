// Compiles the doctests of the parallel loops (core/), of the fast layer's scatter (fast/) and of the loop's survey
// pass (analysis/) into the test program.
#include "mpm/analysis/particle_survey.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/fast/scatter.hpp"
