/// \file
/// Compiles the doctests of `mpm study` (mpm/study/, mpm/cli/study_command.hpp) into the test program.
#include "mpm/study/study_file.hpp"
#include "mpm/study/process.hpp"
#include "mpm/study/measures.hpp"
#include "mpm/study/cases.hpp"
#include "mpm/study/fits.hpp"
#include "mpm/study/runner.hpp"
#include "mpm/study/write.hpp"
#include "mpm/study/study.hpp"
#include "mpm/cli/study_command.hpp"
