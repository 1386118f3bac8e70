// A check of the soil block that is not one-dimensional. With lateral rollers (scenes/soil_block.toml) every particle
// of a row moves alike and the block is the 1D column of paper/07_exact_column.md: the suite's other checks test the
// 2D kernels on a 1D field. With free sides and nu = 0.3 (scenes/soil_block_free_sides.toml) the block spreads
// sideways, by more at the top than at the base, which the frictionless base holds at v_y = 0: u_x varies with x and
// y, sigma_yy varies along a row, and no closed form is known. Two exact statements still hold:
//   - equilibrium of the part above a row of cells (its particles' mid-height, a material line; the sides are
//     traction-free): once the free oscillation is averaged out (over the snapshots of the last period of the
//     column, T1 = 1.19 s at nu = 0.3) the traction on the line carries the weight above it, so the mean sigma_yy of
//     the row's particles is -rho g (H - Y_c), Y_c the cells' mid-height, to the discretisation's accuracy, however
//     sigma_yy varies along the row. (Per row of particles it is not: with 2 x 2 particles per cell the stress is
//     nearly constant over a cell, which puts each row h/4 off its cell's mean, rho g h / 4 = 5 % of rho g H.)
//   - mirror symmetry about x = W/2: the scene is symmetric, so u_x(W - X, Y) = -u_x(X, Y) and u_y(W - X, Y) =
//     u_y(X, Y) up to round-off, which a wrong index in a 2D gradient or a one-sided stencil would break.
#pragma once
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "verification/claims.hpp"
#include "verification/soil_measures.hpp"

namespace verification {

struct PlaneMeasures {
  std::map<double, double> row_mean_stress;  ///< mid-height Y_c of a row of cells -> the mean sigma_yy of its particles,
                                             ///< averaged over the snapshots of the last T1 of the run
  std::map<double, double> row_stress_range; ///< Y_c -> max - min of sigma_yy over the row's particles at the last snapshot
  std::map<double, double> row_mean_band;    ///< Y_c -> the band of that mean: its larger move over the even or the odd
                                             ///< snapshots alone (mpm::band_of_halves; the one rule)
  int snapshots = 0;                         ///< the snapshots averaged
  double largest_asymmetry = 0.0;            ///< max over mirrored pairs of |u_x + u_x'| and |u_y - u_y'|, m
  double largest_lateral = 0.0;              ///< max |u_x| over the particles, m
  int pairs = 0;                             ///< mirrored pairs found
};

inline PlaneMeasures measure_plane(const SoilResult& result) {
  PlaneMeasures m;
  if (result.snapshots.empty()) return m;
  const auto& particles = result.snapshots.back().particles;
  const double width = result.scene.length[0];
  const double h = result.scene.spacing;
  auto row_of = [&](double y) { return (std::floor((y - result.scene.origin[1]) / h) + 0.5) * h + result.scene.origin[1]; };
  std::map<double, std::vector<double>> rows;
  for (const auto& p : particles) {
    rows[row_of(p.reference_y)].push_back(p.sigma_yy);
    m.largest_lateral = std::max(m.largest_lateral, std::abs(p.x - p.reference_x));
    for (const auto& q : particles) {
      if (std::abs(q.reference_y - p.reference_y) > 1e-9 || std::abs(q.reference_x - (width - p.reference_x)) > 1e-9 ||
          p.reference_x >= q.reference_x)
        continue;
      ++m.pairs;
      const double ux = p.x - p.reference_x, uy = p.y - p.reference_y, vx = q.x - q.reference_x, vy = q.y - q.reference_y;
      m.largest_asymmetry = std::max({m.largest_asymmetry, std::abs(ux + vx), std::abs(uy - vy)});
    }
  }
  for (const auto& [height, stresses] : rows) {
    double low = INFINITY, high = -INFINITY;
    for (double s : stresses) low = std::min(low, s), high = std::max(high, s);
    m.row_stress_range[height] = high - low;
  }
  const double start = result.snapshots.back().time - first_period(result.scene) - 1e-9;
  std::map<double, double> sums, half_sums[2];
  std::map<double, int> counts, half_counts[2];
  for (const auto& snap : result.snapshots) {
    if (snap.time < start) continue;
    const int half = m.snapshots++ % 2;
    for (const auto& p : snap.particles) {
      const double row = row_of(p.reference_y);
      sums[row] += p.sigma_yy, ++counts[row], half_sums[half][row] += p.sigma_yy, ++half_counts[half][row];
    }
  }
  for (const auto& [height, sum] : sums) {
    m.row_mean_stress[height] = sum / counts[height];
    m.row_mean_band[height] = m.snapshots < 2 ? 0.0
                                              : mpm::band_of_halves(m.row_mean_stress[height], half_sums[0][height] / half_counts[0][height],
                                                                    half_sums[1][height] / half_counts[1][height]);
  }
  return m;
}

/// The claims of the free-sides, nu = 0.3 block at t = 20 s (the last snapshot).
inline std::vector<DomainClaim> plane_claims(const SoilOutcome& o, double tolerance) {
  const PlaneMeasures m = measure_plane(o.result);
  const auto& scene = o.result.scene;
  const double weight = scene.density * std::abs(scene.gravity[1]), scale = weight * scene.length[1];
  DomainClaim equilibrium{"Free sides, nu = 0.3, averaged over the last T1 (" + std::to_string(m.snapshots) + " snapshots): the mean sigma_yy of each row of cells' particles carries the weight "
                          "above the cells' mid-height, -rho g (H - Y_c), within " + percent(tolerance) + " of rho g H, though sigma_yy varies along the row",
                          "|row mean sigma_yy + rho g (H - Y_c)| / (rho g H) <= " + number(tolerance, "%g") +
                              " beyond its band (the mean over the even or the odd snapshots alone); where: Y_c and the range of "
                              "sigma_yy over the row's particles",
                          {}, false};
  if (o.result.failed || m.row_mean_stress.empty()) equilibrium.add_stopped("the run stopped: " + o.result.failure);
  for (const auto& [height, mean] : m.row_mean_stress) {
    const mpm::Measured error{std::abs(mean + weight * (scene.length[1] - height)) / scale, m.row_mean_band.at(height) / scale,
                              mpm::Ending::done};
    equilibrium.add("Y_c = " + number(height, "%g") + " m (range " + kilopascals(m.row_stress_range.at(height)) + ", ± " +
                        number(error.band, "%.2g") + ")",
                    error.value, mpm::judge(error, mpm::Side::below, mpm::threshold(tolerance)));
  }
  DomainClaim symmetry{"Free sides, nu = 0.3, t = 20 s: the block stays mirror-symmetric about x = W/2 (u_x odd, u_y even) to "
                       "1e-9 m, while it spreads sideways",
                       "largest |u_x(X) + u_x(W - X)|, |u_y(X) - u_y(W - X)| over the mirrored pairs, m", {}, true};
  symmetry.add(std::to_string(m.pairs) + " pairs; largest |u_x| " + metres(m.largest_lateral), m.largest_asymmetry,
               !o.result.failed && m.pairs > 0 && m.largest_asymmetry <= 1e-9);
  // The check is two-dimensional (with rollers both measures are zero): two criteria, two rows.
  DomainClaim spread{"Free sides, nu = 0.3: the check is two-dimensional: the block spreads sideways by over 1 mm",
                     "largest |u_x| > 1e-3 m", {}, false};
  DomainClaim varies{"Free sides, nu = 0.3: the check is two-dimensional: sigma_yy varies along the rows by over 1 % of rho g H",
                     "the largest range of sigma_yy along a row / (rho g H) > 0.01", {}, false};
  double widest = 0.0;
  for (const auto& [height, range] : m.row_stress_range) widest = std::max(widest, range / scale);
  spread.add("lateral displacement", m.largest_lateral, m.largest_lateral > 1e-3);
  varies.add("sigma_yy along a row", widest, widest > 0.01);
  return {equilibrium, symmetry, spread, varies};
}

}  // namespace verification
