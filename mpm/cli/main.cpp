/// \file
/// The `mpm` command: one command per file of mpm/cli/, each parsing its own options with CLI11
/// (mpm/cli/options.hpp) and generating its own help from them; `mpm --help` prints them all.
///   mpm run SCENE.toml      runs a scene into its folder (run_command.hpp)
///   mpm exact SCENE.toml    the scene's exact solution at points and times, without running (exact_command.hpp)
///   mpm compare CSV SCENE   scores another code's CSV against the exact solution, Eq. (43) (compare_command.hpp)
///   mpm shape               a shape function on an unbounded grid (shape_command.hpp)
///   mpm plot RUN_DIR        draws a run with gnuplot (plot_command.hpp)
///   mpm stability           the largest stable CFL of a method from its own linearised step (stability_command.hpp)
///   mpm --version           the project's version and `git describe` at build time (version.cmake)
/// Whatever the command, standard output is checked when it ends: exit 3 `cannot write` if it failed.
///
/// Sample run (measured on the 2-core development machine; the wall time varies):
///   $ build/bin/mpm run scenes/dyka_bar.toml --set grid.cells=[160]
///   Dyka bar: 2428 steps to t = 0.0002 s, 160 particles, 0.0219 s wall, 1.77e+07 particle-steps/s
///   wrote runs/dyka_bar
#include <cerrno>
#include <csignal>
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
#include "mpm/cli/study_command.hpp"
#include "mpm/cli/run_command.hpp"
#include "mpm/version.hpp"  // generated at build time (mpm/cli/version.cmake): MPM_VERSION

namespace {

const char* usage =
    "usage: mpm run SCENE.toml | mpm exact SCENE.toml | mpm compare RESULT.csv SCENE.toml | mpm plot RUN_DIR\n"
    "       mpm shape | mpm stability | mpm study STUDY.toml   [OPTIONS]: mpm COMMAND --help\n"
    "       mpm --version | mpm --help\n";

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
  if (arguments[0] == "study") return mpm::cli::study_command(rest, std::cout, std::cerr);
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
  std::signal(SIGPIPE, SIG_IGN);  // a closed pipe on standard output: a failed write (exit 3), not a silent death
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
