/// \file
/// Compiles the doctests of the exact solutions (exact/) into the test program. They share no
/// code with the solver they check.
#include "mpm/exact/bar.hpp"
#include "mpm/exact/column.hpp"
