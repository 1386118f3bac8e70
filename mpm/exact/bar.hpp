/// \file
/// Exact solution of the 1D linear elastic bar (appendix A.1-A.19, paper/06_exact_bar.md): the oracle of
/// the Dyka test. It shares no code with the solver.
///
/// Method. The bar obeys \f$ \rho v_t = \sigma_X \f$ and \f$ \sigma_t = E v_X \f$ (A.4-A.5). Two
/// Riemann invariants diagonalise the system (A.17-A.18): \f$ \mathfrak{R}^I = (-\sigma + Z v)/(2Z) \f$
/// travels to the right with speed \f$ c = \sqrt{E/\rho} \f$ and \f$ \mathfrak{R}^{II} = (\sigma + Z v)/(2Z) \f$
/// to the left, with \f$ Z = \rho c \f$. Each keeps its initial profile, shifted by \f$ ct \f$ (A.16).
/// The free end \f$ X = 0 \f$ (\f$ \sigma = 0 \f$) turns a left-going wave into an equal right-going one;
/// the fixed end \f$ X = L \f$ (\f$ v = 0 \f$) turns a right-going wave into its negative. Unfolding
/// these two reflections gives a single profile \f$ F \f$ of period \f$ 4L \f$ with
/// \f$ \mathfrak{R}^{II}(X,t) = F(X + ct) \f$ and \f$ \mathfrak{R}^{I}(X,t) = F(ct - X) \f$; the velocity and
/// stress follow from (A.19). For piecewise-constant initial data \f$ F \f$ is a step function: it is
/// tabulated once (jump positions and plateau values over one period), so every evaluation is exact
/// and every jump sits at a known position. At a jump the average of the two one-sided limits is
/// returned (paper/06_exact_bar.md, 'Boundary relations and the unfolded profile').
///
/// Coordinates are reference (material) coordinates X in metres, as in the small-strain appendix.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mpm::exact {

/// piecewise-constant initial data on [from, to] (reference coordinate X, metres)
struct BarPiece {
  double from;      ///< left end of the piece, m
  double to;        ///< right end of the piece, m
  double velocity;  ///< \f$ v_0 \f$ on the piece, m/s
  double stress;    ///< \f$ \sigma_0 \f$ on the piece, Pa (tension positive)
};

/// 1D linear elastic bar on [0, L], free at X = 0 (sigma = 0), fixed at X = L (v = 0).
///
/// The pieces must lie inside [0, L] and must not overlap (they may touch). Points not covered by any
/// piece start at rest and unstressed.
class ElasticBar {
 public:
  ElasticBar(double length, double young_modulus, double density, std::vector<BarPiece> initial_data)
      : length_(length), young_modulus_(young_modulus), density_(density), pieces_(std::move(initial_data)) {
    if (!(length_ > 0.0) || !(young_modulus_ > 0.0) || !(density_ > 0.0))
      throw std::invalid_argument("ElasticBar: length, Young's modulus and density must be positive");
    jump_tolerance_ = 1e-9 * length_;
    check_and_sort_pieces();
    tabulate_left_going_profile();
  }

  double length() const { return length_; }

  /// Eq. (A.6): \f$ c = \sqrt{E/\rho} \f$, the speed of both families of characteristics.
  double wave_speed() const { return std::sqrt(young_modulus_ / density_); }

  /// Eq. (A.19): \f$ Z = \sqrt{E\rho} = \rho c \f$, the impedance that converts velocity jumps into stress jumps.
  double impedance() const { return std::sqrt(young_modulus_ * density_); }

  /// Eq. (A.17) with (A.16): the right-going invariant
  /// \f$ \mathfrak{R}^I(X,t) = \frac{-\sigma + Z v}{2Z} = G(X - ct) \f$.
  /// The free-end relation \f$ \mathfrak{R}^I = \mathfrak{R}^{II} \f$ at \f$ X = 0 \f$ gives \f$ G(\xi) = F(-\xi) \f$,
  /// so \f$ \mathfrak{R}^I(X,t) = F(ct - X) \f$.
  double right_going(double reference_position, double time) const {
    const double position = checked_position(reference_position);
    return left_going_profile(wave_speed() * time - position);
  }

  /// Eq. (A.18) with (A.16): the left-going invariant
  /// \f$ \mathfrak{R}^{II}(X,t) = \frac{\sigma + Z v}{2Z} = F(X + ct) \f$.
  double left_going(double reference_position, double time) const {
    const double position = checked_position(reference_position);
    return left_going_profile(position + wave_speed() * time);
  }

  /// Eq. (A.19), first half: \f$ v(X,t) = \mathfrak{R}^I + \mathfrak{R}^{II} \f$.
  double velocity(double reference_position, double time) const {
    return right_going(reference_position, time) + left_going(reference_position, time);
  }

  /// Eq. (A.19), second half: \f$ \sigma(X,t) = Z\,(\mathfrak{R}^{II} - \mathfrak{R}^I) \f$ (tension positive).
  double stress(double reference_position, double time) const {
    return impedance() * (left_going(reference_position, time) - right_going(reference_position, time));
  }

  /// The displacement since t = 0, \f$ u(X,t) = \int_0^t v(X,s)\,ds \f$ with v of Eq. (A.19):
  /// \f[ u(X,t) = \frac1c\left[P(ct - X) - P(-X) + P(X + ct) - P(X)\right], \qquad P(y) = \int_0^y F, \f]
  /// exact for the step profile F (P is piecewise linear, summed over whole periods of F).
  double displacement(double reference_position, double time) const {
    const double position = checked_position(reference_position), c = wave_speed();
    return (profile_integral(c * time - position) - profile_integral(-position) + profile_integral(position + c * time) -
            profile_integral(position)) / c;
  }

 private:
  double length_;
  double young_modulus_;
  double density_;
  std::vector<BarPiece> pieces_;
  double jump_tolerance_ = 0.0;           ///< distance (m) within which a point counts as sitting on a jump of F
  std::vector<double> jump_positions_;    ///< jumps of F over one period, sorted, first 0, last 4L
  std::vector<double> plateau_values_;    ///< F between jump_positions_[i] and jump_positions_[i+1]
  std::vector<double> integral_to_jump_;  ///< \f$ \int_0^{y_i} F \f$ at each jump y_i of the period (last: the whole period)

  double period() const { return 4.0 * length_; }

  double checked_position(double reference_position) const {
    if (reference_position < -jump_tolerance_ || reference_position > length_ + jump_tolerance_)
      throw std::domain_error("ElasticBar: reference position " + std::to_string(reference_position) +
                              " m lies outside the bar [0, " + std::to_string(length_) + "] m");
    return std::clamp(reference_position, 0.0, length_);
  }

  void check_and_sort_pieces() {
    for (BarPiece& piece : pieces_) {
      if (!std::isfinite(piece.velocity) || !std::isfinite(piece.stress) || !(piece.from < piece.to) ||
          piece.from < -jump_tolerance_ || piece.to > length_ + jump_tolerance_)
        throw std::invalid_argument("ElasticBar: a piece must satisfy 0 <= from < to <= L with finite data");
      piece.from = std::max(piece.from, 0.0);
      piece.to = std::min(piece.to, length_);
    }
    std::sort(pieces_.begin(), pieces_.end(), [](const BarPiece& a, const BarPiece& b) { return a.from < b.from; });
    for (std::size_t i = 1; i < pieces_.size(); ++i)
      if (pieces_[i].from < pieces_[i - 1].to - jump_tolerance_)
        throw std::invalid_argument("ElasticBar: initial-data pieces overlap");
  }

  /// The piece holding X, or nullptr. Only called strictly inside a plateau, where X is never a piece end.
  const BarPiece* piece_at(double reference_position) const {
    for (const BarPiece& piece : pieces_)
      if (piece.from <= reference_position && reference_position <= piece.to) return &piece;
    return nullptr;
  }

  /// Eq. (A.17) at t = 0: \f$ \mathfrak{R}^I_0(X) = \frac{-\sigma_0(X) + Z v_0(X)}{2Z} \f$.
  double initial_right_going(double reference_position) const {
    const BarPiece* piece = piece_at(reference_position);
    if (piece == nullptr) return 0.0;
    return (-piece->stress + impedance() * piece->velocity) / (2.0 * impedance());
  }

  /// Eq. (A.18) at t = 0: \f$ \mathfrak{R}^{II}_0(X) = \frac{\sigma_0(X) + Z v_0(X)}{2Z} \f$.
  double initial_left_going(double reference_position) const {
    const BarPiece* piece = piece_at(reference_position);
    if (piece == nullptr) return 0.0;
    return (piece->stress + impedance() * piece->velocity) / (2.0 * impedance());
  }

  /// paper/06_exact_bar.md, 'Boundary relations and the unfolded profile': the left-going profile unfolded over one period \f$ 0 \le y < 4L \f$,
  /// \f[ F(y) = \begin{cases} \mathfrak{R}^{II}_0(y) & 0 \le y \le L
  ///     \\ -\mathfrak{R}^{I}_0(2L - y) & L < y \le 2L \text{ (fixed end: } \mathfrak{R}^I + \mathfrak{R}^{II} = 0)
  ///     \\ -\mathfrak{R}^{II}_0(y - 2L) & 2L < y \le 3L
  ///     \\ \mathfrak{R}^{I}_0(4L - y) & 3L < y < 4L \text{ (free end: } \mathfrak{R}^I = \mathfrak{R}^{II}) \end{cases} \f]
  /// Evaluated only strictly inside a plateau (never at a jump).
  double unfolded_left_going(double y) const {
    const double L = length_;
    if (y <= L) return initial_left_going(y);
    if (y <= 2.0 * L) return -initial_right_going(2.0 * L - y);
    if (y <= 3.0 * L) return -initial_left_going(y - 2.0 * L);
    return initial_right_going(4.0 * L - y);
  }

  /// Every X where the initial data may jump (the bar ends and the piece ends) appears in one period of
  /// F at its four images \f$ X,\; 2L - X,\; 2L + X,\; 4L - X \f$ (the unfolding of paper/06_exact_bar.md).
  void tabulate_left_going_profile() {
    const double L = length_;
    std::vector<double> jump_sources{0.0, L};
    for (const BarPiece& piece : pieces_) {
      jump_sources.push_back(piece.from);
      jump_sources.push_back(piece.to);
    }
    std::vector<double> images;
    for (double source : jump_sources) {
      images.push_back(source);
      images.push_back(2.0 * L - source);
      images.push_back(2.0 * L + source);
      images.push_back(4.0 * L - source);
    }
    std::sort(images.begin(), images.end());
    jump_positions_.clear();
    for (double image : images)
      if (jump_positions_.empty() || image - jump_positions_.back() > 2.0 * jump_tolerance_)
        jump_positions_.push_back(image);
    jump_positions_.front() = 0.0;      // images of X = 0 and X = L: exact
    jump_positions_.back() = period();  // 4L - 0
    plateau_values_.clear();
    for (std::size_t i = 0; i + 1 < jump_positions_.size(); ++i)
      plateau_values_.push_back(unfolded_left_going(0.5 * (jump_positions_[i] + jump_positions_[i + 1])));
    integral_to_jump_.assign(1, 0.0);
    for (std::size_t i = 0; i < plateau_values_.size(); ++i)
      integral_to_jump_.push_back(integral_to_jump_.back() + plateau_values_[i] * (jump_positions_[i + 1] - jump_positions_[i]));
  }

  /// paper/06_exact_bar.md: at the jump number `index` of the period, the average of the one-sided limits
  /// \f$ \tfrac12\,[F(y^-) + F(y^+)] \f$ (the plateaus wrap around: F has period 4L).
  double average_at_jump(std::size_t index) const {
    const std::size_t last = jump_positions_.size() - 1;  // jump_positions_[last] = 4L is jump 0 again
    const double before = (index == 0) ? plateau_values_.back() : plateau_values_[index - 1];
    const double after = (index == last) ? plateau_values_.front() : plateau_values_[index];
    return 0.5 * (before + after);
  }

  /// \f$ P(y) = \int_0^y F(s)\,ds \f$ for any real y: whole periods (\f$ \int_0^{4L} F \f$ each) plus the plateaus
  /// of the rest of a period, summed over the tabulated steps of F.
  double profile_integral(double y) const {
    auto within_period = [&](double upto) {  // \int_0^upto F, 0 <= upto <= 4L, from the integrals up to each jump
      const auto above = std::upper_bound(jump_positions_.begin(), jump_positions_.end(), upto);
      const std::size_t lower = std::min<std::size_t>(static_cast<std::size_t>(above - jump_positions_.begin()), plateau_values_.size()) - 1;
      return integral_to_jump_[lower] + plateau_values_[lower] * (upto - jump_positions_[lower]);
    };
    const double periods = std::floor(y / period());
    return periods * integral_to_jump_.back() + within_period(std::clamp(y - periods * period(), 0.0, period()));
  }

  /// paper/06_exact_bar.md: \f$ F(y) \f$ for any real y, using the period \f$ F(y + 4L) = F(y) \f$.
  double left_going_profile(double y) const {
    double y_in_period = std::fmod(y, period());
    if (y_in_period < 0.0) y_in_period += period();
    if (y_in_period >= period()) y_in_period -= period();
    const auto above = std::upper_bound(jump_positions_.begin(), jump_positions_.end(), y_in_period);
    const std::size_t upper = static_cast<std::size_t>(above - jump_positions_.begin());  // >= 1: first jump is 0
    const std::size_t lower = upper - 1;
    if (y_in_period - jump_positions_[lower] <= jump_tolerance_) return average_at_jump(lower);
    if (jump_positions_[upper] - y_in_period <= jump_tolerance_) return average_at_jump(upper);
    return plateau_values_[lower];
  }
};

// ---------------------------------------------------------------------------------------------------
// Tests. Every expected value below is derived by hand in the comments, never by the code under test.
// ---------------------------------------------------------------------------------------------------

TEST_CASE("Eq. (A.6), Eq. (A.19): exact::ElasticBar: wave speed and impedance of the Dyka bar (paper/06_exact_bar.md)") {
  const ElasticBar bar(0.1333, 200e9, 7833.0, {});
  CHECK(bar.wave_speed() == doctest::Approx(5053.02).epsilon(1e-6));  // sqrt(200e9 / 7833)
  CHECK(bar.impedance() == doctest::Approx(3.958e7).epsilon(1e-3));   // 7833 * 5053.02
  CHECK(bar.impedance() == doctest::Approx(7833.0 * bar.wave_speed()).epsilon(1e-14));
}

TEST_CASE("exact::ElasticBar: the displacement, by hand for the Dyka bar and as the integral of the velocity") {
  // The Dyka bar (v0 = -5 m/s on [0, a], a = L/4): the free end moves at v0 until t = a/c, then rests until
  // (2L - a)/c (the test below), so u(0, a/(2c)) = v0 a/(2c) and u(0, t) = v0 a/c for a/c < t < (2L - a)/c;
  // then at -v0 until (2L + a)/c: u(0, 2L/c) = v0 a/c - v0 a/c = 0. The fixed end never moves.
  const double length = 0.1333, quarter = length / 4.0, v0 = -5.0;
  const ElasticBar bar(length, 200e9, 7833.0, {{0.0, quarter, v0, 0.0}});
  const double c = bar.wave_speed();
  CHECK(bar.displacement(0.0, 0.0) == 0.0);
  CHECK(bar.displacement(0.0, 0.5 * quarter / c) == doctest::Approx(v0 * 0.5 * quarter / c).epsilon(1e-12));
  CHECK(bar.displacement(0.0, length / c) == doctest::Approx(v0 * quarter / c).epsilon(1e-12));
  CHECK(std::abs(bar.displacement(0.0, 2.0 * length / c)) <= 1e-12 * std::abs(v0) * quarter / c);
  CHECK(std::abs(bar.displacement(length, 0.77e-4)) <= 1e-15);
  // Messy data: (u(t + dt) - u(t - dt)) / 2dt = v wherever v is constant over [t - dt, t + dt] (F is a step
  // function), checked at 200 points over three periods, including times beyond one period of F.
  const ElasticBar messy(2.0, 3.0, 2.0, {{0.0, 0.3, 1.5, -2.0}, {0.5, 0.9, -0.7, 4.0}, {1.7, 2.0, -1.0, -3.0}});
  const double dt = 1e-7;
  int checked = 0;
  for (int i = 1; i < 200; ++i) {
    const double X = 0.37 + 0.001 * i, t = 3.0 * 4.0 * 2.0 / messy.wave_speed() * i / 200.0;
    const double before = messy.velocity(X, t - dt), after = messy.velocity(X, t + dt);
    if (before != after) continue;  // a front passes within dt
    ++checked;
    CHECK((messy.displacement(X, t + dt) - messy.displacement(X, t - dt)) / (2.0 * dt) == doctest::Approx(before).epsilon(1e-6).scale(1.0));
  }
  CHECK(checked > 150);
}

TEST_CASE("Eq. (A.19): exact::ElasticBar: boundary relations, v(L,t) = 0 and sigma(0,t) = 0, for any data and time") {
  // Deliberately messy data: velocity and stress, gaps, adjacent pieces, a piece touching each end.
  const double length = 2.0;
  const ElasticBar bar(length, 3.0, 2.0,
                       {{0.0, 0.3, 1.5, -2.0}, {0.5, 0.9, -0.7, 4.0}, {0.9, 1.2, 2.0, 0.5}, {1.7, 2.0, -1.0, -3.0}});
  const double round_trip = 4.0 * length / bar.wave_speed();
  for (int i = 0; i <= 1000; ++i) {
    const double time = 3.0 * round_trip * i / 1000.0;
    INFO("t = " << time);
    CHECK(std::abs(bar.velocity(length, time)) <= 1e-12);
    CHECK(std::abs(bar.stress(0.0, time)) <= 1e-12);
  }
}

TEST_CASE("Eq. (A.16), Eq. (A.17), Eq. (A.18), Eq. (A.19): exact::ElasticBar: the Dyka bar, velocity of the free end (paper/06_exact_bar.md)") {
  // L = 0.1333 m, a = L/4, v0 = -5 m/s on [0, a]. Hand derivation: R^I_0 = R^II_0 = v0/2 on [0, a], and
  // v(0,t) = 2 F(ct). Unfolding F (paper/06_exact_bar.md): F = v0/2 on [0, a], -v0/2 on [2L - a, 2L + a],
  // +v0/2 on [4L - a, 4L + a], ... so v(0,t) = v0 for ct < a, 0 until 2L - a, -v0 until 2L + a, 0 until
  // 4L - a, v0 until 4L + a, 0 until 6L - a, -v0 until 6L + a, 0 until 8L - a (204.5 us > 200 us).
  const double length = 0.1333, quarter = length / 4.0, v0 = -5.0;
  const ElasticBar bar(length, 200e9, 7833.0, {{0.0, quarter, v0, 0.0}});
  const double c = bar.wave_speed();
  const double a_over_c = quarter / c, l_over_c = length / c;
  // The interval ends of paper/06_exact_bar.md ('Values for the Dyka bar'), in microseconds, from the formulas above.
  const std::vector<double> ends{a_over_c,
                                 2.0 * l_over_c - a_over_c,
                                 2.0 * l_over_c + a_over_c,
                                 4.0 * l_over_c - a_over_c,
                                 4.0 * l_over_c + a_over_c,
                                 6.0 * l_over_c - a_over_c,
                                 6.0 * l_over_c + a_over_c,
                                 200e-6};
  // An earlier reading printed 165.0 for 6L/c + a/c = 158.28 + 6.60 = 164.88 us; rounded, that is 164.9.
  const std::vector<double> printed_ends_us{6.6, 46.2, 59.4, 98.9, 112.1, 151.7, 164.9, 200.0};
  const std::vector<double> plateau{-5.0, 0.0, 5.0, 0.0, -5.0, 0.0, 5.0, 0.0};
  for (std::size_t i = 0; i < ends.size(); ++i) CHECK(std::abs(ends[i] * 1e6 - printed_ends_us[i]) <= 0.0501);
  double start = 0.0;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (int k = 1; k <= 9; ++k) {  // nine times safely inside the interval (5% margin at each end)
      const double time = start + (ends[i] - start) * (0.05 + 0.1125 * (k - 1));
      INFO("interval " << i << ", t = " << time * 1e6 << " us");
      CHECK(bar.velocity(0.0, time) == doctest::Approx(plateau[i]).epsilon(1e-12).scale(1e-12));
      CHECK(std::abs(bar.stress(0.0, time)) <= 1e-6);
    }
    start = ends[i];
  }
  // At the jumps themselves: the average of the one-sided limits (paper/06_exact_bar.md).
  CHECK(bar.velocity(0.0, a_over_c) == doctest::Approx(-2.5));
  CHECK(bar.velocity(0.0, 2.0 * l_over_c - a_over_c) == doctest::Approx(2.5));
  CHECK(bar.velocity(quarter, 0.0) == doctest::Approx(-2.5));   // the initial discontinuity
  CHECK(bar.velocity(0.5 * quarter, 0.0) == doctest::Approx(-5.0));
  CHECK(bar.velocity(2.0 * quarter, 0.0) == 0.0);
}

TEST_CASE("Eq. (A.5), Eq. (A.19): exact::ElasticBar: Dyka tension plateau Z|v0|/2, its doubling at the fixed end, sigma = -Z v behind a right-going front") {
  // Hand derivation: R^I_0 = v0/2 on [0, a] plus its free-end image gives a right-going pulse of
  // R^I = v0/2 occupying X - ct in (-a, a); R^II = 0 in the interior for a < ct < L - a. There
  // v = R^I = v0/2 = -2.5 m/s and sigma = -Z R^I = -Z v0/2 = +98.95 MPa (tension). At the fixed end,
  // sigma(L,t) = -2 Z R^I(L,t) = -Z v0 = 197.9 MPa while L - ct lies in (-a, a).
  const double length = 0.1333, quarter = length / 4.0, v0 = -5.0;
  const ElasticBar bar(length, 200e9, 7833.0, {{0.0, quarter, v0, 0.0}});
  const double c = bar.wave_speed(), impedance = bar.impedance();
  const double middle = 0.5 * length, time = middle / c;  // pulse centred on the middle of the bar
  CHECK(bar.stress(middle, time) == doctest::Approx(98.95e6).epsilon(1e-3));
  CHECK(bar.stress(middle, time) == doctest::Approx(-impedance * v0 / 2.0).epsilon(1e-12));
  CHECK(bar.velocity(middle, time) == doctest::Approx(v0 / 2.0).epsilon(1e-12));
  for (double offset : {-0.9, -0.5, 0.0, 0.5, 0.9}) {  // inside the pulse: sigma = -Z v (right-going)
    const double position = middle + offset * quarter;
    CHECK(bar.stress(position, time) == doctest::Approx(-impedance * bar.velocity(position, time)).epsilon(1e-12));
  }
  // Rankine-Hugoniot across the leading front X = ct + a: [sigma] = -Z [v], both jumps known by hand.
  const double front = middle + quarter, step = 1e-3 * length;
  const double jump_velocity = bar.velocity(front + step, time) - bar.velocity(front - step, time);
  const double jump_stress = bar.stress(front + step, time) - bar.stress(front - step, time);
  CHECK(jump_velocity == doctest::Approx(-v0 / 2.0));
  CHECK(jump_stress == doctest::Approx(-impedance * jump_velocity).epsilon(1e-12));
  // Ahead of the front the bar is at rest and unstressed.
  CHECK(bar.velocity(front + 0.5 * quarter, time) == 0.0);
  CHECK(bar.stress(front + 0.5 * quarter, time) == 0.0);
  // Reflection at the fixed end: doubling while the pulse covers X = L, i.e. (L - a)/c < t < (L + a)/c.
  for (double fraction : {-0.8, -0.3, 0.0, 0.3, 0.8}) {
    const double reflecting = (length + fraction * quarter) / c;
    CHECK(bar.stress(length, reflecting) == doctest::Approx(197.9e6).epsilon(1e-3));
    CHECK(bar.stress(length, reflecting) == doctest::Approx(-impedance * v0).epsilon(1e-12));
    CHECK(std::abs(bar.velocity(length, reflecting)) <= 1e-12);
  }
}

TEST_CASE("Eq. (A.16), Eq. (A.17), Eq. (A.18), Eq. (A.19): exact::ElasticBar: a bar hitting the wall as a whole gives the square wave") {
  // Uniform v0 = +1 m/s towards the fixed end, sigma0 = 0: R^I_0 = R^II_0 = v0/2 on [0, L], hence
  // F = +v0/2 on (0, L), -v0/2 on (L, 3L), +v0/2 on (3L, 4L), v = F(ct - X) + F(ct + X),
  // sigma = Z [F(ct + X) - F(ct - X)]. Phase by phase (c t measured in L):
  //   0 < ct < L : X > L - ct (front from the wall): v = 0,   sigma = -Z v0;  X < L - ct: v = v0,  sigma = 0.
  //   L < ct < 2L: X < ct - L (release from the free end): v = -v0, sigma = 0; X > ct - L: v = 0, sigma = -Z v0.
  //  2L < ct < 3L: X > 3L - ct (tension front from the wall): v = 0, sigma = +Z v0; X < 3L - ct: v = -v0, sigma = 0.
  //  3L < ct < 4L: X < ct - 3L: v = v0, sigma = 0;  X > ct - 3L: v = 0, sigma = +Z v0.  Period 4L/c.
  // The free end therefore moves with v0 for ct < L, -v0 for L < ct < 3L, v0 for 3L < ct < 5L.
  const double length = 1.0, v0 = 1.0;
  const ElasticBar bar(length, 1e6, 1e3, {{0.0, length, v0, 0.0}});
  const double c = bar.wave_speed(), impedance = bar.impedance();
  CHECK(c == doctest::Approx(std::sqrt(1e3)));
  struct Expected { double ct_over_l, x_over_l, velocity, stress_over_z; };
  const std::vector<Expected> table{
      {0.25, 0.9, 0.0, -v0},  {0.25, 0.5, v0, 0.0},   {0.75, 0.5, 0.0, -v0}, {0.75, 0.1, v0, 0.0},
      {1.25, 0.1, -v0, 0.0},  {1.25, 0.5, 0.0, -v0},  {1.75, 0.5, -v0, 0.0}, {1.75, 0.9, 0.0, -v0},
      {2.25, 0.9, 0.0, v0},   {2.25, 0.5, -v0, 0.0},  {2.75, 0.1, -v0, 0.0}, {2.75, 0.5, 0.0, v0},
      {3.25, 0.1, v0, 0.0},   {3.25, 0.5, 0.0, v0},   {3.75, 0.5, v0, 0.0},  {3.75, 0.9, 0.0, v0},
      {4.25, 0.9, 0.0, -v0},  {4.25, 0.5, v0, 0.0},   {9.25, 0.9, 0.0, -v0}, {10.75, 0.9, 0.0, v0},
  };
  for (const Expected& row : table) {
    const double time = row.ct_over_l * length / c, position = row.x_over_l * length;
    INFO("ct/L = " << row.ct_over_l << ", X/L = " << row.x_over_l);
    CHECK(bar.velocity(position, time) == doctest::Approx(row.velocity).epsilon(1e-12).scale(1e-12));
    CHECK(bar.stress(position, time) == doctest::Approx(row.stress_over_z * impedance).epsilon(1e-12).scale(1e-12));
  }
  // Free end: the square wave v0, -v0, v0 with switches at ct = L, 3L, 5L.
  for (double ct : {0.1, 0.9, 1.1, 2.0, 2.9, 3.1, 4.0, 4.9, 5.1, 6.0}) {
    const double expected = (ct < 1.0 || (ct > 3.0 && ct < 5.0)) ? v0 : -v0;
    INFO("ct/L = " << ct);
    CHECK(bar.velocity(0.0, ct * length / c) == doctest::Approx(expected));
  }
  CHECK(bar.velocity(0.0, length / c) == doctest::Approx(0.0));  // at the switch: average of v0 and -v0
}

TEST_CASE("Eq. (A.17), Eq. (A.18), Eq. (A.19): exact::ElasticBar: a stress pulse splits into two halves, sigma = -Z v right-going and +Z v left-going") {
  // sigma0 = s on [0.4L, 0.6L], v0 = 0: R^I_0 = -s/(2Z), R^II_0 = s/(2Z). At ct = 0.25 L the halves are
  // centred at 0.75L (right-going: sigma = s/2, v = -s/(2Z)) and 0.25L (left-going: sigma = s/2, v = +s/(2Z)).
  // A compressive pulse (s < 0) pushes the material outwards on both sides.
  const double length = 1.0, pulse = -4e6;
  const ElasticBar bar(length, 2e9, 2e3, {{0.4, 0.6, 0.0, pulse}});
  const double time = 0.25 * length / bar.wave_speed(), impedance = bar.impedance();
  CHECK(bar.stress(0.75, time) == doctest::Approx(pulse / 2.0));
  CHECK(bar.velocity(0.75, time) == doctest::Approx(-pulse / (2.0 * impedance)));
  CHECK(bar.stress(0.25, time) == doctest::Approx(pulse / 2.0));
  CHECK(bar.velocity(0.25, time) == doctest::Approx(pulse / (2.0 * impedance)));
  CHECK(bar.stress(0.5, time) == 0.0);
  CHECK(bar.velocity(0.5, time) == 0.0);
  CHECK(bar.right_going(0.75, time) == doctest::Approx(-pulse / (2.0 * impedance)));
  CHECK(bar.left_going(0.75, time) == 0.0);
}

/// Midpoint sum of f over [from, to] with n intervals (a plain quadrature for the balance-law tests).
template <class Function>
double midpoint_integral(Function f, double from, double to, int n) {
  const double width = (to - from) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += f(from + (i + 0.5) * width);
  return sum * width;
}

TEST_CASE("Eq. (A.17), Eq. (A.18): the invariants of the initial data, by hand") {
  // E = 4 Pa, rho = 1 kg/m^3: c = 2 m/s, Z = 2. On [0.3, 0.5]: v0 = 1.5, sigma0 = 2, hence
  // R^I_0 = (-2 + 2 * 1.5) / 4 = 0.25 and R^II_0 = (2 + 2 * 1.5) / 4 = 1.25; elsewhere both are 0.
  const ElasticBar bar(1.0, 4.0, 1.0, {{0.3, 0.5, 1.5, 2.0}});
  CHECK(bar.wave_speed() == doctest::Approx(2.0).epsilon(1e-15));
  CHECK(bar.impedance() == doctest::Approx(2.0).epsilon(1e-15));
  CHECK(bar.right_going(0.4, 0.0) == doctest::Approx(0.25).epsilon(1e-15));
  CHECK(bar.left_going(0.4, 0.0) == doctest::Approx(1.25).epsilon(1e-15));
  CHECK(bar.right_going(0.1, 0.0) == 0.0);
  CHECK(bar.left_going(0.7, 0.0) == 0.0);
  // (A.19) inverts them: v = 0.25 + 1.25 = 1.5 and sigma = 2 (1.25 - 0.25) = 2, the data.
  CHECK(bar.velocity(0.4, 0.0) == doctest::Approx(1.5).epsilon(1e-15));
  CHECK(bar.stress(0.4, 0.0) == doctest::Approx(2.0).epsilon(1e-15));
}

TEST_CASE("Eq. (A.5), Eq. (A.1): jumps across a wave front, [sigma] = -Z [v] right-going and +Z [v] left-going") {
  // A front moving with speed s carries jumps that satisfy the balance laws in integral form:
  // (A.1) rho v_t = sigma_X gives -s rho [v] = [sigma], (A.5) sigma_t = E v_X gives -s [sigma] = E [v].
  // Both hold with s = +c and [sigma] = -Z [v] (right-going), or s = -c and [sigma] = +Z [v] (left-going).
  // Data of the test above (c = 2, Z = 2, R^I_0 = 0.25, R^II_0 = 1.25 on [0.3, 0.5]); at t = 0.075 s,
  // ct = 0.15 m, before any wave reaches an end, by hand:
  //   X in (0.15, 0.35): the left-going half,  v = 1.25, sigma = Z * 1.25 = 2.5;
  //   X in (0.35, 0.45): at rest, unstressed;
  //   X in (0.45, 0.65): the right-going half, v = 0.25, sigma = -Z * 0.25 = -0.5; at rest elsewhere.
  const ElasticBar bar(1.0, 4.0, 1.0, {{0.3, 0.5, 1.5, 2.0}});
  const double time = 0.075, impedance = 2.0, c = 2.0;
  struct Plateau { double position, velocity, stress; };
  for (const Plateau& plateau : std::vector<Plateau>{{0.05, 0.0, 0.0}, {0.25, 1.25, 2.5}, {0.40, 0.0, 0.0},
                                                     {0.55, 0.25, -0.5}, {0.80, 0.0, 0.0}}) {
    INFO("X = " << plateau.position);
    CHECK(bar.velocity(plateau.position, time) == doctest::Approx(plateau.velocity).epsilon(1e-14).scale(1.0));
    CHECK(bar.stress(plateau.position, time) == doctest::Approx(plateau.stress).epsilon(1e-14).scale(1.0));
  }
  struct Front { double position, direction, velocity_jump; };  // direction +1: right-going
  const std::vector<Front> fronts{{0.15, -1.0, 1.25}, {0.35, -1.0, -1.25}, {0.45, 1.0, 0.25}, {0.65, 1.0, -0.25}};
  const double side = 1e-6;
  for (const Front& front : fronts) {
    INFO("front at X = " << front.position);
    const double jump_velocity = bar.velocity(front.position + side, time) - bar.velocity(front.position - side, time);
    const double jump_stress = bar.stress(front.position + side, time) - bar.stress(front.position - side, time);
    CHECK(jump_velocity == doctest::Approx(front.velocity_jump).epsilon(1e-14));
    CHECK(jump_stress == doctest::Approx(-front.direction * impedance * front.velocity_jump).epsilon(1e-14));
    // The two balance laws across a front of speed s = direction * c, rho = 1, E = 4:
    CHECK(-front.direction * c * 1.0 * jump_velocity == doctest::Approx(jump_stress).epsilon(1e-14));
    CHECK(-front.direction * c * jump_stress == doctest::Approx(4.0 * jump_velocity).epsilon(1e-14));
    // and the front has moved by ct = 0.15 m from its initial position 0.3 or 0.5 m (A.6).
    const double start = front.position - front.direction * c * time;
    CHECK((std::abs(start - 0.3) < 1e-12 || std::abs(start - 0.5) < 1e-12));
  }
}

TEST_CASE("Eq. (A.1), Eq. (A.4): momentum balance rho v_t = sigma_X in integral form over segments, through reflections") {
  // Integrated over a segment [a, b] and a time interval [t1, t2], (A.1) reads
  //   rho (int_a^b v(X, t2) dX - int_a^b v(X, t1) dX) = int_t1^t2 (sigma(b, t) - sigma(a, t)) dt,
  // which holds for the piecewise-constant exact solution too; the integrands jump, so the midpoint
  // sums agree to about (number of jumps) * (value scale) * (interval / n).
  const double young = 4.0, density = 1.0;
  const ElasticBar bar(1.0, young, density, {{0.1, 0.3, 1.0, 0.5}, {0.5, 0.8, -0.5, -1.0}, {0.9, 1.0, 0.3, 0.0}});
  const int n = 200000;
  struct Window { double a, b, t1, t2; };
  for (const Window& w : std::vector<Window>{{0.2, 0.7, 0.05, 0.35}, {0.0, 1.0, 0.0, 2.3}, {0.45, 0.55, 0.6, 1.9}}) {
    INFO("segment [" << w.a << ", " << w.b << "], times [" << w.t1 << ", " << w.t2 << "]");
    const double momentum_change =
        density * (midpoint_integral([&](double x) { return bar.velocity(x, w.t2); }, w.a, w.b, n) -
                   midpoint_integral([&](double x) { return bar.velocity(x, w.t1); }, w.a, w.b, n));
    const double impulse =
        midpoint_integral([&](double t) { return bar.stress(w.b, t) - bar.stress(w.a, t); }, w.t1, w.t2, n);
    CHECK(std::abs(momentum_change - impulse) <= 1e-4);
  }
  // The check can fail: with the sign of the stress reversed the balance is off by twice the impulse.
  const double wrong = midpoint_integral([&](double t) { return bar.stress(0.2, t) - bar.stress(0.7, t); }, 0.05, 0.35, n);
  const double right = midpoint_integral([&](double t) { return bar.stress(0.7, t) - bar.stress(0.2, t); }, 0.05, 0.35, n);
  CHECK(std::abs(wrong - right) > 0.1);
}

TEST_CASE("Eq. (A.2), Eq. (A.3), Eq. (A.5): sigma_t = E v_X in integral form over segments, through reflections") {
  // (A.2) sigma = E eps and (A.3) eps_t = v_X give (A.5) sigma_t = E v_X; over [a, b] x [t1, t2]:
  //   int_a^b sigma(X, t2) dX - int_a^b sigma(X, t1) dX = E int_t1^t2 (v(b, t) - v(a, t)) dt.
  const double young = 4.0, density = 1.0;
  const ElasticBar bar(1.0, young, density, {{0.1, 0.3, 1.0, 0.5}, {0.5, 0.8, -0.5, -1.0}, {0.9, 1.0, 0.3, 0.0}});
  const int n = 200000;
  struct Window { double a, b, t1, t2; };
  for (const Window& w : std::vector<Window>{{0.2, 0.7, 0.05, 0.35}, {0.0, 1.0, 0.0, 2.3}, {0.45, 0.55, 0.6, 1.9}}) {
    INFO("segment [" << w.a << ", " << w.b << "], times [" << w.t1 << ", " << w.t2 << "]");
    const double stress_change = midpoint_integral([&](double x) { return bar.stress(x, w.t2); }, w.a, w.b, n) -
                                 midpoint_integral([&](double x) { return bar.stress(x, w.t1); }, w.a, w.b, n);
    const double stretching =
        young * midpoint_integral([&](double t) { return bar.velocity(w.b, t) - bar.velocity(w.a, t); }, w.t1, w.t2, n);
    CHECK(std::abs(stress_change - stretching) <= 2e-4);
  }
}

TEST_CASE("Eq. (A.16): each invariant keeps its value along its characteristic, X -+ c s in time s") {
  // R^I(X + c s, t + s) = R^I(X, t) and R^II(X - c s, t + s) = R^II(X, t) while the characteristic
  // stays inside the bar; messy data, many points and times, jumps included (averages travel too).
  const ElasticBar bar(2.0, 3.0, 2.0, {{0.0, 0.3, 1.5, -2.0}, {0.5, 0.9, -0.7, 4.0}, {1.7, 2.0, -1.0, -3.0}});
  const double c = bar.wave_speed();
  int checked = 0;
  for (int i = 0; i <= 40; ++i) {
    const double position = 2.0 * i / 40.0, time = 0.37 * i;
    for (double shift : {0.05, 0.2, 0.6}) {
      const double s = shift / c;
      if (position + shift <= 2.0) {
        CHECK(bar.right_going(position + shift, time + s) == doctest::Approx(bar.right_going(position, time)).epsilon(1e-12).scale(1.0));
        ++checked;
      }
      if (position - shift >= 0.0) {
        CHECK(bar.left_going(position - shift, time + s) == doctest::Approx(bar.left_going(position, time)).epsilon(1e-12).scale(1.0));
        ++checked;
      }
    }
  }
  CHECK(checked > 200);
}

TEST_CASE("exact::ElasticBar: energy of the exact solution is conserved") {
  // E(t) = int_0^L (rho v^2 / 2 + sigma^2 / (2E)) dX. Initially (Dyka): rho v0^2 a / 2; (messy data): sum over pieces.
  const double length = 0.1333, young = 200e9, density = 7833.0;
  const std::vector<std::vector<BarPiece>> cases{
      {{0.0, length / 4.0, -5.0, 0.0}},
      {{0.0, 0.02, 3.0, -1e7}, {0.05, 0.07, -2.0, 4e7}, {0.1, length, 1.0, 2e7}},
  };
  for (const std::vector<BarPiece>& pieces : cases) {
    const ElasticBar bar(length, young, density, pieces);
    double initial_energy = 0.0;
    for (const BarPiece& piece : pieces)
      initial_energy += (piece.to - piece.from) *
                        (0.5 * density * piece.velocity * piece.velocity + 0.5 * piece.stress * piece.stress / young);
    const int samples = 20000;
    const double spacing = length / samples, period = 4.0 * length / bar.wave_speed();
    for (double fraction : {0.0731, 0.21, 0.377, 0.5, 0.6662, 0.9, 1.4142, 1.9}) {
      const double time = fraction * period;
      double energy = 0.0;
      for (int i = 0; i < samples; ++i) {
        const double position = (i + 0.5) * spacing;
        const double v = bar.velocity(position, time), s = bar.stress(position, time);
        energy += spacing * (0.5 * density * v * v + 0.5 * s * s / young);
      }
      INFO("t / period = " << fraction);
      CHECK(energy == doctest::Approx(initial_energy).epsilon(1e-3));
    }
  }
}

TEST_CASE("exact::ElasticBar: invalid input is refused") {
  CHECK_THROWS_AS(ElasticBar(0.0, 1.0, 1.0, {}), std::invalid_argument);
  CHECK_THROWS_AS(ElasticBar(1.0, -1.0, 1.0, {}), std::invalid_argument);
  CHECK_THROWS_AS(ElasticBar(1.0, 1.0, 1.0, {{0.5, 0.4, 1.0, 0.0}}), std::invalid_argument);
  CHECK_THROWS_AS(ElasticBar(1.0, 1.0, 1.0, {{0.5, 1.5, 1.0, 0.0}}), std::invalid_argument);
  CHECK_THROWS_AS(ElasticBar(1.0, 1.0, 1.0, {{0.0, 0.6, 1.0, 0.0}, {0.5, 0.8, 1.0, 0.0}}), std::invalid_argument);
  const ElasticBar bar(1.0, 1.0, 1.0, {{0.0, 0.5, 1.0, 0.0}, {0.5, 1.0, 2.0, 0.0}});  // touching pieces are fine
  CHECK(bar.velocity(0.75, 0.0) == 2.0);
  CHECK_THROWS_AS(bar.velocity(1.1, 0.0), std::domain_error);
  CHECK_THROWS_AS(bar.stress(-0.1, 0.0), std::domain_error);
}

}  // namespace mpm::exact
