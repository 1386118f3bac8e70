/// \file
/// uGIMP shape functions: the "uniform" generalised interpolation material point weights of
/// Bardenhagen & Kober (2004), as the authors use them (paper/04_shape_functions.md).
///
/// A particle is a segment (1D) or rectangle (2D) of half-length \f$ l_p \f$ per axis, centred at
/// \f$ x_p \f$. Its weight at node I is the linear hat averaged over the particle,
/// \f$ S(\Delta) = \frac{1}{2 l_p} \int_{\Delta - l_p}^{\Delta + l_p} \hat N(s)\, ds \f$ with
/// \f$ \Delta = x_p - x_I \f$ and \f$ \hat N(s) = \max(0, 1 - |s|/h) \f$, and in 2D the tensor product
/// \f$ N_I = S(\Delta_x) S(\Delta_y) \f$. "Uniform": \f$ l_p \f$ is fixed at seeding
/// (\f$ h / (2\,\mathrm{ppc}) \f$ per axis) and never updated, however the body deforms.
///
/// Unlike the linear hat, S is C1: grad N does not jump when a particle crosses a cell face,
/// which is why uGIMP has less grid-crossing noise than linear shapes (Fig. 6).
///
/// At the grid's edge (a wall, or a free end with no margin) the particle's domain is clipped to
/// the grid, the usual treatment of GIMP domains at a boundary: per axis the segment
/// \f$ [x_p - l_p, x_p + l_p] \cap [x_{min}, x_{max}] = [a, b] \f$ replaces the particle's, and the weight
/// and its gradient are the hat and the hat's gradient averaged over it,
/// \f$ S_I = \frac{1}{b - a}\int_a^b \hat N_I \f$, \f$ G_I = \frac{\hat N_I(b) - \hat N_I(a)}{b - a} \f$: the formulas
/// above with centre (a + b)/2 and half-length (b - a)/2. Partition of unity, \f$ \sum_I G_I = 0 \f$ and
/// \f$ \sum_I x_I \otimes \nabla N_I = \mathbf I \f$ (a uniform stretch gives its exact strain rate) hold;
/// \f$ \sum_I N_I x_I \f$ is the clipped centre, and G is no longer the derivative of S in x_p (our
/// choice: the averaged gradient is what the weak form, Eq. (14), integrates over the domain).
/// So no ghost cells are needed behind a wall, and a particle is never refused for its size.
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/shape_diagnostics.hpp"
#include "mpm/shape/shape_properties.hpp"
#include "mpm/shape/tensor_product.hpp"

namespace mpm {

/// S and dS/dDelta of one axis, in units where the cell size is 1.
struct GimpFactor {
  double value;
  double derivative;
};

/// The 1D uGIMP weight of paper/04_shape_functions.md (Bardenhagen & Kober 2004) for \f$ l_p \le h/2 \f$, in cell
/// units: \f$ d = \Delta / h \f$, \f$ \lambda = l_p / h \f$; returns S and dS/dd. With h and l_p restored:
/// \f[
///   S(\Delta) = \begin{cases}
///     \dfrac{(h + l_p + \Delta)^2}{4 h l_p} & -h - l_p < \Delta \le -h + l_p \\[1ex]
///     1 + \Delta / h                         & -h + l_p < \Delta \le -l_p \\[1ex]
///     1 - \dfrac{\Delta^2 + l_p^2}{2 h l_p}   & -l_p < \Delta \le l_p \\[1ex]
///     1 - \Delta / h                         & l_p < \Delta \le h - l_p \\[1ex]
///     \dfrac{(h + l_p - \Delta)^2}{4 h l_p} & h - l_p < \Delta \le h + l_p \\[1ex]
///     0 & \text{otherwise}
///   \end{cases}
/// \f]
/// S is even, so the code works with |d|. The pieces meet with equal value and slope (S is C1);
/// only S'' jumps, at \f$ |\Delta| \in \{ l_p,\ h - l_p,\ h + l_p \} \f$.
inline GimpFactor gimp_factor_table(double d, double lambda) {
  const double a = std::abs(d);
  const double sign = d < 0.0 ? -1.0 : 1.0;
  const double inverse_lambda = 1.0 / lambda;  // one division, then products (a division costs ten of them)
  if (a <= lambda) return {1.0 - 0.5 * (d * d + lambda * lambda) * inverse_lambda, -d * inverse_lambda};
  if (a <= 1.0 - lambda) return {1.0 - a, -sign};
  if (a < 1.0 + lambda) {
    const double gap = 1.0 + lambda - a;  // distance to the edge of the support
    return {0.25 * gap * gap * inverse_lambda, -0.5 * sign * gap * inverse_lambda};
  }
  return {0.0, 0.0};
}

/// The same weight from its definition, for any \f$ l_p > 0 \f$ (the table holds only for
/// \f$ l_p \le h/2 \f$: a particle no longer than a cell, which never straddles two nodes):
/// \f[
///   S(\Delta) = \frac{H(\Delta + l_p) - H(\Delta - l_p)}{2 l_p}, \qquad
///   S'(\Delta) = \frac{\hat N(\Delta + l_p) - \hat N(\Delta - l_p)}{2 l_p},
/// \f]
/// with H the antiderivative of the hat, \f$ H(t) = \int_{-\infty}^{t} \hat N \f$. In cell units.
/// The difference of H loses about \f$ \epsilon h / l_p \f$ relative accuracy, harmless for the
/// \f$ l_p > h/2 \f$ it is used for.
inline GimpFactor gimp_factor_average(double d, double lambda) {
  auto hat = [](double t) { return std::max(0.0, 1.0 - std::abs(t)); };
  auto antiderivative = [](double t) {
    if (t <= -1.0) return 0.0;
    if (t <= 0.0) return 0.5 * (1.0 + t) * (1.0 + t);
    if (t <= 1.0) return 1.0 - 0.5 * (1.0 - t) * (1.0 - t);
    return 1.0;
  };
  return {(antiderivative(d + lambda) - antiderivative(d - lambda)) / (2.0 * lambda),
          (hat(d + lambda) - hat(d - lambda)) / (2.0 * lambda)};
}

/// The uGIMP weight in cell units: the table of paper/04_shape_functions.md when it applies, its definition otherwise.
inline GimpFactor gimp_factor(double d, double lambda) {
  return lambda <= 0.5 ? gimp_factor_table(d, lambda) : gimp_factor_average(d, lambda);
}

template <int Dim>
class UgimpShape {
 public:
  static constexpr const char* name = "ugimp";
  /// Largest supported half-length, in cells: a particle at most two cells long.
  static constexpr double max_relative_half_length = 1.0;
  /// Nodes per axis the support can hold at that size: |Delta| < h + l_p covers at most 4 nodes.
  static constexpr int max_nodes_per_axis = 4;

  explicit UgimpShape(const Grid<Dim>& grid) : grid_(grid) {}

  /// Nodes per particle: the product over the axes of the largest per-axis count,
  /// \f$ \lceil 2 (1 + l_p / h) \rceil \f$ (3 per axis for every \f$ l_p \le h/2 \f$), over all particles.
  /// Fixed by initialise(); set_half_length() may raise it, so call that before sizing stencils.
  int capacity() const { return capacity_; }

  /// Copies l_p of every particle (Particles::half_length, set at seeding); never updated after.
  /// \throws std::invalid_argument if some l_p is not in (0, h].
  void initialise(const Particles<Dim>& particles) {
    relative_half_length_.assign(particles.size(), Vector<Dim>::Zero());
    capacity_ = 1 << Dim;
    for (int p = 0; p < particles.size(); ++p) set_half_length(p, particles.half_length[p]);
  }

  /// For callers without Particles (the teaching CLI, tests): particle_count particles of one size.
  void initialise(int particle_count, const Vector<Dim>& half_length) {
    relative_half_length_.assign(particle_count, Vector<Dim>::Zero());
    capacity_ = 1 << Dim;
    for (int p = 0; p < particle_count; ++p) set_half_length(p, half_length);
  }

  /// Sets l_p (per axis) of one particle already counted by initialise(); raises capacity() if needed.
  /// \throws std::invalid_argument if a component is not in (0, h].
  void set_half_length(int particle, const Vector<Dim>& half_length) {
    const double h = grid_.spacing();
    const Vector<Dim> lambda = half_length / h;
    int nodes = 1;
    for (int axis = 0; axis < Dim; ++axis) {
      if (!(lambda[axis] > 0.0 && lambda[axis] <= max_relative_half_length)) {
        std::ostringstream message;
        message << "uGIMP: particle " << particle << " has half-length l_p = " << half_length[axis] << " along "
                << axis_name(axis) << ", outside (0, h] with h = " << h;
        throw std::invalid_argument(message.str());
      }
      nodes *= nodes_along_axis(lambda[axis]);
    }
    relative_half_length_.at(particle) = lambda;
    capacity_ = std::max(capacity_, nodes);
  }

  /// l_p of a particle, per axis.
  Vector<Dim> half_length(int particle) const { return relative_half_length_[particle] * grid_.spacing(); }

  /// N_I(x_p) and grad N_I(x_p) for every node with \f$ |\Delta_a| < h + l_p \f$ on each axis a
  /// (initialise() first), the particle's domain clipped to the grid (see the file's comment). Nodes
  /// nearer to that edge of the support than the rounding of the lattice coordinate xi,
  /// 8 eps (|xi| + 2) cells, are left out: their S is below (8 eps (|xi| + 2))^2 h / (4 l_p),
  /// ~1e-24 h / l_p on a grid of 1000 cells.
  /// \throws ShapeFailure if x_p is outside the grid.
  int evaluate(int particle, const Vector<Dim>& x, int* nodes, double* values, Vector<Dim>* gradients) {
    if (!grid_.contains(x)) throw ShapeFailure(particle, "particle left the grid");
    const double h = grid_.spacing(), inverse_h = 1.0 / h;
    const Vector<Dim>& lambda = relative_half_length_[particle];
    std::array<AxisFactors<max_nodes_per_axis>, Dim> axes;
    for (int axis = 0; axis < Dim; ++axis) {
      double centre = (x[axis] - grid_.origin()[axis]) * inverse_h, half = lambda[axis];  // lattice coordinate, l_p / h
      const double cells = grid_.cells(axis);
      if (centre - half < 0.0 || centre + half > cells) {  // clip [centre - half, centre + half] to [0, cells]
        const double lower = std::max(centre - half, 0.0), upper = std::min(centre + half, cells);
        centre = 0.5 * (lower + upper);
        half = 0.5 * (upper - lower);
      }
      const double slack = 8.0 * std::numeric_limits<double>::epsilon() * (std::abs(centre) + 2.0);
      const double reach = 1.0 + half - slack;
      const int first = std::max(static_cast<int>(std::floor(centre - reach)) + 1, 0);      // first node with xi - k < reach
      int last = std::min(static_cast<int>(std::ceil(centre + reach)) - 1, grid_.cells(axis));  // last with k - xi < reach
      last = std::min(last, first + nodes_along_axis(lambda[axis]) - 1);  // only ever trims a node with S ~ 0
      axes[axis].first = first;
      for (int k = first; k <= last; ++k) {
        const GimpFactor s = gimp_factor(centre - k, half);
        axes[axis].add(s.value, s.derivative * inverse_h);
      }
    }
    const int count = tensor_product_stencil(grid_, axes, nodes, values, gradients);
    diagnostics_.record(count);
    return count;
  }

  const ShapeDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  /// Most lattice points an open interval of length 2 (1 + lambda) can hold (lambda = 1/2 is 3).
  static int nodes_along_axis(double lambda) { return static_cast<int>(std::ceil(2.0 * (1.0 + lambda) - 1e-9)); }

  Grid<Dim> grid_;
  std::vector<Vector<Dim>> relative_half_length_;  ///< l_p / h per particle and axis
  int capacity_ = 1 << Dim;
  ShapeDiagnostics diagnostics_;
};

namespace testing {

/// The uGIMP weight from its definition, by a route independent of gimp_factor: the hat is
/// integrated over [d - lambda, d + lambda] piece by piece (split at its kinks -1, 0, 1), where the
/// trapezoid rule is exact because the hat is linear on each piece. Cell units.
inline double gimp_by_quadrature(double d, double lambda) {
  auto hat = [](double t) { return std::max(0.0, 1.0 - std::abs(t)); };
  std::vector<double> cuts{d - lambda};
  for (double kink : {-1.0, 0.0, 1.0})
    if (kink > d - lambda && kink < d + lambda) cuts.push_back(kink);
  cuts.push_back(d + lambda);
  double integral = 0.0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) integral += 0.5 * (cuts[k + 1] - cuts[k]) * (hat(cuts[k]) + hat(cuts[k + 1]));
  return integral / (2.0 * lambda);
}

/// Distance, in cells, from x to the nearest point where S'' of some node jumps: where an end of the
/// particle, x_a +- l_p, is on a node (the peak or a foot of some node's hat).
template <int Dim>
double distance_to_gimp_kink(const Grid<Dim>& grid, const Vector<Dim>& x, const Vector<Dim>& half_length) {
  double nearest = 1e300;
  for (int axis = 0; axis < Dim; ++axis) {
    const double xi = (x[axis] - grid.origin()[axis]) / grid.spacing();
    const double lambda = half_length[axis] / grid.spacing();
    for (double end : {xi - lambda, xi + lambda}) nearest = std::min(nearest, std::abs(end - std::round(end)));
  }
  return nearest;
}

/// The shape properties at x with the finite-difference tolerance the maths allows there. uGIMP is
/// piecewise quadratic, so central differences with step e = 1e-6 h are exact but for rounding: of
/// x +- e (relative step error eps |x| / e) and of S (eps |xi| / e), about 2e-10 (|x|/h + |xi| + 2),
/// under 1e-8 on these grids. Within e of a kink, where S'' jumps by at most (2 + 1) / (2 l_p / h)
/// (the hat's slope jumps by 2 at its peak and 1 at its feet, one at each end of the particle), the
/// error is at most e |jump| / 4 = 3.75e-7 h / l_p in units of 1/h.
template <int Dim>
void check_ugimp_properties(UgimpShape<Dim>& shape, const Grid<Dim>& grid, int particle, const Vector<Dim>& x) {
  const Vector<Dim> half_length = shape.half_length(particle);
  PropertyTolerances tolerance;
  const double lambda = half_length.minCoeff() / grid.spacing();
  const bool near_kink = distance_to_gimp_kink(grid, x, half_length) < 2e-6;
  tolerance.finite_difference = (near_kink ? 3.75e-7 / lambda : 0.0) + 1e-8;
  // Central differences need the particle, moved by 1e-6 h either way, to stay in the grid.
  const Vector<Dim> room = ((x - half_length - grid.origin()).cwiseMin(grid.upper_corner() - x - half_length));
  tolerance.check_finite_difference = room.minCoeff() > 2e-6 * grid.spacing();
  check_shape_properties(shape, grid, particle, x, tolerance);
}

}  // namespace testing

TEST_CASE("uGIMP 1D weight: the table of paper/04_shape_functions.md by hand, its continuity, and against its definition") {
  const double lambda = 0.25;  // l_p = h/4: two particles per cell
  // By hand. Exact in binary for lambda = 1/4, so only the last bit may differ.
  CHECK(gimp_factor(0.0, lambda).value == doctest::Approx(1.0 - lambda / 2.0).epsilon(1e-15));  // 1 - l_p/(2h)
  CHECK(gimp_factor(0.0, lambda).derivative == 0.0);
  CHECK(gimp_factor(lambda, lambda).value == doctest::Approx(1.0 - lambda).epsilon(1e-15));
  CHECK(gimp_factor(0.5, lambda).value == doctest::Approx(0.5).epsilon(1e-15));     // linear piece
  CHECK(gimp_factor(-0.5, lambda).derivative == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(gimp_factor(1.0, lambda).value == doctest::Approx(lambda / 4.0).epsilon(1e-15));  // (l_p)^2/(4 h l_p)
  CHECK(gimp_factor(1.0, lambda).derivative == doctest::Approx(-0.5).epsilon(1e-15));
  CHECK(gimp_factor(-1.0, lambda).derivative == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(gimp_factor(1.0 + lambda, lambda).value == 0.0);
  CHECK(gimp_factor(-1.3, lambda).value == 0.0);

  // Continuity of S and S' across every piece boundary b, from delta on either side: S changes by at
  // most 2 delta max|S'| = 2 delta, S' by at most 2 delta max|S''| = 2 delta / lambda (cell units).
  const double delta = 1e-9;
  for (double l : {0.5, 0.25, 0.1, 0.01}) {
    for (double b : {l, 1.0 - l, 1.0 + l, -l, -(1.0 - l), -(1.0 + l)}) {
      const GimpFactor below = gimp_factor(b - delta, l), above = gimp_factor(b + delta, l);
      INFO("lambda = ", l, ", boundary = ", b);
      CHECK(std::abs(above.value - below.value) <= 2.0 * delta + 1e-15);
      CHECK(std::abs(above.derivative - below.derivative) <= 2.0 * delta / l + 1e-15 / l);
    }
  }

  // The table and the general formula against an independent quadrature of the definition. Rounding:
  // the quadrature's piece lengths carry ~eps |d| each, divided by 2 lambda; the general formula loses
  // eps / lambda the same way. So 4e-16 / lambda covers both. The derivative: the Leibniz rule.
  auto hat = [](double t) { return std::max(0.0, 1.0 - std::abs(t)); };
  for (double l : {0.5, 0.25, 0.125, 0.01, 0.6, 0.75, 1.0}) {
    for (int k = -900; k <= 900; ++k) {
      const double d = k * (2.1 / 900.0) + 1e-4;  // [-2.1, 2.1], avoiding exact kinks for the derivative
      const GimpFactor s = gimp_factor(d, l);
      INFO("lambda = ", l, ", d = ", d);
      CHECK(std::abs(s.value - testing::gimp_by_quadrature(d, l)) <= 4e-16 / l + 1e-16);
      CHECK(std::abs(s.derivative - (hat(d + l) - hat(d - l)) / (2.0 * l)) <= 4e-16 / l);
      if (l <= 0.5) CHECK(std::abs(s.value - gimp_factor_average(d, l).value) <= 4e-16 / l + 1e-16);
    }
  }
}

TEST_CASE("uGIMP: every shape property in 1D and 2D, near and at the grid edge and on cell faces") {
  // 1D, l_p = h/4 (2 ppc), h/2 (1 ppc) and 0.8 h (beyond the table: the general formula).
  const Grid<1> line(Vector<1>(-1.0), 0.25, {16});
  for (double l : {0.0625, 0.125, 0.2}) {
    UgimpShape<1> gimp(line);
    gimp.initialise(1, Vector<1>(l));
    CHECK(gimp.capacity() == (l <= 0.125 ? 3 : 4));
    const double lower = -1.0 + l, upper = 3.0 - l;  // the particle must stay in the grid
    for (double x : {lower, lower + 1e-9, lower + 0.01, lower + 0.1, -0.75, -0.7, -0.5, -0.45, -0.4375, -0.375, -0.13,
                     0.0, 0.37, 1.0, 2.5,
                     upper - 0.07, upper - 1e-9, upper}) {
      INFO("l_p = ", l);
      testing::check_ugimp_properties(gimp, line, 0, Vector<1>(x));
    }
  }

  // 2D, square and oblong particles (h/4 by h/4, h/4 by h/8, h/2 by h/2) on a 6 x 4 grid of h = 0.5.
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  for (const Vector<2>& l : {Vector<2>(0.125, 0.125), Vector<2>(0.125, 0.0625), Vector<2>(0.25, 0.25)}) {
    UgimpShape<2> gimp(plane);
    gimp.initialise(1, l);
    CHECK(gimp.capacity() == 9);
    const Vector<2> lower = l, upper = Vector<2>(3.0, 2.0) - l;
    for (const Vector<2>& x : {lower, Vector<2>(lower[0] + 1e-9, lower[1]), Vector<2>(lower[0] + 0.03, 0.9),
                               Vector<2>(0.5, 0.5), Vector<2>(0.625, 0.375), Vector<2>(1.0, 0.77), Vector<2>(1.3, 0.7),
                               Vector<2>(1.61, 1.5), Vector<2>(2.75, 1.75), Vector<2>(upper[0], 1.2), upper}) {
      INFO("l_p = ", l.transpose());
      testing::check_ugimp_properties(gimp, plane, 0, x);
    }
  }
}

TEST_CASE("uGIMP tends to the linear shape functions as the particle shrinks") {
  // max_I |N_ugimp - N_linear| over x: in 1D it is exactly l_p / (2h), at the nodes (S(0) = 1 - l_p/(2h));
  // elsewhere the difference is at most l_p / (4h). In 2D, at a node, 1 - (1 - l_p/(2h))^2. Rounding only.
  const Grid<1> line(Vector<1>(0.0), 1.0, {8});
  const Grid<2> plane(Vector<2>(0.0, 0.0), 1.0, {6, 6});
  LinearShape<1> hat(line);
  LinearShape<2> q4(plane);
  for (double lambda : {0.5, 0.25, 0.125, 0.0625, 1.0 / 64.0, 1.0 / 1024.0}) {
    UgimpShape<1> gimp(line);
    gimp.initialise(1, Vector<1>(lambda));
    double largest = 0.0;
    for (int k = 0; k <= 4 * 64; ++k) {
      const Vector<1> x(2.0 + k / 64.0);  // cells 2 to 6, nodes and faces included
      const auto a = testing::dense_values(gimp, line, 0, x), b = testing::dense_values(hat, line, 0, x);
      for (size_t I = 0; I < a.size(); ++I) largest = std::max(largest, std::abs(a[I] - b[I]));
    }
    CHECK(largest == doctest::Approx(lambda / 2.0).epsilon(1e-13));

    UgimpShape<2> gimp2(plane);
    gimp2.initialise(1, Vector<2>(lambda, lambda));
    largest = 0.0;
    for (int i = 0; i <= 32; ++i)
      for (int j = 0; j <= 32; ++j) {
        const Vector<2> x(2.0 + i / 16.0, 2.0 + j / 16.0);
        const auto a = testing::dense_values(gimp2, plane, 0, x), b = testing::dense_values(q4, plane, 0, x);
        for (size_t I = 0; I < a.size(); ++I) largest = std::max(largest, std::abs(a[I] - b[I]));
      }
    CHECK(largest == doctest::Approx(1.0 - (1.0 - lambda / 2.0) * (1.0 - lambda / 2.0)).epsilon(1e-13));
  }
}

TEST_CASE("uGIMP at the grid's edge: the particle's domain clipped to the grid, weights and gradients by hand") {
  // 1D, h = 0.25 on [0, 2] (cell units below: s = x / h). A particle of l_p = h/2 at x = 0.05 spans
  // [-0.3, 0.7] cells, clipped to [0, 0.7]: N_0 = mean of 1 - s = 0.65, N_1 = mean of s = 0.35,
  // grad N = (N(0.7) - N(0)) / 0.7 per cell: -1 and +1, i.e. -4 and +4 per metre.
  const Grid<1> line(Vector<1>(0.0), 0.25, {8});
  UgimpShape<1> gimp(line);
  gimp.initialise(1, Vector<1>(0.125));
  int nodes[16];
  double values[16];
  Vector<1> gradients1[16];
  REQUIRE(gimp.evaluate(0, Vector<1>(0.05), nodes, values, gradients1) == 2);
  CHECK(nodes[0] == 0);
  CHECK(values[0] == doctest::Approx(0.65).epsilon(1e-14));
  CHECK(values[1] == doctest::Approx(0.35).epsilon(1e-14));
  CHECK(gradients1[0][0] == doctest::Approx(-4.0).epsilon(1e-14));
  CHECK(gradients1[1][0] == doctest::Approx(4.0).epsilon(1e-14));
  // Centred on the wall, x = 0: [0, 0.5] cells, N_0 = 0.75, N_1 = 0.25. At the upper wall, x = 2 - 0.02:
  // [7.42, 8.42] clipped to [7.42, 8]: N_7 = mean of 8 - s = 0.29, N_8 = 0.71.
  REQUIRE(gimp.evaluate(0, Vector<1>(0.0), nodes, values, gradients1) == 2);
  CHECK(values[0] == doctest::Approx(0.75).epsilon(1e-14));
  REQUIRE(gimp.evaluate(0, Vector<1>(1.98), nodes, values, gradients1) == 2);
  CHECK(nodes[0] == 7);
  CHECK(values[0] == doctest::Approx(0.29).epsilon(1e-13));
  CHECK(values[1] == doctest::Approx(0.71).epsilon(1e-13));
  CHECK(gradients1[1][0] == doctest::Approx(4.0).epsilon(1e-13));
  // A particle of l_p = h at s = 0.4 spans [-0.6, 1.4], clipped to [0, 1.4]: the integrals of the hats
  // over it are 0.5, 0.5 + 0.32 = 0.82 and 0.08; their gradients' are -1, 0.6 and 0.4. Divided by 1.4.
  gimp.set_half_length(0, Vector<1>(0.25));
  REQUIRE(gimp.evaluate(0, Vector<1>(0.1), nodes, values, gradients1) == 3);
  CHECK(values[0] == doctest::Approx(0.5 / 1.4).epsilon(1e-14));
  CHECK(values[1] == doctest::Approx(0.82 / 1.4).epsilon(1e-14));
  CHECK(values[2] == doctest::Approx(0.08 / 1.4).epsilon(1e-13));
  CHECK(gradients1[0][0] * 0.25 == doctest::Approx(-1.0 / 1.4).epsilon(1e-14));
  CHECK(gradients1[1][0] * 0.25 == doctest::Approx(0.6 / 1.4).epsilon(1e-14));
  CHECK(gradients1[2][0] * 0.25 == doctest::Approx(0.4 / 1.4).epsilon(1e-14));

  // The properties a clipped particle keeps, in 1D and 2D, along every edge and in the corners:
  // sum N = 1 and sum grad N = 0 to 1e-12, sum x_I (x) grad N = I (a uniform stretch is exact),
  // N >= 0, and sum N x_I = the centre of the clipped domain.
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  for (double l : {0.0625, 0.125, 0.25, 0.5}) {
    UgimpShape<2> gimp2(plane);
    gimp2.initialise(1, Vector<2>(l, 0.5 * l));
    const Vector<2> half(l, 0.5 * l);
    for (double fx : {0.0, 1e-9, 0.3, 0.99, 1.0}) {
      for (double fy : {0.0, 0.5, 1.0}) {
        for (const Vector<2>& corner : {Vector<2>(0.0, 0.0), Vector<2>(3.0, 2.0), Vector<2>(0.0, 2.0), Vector<2>(3.0, 0.0)}) {
          const Vector<2> inward((corner[0] == 0.0 ? 1.0 : -1.0) * fx * l, (corner[1] == 0.0 ? 1.0 : -1.0) * fy * 0.5 * l);
          const Vector<2> along_edge(0.0, fy == 0.5 ? (corner[1] == 0.0 ? 0.7 : -0.7) : 0.0);  // away from the corner
          const Vector<2> x = corner + inward + along_edge;
          Vector<2> gradients[16];
          const int count = gimp2.evaluate(0, x, nodes, values, gradients);
          double sum = 0.0;
          Vector<2> reproduced = Vector<2>::Zero(), gradient_sum = Vector<2>::Zero();
          Matrix<2> gradient_of_x = Matrix<2>::Zero();
          for (int k = 0; k < count; ++k) {
            CHECK(values[k] >= 0.0);
            sum += values[k];
            reproduced += values[k] * plane.node_position(nodes[k]);
            gradient_sum += gradients[k];
            gradient_of_x += plane.node_position(nodes[k]) * gradients[k].transpose();
          }
          const Vector<2> lower = (x - half).cwiseMax(plane.origin()), upper = (x + half).cwiseMin(plane.upper_corner());
          INFO("l_p = ", half.transpose(), ", x = ", x.transpose());
          CHECK(std::abs(sum - 1.0) <= 1e-12);
          CHECK(gradient_sum.norm() * plane.spacing() <= 1e-12);
          CHECK((gradient_of_x - Matrix<2>::Identity()).norm() <= 1e-12);
          CHECK((reproduced - 0.5 * (lower + upper)).norm() / plane.spacing() <= 1e-12);
        }
      }
    }
  }
}

TEST_CASE("uGIMP: sizes are checked, capacity is reached, a particle off the grid is refused") {
  const Grid<2> plane(Vector<2>(0.0, 0.0), 0.5, {6, 4});
  Particles<2> particles;
  particles.add(Vector<2>(0.125, 0.125), 1.0, 1.0, Vector<2>::Zero(), Vector<2>(0.125, 0.125));
  particles.add(Vector<2>(1.0, 1.0), 1.0, 1.0, Vector<2>::Zero(), Vector<2>(0.125, 0.0625));
  UgimpShape<2> gimp(plane);
  gimp.initialise(particles);
  CHECK(gimp.capacity() == 9);
  CHECK(gimp.half_length(1).isApprox(Vector<2>(0.125, 0.0625), 1e-15));
  int nodes[16];
  double values[16];
  Vector<2> gradients[16];
  CHECK(gimp.evaluate(0, Vector<2>(0.125, 0.125), nodes, values, gradients) == 4);  // touches the edge: fine
  CHECK(gimp.evaluate(0, Vector<2>(0.5, 1.0), nodes, values, gradients) == 9);       // on a node: 3 x 3
  CHECK(gimp.diagnostics().neighbours_max() == 9);
  CHECK(gimp.diagnostics().evaluations() == 2);

  // Crossing the grid's edge is clipped (above); leaving the grid is refused.
  CHECK(gimp.evaluate(0, Vector<2>(0.12, 1.0), nodes, values, gradients) == 6);
  CHECK(gimp.evaluate(1, Vector<2>(3.0, 1.0), nodes, values, gradients) == 6);
  CHECK_THROWS_WITH_AS(gimp.evaluate(1, Vector<2>(3.0001, 1.0), nodes, values, gradients), "particle left the grid",
                       ShapeFailure);
  CHECK_THROWS_WITH_AS(gimp.evaluate(1, Vector<2>(1.0, -1e-300), nodes, values, gradients), "particle left the grid",
                       ShapeFailure);
  int failed_particle = -1;
  try {
    gimp.evaluate(1, Vector<2>(-0.1, 1.0), nodes, values, gradients);
  } catch (const ShapeFailure& failure) {
    failed_particle = failure.particle;
  }
  CHECK(failed_particle == 1);

  // Sizes: (0, h] only; a larger particle raises the capacity, and the capacity is reached.
  CHECK_THROWS_AS(gimp.set_half_length(0, Vector<2>(0.0, 0.1)), std::invalid_argument);
  CHECK_THROWS_AS(gimp.set_half_length(0, Vector<2>(0.1, 0.5001)), std::invalid_argument);
  CHECK_THROWS_AS(gimp.set_half_length(0, Vector<2>(std::nan(""), 0.1)), std::invalid_argument);
  gimp.set_half_length(1, Vector<2>(0.5, 0.3));  // l_p = h and 0.6 h: 4 nodes per axis
  CHECK(gimp.capacity() == 16);
  CHECK(gimp.evaluate(1, Vector<2>(1.25, 1.25), nodes, values, gradients) == 16);  // mid-cell
  CHECK(gimp.evaluate(1, Vector<2>(1.0, 1.0), nodes, values, gradients) == 9);     // node: S = 0 at |Delta| = 2h
  testing::check_ugimp_properties(gimp, plane, 1, Vector<2>(1.3, 1.1));
}

}  // namespace mpm
