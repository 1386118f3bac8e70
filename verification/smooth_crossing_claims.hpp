// The grid-crossing onset (`smooth_crossing`) and the 2D manufactured solutions (`smooth_manufactured`): their claims,
// the onset table and the CSV of onsets.
#pragma once
#include <fstream>
#include <sstream>

#include "verification/onset.hpp"
#include "verification/smooth_claims.hpp"

namespace verification::smooth {

/// The method's onset (verification/onset.hpp) on the crossing sweep at `ppc` particles per cell.
inline Onset onset(const Runs& runs, const Method& method, int ppc) {
  Case c{Group::crossing, false, method, ppc, 0.5, crossing_ratios().front(), crossing_cells};
  const double base = runs.at(c).velocity_error;
  for (double ratio : crossing_ratios()) {
    c.ratio = ratio;
    const SmoothResult& r = runs.at(c);
    if (r.failed) return {ratio, true};
    if (!(r.velocity_error <= 2.0 * base)) return {ratio, false};
  }
  return {};
}
inline std::string onset_text(double value) { return std::isfinite(value) ? number(value, "%g") : "> " + number(crossing_ratios().back(), "%g"); }
/// The onset as text, "stopped at U/h 0.5" where a run stopped before the error doubled.
inline std::string onset_text(const Onset& onset) { return onset_text(onset, crossing_ratios().back()); }

/// The onsets: uGIMP and LME against linear, today's baselines against the paper's latest; writes smooth_crossing_onset.csv
/// and the onset table (Markdown) into `table`.
inline std::vector<DomainClaim> crossing_claims(const Runs& runs, const std::string& folder, std::ostream& table) {
  const auto methods = with_paper(crossing_baselines());
  std::map<std::pair<std::string, int>, Onset> first;
  std::ofstream csv(folder + "/smooth_crossing_onset.csv");
  csv << "shape,integrator,ppc,no_crossing_error,onset_amplitude_over_h,onset_stopped\n";
  table << "| method | 1 ppc | 2 ppc |\n|---|---|---|\n";
  for (const Method& m : methods) {
    table << "| " << m.name();
    for (int ppc : {1, 2}) {
      const double base = runs.at({Group::crossing, false, m, ppc, 0.5, crossing_ratios().front(), crossing_cells}).velocity_error;
      const Onset o = first[{m.name(), ppc}] = onset(runs, m, ppc);
      CsvRow row;
      row << m.shape << m.integrator << ppc << base << o.ratio << (o.stopped ? 1 : 0);
      csv << row.text.str() << "\n";
      table << " | " << onset_text(o) << " (no-crossing error " << number(base, "%.2g") << ")";
    }
    table << " |\n";
  }
  table << "\n";
  DomainClaim smooth{"uGIMP and LME leave their no-crossing error later than linear shape functions (same integrator and ppc)",
                     "onset U/h (first U/h with a velocity error over twice its value at U/h = 0.01) later than linear's; the same U/h: "
                     "undecided; a run stopped first: stopped", {}, false};
  DomainClaim latest{"With today's baselines in the comparison, uGIMP or LME γ = 3 still leaves its no-crossing error the latest",
                     "the paper's latest onset (uGIMP and LME γ = 3, either integrator, same ppc) later than the baseline's; the same U/h: undecided", {}, false};
  for (int ppc : {1, 2}) {
    Onset paper{0.0, false};
    for (const Method& m : paper_methods())
      if (m.shape != "linear" && !first[{m.name(), ppc}].stopped && later(first[{m.name(), ppc}], paper) == mpm::Outcome::holds)
        paper = first[{m.name(), ppc}];
    for (const Method& m : methods) {
      const Onset mine = first[{m.name(), ppc}];
      const std::string at = m.name() + ", " + std::to_string(ppc) + " ppc: " + onset_text(mine);
      if (m.paper() && m.shape != "linear") {
        const Onset linear = first[{"linear/" + m.integrator, ppc}];
        smooth.add(at + " (linear " + onset_text(linear) + ")", mine.ratio, later(mine, linear));
      }
      if (!m.paper()) latest.add(at + " (paper's latest " + onset_text(paper) + ")", mine.ratio, later(paper, mine));
    }
  }
  return {smooth, latest};
}

/// The 2D manufactured solutions: the convergence bound at small amplitude, convergence at large amplitude, stops.
inline std::vector<DomainClaim> manufactured_claims(const Runs& runs) {
  std::vector<DomainClaim> list;
  list = convergence_claims(runs, cases_of(runs, Group::manufactured, false, true, false, true),
                            "Bound: without grid crossing the 2D kernels converge (small amplitude, every series)", 12, 0.65, true);
  for (auto& claim : convergence_claims(runs, cases_of(runs, Group::manufactured, false, false, true, true),
                                        "Today's baselines converge in 2D as the bound above asks (small amplitude, 2x2 ppc)", 12, 0.65, false))
    list.push_back(claim);
  std::vector<Case> large = cases_of(runs, Group::manufactured, true, true, true, true);
  DomainClaim converges{"At large amplitude (a_x = 0.04 L: particles cross cells from 7 cells per side at 2x2 ppc, 13 at 1x1) the method still converges in 2D",
                        "velocity order (12-32 cells) > 0.5 beyond 2 standard errors", {}, false};
  for (const Case& p : large) {
    const SeriesData v = series(runs, p, &SmoothResult::velocity_error);
    add_order(converges, where(p) + ": " + error_text(v.values.front(), "%.2g") + " -> " + error_text(v.values.back(), "%.2g"), v,
              fit_series(v, 12), mpm::Side::above, 0.5);
  }
  list.push_back(converges);
  list.push_back(finish_claim(runs, cases_of(runs, Group::manufactured, true, true, true, false), "2D manufactured, large amplitude"));
  return list;
}

}  // namespace verification::smooth
