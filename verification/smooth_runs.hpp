// Runs the smooth-data suite's cases (smooth_study.hpp) in parallel, one thread each, and writes each
// study's runs as CSV; the finite-strain references of the large amplitudes are built first.
#pragma once
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "verification/claims.hpp"
#include "verification/parallel.hpp"
#include "verification/smooth_study.hpp"

namespace verification::smooth {

/// The scenes the suite runs.
struct Scenes {
  BarScene bar;
  std::string dyka, manufactured;
};

/// Every case and what it measured.
struct Runs {
  std::vector<Case> cases;
  std::vector<SmoothResult> results;
  std::vector<DykaResult> dyka;  ///< the Dyka cases' own measures (others: empty)
  std::map<double, std::unique_ptr<mpm::exact::FiniteStrainBar>> references;  ///< by the bar's V / (omega L)
  double seconds = 0.0;                                                       ///< wall time of the runs

  std::ptrdiff_t index(const Case& c) const {
    const auto found = std::find(cases.begin(), cases.end(), c);
    return found == cases.end() ? -1 : found - cases.begin();
  }
  bool has(const Case& c) const { return index(c) >= 0; }
  const SmoothResult& at(const Case& c) const {
    const auto k = index(c);
    if (k < 0) throw std::runtime_error(std::string("no ") + group_name(c.group) + " run " + c.method.name() + " " + std::to_string(c.cells));
    return results[k];
  }
  /// The meshes run for the cases equal to `c` but for their cells, coarsest first.
  std::vector<int> meshes(Case c) const {
    std::vector<int> cells;
    for (const Case& other : cases)
      if ((c.cells = other.cells, other == c)) cells.push_back(other.cells);
    std::sort(cells.begin(), cells.end());
    return cells;
  }
};

/// The finite-strain references: the large amplitude on reference_cells cells, each amplitude of the crossing sweep on
/// crossing_reference_cells.
inline void build_references(Runs& runs, const BarScene& bar, unsigned cores) {
  std::vector<double> amplitudes{large_amplitude};
  for (double ratio : crossing_ratios()) amplitudes.push_back(ratio / crossing_cells);
  std::vector<std::unique_ptr<mpm::exact::FiniteStrainBar>> built(amplitudes.size());
  std::vector<std::string> names;
  for (std::size_t k = 0; k < amplitudes.size(); ++k) names.push_back("references_" + std::to_string(k));
  run_cases("smooth", names, std::vector<bool>(amplitudes.size(), false), cores, [&](std::size_t k, int) {
    built[k] = std::make_unique<mpm::exact::FiniteStrainBar>(bar.reference(amplitudes[k], k == 0 ? reference_cells : crossing_reference_cells));
  });
  for (std::size_t k = 0; k < built.size(); ++k) runs.references[amplitudes[k]] = std::move(built[k]);
}

inline std::string dyka_name(const Case& c) { return "dyka2_" + c.method.shape + "_" + c.method.integrator + "_" + std::to_string(c.cells); }

/// Runs case `c` on `threads` threads (the references from `runs`); a Dyka case also fills `dyka`.
inline SmoothResult run_case(const Case& c, const Runs& runs, const Scenes& scenes, int threads, DykaResult& dyka) {
  if (c.group == Group::manufactured)
    return run_manufactured(scenes.manufactured, {c.method.shape, c.method.integrator, c.cells, c.ppc, c.cfl, c.large}, threads);
  if (c.group == Group::dyka) {
    std::vector<std::string> overrides = method_settings(c.method.shape, c.method.integrator);
    overrides.insert(overrides.end(), {"grid.cells=[" + std::to_string(c.cells) + "]", "grid.margin_min=[" + std::to_string(4 + c.cells / 100) + "]",
                                       "body[0].particles_per_cell=[" + std::to_string(c.ppc) + "]", "output.snapshots=[]"});
    dyka = run_dyka(scenes.dyka, dyka_name(c), overrides, threads);
    SmoothResult result;
    result.wall_seconds = dyka.wall_seconds, result.failed = dyka.failed, result.failure = dyka.failure;
    return result;
  }
  const bool reference = c.large || c.group == Group::crossing;
  return run_bar(scenes.bar, {c.method.shape, c.method.integrator, c.cells, c.ppc, c.cfl, c.amplitude(), {}},
                 reference ? runs.references.at(c.amplitude()).get() : nullptr, threads);
}

/// Runs every case of `studies`, the most work first, each on one thread (see verification/parallel.hpp, run_cases).
inline Runs run_all(const std::vector<Axes>& studies, const Scenes& scenes, unsigned cores) {
  Runs runs;
  build_references(runs, scenes.bar, cores);
  runs.cases = expand(studies);
  const SceneSizes sizes(scenes.dyka, scenes.manufactured);
  std::stable_sort(runs.cases.begin(), runs.cases.end(), [&](const Case& a, const Case& b) { return work(a, sizes) > work(b, sizes); });
  runs.results.resize(runs.cases.size());
  runs.dyka.resize(runs.cases.size());
  std::vector<std::string> names;
  for (const Case& c : runs.cases) names.push_back(std::string("smooth_") + group_name(c.group) + "_" + std::to_string(names.size()));
  const auto start = std::chrono::steady_clock::now();
  run_cases("smooth", names, std::vector<bool>(runs.cases.size(), false), cores, [&](std::size_t k, int threads) {
    const double cpu_start = thread_cpu_seconds();
    runs.results[k] = run_case(runs.cases[k], runs, scenes, threads, runs.dyka[k]);
    runs.results[k].cpu_seconds = thread_cpu_seconds() - cpu_start;
  });
  runs.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return runs;
}

/// A CSV row from its fields, numbers with 8 significant digits.
struct CsvRow {
  std::ostringstream text;
  CsvRow() { text.precision(8); }
  template <class T>
  CsvRow& operator<<(const T& field) {
    if (text.tellp() > 0) text << ",";
    text << field;
    return *this;
  }
};

inline const char* status(const SmoothResult& r) { return r.failed ? "failed" : "ok"; }
/// The run's ending by the one rule (mpm/analysis/verdict.hpp): "stopped" (status failed), "failed" (it finished no
/// better than a flat field: velocity_error >= velocity_flat), or "done".
inline const char* ending_name(const SmoothResult& r) {
  return r.ending() == mpm::Ending::stopped ? "stopped" : r.ending() == mpm::Ending::failed ? "failed" : "done";
}

/// Writes smooth_bar.csv, smooth_crossing.csv and smooth_manufactured.csv: one row per run, in the studies' order; each
/// ends with the bands of its two errors (the even and odd particles'), the flat field's score, the run's ending and the
/// band of its energy ratio (its change over the last step).
inline void write_runs(const std::string& folder, const std::vector<Axes>& studies, const Runs& runs) {
  const char* ending_columns = "velocity_band,stress_band,velocity_flat,ending,energy_band\n";
  std::ofstream bar(folder + "/smooth_bar.csv"), crossing(folder + "/smooth_crossing.csv"), manufactured(folder + "/smooth_manufactured.csv");
  bar << "amplitude,shape,integrator,ppc,cfl,cells,velocity_error,stress_error,energy_ratio,wall_seconds,steps,status,velocity_error_own_time,cpu_seconds," << ending_columns;
  crossing << "shape,integrator,ppc,amplitude_over_h,velocity_error,stress_error,status,velocity_error_own_time,cpu_seconds," << ending_columns;
  manufactured << "amplitude,shape,integrator,ppc,cells,velocity_error,stress_error,wall_seconds,steps,status,cpu_seconds," << ending_columns;
  for (const Case& c : expand(studies)) {
    const SmoothResult& r = runs.at(c);
    CsvRow row;
    if (c.group == Group::bar)
      row << (c.large ? "large" : "small") << c.method.shape << c.method.integrator << c.ppc << number(c.cfl, "%.1f") << c.cells << r.velocity_error
          << r.stress_error << r.energy_ratio << r.wall_seconds << r.steps << status(r) << r.velocity_error_own_time << r.cpu_seconds;
    else if (c.group == Group::crossing)
      row << c.method.shape << c.method.integrator << c.ppc << c.ratio << r.velocity_error << r.stress_error << status(r) << r.velocity_error_own_time
          << r.cpu_seconds;
    else if (c.group == Group::manufactured)
      row << (c.large ? "large" : "small") << c.method.shape << c.method.integrator << c.ppc << c.cells << r.velocity_error << r.stress_error
          << r.wall_seconds << r.steps << status(r) << r.cpu_seconds;
    else
      continue;
    row << r.velocity_band << r.stress_band << r.velocity_flat << ending_name(r) << r.energy_band;
    (c.group == Group::bar ? bar : c.group == Group::crossing ? crossing : manufactured) << row.text.str() << "\n";
  }
}

}  // namespace verification::smooth
