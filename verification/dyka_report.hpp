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

/// A sample comparing two runs of a claim at `where`: a stopped run is named as such, a sample not compared,
/// never scored; otherwise `where` + `detail` (the measured numbers), `value` and `holds` as given.
inline void add_pair(DomainClaim& claim, const std::string& where, const std::string& detail, const DykaResult& a, const std::string& a_label,
                     const DykaResult& b, const std::string& b_label, double value, bool holds) {
  if (a.failed || b.failed)
    claim.add_stopped(where + ": " + (a.failed ? a_label + " " + stopped_text(a) : b_label + " " + stopped_text(b)));
  else
    claim.add(where + detail, value, holds);
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
