/// \file
/// Reading a scene: every key of the table of mpm/io/scene_keys.hpp read into a Scene, then the checks across
/// keys, a few named functions in the order the scene's parts depend on each other. Key names are a contract
/// that outside tools rely on: keys may be added, never renamed.
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

/// Reads the keys of `section` from `reader` into entry k of its array (0 for a table), keeping where each lies.
inline void read_keys(SceneReader& reader, const std::string& section, Scene& scene, std::size_t k) {
  for (const SceneKey& key : scene_keys())
    if (key.section() == section && key.read) {
      key.read(reader, key, scene, k);
      scene.locations[reader.full(key.name())] = reader.location(key.name());
    }
}

/// Reads the table `section` ([grid]); a scene without it has its required keys refused by name.
inline void read_table(const SceneFile& file, SceneReader& root, const std::string& section, Scene& scene) {
  SceneReader reader(file, table_or_empty(file, root, section), section);
  read_keys(reader, section, scene, 0);
  reader.reject_unknown_keys();
}

/// Reads each table of the array of tables `section` ([[body]]) into a copy of `fresh` appended to `entries`
/// (the scene's own list), then check(k) checks entry k.
template <class Entry, class Check>
void read_tables(const SceneFile& file, SceneReader& root, const std::string& section, Scene& scene,
                 std::vector<Entry>& entries, const Entry& fresh, Check check) {
  if (!root.has(section)) return;
  const toml::array* array = file.table[section].as_array();
  if (!array || !array->is_array_of_tables())
    root.fail(section, "must be an array of tables: write [[" + section + "]]");
  for (size_t k = 0; k < array->size(); ++k) {
    SceneReader reader(file, *(*array)[k].as_table(), section + "[" + std::to_string(k) + "]");
    entries.push_back(fresh);
    read_keys(reader, section, scene, k);
    check(k);
    reader.reject_unknown_keys();
  }
}

/// Throws the scene's error at `key` unless `holds`.
inline void require(bool holds, const Scene& scene, const std::string& key, const std::string& what) {
  if (!holds) throw scene_error(scene, key, what);
}

/// "body[k].": the start of the keys of entry k of the array of tables `section`.
inline std::string entry_key(const char* section, std::size_t k) { return section + ("[" + std::to_string(k) + "]."); }

/// True if `value` lies in [low, high], widened by a billionth of a cell for round-off.
inline bool in_span(const Scene& scene, double value, double low, double high) {
  return value >= low - 1e-9 * scene.spacing && value <= high + 1e-9 * scene.spacing;
}

/// Refuses a point of `key` outside the grid (margins included), or off its lines when `on_lines`.
inline void check_inside_grid(const Scene& scene, const std::string& key, const std::vector<double>& point,
                              bool on_lines) {
  for (int axis = 0; axis < scene.dimension; ++axis) {
    const double lower = scene.origin[axis] - scene.margin_min[axis] * scene.spacing;
    const double upper = scene.origin[axis] + scene.length[axis] + scene.margin_max[axis] * scene.spacing;
    const double cells = (point[axis] - scene.origin[axis]) / scene.spacing;
    require(in_span(scene, point[axis], lower, upper), scene, key,
            "lies outside the grid [" + std::to_string(lower) + ", " + std::to_string(upper) + "] on " +
                axis_name(axis));
    require(!on_lines || std::abs(cells - std::round(cells)) < 1e-6, scene, key,
            "must lie on grid lines (multiples of the cell size " + std::to_string(scene.spacing) +
                " from the origin)");
  }
}

/// The cell size, the grid's lines distinct numbers where it lies, and square cells.
inline void check_grid(Scene& scene) {
  scene.spacing = scene.length[0] / scene.cells[0];
  for (int axis = 0; axis < scene.dimension; ++axis) {
    const double far = std::max(std::abs(scene.origin[axis]), std::abs(scene.origin[axis] + scene.length[axis])) +
                       (std::max(scene.margin_min[axis], scene.margin_max[axis]) + 1.0) * scene.spacing;
    require(scene.spacing > 1e-9 * far && std::isfinite(far), scene, "grid.origin",
            "too far from 0 for the cell size " + SceneReader::describe(scene.spacing) +
                ": the grid must lie within 1e9 cells of the origin of coordinates");
    const double spacing = scene.length[axis] / scene.cells[axis];
    require(std::abs(spacing - scene.spacing) <= 1e-9 * scene.spacing, scene, "grid.cells",
            "cells must be square: length/cells must be equal on every axis");
  }
}

using Point = std::array<double, 2>;

/// True if the segments [a, b] and [c, d] have a point in common.
inline bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  auto side = [](const auto& p, const auto& q, const auto& r) {  // the sign of (q - p) x (r - p)
    const double cross = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    return (cross > 0.0) - (cross < 0.0);
  };
  auto on = [&](const auto& p, const auto& q, const auto& r) {  // r on the segment [p, q]
    return side(p, q, r) == 0 && std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
           std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
  };
  return (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) || on(a, b, c) || on(a, b, d) ||
         on(c, d, a) || on(c, d, b);
}

/// The first two edges of the polygon that meet other than at a shared vertex; {-1, -1} when it is simple.
/// Edge k runs from vertex k to vertex k + 1 (the last back to the first).
inline std::array<int, 2> crossing_edges(const std::vector<Point>& vertices) {
  const int n = static_cast<int>(vertices.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n && !(i == 0 && j == n - 1); ++j)  // not neighbours through the closing vertex
      if (segments_meet(vertices[i], vertices[i + 1], vertices[j], vertices[(j + 1) % n])) return {i, j};
  return {-1, -1};
}

/// A polygon's vertices: given exactly for shape = "polygon", inside the body's box, the polygon simple.
inline void check_vertices(const Scene& scene, std::size_t k) {
  const BodySettings& body = scene.bodies[k];
  const std::string key = entry_key("body", k) + "vertices";
  const bool polygon = body.shape == BodyShape::Kind::polygon;
  require(polygon || body.vertices.empty(), scene, key, "only a body of shape = \"polygon\" has vertices");
  require(!polygon || !body.vertices.empty(), scene, key, "missing; a polygon needs its vertices, [[x, y], ...] (m)");
  for (size_t v = 0; v < body.vertices.size(); ++v)
    for (int axis = 0; axis < 2; ++axis)
      if (!in_span(scene, body.vertices[v][axis], body.min[axis], body.max[axis]))
        throw scene_error(scene, key, "vertex " + std::to_string(v) + " lies outside the body's box [min, max]: "
                                      "the box is the cells seeded, the polygon the part kept");
  const auto [i, j] = crossing_edges(body.vertices);
  require(i < 0, scene, key,
          "edges " + std::to_string(i) + " and " + std::to_string(j) + " meet (edge k runs from vertex k to k + 1): " +
              "a polygon must be simple, its edges meeting only at the vertices they share");
}

/// The path of a body's particle file: as written when absolute, else from the scene file's folder.
inline std::string particle_file_path(const Scene& scene, const BodySettings& body) {
  return (std::filesystem::path(scene.file).parent_path() / body.file).string();
}

/// A body's particle file, given exactly for shape = "file", read, every particle checked to lie in the body's box.
inline void read_body_file(Scene& scene, std::size_t k) {
  BodySettings& body = scene.bodies[k];
  const std::string key = entry_key("body", k) + "file", path = particle_file_path(scene, body);
  const bool from_file = body.shape == BodyShape::Kind::file;
  require(!from_file || !body.file.empty(), scene, key,
          "missing; a body of shape = \"file\" reads its particles from a CSV file (x[,y],volume|mass[,v_x[,v_y]])");
  require(from_file || body.file.empty(), scene, key, "only a body of shape = \"file\" reads a particle file");
  if (!from_file) return;
  std::string problem;
  body.particles = read_particle_file(path, scene.dimension, body.material.density, body.velocity, problem);
  require(problem.empty(), scene, key, problem);
  for (size_t p = 0; p < body.particles.size(); ++p)
    for (int axis = 0; axis < scene.dimension; ++axis) {
      const double position = axis == 0 ? body.particles[p].x : body.particles[p].y;
      if (position < body.min[axis] || position > body.max[axis])
        throw scene_error(scene, key, path + ": particle " + std::to_string(p + 1) + " lies outside the body's box " +
                                          "[min, max] on " + axis_name(axis) +
                                          ": the box must hold the file's particles");
    }
}

/// A body's box on grid lines, a cell wide at least; its placement, its shape, its particle file and vertices.
inline void check_body(Scene& scene, std::size_t k) {
  const BodySettings& body = scene.bodies[k];
  const std::string at = entry_key("body", k);
  check_inside_grid(scene, at + "min", body.min, true);
  check_inside_grid(scene, at + "max", body.max, true);
  for (int axis = 0; axis < scene.dimension; ++axis)
    require(body.max[axis] > body.min[axis] + 0.5 * scene.spacing, scene, at + "max",
            "must exceed min by at least one cell");
  const auto& ppc = body.particles_per_cell;
  require(body.placement != Placement::gauss || std::count(ppc.begin(), ppc.end(), 2) == static_cast<long>(ppc.size()),
          scene, at + "placement", "'gauss' needs particles_per_cell = 2 on every axis");
  const bool shape_2d = body.shape == BodyShape::Kind::ellipse || body.shape == BodyShape::Kind::polygon;
  require(scene.dimension == 2 || !shape_2d, scene, at + "shape",
          "a 1D body is a box or a file (ellipse and polygon are 2D shapes)");
  read_body_file(scene, k);
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
  using Kind = BodyShape::Kind;
  for (size_t j = 1; j < scene.bodies.size(); ++j)
    for (size_t i = 0; i < j; ++i) {
      const BodySettings &first = scene.bodies[i], &second = scene.bodies[j];
      Vector<2> lower = Vector<2>::Zero(), upper = Vector<2>::Zero();
      double seeds = 1.0;
      bool apart = false;
      for (int axis = 0; axis < scene.dimension; ++axis) {
        lower[axis] = std::max(first.min[axis], second.min[axis]);
        upper[axis] = std::min(first.max[axis], second.max[axis]);
        apart = apart || upper[axis] - lower[axis] < 0.5 * scene.spacing;  // on grid lines: apart, or a cell in common
        seeds *= (upper[axis] - lower[axis]) / scene.spacing * second.particles_per_cell[axis];
      }
      if (apart) continue;
      const double tests = seeds * static_cast<double>(first.vertices.size() + second.vertices.size());
      bool overlap = (first.shape == Kind::box && second.shape == Kind::box) || first.shape == Kind::file ||
                     second.shape == Kind::file || seeds > 4e6 || tests > most_shape_tests;
      if (!overlap) {  // two shapes, so 2D: does a seed of the second lie in both?
        const BodyShape shape_first = body_shape(first), shape_second = body_shape(second);
        auto in_one = [&](const Vector<2>& x) {
          return !(shape_second.holds(x[0], x[1]) && shape_first.holds(x[0], x[1]));
        };
        overlap = !for_each_seed<2>(Vector<2>(scene.origin[0], scene.origin[1]), scene.spacing, lower, upper,
                                    {second.particles_per_cell[0], second.particles_per_cell[1]}, second.placement,
                                    in_one);
      }
      if (!overlap) continue;
      const auto& [file, line] = scene.locations.at(entry_key("body", i) + "min");
      throw scene_error(scene, entry_key("body", j) + "min",
                        "overlaps body[" + std::to_string(i) + "] (" + file + ":" + std::to_string(line) +
                            "): a particle of one would lie in the other; move them apart (their boxes may touch)");
    }
}

/// LME's support reaches a cell's corners; the predictor-corrector updates stress first; uGIMP's particles fit a cell.
inline void check_solver(const SceneFile& file, const Scene& scene) {
  require(!lab_build || scene.kernels == KernelsKind::reference, scene, "solver.kernels",
          "'fast' is not in this lab build (make lab compiles the reference kernels alone): use \"reference\", or the "
          "build of make build");
  // The LME support radius R = h sqrt(-ln(tol)/gamma) must reach the corners of a particle's cell (its convex
  // hull), R >= h sqrt(dimension): gamma <= -ln(tol)/dimension. The key blamed is the one the user changed:
  // lme_tol when it is given and lme_gamma is not overridden, else lme_gamma.
  const int dim = scene.dimension;
  const std::string reach = ": the support must reach the corners of a cell, ";
  if (scene.shape == ShapeKind::lme && scene.lme_gamma > -std::log(scene.lme_tol) / dim) {
    require(!file.table["solver"]["lme_tol"] || file.overridden.count("solver.lme_gamma"), scene, "solver.lme_tol",
            "too large for lme_gamma = " + SceneReader::describe(scene.lme_gamma) + reach +
                "lme_tol <= exp(-lme_gamma * dimension) = " + SceneReader::describe(std::exp(-scene.lme_gamma * dim)));
    throw scene_error(scene, "solver.lme_gamma",
                      "too large for lme_tol = " + SceneReader::describe(scene.lme_tol) + reach +
                          "lme_gamma <= -ln(lme_tol)/dimension = " +
                          SceneReader::describe(-std::log(scene.lme_tol) / dim));
  }
  require(scene.integrator != IntegratorKind::npc || scene.stress_update == StressUpdate::usf, scene,
          "solver.stress_update",
          "the predictor-corrector updates stress first (\"usf\"); usl and musl are forward Euler's");
  for (const BodySettings& body : scene.bodies)  // uGIMP needs each particle's l_p in (0, h] (mpm/shape/ugimp.hpp)
    for (const FileParticle& particle : body.particles)
      if (scene.shape == ShapeKind::ugimp && !(particle.half_length / scene.spacing <= 1.0))
        throw SceneError(particle_file_path(scene, body), particle.line, "volume",
                         "the particle's half-length l_p = V^(1/" + std::to_string(dim) + ") / 2 = " +
                             SceneReader::describe(particle.half_length) + " m exceeds the cell size h = " +
                             SceneReader::describe(scene.spacing) +
                             " m; uGIMP needs 0 < l_p <= h: give smaller particles, a coarser grid, or another shape");
}

/// solver.dt or solver.cfl: a scene gives one; `--set` of one replaces the other given in the file. A fixed step
/// above CFL 10 at t = 0 is refused, as solver.cfl is: far beyond any explicit scheme's stability limit.
inline void choose_time_step(const SceneFile& file, Scene& scene) {
  const bool dt = static_cast<bool>(file.table["solver"]["dt"]), cfl = static_cast<bool>(file.table["solver"]["cfl"]);
  if (dt && cfl) {
    const bool dt_set = file.overridden.count("solver.dt"), cfl_set = file.overridden.count("solver.cfl");
    const auto& [where, line] = scene.locations.at("solver.cfl");
    if (dt_set == cfl_set)
      throw scene_error(scene, "solver.dt",
                        "the scene gives solver.cfl too (" + where + ":" + std::to_string(line) +
                            "): give one of them (dt fixes the step; cfl sets it by Eq. (42))");
    if (cfl_set) scene.control.fixed_dt = 0.0;  // --set solver.cfl over the file's dt
  }
  const double first_cfl = initial_cfl(scene);
  if (scene.control.fixed_dt > 0.0 && !(first_cfl <= 10.0))
    throw scene_error(scene, "solver.dt",
                      SceneReader::describe(scene.control.fixed_dt) + " s is CFL " + SceneReader::describe(first_cfl) +
                          " at t = 0 (dt c / h): far beyond any explicit scheme's stability limit; give at most " +
                          SceneReader::describe(10.0 * scene.spacing / initial_courant_speed(scene)) + " s");
}

/// The box an exact solution holds for: [origin, origin + length], the soil column's as high as its bodies.
inline std::vector<double> exact_length(const Scene& scene) {
  std::vector<double> length = scene.length;
  if (scene.exact == ExactKind::soil_column && scene.dimension == 2) length[1] = column_height(scene);
  return length;
}

/// An observer inside the grid, inside the exact solution's body when there is one (exact.csv is evaluated at
/// its reference position), named for a CSV column, once.
inline void check_observer(const Scene& scene, std::size_t k) {
  const ObserverSettings& observer = scene.observers[k];
  const std::string at = entry_key("observer", k);
  check_inside_grid(scene, at + "position", observer.position, false);
  const std::vector<double> length = exact_length(scene);
  for (int axis = 0; scene.exact != ExactKind::none && axis < scene.dimension; ++axis) {
    const double low = scene.origin[axis], high = low + length[axis];
    require(in_span(scene, observer.position[axis], low, high), scene, at + "position",
            "lies outside the body [" + SceneReader::describe(low) + ", " + SceneReader::describe(high) + "] on " +
                axis_name(axis) + ", where exact = \"" + name_of(scene.exact) + "\" is evaluated for exact.csv");
  }
  const std::string& name = observer.name;
  const char* word = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_";
  require(!name.empty() && name.find_first_not_of(word) == name.npos, scene, at + "name",
          "required; letters, digits and _ only (it names CSV columns)");
  for (size_t other = 0; other < k; ++other)
    if (scene.observers[other].name == name) throw scene_error(scene, at + "name", "'" + name + "' is used twice");
}

/// Snapshot and sample times within the run, at most 10000 and 1000000, the sample times increasing.
inline void check_output(const Scene& scene) {
  const RunControl& control = scene.control;
  const std::vector<double>& snapshots = control.snapshot_times;
  const std::vector<double>& samples = control.sample_times;
  auto within_run = [&](double time) { return time >= 0.0 && time <= control.end_time; };
  const std::string within = "times must lie in [0, solver.end_time]";
  require(snapshots.size() <= 10'000, scene, "output.snapshots", "at most 10000 times");
  require(std::all_of(snapshots.begin(), snapshots.end(), within_run), scene, "output.snapshots", within);
  require(samples.size() <= 1'000'000, scene, "output.times", "at most 1000000 times");
  for (size_t k = 0; k < samples.size(); ++k) {  // up to a million: no message built until one is wrong
    if (!within_run(samples[k])) throw scene_error(scene, "output.times", within);
    if (k > 0 && !(samples[k] > samples[k - 1])) throw scene_error(scene, "output.times", "times must increase");
  }
  require(samples.empty() || control.sample_every == 1, scene, "output.every",
          "give output.every or output.times, not both (times replaces every)");
}

/// True if [[fixed]] holds velocity `component` on the face (`axis`, `upper`).
inline bool has_fixed(const Scene& scene, int axis, bool upper, int component) {
  return std::any_of(scene.fixed.begin(), scene.fixed.end(), [&](const FixedSettings& fixed) {
    return fixed.axis() == axis && fixed.upper() == upper &&
           std::find(fixed.components.begin(), fixed.components.end(), component) != fixed.components.end();
  });
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
      const double low = scene.origin[axis], high = low + length[axis];
      if (!in_span(scene, body.min[axis], low, high) || !in_span(scene, body.max[axis], low, high)) return false;
      body_volume *= body.max[axis] - body.min[axis];
    }
    volume += body_volume;
  }
  return std::abs(volume - box_volume) <= 1e-9 * box_volume;
}

/// The exact solutions hold for one homogeneous body filling their box (the bar, the column, the square):
/// one [[body]] or several boxes side by side, all of the scene's [material], held and loaded as the solution is.
inline void check_exact_setup(const Scene& scene) {
  const std::string name = "'" + name_of(scene.exact) + "' ";
  for (size_t k = 0; k < scene.bodies.size(); ++k)
    require(scene.bodies[k].material == scene.material(), scene, entry_key("body", k) + "min",
            "is of a material other than [material]'s: exact = \"" + name_of(scene.exact) +
                "\" holds for one homogeneous body");
  auto held = [&](int axis, int component) {  // on both faces across the axis
    return has_fixed(scene, axis, false, component) && has_fixed(scene, axis, true, component);
  };
  const std::vector<double>& g = scene.gravity;
  const bool two = scene.dimension == 2, small = scene.exact == ExactKind::manufactured_small;
  const bool manufactured = small || scene.exact == ExactKind::manufactured_large;
  bool holds = fills_exact_box(scene);
  std::string needs;
  switch (scene.exact) {
    case ExactKind::dyka_bar:
    case ExactKind::vibrating_bar:
      holds = holds && !two && has_fixed(scene, 0, true, 0) && g[0] == 0.0;
      needs = "is the 1D bar free at xmin and fixed at xmax without gravity: needs dimension = 1, [[body]] boxes "
              "filling [origin, origin + length], a [[fixed]] face = \"xmax\" holding \"x\", and no gravity";
      break;
    case ExactKind::soil_column:
      holds = holds && two && has_fixed(scene, 1, false, 1) && g[0] == 0.0 && g[1] < 0.0 &&
              (scene.poisson_ratio == 0.0 || held(0, 0));
      needs = "is the 2D column on a roller base under gravity: needs dimension = 2, [[body]] boxes filling [origin, "
              "origin + (length_x, H)] up to their top H, a [[fixed]] face = \"ymin\" holding \"y\", "
              "gravity.acceleration = [0, -g], and rollers on xmin and xmax unless poisson_ratio = 0";
      break;
    default:  // the manufactured motions
      holds = holds && two && std::abs(scene.length[0] - scene.length[1]) <= 1e-9 * scene.length[0] && g[0] == 0.0 &&
              g[1] == 0.0 && held(0, 0) && held(1, 1) && (!small || (held(0, 1) && held(1, 0)));
      needs = std::string("is the square [origin, origin + L]^2 in plane strain without gravity: needs ") +
              "dimension = 2, equal grid lengths, [[body]] boxes filling the box, and " +
              (small ? "every face fixed in x and y"
                     : "rollers on every face (xmin, xmax holding \"x\"; ymin, ymax holding \"y\")");
  }
  require(holds, scene, "exact", name + needs);
  const SceneFormulas& formulas = scene.formulas;
  const std::vector<double>& velocity = scene.bodies[0].velocity;
  const bool moving = std::any_of(velocity.begin(), velocity.end(), [](double v) { return v != 0.0; });
  require(!manufactured || !(formulas.body_force || formulas.initial_velocity || formulas.initial_stress ||
                             !scene.initial_velocities.empty() || moving),
          scene, "exact",
          name + "sets the body force and the initial velocity itself (mpm/exact/manufactured.hpp): "
                 "give no [body_force], [initial_field], [[initial_velocity]] or body velocity");
}

/// [exact_parameters]: each key given only to the solution that reads it, and required by it.
inline void check_exact_parameters(const Scene& scene) {
  const std::string mode = "exact_parameters.mode", velocity = "exact_parameters.velocity_amplitude",
                    displacement = "exact_parameters.displacement_amplitude";
  const bool vibrating = scene.exact == ExactKind::vibrating_bar, small = scene.exact == ExactKind::manufactured_small;
  const bool manufactured = small || scene.exact == ExactKind::manufactured_large;
  require(!vibrating || scene.exact_velocity_amplitude, scene, velocity,
          "required by exact = \"vibrating_bar\": the velocity amplitude V (m/s) of "
          "v(X, 0) = V cos((2 mode - 1) pi X / 2L)");
  require(vibrating || scene.exact_mode == 1, scene, mode, "only exact = \"vibrating_bar\" reads it");
  require(vibrating || !scene.exact_velocity_amplitude, scene, velocity, "only exact = \"vibrating_bar\" reads it");
  const std::vector<double>& a = scene.exact_displacement_amplitude;
  require(manufactured || a.empty(), scene, displacement,
          "only exact = \"manufactured_small\" and \"manufactured_large\" read it");
  if (!manufactured) return;
  require(a.size() == (small ? 1u : 2u), scene, displacement,
          small ? "required by exact = \"manufactured_small\": one amplitude A (m)"
                : "required by exact = \"manufactured_large\": [a_x, a_y] (m)");
  const double wave_number = 3.14159265358979323846 / scene.length[0];
  require(!small || std::abs(a[0]) * wave_number < 0.01, scene, displacement,
          "must be small: |A| pi / L < 0.01 (the small-strain solution; use manufactured_large for large amplitude)");
  require(small || (std::abs(a[0]) * wave_number < 0.9 && 2.0 * std::abs(a[1]) * wave_number < 0.9), scene,
          displacement, "too large: the stretches must stay positive, |a_x| pi / L < 0.9 and 2 |a_y| pi / L < 0.9");
}

}  // namespace detail

/// Reads and validates every key of the scene. \throws SceneError at the first problem.
inline Scene read_scene(const SceneFile& file) {
  using namespace detail;
  Scene scene;
  scene.file = file.path;
  SceneReader root(file, file.table, "");
  read_keys(root, "", scene, 0);
  for (unsigned char character : scene.title)  // it is a line of the VTK header and of the progress line
    if (character < 0x20 || character == 0x7f)
      throw scene_error(scene, "title", "must be one line of printable text (no newline, tab or control character)");
  read_table(file, root, "grid", scene);
  check_grid(scene);
  read_table(file, root, "material", scene);
  BodySettings body;
  body.material = scene.material();  // a body's own material keys default to [material]'s
  read_tables(file, root, "body", scene, scene.bodies, body, [&](size_t k) { check_body(scene, k); });
  if (scene.bodies.empty()) root.fail("body", "the scene needs at least one [[body]]");
  check_bodies_apart(scene);
  read_tables(file, root, "initial_velocity", scene, scene.initial_velocities, VelocityBox{}, [](size_t) {});
  auto check_fixed = [&](size_t k) {
    require(scene.dimension == 2 || scene.fixed[k].axis() == 0, scene, entry_key("fixed", k) + "face",
            "'" + name_of(scene.fixed[k].face) + "' is not allowed; use one of xmin | xmax");
  };
  read_tables(file, root, "fixed", scene, scene.fixed, FixedSettings{}, check_fixed);
  read_table(file, root, "gravity", scene);
  read_table(file, root, "solver", scene);
  choose_time_step(file, scene);
  check_solver(file, scene);
  read_tables(file, root, "observer", scene, scene.observers, ObserverSettings{},
              [&](size_t k) { check_observer(scene, k); });
  read_table(file, root, "output", scene);
  check_output(scene);
  scene.formulas =
      read_scene_formulas(file, root, scene.dimension, scene.young_modulus, scene.poisson_ratio, scene.density);
  read_table(file, root, "exact_parameters", scene);
  if (scene.exact != ExactKind::none) check_exact_setup(scene);
  check_exact_parameters(scene);
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

TEST_CASE("Scene validation: solver.dt, a fixed step, or solver.cfl, one of them, and never beyond CFL 10") {
  // c = sqrt(E / rho) = 2 m/s, h = 0.1 m: dt = 0.5 s is CFL 10
  const std::string bar = "[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 4.0\ndensity = 1.0\n"
                          "[[body]]\nmin = [0.0]\nmax = [1.0]\n[solver]\nend_time = 1.0\n";
  auto read = [&](const std::string& text, const std::vector<std::string>& overrides = {}) {
    SceneFile file = parse_scene_text(text, "d.toml");
    for (size_t k = 0; k < overrides.size(); ++k) apply_override(file, overrides[k], static_cast<int>(k) + 1);
    return read_scene(file);
  };
  auto message_of = [&](const std::string& text, const std::vector<std::string>& overrides = {}) -> std::string {
    try {
      read(text, overrides);
    } catch (const SceneError& error) {
      return error.message();
    }
    return "no error";
  };
  CHECK(read(bar).control.fixed_dt == 0.0);
  CHECK(read(bar + "dt = 0.01\n").control.fixed_dt == 0.01);
  CHECK(initial_cfl(read(bar + "dt = 0.01\n")) == doctest::Approx(0.2).epsilon(1e-14));
  CHECK(initial_cfl(read(bar + "cfl = 0.3\n")) == 0.3);
  CHECK(read(bar + "dt = 0.5\n").control.fixed_dt == 0.5);  // CFL 10: allowed, as solver.cfl = 10 is
  CHECK(message_of(bar + "dt = 0.51\n") == "error: d.toml:12: solver.dt: 0.51 s is CFL 10.2 at t = 0 (dt c / h): far "
                                            "beyond any explicit scheme's stability limit; give at most 0.5 s");
  CHECK(message_of(bar + "dt = 0.0\n") == "error: d.toml:12: solver.dt: must be > 0, got 0.000000");
  CHECK(message_of(bar + "dt = \"1e-3\"\n") == "error: d.toml:12: solver.dt: must be a number");
  CHECK(message_of(bar + "dt = inf\n").find("solver.dt: must be a finite number") != std::string::npos);
  CHECK(message_of(bar + "cfl = 0.5\ndt = 0.01\n") ==
        "error: d.toml:13: solver.dt: the scene gives solver.cfl too (d.toml:12): give one of them (dt fixes the step; "
        "cfl sets it by Eq. (42))");
  CHECK(read(bar + "cfl = 0.5\n", {"solver.dt=0.01"}).control.fixed_dt == 0.01);  // --set dt replaces the file's cfl
  CHECK(read(bar + "dt = 0.01\n", {"solver.cfl=0.5"}).control.fixed_dt == 0.0);   // --set cfl replaces the file's dt
  CHECK(message_of(bar, {"solver.cfl=0.5", "solver.dt=0.01"}).rfind("error: --set(2):1: solver.dt: the scene gives", 0) ==
        0);
}

}  // namespace mpm::io
