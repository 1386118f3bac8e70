/// \file
/// What a scene says, typed: the settings of a run, each choice an enum. The keys that fill them, with their
/// defaults, units and ranges, are declared once, in mpm/io/scene_keys.hpp.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/io/particle_file.hpp"
#include "mpm/io/scene_formulas.hpp"
#include "mpm/particles/body_shape.hpp"
#include "mpm/particles/seeding.hpp"
#include "mpm/shape/lme_options.hpp"
#include "mpm/run_control.hpp"
#include "mpm/transfer/velocity_choices.hpp"

namespace mpm::io {

enum class ShapeKind { linear, ugimp, lme, bspline2, bspline3 };
enum class IntegratorKind { fe, npc };
enum class StressUpdate { usf, usl, musl };
/// The layer of kernels a run takes (mpm/core/kernels.hpp): fast (mpm/fast/) or reference (mpm/transfer/).
enum class KernelsKind { fast, reference };
enum class ExactKind { none, dyka_bar, soil_column, vibrating_bar, manufactured_small, manufactured_large };
enum class WallFace { xmin, xmax, ymin, ymax };

/// The words a scene writes for the choices of an enum, in the order of its values.
template <class Choice>
constexpr std::array<const char*, 0> choice_words{};
template <> inline constexpr std::array choice_words<ShapeKind>{"linear", "ugimp", "lme", "bspline2", "bspline3"};
template <> inline constexpr std::array choice_words<IntegratorKind>{"fe", "npc"};
template <> inline constexpr std::array choice_words<StressUpdate>{"usf", "usl", "musl"};
template <> inline constexpr std::array choice_words<KernelsKind>{"fast", "reference"};
template <> inline constexpr std::array choice_words<ExactKind>{
    "none", "dyka_bar", "soil_column", "vibrating_bar", "manufactured_small", "manufactured_large"};
template <> inline constexpr std::array choice_words<WallFace>{"xmin", "xmax", "ymin", "ymax"};
template <> inline constexpr std::array choice_words<BodyShape::Kind>{"box", "ellipse", "polygon", "file"};
template <> inline constexpr std::array choice_words<Placement>{"uniform", "gauss"};
template <> inline constexpr std::array choice_words<BodyForceTime>{"step_end", "step_start"};
template <> inline constexpr std::array choice_words<CourantSpeed>{"max", "sum"};
template <>
inline constexpr std::array choice_words<LmeOptions::BetaRule>{"grid_spacing", "mean_neighbour_distance", "authors"};
template <>
inline constexpr std::array choice_words<LmeOptions::Neighbours>{"support_radius", "authors_patch"};
template <> inline constexpr std::array choice_words<EulerPositionVelocity>{"updated", "start"};
template <> inline constexpr std::array choice_words<NewmarkPositionVelocity>{"projected", "corrected", "predicted"};
template <> inline constexpr std::array choice_words<NewmarkParticleVelocity>{"eq32", "average"};

/// The word a scene writes for a choice ("lme" for ShapeKind::lme).
template <class Choice>
std::string name_of(Choice choice) {
  return choice_words<Choice>.at(static_cast<std::size_t>(choice));
}

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
  MaterialSettings material;  ///< the body's young_modulus, poisson_ratio, density: by default [material]'s
  std::vector<int> particles_per_cell;
  Placement placement{};
  BodyShape::Kind shape{};                      ///< box | ellipse | polygon (mpm/particles/body_shape.hpp) | file
  std::vector<std::array<double, 2>> vertices;  ///< polygon only, m
  std::string file;                             ///< file only: the CSV as given (mpm/io/particle_file.hpp)
  std::vector<FileParticle> particles;          ///< file only: its particles, read and checked with the scene
};

/// The body's shape, for seeding (mpm/particles/body_shape.hpp).
inline BodyShape body_shape(const BodySettings& body) {
  BodyShape shape;
  shape.kind = body.shape;
  std::copy(body.min.begin(), body.min.end(), shape.min.begin());
  std::copy(body.max.begin(), body.max.end(), shape.max.begin());
  shape.vertices = body.vertices;
  return shape;
}

struct VelocityBox {
  std::vector<double> min, max, velocity;
};

struct FixedSettings {
  WallFace face{};
  std::vector<int> components;  ///< 0: x, 1: y
  int axis() const { return static_cast<int>(face) / 2; }
  bool upper() const { return static_cast<int>(face) % 2 == 1; }
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
  double spacing = 0.0;  ///< length[0] / cells[0]
  // [material]
  double young_modulus = 0.0, poisson_ratio = 0.0, density = 0.0;
  // [[body]], [[initial_velocity]], [[fixed]], [gravity]
  std::vector<BodySettings> bodies;
  std::vector<VelocityBox> initial_velocities;
  std::vector<FixedSettings> fixed;
  std::vector<double> gravity;
  double ramp_period = 0.0;
  // [solver]
  ShapeKind shape{};
  IntegratorKind integrator{};
  double lme_gamma = 0.0, lme_tol = 0.0, lme_newton_tol = 0.0;
  int lme_max_iterations = 0;
  LmeOptions::BetaRule lme_beta{};
  LmeOptions::Neighbours lme_neighbours{};
  double newmark_gamma = 0.0;
  EulerPositionVelocity fe_position_velocity{};
  NewmarkPositionVelocity npc_position_velocity{};
  NewmarkParticleVelocity npc_velocity{};  ///< eq32 (the paper's Eq. 32) | average (Eq. 23, the Newmark average)
  double flip_fraction = 1.0;              ///< forward Euler's PIC/FLIP blend: 1 = FLIP (the paper's)
  StressUpdate stress_update{};            ///< forward Euler's stress update: usf (the paper's) | usl | musl
  KernelsKind kernels{};                   ///< the kernels' layer: fast (default) | reference
  RunControl control;
  // [[observer]], [output]
  std::vector<ObserverSettings> observers;
  // [constants], [initial_field], [body_force] (io/scene_formulas.hpp)
  SceneFormulas formulas;
  /// the exact solution written beside the observers (exact.csv) and evaluated by `mpm exact` and `mpm compare`
  ExactKind exact{};
  // [exact_parameters]
  int exact_mode = 1;                                ///< vibrating_bar: mode n
  std::optional<double> exact_velocity_amplitude;    ///< vibrating_bar: V, m/s
  std::vector<double> exact_displacement_amplitude;  ///< manufactured_small: [A]; manufactured_large: [a_x, a_y], m
  /// where each key read lies, by its full name ("body[0].vertices"): the file and line, or `--set(n)` and 1,
  /// for the errors found after the read (scene_error)
  std::map<std::string, std::pair<std::string, int>> locations;

  MaterialSettings material() const { return {young_modulus, poisson_ratio, density}; }
};

/// An error at a key of a read scene, located where the scene gives it (its table's line when it is left to
/// its default). \returns the SceneError to throw.
inline SceneError scene_error(const Scene& scene, const std::string& key, const std::string& what) {
  const auto found = scene.locations.find(key);
  if (found == scene.locations.end()) return SceneError(scene.file, 0, key, what);  // a default
  return SceneError(found->second.first, found->second.second, key, what);
}

/// The top of the soil column, H above the grid's origin: the highest of its bodies (the grid may reach
/// beyond it, room for nothing but the column's own margin).
inline double column_height(const Scene& scene) {
  double top = scene.origin.at(1);
  for (const BodySettings& body : scene.bodies) top = std::max(top, body.max.at(1));
  return top - scene.origin[1];
}

/// The speed of Eq. (42) at t = 0: the fastest material's wave speed sqrt(E/rho) and the fastest initial particle
/// speed, their maximum (solver.courant = "max") or their sum ("sum"). The scene's numbers give the bodies', the
/// boxes' and the particle files' velocities; `fastest_particle` adds what only the particles know (a formula of
/// [initial_field], an exact solution's initial velocity).
inline double initial_courant_speed(const Scene& scene, double fastest_particle = 0.0) {
  auto norm = [](const std::vector<double>& v) {
    return std::sqrt(std::inner_product(v.begin(), v.end(), v.begin(), 0.0));
  };
  double fastest = fastest_particle, wave_speed = 0.0;
  for (const auto& body : scene.bodies) {
    fastest = std::max(fastest, norm(body.velocity));
    for (const auto& particle : body.particles) fastest = std::max(fastest, std::hypot(particle.v_x, particle.v_y));
    wave_speed = std::max(wave_speed, std::sqrt(body.material.young_modulus / body.material.density));
  }
  for (const auto& box : scene.initial_velocities) fastest = std::max(fastest, norm(box.velocity));
  return scene.control.courant == CourantSpeed::maximum ? std::max(fastest, wave_speed) : fastest + wave_speed;
}

/// The Courant number of the first step: solver.cfl, or for a fixed step (solver.dt) dt C / h with C of Eq. (42)
/// at t = 0.
inline double initial_cfl(const Scene& scene) {
  if (!(scene.control.fixed_dt > 0.0)) return scene.control.cfl;
  return scene.control.fixed_dt * initial_courant_speed(scene) / scene.spacing;
}

TEST_CASE("Scene settings: choice names follow their enums, and errors after the read are located") {
  CHECK(name_of(ShapeKind::bspline3) == "bspline3");
  CHECK(name_of(NewmarkPositionVelocity::predicted) == "predicted");
  CHECK(name_of(LmeOptions::BetaRule::mean_neighbour_distance) == "mean_neighbour_distance");
  CHECK(name_of(LmeOptions::BetaRule::authors) == "authors");
  CHECK(name_of(LmeOptions::Neighbours::authors_patch) == "authors_patch");
  CHECK(name_of(BodyShape::Kind::file) == "file");
  CHECK(FixedSettings{WallFace::ymax, {}}.axis() == 1);
  CHECK(FixedSettings{WallFace::ymax, {}}.upper());
  CHECK(!FixedSettings{WallFace::xmin, {}}.upper());
  Scene scene;
  scene.file = "s.toml";
  scene.locations["body[0].vertices"] = {"--set(2)", 1};
  CHECK(scene_error(scene, "body[0].vertices", "bad").message() == "error: --set(2):1: body[0].vertices: bad");
  CHECK(scene_error(scene, "title", "bad").message() == "error: s.toml: title: bad");  // a default: no line to name
  scene.origin = {0.0, 1.0};
  scene.bodies = {BodySettings{{0.0, 1.0}, {1.0, 3.0}, {}, {}, {}, {}, {}, {}, {}, {}}};
  CHECK(column_height(scene) == 2.0);
}

}  // namespace mpm::io
