// Cost verdicts the smooth suite can defend: the spread of a run's CPU time measured on a sample (each case run 5
// times, interleaved), and the error-cost front with a run counted cheaper only by a margin larger than that spread.
#pragma once
#include <fstream>

#include "verification/error_cost.hpp"
#include "verification/parallel.hpp"
#include "verification/smooth_claims.hpp"

namespace verification::smooth {

/// The spread of CPU time: the largest (max - min) / min over the sample's cases of their repeated CPU times.
struct CpuSpread {
  double relative = std::nan("");  ///< NaN: not measured (every cost comparison is then a tie)
  int cases = 0, repeats = 0;
  std::string worst;  ///< the case with the largest spread
  std::string text() const {
    return std::isfinite(relative) ? number(100.0 * relative, "%.0f") + " % (largest over " + std::to_string(cases) + " cases x " + std::to_string(repeats) +
                                         " interleaved repeats, at " + worst + ")"
                                   : std::string("not measured");
  }
};

/// The sample: every method of the bar at 64 cells (1 ppc, small amplitude) and of the 2D solutions at 16 cells (2x2 ppc).
inline std::vector<Case> spread_sample() {
  std::vector<Case> sample;
  for (const Method& m : with_paper(bar_baselines())) {
    sample.push_back(bar_case(false, m, 1, 0.5, 64));
    sample.push_back(manufactured_case(false, m, 2, 16));
  }
  return sample;
}

/// Runs each case of `sample` `repeats` times, round by round (each round every case once, in parallel on `cores`, one
/// thread each), and measures the spread of each case's CPU time.
inline CpuSpread measure_cpu_spread(const Runs& runs, const Scenes& scenes, const std::vector<Case>& sample, unsigned cores, int repeats = 5) {
  std::vector<std::vector<double>> seconds(sample.size());
  std::vector<std::string> names;
  for (std::size_t k = 0; k < sample.size(); ++k) names.push_back("smooth_cpu_spread_" + std::to_string(k));
  for (int round = 0; round < repeats; ++round) {
    std::vector<double> cpu(sample.size());
    run_cases("smooth", names, std::vector<bool>(sample.size(), false), cores, [&](std::size_t k, int threads) {
      DykaResult unused;
      const double start = thread_cpu_seconds();
      run_case(sample[k], runs, scenes, threads, unused);
      cpu[k] = thread_cpu_seconds() - start;
    });
    for (std::size_t k = 0; k < sample.size(); ++k) seconds[k].push_back(cpu[k]);
  }
  CpuSpread spread{0.0, int(sample.size()), repeats, ""};
  for (std::size_t k = 0; k < sample.size(); ++k) {
    const auto [low, high] = std::minmax_element(seconds[k].begin(), seconds[k].end());
    const double relative = (*high - *low) / *low;
    if (relative > spread.relative) spread.relative = relative, spread.worst = where(sample[k]);
  }
  return spread;
}

inline void write_spread(const std::string& folder, const CpuSpread& spread) {
  std::ofstream out(folder + "/smooth_cpu_spread.csv");
  out << "relative_spread,cases,repeats,worst\n" << spread.relative << "," << spread.cases << "," << spread.repeats << "," << spread.worst << "\n";
}
inline CpuSpread read_spread(const std::string& folder) {
  std::ifstream in(folder + "/smooth_cpu_spread.csv");
  CpuSpread spread;
  std::string header, value;
  if (!std::getline(in, header) || !std::getline(in, value, ',')) return spread;
  spread.relative = std::stod(value);
  std::string cases, repeats;
  std::getline(in, cases, ','), std::getline(in, repeats, ','), std::getline(in, spread.worst);
  spread.cases = std::stoi(cases), spread.repeats = std::stoi(repeats);
  return spread;
}

/// One finished or stopped run of an error-cost comparison.
struct CostRun {
  std::string where;
  bool paper = false;  ///< uGIMP or LME gamma 3
  double error = std::nan(""), cpu = 0.0;  ///< error NaN: the run stopped (not on any front: its own outcome)
  double band = 0.0;   ///< the error's band (the even and odd particles')
  bool failed = false;  ///< finished no better than a flat field (SmoothResult::ending)
};

/// "uGIMP or LME γ = 3 is on the error-cost front", evaluated on each of their finished runs in `runs` by mark_front
/// (error_cost.hpp): it holds where no finished run is both more accurate beyond the two errors' bands and cheaper by more
/// than the CPU spread (CPU x (1 + spread) below its own); undecided where one is so only within the band or the spread.
inline DomainClaim front_claim(const std::vector<CostRun>& runs, const CpuSpread& spread, const std::string& study) {
  DomainClaim claim{"uGIMP or LME γ = 3 is on the error-cost front (" + study + ")",
                    "no finished run both more accurate beyond the errors' bands and cheaper by more than the CPU time's spread, " +
                        spread.text() + "; value: the run's error",
                    {}, false};
  std::vector<CostPoint> points;
  for (const CostRun& run : runs)
    points.push_back(cost_point(run.where, run.error, !std::isfinite(run.error), {run.cpu}, spread.relative, run.band, run.failed));
  mark_front(points, spread.relative);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const CostRun& run = runs[k];
    if (!run.paper || !std::isfinite(run.error)) continue;
    const std::string where = run.where + " in " + number(1e3 * run.cpu, "%.3g") + " ms";
    if (!std::isfinite(spread.relative))
      claim.add_undecided(where + "; no timing spread measured", run.error);
    else if (!points[k].dominated_by.empty())
      claim.add(where + "; beaten by " + points[k].dominated_by, run.error, false);
    else if (!points[k].ties.empty())
      claim.add_undecided(where + "; tied with " + points[k].ties, run.error);
    else
      claim.add(where, run.error, true);
  }
  return claim;
}

/// The runs of the cases equal to `pattern` but for method and cells, every method of `methods` (cells 0: every mesh).
inline std::vector<CostRun> cost_runs(const Runs& runs, const Case& pattern, const std::vector<Method>& methods) {
  std::vector<CostRun> list;
  for (const Method& m : methods) {
    Case p = pattern;
    p.method = m;
    for (int n : pattern.cells ? std::vector<int>{pattern.cells} : runs.meshes(p)) {
      p.cells = n;
      if (!runs.has(p)) continue;
      const SmoothResult& r = runs.at(p);
      list.push_back({where(p), m.paper() && m.shape != "linear", r.failed ? std::nan("") : r.velocity_error, r.cpu_seconds, r.velocity_band,
                      r.ending() == mpm::Ending::failed});
    }
  }
  return list;
}

/// The error-cost fronts of the bar (small and large amplitude, 1 and 2 ppc), the crossing at U/h = 1 and the 2D solutions.
inline std::vector<DomainClaim> front_claims(const Runs& runs, const CpuSpread& spread, Group group) {
  std::vector<DomainClaim> list;
  if (group == Group::bar)
    for (bool large : {false, true})
      for (int ppc : {1, 2})
        list.push_back(front_claim(cost_runs(runs, bar_case(large, {}, ppc, 0.5), with_paper(bar_baselines())), spread,
                                   std::string(large ? "large" : "small") + " amplitude, " + std::to_string(ppc) + " ppc, CFL 0.5, velocity error, every mesh"));
  if (group == Group::crossing)
    for (int ppc : {1, 2})
      list.push_back(front_claim(cost_runs(runs, {Group::crossing, false, {}, ppc, 0.5, 1.0, crossing_cells}, with_paper(crossing_baselines())), spread,
                                 "velocity error at U/h = 1, " + std::to_string(ppc) + " ppc"));
  if (group == Group::manufactured)
    for (bool large : {false, true})
      list.push_back(front_claim(cost_runs(runs, manufactured_case(large, {}, 2), with_paper(bar_baselines())), spread,
                                 std::string(large ? "large" : "small") + " amplitude, 2x2 ppc, velocity error, every mesh"));
  return list;
}

}  // namespace verification::smooth
