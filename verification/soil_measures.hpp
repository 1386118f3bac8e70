// A soil-block run against the exact column (paper/07_exact_column.md, mpm/exact/column.hpp) and its finite-strain
// static counterpart (mpm/exact/column_log_strain.hpp): the numbers the suite's figures, checks and
// report are made of. The exact solutions take their parameters from the scene, never from the solver.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mpm/analysis/rms_error.hpp"
#include "mpm/analysis/verdict.hpp"
#include "mpm/exact/column.hpp"
#include "mpm/exact/column_log_strain.hpp"
#include "verification/soil_case.hpp"

namespace verification {

/// paper/07_exact_column.md: the constrained modulus of a laterally confined column (plane strain, lateral rollers),
/// \f$ M = E(1-\nu)/((1+\nu)(1-2\nu)) \f$; M = E for nu = 0, with or without lateral rollers.
inline double constrained_modulus(const mpm::io::Scene& scene) {
  const double nu = scene.poisson_ratio;
  return scene.young_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

/// The exact column of the scene's block: H = the box height, g = |gravity_y|, T = ramp_period.
inline mpm::exact::SoilColumn exact_column(const mpm::io::Scene& scene) {
  return mpm::exact::SoilColumn(scene.length[1], constrained_modulus(scene), scene.density, std::abs(scene.gravity[1]),
                                scene.ramp_period);
}

inline mpm::exact::SoilColumnLogStrain log_strain_column(const mpm::io::Scene& scene) {
  return mpm::exact::SoilColumnLogStrain(scene.length[1], constrained_modulus(scene), scene.density,
                                         std::abs(scene.gravity[1]));
}

/// \f$ T_1 = 4H/c \f$, \f$ c = \sqrt{M/\rho} \f$: the period of the column's first mode (paper/07_exact_column.md).
inline double first_period(const mpm::io::Scene& scene) {
  return 4.0 * scene.length[1] / std::sqrt(constrained_modulus(scene) / scene.density);
}

struct SettlementMeasures {
  std::vector<double> exact;        ///< u_exact(Y, t_n) at every sample (paper/07_exact_column.md, small strain)
  double final_displacement = 0.0;  ///< u(t_end) of the observed particle
  double exact_final = 0.0;         ///< u_exact(Y, t_end)
  double final_error = 0.0;         ///< u(t_end) - u_exact(Y, t_end)
  double rms_error = 0.0;           ///< Eq. (43) over every sample of u
  /// the band of rms_error's sampling: its larger move when scored on the even or the odd samples alone
  /// (mpm::band_of_halves); two runs' errors closer than their bands together are not told apart
  double rms_band = 0.0;
  /// time average of u over the last four T1 of the run, all after the ramp: it removes the free
  /// oscillation about the static state (paper/07_exact_column.md: +-2.3 mm) and leaves the static settlement
  double mean_settlement = std::numeric_limits<double>::quiet_NaN();
  /// the estimator's floor: the range of that mean over the 4-T1 windows that end 0, T1/8, ..., T1 before the end; a
  /// difference of two means below their floors is not resolved
  double mean_floor = std::numeric_limits<double>::quiet_NaN();
  double swing = std::numeric_limits<double>::quiet_NaN();        ///< max - min of u over that window
  double swing_floor = std::numeric_limits<double>::quiet_NaN();  ///< the range of the swing over the same windows as mean_floor
  double exact_swing = std::numeric_limits<double>::quiet_NaN();  ///< the same for u_exact
  /// after the ramp (constant gravity) the mechanical energy E = kinetic + strain + gravity potential is
  /// conserved: (max - min of E over t >= T/2) / (mean kinetic + strain energy there)
  double energy_drift = std::numeric_limits<double>::quiet_NaN();
  double energy_drift_band = 0.0;  ///< its band: the larger move of the drift taken on the even or the odd samples alone
  double static_small_strain = 0.0;  ///< static u(Y), paper/07_exact_column.md
  double static_log_strain = 0.0;    ///< static u(Y) at finite (logarithmic) strain
};

/// u over a window of time after the ramp: its time average (trapezoid rule over the samples) and its range, and the
/// range of u_exact there.
struct Window {
  double mean = 0.0, swing = 0.0, exact_swing = 0.0;
};

inline Window window(const SoilResult& result, const std::vector<double>& exact, double start, double end) {
  double area = 0.0, span = 0.0;
  double lowest = INFINITY, highest = -INFINITY, exact_lowest = INFINITY, exact_highest = -INFINITY;
  for (size_t n = 1; n < result.time.size(); ++n) {
    if (result.time[n - 1] < start || result.time[n] > end + 1e-9) continue;
    const double dt = result.time[n] - result.time[n - 1];
    area += 0.5 * dt * (result.displacement[n] + result.displacement[n - 1]);
    span += dt;
    lowest = std::min(lowest, result.displacement[n]), highest = std::max(highest, result.displacement[n]);
    exact_lowest = std::min(exact_lowest, exact[n]), exact_highest = std::max(exact_highest, exact[n]);
  }
  return {area / span, highest - lowest, exact_highest - exact_lowest};
}

/// Compares the observed particle's u_y(t) with the exact column at its reference height Y.
inline SettlementMeasures measure_settlement(const SoilResult& result) {
  SettlementMeasures m;
  const auto column = exact_column(result.scene);
  for (double t : result.time) m.exact.push_back(column.displacement(result.reference_height, t));
  m.final_displacement = result.displacement.back();
  m.exact_final = m.exact.back();
  m.final_error = m.final_displacement - m.exact_final;
  m.rms_error = mpm::rms_error(result.displacement, m.exact);
  if (result.time.size() >= 2) {
    auto half = [&](std::size_t first) {
      return mpm::rms_error(mpm::every_other(result.displacement, first), mpm::every_other(m.exact, first));
    };
    m.rms_band = mpm::band_of_halves(m.rms_error, half(0), half(1));
  }
  m.static_small_strain = column.static_displacement(result.reference_height);
  m.static_log_strain = log_strain_column(result.scene).displacement(result.reference_height);
  // the drift on every sample after the ramp (step 1), or on every other one from `first` (its band's halves)
  auto drift = [&result](size_t first, size_t step) {
    double lowest = INFINITY, highest = -INFINITY, strain = 0.0;
    int count = 0;
    size_t after = 0;  // the index among the samples after the ramp
    for (size_t n = 0; n < result.time.size(); ++n) {
      if (result.time[n] < 0.5 * result.scene.ramp_period) continue;
      if (after++ % step != first) continue;
      const double energy = result.kinetic_plus_strain[n] + result.gravity_potential[n];
      lowest = std::min(lowest, energy), highest = std::max(highest, energy);
      strain += result.kinetic_plus_strain[n], ++count;
    }
    return count > 1 ? (highest - lowest) / (strain / count) : std::numeric_limits<double>::quiet_NaN();
  };
  m.energy_drift = drift(0, 1);
  m.energy_drift_band = mpm::band_of_halves(m.energy_drift, drift(0, 2), drift(1, 2));
  const double end = result.scene.control.end_time, period = first_period(result.scene);
  if (!result.failed && end - 5.0 * period >= 0.5 * result.scene.ramp_period) {
    const Window last = window(result, m.exact, end - 4.0 * period, end);
    m.mean_settlement = last.mean, m.swing = last.swing, m.exact_swing = last.exact_swing;
    // the estimator's floor: how far the mean moves when the window's end moves back over one period
    double lowest = last.mean, highest = last.mean, least_swing = last.swing, most_swing = last.swing;
    for (int k = 1; k <= 8; ++k) {
      const Window shifted = window(result, m.exact, end - (4.0 + k / 8.0) * period, end - k / 8.0 * period);
      lowest = std::min(lowest, shifted.mean), highest = std::max(highest, shifted.mean);
      least_swing = std::min(least_swing, shifted.swing), most_swing = std::max(most_swing, shifted.swing);
    }
    m.mean_floor = highest - lowest;
    m.swing_floor = most_swing - least_swing;
  }
  return m;
}

struct StressMeasures {
  double rms_relative = 0.0;      ///< RMS over particles of (sigma_yy - sigma_exact(Y, t)) / (rho g H)
  double largest_relative = 0.0;  ///< the largest |sigma_yy - sigma_exact(Y, t)| / (rho g H)
  double bottom_row_height = 0.0;     ///< Y of the lowest row of particles
  double bottom_row_stress = 0.0;     ///< mean sigma_yy of that row
  double bottom_row_exact = 0.0;      ///< sigma_exact(Y, t) there
  double exact_base = 0.0;            ///< sigma_exact(0, t), the base
  double largest_settlement = 0.0;    ///< max over particles of Y - y
  /// the bands of rms_relative and largest_settlement (mpm::band_of_halves; the one rule): their larger move when taken
  /// on the even or the odd rows of particles alone (the RMS: the field varies with Y only), on the even or the odd
  /// particles alone (the largest: every particle of the top row settles alike)
  double rms_band = 0.0, largest_settlement_band = 0.0;
};

/// sigma_yy of every particle at a snapshot against the exact sigma_yy at its reference height:
/// the column is statically determinate, so sigma(Y) is the same at small and finite strain.
inline StressMeasures measure_stress(const SoilResult& result, const SoilSnapshot& snap) {
  StressMeasures m;
  const auto column = exact_column(result.scene);
  const double scale = result.scene.density * std::abs(result.scene.gravity[1]) * result.scene.length[1];
  double sum = 0.0, half_sum[2] = {0.0, 0.0}, half_largest[2] = {0.0, 0.0};
  int half_count[2] = {0, 0}, index = 0;
  // the RMS's halves are the even and the odd rows of particles (the field varies with Y; along a row it does not)
  std::vector<double> rows;
  for (const auto& p : snap.particles) rows.push_back(p.reference_y);
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), rows.end());
  auto row_parity = [&rows](double y) {
    return static_cast<int>(std::lower_bound(rows.begin(), rows.end(), y - 1e-9) - rows.begin()) % 2;
  };
  m.bottom_row_height = std::numeric_limits<double>::infinity();
  for (const auto& p : snap.particles) m.bottom_row_height = std::min(m.bottom_row_height, p.reference_y);
  int bottom_count = 0;
  for (const auto& p : snap.particles) {
    const double error = (p.sigma_yy - column.stress(p.reference_y, snap.time)) / scale;
    sum += error * error;
    const int row = row_parity(p.reference_y), half = index++ % 2;  // the bands' halves: rows for the RMS, particles for the largest
    half_sum[row] += error * error, ++half_count[row];
    half_largest[half] = std::max(half_largest[half], p.reference_y - p.y);
    m.largest_relative = std::max(m.largest_relative, std::abs(error));
    m.largest_settlement = std::max(m.largest_settlement, p.reference_y - p.y);
    if (std::abs(p.reference_y - m.bottom_row_height) < 1e-9) m.bottom_row_stress += p.sigma_yy, ++bottom_count;
  }
  m.rms_relative = std::sqrt(sum / snap.particles.size());
  if (half_count[0] > 0 && half_count[1] > 0) {
    m.rms_band = mpm::band_of_halves(m.rms_relative, std::sqrt(half_sum[0] / half_count[0]), std::sqrt(half_sum[1] / half_count[1]));
    m.largest_settlement_band = mpm::band_of_halves(m.largest_settlement, half_largest[0], half_largest[1]);
  }
  m.bottom_row_stress /= bottom_count;
  m.bottom_row_exact = column.stress(m.bottom_row_height, snap.time);
  m.exact_base = column.stress(0.0, snap.time);
  return m;
}

struct RatioMeasures {
  double expected = 0.0;           ///< nu / (1 - nu)
  double mean = 0.0;               ///< mean of sigma_xx / sigma_yy over the particles used
  double largest_deviation = 0.0;  ///< max |sigma_xx / sigma_yy - nu/(1-nu)| over them
  int particles = 0;               ///< those below the top cell (Y < H - h), where sigma_yy is far from 0
};

/// Laterally confined column in plane strain: eps_xx = 0 gives sigma_xx / sigma_yy = lambda/(lambda + 2G) = nu/(1-nu).
inline RatioMeasures measure_stress_ratio(const SoilResult& result, const SoilSnapshot& snap) {
  RatioMeasures m;
  const double nu = result.scene.poisson_ratio, top_cell = result.scene.length[1] - result.scene.spacing;
  m.expected = nu / (1.0 - nu);
  for (const auto& p : snap.particles) {
    if (p.reference_y >= top_cell) continue;
    const double ratio = p.sigma_xx / p.sigma_yy;
    m.mean += ratio;
    m.largest_deviation = std::max(m.largest_deviation, std::abs(ratio - m.expected));
    ++m.particles;
  }
  m.mean /= m.particles;
  return m;
}

/// A finished case with its settlement measures.
struct SoilOutcome {
  SoilResult result;
  SettlementMeasures settlement;
  std::vector<double> cpu_repeats;  ///< the CPU times of its timing repeats (the runs of an error-cost front; else none)
};

}  // namespace verification
