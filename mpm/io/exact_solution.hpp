/// \file
/// The exact solution a scene names (its `exact` key), at any material point and time: what `mpm exact`
/// prints, what `mpm compare` measures a CSV against and what a run's exact.csv holds.
///
/// The solutions themselves live in mpm/exact/ and share no code with the solver; this file only
/// reads their parameters from the scene (length, material, initial data, gravity, [exact_parameters]).
/// Every value is in SI units: displacement u since t = 0 (m), velocity v (m/s), Cauchy stress sigma
/// (Pa, tension positive), at the material point X given by its reference position in the scene's
/// coordinates (the grid's origin is the scene's, as for observer positions).
///
///   dyka_bar            exact::ElasticBar (appendix A.1-A.19): the bar's initial data are the scene's, read
///                       from body.velocity, [initial_field] and [[initial_velocity]] as pieces (below)
///   soil_column         exact::SoilColumn (paper/07_exact_column.md); with StrainMeasure::finite the static
///                       finite-strain settlement exact::SoilColumnLogStrain at every t (v = 0); in both,
///                       sigma_xx = nu/(1 - nu) sigma_yy (the column is laterally confined, or nu = 0)
///   vibrating_bar       exact::VibratingBar, mode n and amplitude V of [exact_parameters]; with
///                       StrainMeasure::finite exact::FiniteStrainBar (512 cells), solved up to the times asked
///   manufactured_small  exact::ManufacturedSmall on [origin, origin + L]^2, A of [exact_parameters]
///   manufactured_large  exact::ManufacturedLarge, [a_x, a_y] of [exact_parameters] (finite strain as the solver's)
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
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

/// One material point at one time: u (m), v (m/s), Cauchy stress (Pa, tension positive).
struct ExactState {
  double u_x = 0.0, u_y = 0.0, v_x = 0.0, v_y = 0.0, sigma_xx = 0.0, sigma_yy = 0.0, sigma_xy = 0.0;

  /// The quantity by its name in exact_quantities(); \throws std::invalid_argument for another name.
  double quantity(const std::string& name) const {
    if (name == "u_x") return u_x;
    if (name == "u_y") return u_y;
    if (name == "v_x") return v_x;
    if (name == "v_y") return v_y;
    if (name == "sigma_xx") return sigma_xx;
    if (name == "sigma_yy") return sigma_yy;
    if (name == "sigma_xy") return sigma_xy;
    throw std::invalid_argument("no quantity '" + name + "'");
  }
};

/// The quantities of a dimension, in the order of `mpm exact`'s columns: 1D u_x, v_x, sigma_xx;
/// 2D u_x, u_y, v_x, v_y, sigma_xx, sigma_yy, sigma_xy.
inline std::vector<std::string> exact_quantities(int dimension) {
  if (dimension == 1) return {"u_x", "v_x", "sigma_xx"};
  return {"u_x", "u_y", "v_x", "v_y", "sigma_xx", "sigma_yy", "sigma_xy"};
}

/// The unit of a quantity of exact_quantities().
inline std::string quantity_unit(const std::string& quantity) {
  if (quantity.rfind("u_", 0) == 0) return "m";
  if (quantity.rfind("v_", 0) == 0) return "m/s";
  return "Pa";
}

/// True if the scene's exact solution has a finite-strain reference (StrainMeasure::finite).
inline bool has_finite_strain_reference(ExactKind exact) { return exact == ExactKind::soil_column || exact == ExactKind::vibrating_bar; }

namespace detail {

/// The dyka_bar's initial data read from the scene as pieces of constant velocity and stress on the bar
/// [0, L] (measured from the free end, origin): v_0 is the velocity of the body that holds the point, replaced by [initial_field] velocity
/// where given, replaced by each [[initial_velocity]] box that holds the point (later boxes win, as at the
/// particles); sigma_0 is [initial_field] stress, else 0. The bar is sampled at the midpoints of 4096
/// equal intervals and every change between neighbours is located by bisection to 1e-14 L, so each jump
/// is exact to round-off; a piece shorter than L/4096 between two samples is missed.
/// \throws SceneError when a formula is not finite, or when the data take more than 1024 values
/// (not piecewise constant: a smooth field is the vibrating_bar's).
inline std::vector<exact::BarPiece> scene_bar_pieces(const Scene& scene) {
  const double origin = scene.origin[0], length = scene.length[0];
  const SceneFormulas& formulas = scene.formulas;
  auto formula_at = [&](const FormulaList& list, double x) {
    const double value = list.components[0](&x, &x, 0.0);
    if (!std::isfinite(value)) {
      std::ostringstream what;
      what << "'" << list.components[0].text() << "' is " << value << " at X = " << x << "; dyka_bar needs finite data";
      throw SceneError(list.source.file, list.source.line, list.source.key, what.str());
    }
    return value;
  };
  auto data_at = [&](double X) {  // (v_0, sigma_0) at X from the free end
    const double x = origin + X;
    double velocity = 0.0;  // of the body that holds x (the bodies fill the bar; the first wins at a shared end)
    for (auto body = scene.bodies.rbegin(); body != scene.bodies.rend(); ++body)
      if (x >= body->min[0] && x <= body->max[0]) velocity = body->velocity[0];
    if (formulas.initial_velocity) velocity = formula_at(*formulas.initial_velocity, x);
    for (const auto& box : scene.initial_velocities)
      if (x >= box.min[0] && x <= box.max[0]) velocity = box.velocity[0];
    const double stress = formulas.initial_stress ? formula_at(*formulas.initial_stress, x) : 0.0;
    return std::pair{velocity, stress};
  };
  constexpr int intervals = 4096;
  constexpr size_t most_pieces = 1024;
  std::vector<exact::BarPiece> pieces;
  double from = 0.0;
  auto previous = data_at(0.5 * length / intervals);
  for (int i = 1; i <= intervals; ++i) {
    const double X = (i + 0.5) * length / intervals;
    const auto current = i < intervals ? data_at(X) : previous;
    if (i < intervals && current == previous) continue;
    double jump = length;
    if (i < intervals) {  // bisection between the midpoints: the value left of lower is `previous`
      double lower = (i - 0.5) * length / intervals, upper = X;
      while (upper - lower > 1e-14 * length) {
        const double middle = 0.5 * (lower + upper);
        (data_at(middle) == previous ? lower : upper) = middle;
      }
      jump = 0.5 * (lower + upper);
    }
    pieces.push_back({from, jump, previous.first, previous.second});
    if (pieces.size() > most_pieces) {
      const std::string key = formulas.initial_velocity ? "initial_field.velocity" : "initial_field.stress";
      const FormulaSource& source = formulas.initial_velocity ? formulas.initial_velocity->source : formulas.initial_stress->source;
      throw SceneError(source.file, source.line, key,
                       "takes more than 1024 values along the bar: dyka_bar needs piecewise-constant initial data "
                       "(a smooth field is the vibrating_bar's)");
    }
    from = jump;
    previous = current;
  }
  return pieces;
}

}  // namespace detail

/// The scene's exact solution, built once from the scene and evaluated at any (X, t).
class SceneExactSolution {
 public:
  /// `times`: the times that will be asked (read by the finite-strain vibrating bar only, which is solved
  /// up to them); `pieces`: the dyka_bar's initial data when not the scene's (exact.csv takes them from
  /// the particles). \throws SceneError if the scene names no exact solution or its data are unusable;
  /// std::invalid_argument if the strain measure has no reference for this solution.
  SceneExactSolution(const Scene& scene, StrainMeasure strain, const std::vector<double>& times = {},
                     std::optional<std::vector<exact::BarPiece>> pieces = std::nullopt)
      : scene_(scene), strain_(strain) {
    const ExactKind name = scene.exact;
    if (name == ExactKind::none)
      throw scene_error(scene, "exact", "the scene names no exact solution (exact = \"none\"); give one of dyka_bar, "
                                               "soil_column, vibrating_bar, manufactured_small, manufactured_large");
    if (strain == StrainMeasure::finite && !has_finite_strain_reference(name))
      throw std::invalid_argument("'" + name_of(name) + "' has no separate finite-strain reference (only soil_column and vibrating_bar)");
    const double E = scene.young_modulus, rho = scene.density, nu = scene.poisson_ratio;
    if (name == ExactKind::dyka_bar) {
      const std::vector<exact::BarPiece> data = pieces ? *pieces : detail::scene_bar_pieces(scene);
      bar_ = std::make_unique<exact::ElasticBar>(scene.length[0], E, rho, data);
      double velocity = 0.0;
      for (const auto& piece : data)
        velocity = std::max({velocity, std::abs(piece.velocity), std::abs(piece.stress) / bar_->impedance()});
      scale_velocity_ = velocity;
      scale_stress_ = bar_->impedance() * velocity;
      scale_displacement_ = velocity * scene.length[0] / bar_->wave_speed();
      period_ = 4.0 * scene.length[0] / bar_->wave_speed();
    } else if (name == ExactKind::soil_column) {
      const double M = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)), g = -scene.gravity[1], H = column_height(scene);
      column_ = std::make_unique<exact::SoilColumn>(H, M, rho, g, scene.ramp_period);
      column_finite_ = std::make_unique<exact::SoilColumnLogStrain>(H, M, rho, g);
      scale_stress_ = rho * g * H;
      scale_displacement_ = rho * g * H * H / (2.0 * M);
      scale_velocity_ = g * H / column_->wave_speed();
      period_ = 4.0 * H / column_->wave_speed();
    } else if (name == ExactKind::vibrating_bar) {
      const double V = *scene.exact_velocity_amplitude;
      vibrating_ = std::make_unique<exact::VibratingBar>(scene.length[0], E, rho, V, scene.exact_mode);
      if (strain == StrainMeasure::finite) {
        times_ = times;
        std::sort(times_.begin(), times_.end());
        times_.erase(std::unique(times_.begin(), times_.end()), times_.end());
        try {
          vibrating_finite_ = std::make_unique<exact::FiniteStrainBar>(scene.length[0], E, rho, V, finite_strain_cells, times_,
                                                                       scene.exact_mode);
        } catch (const std::runtime_error& failure) {
          throw scene_error(scene, "exact_parameters.velocity_amplitude", failure.what());
        }
      }
      scale_velocity_ = std::abs(V);
      scale_stress_ = vibrating_->impedance() * std::abs(V);
      scale_displacement_ = std::abs(V) / vibrating_->angular_frequency();
      period_ = 4.0 * scene.length[0] / vibrating_->wave_speed();
    } else {
      const exact::ManufacturedMaterial material{scene.length[0], E, nu, rho};
      const std::vector<double>& a = scene.exact_displacement_amplitude;
      period_ = 2.0 * exact::ManufacturedMaterial::pi / material.angular_frequency();
      if (name == ExactKind::manufactured_small) {
        small_ = std::make_unique<exact::ManufacturedSmall>(material, a[0]);
        scale_velocity_ = small_->velocity_scale();
        scale_stress_ = small_->stress_scale();
        scale_displacement_ = std::abs(a[0]);
      } else {
        large_ = std::make_unique<exact::ManufacturedLarge>(material, a[0], a[1]);
        scale_velocity_ = large_->velocity_scale();
        scale_stress_ = large_->stress_scale();
        scale_displacement_ = std::max(std::abs(a[0]), std::abs(a[1]));
      }
    }
  }

  /// The cells of the finite-strain vibrating bar's reference (second order: relative error ~ (k h)^2, 4e-5 for mode 1).
  static constexpr int finite_strain_cells = 512;

  /// The time steps the finite-strain vibrating bar's reference takes to reach `last_time`: its step is
  /// 0.9 (L/cells) sqrt(0.8 rho/E) (mpm/exact/vibrating_bar_finite_strain.hpp). The CLI refuses more than
  /// most_finite_strain_steps (about 3 s of work).
  static double finite_strain_steps(const Scene& scene, double last_time) {
    const double step = 0.9 * scene.length[0] / finite_strain_cells * std::sqrt(0.8 * scene.density / scene.young_modulus);
    return last_time / step;
  }
  static constexpr double most_finite_strain_steps = 2e6;

  /// Empty if the point (scene coordinates, one entry per axis) is a material point of the solution's body,
  /// the box [origin, origin + length]; else what is wrong.
  std::string outside(const std::vector<double>& point) const {
    for (int axis = 0; axis < scene_.dimension; ++axis) {
      const double lower = scene_.origin[axis], upper = scene_.origin[axis] + scene_.length[axis];
      const double tolerance = 1e-9 * scene_.spacing;
      if (!(point[axis] >= lower - tolerance && point[axis] <= upper + tolerance)) {
        std::ostringstream what;
        what << "lies outside the body [" << lower << ", " << upper << "] m on " << (axis == 0 ? "x" : "y")
             << " (a reference position in the scene's coordinates)";
        return what.str();
      }
    }
    return "";
  }

  /// The state of the material point `point` (scene coordinates) at time t >= 0.
  ExactState at(const std::vector<double>& point, double time) const {
    ExactState state;
    const double X = clamped(point, 0), Y = scene_.dimension == 2 ? clamped(point, 1) : 0.0;
    if (bar_) {
      state.u_x = bar_->displacement(X, time) + 0.0;  // + 0.0: no -0
      state.v_x = bar_->velocity(X, time) + 0.0;
      state.sigma_xx = bar_->stress(X, time) + 0.0;
    } else if (column_) {
      const double ratio = scene_.poisson_ratio / (1.0 - scene_.poisson_ratio);
      if (strain_ == StrainMeasure::small) {
        state.u_y = column_->displacement(Y, time);
        state.v_y = column_->velocity(Y, time);
        state.sigma_yy = column_->stress(Y, time);
      } else {
        state.u_y = column_finite_->displacement(Y);
        state.sigma_yy = column_finite_->stress(Y);
      }
      state.sigma_xx = ratio * state.sigma_yy;
    } else if (vibrating_finite_) {
      const auto found = std::lower_bound(times_.begin(), times_.end(), time);
      if (found == times_.end() || *found != time) throw std::logic_error("FiniteStrainBar: a time not given at construction");
      const int output = static_cast<int>(found - times_.begin());
      state.u_x = vibrating_finite_->displacement(X, output);
      state.v_x = vibrating_finite_->velocity(X, output);
      state.sigma_xx = vibrating_finite_->stress(X, output);
    } else if (vibrating_) {
      state.u_x = vibrating_->displacement(X, time);
      state.v_x = vibrating_->velocity(X, time);
      state.sigma_xx = vibrating_->stress(X, time);
    } else {
      const exact::Pair reference{X, Y};
      exact::Pair displacement, velocity;
      exact::PlaneStress stress;
      if (small_) {
        displacement = small_->displacement(reference, time), velocity = small_->velocity(reference, time);
        stress = small_->stress(reference, time);
      } else {
        const exact::Pair position = large_->position(reference, time);
        displacement = {position[0] - X, position[1] - Y}, velocity = large_->velocity(reference, time);
        stress = large_->stress(reference, time);
      }
      state.u_x = displacement[0], state.u_y = displacement[1], state.v_x = velocity[0], state.v_y = velocity[1];
      state.sigma_xx = stress.xx, state.sigma_yy = stress.yy, state.sigma_xy = stress.xy;
    }
    return state;
  }

  /// The solution's longest period (s): 4L/c of the bars (the round trip of a wave, the first mode's period),
  /// 4H/c of the column's first mode, 2 pi/omega of the manufactured motions. Beyond a million of them the
  /// values lose their precision (c t or omega t carries no digit below a millionth of a period): the CLI
  /// refuses such times.
  double period() const { return period_; }

  /// The scale by which `mpm compare` divides the RMS error of a quantity (same unit):
  ///   dyka_bar            v: V* = the largest |v_0| or |sigma_0|/Z of the initial data (v0 = 5 m/s for the Dyka
  ///                       bar, so RMS/scale is the paper's RMS/v0); sigma: Z V*; u: V* L / c
  ///   soil_column         sigma: rho g H (the base's static stress); u: rho g H^2 / (2M) (the top's static
  ///                       settlement); v: g H / c (the velocity of a wave carrying the base's static strain)
  ///   vibrating_bar       v: |V|; sigma: Z |V|; u: |V| / omega
  ///   manufactured_small  v: A omega; sigma: (lambda + 2G) kappa A; u: |A|
  ///   manufactured_large  v: omega max|a|; sigma: (lambda + 2G) kappa max(|a_x|, 2|a_y|); u: max|a|
  double scale(const std::string& quantity) const {
    if (quantity.rfind("u_", 0) == 0) return scale_displacement_;
    if (quantity.rfind("v_", 0) == 0) return scale_velocity_;
    return scale_stress_;
  }

 private:
  const Scene& scene_;
  StrainMeasure strain_;
  std::vector<double> times_;
  std::unique_ptr<exact::ElasticBar> bar_;
  std::unique_ptr<exact::SoilColumn> column_;
  std::unique_ptr<exact::SoilColumnLogStrain> column_finite_;
  std::unique_ptr<exact::VibratingBar> vibrating_;
  std::unique_ptr<exact::FiniteStrainBar> vibrating_finite_;
  std::unique_ptr<exact::ManufacturedSmall> small_;
  std::unique_ptr<exact::ManufacturedLarge> large_;
  double scale_velocity_ = 0.0, scale_stress_ = 0.0, scale_displacement_ = 0.0, period_ = 0.0;

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
