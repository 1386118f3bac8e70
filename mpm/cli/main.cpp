/// \file
/// The `mpm` command.
///
///   mpm run SCENE.toml [--out DIR] [--set KEY=VALUE]... [--threads N] [--max-memory SIZE] [--max-steps N] [--force]
///       Runs a scene on N cores (default: all; the results are the same bits on any number); writes observers.csv, energy.csv, snapshots and run.json to DIR
///       (default `runs/<scene name>`). Exit codes: 0 done, 2 bad scene or option (nothing written),
///       3 the method failed during the run or a file could not be written (one line on stderr;
///       what was written is kept). A scene whose estimated memory exceeds --max-memory SIZE (bytes, or 512M, 4G; default
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
#include <cmath>
#include <cstdio>
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
#include "mpm/io/exact_series.hpp"
#include "mpm/io/run_writer.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/scene_warnings.hpp"
#include "mpm/run.hpp"
#include "mpm/stability.hpp"
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

/// The version and command line written into run.json.
mpm::io::RunIdentity identity;

template <int Dim>
int run_scene(mpm::io::Scene scene, const std::string& folder, int threads) {
  scene.control.threads = threads;
  const mpm::Setup<Dim> setup = mpm::build_setup<Dim>(scene);
  identity.observed.clear();
  for (size_t k = 0; k < setup.observed.size(); ++k) {
    const int p = setup.observed[k];
    const auto& X = setup.particles.reference_position[p];
    identity.observed.push_back({scene.observers[k].name, setup.particles.id[p], std::vector<double>(X.data(), X.data() + Dim)});
  }
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    std::cerr << mpm::OutputFailure(folder, error.message()).message() << "\n";
    return 3;
  }
  mpm::RunSummary summary;
  try {
    try {
      mpm::io::RunWriter<Dim> writer(folder, scene, setup.observed);
      mpm::io::ExactWriter<Dim> exact_then_writer(folder, scene, setup.particles, writer);
      summary = mpm::run_setup<Dim>(scene, setup, exact_then_writer, &summary);
      exact_then_writer.finish();
      writer.finish();
    } catch (const mpm::SimulationFailure& failure) {
      std::cerr << failure.message() << "\n";
      mpm::io::write_run_json(folder + "/run.json", scene, summary, std::string("failed: ") + failure.what(), setup.particles.size(),
                              identity);
      return 3;
    }
    mpm::io::write_run_json(folder + "/run.json", scene, summary, "done", setup.particles.size(), identity);
  } catch (const mpm::OutputFailure& failure) {
    std::cerr << failure.message() << "\n";
    return 3;
  }
  std::printf("%s: %ld steps to t = %g s, %d particles, %.3g s wall, %.3g particle-steps/s\nwrote %s\n", scene.title.c_str(),
              summary.steps, summary.final_time, setup.particles.size(), summary.wall_seconds,
              summary.particle_steps_per_second, folder.c_str());
  return 0;
}

int run_command(const std::vector<std::string>& arguments) {
  std::string scene_path, folder;
  bool folder_given = false;
  std::vector<std::string> overrides;
  bool print_scene = false;
  mpm::io::Budget budget;
  int threads = 0;
  for (size_t k = 0; k < arguments.size(); ++k) {
    const std::string& argument = arguments[k];
    if ((argument == "--out" || argument == "--set" || argument == "--threads" || argument == "--max-memory" ||
         argument == "--max-steps") &&
        k + 1 >= arguments.size()) {
      std::cerr << "error: " << argument << ": needs a value\n" << usage;
      return 2;
    }
    if (argument == "--out") {
      folder = arguments[++k];
      folder_given = true;
    } else if (argument == "--max-memory") {
      const auto bytes = mpm::io::parse_byte_size(arguments[++k]);
      if (!bytes) {
        std::cerr << "error: --max-memory: '" << arguments[k] << "' is not a size; give bytes or <n>K, <n>M, <n>G, <n>T\n";
        return 2;
      }
      budget.max_bytes = *bytes;
    } else if (argument == "--max-steps") {
      const std::string& text = arguments[++k];
      std::size_t end = 0;
      try {
        budget.max_steps = std::stod(text, &end);
      } catch (const std::exception&) {
        end = 0;
      }
      if (end != text.size() || !(budget.max_steps >= 1.0) || !std::isfinite(budget.max_steps)) {
        std::cerr << "error: --max-steps: '" << text << "' is not a number >= 1\n";
        return 2;
      }
    } else if (argument == "--force") {
      budget.force = true;
    } else if (argument == "--threads") {
      const std::string value = arguments[++k];
      if (value.empty() || value.size() > 4 || value.find_first_not_of("0123456789") != std::string::npos ||
          std::stoi(value) < 1) {
        std::cerr << "error: --threads: expected a whole number of cores >= 1, got '" << value << "'\n" << usage;
        return 2;
      }
      threads = std::stoi(value);
    } else if (argument == "--set") {
      overrides.push_back(arguments[++k]);
    } else if (argument == "--print-scene") {
      print_scene = true;
    } else if (argument.rfind("--set=", 0) == 0) {
      overrides.push_back(argument.substr(6));
    } else if (argument.rfind("--", 0) == 0 || !scene_path.empty()) {
      std::cerr << "error: " << argument << ": unknown option\n" << usage;
      return 2;
    } else {
      scene_path = argument;
    }
  }
  if (scene_path.empty()) {
    std::cerr << "error: run: no scene file given\n" << usage;
    return 2;
  }
  if (folder_given && folder.empty()) {
    std::cerr << "error: --out: empty; give a folder, or leave --out out for runs/<scene name>\n";
    return 2;
  }
  if (folder.empty()) folder = "runs/" + std::filesystem::path(scene_path).stem().string();
  try {
    const mpm::io::Scene scene = mpm::load_scene(scene_path, overrides, budget);
    for (const auto& warning : mpm::io::scene_warnings(scene_path, overrides, scene, mpm::scene_cfl_limit_if_exceeded(scene)))
      std::cerr << warning << "\n";
    if (print_scene) {
      mpm::io::print_resolved_scene(scene, std::cout);
      return 0;
    }
    return scene.dimension == 1 ? run_scene<1>(scene, folder, threads) : run_scene<2>(scene, folder, threads);
  } catch (const mpm::SceneError& error) {
    std::cerr << error.message() << "\n";
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.empty()) {
    std::cerr << usage;
    return 2;
  }
  identity.version = MPM_VERSION;
  identity.command_line.assign(argv, argv + argc);
  if (arguments[0] == "--version" || arguments[0] == "version") {
    if (arguments.size() > 1) {
      std::cerr << "error: --version: takes no argument\n";
      return 2;
    }
    std::cout << "mpm " << MPM_VERSION << "\n";
    return 0;
  }
  if (arguments[0] == "help" || mpm::cli::asks_for_help(arguments)) {
    std::cout << mpm::cli::command_help(arguments.size() > 1 && arguments[0] == "help" ? arguments[1] : arguments[0]);
    return 0;
  }
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  try {  // validation refuses bad input first; this only keeps a defect from ending in a signal
    if (arguments[0] == "plot") return mpm::cli::plot_command(rest, std::cout, std::cerr);
    if (arguments[0] == "exact") return mpm::cli::exact_command(rest, std::cout, std::cerr);
    if (arguments[0] == "compare") return mpm::cli::compare_command(rest, std::cout, std::cerr);
    if (arguments[0] == "run") return run_command(rest);
    if (arguments[0] == "shape") return mpm::cli::shape_command(rest, std::cout, std::cerr);
    if (arguments[0] == "stability") return mpm::cli::stability_command(rest, std::cout, std::cerr);
  } catch (const std::bad_alloc&) {
    std::cerr << "failure: out of memory (the scene's estimate was below --max-memory; please report it)\n";
    return 3;
  } catch (const std::exception& defect) {
    std::cerr << "failure: internal error: " << defect.what() << " (please report it)\n";
    return 3;
  }
  std::cerr << "error: " << arguments[0] << ": unknown command\n" << usage;
  return 2;
}
