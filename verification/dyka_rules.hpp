// LME under the two beta rules side by side: every claim of Figs. 6, 7, 9, 10 and dyka_fair evaluated on LME's runs
// under this project's beta (gamma / h^2) and under the authors' (paper/09_choices.md, 'The authors' beta'), on the
// meshes both rules ran, and which verdicts change.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "verification/dyka_accuracy.hpp"
#include "verification/dyka_fair.hpp"

namespace verification::dyka {

/// Every claim of the accuracy figures on `scope`, in one order (so that the two rules' lists pair up).
inline std::vector<DomainClaim> accuracy_claims(const Runs& runs, const Scope& scope) {
  std::vector<DomainClaim> claims;
  for (const auto& part :
       {fig6_claims(runs, scope), fig7_claims(runs, scope), fair_claims(runs, scope), fig9_10_claims(runs, scope)})
    claims.insert(claims.end(), part.begin(), part.end());
  return claims;
}

/// The largest |RMS_authors / RMS_ours - 1| of LME's sweep over both integrators and authors_cells (CFL 0.5).
inline double largest_rms_change(const Runs& runs) {
  double largest = 0.0;
  for (const auto& integrator : integrators)
    for (int cells : authors_cells)
      largest = std::max(largest, std::abs(runs.rms(sweep_name(authors_lme, integrator, cells)) /
                                           runs.rms(sweep_name("lme", integrator, cells)) - 1.0));
  return largest;
}

/// CPU seconds of every run under the authors' beta in the suite (the sweep's, the large CFLs', the fair comparison's).
inline double authors_cpu_seconds(const Runs& runs) {
  double seconds = 0.0;
  for (const auto& [name, run] : runs.by_name)
    if (name.find(authors_lme) != std::string::npos && name.rfind("dyka_gamma_", 0) != 0) seconds += run.cpu_seconds;
  return seconds;
}

/// The report's section: a row per claim, its verdict on LME's samples under each rule, and whether it changes.
inline Section rules_section(const Runs& runs) {
  const auto ours = accuracy_claims(runs, lme_scope("lme")), theirs = accuracy_claims(runs, lme_scope(authors_lme));
  std::string table = "| claim (LME's samples) | this project's β = γ / h² | the authors' β | verdict |\n"
                      "|---|---|---|---|\n";
  int changed = 0, compared = 0;
  std::string which;
  for (size_t k = 0; k < ours.size() && k < theirs.size(); ++k) {
    if (ours[k].samples.empty() && theirs[k].samples.empty()) {
      table += "| " + ours[k].statement + " | - | - | not compared: no samples under either rule |\n";
      continue;
    }
    // a verdict changes when its direction does (verdict_class: all hold, some, all fail, undecided, none); the same
    // direction over other counts is named, not counted
    const bool same = verdict_class(ours[k]) == verdict_class(theirs[k]);
    ++compared, changed += !same;
    if (!same) which += std::string(which.empty() ? "" : "; ") + ours[k].statement;
    table += "| " + ours[k].statement + " | " + ours[k].verdict() + " | " + theirs[k].verdict() + " | " +
             (!same ? "**changes**" : ours[k].verdict() == theirs[k].verdict() ? "same" : "same direction, other counts") + " |\n";
  }
  const std::string notes =
      "Every claim of Figs. 6, 7, 9, 10 and `dyka_fair` evaluated on LME's runs alone (γ = 3), under this project's β "
      "and under the authors' (`solver.lme_beta = \"authors\"`, paper/09_choices.md), on " + cells_text(authors_cells) +
      " cells and the large CFLs. Fig. 8's claim is evaluated under both rules in its own section (its samples name "
      "the rule). The authors' rule moves LME's RMS/v0 by at most " +
      text(100.0 * largest_rms_change(runs), "%.2f") + " % on these meshes (CFL 0.5, both integrators). Its runs took " +
      text(authors_cpu_seconds(runs), "%.1f") + " s of CPU in all (the blend's calibration included).\n\n"
      "Verdicts that change between the two rules (in direction: all hold, some, all fail, undecided): " +
      std::to_string(changed) + " of " + std::to_string(compared) + " compared claims" + (which.empty() ? "." : " (" + which + ").") + "\n\n" + table;
  return {"LME under the two β rules: which verdicts change", notes, {}};
}

}  // namespace verification::dyka
