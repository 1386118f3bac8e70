/// \file
/// The exact solution a scene names (its `exact` key) at any material point X (its reference position, in the
/// scene's coordinates) and time, in SI units: what `mpm exact` prints, `mpm compare` measures against and exact.csv
/// holds. The solutions live in mpm/exact/ and share no code with the solver; this file reads their parameters.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/exact/bar.hpp"
#include "mpm/exact/column.hpp"
#include "mpm/exact/column_log_strain.hpp"
#include "mpm/exact/manufactured.hpp"
#include "mpm/exact/vibrating_bar.hpp"
#include "mpm/exact/vibrating_bar_finite_strain.hpp"
#include "mpm/io/scene.hpp"

namespace mpm::io {

/// small: the paper's small-strain solutions; finite: the finite-strain references of the solver's
/// updated-Lagrangian model (soil_column, vibrating_bar).
enum class StrainMeasure { small, finite };

/// The quantities of a dimension, in the order of `mpm exact`'s columns.
inline std::vector<std::string> exact_quantities(int dimension) {
  if (dimension == 1) return {"u_x", "v_x", "sigma_xx"};
  return {"u_x", "u_y", "v_x", "v_y", "sigma_xx", "sigma_yy", "sigma_xy"};
}

/// One material point at one time: u since t = 0 (m), v (m/s), Cauchy stress (Pa, tension positive).
struct ExactState {
  double u_x = 0.0, u_y = 0.0, v_x = 0.0, v_y = 0.0, sigma_xx = 0.0, sigma_yy = 0.0, sigma_xy = 0.0;

  /// The quantity by its name in exact_quantities(); \throws std::invalid_argument for another name.
  double quantity(const std::string& name) const {
    static const std::vector<std::string> names = exact_quantities(2);  // in the order of the members
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) throw std::invalid_argument("no quantity '" + name + "'");
    return std::array{u_x, u_y, v_x, v_y, sigma_xx, sigma_yy, sigma_xy}[found - names.begin()];
  }
};

/// 0 for a displacement (u_...), 1 for a velocity (v_...), 2 for a stress.
inline int quantity_kind(const std::string& quantity) {
  return quantity.rfind("u_", 0) == 0 ? 0 : quantity.rfind("v_", 0) == 0 ? 1 : 2;
}

/// The unit of a quantity of exact_quantities().
inline std::string quantity_unit(const std::string& quantity) {
  return std::array{"m", "m/s", "Pa"}[quantity_kind(quantity)];
}

/// True if the scene's exact solution has a finite-strain reference (StrainMeasure::finite).
inline bool has_finite_strain_reference(ExactKind exact) {
  return exact == ExactKind::soil_column || exact == ExactKind::vibrating_bar;
}

namespace detail {

/// The dyka_bar's initial data as pieces of constant (v_0, sigma_0) on [0, L] from the free end: v_0 the body's,
/// replaced by [initial_field]'s and then by the last [[initial_velocity]] box holding the point; sigma_0
/// [initial_field]'s or 0. Sampled at 4096 midpoints, each change located by bisection to 1e-14 L.
/// \throws SceneError when a formula is not finite, or the data take more than 1024 values (not piecewise constant).
inline std::vector<exact::BarPiece> scene_bar_pieces(const Scene& scene) {
  const double length = scene.length[0];
  const auto& velocity_formula = scene.formulas.initial_velocity;
  const auto& stress_formula = scene.formulas.initial_stress;
  auto formula_at = [&](const FormulaList& list, double x) {
    const double value = list.components[0](&x, &x, 0.0);
    if (std::isfinite(value)) return value;
    std::ostringstream what;
    what << "'" << list.components[0].text() << "' is " << value << " at X = " << x << "; dyka_bar needs finite data";
    throw SceneError(list.source.file, list.source.line, list.source.key, what.str());
  };
  auto data_at = [&](double X) {  // (v_0, sigma_0) at X from the free end; the first body wins at a shared end
    const double x = scene.origin[0] + X;
    double velocity = 0.0;
    for (auto body = scene.bodies.rbegin(); body != scene.bodies.rend(); ++body)
      if (x >= body->min[0] && x <= body->max[0]) velocity = body->velocity[0];
    if (velocity_formula) velocity = formula_at(*velocity_formula, x);
    for (const auto& box : scene.initial_velocities)
      if (x >= box.min[0] && x <= box.max[0]) velocity = box.velocity[0];
    return std::pair{velocity, stress_formula ? formula_at(*stress_formula, x) : 0.0};
  };
  constexpr int intervals = 4096;
  std::vector<exact::BarPiece> pieces;
  auto previous = data_at(0.5 * length / intervals);
  for (int i = 1; i <= intervals; ++i) {
    const auto current = i < intervals ? data_at((i + 0.5) * length / intervals) : previous;
    if (i < intervals && current == previous) continue;
    double lower = (i - 0.5) * length / intervals, upper = (i + 0.5) * length / intervals;
    while (i < intervals && upper - lower > 1e-14 * length) {  // left of lower the data are `previous`
      const double middle = 0.5 * (lower + upper);
      (data_at(middle) == previous ? lower : upper) = middle;
    }
    pieces.push_back({pieces.empty() ? 0.0 : pieces.back().to, i < intervals ? 0.5 * (lower + upper) : length,
                      previous.first, previous.second});
    if (pieces.size() > 1024) {
      const std::string what =
          "takes more than 1024 values along the bar: dyka_bar needs piecewise-constant initial data "
          "(a smooth field is the vibrating_bar's)";
      const auto& list = velocity_formula ? velocity_formula : stress_formula;
      if (!list) throw scene_error(scene, "initial_velocity[0].min", what);
      throw SceneError(list->source.file, list->source.line, list->source.key, what);
    }
    previous = current;
  }
  return pieces;
}

}  // namespace detail

/// The scene's exact solution, built once from the scene and evaluated at any (X, t).
class SceneExactSolution {
 public:
  /// `times`: those that will be asked (the finite-strain vibrating bar is solved up to them); `pieces`: the
  /// dyka_bar's initial data when not the scene's. \throws SceneError for no or an unusable exact solution,
  /// std::invalid_argument for a strain measure it has no reference for.
  SceneExactSolution(const Scene& scene, StrainMeasure strain, const std::vector<double>& times = {},
                     std::optional<std::vector<exact::BarPiece>> pieces = std::nullopt)
      : scene_(scene) {
    if (scene.exact == ExactKind::none)
      throw scene_error(scene, "exact",
                        "the scene names no exact solution (exact = \"none\"); give one of dyka_bar, "
                        "soil_column, vibrating_bar, manufactured_small, manufactured_large");
    if (strain == StrainMeasure::finite && !has_finite_strain_reference(scene.exact))
      throw std::invalid_argument("'" + name_of(scene.exact) +
                                  "' has no separate finite-strain reference (only soil_column and vibrating_bar)");
    if (scene.exact == ExactKind::dyka_bar) bar(pieces ? *pieces : detail::scene_bar_pieces(scene));
    if (scene.exact == ExactKind::soil_column) column(strain);
    if (scene.exact == ExactKind::vibrating_bar) vibrating(strain, times);
    if (scene.exact == ExactKind::manufactured_small || scene.exact == ExactKind::manufactured_large) manufactured();
  }

  /// The cells of the finite-strain vibrating bar's reference (second order: relative error ~ (k h)^2).
  static constexpr int finite_strain_cells = 512;
  /// The most steps the CLI lets the finite-strain vibrating bar take (about 3 s of work).
  static constexpr double most_finite_strain_steps = 2e6;

  /// The steps the finite-strain vibrating bar takes to reach `last_time`, at its step 0.9 (L/cells) sqrt(0.8 rho/E).
  static double finite_strain_steps(const Scene& scene, double last_time) {
    return last_time /
           (0.9 * scene.length[0] / finite_strain_cells * std::sqrt(0.8 * scene.density / scene.young_modulus));
  }

  /// Empty if the point (scene coordinates) lies in the solution's body [origin, origin + length]; else why not.
  std::string outside(const std::vector<double>& point) const {
    for (int axis = 0; axis < scene_.dimension; ++axis) {
      const double lower = scene_.origin[axis], upper = scene_.origin[axis] + scene_.length[axis];
      const double tolerance = 1e-9 * scene_.spacing;
      if (point[axis] >= lower - tolerance && point[axis] <= upper + tolerance) continue;
      std::ostringstream what;
      what << "lies outside the body [" << lower << ", " << upper << "] m on " << (axis == 0 ? "x" : "y")
           << " (a reference position in the scene's coordinates)";
      return what.str();
    }
    return "";
  }

  /// The state of the material point `point` (scene coordinates, clamped into the body) at time t >= 0.
  ExactState at(const std::vector<double>& point, double time) const {
    return state_(clamped(point, 0), scene_.dimension == 2 ? clamped(point, 1) : 0.0, time);
  }

  /// The solution's longest period (s): 4L/c of the bars, 4H/c of the column, 2 pi/omega of the manufactured
  /// motions. Beyond a million of them the values lose their precision: the CLI refuses such times.
  double period() const { return period_; }

  /// The scale by which `mpm compare` divides the RMS error of a quantity (same unit):
  ///   dyka_bar       v: V* = the largest |v_0| or |sigma_0|/Z of the initial data; sigma: Z V*; u: V* L / c
  ///   soil_column    sigma: rho g H; u: rho g H^2 / (2M), the top's static settlement; v: g H / c
  ///   vibrating_bar  v: |V|; sigma: Z |V|; u: |V| / omega
  ///   manufactured   v: omega max|a|; sigma: (lambda + 2G) kappa max(|a_x|, 2|a_y|) (small: A); u: max|a|
  double scale(const std::string& quantity) const { return scales_[quantity_kind(quantity)]; }

 private:
  const Scene& scene_;
  std::function<ExactState(double X, double Y, double t)> state_;  ///< X, Y from the origin
  std::array<double, 3> scales_{};                                 ///< of u, v, sigma: scale()
  double period_ = 0.0;

  /// A state along x only (the bars).
  static ExactState axial(double u, double v, double sigma) { return {u, 0.0, v, 0.0, sigma}; }

  /// exact::ElasticBar, appendix A.1-A.19, from the pieces of its initial data.
  void bar(const std::vector<exact::BarPiece>& data) {
    const auto bar = std::make_shared<exact::ElasticBar>(scene_.length[0], scene_.young_modulus, scene_.density, data);
    double velocity = 0.0;
    for (const auto& piece : data)
      velocity = std::max({velocity, std::abs(piece.velocity), std::abs(piece.stress) / bar->impedance()});
    scales_ = {velocity * scene_.length[0] / bar->wave_speed(), velocity, bar->impedance() * velocity};
    period_ = 4.0 * scene_.length[0] / bar->wave_speed();
    state_ = [bar](double X, double, double t) {  // + 0.0: no -0
      return axial(bar->displacement(X, t) + 0.0, bar->velocity(X, t) + 0.0, bar->stress(X, t) + 0.0);
    };
  }

  /// exact::SoilColumn (paper/07_exact_column.md) or, finite, the static exact::SoilColumnLogStrain at every t;
  /// both laterally confined: sigma_xx = nu/(1 - nu) sigma_yy.
  void column(StrainMeasure strain) {
    const double E = scene_.young_modulus, rho = scene_.density, nu = scene_.poisson_ratio, H = column_height(scene_);
    const double M = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)), g = -scene_.gravity[1], ratio = nu / (1.0 - nu);
    const auto small = std::make_shared<exact::SoilColumn>(H, M, rho, g, scene_.ramp_period);
    const auto finite = std::make_shared<exact::SoilColumnLogStrain>(H, M, rho, g);
    scales_ = {rho * g * H * H / (2.0 * M), g * H / small->wave_speed(), rho * g * H};
    period_ = 4.0 * H / small->wave_speed();
    state_ = [=](double, double Y, double t) {
      ExactState state;
      const bool dynamic = strain == StrainMeasure::small;
      state.u_y = dynamic ? small->displacement(Y, t) : finite->displacement(Y);
      state.v_y = dynamic ? small->velocity(Y, t) : 0.0;
      state.sigma_yy = dynamic ? small->stress(Y, t) : finite->stress(Y);
      state.sigma_xx = ratio * state.sigma_yy;
      return state;
    };
  }

  /// exact::VibratingBar, mode n and amplitude V of [exact_parameters]; finite: exact::FiniteStrainBar solved up
  /// to the times that will be asked.
  void vibrating(StrainMeasure strain, std::vector<double> times) {
    const double L = scene_.length[0], E = scene_.young_modulus, rho = scene_.density,
                 V = *scene_.exact_velocity_amplitude;
    const auto bar = std::make_shared<exact::VibratingBar>(L, E, rho, V, scene_.exact_mode);
    scales_ = {std::abs(V) / bar->angular_frequency(), std::abs(V), bar->impedance() * std::abs(V)};
    period_ = 4.0 * L / bar->wave_speed();
    state_ = [bar](double X, double, double t) {
      return axial(bar->displacement(X, t), bar->velocity(X, t), bar->stress(X, t));
    };
    if (strain == StrainMeasure::small) return;
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    std::shared_ptr<exact::FiniteStrainBar> finite;
    try {
      finite = std::make_shared<exact::FiniteStrainBar>(L, E, rho, V, finite_strain_cells, times, scene_.exact_mode);
    } catch (const std::runtime_error& failure) {
      throw scene_error(scene_, "exact_parameters.velocity_amplitude", failure.what());
    }
    state_ = [finite, times](double X, double, double t) {
      const auto found = std::lower_bound(times.begin(), times.end(), t);
      if (found == times.end() || *found != t)
        throw std::logic_error("FiniteStrainBar: a time not given at construction");
      const int output = static_cast<int>(found - times.begin());
      return axial(finite->displacement(X, output), finite->velocity(X, output), finite->stress(X, output));
    };
  }

  /// exact::ManufacturedSmall (A of [exact_parameters]) or exact::ManufacturedLarge ([a_x, a_y]) on the square.
  void manufactured() {
    const exact::ManufacturedMaterial material{scene_.length[0], scene_.young_modulus, scene_.poisson_ratio,
                                               scene_.density};
    const std::vector<double>& a = scene_.exact_displacement_amplitude;
    period_ = 2.0 * exact::ManufacturedMaterial::pi / material.angular_frequency();
    auto plane = [](const exact::Pair& u, const exact::Pair& v, const exact::PlaneStress& sigma) {
      return ExactState{u[0], u[1], v[0], v[1], sigma.xx, sigma.yy, sigma.xy};
    };
    if (scene_.exact == ExactKind::manufactured_small) {
      const auto small = std::make_shared<exact::ManufacturedSmall>(material, a[0]);
      scales_ = {std::abs(a[0]), small->velocity_scale(), small->stress_scale()};
      state_ = [small, plane](double X, double Y, double t) {
        return plane(small->displacement({X, Y}, t), small->velocity({X, Y}, t), small->stress({X, Y}, t));
      };
      return;
    }
    const auto large = std::make_shared<exact::ManufacturedLarge>(material, a[0], a[1]);
    scales_ = {std::max(std::abs(a[0]), std::abs(a[1])), large->velocity_scale(), large->stress_scale()};
    state_ = [large, plane](double X, double Y, double t) {
      const exact::Pair x = large->position({X, Y}, t);
      return plane({x[0] - X, x[1] - Y}, large->velocity({X, Y}, t), large->stress({X, Y}, t));
    };
  }

  /// The coordinate on `axis` from the origin, clamped into [0, length] (outside() has checked it to 1e-9 cells).
  double clamped(const std::vector<double>& point, int axis) const {
    return std::clamp(point[axis] - scene_.origin[axis], 0.0, scene_.length[axis]);
  }
};

TEST_CASE("SceneExactSolution: the Dyka bar's pieces from the scene, each jump exact, the values at the free end by hand") {
  // The bar [1, 1.1333] (origin 1): body at rest, a box at -5 m/s on x <= 1.05 (X <= 0.05, not on a cell line),
  // then a box at +2 m/s on [1.12, 1.2]; the initial stress -1 MPa from a formula on X > 0.1.
  const std::string text =
      "exact = \"dyka_bar\"\n[grid]\norigin = [1.0]\nlength = [0.1333]\ncells = [40]\n[material]\nyoung_modulus = 200e9\n"
      "density = 7833.0\n[[body]]\nmin = [1.0]\nmax = [1.1333]\n[[initial_velocity]]\nmin = [0.0]\nmax = [1.05]\n"
      "velocity = [-5.0]\n[[initial_velocity]]\nmin = [1.12]\nmax = [1.2]\nvelocity = [2.0]\n"
      "[initial_field]\nstress = [\"X > 1.1 ? -1e6 : 0\"]\n[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[solver]\nend_time = 1e-4\n";
  const Scene scene = read_scene(parse_scene_text(text, "bar.toml"));
  const auto pieces = detail::scene_bar_pieces(scene);
  REQUIRE(pieces.size() == 4);
  CHECK(pieces[0].from == 0.0);
  CHECK(pieces[0].to == doctest::Approx(0.05).epsilon(1e-12));
  CHECK(pieces[0].velocity == -5.0);
  CHECK(pieces[1].to == doctest::Approx(0.1).epsilon(1e-12));
  CHECK(pieces[1].velocity == 0.0);
  CHECK(pieces[2].to == doctest::Approx(0.12).epsilon(1e-12));
  CHECK(pieces[2].stress == -1e6);
  CHECK(pieces[3].to == doctest::Approx(0.1333).epsilon(1e-15));
  CHECK(pieces[3].velocity == 2.0);
  // At the free end (x = 1) before any wave arrives from X = 0.05 (t < 0.05 / c): v = v_0 = -5, sigma = 0,
  // u = -5 t; the scale of v is the largest of |v_0| = 5 and |sigma_0| / Z = 1e6 / 3.958e7.
  const SceneExactSolution solution(scene, StrainMeasure::small);
  const double c = std::sqrt(200e9 / 7833.0), t = 0.5 * 0.05 / c;
  const ExactState state = solution.at({1.0}, t);
  CHECK(state.v_x == -5.0);
  CHECK(state.sigma_xx == 0.0);
  CHECK(state.u_x == doctest::Approx(-5.0 * t).epsilon(1e-12));
  CHECK(solution.scale("v_x") == 5.0);
  CHECK(solution.scale("sigma_xx") == doctest::Approx(5.0 * std::sqrt(200e9 * 7833.0)).epsilon(1e-14));
  CHECK(solution.outside({0.99}).find("lies outside the body [1, 1.1333] m on x") == 0);
  CHECK(solution.outside({1.1333}).empty());
  CHECK_THROWS_AS(SceneExactSolution(scene, StrainMeasure::finite), std::invalid_argument);

  // A bar of two bodies, [0, 0.3] at -2 m/s and [0.3, 1] at rest: each piece has its body's velocity.
  const std::string two_bodies =
      "exact = \"dyka_bar\"\n[grid]\nlength = [1.0]\ncells = [10]\n[material]\nyoung_modulus = 1.0\ndensity = 1.0\n"
      "[[body]]\nmin = [0.0]\nmax = [0.3]\nvelocity = [-2.0]\n[[body]]\nmin = [0.3]\nmax = [1.0]\n"
      "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[solver]\nend_time = 1.0\n";
  const auto two = detail::scene_bar_pieces(read_scene(parse_scene_text(two_bodies, "two.toml")));
  REQUIRE(two.size() == 2);
  CHECK(two[0].velocity == -2.0);
  CHECK(two[0].to == doctest::Approx(0.3).epsilon(1e-12));
  CHECK(two[1].velocity == 0.0);
}

TEST_CASE("SceneExactSolution: the column's sigma_xx = nu/(1 - nu) sigma_yy, the finite-strain column is static") {
  const std::string text =
      "dimension = 2\nexact = \"soil_column\"\n[grid]\nlength = [10.0, 10.0]\ncells = [5, 5]\n[material]\nyoung_modulus = 5e6\n"
      "poisson_ratio = 0.25\ndensity = 6000.0\n[[body]]\nmin = [0.0, 0.0]\nmax = [10.0, 10.0]\n"
      "[[fixed]]\nface = \"ymin\"\ncomponents = [\"y\"]\n[[fixed]]\nface = \"xmin\"\ncomponents = [\"x\"]\n"
      "[[fixed]]\nface = \"xmax\"\ncomponents = [\"x\"]\n[gravity]\nacceleration = [0.0, -9.81]\n[solver]\nend_time = 1.0\n";
  const Scene scene = read_scene(parse_scene_text(text, "column.toml"));
  const SceneExactSolution small(scene, StrainMeasure::small), finite(scene, StrainMeasure::finite);
  const ExactState base = finite.at({3.0, 0.0}, 7.0);
  CHECK(base.sigma_yy == doctest::Approx(-6000.0 * 9.81 * 10.0).epsilon(1e-14));  // rho g H at the base
  CHECK(base.sigma_xx == doctest::Approx(-6000.0 * 9.81 * 10.0 / 3.0).epsilon(1e-14));  // nu/(1 - nu) = 1/3
  CHECK(finite.at({3.0, 10.0}, 0.0).v_y == 0.0);
  const ExactState moving = small.at({3.0, 10.0}, 0.1);  // free fall at first (constant gravity): v = -g t
  CHECK(moving.v_y == doctest::Approx(-0.981).epsilon(1e-3));
  CHECK(moving.u_x == 0.0);
  CHECK(small.scale("sigma_yy") == doctest::Approx(588600.0).epsilon(1e-14));
}

}  // namespace mpm::io
