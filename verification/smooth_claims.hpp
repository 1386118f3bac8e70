// The smooth-data suite's claims, one analysis function per figure, each claim a DomainClaim evaluated on
// every run (or series) of its study: where it holds, where it fails. A stopped run is its own outcome: it is
// never compared with an error; the claims "every run finishes" say where runs stopped.
#pragma once
#include "verification/smooth_fit.hpp"
#include "verification/smooth_runs.hpp"

namespace verification::smooth {

inline Case bar_case(bool large, const Method& m, int ppc, double cfl, int cells = 0) { return {Group::bar, large, m, ppc, cfl, 0.0, cells}; }
inline Case manufactured_case(bool large, const Method& m, int ppc, int cells = 0) { return {Group::manufactured, large, m, ppc, 0.5, 0.0, cells}; }

/// "linear/fe, 1 ppc, CFL 0.5" (+ ", 64 cells" when the case has cells).
inline std::string where(const Case& c) {
  const std::string ppc = c.group == Group::manufactured ? std::to_string(c.ppc) + "x" + std::to_string(c.ppc) : std::to_string(c.ppc);
  std::string text = c.method.name() + ", " + ppc + " ppc";
  if (c.group == Group::bar) text += ", CFL " + number(c.cfl, "%.1f");
  if (c.group == Group::crossing) text += ", U/h " + number(c.ratio, "%g");
  return c.cells ? text + ", " + std::to_string(c.cells) + " cells" : text;
}

/// One measure of a series (the cases equal to `pattern` but for their cells) over its meshes.
struct SeriesData {
  std::vector<int> cells;
  std::vector<double> values;
  std::vector<int> stopped;  ///< the meshes whose run stopped
  std::vector<int> failed;   ///< the meshes whose run finished no better than a flat field (SmoothResult::ending)
};
inline SeriesData series(const Runs& runs, Case pattern, double SmoothResult::*measure) {
  SeriesData data;
  for (int n : runs.meshes(pattern)) {
    pattern.cells = n;
    const SmoothResult& r = runs.at(pattern);
    data.cells.push_back(n), data.values.push_back(r.failed ? std::nan("") : r.*measure);
    if (r.failed) data.stopped.push_back(n);
    if (r.ending() == mpm::Ending::failed) data.failed.push_back(n);
  }
  return data;
}
/// The order of a series from `from_cells` up, its failed runs left out and counted (as `mpm study` leaves them out).
inline OrderFit fit_series(const SeriesData& data, int from_cells) {
  std::vector<int> cells;
  std::vector<double> values;
  int failed = 0;
  for (std::size_t k = 0; k < data.cells.size(); ++k) {
    const bool left_out = std::find(data.failed.begin(), data.failed.end(), data.cells[k]) != data.failed.end();
    if (left_out) failed += data.cells[k] >= from_cells;
    else cells.push_back(data.cells[k]), values.push_back(data.values[k]);
  }
  OrderFit fit = fit_order(cells, values, from_cells);
  fit.failed = failed;
  return fit;
}
inline OrderFit order(const Runs& runs, const Case& pattern, double SmoothResult::*measure, int from_cells) {
  return fit_series(series(runs, pattern, measure), from_cells);
}
/// " (stopped at 128, 256 cells)", " (failed at 64 cells)", both, or "".
inline std::string stopped_text(const SeriesData& data) {
  auto list = [](const std::vector<int>& cells) {
    std::string text;
    for (int n : cells) text += (text.empty() ? "" : ", ") + std::to_string(n);
    return text;
  };
  return (data.stopped.empty() ? std::string() : " (stopped at " + list(data.stopped) + " cells)") +
         (data.failed.empty() ? std::string() : " (failed at " + list(data.failed) + " cells: no better than a flat field)");
}

/// A run's error `measure` with its band (the stress's for the stress error, the velocity's for the others: the even and
/// odd particles' RMS) and its ending (SmoothResult::ending: stopped, failed or done).
inline mpm::Measured smooth_measured(const SmoothResult& r, double SmoothResult::*measure) {
  if (r.failed || !std::isfinite(r.*measure)) return {std::nan(""), 0.0, mpm::Ending::stopped};
  return {r.*measure, measure == &SmoothResult::stress_error ? r.stress_band : r.velocity_band, r.ending()};
}

/// A sample of an order claim: the series' fitted order of `measure` on `side` of `threshold` (OrderFit::against).
inline void add_order(DomainClaim& claim, const std::string& where, const SeriesData& data, const OrderFit& fit, mpm::Side side,
                      double threshold) {
  claim.add(where + ": " + fit.text() + stopped_text(data), fit.order, fit.against(side, threshold));
}

/// A sample of a falling-error claim: the error at the series' finest mesh over its error at `from` cells at most
/// `fall`, the ratio's band from the two runs' (the one rule: a stopped run, or two failed runs, make it stopped).
inline void add_fall(DomainClaim& claim, const std::string& where, const Runs& runs, Case pattern, double SmoothResult::*measure, int from,
                     double fall) {
  const std::vector<int> meshes = runs.meshes(pattern);
  Case fine = pattern, coarse = pattern;
  fine.cells = meshes.back(), coarse.cells = from;
  const mpm::Measured a = smooth_measured(runs.at(fine), measure), b = smooth_measured(runs.at(coarse), measure);
  const mpm::Measured r = mpm::ratio(a, b);
  const mpm::Outcome outcome = mpm::judge(r, mpm::Side::below, mpm::threshold(fall));
  claim.add(where + ": " + (outcome == mpm::Outcome::stopped ? std::string("a run stopped, or both failed")
                                                                : error_text(b.value, "%.2g") + " -> " + error_text(a.value, "%.2g") +
                                                                      ", ratio ± " + number(r.band, "%.2g")),
            r.value, outcome);
}

/// A hard or soft bound: the series converges, as four criteria, four rows: its velocity order and its stress order lie
/// above 0.5 (from `from` cells, beyond 2 standard errors), and its velocity error and its stress error at the finest mesh
/// are at most `fall` times those at `from` cells (beyond the ratio's band); a sample per series, on each of `patterns`.
inline std::vector<DomainClaim> convergence_claims(const Runs& runs, const std::vector<Case>& patterns, const std::string& statement,
                                                   int from, double fall, bool hard) {
  const std::string start = std::to_string(from) + " cells";
  std::vector<DomainClaim> orders, falls;
  for (const auto& [name, measure] : {std::pair{"velocity", &SmoothResult::velocity_error}, std::pair{"stress", &SmoothResult::stress_error}}) {
    orders.push_back({statement + ": the " + name + " order lies above 0.5",
                      name + std::string(" order from ") + start + " > 0.5 beyond 2 standard errors", {}, hard});
    falls.push_back({statement + ": the " + name + " error at the finest mesh is at most " + number(fall, "%g") + " of its error at " + start,
                     name + std::string(" error at the finest mesh / at ") + start + " <= " + number(fall, "%g") + " beyond its band", {}, hard});
    for (const Case& p : patterns) {
      const SeriesData data = series(runs, p, measure);
      add_order(orders.back(), where(p), data, fit_series(data, from), mpm::Side::above, 0.5);
      add_fall(falls.back(), where(p), runs, p, measure, from, fall);
    }
  }
  return {orders[0], orders[1], falls[0], falls[1]};
}

/// Every run of `cases` finishes (no stop: the solver's diagnosis, instability or a particle off the grid).
inline DomainClaim finish_claim(const Runs& runs, const std::vector<Case>& cases, const std::string& study) {
  DomainClaim claim{"Every run finishes (" + study + ")", "the run reaches its end time (value 1) or stops (0): here a stop is what the claim counts, a fail (elsewhere a stopped run is its own outcome, never scored as an error)", {}, false};
  for (const Case& c : cases) {
    const SmoothResult& r = runs.at(c);
    claim.add(where(c), r.failed ? 0.0 : 1.0, !r.failed);
  }
  return claim;
}

/// The cases of the studies `group` / `large` with their cells set (every run), or only the series (cells 0).
inline std::vector<Case> cases_of(const Runs& runs, Group group, bool large, bool paper, bool baselines, bool series_only) {
  std::vector<Case> cases;
  for (const Axes& a : studies())
    if (a.group == group && a.large == large)
      for (Case c : expand({a})) {
        if (!(c.method.paper() ? paper : baselines) || !runs.has(c)) continue;
        if (series_only) c.cells = 0;
        if (std::find(cases.begin(), cases.end(), c) == cases.end()) cases.push_back(c);
      }
  return cases;
}

}  // namespace verification::smooth
