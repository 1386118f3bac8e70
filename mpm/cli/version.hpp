/// \file
/// `mpm --version` and run.json's version: defined in a unit of its own that mpm/cli/version.cmake writes at build
/// time (the build folder's generated/mpm/version.cpp), so that a new version recompiles one line, not main.cpp.
#pragma once

namespace mpm::cli {
/// The version of this build, "0.1.0+git.41aa0a0" ("-dirty" appended when the tree had changes), "0.1.0+unknown"
/// outside a git checkout.
const char* version();
}  // namespace mpm::cli
