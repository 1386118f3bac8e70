// The report of the Dyka-bar suite: sections of claims over their domains (verification/claims.hpp), and the
// small helpers the analysis functions share.
#pragma once
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "verification/claims.hpp"
#include "verification/dyka_fit.hpp"
#include "verification/dyka_runs.hpp"

namespace verification::dyka {

/// A section of the report: its title (figures named in `backticks` are shown), Markdown before the claims, the claims.
struct Section {
  std::string title, notes;
  std::vector<DomainClaim> claims;
};

inline void write_section(std::ostream& out, const Section& section) {
  out << "### " << section.title << "\n\n";
  const std::string& title = section.title;
  for (size_t at = title.find('`'); at != std::string::npos; at = title.find('`', title.find('`', at + 1) + 1)) {
    const std::string figure = title.substr(at + 1, title.find('`', at + 1) - at - 1);
    if (figure.rfind("dyka_", 0) == 0) out << "![" << figure << "](figures/" << figure << ".png)\n\n";
  }
  if (!section.notes.empty()) out << section.notes << "\n\n";
  if (!section.claims.empty()) write_domain_claims(out, section.claims);
}

/// "640 cells" at CFL 0.5, "40 cells, CFL 1.3" otherwise.
inline std::string mesh_text(int cells, double cfl = 0.5) {
  return std::to_string(cells) + " cells" + (cfl == 0.5 ? std::string() : ", CFL " + text(cfl));
}
inline std::string rms_text(double value) { return text(value, "%.4f"); }

/// The runs a claim is evaluated on: its shapes (LME under one beta rule) and the meshes of the sweep.
struct Scope {
  std::vector<std::string> shapes;
  std::vector<int> cells;
  std::string lme;  ///< "lme" or authors_lme: the LME that claims over every shape compare
};
/// The report's claims: every shape, LME at this project's beta, every mesh of the sweep.
inline Scope full_scope() { return {shapes, sweep_cells, "lme"}; }
/// LME alone under one beta rule (`lme`: "lme" or authors_lme) on the meshes both rules ran: the claims compared
/// between the rules.
inline Scope lme_scope(const std::string& lme) { return {{lme}, authors_cells, lme}; }
/// Claims evaluated on lme_scope(authors_lme), their statements saying so.
inline std::vector<DomainClaim> under_authors_beta(std::vector<DomainClaim> claims) {
  for (auto& claim : claims) claim.statement += " *[LME at the authors' β, " + cells_text(authors_cells) + " cells]*";
  return claims;
}

/// The runs a shape's integrator comparison is evaluated on: the meshes `cells` at CFL 0.5, then the large CFLs.
struct MeshCfl {
  int cells;
  double cfl;
};
inline std::vector<MeshCfl> comparison_domain(const std::vector<int>& cells_of_sweep = sweep_cells) {
  std::vector<MeshCfl> domain;
  for (int cells : cells_of_sweep) domain.push_back({cells, 0.5});
  for (double cfl : large_cfls)
    for (int cells : large_cfl_cells) domain.push_back({cells, cfl});
  return domain;
}

/// A claim of a figure at CFL 0.5 and its extension to the large CFLs, a row of its own ("Beyond the figure's CFL 0.5:
/// ..."): the claim a sample at `cfl` goes to.
struct CflRows {
  DomainClaim figure, beyond;
  CflRows(const std::string& statement, const std::string& measure)
      : figure{statement, measure + ", on every mesh of the sweep at CFL 0.5", {}, false},
        beyond{"Beyond the figure's CFL 0.5: " + statement, measure + ", at the large CFLs", {}, false} {}
  DomainClaim& at(double cfl) { return cfl == 0.5 ? figure : beyond; }
};

/// A run's score with the band of its own sampling and its ending (mpm/analysis/verdict.hpp): RMS/v0, its band the
/// larger move of the even or the odd rows' RMS; a finished run whose RMS is no smaller than a flat line's has failed.
inline mpm::Measured rms_measured(const DykaResult& run) {
  if (run.failed) return {std::nan(""), 0.0, mpm::Ending::stopped};
  return {run.rms / speed_v0, mpm::band_of_halves(run.rms, run.even.rms, run.odd.rms) / speed_v0,
          mpm::score_ending(run.rms, run.flat_rms)};
}
/// The ringing (DykaResult::ringing) with the band of its sampling, and the run's ending as rms_measured's.
inline mpm::Measured ringing_measured(const DykaResult& run) {
  mpm::Measured m = rms_measured(run);
  if (!run.failed) m.value = run.ringing, m.band = mpm::band_of_halves(run.ringing, run.even.ringing, run.odd.ringing);
  return m;
}
/// The plateau overshoot (DykaResult::overshoot, / v0) with the band of its sampling.
inline mpm::Measured overshoot_measured(const DykaResult& run) {
  mpm::Measured m = rms_measured(run);
  if (!run.failed) m.value = run.overshoot, m.band = mpm::band_of_halves(run.overshoot, run.even.overshoot, run.odd.overshoot);
  return m;
}
/// The plateau deficit (DykaResult::undershoot, / v0) with the band of its sampling.
inline mpm::Measured deficit_measured(const DykaResult& run) {
  mpm::Measured m = rms_measured(run);
  if (!run.failed) m.value = run.undershoot, m.band = mpm::band_of_halves(run.undershoot, run.even.undershoot, run.odd.undershoot);
  return m;
}

/// The spread of RMS over `runs`, 100 (largest - smallest) / smallest in %, with its band from the two runs' bands;
/// stopped when a run stopped or every run failed.
inline mpm::Measured rms_spread(const std::vector<const DykaResult*>& runs) {
  std::vector<mpm::Measured> m;
  bool every_failed = true;
  for (const DykaResult* run : runs) {
    m.push_back(rms_measured(*run));
    if (m.back().ending == mpm::Ending::stopped) return {std::nan(""), 0.0, mpm::Ending::stopped};
    every_failed = every_failed && m.back().ending == mpm::Ending::failed;
  }
  if (m.empty() || every_failed) return {std::nan(""), 0.0, mpm::Ending::stopped};
  const auto by_value = [](const mpm::Measured& a, const mpm::Measured& b) { return a.value < b.value; };
  const mpm::Measured &low = *std::min_element(m.begin(), m.end(), by_value), &high = *std::max_element(m.begin(), m.end(), by_value);
  return {100.0 * (high.value - low.value) / low.value, 100.0 * (high.band + low.band) / low.value, mpm::Ending::done};
}

/// "NPC stopped at 156 µs: ...", "both failed (RMS no smaller than a flat line's)": why a comparison is not compared.
inline std::string not_compared_text(const DykaResult& a, const std::string& a_label, const DykaResult& b,
                                     const std::string& b_label) {
  if (a.failed) return a_label + " " + stopped_text(a);
  if (b.failed) return b_label + " " + stopped_text(b);
  return "both failed (RMS/v0 " + text(a.rms / speed_v0, "%.3f") + " and " + text(b.rms / speed_v0, "%.3f") +
         ", no smaller than a flat line's " + text(a.flat_rms / speed_v0, "%.3f") + ")";
}

/// A sample comparing two runs by the one rule (mpm::judge): the ratio of their measures `ma` / `mb`, with its band,
/// on `side` of `bound` (1 by default). A stopped run, or two failed runs, make it "stopped", named so; a ratio within
/// its band of the bound is undecided. `detail` (the measured numbers) follows `where`, then the ratio's band.
inline void add_pair(DomainClaim& claim, const std::string& where, const std::string& detail, const DykaResult& a,
                     const std::string& a_label, const mpm::Measured& ma, const DykaResult& b, const std::string& b_label,
                     const mpm::Measured& mb, mpm::Side side, double bound = 1.0) {
  const mpm::Measured r = mpm::ratio(ma, mb);
  const mpm::Outcome outcome = mpm::judge(r, side, mpm::threshold(bound));
  if (outcome == mpm::Outcome::stopped)
    claim.add(where + ": " + not_compared_text(a, a_label, b, b_label), std::nan(""), outcome);
  else
    claim.add(where + detail + ", ratio ± " + text(r.band, "%.2g"), r.value, outcome);
}

/// One run's measure `m` (an overshoot, a deficit, a ringing, an amplitude) on `side` of `bound` by the one rule: where +
/// detail, the measure's band, or "stopped". A failed run's such measure describes no approximation (its RMS is no
/// smaller than a flat line's): not compared against a fixed bound, stopped, as two failed runs are.
inline void add_single(DomainClaim& claim, const std::string& where, const std::string& detail, const DykaResult& run,
                       const std::string& label, const mpm::Measured& m, mpm::Side side, double bound) {
  const mpm::Outcome outcome = m.ending == mpm::Ending::failed ? mpm::Outcome::stopped : mpm::judge(m, side, mpm::threshold(bound));
  if (outcome == mpm::Outcome::stopped)
    claim.add(where + ": " + label + " " + (run.failed ? stopped_text(run) : "failed (RMS no smaller than a flat line's)"),
              std::nan(""), outcome);
  else
    claim.add(where + detail + " ± " + text(m.band, "%.2g"), m.value, outcome);
}

/// A sample of an order claim: the fitted order above `threshold` beyond 2 standard errors (the one rule), or stopped
/// where there is no fit (fewer than 3 finished runs).
inline void add_order(DomainClaim& claim, const std::string& where, const OrderFit& fit, double threshold) {
  if (fit.fitted())
    claim.add(where + ": order " + order_text(fit), fit.order,
              mpm::judge({fit.order, 2.0 * fit.standard_error, mpm::Ending::done}, mpm::Side::above, mpm::threshold(threshold)));
  else
    claim.add_stopped(where + ": no fit (" + order_text(fit) + ")");
}

/// Fitted order of a run family over the meshes `cells` it ran (finished runs only), by `measure` (RMS/v0 by default).
template <class Measure>
OrderFit fit_runs(const Runs& runs, const std::vector<int>& cells, const std::string& shape, const std::string& integrator, Measure measure) {
  std::vector<int> used;
  std::vector<double> error;
  for (int n : cells) {
    if (!swept(shape, n)) continue;
    const DykaResult& run = runs.at(sweep_name(shape, integrator, n));
    if (!run.failed) used.push_back(n), error.push_back(measure(run));
  }
  return fit_order(used, error);
}
inline OrderFit fit_runs(const Runs& runs, const std::vector<int>& cells, const std::string& shape, const std::string& integrator) {
  return fit_runs(runs, cells, shape, integrator, [](const DykaResult& run) { return run.rms; });
}
inline std::vector<int> without_first(std::vector<int> cells) {
  if (!cells.empty()) cells.erase(cells.begin());
  return cells;
}

}  // namespace verification::dyka
