// The data files of the Dyka suite (CSV, one per figure or table), written from its runs.
#pragma once
#include <cmath>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "mpm/analysis/verdict.hpp"

#include "verification/dyka_report.hpp"

namespace verification::dyka {

inline std::ofstream csv(const Runs& runs, const std::string& file, const std::string& header) {
  std::ofstream out(runs.folder + "/" + file);
  out << std::setprecision(8) << header << "\n";
  return out;
}
inline const char* status(const DykaResult& run) { return run.failed ? "failed" : "ok"; }
/// The run's ending by the one rule (mpm/analysis/verdict.hpp): stopped, failed (RMS no smaller than a flat line's), done.
inline const char* ending(const DykaResult& run) {
  return run.failed ? "stopped" : mpm::score_ending(run.rms, run.flat_rms) == mpm::Ending::failed ? "failed" : "done";
}
/// The band of RMS / v0 from its even and odd rows (mpm::band_of_halves); NaN for a stopped run.
inline double rms_band_over_v0(const DykaResult& run) {
  return run.failed ? std::nan("") : mpm::band_of_halves(run.rms, run.even.rms, run.odd.rms) / speed_v0;
}

/// One row of dyka_sweep.csv for `run`, `shape` + `integrator` on `cells`.
inline void sweep_row(std::ofstream& out, const DykaResult& run, const std::string& shape, const std::string& integrator, int cells) {
  out << shape << "," << integrator << "," << cells << "," << 0.1333 / cells << "," << crossing_ratio(cells) << "," << band_of(cells) << ","
      << run.rms << "," << run.rms / speed_v0 << "," << run.largest_speed / speed_v0 << "," << run.wall_seconds << "," << run.steps << ","
      << status(run) << "," << run.rms_own_time / speed_v0 << "," << run.newton_mean << "," << run.newton_max << "," << run.neighbours_mean << ","
      << run.cpu_seconds << "," << run.overshoot << "," << run.undershoot << "," << run.ringing << "," << rms_band_over_v0(run) << ","
      << ending(run) << "," << (run.failed ? std::nan("") : mpm::band_of_halves(run.ringing, run.even.ringing, run.odd.ringing)) << ","
      << (run.failed ? std::nan("") : mpm::band_of_halves(run.overshoot, run.even.overshoot, run.odd.overshoot)) << ","
      << (run.failed ? std::nan("") : mpm::band_of_halves(run.undershoot, run.even.undershoot, run.odd.undershoot)) << ","
      << (run.failed ? std::nan("") : run.space_time / speed_v0) << ","
      << (run.failed ? std::nan("") : mpm::band_of_halves(run.space_time, run.space_time_even, run.space_time_odd) / speed_v0) << "\n";
}

/// dyka_profiles.csv: the profiles' scores (dyka_profiles.hpp) of every run of the sweep at CFL 0.5, one row per run,
/// chosen time and field, each score on every particle and on the even and the odd ones; a run that stopped before a
/// chosen time has no row there.
inline void write_profiles(const Runs& runs) {
  std::ofstream out = csv(runs, "dyka_profiles.csv",
                          "shape,integrator,cells,target_time,step_time,field,rms,rms_even,rms_odd,ringing,ringing_even,ringing_odd,"
                          "amplitude,amplitude_even,amplitude_odd,ending");
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators)
      for (int cells : sweep_cells) {
        const DykaResult& run = runs.at(sweep_name(shape, integrator, cells));
        for (const Profile& p : run.failed ? std::vector<Profile>{} : run.profiles)
          for (const bool velocity : {true, false}) {
            const ProfileScores s = velocity ? score_profile(p.velocity, p.exact_velocity) : score_profile(p.stress, p.exact_stress);
            out << shape << "," << integrator << "," << cells << "," << p.target << "," << p.time << "," << (velocity ? "v" : "sigma");
            for (const ProfileScore& score : {s.rms, s.ringing, s.amplitude}) out << "," << score.whole << "," << score.even << "," << score.odd;
            out << "," << ending(run) << "\n";
          }
      }
}

/// dyka_sweep.csv (Fig. 6, the work-precision chart; the smooth suite reads it), dyka_cfl.csv (every CFL) and
/// dyka_sweep_authors.csv (LME under the authors' beta, CFL 0.5, on authors_cells; same columns as dyka_sweep.csv).
inline void write_sweep(const Runs& runs) {
  const std::string columns = "shape,integrator,cells,h,crossing_ratio,band,rms,rms_over_v0,largest_speed_over_v0,wall_seconds,steps,status,"
                              "rms_own_time_over_v0,newton_mean,newton_max,neighbours_mean,cpu_seconds,overshoot,undershoot,ringing,"
                              "rms_band_over_v0,ending,ringing_band,overshoot_band,undershoot_band,space_time_over_v0,space_time_band_over_v0";
  std::ofstream sweep = csv(runs, "dyka_sweep.csv", columns), all = csv(runs, "dyka_cfl.csv", "cfl," + columns);
  std::ofstream authors = csv(runs, "dyka_sweep_authors.csv", columns);
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators) {
      for (int cells : sweep_cells) sweep_row(sweep, runs.at(sweep_name(shape, integrator, cells)), shape, integrator, cells);
      for (const auto& [cells, cfl] : comparison_domain()) {
        all << cfl << ",";
        sweep_row(all, runs.at(sweep_name(shape, integrator, cells, cfl)), shape, integrator, cells);
      }
    }
  for (const auto& integrator : integrators)
    for (int cells : authors_cells)
      sweep_row(authors, runs.at(sweep_name(authors_lme, integrator, cells)), authors_lme, integrator, cells);
  write_profiles(runs);
}

/// dyka_fair.csv: FE against NPC, fairly (the meshes without crossing).
inline void write_fair(const Runs& runs) {
  std::ofstream fair = csv(runs, "dyka_fair.csv", "shape,cells,fe,fe_own_time,npc,npc_average,fe_blend,flip_fraction,energy_fe,energy_npc,"
                                                   "energy_npc_average,energy_fe_blend");
  for (const auto& shape : shapes)
    for (int cells : band_cells("negligible")) {
      const auto &fe = runs.at(sweep_name(shape, "fe", cells)), &npc = runs.at(sweep_name(shape, "npc", cells));
      const auto &average = runs.at(fair_name(shape, "npcavg", cells)), &blend = runs.at(fair_name(shape, "feblend", cells));
      fair << shape << "," << cells << "," << fe.rms / speed_v0 << "," << fe.rms_own_time / speed_v0 << "," << npc.rms / speed_v0 << ","
           << average.rms / speed_v0 << "," << blend.rms / speed_v0 << "," << runs.flip_fraction.at(blend.name) << "," << fe.final_energy_ratio << ","
           << npc.final_energy_ratio << "," << average.final_energy_ratio << "," << blend.final_energy_ratio << "\n";
    }
}

/// dyka_choices.csv: each choice of paper/09_choices.md against its reference run, v_A compared where both sampled the
/// same times (the step follows the solution, Eq. 42, so the times may differ by round-off).
inline void write_choices(const Runs& runs) {
  std::ofstream out = csv(runs, "dyka_choices.csv", "choice,shape,integrator,cells,rms_over_v0,reference_rms_over_v0,steps,reference_steps,end_time,"
                                                    "status,largest_velocity_difference,rms_velocity_difference");
  for (const auto& c : choice_cases) {
    const auto &run = runs.at(c.name()), &reference = runs.at(c.reference_name());
    double largest = std::nan(""), rms = std::nan("");
    bool same_times = !run.failed && !reference.failed && run.time.size() == reference.time.size() && run.time.size() > 1;
    std::vector<double> difference;
    for (size_t n = 0; same_times && n < run.time.size(); ++n) {
      same_times = std::abs(run.time[n] - reference.time[n]) <= 1e-3 * (reference.time[1] - reference.time[0]);
      difference.push_back(run.velocity[n] - reference.velocity[n]);
    }
    if (same_times) {
      largest = 0.0;
      for (double d : difference) largest = std::max(largest, std::abs(d));
      rms = mpm::rms_error(difference, std::vector<double>(difference.size(), 0.0));
    }
    out << c.choice << "," << c.shape << "," << c.integrator << "," << c.cells << "," << (run.failed ? std::nan("") : run.rms / speed_v0) << ","
        << reference.rms / speed_v0 << "," << run.steps << "," << reference.steps << "," << (run.time.empty() ? 0.0 : run.time.back()) << ","
        << status(run) << "," << largest << "," << rms << "\n";
  }
}

/// dyka_energy.csv (10 periods, 40 cells; make studies).
inline void write_energy(const Runs& runs) {
  std::ofstream energy = csv(runs, "dyka_energy.csv", "shape,integrator,cfl,periods,smallest_over_initial,largest_over_initial,final_over_initial,"
                                                      "largest_step_increase_over_initial,steps,status");
  for (const auto& c : energy_cases()) {
    const auto& run = runs.at(c.name());
    energy << c.shape << "," << c.integrator << "," << c.cfl << ",10," << run.smallest_energy_ratio << "," << run.largest_energy_ratio << ","
           << run.final_energy_ratio << "," << run.largest_energy_step_increase << "," << run.steps << "," << status(run) << "\n";
  }
}

/// dyka_gamma.csv (Fig. 8, second panel; make figures).
inline void write_gamma(const Runs& runs) {
  std::ofstream gamma = csv(runs, "dyka_gamma.csv",
                            "gamma,rms_fe,rms_npc,rms_fe_over_v0,rms_npc_over_v0,rms_fe_own_time_over_v0,"
                            "rms_fe_authors_over_v0,rms_npc_authors_over_v0");
  for (double g : gammas) {
    const auto &fe = runs.at(gamma_name("fe", g)), &npc = runs.at(gamma_name("npc", g));
    const auto &fe_authors = runs.at(authors_gamma_name("fe", g)), &npc_authors = runs.at(authors_gamma_name("npc", g));
    gamma << g << "," << fe.rms << "," << npc.rms << "," << fe.rms / speed_v0 << "," << npc.rms / speed_v0 << ","
          << fe.rms_own_time / speed_v0 << "," << fe_authors.rms / speed_v0 << "," << npc_authors.rms / speed_v0
          << "\n";
  }
}

/// dyka_orders.csv: the fitted order per band (NaN: no fit on fewer than 3 finished runs), with its standard error,
/// LME under both beta rules (lme_authors: on the meshes it ran);
/// band "negligible_from_20": the band without crossing less its coarsest mesh.
inline void write_orders(const Runs& runs) {
  std::ofstream out = csv(runs, "dyka_orders.csv", "shape,integrator,band,order,first_cells,last_cells,meshes,standard_error");
  for (const auto& shape : both_rules_shapes)
    for (const auto& integrator : integrators)
      for (const std::string band : {"negligible", "transition", "crossing", "negligible_from_20"}) {
        const auto cells = band == "negligible_from_20" ? without_first(band_cells("negligible")) : band_cells(band);
        const OrderFit fit = fit_runs(runs, cells, shape, integrator);
        out << shape << "," << integrator << "," << band << "," << fit.order << "," << fit.first_cells << "," << fit.last_cells << "," << fit.points << ","
            << fit.standard_error << "\n";
      }
}

}  // namespace verification::dyka
