/// \file
/// What a scene says, validated: the typed settings of a run, read from a SceneFile.
///
/// Key names are a contract that outside tools rely on: keys may be added, never renamed.
/// Every key is listed in README.md ("Scene files"); scenes/ holds complete examples.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mpm/io/scene_file.hpp"
#include "mpm/io/particle_file.hpp"
#include "mpm/io/scene_formulas.hpp"
#include "mpm/particles/seeding.hpp"
#include "mpm/simulation.hpp"

namespace mpm::io {

/// A linear elastic material, Eq. (3): the scene's [material], or a body's own (its keys young_modulus,
/// poisson_ratio and density, each defaulting to [material]'s).
struct MaterialSettings {
  double young_modulus = 0.0, poisson_ratio = 0.0, density = 0.0;  ///< E (Pa), nu, rho_0 (kg/m^3)
  bool operator==(const MaterialSettings& other) const {
    return young_modulus == other.young_modulus && poisson_ratio == other.poisson_ratio && density == other.density;
  }
};

struct BodySettings {
  std::vector<double> min, max, velocity;
  MaterialSettings material;                      ///< the body's young_modulus, poisson_ratio, density: by default [material]'s
  std::vector<int> particles_per_cell;
  std::string placement = "uniform";
  std::string shape = "box";                      ///< box | ellipse | polygon (mpm/particles/body_shape.hpp) | file
  std::vector<std::array<double, 2>> vertices;    ///< polygon only, m
  std::string file;                               ///< file only: the CSV as given (mpm/io/particle_file.hpp)
  std::vector<FileParticle> particles;            ///< file only: its particles, read and checked with the scene
};

/// The body's shape, for seeding (mpm/particles/body_shape.hpp).
inline BodyShape body_shape(const BodySettings& body) {
  BodyShape shape;
  shape.kind = body.shape == "ellipse" ? BodyShape::Kind::ellipse : body.shape == "polygon" ? BodyShape::Kind::polygon : BodyShape::Kind::box;
  for (size_t axis = 0; axis < body.min.size(); ++axis) shape.min[axis] = body.min[axis], shape.max[axis] = body.max[axis];
  shape.vertices = body.vertices;
  return shape;
}
struct VelocityBox {
  std::vector<double> min, max, velocity;
};
struct FixedSettings {
  int axis = 0;
  bool upper = false;
  std::vector<int> components;
};
/// An observer names a material point by its reference position: the particle nearest it at t = 0 is
/// observed (observers.csv), and the scene's exact solution is evaluated at the point itself (exact.csv).
struct ObserverSettings {
  std::string name;
  std::vector<double> position;
};

struct Scene {
  std::string file, title;
  int dimension = 1;
  // [grid]
  std::vector<double> origin, length;
  std::vector<int> cells, margin_min, margin_max;
  double spacing = 0.0;
  // [material]
  double young_modulus = 0.0, poisson_ratio = 0.0, density = 0.0;
  // [[body]], [[initial_velocity]], [[fixed]], [gravity]
  std::vector<BodySettings> bodies;
  std::vector<VelocityBox> initial_velocities;
  std::vector<FixedSettings> fixed;
  std::vector<double> gravity;
  double ramp_period = 0.0;
  // [solver]
  std::string shape = "linear", integrator = "fe";
  double lme_gamma = 3.0, lme_tol = 1e-6, lme_newton_tol = 1e-10;
  int lme_max_iterations = 100;
  std::string lme_beta = "grid_spacing";
  double newmark_gamma = 0.5;
  std::string fe_position_velocity = "updated", npc_position_velocity = "projected";
  std::string npc_velocity = "eq32";  ///< eq32 (the paper's Eq. 32) | average (Eq. 23, the Newmark average)
  double flip_fraction = 1.0;         ///< forward Euler's PIC/FLIP blend: 1 = FLIP (the paper's)
  std::string stress_update = "usf";  ///< forward Euler's stress update: usf (the paper's) | usl | musl
  RunControl control;
  // [[observer]], [output]
  std::vector<ObserverSettings> observers;
  // [constants], [initial_field], [body_force] (io/scene_formulas.hpp)
  SceneFormulas formulas;
  /// exact solution written beside the observers (exact.csv) and evaluated by `mpm exact` and `mpm compare`:
  /// "none", "dyka_bar", "soil_column", "vibrating_bar", "manufactured_small" or "manufactured_large"
  std::string exact = "none";
  // [exact_parameters]
  int exact_mode = 1;                                 ///< vibrating_bar: mode n
  std::optional<double> exact_velocity_amplitude;     ///< vibrating_bar: V, m/s
  std::vector<double> exact_displacement_amplitude;   ///< manufactured_small: [A]; manufactured_large: [a_x, a_y], m
  /// the resolved scene (file plus overrides) as JSON, for run.json
  std::string resolved_json;
};

namespace detail {

/// The largest count of cells or margin cells on one axis: a bound that keeps every sum and
/// product of them exact in 64-bit arithmetic; the budget (scene_budget.hpp) bounds the totals.
inline constexpr int max_cells_per_axis = 100'000'000;

/// Calls `read` with a reader for every table of the array of tables `key` ([[key]] in TOML).
template <class Read>
void each_table(const SceneFile& file, SceneReader& root, const std::string& key, Read read) {
  if (!root.has(key)) return;
  const toml::array* array = file.table[key].as_array();
  if (!array || !array->is_array_of_tables()) root.fail(key, "must be an array of tables: write [[" + key + "]]");
  for (size_t k = 0; k < array->size(); ++k) {
    SceneReader reader(file, *(*array)[k].as_table(), key + "[" + std::to_string(k) + "]");
    read(reader);
    reader.reject_unknown_keys();
  }
}

inline const toml::table& table_or_empty(const SceneFile& file, SceneReader& root, const std::string& key, bool required) {
  static const toml::table empty;
  if (!root.has(key)) {
    if (required) root.fail(key, "missing table [" + key + "]");
    return empty;
  }
  const toml::table* table = file.table[key].as_table();
  if (!table) root.fail(key, "must be a table: write [" + key + "]");
  return *table;
}

/// True if `value` lies on a grid line of the axis (within 1e-6 of a cell).
inline bool on_grid_line(double value, double origin, double spacing) {
  const double cells = (value - origin) / spacing;
  return std::abs(cells - std::round(cells)) < 1e-6;
}

/// A key of numbers, each a number or a formula of the scene's constants in quotes ("V", "0.05 * L"):
/// `key = 1.5`, `key = "V"` or `key = [1.5, "a"]`. \throws SceneError naming the key.
inline std::vector<double> constant_or_formula(SceneReader& reader, const std::string& key,
                                               const std::map<std::string, double>& constants) {
  std::vector<const toml::node*> entries;
  const toml::node* node = reader.node(key);
  if (const toml::array* array = node->as_array()) {
    if (array->empty() || array->size() > 2) reader.fail(key, "give one or two values");
    for (const auto& entry : *array) entries.push_back(&entry);
  } else {
    entries.push_back(node);
  }
  std::vector<double> values;
  const FormulaVariables none{0, false};
  for (const toml::node* entry : entries) {
    double value = 0.0;
    if (entry->is_floating_point() || entry->is_integer()) {
      value = *entry->value<double>();
    } else if (entry->is_string()) {
      const std::string text = *entry->value<std::string>();
      try {
        value = Formula(text, constants, none)(nullptr, nullptr, 0.0);
      } catch (const mu::Parser::exception_type& error) {
        reader.fail(key, formula_problem(error, text, constants, none));
      }
    } else {
      reader.fail(key, "must be a number or a formula of the constants in quotes");
    }
    if (!std::isfinite(value)) reader.fail(key, "must be finite, got " + SceneReader::describe(value));
    values.push_back(value);
  }
  return values;
}

/// Bodies may not overlap: a particle of one may not lie in another (its box cut by its shape). Boxes whose
/// interiors meet overlap; where a shape cuts one of them, the particles of the second body in the common
/// box are tested against the first (at most 4e6 of them: beyond, the boxes must be apart).
/// \throws SceneError at the second body's min, naming the first body and its line.
inline void check_bodies_apart(const SceneFile& file, const Scene& scene) {
  const int dim = scene.dimension;
  const toml::array* tables = file.table["body"].as_array();
  auto where_is_body = [&](size_t k) {  // FILE:LINE of body k, or the --set that gave it
    for (const std::string& key : {"body[" + std::to_string(k) + "]", std::string("body")})
      if (auto given = file.overridden.find(key); given != file.overridden.end()) return given->second + ":1";
    return file.path + ":" + std::to_string(tables && k < tables->size() ? line_of(*tables->get(k)) : 0);
  };
  for (size_t j = 1; j < scene.bodies.size(); ++j)
    for (size_t i = 0; i < j; ++i) {
      const BodySettings &first = scene.bodies[i], &second = scene.bodies[j];
      Vector<2> lower = Vector<2>::Zero(), upper = Vector<2>::Zero();
      double seeds = 1.0;
      bool apart = false;
      for (int axis = 0; axis < dim; ++axis) {
        lower[axis] = std::max(first.min[axis], second.min[axis]), upper[axis] = std::min(first.max[axis], second.max[axis]);
        apart = apart || upper[axis] - lower[axis] < 0.5 * scene.spacing;  // both on grid lines: apart, or a cell in common
        seeds *= (upper[axis] - lower[axis]) / scene.spacing * second.particles_per_cell[axis];
      }
      if (apart) continue;
      bool overlap = (first.shape == "box" && second.shape == "box") || first.shape == "file" || second.shape == "file";
      if (!overlap && seeds > 4e6) overlap = true;
      if (!overlap) {
        const BodyShape shape_first = body_shape(first), shape_second = body_shape(second);
        auto visit = [&](const auto& x) {
          overlap = shape_second.holds(x[0], x[dim - 1]) && shape_first.holds(x[0], x[dim - 1]);
          return !overlap;
        };
        Vector<2> origin(scene.origin[0], dim == 2 ? scene.origin[1] : 0.0);
        std::array<int, 2> ppc{second.particles_per_cell[0], second.particles_per_cell[dim - 1]};
        const Placement placement = second.placement == "gauss" ? Placement::gauss : Placement::uniform;
        if (dim == 2) for_each_seed<2>(origin, scene.spacing, lower, upper, ppc, placement, visit);
        else for_each_seed<1>(Vector<1>(origin[0]), scene.spacing, Vector<1>(lower[0]), Vector<1>(upper[0]), {ppc[0]}, placement, visit);
      }
      if (overlap) {
        SceneReader reader(file, *tables->get(j)->as_table(), "body[" + std::to_string(j) + "]");
        reader.fail("min", "overlaps body[" + std::to_string(i) + "] (" + where_is_body(i) +
                               "): a particle of one would lie in the other; move them apart (their boxes may touch)");
      }
    }
}

}  // namespace detail

/// Reads and validates every key of the scene. \throws SceneError at the first problem.
inline Scene read_scene(const SceneFile& file) {
  using detail::each_table;
  Scene scene;
  scene.file = file.path;
  SceneReader root(file, file.table, "");
  scene.title = root.any_text("title", "untitled");
  for (unsigned char character : scene.title)  // it is a line of the VTK header and of the progress line
    if (character < 0x20 || character == 0x7f) root.fail("title", "must be one line of printable text (no newline, tab or control character)");
  scene.dimension = root.integer("dimension", 1, 1, 2);
  const int dim = scene.dimension;
  const std::vector<std::string> axes = dim == 1 ? std::vector<std::string>{"x"} : std::vector<std::string>{"x", "y"};

  {  // [grid]
    SceneReader grid(file, detail::table_or_empty(file, root, "grid", true), "grid");
    scene.origin = grid.numbers("origin", dim, std::vector<double>(dim, 0.0));
    scene.length = grid.numbers("length", dim);
    for (int axis = 0; axis < dim; ++axis)
      if (!(scene.length[axis] > 0.0)) grid.fail("length", "entries must be > 0");
    scene.cells = grid.integers("cells", dim, std::nullopt, 1, detail::max_cells_per_axis);
    scene.margin_min = grid.integers("margin_min", dim, std::vector<int>(dim, 0), 0, detail::max_cells_per_axis);
    scene.margin_max = grid.integers("margin_max", dim, std::vector<int>(dim, 0), 0, detail::max_cells_per_axis);
    scene.spacing = scene.length[0] / scene.cells[0];
    for (int axis = 0; axis < dim; ++axis) {  // the grid's lines must be distinct numbers where it lies
      const double far = std::max(std::abs(scene.origin[axis]), std::abs(scene.origin[axis] + scene.length[axis])) +
                         (std::max(scene.margin_min[axis], scene.margin_max[axis]) + 1.0) * scene.spacing;
      if (!(scene.spacing > 1e-9 * far) || !std::isfinite(far))
        grid.fail("origin", "too far from 0 for the cell size " + SceneReader::describe(scene.spacing) +
                                ": the grid must lie within 1e9 cells of the origin of coordinates");
    }
    for (int axis = 1; axis < dim; ++axis)
      if (std::abs(scene.length[axis] / scene.cells[axis] - scene.spacing) > 1e-9 * scene.spacing)
        grid.fail("cells", "cells must be square: length/cells must be equal on every axis");
    grid.reject_unknown_keys();
  }
  // A material's keys: those of [material], or a body's own, each defaulting to [material]'s.
  auto read_material = [&](SceneReader& material, std::optional<MaterialSettings> defaults) {
    MaterialSettings settings;
    settings.young_modulus = material.positive("young_modulus", defaults ? std::optional(defaults->young_modulus) : std::nullopt);
    settings.poisson_ratio = material.number("poisson_ratio", defaults ? defaults->poisson_ratio : 0.0);
    if (!(settings.poisson_ratio >= 0.0 && settings.poisson_ratio < 0.5)) material.fail("poisson_ratio", "must be in [0, 0.5)");
    settings.density = material.positive("density", defaults ? std::optional(defaults->density) : std::nullopt);
    return settings;
  };
  {  // [material]
    SceneReader material(file, detail::table_or_empty(file, root, "material", true), "material");
    const MaterialSettings settings = read_material(material, std::nullopt);
    material.reject_unknown_keys();
    scene.young_modulus = settings.young_modulus, scene.poisson_ratio = settings.poisson_ratio, scene.density = settings.density;
  }
  auto inside_grid = [&](SceneReader& reader, const std::string& key, const std::vector<double>& point, bool on_lines) {
    for (int axis = 0; axis < dim; ++axis) {
      const double lower = scene.origin[axis] - scene.margin_min[axis] * scene.spacing;
      const double upper = scene.origin[axis] + scene.length[axis] + scene.margin_max[axis] * scene.spacing;
      if (point[axis] < lower - 1e-9 * scene.spacing || point[axis] > upper + 1e-9 * scene.spacing)
        reader.fail(key, "lies outside the grid [" + std::to_string(lower) + ", " + std::to_string(upper) + "] on " + axes[axis]);
      if (on_lines && !detail::on_grid_line(point[axis], scene.origin[axis], scene.spacing))
        reader.fail(key, "must lie on grid lines (multiples of the cell size " + std::to_string(scene.spacing) + " from the origin)");
    }
  };
  each_table(file, root, "body", [&](SceneReader& reader) {
    BodySettings body;
    body.material = read_material(reader, MaterialSettings{scene.young_modulus, scene.poisson_ratio, scene.density});
    body.min = reader.numbers("min", dim);
    body.max = reader.numbers("max", dim);
    inside_grid(reader, "min", body.min, true);
    inside_grid(reader, "max", body.max, true);
    for (int axis = 0; axis < dim; ++axis)
      if (!(body.max[axis] > body.min[axis] + 0.5 * scene.spacing)) reader.fail("max", "must exceed min by at least one cell");
    body.particles_per_cell = reader.integers("particles_per_cell", dim, std::vector<int>(dim, 1), 1, detail::max_cells_per_axis);
    body.velocity = reader.numbers("velocity", dim, std::vector<double>(dim, 0.0));
    body.placement = reader.text("placement", {"uniform", "gauss"}, std::string("uniform"));
    if (body.placement == "gauss")
      for (int ppc : body.particles_per_cell)
        if (ppc != 2) reader.fail("placement", "'gauss' needs particles_per_cell = 2 on every axis");
    body.shape = reader.text("shape", {"box", "ellipse", "polygon", "file"}, std::string("box"));
    if (dim == 1 && (body.shape == "ellipse" || body.shape == "polygon"))
      reader.fail("shape", "a 1D body is a box or a file (ellipse and polygon are 2D shapes)");
    if (reader.has("file")) {
      body.file = reader.any_text("file", "");
      if (body.shape != "file") reader.fail("file", "only a body of shape = \"file\" reads a particle file");
      namespace fs = std::filesystem;
      const fs::path path = fs::path(body.file).is_absolute() ? fs::path(body.file) : fs::path(file.path).parent_path() / body.file;
      std::string problem;
      body.particles = read_particle_file(path.string(), dim, body.material.density, body.velocity, problem);
      if (!problem.empty()) reader.fail("file", problem);
      for (size_t p = 0; p < body.particles.size(); ++p) {
        const double position[2] = {body.particles[p].x, body.particles[p].y};
        for (int axis = 0; axis < dim; ++axis)
          if (position[axis] < body.min[axis] || position[axis] > body.max[axis])
            reader.fail("file", path.string() + ": particle " + std::to_string(p + 1) + " lies outside the body's box [min, max] on " +
                                    axes[axis] + ": the box must hold the file's particles");
      }
    } else if (body.shape == "file") {
      reader.fail("file", "missing; a body of shape = \"file\" reads its particles from a CSV file (x[,y],volume|mass[,v_x[,v_y]])");
    }
    if (const toml::node* node = reader.node("vertices")) {
      if (body.shape != "polygon") reader.fail("vertices", "only a body of shape = \"polygon\" has vertices");
      const toml::array* list = node->as_array();
      if (!list || list->size() < 3 || list->size() > 10000)
        reader.fail("vertices", "must be an array of 3 to 10000 points [x, y], e.g. [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]");
      for (const auto& entry : *list) {
        const toml::array* point = entry.as_array();
        std::array<double, 2> vertex{};
        for (int axis = 0; axis < 2; ++axis) {
          const toml::node* coordinate = point && point->size() == 2 ? point->get(axis) : nullptr;
          if (!coordinate || !coordinate->is_number() || !std::isfinite(*coordinate->value<double>()))
            reader.fail("vertices", "every vertex is a point [x, y] of two finite numbers (m)");
          vertex[axis] = *coordinate->value<double>();
          if (vertex[axis] < body.min[axis] - 1e-9 * scene.spacing || vertex[axis] > body.max[axis] + 1e-9 * scene.spacing)
            reader.fail("vertices", "vertex " + std::to_string(body.vertices.size()) + " lies outside the body's box [min, max]: "
                                    "the box is the cells seeded, the polygon the part kept");
        }
        body.vertices.push_back(vertex);
      }
    } else if (body.shape == "polygon") {
      reader.fail("vertices", "missing; a polygon needs its vertices, [[x, y], ...] (m)");
    }
    scene.bodies.push_back(body);
  });
  if (scene.bodies.empty()) root.fail("body", "the scene needs at least one [[body]]");
  detail::check_bodies_apart(file, scene);
  each_table(file, root, "initial_velocity", [&](SceneReader& reader) {
    scene.initial_velocities.push_back({reader.numbers("min", dim), reader.numbers("max", dim), reader.numbers("velocity", dim)});
  });
  each_table(file, root, "fixed", [&](SceneReader& reader) {
    const std::vector<std::string> faces = dim == 1 ? std::vector<std::string>{"xmin", "xmax"}
                                                    : std::vector<std::string>{"xmin", "xmax", "ymin", "ymax"};
    const std::string face = reader.text("face", faces);
    FixedSettings fixed;
    fixed.axis = face[0] == 'x' ? 0 : 1;
    fixed.upper = face.substr(1) == "max";
    for (const auto& component : reader.texts("components", axes)) fixed.components.push_back(component == "x" ? 0 : 1);
    scene.fixed.push_back(fixed);
  });
  {  // [gravity]
    SceneReader gravity(file, detail::table_or_empty(file, root, "gravity", false), "gravity");
    scene.gravity = gravity.numbers("acceleration", dim, std::vector<double>(dim, 0.0));
    scene.ramp_period = gravity.number("ramp_period", 0.0);
    if (scene.ramp_period < 0.0) gravity.fail("ramp_period", "must be >= 0 (0: no ramp)");
    scene.control.body_force_time = gravity.text("evaluate_at", {"step_end", "step_start"}, std::string("step_end")) == "step_end"
                                        ? BodyForceTime::step_end
                                        : BodyForceTime::step_start;
    gravity.reject_unknown_keys();
  }
  {  // [solver]
    SceneReader solver(file, detail::table_or_empty(file, root, "solver", true), "solver");
    scene.shape = solver.text("shape", {"linear", "ugimp", "lme", "bspline2", "bspline3"}, std::string("linear"));
    scene.lme_gamma = solver.positive("lme_gamma", 3.0);
    scene.lme_tol = solver.positive("lme_tol", 1e-6);
    if (scene.lme_tol >= 1.0) solver.fail("lme_tol", "must be in (0, 1)");
    scene.lme_newton_tol = solver.positive("lme_newton_tol", 1e-10);
    scene.lme_max_iterations = solver.integer("lme_max_iterations", 100, 1, 1000);  // Newton converges in < 10
    // The LME support radius R = h sqrt(-ln(tol)/gamma) must reach the corners of a particle's cell
    // (its convex hull), R >= h sqrt(dimension): gamma <= -ln(tol)/dimension. The key blamed is the
    // one the user changed: lme_tol when it is given and lme_gamma is not overridden, else lme_gamma.
    if (scene.shape == "lme" && scene.lme_gamma > -std::log(scene.lme_tol) / dim) {
      const bool blame_tol = solver.has("lme_tol") && !file.overridden.count("solver.lme_gamma");
      if (blame_tol)
        solver.fail("lme_tol", "too large for lme_gamma = " + SceneReader::describe(scene.lme_gamma) +
                                   ": the support must reach the corners of a cell, lme_tol <= exp(-lme_gamma * dimension) = " +
                                   SceneReader::describe(std::exp(-scene.lme_gamma * dim)));
      solver.fail("lme_gamma", "too large for lme_tol = " + SceneReader::describe(scene.lme_tol) +
                                   ": the support must reach the corners of a cell, lme_gamma <= -ln(lme_tol)/dimension = " +
                                   SceneReader::describe(-std::log(scene.lme_tol) / dim));
    }
    scene.lme_beta = solver.text("lme_beta", {"grid_spacing", "mean_neighbour_distance"}, std::string("grid_spacing"));
    scene.integrator = solver.text("integrator", {"fe", "npc"}, std::string("fe"));
    scene.control.cfl = solver.positive("cfl", 0.5);
    if (scene.control.cfl > 10.0) solver.fail("cfl", "must be in (0, 10]: far beyond any explicit scheme's stability limit");
    scene.control.courant = solver.text("courant", {"max", "sum"}, std::string("max")) == "max" ? CourantSpeed::maximum : CourantSpeed::sum;
    scene.control.end_time = solver.positive("end_time");
    scene.newmark_gamma = solver.number("newmark_gamma", 0.5);
    if (!(scene.newmark_gamma >= 0.0 && scene.newmark_gamma <= 1.0)) solver.fail("newmark_gamma", "must be in [0, 1]");
    scene.fe_position_velocity = solver.text("fe_position_velocity", {"updated", "start"}, std::string("updated"));
    scene.npc_position_velocity = solver.text("npc_position_velocity", {"projected", "corrected", "predicted"}, std::string("projected"));
    scene.npc_velocity = solver.text("npc_velocity", {"eq32", "average"}, std::string("eq32"));
    scene.stress_update = solver.text("stress_update", {"usf", "usl", "musl"}, std::string("usf"));
    if (scene.integrator == "npc" && scene.stress_update != "usf")
      solver.fail("stress_update", "the predictor-corrector updates stress first (\"usf\"); usl and musl are forward Euler's");
    scene.flip_fraction = solver.number("flip_fraction", 1.0);
    if (!(scene.flip_fraction >= 0.0 && scene.flip_fraction <= 1.0)) solver.fail("flip_fraction", "must be in [0, 1] (1: FLIP, 0: PIC)");
    scene.control.energy_growth_limit = solver.number("energy_growth_limit", 10.0);
    if (scene.control.energy_growth_limit < 0.0) solver.fail("energy_growth_limit", "must be >= 0 (0: no check)");
    solver.reject_unknown_keys();
  }
  scene.exact = root.text("exact", {"none", "dyka_bar", "soil_column", "vibrating_bar", "manufactured_small", "manufactured_large"},
                          std::string("none"));
  each_table(file, root, "observer", [&](SceneReader& reader) {
    ObserverSettings observer{reader.any_text("name", ""), reader.numbers("position", dim)};
    inside_grid(reader, "position", observer.position, false);
    // The observer names a material point by its reference position: exact.csv is evaluated there, so it
    // must be a point of the body the exact solution holds for, [origin, origin + length].
    for (int axis = 0; scene.exact != "none" && axis < dim; ++axis)
      if (observer.position[axis] < scene.origin[axis] - 1e-9 * scene.spacing ||
          observer.position[axis] > scene.origin[axis] + scene.length[axis] + 1e-9 * scene.spacing)
        reader.fail("position", "lies outside the body [" + SceneReader::describe(scene.origin[axis]) + ", " +
                                    SceneReader::describe(scene.origin[axis] + scene.length[axis]) + "] on " + axes[axis] +
                                    ", where exact = \"" + scene.exact + "\" is evaluated for exact.csv");
    if (observer.name.empty() || observer.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      reader.fail("name", "required; letters, digits and _ only (it names CSV columns)");
    for (const auto& other : scene.observers)
      if (other.name == observer.name) reader.fail("name", "'" + observer.name + "' is used twice");
    scene.observers.push_back(observer);
  });
  {  // [output]
    SceneReader output(file, detail::table_or_empty(file, root, "output", false), "output");
    scene.control.sample_every = output.integer("every", 1, 1);
    scene.control.snapshot_times = output.numbers("snapshots", -1, std::vector<double>{});
    if (scene.control.snapshot_times.size() > 10'000) output.fail("snapshots", "at most 10000 times");
    for (double time : scene.control.snapshot_times)
      if (time < 0.0 || time > scene.control.end_time) output.fail("snapshots", "times must lie in [0, solver.end_time]");
    scene.control.sample_times = output.numbers("times", -1, std::vector<double>{});
    if (scene.control.sample_times.size() > 1'000'000) output.fail("times", "at most 1000000 times");
    for (size_t k = 0; k < scene.control.sample_times.size(); ++k) {
      const double time = scene.control.sample_times[k];
      if (time < 0.0 || time > scene.control.end_time) output.fail("times", "times must lie in [0, solver.end_time]");
      if (k > 0 && !(time > scene.control.sample_times[k - 1])) output.fail("times", "times must increase");
    }
    if (!scene.control.sample_times.empty() && scene.control.sample_every != 1)
      output.fail("every", "give output.every or output.times, not both (times replaces every)");
    output.reject_unknown_keys();
  }
  scene.formulas = read_scene_formulas(file, root, dim, scene.young_modulus, scene.poisson_ratio, scene.density);
  SceneReader parameters(file, detail::table_or_empty(file, root, "exact_parameters", false), "exact_parameters");
  scene.exact_mode = parameters.integer("mode", 1, 1, 1000);
  if (parameters.has("velocity_amplitude"))
    scene.exact_velocity_amplitude = detail::constant_or_formula(parameters, "velocity_amplitude", scene.formulas.constants).at(0);
  if (parameters.has("displacement_amplitude"))
    scene.exact_displacement_amplitude = detail::constant_or_formula(parameters, "displacement_amplitude", scene.formulas.constants);
  parameters.reject_unknown_keys();
  auto has_fixed = [&](int axis, bool upper, int component) {
    for (const auto& fixed : scene.fixed)
      if (fixed.axis == axis && fixed.upper == upper &&
          std::find(fixed.components.begin(), fixed.components.end(), component) != fixed.components.end())
        return true;
    return false;
  };
  // The exact solutions hold for one homogeneous body filling the box [origin, origin + length] (the bar,
  // the column): one [[body]] or several boxes side by side (layers of a column seeded differently, say),
  // all of the scene's [material]. Bodies never overlap (check_bodies_apart), so boxes inside the box whose
  // volumes add up to its volume fill it.
  if (scene.exact != "none")
    for (size_t k = 0; k < scene.bodies.size(); ++k)
      if (!(scene.bodies[k].material == MaterialSettings{scene.young_modulus, scene.poisson_ratio, scene.density}))
        SceneReader(file, *file.table["body"].as_array()->get(k)->as_table(), "body[" + std::to_string(k) + "]")
            .fail("min", "is of a material other than [material]'s: exact = \"" + scene.exact + "\" holds for one homogeneous body");
  auto fills_box = [&] {
    double volume = 0.0, box_volume = 1.0;
    for (int axis = 0; axis < dim; ++axis) box_volume *= scene.length[axis];
    for (const BodySettings& body : scene.bodies) {
      if (body.shape != "box") return false;
      double body_volume = 1.0;
      for (int axis = 0; axis < dim; ++axis) {
        if (body.min[axis] < scene.origin[axis] - 1e-9 * scene.spacing ||
            body.max[axis] > scene.origin[axis] + scene.length[axis] + 1e-9 * scene.spacing)
          return false;
        body_volume *= body.max[axis] - body.min[axis];
      }
      volume += body_volume;
    }
    return std::abs(volume - box_volume) <= 1e-9 * box_volume;
  };
  if (scene.exact == "dyka_bar" && !(dim == 1 && fills_box() && has_fixed(0, true, 0) && scene.gravity[0] == 0.0))
    root.fail("exact", "'dyka_bar' is the 1D bar free at xmin and fixed at xmax without gravity: needs dimension = 1, "
                       "[[body]] boxes filling [origin, origin + length], a [[fixed]] face = \"xmax\" holding \"x\", "
                       "and no gravity");
  if (scene.exact == "soil_column" &&
      !(dim == 2 && fills_box() && has_fixed(1, false, 1) && scene.gravity[0] == 0.0 && scene.gravity[1] < 0.0 &&
        (scene.poisson_ratio == 0.0 || (has_fixed(0, false, 0) && has_fixed(0, true, 0)))))
    root.fail("exact", "'soil_column' is the 2D column on a roller base under gravity: needs dimension = 2, [[body]] boxes "
                       "filling [origin, origin + length], a [[fixed]] face = \"ymin\" holding \"y\", "
                       "gravity.acceleration = [0, -g], and rollers on xmin and xmax unless poisson_ratio = 0");
  const bool manufactured = scene.exact == "manufactured_small" || scene.exact == "manufactured_large";
  if (scene.exact == "vibrating_bar") {
    if (!(dim == 1 && fills_box() && has_fixed(0, true, 0) && scene.gravity[0] == 0.0))
      root.fail("exact", "'vibrating_bar' is the 1D bar free at xmin and fixed at xmax without gravity: needs dimension = 1, "
                         "[[body]] boxes filling [origin, origin + length], a [[fixed]] face = \"xmax\" holding \"x\", "
                         "and no gravity");
    if (!scene.exact_velocity_amplitude)
      parameters.fail("velocity_amplitude", "required by exact = \"vibrating_bar\": the velocity amplitude V (m/s) of "
                                            "v(X, 0) = V cos((2 mode - 1) pi X / 2L)");
  } else {
    if (scene.exact_mode != 1) parameters.fail("mode", "only exact = \"vibrating_bar\" reads it");
    if (scene.exact_velocity_amplitude) parameters.fail("velocity_amplitude", "only exact = \"vibrating_bar\" reads it");
  }
  if (manufactured) {
    const bool small = scene.exact == "manufactured_small";
    auto holds = [&](int axis, int component) { return has_fixed(axis, false, component) && has_fixed(axis, true, component); };
    const bool supported = small ? holds(0, 0) && holds(0, 1) && holds(1, 0) && holds(1, 1) : holds(0, 0) && holds(1, 1);
    if (!(dim == 2 && fills_box() && std::abs(scene.length[0] - scene.length[1]) <= 1e-9 * scene.length[0] && supported &&
          scene.gravity[0] == 0.0 && scene.gravity[1] == 0.0))
      root.fail("exact", "'" + scene.exact + "' is the square [origin, origin + L]^2 in plane strain without gravity: needs "
                         "dimension = 2, equal grid lengths, [[body]] boxes filling the box, and " +
                         (small ? std::string("every face fixed in x and y") : std::string("rollers on every face (xmin, xmax holding \"x\"; ymin, ymax holding \"y\")")));
    if (scene.formulas.body_force || scene.formulas.initial_velocity || scene.formulas.initial_stress || !scene.initial_velocities.empty() ||
        std::any_of(scene.bodies[0].velocity.begin(), scene.bodies[0].velocity.end(), [](double v) { return v != 0.0; }))
      root.fail("exact", "'" + scene.exact + "' sets the body force and the initial velocity itself (mpm/exact/manufactured.hpp): "
                         "give no [body_force], [initial_field], [[initial_velocity]] or body velocity");
    const size_t count = small ? 1 : 2;
    if (scene.exact_displacement_amplitude.size() != count)
      parameters.fail("displacement_amplitude", small ? "required by exact = \"manufactured_small\": one amplitude A (m)"
                                                      : "required by exact = \"manufactured_large\": [a_x, a_y] (m)");
    const double wave_number = 3.14159265358979323846 / scene.length[0];
    if (small && !(std::abs(scene.exact_displacement_amplitude[0]) * wave_number < 0.01))
      parameters.fail("displacement_amplitude", "must be small: |A| pi / L < 0.01 (the small-strain solution; "
                                                "use manufactured_large for large amplitude)");
    if (!small && !(std::abs(scene.exact_displacement_amplitude[0]) * wave_number < 0.9 &&
                    2.0 * std::abs(scene.exact_displacement_amplitude[1]) * wave_number < 0.9))
      parameters.fail("displacement_amplitude", "too large: the stretches must stay positive, |a_x| pi / L < 0.9 and 2 |a_y| pi / L < 0.9");
  } else if (!scene.exact_displacement_amplitude.empty()) {
    parameters.fail("displacement_amplitude", "only exact = \"manufactured_small\" and \"manufactured_large\" read it");
  }
  root.reject_unknown_keys();
  std::ostringstream json;
  json << toml::json_formatter{file.table};
  scene.resolved_json = json.str();
  return scene;
}

TEST_CASE("Scene validation: a minimal scene reads, each kind of mistake names its key and line") {
  const std::string minimal =
      "dimension = 1\n[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[solver]\nend_time = 1.0\n";
  const auto scene = read_scene(parse_scene_text(minimal, "m.toml"));
  CHECK(scene.spacing == doctest::Approx(0.1));
  CHECK(scene.shape == "linear");
  CHECK(scene.bodies.at(0).particles_per_cell.at(0) == 1);

  auto message_of = [&](const std::string& text) -> std::string {
    try {
      read_scene(parse_scene_text(text, "m.toml"));
    } catch (const SceneError& error) {
      return error.message();
    }
    return "no error";
  };
  CHECK(message_of(minimal + "cfl = -2\n") == "error: m.toml:13: solver.cfl: must be > 0, got -2.000000");
  CHECK(message_of(minimal + "shape = \"quadratic\"\n") ==
        "error: m.toml:13: solver.shape: 'quadratic' is not allowed; use one of linear | ugimp | lme | bspline2 | bspline3");
  CHECK(message_of(minimal + "cfll = 0.5\n").rfind("error: m.toml:13: solver.cfll: unknown key", 0) == 0);
  CHECK(message_of(minimal + "[[body]]\nmin = [0.05]\nmax = [1.0]\n").rfind("error: m.toml:14: body[1].min: must lie on grid lines", 0) == 0);
  CHECK(message_of(minimal + "[[fixed]]\nface = \"ymin\"\ncomponents = [\"x\"]\n").rfind("error: m.toml:14: fixed[0].face:", 0) == 0);

  // A material per body: each key defaults to [material]'s; a bad one is located at its key; an exact
  // solution, which holds for one material, refuses a body of another.
  const std::string halves = "dimension = 1\n[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
                             "[[body]]\nmin = [0.0]\nmax = [0.5]\n[[body]]\nmin = [0.5]\nmax = [1.0]\ndensity = 3.0\n"
                             "[solver]\nend_time = 1.0\n";
  const Scene two = read_scene(parse_scene_text(halves, "m.toml"));
  CHECK(two.bodies.at(0).material == MaterialSettings{1.0, 0.0, 1.0});
  CHECK(two.bodies.at(1).material == MaterialSettings{1.0, 0.0, 3.0});
  CHECK(message_of(halves + "[[body]]\nmin = [0.0]\nmax = [0.1]\nyoung_modulus = -2.0\n").rfind("error: m.toml:20: body[2].young_modulus: must be > 0", 0) == 0);
  // Two boxes of [material]'s filling the bar are one homogeneous body: the exact solution takes them.
  std::string halves_alike = halves;
  halves_alike.replace(halves_alike.find("density = 3.0\n"), 14, "");
  CHECK(message_of("exact = \"dyka_bar\"\n" + halves_alike + "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n") == "no error");
  CHECK(message_of("exact = \"dyka_bar\"\n" + halves + "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n")
            .rfind("error: m.toml:13: body[1].min: is of a material other than [material]'s", 0) == 0);
}

}  // namespace mpm::io
