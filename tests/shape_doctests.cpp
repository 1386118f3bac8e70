/// \file
/// Compiles the doctests of the shape functions (shape/) into the test program.
#include "mpm/shape/bspline.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/lme.hpp"
#include "mpm/shape/ugimp.hpp"
