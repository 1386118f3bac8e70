// The smooth suite's verdict helpers (verification/smooth_fit.hpp, verification/smooth_crossing_claims.hpp): their
// doctests, next to each helper in its header, compiled here into mpm_tests.
#include <doctest/doctest.h>

#include "verification/smooth_crossing_claims.hpp"
