/// \file
/// The help of the `mpm` command: `mpm --help`, `mpm run --help`, `mpm shape --help`, `mpm plot --help`.
/// The scene keys come from the one table of mpm/io/scene_keys.hpp, so the help lists exactly what the
/// parser reads, with the parser's defaults.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/shape_command.hpp"
#include "mpm/cli/stability_command.hpp"
#include "mpm/io/scene_keys.hpp"

namespace mpm::cli {

inline const char* run_usage =
    "usage: mpm run SCENE.toml [--out DIR] [--set KEY=VALUE]... [--threads N] [--print-scene]\n"
    "  Runs a scene and writes observers.csv, energy.csv, exact.csv (when the scene names an exact solution),\n"
    "  snapshot_NNNN.csv/.vtk/.vtp, snapshots.pvd (ParaView time series) and run.json into DIR.\n"
    "  --out DIR          output folder (default runs/<scene file name>)\n"
    "  --set KEY=VALUE    overrides a scene key with a TOML value: --set solver.cfl=0.2,\n"
    "                     --set 'solver.shape=\"lme\"', --set grid.cells=[160], --set 'body[0].max=[1.0]'\n"
    "  --threads N        cores to run on (default: all; the results equal those on one core to 1e-12)\n"
    "  --print-scene      prints the resolved scene (every key, defaults filled in) and exits without running\n"
    "  Warnings (`warning: FILE:LINE: KEY: ...` on stderr) flag a suspicious but valid scene; they never stop a run.\n";

/// `mpm shape`'s usage, its defaults taken from ShapeRequest.
inline std::string shape_usage() {
  const ShapeRequest defaults;
  std::ostringstream out;
  out << "usage: mpm shape --dim 1|2 --kind linear|ugimp|lme|bspline2|bspline3 --at X[,Y] [--at ...] [--gamma G] [--cell-size H]\n"
         "                 [--particle-size S] [--tol T]\n"
         "  Evaluates a shape function on an unbounded uniform grid (nodes at multiples of the cell size) and prints\n"
         "  CSV: point,node_x[,node_y],N,dN_dx[,dN_dy], one row per node of each point's stencil.\n"
      << "  --dim D            1 or 2 (default " << defaults.dimension << ")\n"
      << "  --kind K           linear | ugimp | lme | bspline2 | bspline3 (required)\n"
         "  --at X[,Y]         a point, m; repeat for more points (at least one)\n"
      << "  --gamma G          LME locality gamma, beta = gamma / h^2 (default " << defaults.gamma << ")\n"
      << "  --cell-size H      grid spacing h, m (default " << defaults.cell_size << ")\n"
      << "  --particle-size S  uGIMP particle length 2 l_p, m (default h / 2)\n"
      << "  --tol T            LME support tolerance, in (0, 1) (default " << defaults.tolerance << ")\n";
  return out.str();
}

inline const char* plot_usage =
    "usage: mpm plot RUN_DIR\n"
    "  Draws a run's observer histories (observers.csv, with exact.csv beside them when the scene names an\n"
    "  exact solution) into RUN_DIR/observers.png and its energy balance (energy.csv) into RUN_DIR/energy.png,\n"
    "  with gnuplot.\n";

inline const char* exit_codes =
    "Exit codes:\n"
    "  0  done\n"
    "  2  a bad scene, option or run folder: one line `error: FILE:LINE: KEY: what is wrong`, nothing written\n"
    "  3  the method failed during the run (or gnuplot failed for `mpm plot`): one line on stderr; what was\n"
    "     written so far is kept\n";

/// Every scene key with its default, unit and meaning, one line each.
inline std::string scene_keys_help() {
  std::ostringstream out;
  out << "Scene keys (TOML; body[].min is `min` of every [[body]]; \"per axis\": the default on every axis;\n"
         "`required`: no default; `none`: optional, absent unless given):\n";
  auto default_text = [](const io::SceneKey& key) {
    if (!key.fallback) return std::string(key.optional ? "none" : "required");
    return std::string(key.fallback) + (key.per_axis ? " per axis" : "");
  };
  size_t key_width = 0, default_width = 0, unit_width = 0;
  for (const auto& key : io::scene_keys()) {
    key_width = std::max(key_width, std::string(key.key).size());
    default_width = std::max(default_width, default_text(key).size());
    unit_width = std::max(unit_width, std::string(key.unit).size());
  }
  auto padded = [](std::string text, size_t width) { return text + std::string(width + 2 - text.size(), ' '); };
  out << "  " << padded("key", key_width) << padded("default", default_width) << padded("unit", unit_width) << "meaning\n";
  for (const auto& key : io::scene_keys())
    out << "  " << padded(key.key, key_width) << padded(default_text(key), default_width) << padded(key.unit, unit_width)
        << key.meaning << "\n";
  return out.str();
}

/// `mpm --help`
inline std::string main_help() {
  return std::string("mpm: the Material Point Method with linear, uGIMP and LME shape functions (README.md)\n\n") +
         run_usage + "\n" + shape_usage() + "\n" + plot_usage + "\n" + stability_usage() + "\n" + scene_keys_help() + "\n" + exit_codes;
}

/// The help of one command ("run", "shape", "plot"); the main help for any other.
inline std::string command_help(const std::string& command) {
  if (command == "run") return std::string(run_usage) + "\n" + scene_keys_help() + "\n" + exit_codes;
  if (command == "shape") return shape_usage() + "\n" + exit_codes;
  if (command == "plot") return std::string(plot_usage) + "\n" + exit_codes;
  if (command == "stability") return stability_usage() + "\n" + exit_codes;
  return main_help();
}

/// True if the arguments ask for help (`--help` or `-h` anywhere).
inline bool asks_for_help(const std::vector<std::string>& arguments) {
  return std::any_of(arguments.begin(), arguments.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

TEST_CASE("mpm help: every scene key with its default and unit, and the exit codes") {
  const std::string help = command_help("run");
  for (const auto& key : io::scene_keys()) {
    const std::string name = key.key;
    CAPTURE(name);
    const auto line_start = help.find("\n  " + std::string(key.key) + " ");
    REQUIRE(line_start != std::string::npos);
    const std::string line = help.substr(line_start + 1, help.find('\n', line_start + 1) - line_start - 1);
    CHECK(line.find(key.fallback ? key.fallback : key.optional ? "none" : "required") != std::string::npos);
    CHECK(line.find(std::string("  ") + key.unit + "  ") != std::string::npos);
  }
  for (const std::string command : {"run", "shape", "plot", "stability", ""})
    CHECK(command_help(command).find("  3  the method failed") != std::string::npos);
  CHECK(command_help("shape").find("--tol T            LME support tolerance, in (0, 1) (default 1e-06)") != std::string::npos);
  CHECK(asks_for_help({"--dim", "1", "-h"}));
  CHECK(!asks_for_help({"--dim", "1"}));
}

}  // namespace mpm::cli
