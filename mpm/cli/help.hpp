/// \file
/// The help of the `mpm` command: `mpm --help`, `mpm run --help`, `mpm exact --help`, `mpm compare --help`,
/// `mpm shape --help`, `mpm plot --help`.
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

#include <cstdlib>
#include <fstream>

namespace mpm::cli {

inline const char* run_usage =
    "usage: mpm run SCENE.toml [--out DIR] [--set KEY=VALUE]... [--threads N] [--print-scene]\n"
    "  Runs a scene and writes observers.csv, energy.csv, exact.csv (when the scene names an exact solution),\n"
    "  snapshot_NNNN.csv/.vtk/.vtp, snapshots.pvd (ParaView time series) and run.json into DIR.\n"
    "  --out DIR          output folder (default runs/<scene file name>)\n"
    "  --set KEY=VALUE    overrides a scene key with a TOML value: --set solver.cfl=0.2,\n"
    "                     --set 'solver.shape=\"lme\"', --set grid.cells=[160], --set 'body[0].max=[1.0]'\n"
    "  --threads N        cores to run on (default: all; the results are the same bits on any number)\n"
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
    "  with gnuplot. Either CSV may be missing (a folder of another code's observers.csv): what is there is drawn.\n";

/// `mpm exact`'s usage, with each solution's parameters, defaults and units.
inline const char* exact_usage =
    "usage: mpm exact SCENE.toml [--set KEY=VALUE]... --at X[,Y] [--at ...] (--times T0:DT:T1 | --times-file FILE)\n"
    "                 [--strain small|finite]\n"
    "  Prints, without running the solver, the exact solution the scene's `exact` key names at every material\n"
    "  point and time asked, as CSV in SI units, one row per time and point:\n"
    "    1D  t,X,u_x,v_x,sigma_xx           2D  t,X,Y,u_x,u_y,v_x,v_y,sigma_xx,sigma_yy,sigma_xy\n"
    "  t (s), X, Y: the point's reference position (m, the scene's coordinates), u: displacement since t = 0 (m),\n"
    "  v: velocity (m/s), sigma: Cauchy stress (Pa, tension > 0).\n"
    "  --at X[,Y]          a material point of the body, by its reference position (m); repeat for more\n"
    "  --times T0:DT:T1    the times T0, T0 + DT, ... <= T1 (s)\n"
    "  --times-file FILE   one time (s) per line; # comments and a first header line are skipped\n"
    "  --strain small      the small-strain solution (default)\n"
    "  --strain finite     the finite-strain reference of the solver's updated-Lagrangian model (soil_column,\n"
    "                      vibrating_bar)\n"
    "  --set KEY=VALUE     overrides a scene key, as for mpm run\n"
    "  The solutions (scene key `exact`; their parameters come from the scene, SI units):\n"
    "    dyka_bar            1D elastic bar [origin, origin + L], free at xmin, fixed at xmax (appendix A.1-A.19):\n"
    "                        L = grid.length (m), E = material.young_modulus (Pa), rho = material.density (kg/m^3);\n"
    "                        piecewise-constant initial velocity (m/s) from body.velocity, [initial_field] velocity and\n"
    "                        [[initial_velocity]] boxes (later boxes win), initial stress (Pa) from [initial_field] stress\n"
    "                        (default 0); every jump located to 1e-14 L\n"
    "    soil_column         2D column on a roller base under gravity (paper/07_exact_column.md): H = the top of its\n"
    "                        bodies above grid.origin (m; the grid may reach higher), M = E(1 - nu)/((1 + nu)(1 - 2 nu))\n"
    "                        (Pa), rho, g = -gravity.acceleration[1] (m/s^2), the\n"
    "                        ramp of Eq. (44) with T = gravity.ramp_period (s; 0: none); 200 modes; sigma_xx =\n"
    "                        nu/(1 - nu) sigma_yy. --strain finite: the static settlement at finite (logarithmic)\n"
    "                        strain under full gravity, at every t (v = 0)\n"
    "    vibrating_bar       the bar of dyka_bar in its mode n: v(X, 0) = V cos((2n - 1) pi X / 2L), unstressed;\n"
    "                        n = exact_parameters.mode (default 1), V = exact_parameters.velocity_amplitude (m/s,\n"
    "                        required). --strain finite: sigma = E ln(stretch), solved by finite differences\n"
    "                        (512 cells, second order; at most 4000 times)\n"
    "    manufactured_small  2D square [origin, origin + L]^2, every face held: u = A sin(omega t) (sin kX sin kY,\n"
    "                        sin 2kX sin kY), k = pi/L, omega = c_p k; A = exact_parameters.displacement_amplitude\n"
    "                        (m, required, |A| pi/L < 0.01); E, nu, rho of [material]\n"
    "    manufactured_large  2D square, rollers on every face, each axis stretched on its own at finite strain;\n"
    "                        [a_x, a_y] = exact_parameters.displacement_amplitude (m, required)\n"
    "  Both manufactured solutions give the run (mpm run) its body force and initial velocity (mpm/exact/manufactured.hpp).\n";

/// `mpm compare`'s usage.
inline const char* compare_usage =
    "usage: mpm compare RESULT.csv SCENE.toml --at X[,Y] --column COL=QUANTITY [--column ...] [--time-column NAME]\n"
    "                   [--tolerance TOL] [--plot FILE.png] [--set KEY=VALUE]... [--strain small|finite]\n"
    "  Scores any CSV with a header line (another code's output) against the scene's exact solution (as mpm exact\n"
    "  evaluates it) at the material point --at and at the CSV's own sample times, and prints CSV:\n"
    "    column,quantity,samples,rms,rms_normalised,max_abs,t_of_max\n"
    "  rms: Eq. (43), sqrt(sum (c_n - e_n)^2 / N) over the N rows, in the quantity's unit; rms_normalised: rms\n"
    "  divided by the solution's scale of the quantity: velocity V* (the largest |v_0| or |sigma_0|/Z of the initial\n"
    "  data: v0 for the Dyka bar, so the paper's RMS/v0), stress Z V*, displacement V* L/c (dyka_bar); rho g H,\n"
    "  rho g H^2/(2M), g H/c (soil_column: base stress, top settlement, wave velocity); Z|V|, |V|, |V|/omega\n"
    "  (vibrating_bar); A omega, (lambda + 2G) k A, |A| (manufactured); max_abs: the largest |c_n - e_n|, at t_of_max (s).\n"
    "  --at X[,Y]           the material point whose history the CSV holds, by its reference position (m)\n"
    "  --column COL=QUANTITY  the CSV's column COL holds QUANTITY: u_x, v_x, sigma_xx (2D also u_y, v_y, sigma_yy,\n"
    "                       sigma_xy), SI units; repeat for more columns\n"
    "  --time-column NAME   the column of the sample times, s (default t)\n"
    "  --tolerance TOL      exit 1 when an rms_normalised exceeds TOL (default: no check, exit 0)\n"
    "  --plot FILE.png      draws each column and the exact solution against t (gnuplot)\n"
    "  --strain, --set      as for mpm exact\n"
    "  Exit codes: 0 within the tolerance, 1 above it, 2 a bad input (nothing written), 3 gnuplot failed.\n";

inline const char* exit_codes =
    "Exit codes:\n"
    "  0  done\n"
    "  2  a bad scene, option or run folder: one line `error: FILE:LINE: KEY: what is wrong`, nothing written\n"
    "  3  the method failed during the run (or gnuplot failed for `mpm plot`): one line on stderr; what was\n"
    "     written so far is kept\n";

/// A key's default as the help and README show it: `0.5`, `0.0 per axis`, `required`, `none` (optional).
inline std::string default_text(const io::SceneKey& key) {
  if (!key.fallback) return "required";
  if (key.is_optional()) return "none";
  return std::string(key.fallback) + (key.per_axis ? " per axis" : "");
}

/// Every scene key with its default, unit and meaning, one line each.
inline std::string scene_keys_help() {
  std::ostringstream out;
  out << "Scene keys (TOML; body[].min is `min` of every [[body]]; \"per axis\": the default on every axis;\n"
         "`required`: no default; `none`: optional, absent unless given):\n";
  size_t key_width = 0, default_width = 0, unit_width = 0;
  for (const auto& key : io::scene_keys()) {
    key_width = std::max(key_width, key.key.size());
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

/// README's table of scene keys, one row per key (README.md, between the lines `<!-- scene keys -->` and
/// `<!-- /scene keys -->`; the doctest below holds README to it).
inline std::string scene_keys_markdown() {
  std::string table = "| key | default | unit | meaning |\n|---|---|---|---|\n";
  for (const auto& key : io::scene_keys()) {
    std::string meaning;
    for (char character : std::string(key.meaning)) meaning += character == '|' ? std::string("\\|") : std::string(1, character);
    std::string fallback = default_text(key);
    if (key.fallback && *key.fallback) fallback = "`" + std::string(key.fallback) + "`" + (key.per_axis ? " per axis" : "");
    table += "| `" + key.key + "` | " + fallback + " | " + key.unit + " | " + meaning + " |\n";
  }
  return table;
}

/// `mpm --help`
inline std::string main_help() {
  return std::string("mpm: the Material Point Method with linear, uGIMP and LME shape functions (README.md)\n\n") +
         run_usage + "\n" + exact_usage + "\n" + compare_usage + "\n" + shape_usage() + "\n" + plot_usage + "\n" + stability_usage() + "\n" +
         "usage: mpm --version\n  Prints the version (git describe at build time).\n\n" + scene_keys_help() + "\n" + exit_codes;
}

/// The help of one command ("run", "exact", "compare", "shape", "plot"); the main help for any other.
inline std::string command_help(const std::string& command) {
  if (command == "run") return std::string(run_usage) + "\n" + scene_keys_help() + "\n" + exit_codes;
  if (command == "shape") return shape_usage() + "\n" + exit_codes;
  if (command == "plot") return std::string(plot_usage) + "\n" + exit_codes;
  if (command == "stability") return stability_usage() + "\n" + exit_codes;
  if (command == "exact") return std::string(exact_usage) + "\n" + exit_codes + "  (mpm exact exits 3 only when its output cannot be written)\n";
  if (command == "compare") return compare_usage;
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
    CHECK(line.find(default_text(key)) != std::string::npos);
    for (const std::string& choice : key.choices) CHECK(line.find(choice) != std::string::npos);  // every word a choice takes
    CHECK(line.find(std::string("  ") + key.unit + "  ") != std::string::npos);
  }
  for (const std::string command : {"run", "shape", "plot", "exact", "stability", ""})
    CHECK(command_help(command).find("  3  the method failed") != std::string::npos);
  for (const std::string name : {"dyka_bar", "soil_column", "vibrating_bar", "manufactured_small", "manufactured_large"})
    CHECK(command_help("exact").find("\n    " + name + " ") != std::string::npos);  // every value of the scene key `exact`
  CHECK(command_help("compare").find("Exit codes: 0 within the tolerance, 1 above it, 2 a bad input") != std::string::npos);
  CHECK(main_help().find("usage: mpm compare RESULT.csv SCENE.toml") != std::string::npos);
  CHECK(command_help("shape").find("--tol T            LME support tolerance, in (0, 1) (default 1e-06)") != std::string::npos);
  CHECK(asks_for_help({"--dim", "1", "-h"}));
  CHECK(!asks_for_help({"--dim", "1"}));
}


#ifdef MPM_SOURCE_DIR
TEST_CASE("README's table of scene keys is the table of mpm/io/scene_keys.hpp (MPM_UPDATE_README=1 rewrites it)") {
  const std::string path = std::string(MPM_SOURCE_DIR) + "/README.md";
  std::ifstream in(path);
  std::stringstream read;
  read << in.rdbuf();
  std::string readme = read.str();
  const std::string begin = "<!-- scene keys -->\n", end = "<!-- /scene keys -->";
  const auto from = readme.find(begin), to = readme.find(end);
  REQUIRE_MESSAGE((from != std::string::npos && to != std::string::npos && from < to), "README.md lacks the markers " << begin << end);
  const std::string given = readme.substr(from + begin.size(), to - from - begin.size()), wanted = scene_keys_markdown();
  if (given != wanted && std::getenv("MPM_UPDATE_README")) {
    std::ofstream(path) << readme.replace(from + begin.size(), to - from - begin.size(), wanted);
    return;
  }
  std::istringstream given_rows(given), wanted_rows(wanted);
  for (std::string a, b; std::getline(wanted_rows, b);) {
    if (!std::getline(given_rows, a)) a = "(no row)";
    CHECK_MESSAGE(a == b, "README.md's row differs from the key's declaration; want:\n" << b);
    if (a != b) break;  // one row named: the key that differs
  }
  CHECK(given.size() == wanted.size());
}
#endif

}  // namespace mpm::cli
