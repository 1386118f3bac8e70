/// \file
/// Compiles the doctests of scene reading, of the run budget and of the `mpm shape` command into the test program.
#include "mpm/cli/shape_command.hpp"
#include "mpm/io/scene.hpp"
#include "mpm/io/scene_file.hpp"
#include "mpm/io/scene_formulas.hpp"
#include "mpm/cli/help.hpp"
#include "mpm/cli/plot_command.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/scene_warnings.hpp"
#include "mpm/io/exact_series.hpp"
#include "mpm/io/scene_budget.hpp"
