// The vibrating bar's claims: the exact solutions and references, the small amplitude (`smooth_bar_small`, no
// grid crossing) and the large amplitude (`smooth_bar_large`, particles cross cells).
#pragma once
#include "verification/smooth_claims.hpp"

namespace verification::smooth {

/// The scene's initial field and the finite-strain references, checked (hard).
inline std::vector<DomainClaim> reference_claims(const Runs& runs, const BarScene& bar) {
  std::vector<DomainClaim> list;
  double mismatch = 0.0;
  for (std::size_t k = 0; k < runs.cases.size(); ++k)
    if (runs.cases[k].group == Group::bar || runs.cases[k].group == Group::crossing) mismatch = std::max(mismatch, runs.results[k].initial_mismatch);
  list.push_back({"The scene's [initial_field] formula gives every particle the exact mode's velocity V cos(πX/2L)", "largest |v_p - v|/V < 1e-12", {}, true});
  list.back().add("every bar and crossing run (largest)", mismatch, mismatch < 1e-12);
  const auto mode = bar.mode(small_amplitude), large_mode = bar.mode(large_amplitude);
  const auto tiny = bar.reference(small_amplitude, 512), coarse = bar.reference(large_amplitude, reference_cells / 2);
  const auto& fine = *runs.references.at(large_amplitude);
  double worst = 0.0, change = 0.0, nonlinear = 0.0;
  for (std::size_t k = 0; k < bar_sample_fractions().size(); ++k)
    for (int i = 0; i <= 100; ++i) {
      const double X = bar.length * i / 100.0, t = bar_sample_fractions()[k] * mode.period(), T = bar_sample_fractions()[k] * large_mode.period();
      worst = std::max({worst, std::abs(tiny.velocity(X, int(k)) - mode.velocity(X, t)) / mode.velocity_amplitude(),
                        std::abs(tiny.stress(X, int(k)) - mode.stress(X, t)) / (mode.impedance() * mode.velocity_amplitude())});
      change = std::max(change, std::abs(fine.velocity(X, int(k)) - coarse.velocity(X, int(k))) / large_mode.velocity_amplitude());
      nonlinear = std::max(nonlinear, std::abs(fine.velocity(X, int(k)) - large_mode.velocity(X, T)) / large_mode.velocity_amplitude());
    }
  double smallest = 1e300;
  for (std::size_t k = 0; k < runs.cases.size(); ++k)
    if (runs.cases[k].group == Group::bar && runs.cases[k].large && !runs.results[k].failed) smallest = std::min(smallest, runs.results[k].velocity_error);
  list.push_back({"The finite-strain reference (512 cells) is the exact first mode at small amplitude (V/ω = 1e-6 L)",
                  "largest difference of v/V and σ/ZV at the sample times < 1e-4", {}, true});
  list.back().add("T/4, T/2, 3T/4, T; 101 points", worst, worst < 1e-4);
  list.push_back({"The large-amplitude reference (" + std::to_string(reference_cells) + " cells) has converged",
                  "largest change of v/V on halving its cells < 0.1 x the smallest MPM error (" + number(smallest, "%.3g") + ")", {}, true});
  list.back().add("V/ω = 0.05 L", change, change < 0.1 * smallest);
  list.push_back({"At V/ω = 0.05 L the finite-strain solution differs from the linear mode (the reference is needed)",
                  "largest |v - v_linear|/V at the sample times > 10 x the reference's own change", {}, false});
  list.back().add("V/ω = 0.05 L", nonlinear, nonlinear > 10.0 * change);
  return list;
}

/// A ratio of two runs' measures over every mesh of the series `a` and `b` share, decided by the one rule: within
/// (low, high) beyond the ratio's band (mpm::judge_within), stopped where a run stopped.
inline void add_ratios(DomainClaim& claim, const Runs& runs, const Case& a, const Case& b, double SmoothResult::*measure_a,
                       double SmoothResult::*measure_b, double low, double high) {
  for (int n : runs.meshes(a)) {
    Case x = a, y = b;
    x.cells = y.cells = n;
    if (!runs.has(y)) continue;
    const mpm::Measured r = mpm::ratio(smooth_measured(runs.at(x), measure_a), smooth_measured(runs.at(y), measure_b));
    const mpm::Outcome outcome = mpm::judge_within(r, low, high);
    claim.add(where(x) + (outcome == mpm::Outcome::stopped ? ": a run stopped" : ", ratio ± " + number(r.band, "%.2g")), r.value, outcome);
  }
}

/// The predictor-corrector dissipates energy (E(T)/E(0) < 0.999), forward Euler conserves it (|E(T)/E(0) - 1| < 1e-3), on
/// every run of the series `paper` with `integrator`, by the one rule: the ratio's band its change over the last step.
inline DomainClaim energy_claim(const Runs& runs, const std::vector<Case>& paper, const std::string& integrator) {
  const bool npc = integrator == "npc";
  DomainClaim claim{npc ? "The predictor-corrector dissipates energy" : "Forward Euler conserves energy",
                    npc ? "kinetic + strain energy at T over t = 0 < 0.999 beyond its band (its change over the last step)"
                        : "|energy at T over t = 0 - 1| < 1e-3 beyond its band (its change over the last step)",
                    {}, false};
  for (const Case& p : paper) {
    if (p.method.integrator != integrator) continue;
    for (int n : runs.meshes(p)) {
      Case c = p;
      c.cells = n;
      const SmoothResult& r = runs.at(c);
      const mpm::Measured m{r.energy_ratio, r.energy_band, r.failed ? mpm::Ending::stopped : mpm::Ending::done};
      claim.add(where(c) + (r.failed ? ": stopped" : " ± " + number(m.band, "%.2g")), m.value,
                npc ? mpm::judge(m, mpm::Side::below, mpm::threshold(0.999)) : mpm::judge_within(m, 1.0 - 1e-3, 1.0 + 1e-3));
    }
  }
  return claim;
}

/// The small amplitude: convergence bounds, orders, the time step's share, FE against NPC, energy.
inline std::vector<DomainClaim> small_bar_claims(const Runs& runs) {
  const auto paper = cases_of(runs, Group::bar, false, true, false, true);
  std::vector<DomainClaim> list;
  list = convergence_claims(runs, paper, "Bound: without grid crossing the method converges (small amplitude, every series)", 16, 0.35, true);
  DomainClaim first{"The velocity error is first order in h at fixed CFL, compared at the sample times", "velocity order (16 cells up) in [0.8, 1.3] beyond 2 s.e.", {}, false};
  DomainClaim own{"Compared at the time it approximates, t + dt/2, forward Euler's velocity is second order", "velocity order at t + dt/2 >= 1.7 beyond 2 s.e.", {}, false};
  DomainClaim npc{"The predictor-corrector's velocity (Eq. 32, γ = 1/2) is first order at t, as at any shift of t", "velocity order in [0.8, 1.3] beyond 2 s.e.", {}, false};
  for (const Case& p : paper) {
    const OrderFit v = order(runs, p, &SmoothResult::velocity_error, 16);
    first.add(where(p) + ": " + v.text(), v.order, mpm::judge_within(v.measured(), 0.8, 1.3));
    if (p.method.integrator == "fe") {
      const OrderFit o = order(runs, p, &SmoothResult::velocity_error_own_time, 16);
      own.add(where(p) + ": " + o.text(), o.order, mpm::judge(o.measured(), mpm::Side::above, mpm::threshold(1.7)));
    } else {
      npc.add(where(p) + ": " + v.text(), v.order, mpm::judge_within(v.measured(), 0.8, 1.3));
    }
  }
  list.insert(list.end(), {first, own, npc});
  DomainClaim cfl{"The velocity error is set by the time step: it falls about 5x from CFL 0.5 to 0.1", "error at CFL 0.5 / at CFL 0.1 in [3.5, 6.5]", {}, false};
  DomainClaim stress{"Forward Euler's stress error at 2 particles per cell is over 10x its error at 1", "σ error at 2 ppc / at 1 ppc > 10", {}, false};
  DomainClaim better{"The predictor-corrector is more accurate than forward Euler on smooth data, velocities compared at the sample times",
                     "v error NPC / FE < 1, on every mesh, ppc and CFL", {}, false};
  DomainClaim better_own{"... and with forward Euler's velocity compared at t + dt/2, the time it approximates", "v error NPC (at t) / FE (at t + dt/2) < 1", {}, false};
  for (const Case& p : paper) {
    if (p.cfl == 0.5) add_ratios(cfl, runs, p, bar_case(false, p.method, p.ppc, 0.1), &SmoothResult::velocity_error, &SmoothResult::velocity_error, 3.5, 6.5);
    if (p.method.integrator == "fe" && p.ppc == 2)
      add_ratios(stress, runs, p, bar_case(false, p.method, 1, p.cfl), &SmoothResult::stress_error, &SmoothResult::stress_error, 10.0, HUGE_VAL);
    if (p.method.integrator != "npc") continue;
    const Case fe = bar_case(false, {p.method.shape, "fe"}, p.ppc, p.cfl);
    add_ratios(better, runs, p, fe, &SmoothResult::velocity_error, &SmoothResult::velocity_error, 0.0, 1.0);
    add_ratios(better_own, runs, p, fe, &SmoothResult::velocity_error, &SmoothResult::velocity_error_own_time, 0.0, 1.0);
  }
  DomainClaim fe_stress1{"Forward Euler's stress is second order at 1 particle per cell", "σ order >= 1.7 beyond 2 s.e.", {}, false};
  DomainClaim fe_stress2{"Forward Euler's stress is first order at 2 particles per cell", "σ order <= 1.3 beyond 2 s.e.", {}, false};
  for (const Case& p : paper)
    if (p.method.integrator == "fe") {
      const OrderFit s = order(runs, p, &SmoothResult::stress_error, 16);
      (p.ppc == 1 ? fe_stress1 : fe_stress2)
          .add(where(p) + ": " + s.text(), s.order, s.against(p.ppc == 1 ? mpm::Side::above : mpm::Side::below, p.ppc == 1 ? 1.7 : 1.3));
    }
  list.insert(list.end(), {cfl, fe_stress1, fe_stress2, stress, better, better_own, energy_claim(runs, paper, "npc"), energy_claim(runs, paper, "fe")});
  for (auto& claim : convergence_claims(runs, cases_of(runs, Group::bar, false, false, true, true),
                                        "Today's baselines converge as the bound above asks (small amplitude, 16-128 cells)", 16, 0.35, false))
    list.push_back(claim);
  return list;
}

/// The large amplitude: where each method converges, and where runs stop.
inline std::vector<DomainClaim> large_bar_claims(const Runs& runs) {
  std::vector<Case> patterns = cases_of(runs, Group::bar, true, true, false, true), baselines = cases_of(runs, Group::bar, true, false, true, true);
  patterns.insert(patterns.end(), baselines.begin(), baselines.end());
  const std::string statement = "At large amplitude, where particles cross cells, the method keeps converging (the paper's methods and today's baselines)";
  DomainClaim orders{statement + ": the velocity order lies above 0.5", "velocity order from 16 cells > 0.5 beyond 2 standard errors", {}, false};
  DomainClaim falls{statement + ": the velocity error at the finest mesh lies below its error at 16 cells",
                    "velocity error at the finest mesh / at 16 cells < 1 beyond its band", {}, false};
  for (const Case& p : patterns) {
    const SeriesData v = series(runs, p, &SmoothResult::velocity_error);
    add_order(orders, where(p), v, fit_series(v, 16), mpm::Side::above, 0.5);
    add_fall(falls, where(p), runs, p, &SmoothResult::velocity_error, 16, 1.0);
  }
  std::vector<DomainClaim> list{orders, falls};
  list.push_back(finish_claim(runs, cases_of(runs, Group::bar, true, true, true, false), "vibrating bar, large amplitude, CFL 0.5"));
  return list;
}

}  // namespace verification::smooth
