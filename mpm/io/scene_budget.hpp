/// \file
/// The size of a run, estimated in double precision (no size can wrap) from its validated scene before anything
/// is allocated, and the limits it must keep: memory (default half the machine's) and end_time / dt (default
/// 10^7). A scene beyond them is refused like any other bad input (exit 2), naming the key that makes it large.
#pragma once
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <optional>
#include <regex>
#include <sstream>
#include <string>

#include "mpm/core/parallel.hpp"
#include "mpm/io/scene.hpp"

namespace mpm::io {

/// The limits of one run (`mpm run --max-memory BYTES|<n>G --max-steps N --force`).
struct Budget {
  double max_bytes = 0.0;  ///< 0: half the machine's memory (default_max_memory())
  double max_steps = 1e7;  ///< end_time / dt at t = 0
  bool force = false;      ///< run even beyond max_steps
};

/// Half the machine's physical memory, or 4 GiB when it cannot be told.
inline double default_max_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? 0.5 * static_cast<double>(pages) * static_cast<double>(page_size)
                                    : 4.0 * (1 << 30);
}

/// Reads `12345`, `512M`, `4G`, `1.5GB`, `2TiB` (powers of 1024); nothing unless it is a finite size > 0.
inline std::optional<double> parse_byte_size(const std::string& text) {
  std::smatch match;
  if (!std::regex_match(text, match, std::regex(R"(([0-9.][0-9.eE+-]*)(?:([KMGT])(?:i?B)?|B)?)"))) return std::nullopt;
  const std::string number = match[1];
  char* end = nullptr;
  const double power = match[2].matched ? 1.0 + static_cast<double>(std::string("KMGT").find(match.str(2))) : 0.0;
  const double bytes = std::strtod(number.c_str(), &end) * std::pow(1024.0, power);
  if (*end != '\0' || !(bytes > 0.0) || !std::isfinite(bytes)) return std::nullopt;
  return bytes;
}

/// What a scene will need, estimated from its numbers alone.
struct SceneCost {
  double particles = 0.0;           ///< sum over bodies of cells x particles_per_cell
  double nodes = 0.0;               ///< prod over axes of (cells + margins + 1)
  double nodes_per_particle = 0.0;  ///< the stencil capacity of the shape function
  double particle_bytes = 0.0, node_bytes = 0.0, stencil_bytes = 0.0;
  double time_step = 0.0, steps = 0.0;  ///< Eq. (42) at t = 0, and end_time over it
  int largest_body = 0;                 ///< the body with most particles
  double shape_tests = 0.0;             ///< seeds times vertices of the polygon with most (seeding tests each seed)
  int costliest_polygon = -1;           ///< that polygon's body; -1: none
  /// The process itself (code, libraries, the threads' stacks, the allocator), counted generously.
  static constexpr double process_bytes = 16.0 * (1 << 20);
  double bytes() const { return process_bytes + particle_bytes + stencil_bytes + node_bytes; }
};

/// The most nodes, and stencil entries, the code's 32-bit indices can count.
inline constexpr double most_index = 2147483647.0;
/// The most point-in-polygon tests (a seed against an edge, about 1 ns each) that seeding one body may take.
inline constexpr double most_seeding_tests = 1e10;

/// The particles per cell and axis of the uniform body on which `mpm run` checks a scene's CFL (warning_body() of
/// mpm/stability.hpp): the scene's largest, at most 4.
inline int warning_body_ppc(const Scene& scene) {
  int ppc = 1;
  for (const auto& body : scene.bodies)
    for (int per_axis : body.particles_per_cell) ppc = std::max(ppc, std::min(per_axis, 4));
  return ppc;
}

/// That body's cells per axis: 16 in 1D; in 2D 6 at 1 particle per cell and axis, 4 at 2 and 2 from 3.
inline int warning_body_cells(int dimension, int ppc) { return dimension == 1 ? 16 : ppc == 1 ? 6 : ppc == 2 ? 4 : 2; }

/// That body's particles, whose stencils are as wide as the run's: the run's peak is the larger of the two.
inline double warning_body_particles(const Scene& scene) {
  const int ppc = warning_body_ppc(scene);
  return std::pow(static_cast<double>(warning_body_cells(scene.dimension, ppc) * ppc), scene.dimension);
}

TEST_CASE("Scene budget: the CFL check's body has 16 x ppc particles in 1D, at most 8 x 8 in 2D") {
  Scene scene;
  scene.dimension = 1;
  scene.bodies.resize(2);
  scene.bodies[0].particles_per_cell = {2};
  scene.bodies[1].particles_per_cell = {3};
  CHECK(warning_body_ppc(scene) == 3);
  CHECK(warning_body_particles(scene) == 48.0);
  scene.bodies[1].particles_per_cell = {100};
  CHECK(warning_body_particles(scene) == 64.0);  // at most 4 per cell
  scene.dimension = 2;
  scene.bodies[0].particles_per_cell = {1, 1};
  scene.bodies[1].particles_per_cell = {1, 1};
  CHECK(warning_body_particles(scene) == 36.0);
  scene.bodies[1].particles_per_cell = {2, 1};
  CHECK(warning_body_particles(scene) == 64.0);
  scene.bodies[1].particles_per_cell = {3, 3};
  CHECK(warning_body_particles(scene) == 36.0);
}

/// The time step at t = 0: solver.dt, or Eq. (42)'s cfl h over the fastest material's wave speed and the fastest
/// particle's speed (the scene's, or `fastest_particle` when faster: initial_courant_speed()).
inline double initial_time_step(const Scene& scene, double fastest_particle = 0.0) {
  if (scene.control.fixed_dt > 0.0) return scene.control.fixed_dt;
  return scene.control.cfl * scene.spacing / initial_courant_speed(scene, fastest_particle);
}

/// The output times strictly between 0 and end_time: a step that lands on one is shortened, and the step after it
/// starts anew, so each may add a step.
inline double landing_count(const Scene& scene) {
  const RunControl& control = scene.control;
  double landings = 0.0;
  for (const auto* times : {&control.sample_times, &control.snapshot_times})
    for (double time : *times) landings += time > 0.0 && time < control.end_time;
  return landings;
}

/// The steps of a run at time step `time_step`: end_time / dt, plus one for each output time before the end.
inline double step_count(const Scene& scene, double time_step) {
  return std::ceil(scene.control.end_time / time_step) + landing_count(scene);
}

/// The estimate, an upper bound of the peak resident memory: the particles' arrays thrice (seeding doubles vectors;
/// the simulation holds a copy), the stencils of the run or of its CFL check's body if larger, and the nodal fields
/// with one copy per chunk of the scatter beyond the first (held by the fast layer's ScatterScratch,
/// mpm/fast/scatter.hpp; at most three vector fields at once; in 1D most of the memory).
inline SceneCost estimate_cost(const Scene& scene) {
  const int d = scene.dimension;
  SceneCost cost;
  double most = -1.0;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const BodySettings& body = scene.bodies[k];
    double count = 1.0;
    for (int axis = 0; axis < d; ++axis)
      count *= std::round((body.max[axis] - body.min[axis]) / scene.spacing) * body.particles_per_cell[axis];
    if (body.shape == BodyShape::Kind::file) count = static_cast<double>(body.particles.size());
    cost.particles += count;
    if (count > most) {
      most = count;
      cost.largest_body = static_cast<int>(k);
    }
    if (count * static_cast<double>(body.vertices.size()) > cost.shape_tests) {
      cost.shape_tests = count * static_cast<double>(body.vertices.size());
      cost.costliest_polygon = static_cast<int>(k);
    }
  }
  cost.nodes = 1.0;
  for (int axis = 0; axis < d; ++axis)
    cost.nodes *= static_cast<double>(scene.cells[axis]) + scene.margin_min[axis] + scene.margin_max[axis] + 1.0;
  const bool lme = scene.shape == ShapeKind::lme;  // stencil capacity: linear 2^d, uGIMP 3^d, LME (2R/h + 2)^d
  const double width = scene.shape == ShapeKind::linear     ? 2.0
                       : scene.shape == ShapeKind::bspline3 ? 4.0
                       : lme ? 2.0 * std::sqrt(-std::log(scene.lme_tol) / scene.lme_gamma) + 2.0
                             : 3.0;
  cost.nodes_per_particle = std::pow(width, d);
  const double particle_arrays = 4 + 8 + 8 + 5 * 8.0 * d + 2 * 8.0 * d * d + 8 + 4;  // Particles<Dim>
  const double entry = 4 + 8 + 8.0 * d + (lme ? 4 + 8 : 0);  // Stencils<Dim>; LmeShape's last_nodes_, last_values_
  cost.particle_bytes = cost.particles * (3 * particle_arrays + 8.0 * d);
  cost.stencil_bytes = std::max(cost.particles, warning_body_particles(scene)) * (4 + cost.nodes_per_particle * entry);
  const double copies = std::clamp(std::floor(cost.particles / items_per_chunk), 1.0, double(max_chunks)) - 1.0;
  cost.node_bytes = cost.nodes * (8 + 7 * 8.0 * d + copies * (8 + 3 * 8.0 * d));  // GridFields<Dim>: m_I, 7 vectors; the copies
  cost.time_step = initial_time_step(scene);
  cost.steps = step_count(scene, cost.time_step);
  return cost;
}

/// "2.82 GiB": a size in bytes to 3 digits in powers of 1024.
inline std::string bytes_text(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  for (; bytes >= 1024.0 && unit < 6; ++unit) bytes /= 1024.0;
  std::ostringstream out;
  out << std::setprecision(3) << bytes << " " << units[unit];
  return out.str();
}

/// The key that makes a run too large: the largest grid entry when the nodes dominate, lme_gamma for a very wide
/// LME support, else particles_per_cell or grid.cells of the body with most particles.
inline std::string largest_key(const Scene& scene, const SceneCost& cost) {
  if (cost.node_bytes >= cost.particle_bytes + cost.stencil_bytes || cost.nodes > most_index) {
    auto most = [](const std::vector<int>& values) { return *std::max_element(values.begin(), values.end()); };
    const int cells = most(scene.cells), low = most(scene.margin_min), high = most(scene.margin_max);
    return high > std::max(cells, low) ? "grid.margin_max" : low > cells ? "grid.margin_min" : "grid.cells";
  }
  if (scene.shape == ShapeKind::lme && cost.nodes_per_particle > 256) return "solver.lme_gamma";
  const BodySettings& body = scene.bodies[cost.largest_body];
  double per_cell = 1.0, cells = 1.0;
  for (int axis = 0; axis < scene.dimension; ++axis) {
    per_cell *= body.particles_per_cell[axis];
    cells *= std::round((body.max[axis] - body.min[axis]) / scene.spacing);
  }
  return per_cell > cells ? "body[" + std::to_string(cost.largest_body) + "].particles_per_cell" : "grid.cells";
}

/// Refuses a run of more steps (step_count() at `time_step`) than the budget allows, or than time can count in
/// double precision. \throws SceneError at solver.end_time.
inline void check_step_budget(const Scene& scene, const Budget& budget, double time_step) {
  const double steps = step_count(scene, time_step);
  const bool endless = !(steps <= std::pow(2.0, 50));  // t + dt == t may hold beyond: time would stop
  if (!endless && (steps <= budget.max_steps || budget.force)) return;
  std::ostringstream what;
  const double landings = landing_count(scene);
  what << std::setprecision(3) << "end_time / dt = " << scene.control.end_time << " s / " << time_step << " s = "
       << std::ceil(scene.control.end_time / time_step) << " time steps";
  if (landings > 0) what << " and " << static_cast<long long>(landings) << " landings on output times";
  what << " (dt at t = 0: solver.dt, or Eq. (42)'s cfl h / wave or particle speed)";
  if (endless)
    what << "; no run can take that many steps (time would stop advancing in double precision)";
  else
    what << ", more than the limit of " << budget.max_steps
         << "; shorten end_time or coarsen the grid, or raise the limit (--max-steps N) or lift it (--force)";
  throw scene_error(scene, "solver.end_time", what.str());
}

/// Refuses a scene whose estimated size exceeds the budget or the 32-bit indices, whose polygon takes more than
/// most_seeding_tests to seed, or whose time steps exceed the limit. \throws SceneError naming the key to change.
inline void check_budget(const Scene& scene, const Budget& budget) {
  const SceneCost cost = estimate_cost(scene);
  const double max_bytes = budget.max_bytes > 0.0 ? budget.max_bytes : default_max_memory();
  const bool too_big = cost.bytes() > max_bytes;
  std::ostringstream what;
  what << std::setprecision(3);
  if (too_big || cost.nodes > most_index || cost.particles * cost.nodes_per_particle > most_index) {
    what << "the scene needs " << cost.particles << " particles, " << cost.nodes << " nodes and "
         << cost.nodes_per_particle << " stencil nodes per particle, about " << bytes_text(cost.bytes());
    if (too_big)
      what << "; the limit is " << bytes_text(max_bytes)
           << (budget.max_bytes > 0.0 ? " (--max-memory)"
                                      : " (half this machine's memory; --max-memory BYTES|<n>G to change it)");
    else
      what << "; the code indexes nodes and stencil entries with 32-bit integers, at most 2^31 - 1 of each";
    const std::string key = largest_key(scene, cost);
    throw scene_error(scene, key,
                      what.str() + (key == "solver.lme_gamma" ? "; a larger lme_gamma narrows the support" : ""));
  }
  if (cost.shape_tests > most_seeding_tests) {
    const std::size_t vertices = scene.bodies[cost.costliest_polygon].vertices.size();
    what << vertices << " vertices over " << cost.shape_tests / static_cast<double>(vertices) << " seeds take "
         << cost.shape_tests << " point-in-polygon tests to seed, more than " << most_seeding_tests
         << " (about 10 s); give fewer vertices, or fewer particles_per_cell";
    throw scene_error(scene, "body[" + std::to_string(cost.costliest_polygon) + "].vertices", what.str());
  }
  check_step_budget(scene, budget, cost.time_step);
}

TEST_CASE("Scene budget: sizes are estimated without overflow and the key that makes a run large is named") {
  CHECK(parse_byte_size("4G") == 4.0 * 1024 * 1024 * 1024);
  CHECK(parse_byte_size("512MiB") == 512.0 * 1024 * 1024);
  CHECK(parse_byte_size("1000") == 1000.0);
  CHECK(parse_byte_size("1.5K") == 1536.0);
  CHECK_FALSE(parse_byte_size("4X"));
  CHECK_FALSE(parse_byte_size("-1G"));
  CHECK_FALSE(parse_byte_size("nan"));
  CHECK_FALSE(parse_byte_size("inf"));
  CHECK_FALSE(parse_byte_size(""));
  CHECK_FALSE(parse_byte_size("0"));

  const std::string bar =
      "dimension = 1\n[grid]\nlength = [1.0]\ncells = [10]\nmargin_max = [2]\n[material]\nyoung_modulus = 100.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\nparticles_per_cell = [2]\n[solver]\nend_time = 1.0\ncfl = 0.5\n";
  // by hand: 20 particles, 13 nodes; c = 10 m/s, h = 0.1 m, dt = 0.5 * 0.1 / 10 = 5 ms, 200 steps
  const auto file = parse_scene_text(bar, "b.toml");
  const SceneCost cost = estimate_cost(read_scene(file));
  CHECK(cost.particles == 20.0);
  CHECK(cost.nodes == 13.0);
  CHECK(cost.nodes_per_particle == 2.0);
  CHECK(cost.time_step == doctest::Approx(0.005));
  CHECK(cost.steps == 200.0);
  CHECK(cost.bytes() > 20 * (3 * 108.0));

  auto message_of = [](const std::string& text, const std::vector<std::string>& overrides, Budget budget) -> std::string {
    try {
      SceneFile scene = parse_scene_text(text, "b.toml");
      for (std::size_t k = 0; k < overrides.size(); ++k) apply_override(scene, overrides[k], static_cast<int>(k) + 1);
      check_budget(read_scene(scene), budget);
    } catch (const SceneError& error) {
      return error.message();
    }
    return "no error";
  };
  Budget small;
  small.max_bytes = 20e6;  // the process itself counts 16 MiB
  CHECK(message_of(bar, {}, small) == "no error");
  CHECK(message_of(bar, {"grid.cells=[100000]"}, small).rfind("error: --set(1):1: grid.cells: the scene needs 2e+05 particles", 0) == 0);
  CHECK(message_of(bar, {"grid.margin_max=[100000]"}, small).rfind("error: --set(1):1: grid.margin_max: the scene needs", 0) == 0);
  CHECK(message_of(bar, {"body[0].particles_per_cell=[100000]"}, small).rfind("error: --set(1):1: body[0].particles_per_cell:", 0) == 0);
  // 10^8 cells on each of two axes: 10^16 particles, far beyond any int, reported, not wrapped
  const std::string plane = "dimension = 2\n[grid]\nlength = [1.0, 1.0]\ncells = [100000000, 100000000]\n[material]\n"
                            "young_modulus = 100.0\ndensity = 1.0\n[[body]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[solver]\nend_time = 1.0\n";
  CHECK(message_of(plane, {}, Budget{}).rfind("error: b.toml:4: grid.cells: the scene needs 1e+16 particles, 1e+16 nodes", 0) == 0);
  Budget few_steps;
  few_steps.max_steps = 100;
  CHECK(message_of(bar, {}, few_steps).rfind("error: b.toml:14: solver.end_time: end_time / dt = 1 s / 0.005 s = 200 time steps", 0) == 0);
  // 1D: 10^6 cells under 2048 particles, 16 chunks of the scatter clamped to 8, 7 copies of m_I, p_I, v_I, f_I per node
  const SceneCost long_bar = estimate_cost(read_scene(parse_scene_text(
      "[grid]\nlength = [1.0]\ncells = [1000000]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [0.002048]\n[solver]\nend_time = 1e-9\n", "l.toml")));
  CHECK(long_bar.particles == 2048.0);
  CHECK(long_bar.node_bytes == 1000001.0 * (8 + 7 * 8 + 7 * (8 + 3 * 8)));
  // a polygon of 3000 vertices over 10^8 seeds: 3e11 tests to seed, named at its vertices
  std::string circle = "[";
  for (int v = 0; v < 3000; ++v)
    circle += (v ? ", [" : "[") + std::to_string(0.5 + 0.4 * std::cos(v * 2.0 * M_PI / 3000)) + ", " +
              std::to_string(0.5 + 0.4 * std::sin(v * 2.0 * M_PI / 3000)) + "]";
  const std::string disk = "dimension = 2\n[grid]\nlength = [1.0, 1.0]\ncells = [100, 100]\n[material]\nyoung_modulus = 1.0\n"
                           "density = 1.0\n[[body]]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\nshape = \"polygon\"\nvertices = " + circle +
                           "]\nparticles_per_cell = [100, 100]\n[solver]\nend_time = 1e-9\n";
  Budget plenty;
  plenty.max_bytes = 1e15;
  CHECK(message_of(disk, {}, plenty).rfind("error: b.toml:12: body[0].vertices: 3000 vertices over 1e+08 seeds take 3e+11", 0) == 0);
  CHECK(message_of(disk, {"body[0].particles_per_cell=[10, 10]"}, plenty) == "no error");  // 3e9 tests
  // 150 output times before the end: 150 steps more, each one landing on its time
  std::string times = "[";
  for (int k = 1; k <= 150; ++k) times += (k > 1 ? ", " : "") + std::to_string(k * 1e-3);
  CHECK(message_of(bar, {"output.times=" + times + "]", "solver.end_time=0.25"}, few_steps)
            .find("= 50 time steps and 150 landings on output times") != std::string::npos);
  // a speed only the particles know (a formula's): 1 km/s, 100 times the wave speed, 100 times the steps
  Budget steps_only;
  steps_only.max_steps = 1000;
  const Scene slow = read_scene(parse_scene_text(bar, "b.toml"));
  CHECK(initial_time_step(slow, 1000.0) == doctest::Approx(5e-5));
  CHECK_NOTHROW(check_step_budget(slow, steps_only, initial_time_step(slow, 5.0)));
  CHECK_THROWS_WITH_AS(check_step_budget(slow, steps_only, initial_time_step(slow, 1000.0)),
                       doctest::Contains("= 2e+04 time steps"), SceneError);
  few_steps.force = true;
  CHECK(message_of(bar, {}, few_steps) == "no error");
  CHECK(message_of(bar, {"solver.end_time=1e20"}, few_steps).find("no run can take that many steps") != std::string::npos);
}

}  // namespace mpm::io
