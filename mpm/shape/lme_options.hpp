/// \file
/// The options of the local max-ent (LME) shape functions and what both of their forms share: the support
/// radius R with its check that every point lies inside the convex hull of its neighbours, the rules for the
/// locality beta of the prior of Eq. (36), and the messages of a failed evaluation. The equations themselves are
/// in mpm/shape/lme_reference.hpp; everything is in cell units (lengths divided by h).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm {

struct LmeOptions {
  /// regularisation, \f$ \gamma = \beta h^2 \f$ (paper/04_shape_functions.md: beta = gamma / h^2)
  double gamma = 3.0;
  /// the prior \f$ e^{-\beta R^2} \f$ at the support radius R (A\&O06; authors: 1e-5)
  double support_tolerance = 1e-6;
  double newton_tolerance = 1e-10;  ///< convergence when \f$ |r| / h \f$ is at most this (paper/04_shape_functions.md)
  int max_iterations = 100;         ///< Newton updates of lambda per evaluation before ShapeFailure
  /// grid_spacing: beta = gamma / h^2 (the paper, A\&O06). mean_neighbour_distance: beta = gamma / hbar^2,
  /// hbar the mean distance from x to its current neighbours (the formula of the authors' LME_Beta on this
  /// project's neighbours, paper/09_choices.md). authors: the same formula on the authors' node patch
  /// (authors_beta_in_cell_units). The neighbours are those within R = h sqrt(-ln(support_tolerance) / gamma)
  /// under every rule (with hbar in R the radius would feed on itself: hbar ~ 2R/3 in 2D makes R grow unless
  /// the patch is capped).
  enum class BetaRule { grid_spacing, mean_neighbour_distance, authors } beta_rule = BetaRule::grid_spacing;
  /// support_radius: the nodes within R (A\&O06, the paper). authors_patch: the authors' 4^Dim node patch around the
  /// point's cell whatever R (lme_patch_neighbours; paper/09_choices.md, "The authors' neighbours"); R then only
  /// sets the hull condition of lme_radius_squared.
  enum class Neighbours { support_radius, authors_patch } neighbours = Neighbours::support_radius;
};

/// \f$ (R/h)^2 = -\ln(\mathrm{tol}) / \gamma \f$, the support radius where the prior
/// \f$ e^{-\beta R^2} = \mathrm{tol} \f$.
/// \throws std::invalid_argument if an option is out of range, or if R is shorter than the cell diagonal
/// \f$ h \sqrt{Dim} \f$: then a point could lie outside the convex hull of its neighbours, where LME does not exist.
template <int Dim>
double lme_radius_squared(const LmeOptions& options) {
  auto refuse = [](const std::string& what) { throw std::invalid_argument("LME: " + what); };
  std::ostringstream value;
  value << "gamma = " << options.gamma << ", support_tolerance = " << options.support_tolerance
        << ", newton_tolerance = " << options.newton_tolerance << ", max_iterations = " << options.max_iterations;
  if (!(options.gamma > 0.0 && std::isfinite(options.gamma))) refuse("gamma must be > 0 (" + value.str() + ")");
  if (!(options.support_tolerance > 0.0 && options.support_tolerance < 1.0))
    refuse("support_tolerance must be in (0, 1) (" + value.str() + ")");
  if (!(options.newton_tolerance > 0.0)) refuse("newton_tolerance must be > 0 (" + value.str() + ")");
  if (options.max_iterations < 1) refuse("max_iterations must be >= 1 (" + value.str() + ")");
  const double radius_squared = -std::log(options.support_tolerance) / options.gamma;
  if (radius_squared < Dim) {
    std::ostringstream message;
    message.precision(4);
    message << "support radius R = h sqrt(-ln(support_tolerance)/gamma) = " << std::sqrt(radius_squared)
            << " h is shorter than the cell diagonal " << std::sqrt(double(Dim))
            << " h, so a point may fall outside the convex hull of its neighbours: gamma = " << options.gamma
            << " is too large for support_tolerance = " << options.support_tolerance << " (need gamma <= "
            << -std::log(options.support_tolerance) / Dim << ", or support_tolerance <= "
            << std::exp(-options.gamma * Dim) << ")";
    refuse(message.str());
  }
  return radius_squared;
}

/// The authors' beta of the prior of Eq. (36), in cell units (NL-PartSol, commit 1d5da04: src/ShapeFun/LME.c,
/// LME_Beta and LME_Tributary_Nodes; src/MPM/Mesh_Tools.c calls them at each step, src/ShapeFun/Operators.c at
/// each evaluation):
/// \f[ \beta = \frac{\gamma}{\bar h^2}, \qquad \bar h = \frac{1}{|P|} \sum_{I \in P} |x - x_I| , \f]
/// P the nodes of the cell that holds x and of the cells that share a node with it, on the grid (fewer at its
/// edges). In 1D the distances are those on the authors' one-cell-high strip, each node counted at y = +-h/2 (twice,
/// which leaves the mean as it is): \f$ |x - x_I| = \sqrt{(x - x_I)^2 + h^2/4} \f$. The authors' patch also drops
/// the nodes beyond \f$ \sqrt{-\ln 10^{-5} / \beta} \f$ of the last evaluation; on the strip that drops none
/// (\f$ \beta h^2 \le 3.01 \f$ gives at least 1.96 h, the farthest node is at 1.58 h), in 2D it can drop the
/// corners of the 4 x 4 block at a first evaluation, which this rule keeps.
template <int Dim>
double authors_beta_in_cell_units(const Grid<Dim>& grid, const Vector<Dim>& x, double gamma) {
  static_assert(Dim == 1 || Dim == 2, "the authors' patch is defined in 1D (their strip) and 2D");
  const auto cell = grid.cell_of(x);
  std::array<int, 2> first{0, 0}, last{0, 0};  // node lattice range of the patch, per axis
  Vector<Dim> local = (x - grid.origin()) / grid.spacing();
  for (int axis = 0; axis < Dim; ++axis) {
    first[axis] = std::max(cell[axis] - 1, 0);
    last[axis] = std::min(cell[axis] + 1, grid.cells(axis) - 1) + 1;
  }
  const double strip = Dim == 1 ? 0.25 : 0.0;  // (y - y_I)^2 / h^2 on the authors' strip
  double sum = 0.0;
  int count = 0;
  for (int j = first[1]; j <= last[1]; ++j)
    for (int i = first[0]; i <= last[0]; ++i) {
      double squared = (local[0] - i) * (local[0] - i) + strip;
      if (Dim == 2) squared += (local[Dim - 1] - j) * (local[Dim - 1] - j);
      sum += std::sqrt(squared);
      ++count;
    }
  const double mean = sum / count;
  return gamma / (mean * mean);
}

/// \f$ \beta h^2 \f$ at x under the options' rule: \f$ \gamma \f$, or \f$ \gamma (h / \bar h)^2 \f$ under the authors'
/// formula (on the `count` neighbours at `offsets` = (x - x_I)/h, or on the authors' patch). Then beta varies with
/// x and Eq. (41), which takes beta constant, is not the exact gradient; the authors' code makes the same
/// approximation.
template <int Dim>
double lme_beta_in_cell_units(const LmeOptions& options, const Grid<Dim>& grid, const Vector<Dim>& x, int count,
                              const Vector<Dim>* offsets) {
  if (options.beta_rule == LmeOptions::BetaRule::grid_spacing) return options.gamma;
  if (options.beta_rule == LmeOptions::BetaRule::authors) return authors_beta_in_cell_units(grid, x, options.gamma);
  double mean = 0.0;
  for (int I = 0; I < count; ++I) mean += offsets[I].norm();
  mean /= count;
  return options.gamma / (mean * mean);
}

/// The failure of Newton's solve of Eq. (38) at a particle: its iterations, \f$ |r|/h \f$ and gamma, then `why`.
inline ShapeFailure lme_not_converged(int particle, int iterations, double residual, double gamma, const char* why) {
  std::ostringstream cause;
  cause.precision(3);
  cause << "LME Newton did not converge: " << iterations << " iterations, |r|/h = " << residual << ", gamma = " << gamma
        << why;
  return ShapeFailure(particle, cause.str());
}

/// The failure of Eq. (41) where J of Eq. (37) is singular at convergence (`determinant`: det J in cell units).
inline ShapeFailure lme_singular_hessian(int particle, int dimension, double determinant) {
  std::ostringstream cause;
  cause << "LME Hessian J is singular at convergence (x on the edge of the convex hull of its neighbours): det(J)/h^"
        << 2 * dimension << " = " << determinant;
  return ShapeFailure(particle, cause.str());
}

TEST_CASE("LME options: the hull condition on gamma and the support tolerance, each option's range") {
  LmeOptions options;
  options.gamma = 7.0;  // R = 1.405 h < sqrt(2) h with tol = 1e-6
  CHECK_THROWS_WITH_AS(lme_radius_squared<2>(options),
                       doctest::Contains("gamma = 7 is too large for support_tolerance = 1e-06"),
                       std::invalid_argument);
  CHECK(lme_radius_squared<1>(options) == doctest::Approx(-std::log(1e-6) / 7.0));  // 1D needs only R >= h
  options.support_tolerance = 1e-7;                                                   // R = 1.52 h
  CHECK_NOTHROW(lme_radius_squared<2>(options));
  options = LmeOptions();
  options.gamma = 0.0;
  CHECK_THROWS_AS(lme_radius_squared<1>(options), std::invalid_argument);
  options = LmeOptions();
  options.support_tolerance = 1.0;
  CHECK_THROWS_AS(lme_radius_squared<1>(options), std::invalid_argument);
  options = LmeOptions();
  options.newton_tolerance = 0.0;
  CHECK_THROWS_AS(lme_radius_squared<1>(options), std::invalid_argument);
  options = LmeOptions();
  options.max_iterations = 0;
  CHECK_THROWS_AS(lme_radius_squared<1>(options), std::invalid_argument);
}

TEST_CASE("The authors' beta: gamma / hbar^2 on their strip in 1D and on the 4 x 4 node patch in 2D, by hand") {
  const Grid<1> line(Vector<1>(0.0), 1.0, {10});
  // At a cell centre the strip's nodes are at sqrt(0.5^2 + 0.5^2) and sqrt(1.5^2 + 0.5^2), twice each:
  // hbar = (sqrt(2) + sqrt(10)) / 4, so beta h^2 = 48 / (sqrt(2) + sqrt(10))^2 = 3 (3 - sqrt(5)) = 2.292 at gamma 3.
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.5), 3.0) == doctest::Approx(3.0 * (3.0 - std::sqrt(5.0))));
  // At h/4 from the centre, either side: distances sqrt(d^2 + 1/4) for d = 0.25, 0.75, 1.25, 1.75: 2.242.
  const double quarter = (std::sqrt(0.3125) + std::sqrt(0.8125) + std::sqrt(1.8125) + std::sqrt(3.3125)) / 4.0;
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.75), 3.0) == doctest::Approx(3.0 / (quarter * quarter)));
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.25), 3.0) == doctest::Approx(3.0 / (quarter * quarter)));
  // In the end cells no cell lies beyond: three nodes, hbar = (sqrt(2) + sqrt(10) / 2) / 3, beta h^2 = 3.009.
  const double end = (std::sqrt(2.0) + std::sqrt(10.0) / 2.0) / 3.0;
  CHECK(authors_beta_in_cell_units(line, Vector<1>(0.5), 3.0) == doctest::Approx(3.0 / (end * end)));
  CHECK(authors_beta_in_cell_units(line, Vector<1>(9.5), 3.0) == doctest::Approx(3.0 / (end * end)));
  CHECK(authors_beta_in_cell_units(line, Vector<1>(4.5), 1.5) == doctest::Approx(1.5 * (3.0 - std::sqrt(5.0))));
  // 2D, a cell centre: 4 nodes at sqrt(2)/2, 8 at sqrt(10)/2, 4 at 3 sqrt(2)/2 (beta h^2 = 1.337 at gamma 3).
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {10, 10});
  const double centre = (4.0 * std::sqrt(0.5) + 8.0 * std::sqrt(2.5) + 4.0 * std::sqrt(4.5)) / 16.0;
  CHECK(authors_beta_in_cell_units(plane, Vector<2>(4.5, 6.5), 3.0) == doctest::Approx(3.0 / (centre * centre)));
  const double corner = (std::sqrt(0.5) * 4.0 + std::sqrt(2.5) * 4.0 + std::sqrt(4.5)) / 9.0;  // 3 x 3 nodes
  CHECK(authors_beta_in_cell_units(plane, Vector<2>(0.5, 0.5), 3.0) == doctest::Approx(3.0 / (corner * corner)));
  // The rule's dispatch: the mean distance to the given neighbours, 0.5 and 1.5 cells: hbar = 1, beta h^2 = gamma.
  LmeOptions options;
  options.beta_rule = LmeOptions::BetaRule::mean_neighbour_distance;
  const Vector<1> offsets[2] = {Vector<1>(0.5), Vector<1>(-1.5)};
  CHECK(lme_beta_in_cell_units(options, line, Vector<1>(4.5), 2, offsets) == doctest::Approx(3.0));
  const Vector<1> far[2] = {Vector<1>(1.0), Vector<1>(-2.0)};  // hbar = 1.5
  CHECK(lme_beta_in_cell_units(options, line, Vector<1>(4.5), 2, far) == doctest::Approx(3.0 / 2.25));
  options.beta_rule = LmeOptions::BetaRule::authors;
  CHECK(lme_beta_in_cell_units(options, line, Vector<1>(4.5), 2, far) == doctest::Approx(3.0 * (3.0 - std::sqrt(5.0))));
  options.beta_rule = LmeOptions::BetaRule::grid_spacing;
  CHECK(lme_beta_in_cell_units(options, line, Vector<1>(4.5), 2, far) == 3.0);
}

}  // namespace mpm
