/// \file
/// The `mpm` command.
///
///   mpm run SCENE.toml [--out DIR] [--set KEY=VALUE]... [--threads N] [--max-memory SIZE] [--max-steps N] [--force]
///       Runs a scene on N cores (default: all; the results are the same bits on any number); writes observers.csv, energy.csv, snapshots and run.json to DIR
///       (default `runs/<scene name>`; mpm/cli/run_command.hpp). Exit codes: 0 done, 2 bad scene or option (nothing written),
///       3 the method failed during the run or a file could not be written (one line on stderr;
///       what was written is kept), 128 + N when signal N (SIGINT, SIGTERM) stopped it. A scene whose estimated memory exceeds --max-memory SIZE (bytes, or 512M, 4G; default
///       half the machine's memory) or whose end_time / dt exceeds --max-steps (default 1e7;
///       --force lifts it) is a bad scene.
///   mpm run SCENE.toml --print-scene [--set KEY=VALUE]...
///       Prints the resolved scene (every key, defaults filled in) and exits 0 without running.
///   mpm plot RUN_DIR
///       Draws the run's observers (beside exact.csv when the scene names an exact solution) and
///       energy balance into RUN_DIR/observers.png and energy.png (mpm/cli/plot_command.hpp).
///   mpm stability [--shape S] [--integrator I] [--newmark-gamma G] [--npc-velocity V] [--ppc N] [--lme-gamma G] [--dim D] ...
///       Prints the largest stable CFL of a method from its own linearised step (mpm/cli/stability_command.hpp).
///   mpm exact SCENE.toml --at X[,Y] (--times T0:DT:T1 | --times-file FILE) [--strain small|finite] [--set KEY=VALUE]...
///       Prints the scene's exact solution at material points and times, without running (mpm/cli/exact_command.hpp).
///   mpm compare RESULT.csv SCENE.toml --at X[,Y] --column COL=QUANTITY [...] [--tolerance TOL] [--plot FILE.png]
///       Scores another code's CSV against the exact solution, Eq. (43); exit 0/1 within/above TOL
///       (mpm/cli/compare_command.hpp).
///   mpm --version
///       Prints the version: the project's version and `git describe` at build time (mpm/cli/version.cmake).
///   mpm --help, mpm run --help, mpm exact --help, mpm compare --help, mpm shape --help, mpm plot --help,
///   mpm stability --help (mpm/cli/help.hpp)
///   mpm shape --dim 1|2 --kind linear|ugimp|lme|bspline2|bspline3 --at X[,Y] [--at ...] [--gamma G] [--cell-size H]
///             [--particle-size S] [--tol T]
///       Evaluates a shape function on an unbounded uniform grid (nodes at integer multiples of
///       the cell size) and prints CSV: point,node_x[,node_y],N,dN_dx[,dN_dy].
///
/// Sample run (measured on the 2-core development machine; the wall time varies):
///   $ build/bin/mpm run scenes/dyka_bar.toml --set grid.cells=[160]
///   Dyka bar: 2428 steps to t = 0.0002 s, 160 particles, 0.0219 s wall, 1.77e+07 particle-steps/s
///   wrote runs/dyka_bar
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "mpm/cli/compare_command.hpp"
#include "mpm/cli/exact_command.hpp"
#include "mpm/cli/help.hpp"
#include "mpm/cli/plot_command.hpp"
#include "mpm/cli/shape_command.hpp"
#include "mpm/cli/stability_command.hpp"
#include "mpm/cli/run_command.hpp"
#include "mpm/version.hpp"  // generated at build time (mpm/cli/version.cmake): MPM_VERSION

namespace {

const char* usage =
    "usage: mpm run SCENE.toml [--out DIR] [--set KEY=VALUE]... [--threads N] [--print-scene]\n"
    "                [--max-memory BYTES|<n>G] [--max-steps N] [--force]\n"
    "       mpm exact SCENE.toml [--set KEY=VALUE]... --at X[,Y] [--at ...] (--times T0:DT:T1 | --times-file FILE)\n"
    "                 [--strain small|finite]\n"
    "       mpm compare RESULT.csv SCENE.toml --at X[,Y] --column COL=QUANTITY [--column ...] [--time-column NAME]\n"
    "                   [--tolerance TOL] [--plot FILE.png] [--set KEY=VALUE]... [--strain small|finite]\n"
    "       mpm shape --dim 1|2 --kind linear|ugimp|lme|bspline2|bspline3 --at X[,Y] [--at ...] [--gamma G] [--cell-size H]\n"
    "                 [--particle-size S] [--tol T]\n"
    "       mpm plot RUN_DIR\n"
    "       mpm stability [--shape S] [--integrator I] [--newmark-gamma G] [--npc-velocity V] [--ppc N] [--lme-gamma G] [--dim D]\n"
    "       mpm --version | mpm --help | mpm COMMAND --help\n";

/// Standard output flushed and closed: a full disk or a closed pipe shows here, after the command said
/// everything (exit 3 in place of 0, and of compare's 1).
int check_standard_output(int code) {
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) || std::fclose(stdout) != 0;
  if (!failed || (code != 0 && code != 1)) return code;
  std::cerr << "error: standard output: cannot write: " << std::strerror(errno) << "\n";
  return 3;
}

int dispatch(const std::vector<std::string>& arguments, const mpm::io::RunIdentity& identity) {
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (arguments[0] == "plot") return mpm::cli::plot_command(rest, std::cout, std::cerr);
  if (arguments[0] == "exact") return mpm::cli::exact_command(rest, std::cout, std::cerr);
  if (arguments[0] == "compare") return mpm::cli::compare_command(rest, std::cout, std::cerr);
  if (arguments[0] == "shape") return mpm::cli::shape_command(rest, std::cout, std::cerr);
  if (arguments[0] == "stability") return mpm::cli::stability_command(rest, std::cout, std::cerr);
  if (arguments[0] == "run") {
    mpm::cli::RunRequest request;
    request.identity = identity;
    const auto code = mpm::cli::read_run_options(rest, request, std::cout, std::cerr);
    return code ? *code : mpm::cli::run_command(request);
  }
  std::cerr << "error: " << arguments[0] << ": unknown command\n" << usage;
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.empty()) {
    std::cerr << usage;
    return 2;
  }
  mpm::io::RunIdentity identity;  // the version and command line written into run.json
  identity.version = MPM_VERSION;
  identity.command_line.assign(argv, argv + argc);
  if (arguments[0] == "--version" || arguments[0] == "version") {
    if (arguments.size() > 1) {
      std::cerr << "error: --version: takes no argument\n";
      return 2;
    }
    std::cout << "mpm " << MPM_VERSION << "\n";
    return check_standard_output(0);
  }
  if (arguments[0] == "help" || mpm::cli::asks_for_help(arguments)) {
    std::cout << mpm::cli::command_help(arguments.size() > 1 && arguments[0] == "help" ? arguments[1] : arguments[0]);
    return check_standard_output(0);
  }
  int code = 3;
  try {  // validation refuses bad input first; this only keeps a defect from ending in a signal
    code = dispatch(arguments, identity);
  } catch (const std::bad_alloc&) {
    std::cerr << "failure: out of memory (the scene's estimate was below --max-memory; please report it)\n";
  } catch (const std::exception& defect) {
    std::cerr << "failure: internal error: " << defect.what() << " (please report it)\n";
  }
  return check_standard_output(code);
}
