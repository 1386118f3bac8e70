// Compiles the doctests of the parallel loops and the scatter (core/) and of the loop's survey pass (analysis/)
// into the test program.
#include "mpm/analysis/particle_survey.hpp"
#include "mpm/core/parallel.hpp"
#include "mpm/core/scatter.hpp"
