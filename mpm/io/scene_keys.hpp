/// \file
/// Every key a scene may hold, in one table: its default, its unit and what it means.
///
/// `mpm --help` and `mpm run --help` print this table, `mpm run --print-scene` prints a scene in its
/// order, and the doctest of mpm/io/scene_resolved.hpp checks it against the parser (mpm/io/scene.hpp):
/// every key the parser accepts is listed here and every key listed here is accepted; a key without a
/// default here is one the parser requires; every default here is the parser's. So the help cannot
/// drift from the code: a key added to the parser and not here fails `make test`.
#pragma once
#include <string>
#include <vector>

namespace mpm::io {

struct SceneKey {
  /// "solver.cfl"; "body[].min" for a key of every table of an array of tables ([[body]])
  const char* key;
  /// the default as a TOML value ("0.5", "\"linear\"", "[]"); nullptr: the key is required
  const char* fallback;
  /// the default is repeated on every axis: "0" means [0] in 1D and [0, 0] in 2D
  bool per_axis;
  const char* unit;
  const char* meaning;
  /// with fallback nullptr: the key is optional and has no default (absent unless the scene gives it)
  bool optional = false;
};

/// The name that stands for any name in a table of free names ("constants.<name>").
inline const std::string any_name = "<name>";

/// The scene's keys, in the order a scene file writes them.
inline const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = {
      {"title", "\"untitled\"", false, "-", "name of the run (printed, written into run.json)"},
      {"dimension", "1", false, "-", "1 or 2 (2D is plane strain)"},
      {"exact", "\"none\"", false, "-",
       "exact solution written beside the observers into exact.csv, drawn by `mpm plot`, evaluated by `mpm exact` "
       "and `mpm compare`: none | dyka_bar (1D bar free at xmin, fixed at xmax; appendix A.1-A.19) | "
       "soil_column (2D column on a roller base under gravity along -y; mpm/exact/column.hpp) | "
       "vibrating_bar (a mode of the dyka_bar's bar; mpm/exact/vibrating_bar.hpp) | manufactured_small | "
       "manufactured_large (2D square, its body force and initial velocity set by the solution; mpm/exact/manufactured.hpp)"},
      {"exact_parameters.mode", "1", false, "-", "vibrating_bar: the mode n, v(X, 0) = V cos((2n - 1) pi X / 2L)"},
      {"exact_parameters.velocity_amplitude", nullptr, false, "m/s",
       "vibrating_bar: V, a number or a formula of the constants (\"V\")", true},
      {"exact_parameters.displacement_amplitude", nullptr, false, "m",
       "manufactured_small: A; manufactured_large: [a_x, a_y]; numbers or formulas of the constants", true},
      {"grid.origin", "0.0", true, "m", "lower corner of the box [origin, origin + length] the body's grid spans"},
      {"grid.length", nullptr, false, "m", "size of the box on each axis"},
      {"grid.cells", nullptr, false, "cells", "cells on each axis; cells must be square (equal length/cells)"},
      {"grid.margin_min", "0", true, "cells", "extra cells below origin on each axis (room to move, supports)"},
      {"grid.margin_max", "0", true, "cells", "extra cells above origin + length on each axis"},
      {"material.young_modulus", nullptr, false, "Pa", "Young's modulus E of the linear elastic material, Eq. (3)"},
      {"material.poisson_ratio", "0.0", false, "-", "Poisson's ratio nu, in [0, 0.5)"},
      {"material.density", nullptr, false, "kg/m^3", "initial density rho"},
      {"body[].min", nullptr, false, "m", "lower corner of a box of whole cells filled with particles"},
      {"body[].max", nullptr, false, "m", "upper corner of the box"},
      {"body[].particles_per_cell", "1", true, "-", "particles per cell on each axis"},
      {"body[].velocity", "0.0", true, "m/s", "initial velocity of the body's particles"},
      {"body[].placement", "\"uniform\"", false, "-", "uniform (cell split evenly) | gauss (2x2 Gauss points)"},
      {"body[].shape", "\"box\"", false, "-",
       "box | ellipse (inscribed in the box [min, max]: a disk in a square box) | polygon (vertices): the particles of "
       "the box's cells that lie in the shape are kept, each with its share of the cell's mass (2D) | file (particles read from file)"},
      {"body[].vertices", nullptr, false, "m", "polygon: its vertices [[x, y], ...], in order, inside [min, max]", true},
      {"body[].file", nullptr, false, "-",
       "file: a CSV of the body's particles, x[,y] (m), volume (m^Dim) or mass (kg), optional v_x[,v_y] (m/s), by column "
       "name; relative to the scene's folder; every particle inside [min, max]", true},
      {"body[].young_modulus", nullptr, false, "Pa", "the body's own material: E (default [material]'s)", true},
      {"body[].poisson_ratio", nullptr, false, "-", "the body's own material: nu in [0, 0.5) (default [material]'s)", true},
      {"body[].density", nullptr, false, "kg/m^3", "the body's own material: rho_0, its particles' masses (default [material]'s)", true},
      {"initial_velocity[].min", nullptr, false, "m", "lower corner of a box; particles in it start with `velocity`"},
      {"initial_velocity[].max", nullptr, false, "m", "upper corner of the box"},
      {"initial_velocity[].velocity", nullptr, false, "m/s", "their initial velocity (later boxes win)"},
      {"fixed[].face", nullptr, false, "-", "xmin | xmax | ymin | ymax of the box: a rigid wall there and beyond"},
      {"fixed[].components", nullptr, false, "-", "velocity components held at zero, e.g. [\"x\"]"},
      {"gravity.acceleration", "0.0", true, "m/s^2", "body force per unit mass"},
      {"gravity.ramp_period", "0.0", false, "s", "T of the ramp of Eq. (44), full gravity from T/2 on (0: no ramp)"},
      {"gravity.evaluate_at", "\"step_end\"", false, "-", "time of a step at which the ramp is read: step_end | step_start"},
      {"solver.shape", "\"linear\"", false, "-",
       "shape function: linear | ugimp | lme (Eqs. 34-41) | bspline2 | bspline3 (quadratic, cubic B-splines)"},
      {"solver.integrator", "\"fe\"", false, "-", "fe (forward Euler) | npc (Newmark predictor-corrector)"},
      {"solver.cfl", "0.5", false, "-", "Courant number of Eq. (42)"},
      {"solver.courant", "\"max\"", false, "-", "max (Eq. 42 as printed) | sum (the authors' c + |v|)"},
      {"solver.end_time", nullptr, false, "s", "time at which the run ends (the last step lands on it)"},
      {"solver.lme_gamma", "3.0", false, "-", "LME locality gamma, beta = gamma / h^2 (Eq. 36)"},
      {"solver.lme_tol", "1e-6", false, "-", "LME support tolerance, in (0, 1): R = h sqrt(-ln(tol) / gamma)"},
      {"solver.lme_newton_tol", "1e-10", false, "-", "relative tolerance of the LME Newton iteration"},
      {"solver.lme_max_iterations", "100", false, "-", "most LME Newton iterations before the run fails"},
      {"solver.lme_beta", "\"grid_spacing\"", false, "-", "grid_spacing | mean_neighbour_distance (the authors' h)"},
      {"solver.newmark_gamma", "0.5", false, "-", "Newmark gamma of the predictor-corrector, in [0, 1]"},
      {"solver.fe_position_velocity", "\"updated\"", false, "-", "updated | start (literal Eqs. 19-22)"},
      {"solver.npc_position_velocity", "\"projected\"", false, "-",
       "projected (literal Eq. 33, v_I^k) | corrected (the authors' code, v_I^{k+1}) | predicted"},
      {"solver.npc_velocity", "\"eq32\"", false, "-",
       "eq32 (Eq. 32 as printed: new acceleration only, damped) | average (Eq. 23: Newmark average, undamped)"},
      {"solver.flip_fraction", "1.0", false, "-", "forward Euler's PIC/FLIP blend of the particle velocity: 1 FLIP, 0 PIC"},
      {"solver.stress_update", "\"usf\"", false, "-",
       "forward Euler's stress update: usf (first, the paper's) | usl (last) | musl (last, from the particle velocities "
       "projected again); paper/11_stress_update.md"},
      {"solver.energy_growth_limit", "10.0", false, "-",
       "stop (exit 3) when the energy exceeds this times (initial + work of gravity); 0: off"},
      {"constants.<name>", nullptr, false, "-",
       "a named constant: a number, or a formula of other constants (pi, young_modulus, poisson_ratio and density "
       "are predefined); usable in every formula",
       true},
      {"initial_field.velocity", nullptr, false, "m/s",
       "initial velocity per axis as formulas of x, X (y, Y) and the constants; [[initial_velocity]] boxes win",
       true},
      {"initial_field.stress", nullptr, false, "Pa",
       "initial stress as formulas: [xx] in 1D, [xx, yy, xy] in 2D", true},
      {"body_force.acceleration", nullptr, false, "m/s^2",
       "body force per unit mass per axis as formulas of x, X (y, Y) and t, added to [gravity]", true},
      {"observer[].name", nullptr, false, "-", "column name in observers.csv (letters, digits, _)"},
      {"observer[].position", nullptr, false, "m", "the particle nearest this point at t = 0 is observed"},
      {"output.every", "1", false, "steps", "observers and energy sampled every n steps and at the end"},
      {"output.snapshots", "[]", false, "s", "times at which every particle is written (CSV, VTK, .pvd)"},
      {"output.times", "[]", false, "s",
       "times at which observers, energy and exact.csv are sampled, each landed on by a step; replaces every"},
  };
  return keys;
}

/// The table of `key` ("body[].min" -> "body"); empty for a top-level key.
inline std::string key_section(const std::string& key) {
  const auto dot = key.find('.');
  if (dot == std::string::npos) return "";
  std::string section = key.substr(0, dot);
  if (section.size() > 2 && section.compare(section.size() - 2, 2, "[]") == 0) section.resize(section.size() - 2);
  return section;
}

/// The name of `key` inside its table ("body[].min" -> "min").
inline std::string key_name(const std::string& key) {
  const auto dot = key.find('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

/// True if the key belongs to an array of tables ([[body]]).
inline bool key_in_array(const std::string& key) { return key.find("[]") != std::string::npos; }

}  // namespace mpm::io
