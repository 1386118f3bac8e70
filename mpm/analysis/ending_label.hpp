/// \file
/// The word a CSV cell holds for a run's ending (mpm::Ending, mpm/analysis/verdict.hpp): `done`, `failed` or
/// `stopped`, as `mpm compare` and `mpm study` write it and the scripts read it (verification/verdict_rule.py uses the
/// same three words).
#pragma once
#include <doctest/doctest.h>

#include <string>

#include "mpm/analysis/verdict.hpp"

namespace mpm {

/// The word for `ending` in a CSV cell.
inline const char* ending_label(Ending ending) {
  switch (ending) {
    case Ending::done: return "done";
    case Ending::failed: return "failed";
    case Ending::stopped: return "stopped";
  }
  return "stopped";
}

TEST_CASE("ending_label: each ending's word") {
  CHECK(std::string(ending_label(Ending::done)) == "done");
  CHECK(std::string(ending_label(Ending::failed)) == "failed");
  CHECK(std::string(ending_label(Ending::stopped)) == "stopped");
}

}  // namespace mpm
