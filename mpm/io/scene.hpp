/// \file
/// Reading a scene: every key of the table of mpm/io/scene_keys.hpp read into a Scene, then the checks
/// that span keys, a few named functions in the order the scene's parts depend on each other.
///
/// Key names are a contract that outside tools rely on: keys may be added, never renamed.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "mpm/io/scene_keys.hpp"

namespace mpm::io {

namespace detail {

/// The table `key`, or an empty one when the scene has none (its required keys are then refused by name).
inline const toml::table& table_or_empty(const SceneFile& file, SceneReader& root, const std::string& key) {
  static const toml::table empty;
  if (!root.has(key)) return empty;
  const toml::table* table = file.table[key].as_table();
  if (!table) root.fail(key, "must be a table: write [" + key + "]");
  return *table;
}

/// Reads the keys of `section` from `reader` into entry k of its array (0 for a table), keeping where each lies.
inline void read_keys(SceneReader& reader, const std::string& section, Scene& scene, std::size_t k) {
  for (const SceneKey& key : scene_keys())
    if (key.section() == section && key.read) {
      key.read(reader, key, scene, k);
      scene.locations[reader.full(key.name())] = reader.location(key.name());
    }
}

inline void read_table(const SceneFile& file, SceneReader& root, const std::string& section, Scene& scene) {
  SceneReader reader(file, table_or_empty(file, root, section), section);
  read_keys(reader, section, scene, 0);
  reader.reject_unknown_keys();
}

/// Reads every table of the array of tables `section` ([[body]]): `add` appends the entry each fills, `check(k)`
/// checks entry k.
template <class Add, class Check>
void read_tables(const SceneFile& file, SceneReader& root, const std::string& section, Scene& scene, Add add, Check check) {
  if (!root.has(section)) return;
  const toml::array* array = file.table[section].as_array();
  if (!array || !array->is_array_of_tables()) root.fail(section, "must be an array of tables: write [[" + section + "]]");
  for (size_t k = 0; k < array->size(); ++k) {
    SceneReader reader(file, *(*array)[k].as_table(), section + "[" + std::to_string(k) + "]");
    add();
    read_keys(reader, section, scene, k);
    check(k);
    reader.reject_unknown_keys();
  }
}

/// True if `value` lies on a grid line of the axis (within 1e-6 of a cell).
inline bool on_grid_line(double value, double origin, double spacing) {
  const double cells = (value - origin) / spacing;
  return std::abs(cells - std::round(cells)) < 1e-6;
}

inline const char* axis_name(int axis) { return axis == 0 ? "x" : "y"; }

/// Refuses a point of `key` outside the grid (margins included), or off its lines when `on_lines`.
inline void check_inside_grid(const Scene& scene, const std::string& key, const std::vector<double>& point, bool on_lines) {
  for (int axis = 0; axis < scene.dimension; ++axis) {
    const double lower = scene.origin[axis] - scene.margin_min[axis] * scene.spacing;
    const double upper = scene.origin[axis] + scene.length[axis] + scene.margin_max[axis] * scene.spacing;
    if (point[axis] < lower - 1e-9 * scene.spacing || point[axis] > upper + 1e-9 * scene.spacing)
      throw scene_error(scene, key, "lies outside the grid [" + std::to_string(lower) + ", " + std::to_string(upper) + "] on " + axis_name(axis));
    if (on_lines && !on_grid_line(point[axis], scene.origin[axis], scene.spacing))
      throw scene_error(scene, key, "must lie on grid lines (multiples of the cell size " + std::to_string(scene.spacing) + " from the origin)");
  }
}

inline void check_title(const Scene& scene) {
  for (unsigned char character : scene.title)  // it is a line of the VTK header and of the progress line
    if (character < 0x20 || character == 0x7f)
      throw scene_error(scene, "title", "must be one line of printable text (no newline, tab or control character)");
}

/// The cell size, the grid's lines distinct numbers where it lies, and square cells.
inline void check_grid(Scene& scene) {
  scene.spacing = scene.length[0] / scene.cells[0];
  for (int axis = 0; axis < scene.dimension; ++axis) {
    const double far = std::max(std::abs(scene.origin[axis]), std::abs(scene.origin[axis] + scene.length[axis])) +
                       (std::max(scene.margin_min[axis], scene.margin_max[axis]) + 1.0) * scene.spacing;
    if (!(scene.spacing > 1e-9 * far) || !std::isfinite(far))
      throw scene_error(scene, "grid.origin", "too far from 0 for the cell size " + SceneReader::describe(scene.spacing) +
                                                  ": the grid must lie within 1e9 cells of the origin of coordinates");
  }
  for (int axis = 1; axis < scene.dimension; ++axis)
    if (std::abs(scene.length[axis] / scene.cells[axis] - scene.spacing) > 1e-9 * scene.spacing)
      throw scene_error(scene, "grid.cells", "cells must be square: length/cells must be equal on every axis");
}

/// True if the segments [a, b] and [c, d] have a point in common.
inline bool segments_meet(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
                          const std::array<double, 2>& d) {
  auto side = [](const auto& p, const auto& q, const auto& r) {
    const double cross = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    return (cross > 0.0) - (cross < 0.0);
  };
  auto within = [](const auto& p, const auto& q, const auto& r) {  // r on the line pq: inside its box
    return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
  };
  const int s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
  if (s1 * s2 < 0 && s3 * s4 < 0) return true;
  return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) || (s3 == 0 && within(c, d, a)) || (s4 == 0 && within(c, d, b));
}

/// The first two edges of the polygon that meet other than at a shared vertex; {-1, -1} when it is simple.
/// Edge k runs from vertex k to vertex k + 1 (the last back to the first).
inline std::array<int, 2> crossing_edges(const std::vector<std::array<double, 2>>& vertices) {
  const int n = static_cast<int>(vertices.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing vertex
      if (segments_meet(vertices[i], vertices[(i + 1) % n], vertices[j], vertices[(j + 1) % n])) return {i, j};
    }
  return {-1, -1};
}

/// A polygon's vertices: given exactly for shape = "polygon", inside the body's box, the polygon simple.
inline void check_vertices(const Scene& scene, std::size_t k) {
  const BodySettings& body = scene.bodies[k];
  const std::string key = "body[" + std::to_string(k) + "].vertices";
  if (body.shape != BodyShape::Kind::polygon) {
    if (!body.vertices.empty()) throw scene_error(scene, key, "only a body of shape = \"polygon\" has vertices");
    return;
  }
  if (body.vertices.empty()) throw scene_error(scene, key, "missing; a polygon needs its vertices, [[x, y], ...] (m)");
  for (size_t v = 0; v < body.vertices.size(); ++v)
    for (int axis = 0; axis < 2; ++axis)
      if (body.vertices[v][axis] < body.min[axis] - 1e-9 * scene.spacing || body.vertices[v][axis] > body.max[axis] + 1e-9 * scene.spacing)
        throw scene_error(scene, key, "vertex " + std::to_string(v) + " lies outside the body's box [min, max]: "
                                      "the box is the cells seeded, the polygon the part kept");
  const auto [i, j] = crossing_edges(body.vertices);
  if (i >= 0)
    throw scene_error(scene, key, "edges " + std::to_string(i) + " and " + std::to_string(j) + " meet (edge k runs from vertex k to k + 1): "
                                  "a polygon must be simple, its edges meeting only at the vertices they share");
}

/// A body's particle file, read and every particle checked to lie in the body's box.
inline void read_body_file(const SceneFile& file, Scene& scene, std::size_t k) {
  BodySettings& body = scene.bodies[k];
  const std::string key = "body[" + std::to_string(k) + "].file";
  if (body.file.empty()) {
    if (body.shape == BodyShape::Kind::file)
      throw scene_error(scene, key, "missing; a body of shape = \"file\" reads its particles from a CSV file (x[,y],volume|mass[,v_x[,v_y]])");
    return;
  }
  if (body.shape != BodyShape::Kind::file) throw scene_error(scene, key, "only a body of shape = \"file\" reads a particle file");
  namespace fs = std::filesystem;
  const fs::path path = fs::path(body.file).is_absolute() ? fs::path(body.file) : fs::path(file.path).parent_path() / body.file;
  std::string problem;
  body.particles = read_particle_file(path.string(), scene.dimension, body.material.density, body.velocity, problem);
  if (!problem.empty()) throw scene_error(scene, key, problem);
  for (size_t p = 0; p < body.particles.size(); ++p) {
    const double position[2] = {body.particles[p].x, body.particles[p].y};
    for (int axis = 0; axis < scene.dimension; ++axis)
      if (position[axis] < body.min[axis] || position[axis] > body.max[axis])
        throw scene_error(scene, key, path.string() + ": particle " + std::to_string(p + 1) + " lies outside the body's box [min, max] on " +
                                      axis_name(axis) + ": the box must hold the file's particles");
  }
}

inline void check_body(const SceneFile& file, Scene& scene, std::size_t k) {
  const BodySettings& body = scene.bodies[k];
  const std::string at = "body[" + std::to_string(k) + "].";
  check_inside_grid(scene, at + "min", body.min, true);
  check_inside_grid(scene, at + "max", body.max, true);
  for (int axis = 0; axis < scene.dimension; ++axis)
    if (!(body.max[axis] > body.min[axis] + 0.5 * scene.spacing)) throw scene_error(scene, at + "max", "must exceed min by at least one cell");
  if (body.placement == Placement::gauss)
    for (int ppc : body.particles_per_cell)
      if (ppc != 2) throw scene_error(scene, at + "placement", "'gauss' needs particles_per_cell = 2 on every axis");
  if (scene.dimension == 1 && (body.shape == BodyShape::Kind::ellipse || body.shape == BodyShape::Kind::polygon))
    throw scene_error(scene, at + "shape", "a 1D body is a box or a file (ellipse and polygon are 2D shapes)");
  read_body_file(file, scene, k);
  check_vertices(scene, k);
}

/// The most seeds times polygon vertices that the test of two bodies apart evaluates (about a second).
inline constexpr double most_shape_tests = 4e8;

/// Bodies may not overlap: a particle of one may not lie in another (its box cut by its shape). Boxes whose
/// interiors meet overlap; where a shape cuts one of them, the particles of the second body in the common
/// box are tested against the first (at most 4e6 of them, and most_shape_tests seeds times vertices:
/// beyond, the boxes must be apart).
/// \throws SceneError at the second body's min, naming the first body and where its min lies.
inline void check_bodies_apart(const Scene& scene) {
  const int dim = scene.dimension;
  auto where_is_body = [&](size_t k) {
    const auto& [file, line] = scene.locations.at("body[" + std::to_string(k) + "].min");
    return file + ":" + std::to_string(line);
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
      using Kind = BodyShape::Kind;
      bool overlap = (first.shape == Kind::box && second.shape == Kind::box) || first.shape == Kind::file || second.shape == Kind::file;
      const double vertices = static_cast<double>(first.vertices.size() + second.vertices.size());
      if (!overlap && (seeds > 4e6 || seeds * vertices > most_shape_tests)) overlap = true;
      if (!overlap) {
        const BodyShape shape_first = body_shape(first), shape_second = body_shape(second);
        auto visit = [&](const auto& x) {
          overlap = shape_second.holds(x[0], x[dim - 1]) && shape_first.holds(x[0], x[dim - 1]);
          return !overlap;
        };
        Vector<2> origin(scene.origin[0], dim == 2 ? scene.origin[1] : 0.0);
        std::array<int, 2> ppc{second.particles_per_cell[0], second.particles_per_cell[dim - 1]};
        if (dim == 2) for_each_seed<2>(origin, scene.spacing, lower, upper, ppc, second.placement, visit);
        else for_each_seed<1>(Vector<1>(origin[0]), scene.spacing, Vector<1>(lower[0]), Vector<1>(upper[0]), {ppc[0]}, second.placement, visit);
      }
      if (overlap)
        throw scene_error(scene, "body[" + std::to_string(j) + "].min",
                          "overlaps body[" + std::to_string(i) + "] (" + where_is_body(i) +
                              "): a particle of one would lie in the other; move them apart (their boxes may touch)");
    }
}

inline void check_fixed(const Scene& scene, std::size_t k) {
  if (scene.dimension == 1 && scene.fixed[k].axis() == 1)
    throw scene_error(scene, "fixed[" + std::to_string(k) + "].face",
                      "'" + name_of(scene.fixed[k].face) + "' is not allowed; use one of xmin | xmax");
}

/// LME's support must reach a cell's corners; the predictor-corrector updates stress first.
inline void check_solver(const SceneFile& file, const Scene& scene) {
  // The LME support radius R = h sqrt(-ln(tol)/gamma) must reach the corners of a particle's cell
  // (its convex hull), R >= h sqrt(dimension): gamma <= -ln(tol)/dimension. The key blamed is the
  // one the user changed: lme_tol when it is given and lme_gamma is not overridden, else lme_gamma.
  const int dim = scene.dimension;
  if (scene.shape == ShapeKind::lme && scene.lme_gamma > -std::log(scene.lme_tol) / dim) {
    if (file.table["solver"]["lme_tol"] && !file.overridden.count("solver.lme_gamma"))
      throw scene_error(scene, "solver.lme_tol", "too large for lme_gamma = " + SceneReader::describe(scene.lme_gamma) +
                                                     ": the support must reach the corners of a cell, lme_tol <= exp(-lme_gamma * dimension) = " +
                                                     SceneReader::describe(std::exp(-scene.lme_gamma * dim)));
    throw scene_error(scene, "solver.lme_gamma", "too large for lme_tol = " + SceneReader::describe(scene.lme_tol) +
                                                     ": the support must reach the corners of a cell, lme_gamma <= -ln(lme_tol)/dimension = " +
                                                     SceneReader::describe(-std::log(scene.lme_tol) / dim));
  }
  if (scene.integrator == IntegratorKind::npc && scene.stress_update != StressUpdate::usf)
    throw scene_error(scene, "solver.stress_update", "the predictor-corrector updates stress first (\"usf\"); usl and musl are forward Euler's");
}

/// The box an exact solution holds for: [origin, origin + length], the soil column's as high as its bodies.
inline std::vector<double> exact_length(const Scene& scene) {
  std::vector<double> length = scene.length;
  if (scene.exact == ExactKind::soil_column && scene.dimension == 2) length[1] = column_height(scene);
  return length;
}

/// An observer inside the grid, inside the exact solution's body when there is one, named for a CSV column.
inline void check_observer(const Scene& scene, std::size_t k) {
  const ObserverSettings& observer = scene.observers[k];
  const std::string at = "observer[" + std::to_string(k) + "].";
  check_inside_grid(scene, at + "position", observer.position, false);
  // The observer names a material point by its reference position: exact.csv is evaluated there, so it
  // must be a point of the body the exact solution holds for.
  const std::vector<double> length = exact_length(scene);
  for (int axis = 0; scene.exact != ExactKind::none && axis < scene.dimension; ++axis)
    if (observer.position[axis] < scene.origin[axis] - 1e-9 * scene.spacing ||
        observer.position[axis] > scene.origin[axis] + length[axis] + 1e-9 * scene.spacing)
      throw scene_error(scene, at + "position", "lies outside the body [" + SceneReader::describe(scene.origin[axis]) + ", " +
                                                    SceneReader::describe(scene.origin[axis] + length[axis]) + "] on " + axis_name(axis) +
                                                    ", where exact = \"" + name_of(scene.exact) + "\" is evaluated for exact.csv");
  if (observer.name.empty() || observer.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
    throw scene_error(scene, at + "name", "required; letters, digits and _ only (it names CSV columns)");
  for (size_t other = 0; other < k; ++other)
    if (scene.observers[other].name == observer.name) throw scene_error(scene, at + "name", "'" + observer.name + "' is used twice");
}

inline void check_output(const Scene& scene) {
  const RunControl& control = scene.control;
  if (control.snapshot_times.size() > 10'000) throw scene_error(scene, "output.snapshots", "at most 10000 times");
  for (double time : control.snapshot_times)
    if (time < 0.0 || time > control.end_time) throw scene_error(scene, "output.snapshots", "times must lie in [0, solver.end_time]");
  if (control.sample_times.size() > 1'000'000) throw scene_error(scene, "output.times", "at most 1000000 times");
  for (size_t k = 0; k < control.sample_times.size(); ++k) {
    const double time = control.sample_times[k];
    if (time < 0.0 || time > control.end_time) throw scene_error(scene, "output.times", "times must lie in [0, solver.end_time]");
    if (k > 0 && !(time > control.sample_times[k - 1])) throw scene_error(scene, "output.times", "times must increase");
  }
  if (!control.sample_times.empty() && control.sample_every != 1)
    throw scene_error(scene, "output.every", "give output.every or output.times, not both (times replaces every)");
}

/// True if [[fixed]] holds velocity `component` on the face (`axis`, `upper`).
inline bool has_fixed(const Scene& scene, int axis, bool upper, int component) {
  for (const auto& fixed : scene.fixed)
    if (fixed.axis() == axis && fixed.upper() == upper &&
        std::find(fixed.components.begin(), fixed.components.end(), component) != fixed.components.end())
      return true;
  return false;
}

/// True if the bodies, all boxes, fill the box of the exact solution, [origin, origin + exact_length]: boxes
/// inside it whose volumes add up to its volume fill it, since bodies never overlap (check_bodies_apart).
inline bool fills_exact_box(const Scene& scene) {
  const std::vector<double> length = exact_length(scene);
  double volume = 0.0, box_volume = 1.0;
  for (int axis = 0; axis < scene.dimension; ++axis) box_volume *= length[axis];
  for (const BodySettings& body : scene.bodies) {
    if (body.shape != BodyShape::Kind::box) return false;
    double body_volume = 1.0;
    for (int axis = 0; axis < scene.dimension; ++axis) {
      if (body.min[axis] < scene.origin[axis] - 1e-9 * scene.spacing || body.max[axis] > scene.origin[axis] + length[axis] + 1e-9 * scene.spacing)
        return false;
      body_volume *= body.max[axis] - body.min[axis];
    }
    volume += body_volume;
  }
  return std::abs(volume - box_volume) <= 1e-9 * box_volume;
}

/// The exact solutions hold for one homogeneous body filling their box (the bar, the column, the square):
/// one [[body]] or several boxes side by side, all of the scene's [material], held and loaded as the solution is.
inline void check_exact_setup(const Scene& scene) {
  for (size_t k = 0; k < scene.bodies.size(); ++k)
    if (!(scene.bodies[k].material == scene.material()))
      throw scene_error(scene, "body[" + std::to_string(k) + "].min", "is of a material other than [material]'s: exact = \"" +
                                                                          name_of(scene.exact) + "\" holds for one homogeneous body");
  const int dim = scene.dimension;
  const bool fills = fills_exact_box(scene);
  const std::string bar = "is the 1D bar free at xmin and fixed at xmax without gravity: needs dimension = 1, [[body]] boxes "
                          "filling [origin, origin + length], a [[fixed]] face = \"xmax\" holding \"x\", and no gravity";
  const std::string& name = name_of(scene.exact);
  if ((scene.exact == ExactKind::dyka_bar || scene.exact == ExactKind::vibrating_bar) &&
      !(dim == 1 && fills && has_fixed(scene, 0, true, 0) && scene.gravity[0] == 0.0))
    throw scene_error(scene, "exact", "'" + name + "' " + bar);
  if (scene.exact == ExactKind::soil_column &&
      !(dim == 2 && fills && has_fixed(scene, 1, false, 1) && scene.gravity[0] == 0.0 && scene.gravity[1] < 0.0 &&
        (scene.poisson_ratio == 0.0 || (has_fixed(scene, 0, false, 0) && has_fixed(scene, 0, true, 0)))))
    throw scene_error(scene, "exact", "'soil_column' is the 2D column on a roller base under gravity: needs dimension = 2, [[body]] boxes "
                                      "filling [origin, origin + (length_x, H)] up to their top H, a [[fixed]] face = \"ymin\" holding \"y\", "
                                      "gravity.acceleration = [0, -g], and rollers on xmin and xmax unless poisson_ratio = 0");
  if (scene.exact != ExactKind::manufactured_small && scene.exact != ExactKind::manufactured_large) return;
  const bool small = scene.exact == ExactKind::manufactured_small;
  auto holds = [&](int axis, int component) { return has_fixed(scene, axis, false, component) && has_fixed(scene, axis, true, component); };
  const bool supported = small ? holds(0, 0) && holds(0, 1) && holds(1, 0) && holds(1, 1) : holds(0, 0) && holds(1, 1);
  if (!(dim == 2 && fills && std::abs(scene.length[0] - scene.length[1]) <= 1e-9 * scene.length[0] && supported &&
        scene.gravity[0] == 0.0 && scene.gravity[1] == 0.0))
    throw scene_error(scene, "exact", "'" + name + "' is the square [origin, origin + L]^2 in plane strain without gravity: needs "
                                      "dimension = 2, equal grid lengths, [[body]] boxes filling the box, and " +
                                      (small ? std::string("every face fixed in x and y") : std::string("rollers on every face (xmin, xmax holding \"x\"; ymin, ymax holding \"y\")")));
  if (scene.formulas.body_force || scene.formulas.initial_velocity || scene.formulas.initial_stress || !scene.initial_velocities.empty() ||
      std::any_of(scene.bodies[0].velocity.begin(), scene.bodies[0].velocity.end(), [](double v) { return v != 0.0; }))
    throw scene_error(scene, "exact", "'" + name + "' sets the body force and the initial velocity itself (mpm/exact/manufactured.hpp): "
                                      "give no [body_force], [initial_field], [[initial_velocity]] or body velocity");
}

/// [exact_parameters]: each key given only to the solution that reads it, and required by it.
inline void check_exact_parameters(const Scene& scene) {
  const std::string mode = "exact_parameters.mode", velocity = "exact_parameters.velocity_amplitude",
                    displacement = "exact_parameters.displacement_amplitude";
  if (scene.exact == ExactKind::vibrating_bar) {
    if (!scene.exact_velocity_amplitude)
      throw scene_error(scene, velocity, "required by exact = \"vibrating_bar\": the velocity amplitude V (m/s) of "
                                         "v(X, 0) = V cos((2 mode - 1) pi X / 2L)");
  } else {
    if (scene.exact_mode != 1) throw scene_error(scene, mode, "only exact = \"vibrating_bar\" reads it");
    if (scene.exact_velocity_amplitude) throw scene_error(scene, velocity, "only exact = \"vibrating_bar\" reads it");
  }
  const std::vector<double>& a = scene.exact_displacement_amplitude;
  if (scene.exact != ExactKind::manufactured_small && scene.exact != ExactKind::manufactured_large) {
    if (!a.empty()) throw scene_error(scene, displacement, "only exact = \"manufactured_small\" and \"manufactured_large\" read it");
    return;
  }
  const bool small = scene.exact == ExactKind::manufactured_small;
  if (a.size() != (small ? 1u : 2u))
    throw scene_error(scene, displacement, small ? "required by exact = \"manufactured_small\": one amplitude A (m)"
                                                 : "required by exact = \"manufactured_large\": [a_x, a_y] (m)");
  const double wave_number = 3.14159265358979323846 / scene.length[0];
  if (small && !(std::abs(a[0]) * wave_number < 0.01))
    throw scene_error(scene, displacement, "must be small: |A| pi / L < 0.01 (the small-strain solution; use manufactured_large for large amplitude)");
  if (!small && !(std::abs(a[0]) * wave_number < 0.9 && 2.0 * std::abs(a[1]) * wave_number < 0.9))
    throw scene_error(scene, displacement, "too large: the stretches must stay positive, |a_x| pi / L < 0.9 and 2 |a_y| pi / L < 0.9");
}

inline void check_exact(const Scene& scene) {
  if (scene.exact != ExactKind::none) check_exact_setup(scene);
  check_exact_parameters(scene);
}

}  // namespace detail

/// Reads and validates every key of the scene. \throws SceneError at the first problem.
inline Scene read_scene(const SceneFile& file) {
  using namespace detail;
  Scene scene;
  scene.file = file.path;
  SceneReader root(file, file.table, "");
  read_keys(root, "", scene, 0);
  check_title(scene);
  read_table(file, root, "grid", scene);
  check_grid(scene);
  read_table(file, root, "material", scene);
  auto add_body = [&] {
    scene.bodies.emplace_back();
    scene.bodies.back().material = scene.material();  // a body's own material keys default to [material]'s
  };
  read_tables(file, root, "body", scene, add_body, [&](size_t k) { check_body(file, scene, k); });
  if (scene.bodies.empty()) root.fail("body", "the scene needs at least one [[body]]");
  check_bodies_apart(scene);
  read_tables(file, root, "initial_velocity", scene, [&] { scene.initial_velocities.emplace_back(); }, [](size_t) {});
  read_tables(file, root, "fixed", scene, [&] { scene.fixed.emplace_back(); }, [&](size_t k) { check_fixed(scene, k); });
  read_table(file, root, "gravity", scene);
  read_table(file, root, "solver", scene);
  check_solver(file, scene);
  read_tables(file, root, "observer", scene, [&] { scene.observers.emplace_back(); }, [&](size_t k) { check_observer(scene, k); });
  read_table(file, root, "output", scene);
  check_output(scene);
  scene.formulas = read_scene_formulas(file, root, scene.dimension, scene.young_modulus, scene.poisson_ratio, scene.density);
  read_table(file, root, "exact_parameters", scene);
  check_exact(scene);
  root.reject_unknown_keys();
  return scene;
}

TEST_CASE("Scene validation: a minimal scene reads, each kind of mistake names its key and line") {
  const std::string minimal =
      "dimension = 1\n[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[solver]\nend_time = 1.0\n";
  const auto scene = read_scene(parse_scene_text(minimal, "m.toml"));
  CHECK(scene.spacing == doctest::Approx(0.1));
  CHECK(scene.shape == ShapeKind::linear);
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

TEST_CASE("Scene validation: integers of any size, a missing table at its required key, polygons that cross themselves") {
  const std::string minimal =
      "dimension = 1\n[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[solver]\nend_time = 1.0\n";
  auto message_of = [](const std::string& text, const std::vector<std::string>& overrides = {}) -> std::string {
    try {
      SceneFile file = parse_scene_text(text, "m.toml");
      for (size_t k = 0; k < overrides.size(); ++k) apply_override(file, overrides[k], static_cast<int>(k) + 1);
      read_scene(file);
    } catch (const SceneError& error) {
      return error.message();
    }
    return "no error";
  };
  // 2^63 - 1 is an integer toml++ holds exactly but no double does: checked as the integer written
  CHECK(message_of(minimal, {"grid.margin_max=[9223372036854775807]"}) ==
        "error: --set(1):1: grid.margin_max: entries must be whole numbers in [0, 100000000], got 9223372036854775807");
  CHECK(message_of(minimal, {"grid.cells=[9223372036854775807]"}).find("got 9223372036854775807") != std::string::npos);
  CHECK(message_of(minimal, {"output.snapshots=[9223372036854775807]"}) ==
        "error: --set(1):1: output.snapshots: times must lie in [0, solver.end_time]");
  CHECK(message_of(minimal, {"dimension=-9223372036854775808"}) ==
        "error: --set(1):1: dimension: must be an integer in [1, 2], got -9223372036854775808");
  // a required table the scene lacks: refused at its first required key, never at line 0
  CHECK(message_of(minimal.substr(0, minimal.find("[solver]"))) == "error: m.toml:1: solver.end_time: missing; a number is required");
  CHECK(message_of("[solver]\nend_time = 1.0\n") == "error: m.toml:1: grid.length: missing; an array of 1 numbers is required");
  // a polygon must be simple: the bow tie (0,0), (1,1), (1,0), (0,1) crosses itself
  const std::string square = "dimension = 2\n[grid]\nlength = [1.0, 1.0]\ncells = [10, 10]\n[material]\nyoung_modulus = 1.0\n"
                             "density = 1.0\n[[body]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\nshape = \"polygon\"\n";
  CHECK(message_of(square + "vertices = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]\n[solver]\nend_time = 1.0\n") ==
        "error: m.toml:12: body[0].vertices: edges 0 and 2 meet (edge k runs from vertex k to k + 1): a polygon must be simple, "
        "its edges meeting only at the vertices they share");
  CHECK(message_of(square + "vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]\n[solver]\nend_time = 1.0\n") == "no error");
  CHECK(detail::crossing_edges({{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {1.0, 0.0}, {0.0, 2.0}})[0] >= 0);  // a vertex on an edge
  CHECK(detail::crossing_edges({{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.5, 0.2}, {0.0, 1.0}})[0] == -1);  // concave, simple
}

}  // namespace mpm::io
