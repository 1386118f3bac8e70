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
};
inline SeriesData series(const Runs& runs, Case pattern, double SmoothResult::*measure) {
  SeriesData data;
  for (int n : runs.meshes(pattern)) {
    pattern.cells = n;
    const SmoothResult& r = runs.at(pattern);
    data.cells.push_back(n), data.values.push_back(r.failed ? std::nan("") : r.*measure);
    if (r.failed) data.stopped.push_back(n);
  }
  return data;
}
inline OrderFit order(const Runs& runs, const Case& pattern, double SmoothResult::*measure, int from_cells) {
  const SeriesData data = series(runs, pattern, measure);
  return fit_order(data.cells, data.values, from_cells);
}
/// " (stopped at 128, 256 cells)" or "".
inline std::string stopped_text(const SeriesData& data) {
  if (data.stopped.empty()) return "";
  std::string text;
  for (int n : data.stopped) text += (text.empty() ? "" : ", ") + std::to_string(n);
  return " (stopped at " + text + " cells)";
}

/// A hard or soft bound: the series converges (velocity and stress orders >= 0.5 from `from` cells, no run stopped, both
/// errors at the finest mesh <= `fall` x at `from` cells), evaluated on each of `patterns`. Value: the velocity order.
inline DomainClaim convergence_claim(const Runs& runs, const std::vector<Case>& patterns, const std::string& statement, int from, double fall,
                                     bool hard) {
  DomainClaim claim{statement, "velocity and stress orders (± standard error) above 0.5 by 2 s.e. from " + std::to_string(from) +
                                   " cells, errors at the finest mesh <= " + number(fall, "%g") + " x at " + std::to_string(from) + "; no run stopped",
                    {}, hard};
  for (const Case& p : patterns) {
    const SeriesData v = series(runs, p, &SmoothResult::velocity_error), s = series(runs, p, &SmoothResult::stress_error);
    const OrderFit vo = fit_order(v.cells, v.values, from), so = fit_order(s.cells, s.values, from);
    const auto first = std::find(v.cells.begin(), v.cells.end(), from) - v.cells.begin();
    const bool falls = v.values.back() <= fall * v.values[first] && s.values.back() <= fall * s.values[first];
    add_orders(claim, where(p) + ": v " + vo.text() + ", σ " + so.text() + stopped_text(v), vo.order,
               orders_against({vo, so}, 0.5), v.stopped.empty() && falls, !v.stopped.empty());
  }
  return claim;
}

/// Every run of `cases` finishes (no stop: the solver's diagnosis, instability or a particle off the grid).
inline DomainClaim finish_claim(const Runs& runs, const std::vector<Case>& cases, const std::string& study) {
  DomainClaim claim{"Every run finishes (" + study + ")", "the run reaches its end time (value 1) or stops (0, its own outcome: not scored as an error)", {}, false};
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
