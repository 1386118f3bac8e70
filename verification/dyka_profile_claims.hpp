// Fig. 7's oscillation and damping claims on the profiles along the whole bar (verification/dyka_profiles.hpp): v and
// sigma of every particle at the steps nearest to the chosen times, against the exact solution at each step's own t,
// on every run of the sweep at CFL 0.5; each comparison by the one rule, with the band of the even and odd particles.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "verification/dyka_report.hpp"

namespace verification::dyka {

/// v or sigma of a profile.
enum class ProfileField { velocity, stress };
inline const char* field_name(ProfileField field) { return field == ProfileField::velocity ? "v" : "σ"; }

/// The scores of `run`'s profile at `index` of field `field` (none when the run stopped before it).
inline bool profile_scores(const DykaResult& run, std::size_t index, ProfileField field, ProfileScores& scores) {
  if (run.failed || index >= run.profiles.size()) return false;
  const Profile& p = run.profiles[index];
  scores = field == ProfileField::velocity ? score_profile(p.velocity, p.exact_velocity) : score_profile(p.stress, p.exact_stress);
  return true;
}

/// A profile score as a measured number, the run's ending as its history's (rms_measured: failed when its RMS at A is
/// no smaller than a flat line's), stopped when the run stopped before the profile's time.
inline mpm::Measured profile_measured(const DykaResult& run, bool scored, const ProfileScore& score) {
  if (!scored) return {std::nan(""), 0.0, mpm::Ending::stopped};
  return {score.whole, score.band(), rms_measured(run).ending};
}

/// "150 µs (step at 150.2 µs)": the chosen time and the step the profile was taken at.
inline std::string profile_time_text(const DykaResult& run, std::size_t index) {
  if (index >= run.profiles.size()) return "t " + std::to_string(index);
  return text(1e6 * run.profiles[index].target, "%.0f") + " µs (step at " + text(1e6 * run.profiles[index].time, "%.2f") + " µs)";
}

/// Per field: NPC rings less than FE along the bar; NPC's ringing within the bound 1.18 (as for the histories, Fig. 7);
/// NPC keeps the amplitude: its spread about the mean at least 0.91 of the exact's (the 0.09 of the paper's band, as a
/// relative loss: a choice, as the plateau deficit's).
inline std::vector<DomainClaim> profile_claims(const Runs& runs, const Scope& scope) {
  std::vector<DomainClaim> claims;
  for (ProfileField field : {ProfileField::velocity, ProfileField::stress}) {
    const std::string f = field_name(field);
    DomainClaim less{"Along the bar the predictor-corrector rings less than forward Euler (" + f + " profiles)",
                     "ringing of the " + f + " profile (total variation along the bar over the exact's) NPC / FE < 1 beyond its "
                     "band, every shape and mesh of the sweep at CFL 0.5, at each chosen time", {}, false};
    DomainClaim removes{"Along the bar the predictor-corrector removes the spurious oscillations (" + f + " profiles)",
                        "NPC's ringing of the " + f + " profile <= 1.18 beyond its band (the histories' bound, Fig. 7)", {}, false};
    DomainClaim keeps{"Along the bar the predictor-corrector keeps the amplitude (" + f + " profiles)",
                      "NPC's amplitude of the " + f + " profile (its spread about the mean over the exact's) >= 0.91 beyond its "
                      "band (a loss of at most 0.09, the width of the paper's band, as for the plateau deficit)", {}, false};
    for (const auto& shape : scope.shapes)
      for (int cells : scope.cells)
        for (std::size_t k = 0; k < profile_fractions.size(); ++k) {
          const auto &fe = runs.at(sweep_name(shape, "fe", cells)), &npc = runs.at(sweep_name(shape, "npc", cells));
          ProfileScores s_fe, s_npc;
          const bool fe_scored = profile_scores(fe, k, field, s_fe), npc_scored = profile_scores(npc, k, field, s_npc);
          const std::string where = shape_label(shape) + " " + std::to_string(cells) + ", " + profile_time_text(npc, k);
          const mpm::Measured npc_ringing = profile_measured(npc, npc_scored, s_npc.ringing);
          add_pair(less, where, ", NPC " + text(s_npc.ringing.whole, "%.2f") + ", FE " + text(s_fe.ringing.whole, "%.2f"), npc, "NPC",
                   npc_ringing, fe, "FE", profile_measured(fe, fe_scored, s_fe.ringing), mpm::Side::below);
          add_single(removes, where, ", NPC " + text(s_npc.ringing.whole, "%.2f"), npc, "NPC", npc_ringing, mpm::Side::below, 1.18);
          add_single(keeps, where, ", NPC " + text(s_npc.amplitude.whole, "%.3f"), npc, "NPC",
                     profile_measured(npc, npc_scored, s_npc.amplitude), mpm::Side::above, 0.91);
        }
    claims.insert(claims.end(), {less, removes, keeps});
  }
  return claims;
}

/// The section: the profiles' claims at this project's beta, then LME's under the authors' beta.
inline Section profile_section(const Runs& runs) {
  Section section{"Fig. 7 along the bar: v and σ profiles of every particle",
                  "Every run of the sweep at CFL 0.5, v and σ of every particle at the steps nearest to 1/4, 1/2 and 3/4 of the end "
                  "time (no extra step: the runs' own steps, each named), against the exact solution at that step's own t. Ringing: "
                  "the total variation along the bar over the exact profile's; amplitude: the spread about the mean over the exact's "
                  "(below 1: damped). Bands: the same scores on the even and on the odd particles alone.",
                  profile_claims(runs, full_scope())};
  for (const auto& claim : under_authors_beta(profile_claims(runs, lme_scope(authors_lme)))) section.claims.push_back(claim);
  return section;
}

}  // namespace verification::dyka
