// The experiments that decide the Dyka bar's claims rather than score them (make studies): LME's gamma on a mesh
// without crossing, one in transition and one with crossing; the temporal order alone, the step refined at fixed h;
// grid crossing isolated, the initial speed swept on one mesh; and point A's RMS beside the all-particle space-time
// norm in the convergence table. The runs are dyka_cases.hpp's experiment_cases(); each claim is evaluated on every
// run of its experiment by the one rule.
#pragma once
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "verification/dyka_data.hpp"
#include "verification/onset.hpp"

namespace verification::dyka {

/// A run's score divided by its own |v0| (the amplitude sweep's runs start at other speeds than 5 m/s).
inline mpm::Measured rms_over_own_v0(const DykaResult& run) {
  mpm::Measured m = rms_measured(run);
  if (!run.failed) m.value *= speed_v0 / std::abs(run.v0), m.band *= speed_v0 / std::abs(run.v0);
  return m;
}
/// The all-particle space-time norm (DykaResult::space_time) / |v0|, with the band of its even and odd samples.
inline mpm::Measured space_time_measured(const DykaResult& run) {
  mpm::Measured m = rms_measured(run);
  if (!run.failed)
    m.value = run.space_time / std::abs(run.v0),
    m.band = mpm::band_of_halves(run.space_time, run.space_time_even, run.space_time_odd) / std::abs(run.v0);
  return m;
}
/// The plateau mean shortfall (DykaResult::mean_shortfall, / v0), the damping, with the band of its sampling.
inline mpm::Measured shortfall_measured(const DykaResult& run) {
  mpm::Measured m = rms_measured(run);
  if (!run.failed)
    m.value = run.mean_shortfall, m.band = mpm::band_of_halves(run.mean_shortfall, run.even.mean_shortfall, run.odd.mean_shortfall);
  return m;
}
/// "0.0843 ± 0.0012", or the run's stop.
inline std::string measured_text(const mpm::Measured& m, const DykaResult& run) {
  return run.failed ? stopped_text(run) : text(m.value, "%.4g") + " ± " + text(m.band, "%.2g");
}
/// A sample "a on `side` of b" by the one rule on the two measures themselves (not their ratio: a shortfall may be 0):
/// a failed run beside a finished one is compared (rule 4), two failed runs or a stopped one are not.
inline void add_compared(DomainClaim& claim, const std::string& where, const DykaResult& a, const mpm::Measured& ma,
                         const DykaResult& b, const mpm::Measured& mb, mpm::Side side) {
  const mpm::Outcome outcome = mpm::judge(ma, side, mb);
  if (outcome == mpm::Outcome::stopped)
    claim.add(where + ": " + not_compared_text(a, "it", b, "the other"), std::nan(""), outcome);
  else
    claim.add(where + ": " + measured_text(ma, a) + " against " + measured_text(mb, b), ma.value, outcome);
}

/// dyka_gamma_meshes.csv and the claims of Fig. 8 on the three meshes.
inline Section gamma_meshes_section(const Runs& runs) {
  std::ofstream out = csv(runs, "dyka_gamma_meshes.csv", "cells,integrator,gamma,rms_over_v0,rms_band_over_v0,space_time_over_v0,"
                                                          "ringing,ringing_band,shortfall,shortfall_band,ending");
  DomainClaim best{"Fig. 8 on more meshes: γ = 3 is LME's most accurate γ",
                   "RMS at γ = 3 below the smallest RMS of the other γ (0.8-5) beyond their bands, per mesh and integrator", {}, false};
  DomainClaim flat{"Above γ = 2 the choice of γ moves the RMS by less than 1 %",
                   "100 (largest - smallest) / smallest RMS over γ = 2, 3, 4, 5 < 1 % beyond its band", {}, false};
  DomainClaim rings{"Small γ adds ringing: the ringing at γ <= 1.5 exceeds γ = 3's",
                    "ringing (total variation of v_A over the exact one's) at γ above its value at γ = 3 beyond their bands", {}, false};
  DomainClaim damps{"Small γ damps: the plateau mean shortfall at γ <= 1.5 exceeds γ = 3's",
                    "the mean of v_A's shortfall below the exact level on the plateaus' middle halves, / v0 (the amplitude lost; "
                    "ringing averages out), above its value at γ = 3 beyond their bands", {}, false};
  for (int cells : gamma_meshes)
    for (const auto& integrator : integrators) {
      const std::string mesh = std::to_string(cells) + " cells (" + band_of(cells) + "), " + integrator;
      const DykaResult& three = runs.at(gamma_mesh_name(integrator, 3.0, cells));
      std::vector<mpm::Measured> others;
      std::vector<double> other_gammas;
      std::vector<const DykaResult*> upper;
      for (double gamma : gammas) {
        const DykaResult& run = runs.at(gamma_mesh_name(integrator, gamma, cells));
        const mpm::Measured rms = rms_measured(run), ringing = ringing_measured(run), deficit = shortfall_measured(run);
        out << cells << "," << integrator << "," << gamma << "," << rms.value << "," << rms.band << "," << run.space_time / speed_v0 << ","
            << ringing.value << "," << ringing.band << "," << deficit.value << "," << deficit.band << "," << ending(run) << "\n";
        if (gamma != 3.0) others.push_back(rms), other_gammas.push_back(gamma);
        if (gamma >= 2.0) upper.push_back(&run);
        if (gamma > 1.5) continue;
        const std::string where = mesh + ", γ " + text(gamma) + " against 3";
        add_compared(rings, where, run, ringing, three, ringing_measured(three), mpm::Side::above);
        add_compared(damps, where, run, deficit, three, shortfall_measured(three), mpm::Side::above);
      }
      const BestOfGroups b = judge_best({rms_measured(three)}, others);
      if (b.outcome == mpm::Outcome::stopped)
        best.add(mesh + ": a run stopped (" + (three.failed ? stopped_text(three) : "every other γ") + ")", std::nan(""), b.outcome);
      else
        best.add(mesh + ": γ 3 " + measured_text(rms_measured(three), three) + ", best other γ " + text(other_gammas[b.other]) + " " +
                     text(others[b.other].value, "%.4g"), rms_measured(three).value, b.outcome);
      const mpm::Measured spread = rms_spread(upper);
      flat.add(mesh + ": " + (spread.ending == mpm::Ending::stopped ? "a run stopped" : text(spread.value, "%.3g") + " % ± " + text(spread.band, "%.2g")),
               spread.value, mpm::judge(spread, mpm::Side::below, mpm::threshold(1.0)));
    }
  return {"LME's γ on three meshes (`dyka_gamma_meshes`)",
          "Fig. 8's γ = 0.8-5 on " + std::to_string(gamma_meshes[0]) + ", " + std::to_string(gamma_meshes[1]) + " and " +
              std::to_string(gamma_meshes[2]) + " cells (the bands without crossing, transition, crossing of paper/08), both integrators, "
              "CFL 0.5: accuracy (RMS of v_A), ringing (total variation over the exact one's) and damping (the plateau mean shortfall: "
              "the amplitude lost, where ringing about the exact level averages out), each with the band of its even and odd samples "
              "(data/dyka_gamma_meshes.csv). γ under this project's rule β = γ/h² (the paper's, A&O06); the authors' code's γ = 3 "
              "is β h² = 2.29 at a cell centre of their 1D strip (paper/09, \"The authors' beta\"), between this sweep's 2 and 3.",
          {best, flat, rings, damps}};
}

/// The difference of every particle's v (or sigma) at the end time from the reference run's: RMS over the particles,
/// / |v0| (or / rho c |v0|); NaN when either stopped.
inline double end_difference(const DykaResult& run, const DykaResult& reference, bool velocity) {
  if (run.failed || reference.failed) return std::nan("");
  const std::vector<double>&a = velocity ? run.final_velocity : run.final_stress, &b = velocity ? reference.final_velocity : reference.final_stress;
  const double scale = std::abs(run.v0) * (velocity ? 1.0 : std::sqrt(200.0e9 * 7833.0));
  return mpm::rms_error(a, b) / scale;
}

/// x = (1 - gamma) (c/h)^2 dt T, gamma = 1/2: Eq. (32) leaves the highest mode that linear shapes at 1 ppc carry
/// (omega_max = c/h, paper/10_integrator_analysis.md, "The highest mode") e^-x of its energy over the Dyka run ("Spectral
/// radius and damping"), dt = CFL h / c.
inline double damped_exponent(int cells, double cfl) {
  const double c = std::sqrt(200.0e9 / 7833.0), h = 0.1333 / cells, omega = c / h;
  return 0.5 * omega * omega * (cfl * h / c) * 2.0e-4;
}

/// The fitted temporal order of `shape` + `integrator` on `cells` (error ~ C dt^order over temporal_cfls), of v or sigma.
inline OrderFit temporal_fit(const Runs& runs, const std::string& shape, const std::string& integrator, int cells, bool velocity) {
  const DykaResult& reference = runs.at(temporal_name(shape, integrator, cells, temporal_reference_cfl));
  std::vector<int> steps;
  std::vector<double> error;
  for (double cfl : temporal_cfls) {
    const DykaResult& run = runs.at(temporal_name(shape, integrator, cells, cfl));
    steps.push_back(int(run.steps)), error.push_back(end_difference(run, reference, velocity));
  }
  return fit_order(steps, error);
}

/// dyka_temporal.csv, dyka_temporal_orders.csv and the claims of the temporal order.
inline Section temporal_section(const Runs& runs) {
  std::ofstream out = csv(runs, "dyka_temporal.csv", "cells,shape,integrator,cfl,steps,velocity_difference_over_v0,stress_difference_over_z_v0,ending");
  std::ofstream orders = csv(runs, "dyka_temporal_orders.csv", "cells,shape,integrator,field,order,standard_error,points");
  const std::string range = "CFL " + text(temporal_cfls.front()) + "-" + text(temporal_cfls.back());
  DomainClaim fe{"Forward Euler converges in time at least at first order at fixed h (paper/10: first order at t, second at t + dt/2)",
                 "fitted order of v's difference at the end time, " + range + ", above 0.9 beyond 2 standard errors", {}, false};
  DomainClaim npc{"Over CFL " + text(temporal_cfls.front()) + "-" + text(temporal_cfls.back()) + " Eq. (32)'s step error at fixed h "
                      "falls at its asymptotic first order (paper/10: first order in the velocity)",
                  "fitted order of v's difference at the end time, " + range + ", within [0.9, 1.1] beyond 2 standard errors", {}, false};
  std::string table = "| cells | shape | integrator | order of v | order of σ | v's local order, CFL " + text(temporal_cfls.end()[-2]) + " to " +
                      text(temporal_cfls.back()) + " |\n|---|---|---|---|---|---|\n";
  for (int cells : temporal_cells)
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators) {
        const DykaResult& reference = runs.at(temporal_name(shape, integrator, cells, temporal_reference_cfl));
        for (double cfl : with_reference(temporal_cfls)) {
          const DykaResult& run = runs.at(temporal_name(shape, integrator, cells, cfl));
          out << cells << "," << shape << "," << integrator << "," << cfl << "," << run.steps << "," << end_difference(run, reference, true) << ","
              << end_difference(run, reference, false) << "," << ending(run) << "\n";
        }
        const OrderFit v = temporal_fit(runs, shape, integrator, cells, true), sigma = temporal_fit(runs, shape, integrator, cells, false);
        for (const auto& [field, fit] : {std::pair<const char*, OrderFit>{"v", v}, {"sigma", sigma}})
          orders << cells << "," << shape << "," << integrator << "," << field << "," << fit.order << "," << fit.standard_error << "," << fit.points << "\n";
        const DykaResult &coarser = runs.at(temporal_name(shape, integrator, cells, temporal_cfls.end()[-2])),
                         &finest = runs.at(temporal_name(shape, integrator, cells, temporal_cfls.back()));
        const double local = std::log(end_difference(coarser, reference, true) / end_difference(finest, reference, true)) /
                             std::log(double(finest.steps) / double(coarser.steps));
        table += "| " + std::to_string(cells) + " | " + shape + " | " + integrator + " | " + order_text(v, "steps") + " | " + order_text(sigma, "steps") +
                 " | " + text(local, "%.2f") + " |\n";
        DomainClaim& claim = integrator == "fe" ? fe : npc;
        const double high = integrator == "fe" ? HUGE_VAL : 1.1;
        const std::string where = shape + ", " + std::to_string(cells) + " cells";
        if (v.fitted())
          claim.add(where + ": order " + order_text(v, "steps"), v.order,
                    mpm::judge_within({v.order, 2.0 * v.standard_error, mpm::Ending::done}, 0.9, high));
        else
          claim.add_stopped(where + ": no fit (" + order_text(v, "steps") + ")");
      }
  return {"The temporal order alone: the step refined at fixed h (`dyka_temporal`)",
          "Each shape and integrator on " + std::to_string(temporal_cells[0]) + " and " + std::to_string(temporal_cells[1]) +
              " cells at CFL " + text(temporal_cfls.front()) + " to " + text(temporal_cfls.back()) + " (halved each time), every particle's v "
              "and σ at the end time (200 µs, where every run lands) against the same method at CFL " + text(temporal_reference_cfl) +
              " (" + text(temporal_cfls.back() / temporal_reference_cfl, "%g") + " times finer than the finest): the RMS over the particles of the difference, / |v0| (σ: / ρ c |v0|), fitted as C dt^p "
              "(GSL least squares on the logs against the steps taken, ± the slope's standard error; data/dyka_temporal.csv, "
              "data/dyka_temporal_orders.csv). The mesh is fixed, so the space error is the same in every run of a row: what is left "
              "is the integrator's own. Eq. (32) removes the fraction (1 - γ) Ω² of a mode's energy per step (paper/10, Ω = ω dt): over "
              "the run the highest mode linear shapes carry at 1 ppc (ω = c/h, paper/10) keeps e^-x of it, x = (1 - γ) (c/h)² dt T, which at the finest CFL is " +
              text(damped_exponent(temporal_cells[0], temporal_cfls.back()), "%.2g") + " on " + std::to_string(temporal_cells[0]) + " cells and " +
              text(damped_exponent(temporal_cells[1], temporal_cfls.back()), "%.2g") + " on " + std::to_string(temporal_cells[1]) + " (γ = 1/2): every "
              "refinement of the range still lets through modes that a coarser step damps away, and the jump of the Dyka data puts energy "
              "in all of them, so the range is short of Eq. (32)'s asymptotic order; the local order of the finest pair (against a "
              "reference " + text(temporal_cfls.back() / temporal_reference_cfl, "%g") + " times finer still) shows where it stands.\n\n" + table,
          {fe, npc}};
}

/// The onset of `shape` + `integrator` on the amplitude sweep: the first U/h at which RMS / |v0| exceeds twice its value
/// at the smallest U/h, or the U/h where a run stopped first.
inline Onset amplitude_onset(const Runs& runs, const std::string& shape, const std::string& integrator) {
  const double base = rms_over_own_v0(runs.at(amplitude_name(shape, integrator, amplitude_ratios.front()))).value;
  for (double ratio : amplitude_ratios) {
    const DykaResult& run = runs.at(amplitude_name(shape, integrator, ratio));
    if (run.failed) return {ratio, true};
    if (!(rms_over_own_v0(run).value <= 2.0 * base)) return {ratio, false};
  }
  return {};
}

/// dyka_amplitude.csv and the claims of grid crossing isolated on the Dyka bar.
inline Section amplitude_section(const Runs& runs) {
  std::ofstream out = csv(runs, "dyka_amplitude.csv", "shape,integrator,amplitude_over_h,v0,rms_over_v0,rms_band_over_v0,space_time_over_v0,"
                                                       "ringing,shortfall,ending,end_time");
  DomainClaim later_than{"Dyka bar, grid crossing isolated: uGIMP and LME leave their no-crossing error later than linear shape functions",
                         "onset U/h (the first U/h with RMS/|v0| over twice its value at U/h = " + text(amplitude_ratios.front()) +
                             ") later than linear's with the same integrator; the same U/h: undecided; a run stopped first: stopped", {}, false};
  DomainClaim floor{"Before the particle next to the free end reaches a cell face the error changes by less than 1 % with the amplitude",
                    "RMS/|v0| at U/h = 0.25 over its value at U/h = " + text(amplitude_ratios.front()) + " within [0.99, 1.01] beyond "
                    "its band (uGIMP's domain edges start on the nodes: they cross node lines from the first motion)", {}, false};
  DomainClaim finishes{"Dyka bar: uGIMP and LME approximate the solution where linear shape functions stop",
                       "at each U/h where linear stopped (same integrator), the run reaches its end time better than a flat line (holds), "
                       "no better (fails) or stops (fails): the ending is what this claim counts, as in \"Every run reaches its end "
                       "time\"", {}, false};
  std::string table = "| shape | integrator | RMS/\\|v0\\| at U/h = " + text(amplitude_ratios.front()) + " | onset U/h |\n|---|---|---|---|\n";
  std::map<std::string, Onset> onsets;
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators) {
      for (double ratio : amplitude_ratios) {
        const DykaResult& run = runs.at(amplitude_name(shape, integrator, ratio));
        const mpm::Measured m = rms_over_own_v0(run);
        out << shape << "," << integrator << "," << ratio << "," << run.v0 << "," << m.value << "," << m.band << ","
            << (run.failed ? std::nan("") : run.space_time / std::abs(run.v0)) << "," << (run.failed ? std::nan("") : run.ringing) << ","
            << (run.failed ? std::nan("") : run.mean_shortfall) << "," << ending(run) << "," << (run.time.empty() ? 0.0 : run.time.back()) << "\n";
      }
      const Onset o = onsets[shape + integrator] = amplitude_onset(runs, shape, integrator);
      const DykaResult &small = runs.at(amplitude_name(shape, integrator, amplitude_ratios.front())), &quarter = runs.at(amplitude_name(shape, integrator, 0.25));
      table += "| " + shape + " | " + integrator + " | " + measured_text(rms_over_own_v0(small), small) + " | " + onset_text(o, amplitude_ratios.back()) + " |\n";
      const mpm::Measured r = mpm::ratio(rms_over_own_v0(quarter), rms_over_own_v0(small));
      const std::string where = shape + " " + integrator;
      if (r.ending == mpm::Ending::stopped)
        floor.add(where + ": " + not_compared_text(quarter, "U/h 0.25", small, "U/h 0.01"), std::nan(""), mpm::Outcome::stopped);
      else
        floor.add(where + ": " + text(r.value, "%.4f") + " ± " + text(r.band, "%.2g"), r.value, mpm::judge_within(r, 0.99, 1.01));
    }
  for (const auto& shape : {"ugimp", "lme"})
    for (const auto& integrator : integrators) {
      const Onset &mine = onsets[shape + integrator], &linear = onsets["linear" + integrator];
      later_than.add(std::string(shape) + " " + integrator + ": " + onset_text(mine, amplitude_ratios.back()) + " (linear " +
                         onset_text(linear, amplitude_ratios.back()) + ")", mine.ratio, later(mine, linear));
      for (double ratio : amplitude_ratios) {
        if (!runs.at(amplitude_name("linear", integrator, ratio)).failed) continue;
        const DykaResult& run = runs.at(amplitude_name(shape, integrator, ratio));
        const std::string e = ending(run);
        finishes.add(std::string(shape) + " " + integrator + ", U/h " + text(ratio) + ": " + (run.failed ? stopped_text(run) : e == "failed" ?
                         "failed (RMS/|v0| " + text(rms_over_own_v0(run).value, "%.3f") + ", no smaller than a flat line's)" :
                         "RMS/|v0| " + text(rms_over_own_v0(run).value, "%.4f")), run.failed ? std::nan("") : rms_over_own_v0(run).value, e == "done");
      }
    }
  return {"Grid crossing isolated on the Dyka bar: the initial speed swept at " + std::to_string(amplitude_cells) + " cells (`dyka_amplitude`)",
          "The loaded quarter's speed |v0| set so that the free end's largest displacement U = |v0| (L/4) / c is U/h = " +
              [] { std::string s; for (double r : amplitude_ratios) s += (s.empty() ? "" : ", ") + text(r); return s; }() +
              " of a cell (|v0| " + text(amplitude_speed(amplitude_ratios.front()), "%.3g") + " to " + text(amplitude_speed(amplitude_ratios.back()), "%.3g") +
              " m/s; the strain |v0| / 2c, doubled where the pulse reflects at the fixed end, stays at most " +
              text(100.0 * amplitude_speed(amplitude_ratios.back()) / std::sqrt(200.0e9 / 7833.0), "%.3g") + " %), each shape and integrator, CFL 0.5, RMS of v_A / |v0| (data/dyka_amplitude.csv). The particle next to the free end "
              "reaches a cell face at U/h = 0.5. Onset: the first U/h whose RMS/|v0| exceeds twice its value at U/h = " + text(amplitude_ratios.front()) +
              " (the rule of the smooth bar's crossing sweep), or the U/h where a run stopped first.\n\n" + table,
          {later_than, finishes, floor}};
}

/// Point A's RMS beside the all-particle space-time norm over the sweep: the fitted orders by both, and the claims of
/// Fig. 6 that rest on them (the error falls without crossing; crossing spoils it at the finest mesh; uGIMP and LME
/// withstand it better than linear) evaluated by each, with the verdicts that change named.
inline Section space_time_section(const Runs& runs) {
  const auto negligible = band_cells("negligible"), transition = band_cells("transition"), crossing = band_cells("crossing");
  auto st = [](const DykaResult& run) { return run.space_time; };
  std::string table = "| shape | integrator | negligible: point A | negligible: all particles | transition: point A | transition: all particles |\n"
                      "|---|---|---|---|---|---|\n";
  DomainClaim orders[2] = {{"Without grid crossing the error falls under refinement: fitted order > 0 (point A)", "fitted order over " +
                                cells_text(negligible) + " cells > 0 beyond 2 standard errors, point A's RMS", {}, false},
                           {"Without grid crossing the error falls under refinement: fitted order > 0 (all particles)", "the same, on the "
                                "all-particle space-time norm", {}, false}};
  const int fine = sweep_cells.back(), coarse = transition.back();
  DomainClaim spoils[2] = {{"Grid crossing spoils the solution: the error at " + std::to_string(fine) + " cells exceeds the error at " +
                                std::to_string(coarse) + " (point A)", "ratio > 1 beyond its band, point A's RMS", {}, false},
                           {"Grid crossing spoils the solution: the error at " + std::to_string(fine) + " cells exceeds the error at " +
                                std::to_string(coarse) + " (all particles)", "ratio > 1 beyond its band, the space-time norm", {}, false}};
  DomainClaim better[2] = {{"uGIMP and LME withstand grid crossing better than linear shape functions, " + std::to_string(fine) + " cells (point A)",
                            "RMS_shape / RMS_linear < 1 beyond its band, point A's RMS", {}, false},
                           {"uGIMP and LME withstand grid crossing better than linear shape functions, " + std::to_string(fine) + " cells (all particles)",
                            "the same ratio on the space-time norm", {}, false}};
  std::ofstream out = csv(runs, "dyka_space_time_orders.csv", "shape,integrator,band,measure,order,standard_error,meshes");
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators) {
      for (const auto& [band, cells] : {std::pair<const char*, std::vector<int>>{"negligible", negligible}, {"transition", transition}})
        for (const bool all : {false, true}) {
          const OrderFit fit = all ? fit_runs(runs, cells, shape, integrator, st) : fit_runs(runs, cells, shape, integrator);
          out << shape << "," << integrator << "," << band << "," << (all ? "all_particles" : "point_a") << "," << fit.order << ","
              << fit.standard_error << "," << fit.points << "\n";
        }
      table += "| " + shape + " | " + integrator + " | " + order_text(fit_runs(runs, negligible, shape, integrator)) + " | " +
               order_text(fit_runs(runs, negligible, shape, integrator, st)) + " | " + order_text(fit_runs(runs, transition, shape, integrator)) + " | " +
               order_text(fit_runs(runs, transition, shape, integrator, st)) + " |\n";
      const std::string where = shape + " " + integrator;
      add_order(orders[0], where, fit_runs(runs, negligible, shape, integrator), 0.0);
      add_order(orders[1], where, fit_runs(runs, negligible, shape, integrator, st), 0.0);
      const auto &f = runs.at(sweep_name(shape, integrator, fine)), &c = runs.at(sweep_name(shape, integrator, coarse));
      add_pair(spoils[0], where, "", f, std::to_string(fine), rms_measured(f), c, std::to_string(coarse), rms_measured(c), mpm::Side::above);
      add_pair(spoils[1], where, "", f, std::to_string(fine), space_time_measured(f), c, std::to_string(coarse), space_time_measured(c), mpm::Side::above);
      if (shape == "linear") continue;
      const auto& linear = runs.at(sweep_name("linear", integrator, fine));
      add_pair(better[0], where, "", f, shape, rms_measured(f), linear, "linear", rms_measured(linear), mpm::Side::below);
      add_pair(better[1], where, "", f, shape, space_time_measured(f), linear, "linear", space_time_measured(linear), mpm::Side::below);
    }
  std::string changed;
  for (const auto* pair : {orders, spoils, better})
    add_changed_verdicts(changed, pair[1].statement.substr(0, pair[1].statement.find(" (all")), pair[0], pair[1]);
  return {"Point A against every particle: the all-particle space-time norm (`dyka_space_time`)",
          "The RMS of v_p - v(X_p, t) over every particle and every step (the exact solution at each particle's reference position), "
          "/ |v0|, beside point A's RMS (data/dyka_sweep.csv, column space_time_over_v0); fitted orders of each (± the slope's "
          "standard error; data/dyka_space_time_orders.csv):\n\n" + table + "\nVerdicts that change from point A to all particles: " + (changed.empty() ? "none" : changed) + ".",
          {orders[0], orders[1], spoils[0], spoils[1], better[0], better[1]}};
}

}  // namespace verification::dyka
