/// \file
/// The `mpm` command: `mpm COMMAND ...` runs the command of mpm/cli/COMMAND_command.hpp, each parsing its own
/// options (mpm/cli/options.hpp); `mpm --help` prints them all (help.hpp). Whatever the command, standard output
/// is checked when it ends: exit 3 `cannot write` if it failed.
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "mpm/cli/help.hpp"  // and through it every command
#include "mpm/cli/version.hpp"  // defined by a unit generated at build time (mpm/cli/version.cmake)

namespace {

const char* usage =
    "usage: mpm run SCENE.toml | mpm exact SCENE.toml | mpm compare RESULT.csv SCENE.toml | mpm plot RUN_DIR\n"
    "       mpm shape | mpm stability | mpm study STUDY.toml | mpm trace SCENE.toml --step N\n"
    "       [OPTIONS]: mpm COMMAND --help\n"
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

/// Runs the command `arguments` name; its exit code.
int dispatch(const std::vector<std::string>& arguments, const mpm::io::RunIdentity& identity) {
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (arguments[0] == "plot") return mpm::cli::plot_command(rest, std::cout, std::cerr);
  if (arguments[0] == "exact") return mpm::cli::exact_command(rest, std::cout, std::cerr);
  if (arguments[0] == "compare") return mpm::cli::compare_command(rest, std::cout, std::cerr);
  if (arguments[0] == "shape") return mpm::cli::shape_command(rest, std::cout, std::cerr);
  if (arguments[0] == "stability") return mpm::cli::stability_command(rest, std::cout, std::cerr);
  if (arguments[0] == "study") return mpm::cli::study_command(rest, std::cout, std::cerr);
  if (arguments[0] == "trace") return mpm::cli::trace_command(rest, std::cout, std::cerr);
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
  identity.version = mpm::cli::version();
  identity.command_line.assign(argv, argv + argc);
  if (arguments[0] == "--version" || arguments[0] == "version") {
    if (arguments.size() > 1) {
      std::cerr << "error: --version: takes no argument\n";
      return 2;
    }
    std::cout << "mpm " << mpm::cli::version() << "\n";
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
