// The soil block's verdicts over their whole domain (verification/claims.hpp, DomainClaim): the refinement against the
// finite-strain column, step by step and shape by shape, and the energy growth of linear shapes against the cell
// crossings of every linear run. Each sample says where it is and what it measured; a stopped run is its own outcome.
#pragma once
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

/// What one refinement step (h -> h/2) does to the finite-strain gap e, with the estimators' floors f of both runs:
/// "falls" when |e(h/2)| + f < |e(h)|, "grows" when |e(h/2)| > |e(h)| + f, "changes sign" when the two gaps have
/// opposite signs and each lies beyond its own floor, "flat within the floor" otherwise; "stopped" when a run stopped.
inline std::string refinement_outcome(const SoilOutcome& coarse, const SoilOutcome& fine) {
  if (coarse.result.failed || fine.result.failed) return "stopped";
  const double a = finite_strain_gap(coarse), b = finite_strain_gap(fine);
  const double fa = coarse.settlement.mean_floor, fb = fine.settlement.mean_floor, floor = fa + fb;
  if (a * b < 0.0 && std::abs(a) > fa && std::abs(b) > fb) return "changes sign";
  if (std::abs(b) + floor < std::abs(a)) return "falls";
  if (std::abs(b) > std::abs(a) + floor) return "grows";
  return "flat within the floor";
}

/// One sample per method and refinement step: "uGIMP, 1 -> 0.5 m: +0.30 -> -0.20 mm (floors 0.02, 0.01 mm), changes
/// sign", with |e(h/2)| / |e(h)| as its value; it holds where the gap falls by more than the floors.
inline DomainClaim refinement_domain_claim(const SoilLookup& get, const std::vector<std::string>& methods,
                                           const std::vector<double>& sizes, const std::string& integrator) {
  DomainClaim claim;
  claim.statement = std::string("Under refinement the mean settlement after the ramp approaches the finite-strain column") +
                    (integrator == "fe" ? " (forward Euler)" : " (predictor-corrector)") +
                    ": at each halving of h its gap e falls by more than the estimator's floor";
  claim.measure = "|e(h/2)| / |e(h)|; holds where |e(h/2)| + floor(h) + floor(h/2) < |e(h)| (e: mean over the last 4 T1 - "
                  "finite-strain static, mm; floor: the range of that mean as the window's end moves back over one T1)";
  for (const auto& method : methods)
    for (size_t k = 1; k < sizes.size(); ++k) {
      const auto& coarse = get(run_name(method, integrator, sizes[k - 1]));
      const auto& fine = get(run_name(method, integrator, sizes[k]));
      const std::string outcome = refinement_outcome(coarse, fine);
      std::string where = method_label(method) + ", " + number(sizes[k - 1], "%g") + " -> " + number(sizes[k], "%g") + " m: ";
      if (outcome == "stopped") {
        const auto& stopped = coarse.result.failed ? coarse : fine;
        where += "the " + number(stopped.result.scene.spacing, "%g") + " m run stopped at t = " +
                 number(stopped.result.time.empty() ? 0.0 : stopped.result.time.back(), "%.2f") + " s";
        claim.add_stopped(where);
        continue;
      }
      const double a = finite_strain_gap(coarse), b = finite_strain_gap(fine);
      where += millimetres(a) + " -> " + millimetres(b) + " mm (floors " + number(1e3 * coarse.settlement.mean_floor, "%.2f") + ", " +
               number(1e3 * fine.settlement.mean_floor, "%.2f") + " mm), " + outcome;
      claim.add(where, std::abs(b) / std::abs(a), outcome == "falls");
    }
  return claim;
}

/// Per method, the outcomes of its refinement steps in order, e.g. "falls, changes sign".
inline std::string refinement_outcomes(const SoilLookup& get, const std::string& method, const std::vector<double>& sizes,
                                       const std::string& integrator) {
  std::string text;
  for (size_t k = 1; k < sizes.size(); ++k)
    text += (k > 1 ? ", " : "") +
            refinement_outcome(get(run_name(method, integrator, sizes[k - 1])), get(run_name(method, integrator, sizes[k])));
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
                    "|e| / |finite-strain static settlement|, holds below 0.01", {}, false};
  for (const auto& method : methods) {
    const auto& o = get(run_name(method, integrator, h));
    if (o.result.failed) {
      claim.add_stopped(method_label(method) + ": stopped at t = " + number(o.result.time.back(), "%.2f") + " s");
      continue;
    }
    const double relative = std::abs(finite_strain_gap(o) / o.settlement.static_log_strain);
    claim.add(method_label(method), relative, relative < 0.01);
  }
  return claim;
}

/// The regression bound the suite holds itself to (hard): LME gamma = 3 with NPC, the paper's method, falls at every
/// refinement step and ends within 1 %.
inline DomainClaim lme3_convergence_claim(const SoilLookup& get, const std::vector<double>& sizes) {
  DomainClaim steps = refinement_domain_claim(get, {"lme3"}, sizes, "npc");
  DomainClaim finest = finest_gap_claim(get, {"lme3"}, sizes.back(), "npc");
  DomainClaim claim{"LME gamma = 3 with the predictor-corrector (the paper's method): the gap to the finite-strain column falls at "
                    "every refinement step and ends within 1 %",
                    "steps: |e(h/2)| / |e(h)| as above; finest grid: |e| / |static settlement| below 0.01", steps.samples, true};
  for (const auto& sample : finest.samples) claim.samples.push_back({sample.where + ", finest grid", sample.value, sample.holds});
  return claim;
}

/// "linear (Q4), USL, FE, 2 m: 14 particles crossed" or "...: stopped at t = 19.21 s, 20 particles crossed".
inline std::string crossing_place(const SoilOutcome& o, const std::string& label) {
  return label + ", " + number(o.result.scene.spacing, "%g") + " m: " +
         (o.result.failed ? "stopped at t = " + number(o.result.time.back(), "%.2f") + " s, " : std::string()) +
         std::to_string(o.result.particles_crossed) + " particles crossed";
}

/// "Linear shapes' energy growth after the ramp is due to cell crossing", over every run with linear shapes: the
/// predictor-corrector and forward Euler with each stress update, on every grid. It holds on a run where particles
/// crossed a cell face and the energy drifted by more than 1 % (or the run stopped: its energy grew past the solver's
/// bound), and on a run without crossings that drifted by at most 1 %.
inline std::vector<DomainClaim> crossing_claims(const SoilLookup& get, const std::vector<double>& sizes) {
  const std::vector<std::pair<std::string, std::string>> runs{
      {"linear", "npc"}, {"linear", "fe"}, {"linear_usl", "fe"}, {"linear_musl", "fe"}};
  DomainClaim crossing{"Cell crossing makes the energy of linear shapes grow after the ramp: every linear run whose particles cross "
                       "a cell face drifts by more than 1 % of the strain energy (and every one without crossings by less)",
                       "energy drift after the ramp (max - min of kinetic + strain + gravity potential over t >= 10 s, / mean "
                       "strain energy); a stopped run counts as growth", {}, false};
  DomainClaim usf{"The growth comes with forward Euler's USF update: on each grid linear USF drifts by more than 10 times the "
                  "largest drift of linear NPC, USL and MUSL there",
                  "drift(USF) / max(drift NPC, USL, MUSL) on the same grid, holds above 10 (a stopped USF run: growth)", {}, false};
  for (double h : sizes) {
    double others = 0.0;
    for (const auto& [method, integrator] : runs) {
      const auto& o = get(run_name(method, integrator, h));
      const std::string label = method_label(method) + (integrator == "npc" ? ", NPC" : method == "linear" ? ", USF" : "");
      const bool grew = o.result.failed || o.settlement.energy_drift > 0.01;
      crossing.add(crossing_place(o, label), o.settlement.energy_drift, grew == (o.result.particles_crossed > 0));
      if (!(method == "linear" && integrator == "fe")) others = std::max(others, o.settlement.energy_drift);
    }
    const auto& euler = get(run_name("linear", "fe", h));
    const double ratio = euler.settlement.energy_drift / others;
    usf.add(crossing_place(euler, "linear (Q4), USF"), ratio, euler.result.failed || ratio > 10.0);
  }
  return {crossing, usf};
}

}  // namespace verification
