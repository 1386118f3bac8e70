/// \file
/// Compiles the doctests of the exact solutions (exact/) into the test program. They share no
/// code with the solver they check.
#include "mpm/exact/bar.hpp"
#include "mpm/exact/column.hpp"
#include "mpm/exact/vibrating_bar.hpp"
#include "mpm/exact/vibrating_bar_finite_strain.hpp"
#include "mpm/exact/manufactured.hpp"
