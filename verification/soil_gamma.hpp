// LME's gamma swept on the soil block's 2 m grid (make studies): accuracy, ringing and damping per gamma, with both
// integrators, each claim evaluated on every gamma by the one rule (the Dyka bar's sweep: dyka_experiments.hpp).
#pragma once
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "verification/soil_report.hpp"

namespace verification {

/// Fig. 8's gammas, as the soil suite's method names "lme0.8" ... "lme5".
inline const std::vector<std::string>& soil_gamma_methods() {
  static const std::vector<std::string> methods{"lme0.8", "lme1", "lme1.5", "lme2", "lme3", "lme4", "lme5"};
  return methods;
}

/// Each measure of a soil run with its band and ending: the RMS of u_y over 0-20 s (band: its even and odd samples),
/// the swing of u_y over the last 4 T1 (band: its range when the window moves back over a period) and the energy lost
/// after the ramp, the trend of SettlementMeasures::energy_loss (band: its even and odd samples).
inline mpm::Measured soil_measured(const SoilOutcome& o, double value, double band) {
  if (o.result.failed) return {std::nan(""), 0.0, mpm::Ending::stopped};
  return {value, band, mpm::Ending::done};
}
inline mpm::Measured soil_rms(const SoilOutcome& o) { return soil_measured(o, o.settlement.rms_error, o.settlement.rms_band); }
inline mpm::Measured soil_swing(const SoilOutcome& o) { return soil_measured(o, o.settlement.swing, o.settlement.swing_floor); }
inline mpm::Measured soil_loss(const SoilOutcome& o) { return soil_measured(o, o.settlement.energy_loss, o.settlement.energy_loss_band); }

/// "0.0123 ± 0.0004" (a measure's value and band, %.3g), or "stopped".
inline std::string soil_measured_text(const mpm::Measured& m) {
  return m.ending == mpm::Ending::stopped ? "stopped" : number(m.value, "%.4g") + " ± " + number(m.band, "%.2g");
}

/// data/soil_gamma.csv and the section "LME's gamma on the soil block".
inline void write_soil_gamma_section(std::ostream& report, const SoilLookup& get, const std::string& folder) {
  std::ofstream csv(folder + "/soil_gamma.csv");
  csv << "integrator,gamma,rms_error,rms_band,final_error,swing,swing_floor,exact_swing,energy_loss,energy_loss_band,energy_drift,"
         "energy_drift_band,status\n";
  DomainClaim best{"On the soil block γ = 3 is LME's most accurate γ",
                   "RMS of u_y over 0-20 s at γ = 3 below the smallest of the other γ (0.8-5) beyond their bands", {}, false};
  DomainClaim rings{"On the soil block small γ rings more: the swing of u_y after the ramp at γ <= 1.5 exceeds γ = 3's",
                    "max - min of u_y over the last 4 T1 (m; band: its range over windows moved back by up to T1) above γ = 3's "
                    "beyond their bands", {}, false};
  DomainClaim damps{"On the soil block small γ damps more: the energy lost after the ramp at γ <= 1.5 exceeds γ = 3's",
                    "the mechanical energy's least-squares trend over 10-20 s, lost, / the mean kinetic + strain energy, above γ = 3's "
                    "beyond their bands", {}, false};
  for (const std::string integrator : {"npc", "fe"}) {
    const SoilOutcome& three = get(run_name("lme3", integrator, 2.0));
    std::vector<mpm::Measured> others;
    std::vector<std::string> other_names;
    for (const auto& method : soil_gamma_methods()) {
      const SoilOutcome& o = get(run_name(method, integrator, 2.0));
      const SettlementMeasures& m = o.settlement;
      csv << integrator << "," << method.substr(3) << "," << m.rms_error << "," << m.rms_band << "," << m.final_error << "," << m.swing << ","
          << m.swing_floor << "," << m.exact_swing << "," << m.energy_loss << "," << m.energy_loss_band << "," << m.energy_drift << "," << m.energy_drift_band << ","
          << (o.result.failed ? "failed" : "ok") << "\n";
      if (method != "lme3") others.push_back(soil_rms(o)), other_names.push_back(method.substr(3));
      if (std::stod(method.substr(3)) > 1.5) continue;
      const std::string where = (integrator == "npc" ? "NPC, γ " : "FE, γ ") + method.substr(3) + " against 3: ";
      rings.add(where + soil_measured_text(soil_swing(o)) + " m against " + soil_measured_text(soil_swing(three)) + " m",
                soil_swing(o).value, mpm::judge(soil_swing(o), mpm::Side::above, soil_swing(three)));
      damps.add(where + soil_measured_text(soil_loss(o)) + " against " + soil_measured_text(soil_loss(three)), soil_loss(o).value,
                mpm::judge(soil_loss(o), mpm::Side::above, soil_loss(three)));
    }
    const BestOfGroups b = judge_best({soil_rms(three)}, others);
    const std::string where = integrator == "npc" ? "NPC" : "FE";
    if (b.outcome == mpm::Outcome::stopped)
      best.add(where + ": a run stopped", std::nan(""), b.outcome);
    else
      best.add(where + ": γ 3 " + soil_measured_text(soil_rms(three)) + " m, best other γ " + other_names[b.other] + " " +
                   number(others[b.other].value, "%.4g") + " m", soil_rms(three).value, b.outcome);
  }
  report << "### Beyond the paper: LME's γ on the soil block (2 m cells)\n\n"
         << "![soil_gamma](figures/soil_gamma.png)\n\n"
         << "Fig. 8's γ = 0.8-5 on the paper's 2 m grid, with both integrators (the Dyka bar's sweep on three meshes: "
            "\"LME's γ on three meshes\"): accuracy (the RMS of the observed particle's u_y against the exact column over 0-20 s), "
            "ringing (the swing of u_y over the last 4 T1, all after the ramp; the exact column's free oscillation swings "
         << number(get(run_name("lme3", "npc", 2.0)).settlement.exact_swing * 1e3, "%.2g")
         << " mm) and damping (the energy lost after the ramp, when gravity is constant and the model itself dissipates nothing: the trend of the mechanical energy, not its oscillation about it), each "
            "with its band (data/soil_gamma.csv).\n\n";
  write_domain_claims(report, {best, rings, damps});
}

}  // namespace verification
