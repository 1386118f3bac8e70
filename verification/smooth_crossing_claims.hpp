// The grid-crossing onset (`smooth_crossing`) and the 2D manufactured solutions (`smooth_manufactured`): their claims,
// the onset table and the CSV of onsets.
#pragma once
#include <fstream>
#include <sstream>

#include "verification/smooth_claims.hpp"

namespace verification::smooth {

/// The first U/h of the sweep at which the velocity error exceeds twice its value at the smallest U/h, or the run stops;
/// NaN when none does up to the largest.
inline double onset(const Runs& runs, const Method& method, int ppc) {
  Case c{Group::crossing, false, method, ppc, 0.5, crossing_ratios().front(), crossing_cells};
  const double base = runs.at(c).velocity_error;
  for (double ratio : crossing_ratios()) {
    c.ratio = ratio;
    const SmoothResult& r = runs.at(c);
    if (r.failed || !(r.velocity_error <= 2.0 * base)) return ratio;
  }
  return std::nan("");
}
inline std::string onset_text(double value) { return std::isfinite(value) ? number(value, "%g") : "> " + number(crossing_ratios().back(), "%g"); }
/// The onset as text, " (stopped)" where the run at the onset stopped rather than exceeding twice its error.
inline std::string onset_text(const Runs& runs, const Method& method, int ppc, double value) {
  const bool stopped = std::isfinite(value) && runs.at({Group::crossing, false, method, ppc, 0.5, value, crossing_cells}).failed;
  return onset_text(value) + (stopped ? " (stopped)" : "");
}
/// a leaves its no-crossing error later than b (NaN: no onset in the sweep, the latest).
inline bool later(double a, double b) { return std::isfinite(b) && !(a <= b); }

/// The onsets: uGIMP and LME against linear, today's baselines against the paper's latest; writes smooth_crossing_onset.csv
/// and the onset table (Markdown) into `table`.
inline std::vector<DomainClaim> crossing_claims(const Runs& runs, const std::string& folder, std::ostream& table) {
  const auto methods = with_paper(crossing_baselines());
  std::map<std::pair<std::string, int>, double> first;
  std::ofstream csv(folder + "/smooth_crossing_onset.csv");
  csv << "shape,integrator,ppc,no_crossing_error,onset_amplitude_over_h\n";
  table << "| method | 1 ppc | 2 ppc |\n|---|---|---|\n";
  for (const Method& m : methods) {
    table << "| " << m.name();
    for (int ppc : {1, 2}) {
      const double base = runs.at({Group::crossing, false, m, ppc, 0.5, crossing_ratios().front(), crossing_cells}).velocity_error;
      first[{m.name(), ppc}] = onset(runs, m, ppc);
      CsvRow row;
      row << m.shape << m.integrator << ppc << base << first[{m.name(), ppc}];
      csv << row.text.str() << "\n";
      table << " | " << onset_text(runs, m, ppc, first[{m.name(), ppc}]) << " (no-crossing error " << number(base, "%.2g") << ")";
    }
    table << " |\n";
  }
  table << "\n";
  DomainClaim smooth{"uGIMP and LME leave their no-crossing error later than linear shape functions (same integrator and ppc)",
                     "onset U/h (first U/h with a velocity error over twice its value at U/h = 0.01, or a stop) later than linear's", {}, false};
  DomainClaim latest{"With today's baselines in the comparison, uGIMP or LME γ = 3 still leaves its no-crossing error the latest",
                     "the baseline's onset U/h not later than the latest of uGIMP and LME γ = 3 (either integrator, same ppc)", {}, false};
  for (int ppc : {1, 2}) {
    double paper = 0.0;
    for (const Method& m : paper_methods())
      if (m.shape != "linear" && (later(first[{m.name(), ppc}], paper) || !std::isfinite(first[{m.name(), ppc}]))) paper = first[{m.name(), ppc}];
    for (const Method& m : methods) {
      const double mine = first[{m.name(), ppc}];
      const std::string at = m.name() + ", " + std::to_string(ppc) + " ppc: " + onset_text(runs, m, ppc, mine);
      if (m.paper() && m.shape != "linear") {
        const double linear = first[{"linear/" + m.integrator, ppc}];
        smooth.add(at + " (linear " + onset_text(linear) + ")", mine, later(mine, linear) || (!std::isfinite(mine) && std::isfinite(linear)));
      }
      if (!m.paper()) latest.add(at + " (paper's latest " + onset_text(paper) + ")", mine, !later(mine, paper) && (std::isfinite(mine) || !std::isfinite(paper)));
    }
  }
  return {smooth, latest};
}

/// The 2D manufactured solutions: the convergence bound at small amplitude, convergence at large amplitude, stops.
inline std::vector<DomainClaim> manufactured_claims(const Runs& runs) {
  std::vector<DomainClaim> list;
  list.push_back(convergence_claim(runs, cases_of(runs, Group::manufactured, false, true, false, true),
                                   "Bound: without grid crossing the 2D kernels converge (small amplitude, every series)", 12, 0.65, true));
  list.push_back(convergence_claim(runs, cases_of(runs, Group::manufactured, false, false, true, true),
                                   "Today's baselines converge in 2D as the bound above asks (small amplitude, 2x2 ppc)", 12, 0.65, false));
  std::vector<Case> large = cases_of(runs, Group::manufactured, true, true, true, true);
  DomainClaim converges{"At large amplitude (a_x = 0.04 L: particles cross cells from 7 cells per side at 2x2 ppc, 13 at 1x1) the method still converges in 2D",
                        "velocity order (± standard error, 12-32 cells) above 0.5 by 2 s.e., no run stopped", {}, false};
  for (const Case& p : large) {
    const SeriesData v = series(runs, p, &SmoothResult::velocity_error);
    const OrderFit fit = fit_order(v.cells, v.values, 12);
    add_orders(converges, where(p) + ": " + error_text(v.values.front(), "%.2g") + " -> " + error_text(v.values.back(), "%.2g") +
                   ", order " + fit.text() + stopped_text(v),
               fit.order, orders_against({fit}, 0.5), v.stopped.empty(), !v.stopped.empty());
  }
  list.push_back(converges);
  list.push_back(finish_claim(runs, cases_of(runs, Group::manufactured, true, true, true, false), "2D manufactured, large amplitude"));
  return list;
}

}  // namespace verification::smooth
