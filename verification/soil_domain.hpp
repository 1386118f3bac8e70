// The soil block's verdicts over their whole domain (verification/claims.hpp, DomainClaim): the refinement against the
// finite-strain column, step by step and shape by shape, and the energy growth of linear shapes against the cell
// crossings of every linear run. Each sample says where it is and what it measured; a stopped run is its own outcome.
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "verification/claims.hpp"
#include "verification/soil_report.hpp"

namespace verification {

/// The mean settlement after the ramp minus the finite-strain static settlement (signed, m): the discretisation error
/// against the model the solver discretises (mpm/exact/column_log_strain.hpp).
inline double finite_strain_gap(const SoilOutcome& o) { return o.settlement.mean_settlement - o.settlement.static_log_strain; }

inline std::string millimetres(double metres_value) { return number(1e3 * metres_value, "%+.2f"); }

/// One refinement step (h -> h/2) of the finite-strain gap e, judged by the one rule (mpm::judge): the claim
/// |e(h/2)| < |e(h)|, each gap with its estimator's floor f as its band. It holds when |e(h/2)| + f(h) + f(h/2) < |e(h)|
/// (the rule as the claim states it), fails when |e(h/2)| > |e(h)| + f(h) + f(h/2), is undecided in between and stopped
/// when a run stopped. `words` names what the gap did: "falls", "grows", "flat within the floors", each with
/// ", changes sign" where the two gaps have opposite signs beyond their floors (a sign change is no outcome of its own:
/// a gap that changes sign and shrinks beyond the floors has fallen).
struct RefinementStep {
  mpm::Outcome outcome;
  std::string words;
};
inline RefinementStep refinement_step(double coarse_gap, double coarse_floor, double fine_gap, double fine_floor, bool stopped) {
  if (stopped) return {mpm::Outcome::stopped, "stopped"};
  const mpm::Outcome outcome = mpm::judge({std::abs(fine_gap), fine_floor, mpm::Ending::done}, mpm::Side::below,
                                          {std::abs(coarse_gap), coarse_floor, mpm::Ending::done});
  std::string words = outcome == mpm::Outcome::holds ? "falls" : outcome == mpm::Outcome::fails ? "grows" : "flat within the floors";
  if (coarse_gap * fine_gap < 0.0 && std::abs(coarse_gap) > coarse_floor && std::abs(fine_gap) > fine_floor) words += ", changes sign";
  return {outcome, words};
}

TEST_CASE("soil refinement step: each branch of the rule by hand (gaps and floors in mm)") {
  using mpm::Outcome;
  CHECK(refinement_step(1.14, 0.03, 0.18, 0.05, false).outcome == Outcome::holds);  // 0.18 + 0.08 < 1.14
  CHECK(refinement_step(1.14, 0.03, -0.18, 0.05, false).outcome == Outcome::holds);  // a sign change that shrinks: falls
  CHECK(refinement_step(1.14, 0.03, -0.18, 0.05, false).words == "falls, changes sign");
  CHECK(refinement_step(0.30, 0.02, -0.20, 0.01, false).outcome == Outcome::holds);
  CHECK(refinement_step(0.20, 0.05, -0.30, 0.04, false).outcome == Outcome::fails);  // grows by 0.10 > 0.09
  CHECK(refinement_step(0.20, 0.05, -0.30, 0.04, false).words == "grows, changes sign");
  CHECK(refinement_step(0.20, 0.05, 0.26, 0.04, false).outcome == Outcome::undecided);  // 0.06 <= 0.09
  CHECK(refinement_step(0.20, 0.05, 0.26, 0.04, false).words == "flat within the floors");
  CHECK(refinement_step(0.5, 0.125, 0.25, 0.125, false).outcome == Outcome::undecided);  // falls by exactly the floors
  CHECK(refinement_step(0.5, 0.125, 0.24, 0.125, false).outcome == Outcome::holds);
  CHECK(refinement_step(0.03, 0.05, -0.02, 0.04, false).words == "flat within the floors");  // no sign beyond the floors
  CHECK(refinement_step(104.0, 0.1, 3.2, 0.1, true).outcome == Outcome::stopped);
}

/// The refinement step between two runs (SoilOutcome): refinement_step on their gaps and floors.
inline RefinementStep refinement_outcome(const SoilOutcome& coarse, const SoilOutcome& fine) {
  return refinement_step(finite_strain_gap(coarse), coarse.settlement.mean_floor, finite_strain_gap(fine),
                         fine.settlement.mean_floor, coarse.result.failed || fine.result.failed);
}

/// One sample per method and refinement step: "uGIMP, 1 -> 0.5 m: +0.30 -> -0.20 mm (floors 0.02, 0.01 mm), falls,
/// changes sign", with |e(h/2)| / |e(h)| as its value, decided by refinement_step.
inline DomainClaim refinement_domain_claim(const SoilLookup& get, const std::vector<std::string>& methods,
                                           const std::vector<double>& sizes, const std::string& integrator) {
  DomainClaim claim;
  claim.statement = std::string("Under refinement the mean settlement after the ramp approaches the finite-strain column") +
                    (integrator == "fe" ? " (forward Euler)" : " (predictor-corrector)") +
                    ": at each halving of h its gap e falls by more than the estimator's floor";
  claim.measure = "|e(h/2)| / |e(h)|; holds where |e(h/2)| + floor(h) + floor(h/2) < |e(h)|, fails where |e(h/2)| > "
                  "|e(h)| + floor(h) + floor(h/2), undecided between (a sign change is named, and judged so) (e: mean over "
                  "the last 4 T1 - finite-strain static, mm; floor: the range of that mean as the window's end moves back over one T1)";
  for (const auto& method : methods)
    for (size_t k = 1; k < sizes.size(); ++k) {
      const auto& coarse = get(run_name(method, integrator, sizes[k - 1]));
      const auto& fine = get(run_name(method, integrator, sizes[k]));
      const RefinementStep step = refinement_outcome(coarse, fine);
      std::string where = method_label(method) + ", " + number(sizes[k - 1], "%g") + " -> " + number(sizes[k], "%g") + " m: ";
      if (step.outcome == mpm::Outcome::stopped) {
        const auto& stopped = coarse.result.failed ? coarse : fine;
        where += "the " + number(stopped.result.scene.spacing, "%g") + " m run stopped at t = " +
                 number(stopped.result.time.empty() ? 0.0 : stopped.result.time.back(), "%.2f") + " s";
        claim.add_stopped(where);
        continue;
      }
      const double a = finite_strain_gap(coarse), b = finite_strain_gap(fine);
      where += millimetres(a) + " -> " + millimetres(b) + " mm (floors " + number(1e3 * coarse.settlement.mean_floor, "%.2f") + ", " +
               number(1e3 * fine.settlement.mean_floor, "%.2f") + " mm), " + step.words;
      claim.add(where, std::abs(b) / std::abs(a), step.outcome);
    }
  return claim;
}

/// Per method, the outcomes of its refinement steps in order, e.g. "falls then grows, changes sign" (two steps).
inline std::string refinement_outcomes(const SoilLookup& get, const std::string& method, const std::vector<double>& sizes,
                                       const std::string& integrator) {
  std::string text;
  for (size_t k = 1; k < sizes.size(); ++k)
    text += (k > 1 ? " then " : "") +
            refinement_outcome(get(run_name(method, integrator, sizes[k - 1])), get(run_name(method, integrator, sizes[k]))).words;
  return text;
}

/// The sentence that replaces "against the finite-strain column they fall": the methods grouped by the outcomes of
/// their refinement steps, from the data.
inline std::string refinement_summary(const SoilLookup& get, const std::vector<std::string>& methods, const std::vector<double>& sizes,
                                      const std::string& integrator) {
  std::vector<std::pair<std::string, std::string>> groups;  // outcomes, methods
  for (const auto& method : methods) {
    const std::string outcomes = refinement_outcomes(get, method, sizes, integrator);
    bool found = false;
    for (auto& group : groups)
      if (group.first == outcomes) group.second += ", " + method_label(method), found = true;
    if (!found) groups.push_back({outcomes, method_label(method)});
  }
  std::string text = "Against the finite-strain column, step by step (" + number(sizes.front(), "%g") + " -> " + number(sizes[1], "%g");
  for (size_t k = 2; k < sizes.size(); ++k) text += ", " + number(sizes[k - 1], "%g") + " -> " + number(sizes[k], "%g");
  text += " m): ";
  for (size_t k = 0; k < groups.size(); ++k) text += (k ? "; " : "") + groups[k].second + ": " + groups[k].first;
  return text + ". Only a method whose gap falls at every step converges on these grids; the others are named by what their "
                "gap does (the table's last column, the claim below with the numbers).";
}

/// The finest grid: the gap below 1 % of the static settlement, on every method.
inline DomainClaim finest_gap_claim(const SoilLookup& get, const std::vector<std::string>& methods, double h, const std::string& integrator) {
  DomainClaim claim{"On the finest grid (" + number(h, "%g") + " m) the mean settlement after the ramp lies within 1 % of the "
                    "finite-strain static settlement" + (integrator == "fe" ? " (forward Euler)" : " (predictor-corrector)"),
                    "|e| / |finite-strain static settlement| < 0.01 beyond its band (the estimator's floor over the same)", {}, false};
  for (const auto& method : methods) {
    const auto& o = get(run_name(method, integrator, h));
    if (o.result.failed) {
      claim.add_stopped(method_label(method) + ": stopped at t = " + number(o.result.time.back(), "%.2f") + " s");
      continue;
    }
    const double scale = std::abs(o.settlement.static_log_strain), relative = std::abs(finite_strain_gap(o)) / scale;
    const mpm::Measured m{relative, o.settlement.mean_floor / scale, mpm::Ending::done};
    claim.add(method_label(method) + " (± " + number(m.band, "%.2g") + ")", relative, mpm::judge(m, mpm::Side::below, mpm::threshold(0.01)));
  }
  return claim;
}

/// The regression bound the suite holds itself to (hard): LME gamma = 3 with NPC, the paper's method, falls at every
/// refinement step, and ends within 1 %: two criteria, two rows, each by the one rule (refinement_step, finest_gap_claim).
inline std::vector<DomainClaim> lme3_convergence_claims(const SoilLookup& get, const std::vector<double>& sizes) {
  DomainClaim steps = refinement_domain_claim(get, {"lme3"}, sizes, "npc");
  DomainClaim finest = finest_gap_claim(get, {"lme3"}, sizes.back(), "npc");
  std::string grids;
  for (double h : sizes) grids += (grids.empty() ? "" : ", ") + number(h, "%g");
  const std::string paper = "LME gamma = 3 with the predictor-corrector (the paper's method): ",
                    domain = " (its domain: the " + std::to_string(sizes.size()) + " grids " + grids + " m, no more; a rate is not claimed)";
  steps.statement = paper + "the gap to the finite-strain column falls at every refinement step" + domain;
  finest.statement = paper + "on the finest grid the gap to the finite-strain column is within 1 %" + domain;
  steps.hard = finest.hard = true;
  return {steps, finest};
}

/// "linear (Q4), USL, FE, 2 m: 14 particles crossed" or "...: stopped at t = 19.21 s, 20 particles crossed".
inline std::string crossing_place(const SoilOutcome& o, const std::string& label) {
  return label + ", " + number(o.result.scene.spacing, "%g") + " m: " +
         (o.result.failed ? "stopped at t = " + number(o.result.time.back(), "%.2f") + " s, " : std::string()) +
         std::to_string(o.result.particles_crossed) + " particles crossed";
}

/// "Linear shapes' energy growth after the ramp is due to cell crossing", over every run with linear shapes: the
/// predictor-corrector and forward Euler with each stress update, on every grid. It holds on a run where particles
/// crossed a cell face and the energy drifted by more than 1 %, and on a run without crossings that drifted by at most
/// 1 %; a stopped run is its own outcome (the one rule), not counted as growth.
inline std::vector<DomainClaim> crossing_claims(const SoilLookup& get, const std::vector<double>& sizes) {
  const std::vector<std::pair<std::string, std::string>> runs{
      {"linear", "npc"}, {"linear", "fe"}, {"linear_usl", "fe"}, {"linear_musl", "fe"}};
  const std::string drift = "energy drift after the ramp (max - min of kinetic + strain + gravity potential over t >= 10 s, / mean "
                            "strain energy)";
  DomainClaim crossing{"Cell crossing makes the energy of linear shapes grow after the ramp: every linear run whose particles cross "
                       "a cell face drifts by more than 1 % of the strain energy",
                       drift + " > 0.01 beyond its band (the even and odd samples' drift); a stopped run is its own outcome "
                       "(stopped), not counted as growth", {}, false};
  DomainClaim still{"Without cell crossing the energy of linear shapes stays: every linear run whose particles cross no cell face "
                    "drifts by at most 1 % of the strain energy",
                    drift + " <= 0.01 beyond its band; a stopped run is its own outcome", {}, false};
  DomainClaim usf{"The growth comes with forward Euler's USF update: on each grid linear USF drifts by more than 10 times the "
                  "largest drift of linear NPC, USL and MUSL there",
                  "drift(USF) / max(drift NPC, USL, MUSL) on the same grid > 10 beyond the ratio's band (a stopped run: its own "
                  "outcome)", {}, false};
  for (double h : sizes) {
    mpm::Measured others{0.0, 0.0, mpm::Ending::done};  // the largest drift of the others, with its band
    for (const auto& [method, integrator] : runs) {
      const auto& o = get(run_name(method, integrator, h));
      const std::string label = method_label(method) + (integrator == "npc" ? ", NPC" : method == "linear" ? ", USF" : "");
      DomainClaim& claim = o.result.particles_crossed > 0 ? crossing : still;
      if (o.result.failed) {  // the one rule: a stopped run is its own outcome, not counted as growth
        claim.add_stopped(crossing_place(o, label));
        continue;
      }
      const mpm::Measured drift{o.settlement.energy_drift, o.settlement.energy_drift_band, mpm::Ending::done};
      claim.add(crossing_place(o, label) + " (± " + number(drift.band, "%.2g") + ")", drift.value,
                mpm::judge(drift, o.result.particles_crossed > 0 ? mpm::Side::above : mpm::Side::below, mpm::threshold(0.01)));
      if (!(method == "linear" && integrator == "fe") && drift.value > others.value) others = drift;
    }
    const auto& euler = get(run_name("linear", "fe", h));
    const mpm::Measured ratio = mpm::ratio({euler.settlement.energy_drift, euler.settlement.energy_drift_band, mpm::Ending::done}, others);
    if (euler.result.failed)
      usf.add_stopped(crossing_place(euler, "linear (Q4), USF"));
    else
      usf.add(crossing_place(euler, "linear (Q4), USF") + ", ratio ± " + number(ratio.band, "%.2g"), ratio.value,
              mpm::judge(ratio, mpm::Side::above, mpm::threshold(10.0)));
  }
  std::vector<DomainClaim> claims{crossing, usf};
  if (!still.samples.empty()) claims.insert(claims.begin() + 1, still);  // a row only where some linear run crossed no face
  return claims;
}

}  // namespace verification
