// The runs of the Dyka-bar suite: every case of dyka_cases.hpp on the machine's cores, the PIC/FLIP blend
// calibrated per shape and mesh, and the repeated, interleaved timings of the error-cost fronts.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "verification/dyka_cases.hpp"
#include "verification/parallel.hpp"

namespace verification::dyka {

/// Every run of the suite by name, and the timing repeats of the fronts.
struct Runs {
  std::string scene, folder;
  unsigned cores = 1;
  std::map<std::string, DykaResult> by_name;
  std::map<std::string, double> flip_fraction;            ///< per fair_name(shape, "feblend", cells)
  std::map<std::string, std::vector<double>> cpu_repeats;  ///< per run name: its repeated CPU times, s

  const DykaResult& at(const std::string& name) const {
    const auto found = by_name.find(name);
    if (found == by_name.end()) throw std::runtime_error("dyka_suite: no run " + name);
    return found->second;
  }
  double rms(const std::string& name) const { return at(name).rms / speed_v0; }  ///< RMS / |v0|
};

/// "stopped at 87.3 µs: energy grew to 10.23 times (limit 10)": a stopped run, as its own outcome.
inline std::string stopped_text(const DykaResult& run) {
  std::string reason = run.failure.substr(run.failure.rfind(": ") == std::string::npos ? 0 : run.failure.rfind(": ") + 2);
  const std::string long_part = " the initial energy plus the work of the body force";
  if (reason.find(long_part) != std::string::npos) reason.erase(reason.find(long_part), long_part.size());
  return "stopped at " + text(run.time.empty() ? 0.0 : 1e6 * run.time.back(), "%.1f") + " µs: " + reason;
}

/// Runs `cases` on the cores, longest first, and keeps them under their names (writing each series when asked).
inline void run_all(Runs& runs, std::vector<CaseSpec> cases, bool write_series_files) {
  std::stable_sort(cases.begin(), cases.end(), [](const CaseSpec& a, const CaseSpec& b) { return case_weight(a) > case_weight(b); });
  std::vector<std::string> names;
  for (const auto& spec : cases) names.push_back(spec.name);
  std::vector<DykaResult> results(cases.size());
  run_cases("dyka", names, std::vector<bool>(cases.size(), false), runs.cores, [&](size_t k, int threads) {
    results[k] = run_dyka(runs.scene, cases[k].name, cases[k].overrides, threads);
    if (write_series_files) write_series(results[k], runs.folder + "/" + cases[k].name + ".csv");
  });
  for (auto& result : results) runs.by_name[result.name] = std::move(result);
}

/// Forward Euler given the predictor-corrector's energy loss: per shape (LME under both beta rules) and mesh without
/// crossing, bisection on the FLIP fraction of shape + FE until its energy at 200 µs matches shape + NPC's (to 1e-4 of
/// it; the energy left grows with the fraction); that run is the shape's "feblend" run on the mesh.
inline void calibrate_blends(Runs& runs) {
  std::vector<std::pair<std::string, int>> tasks;
  std::vector<std::string> names;
  for (int cells : band_cells("negligible"))
    for (const auto& shape : both_rules_shapes) tasks.push_back({shape, cells}), names.push_back("dyka_fair_" + shape + "_" + std::to_string(cells));
  std::vector<DykaResult> blends(tasks.size());
  std::vector<double> fractions(tasks.size());
  run_cases("dyka", names, std::vector<bool>(tasks.size(), false), runs.cores, [&](size_t k, int threads) {
    const auto& [shape, cells] = tasks[k];
    const double target = runs.at(sweep_name(shape, "npc", cells)).final_energy_ratio;
    auto blended = [&](double fraction) {
      return run_dyka(runs.scene, fair_name(shape, "feblend", cells),
                      with(mesh_settings(shape, cells), {"solver.integrator=\"fe\"", "solver.flip_fraction=" + text(fraction, "%.17g")}), threads);
    };
    double low = 0.0, high = 1.0;
    DykaResult best;
    for (int iteration = 0; iteration < 40; ++iteration) {
      const double middle = 0.5 * (low + high);
      best = blended(middle);
      fractions[k] = middle;
      if (std::abs(best.final_energy_ratio - target) <= 1e-4 * target) break;
      (best.final_energy_ratio > target ? high : low) = middle;
    }
    blends[k] = std::move(best);
    write_series(blends[k], runs.folder + "/" + blends[k].name + ".csv");
  });
  for (size_t k = 0; k < tasks.size(); ++k) {
    runs.flip_fraction[blends[k].name] = fractions[k];
    runs.by_name[blends[k].name] = std::move(blends[k]);
  }
}

/// The runs of the error-cost fronts on the repeated meshes, each `timing_repeats` times more, interleaved: every round
/// runs every one of them once, in an order rotated from round to round, `cores` at a time; their CPU times are kept.
inline void time_repeats(Runs& runs, const std::vector<std::string>& timed) {
  std::vector<std::string> names;
  std::vector<size_t> which;
  for (int round = 0; round < timing_repeats; ++round)
    for (size_t k = 0; k < timed.size(); ++k) {
      const size_t pick = (k + round * (timed.size() / timing_repeats + 1)) % timed.size();
      names.push_back("dyka_timing_" + std::to_string(round)), which.push_back(pick);
    }
  std::vector<double> cpu(names.size());
  run_cases("dyka", names, std::vector<bool>(names.size(), false), runs.cores, [&](size_t k, int threads) {
    const DykaResult& original = runs.at(timed[which[k]]);
    cpu[k] = run_dyka(runs.scene, original.name, original.overrides, threads).cpu_seconds;
  });
  for (size_t k = 0; k < names.size(); ++k) runs.cpu_repeats[timed[which[k]]].push_back(cpu[k]);
}

}  // namespace verification::dyka
