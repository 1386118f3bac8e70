/// \file
/// Warnings for a valid but suspicious scene, `warning: FILE:LINE: KEY: what and why` on stderr before the run;
/// a warning never stops a run. The CFL limit comes from the caller (mpm/stability.hpp), so that reading a scene
/// needs no solver.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "mpm/io/scene.hpp"
#include "mpm/io/scene_file.hpp"

namespace mpm::io {

namespace detail {

/// True if the first `dim` coordinates of `x` lie in the box [min - tolerance, max + tolerance].
template <class Point>
bool in_box(const Point& x, const std::vector<double>& min, const std::vector<double>& max, int dim,
            double tolerance = 0.0) {
  for (int axis = 0; axis < dim; ++axis)
    if (!(x[axis] >= min[axis] - tolerance && x[axis] <= max[axis] + tolerance)) return false;
  return true;
}

/// True if a particle of the scene lies in `box`, or if there are too many particles to look at here.
inline bool box_holds_particle(const Scene& scene, const VelocityBox& box) {
  const int dim = scene.dimension;
  double seeds = 0.0, shape_tests = 0.0;
  for (const auto& body : scene.bodies) {
    double count = 1.0;
    for (int axis = 0; axis < dim; ++axis)
      count *= (body.max[axis] - body.min[axis]) / scene.spacing * body.particles_per_cell[axis];
    seeds += count;
    shape_tests += count * static_cast<double>(body.vertices.size());
  }
  if (seeds > 1e7 || shape_tests > most_shape_tests) return true;
  for (const auto& body : scene.bodies) {
    for (const auto& particle : body.particles) {  // a body read from a file: its own particles
      const double x[2] = {particle.x, particle.y};
      if (in_box(x, box.min, box.max, dim)) return true;
    }
    if (body.shape == BodyShape::Kind::file) continue;
    const BodyShape shape = body_shape(body);
    auto outside = [&](const auto& x) { return !(in_box(x, box.min, box.max, dim) && shape.holds(x[0], x[dim - 1])); };
    const auto &min = body.min, &max = body.max;
    const auto& ppc = body.particles_per_cell;
    const bool none = dim == 1 ? for_each_seed<1>(Vector<1>(scene.origin[0]), scene.spacing, Vector<1>(min[0]),
                                                  Vector<1>(max[0]), {ppc[0]}, body.placement, outside)
                               : for_each_seed<2>(Vector<2>(scene.origin[0], scene.origin[1]), scene.spacing,
                                                  Vector<2>(min[0], min[1]), Vector<2>(max[0], max[1]),
                                                  {ppc[0], ppc[1]}, body.placement, outside);
    if (!none) return true;
  }
  return false;
}

}  // namespace detail

/// The warnings of a validated scene, one line each, located where the scene gives its key (else its table's line):
/// an observer outside every body, a velocity box that holds no particle, a CFL above `cfl_limit` (the method's
/// largest stable CFL; NaN: not known), LME next to rigid margin nodes behind a fixed face.
inline std::vector<std::string> scene_warnings(const Scene& scene,
                                               double cfl_limit = std::numeric_limits<double>::quiet_NaN()) {
  std::vector<std::string> warnings;
  auto warn = [&](const std::string& key, const std::string& what) {
    warnings.push_back("warning:" + scene_error(scene, key, what).message().substr(std::string("error:").size()));
  };
  for (size_t k = 0; k < scene.observers.size(); ++k) {
    const auto holds = [&](const BodySettings& body) {
      return detail::in_box(scene.observers[k].position, body.min, body.max, scene.dimension, 1e-9 * scene.spacing);
    };
    if (std::none_of(scene.bodies.begin(), scene.bodies.end(), holds))
      warn("observer[" + std::to_string(k) + "].position",
           "lies outside every [[body]]: the particle nearest to it at t = 0 is observed instead");
  }
  for (size_t k = 0; k < scene.initial_velocities.size(); ++k)
    if (!detail::box_holds_particle(scene, scene.initial_velocities[k]))
      warn("initial_velocity[" + std::to_string(k) + "].min", "the box holds no particle: it sets no velocity");
  const double first_cfl = initial_cfl(scene);
  if (first_cfl > cfl_limit) {  // false when the limit is NaN
    const bool npc = scene.integrator == IntegratorKind::npc, fixed = scene.control.fixed_dt > 0.0;
    char step[120] = "", what[520];
    if (fixed)  // a fixed step: its CFL at t = 0, and the longest stable step
      std::snprintf(step, sizeof step, " s is CFL %g at t = 0 (dt c / h), dt <= %.3g s,", first_cfl,
                    scene.control.fixed_dt * cfl_limit / first_cfl);
    std::snprintf(
        what, sizeof what,
        "%g%s is above the stability limit %.3f of %s shapes with %s%s, from the method's own linearised step "
        "(`mpm stability`, paper/10_integrator_analysis.md); expect the run to stop with energy growth (exit 3)",
        fixed ? scene.control.fixed_dt : scene.control.cfl, step, cfl_limit, name_of(scene.shape).c_str(),
        npc ? "the predictor-corrector" : "forward Euler",
        npc && scene.npc_velocity == NewmarkParticleVelocity::average ? " (Newmark average)" : "");
    warn(fixed ? "solver.dt" : "solver.cfl", what);
  }
  for (const auto& fixed : scene.fixed)
    if (scene.shape == ShapeKind::lme && (fixed.upper() ? scene.margin_max : scene.margin_min)[fixed.axis()] > 0)
      warn(std::string("grid.") + (fixed.upper() ? "margin_max" : "margin_min"),
           "LME next to rigid margin nodes behind the fixed face " + name_of(fixed.face) +
               " gives way there (its wide support drags the particles along the held nodes); with no margin at "
               "a fixed face LME interpolates the wall exactly");
  return warnings;
}

/// The same, for `mpm run`'s call with the scene's path and overrides (which `scene` already locates).
inline std::vector<std::string> scene_warnings(const std::string&, const std::vector<std::string>&, const Scene& scene,
                                               double cfl_limit) {
  return scene_warnings(scene, cfl_limit);
}

TEST_CASE("Scene warnings: the CFL above the method's limit, and each warning at its key and line") {
  const std::string base =
      "[grid]\nlength = [1.0]\ncells = [10]\nmargin_min = [2]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [1.0]\n[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n"
      "[[observer]]\nname = \"A\"\nposition = [0.0]\n[solver]\nend_time = 1.0\n";
  auto warnings_of = [](const std::string& text, const std::vector<std::string>& overrides = {},
                        double cfl_limit = std::numeric_limits<double>::quiet_NaN()) {
    SceneFile file = parse_scene_text(text, "w.toml");
    for (size_t k = 0; k < overrides.size(); ++k) apply_override(file, overrides[k], static_cast<int>(k) + 1);
    return scene_warnings(read_scene(file), cfl_limit);
  };
  CHECK(warnings_of(base).empty());
  auto cfl = warnings_of(base + "cfl = 2.1\n", {}, 2.0);
  REQUIRE(cfl.size() == 1);
  CHECK(cfl[0].rfind("warning: w.toml:19: solver.cfl: 2.1 is above the stability limit 2.000 of linear shapes with forward Euler", 0) == 0);
  CHECK(warnings_of(base + "cfl = 2.0\n", {}, 2.0).empty());
  CHECK(warnings_of(base + "cfl = 2.1\n").empty());  // no limit known: no warning
  CHECK(warnings_of(base + "cfl = 1.43\nintegrator = \"npc\"\n", {}, 1.414).size() == 1);
  // A fixed step: c = 1 m/s, h = 0.1 m, so dt = 0.21 s is CFL 2.1.
  auto dt = warnings_of(base + "dt = 0.21\n", {}, 2.0);
  REQUIRE(dt.size() == 1);
  CHECK(dt[0].rfind("warning: w.toml:19: solver.dt: 0.21 s is CFL 2.1 at t = 0 (dt c / h), dt <= 0.2 s, is above the "
                    "stability limit 2.000 of linear shapes with forward Euler", 0) == 0);
  CHECK(warnings_of(base + "dt = 0.19\n", {}, 2.0).empty());
  auto observer = warnings_of(base, {"observer[0].position=[-0.1]"});
  REQUIRE(observer.size() == 1);
  CHECK(observer[0].rfind("warning: --set(1):1: observer[0].position: lies outside every [[body]]", 0) == 0);
  auto lme = warnings_of(base + "shape = \"lme\"\n", {"grid.margin_max=[1]"});
  REQUIRE(lme.size() == 1);
  CHECK(lme[0].rfind("warning: --set(1):1: grid.margin_max: LME next to rigid margin nodes behind the fixed face xmax", 0) == 0);
  // uGIMP is clipped at the grid's edge: at a fixed face it needs no margin, and gets no warning either way.
  CHECK(warnings_of(base + "shape = \"ugimp\"\n").empty());
  CHECK(warnings_of(base + "shape = \"ugimp\"\n", {"grid.margin_max=[1]"}).empty());
}

}  // namespace mpm::io
