// The Dyka-bar part of `make figures`: runs every case in parallel on the machine's
// cores, writes the data of each figure as CSV into DATA_DIR, and the report fragment
// REPORT (Markdown) with the paper's claims, the measured numbers and whether each holds.
// Exit code 1 when a hard check (a bound the theory gives) fails.
//
//   build/bin/dyka_suite DATA_DIR REPORT SCENE
//
// Cases: the mesh sweep of Fig. 6 (10 to 2560 cells, paper/08_test_cases.md) for linear, uGIMP and LME
// gamma 3 with forward Euler and the predictor-corrector (also Figs. 7, 9, 10 and the work-
// precision chart); the gamma sweep of Fig. 8 (40 cells); the energy over 10 periods at 40 cells (the runs of
// tests/energy.cpp, into dyka_energy.csv); each choice of paper/09_choices.md switched on its own (dyka_choices.csv),
// for the numbers paper/ quotes.
//
// FE against NPC, fairly (paper/10_integrator_analysis.md): on the meshes without grid crossing, every
// shape also runs the predictor-corrector with the Newmark average (undamped) and forward Euler damped by
// a PIC/FLIP blend (Zhu and Bridson 2005) whose FLIP fraction is set, mesh by mesh, so that linear + FE
// loses the energy that linear + NPC loses by t = 200 us; and forward Euler's velocity is also compared
// with the exact solution at t + dt/2, the time it approximates.
//
// The sweep stops at 2560 cells, the first mesh where particles cross cells at 1 particle per cell
// (crossing ratio 1.27). 5120 cells (ratio 2.5) alone cost 167 of the 228 CPU-seconds of this suite,
// which would put make figures past its 180 s on 2 cores; what it showed, each
// shape's error leaving its no-crossing value, is measured more directly by the smooth suite (error
// against amplitude / h on a fixed mesh, and Fig. 6 at 2 particles per cell). Add 5120 to
// sweep_cells to see it; every claim below follows sweep_cells.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "verification/dyka_case.hpp"
#include "verification/fitted_order.hpp"
#include "verification/parallel.hpp"
#include "mpm/stability.hpp"

namespace {

const std::vector<int> sweep_cells{10, 20, 40, 80, 160, 320, 640, 1280, 2560};
const std::vector<std::string> shapes{"linear", "ugimp", "lme"}, integrators{"fe", "npc"};
const std::vector<double> gammas{0.8, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0};
constexpr double speed_v0 = 5.0;              // |v0|, m/s
constexpr double largest_displacement = 3.298e-5;  // a |v0| / c, m (paper/08_test_cases.md)

struct CaseSpec {
  std::string name;
  std::vector<std::string> overrides;
};

std::string sweep_name(const std::string& shape, const std::string& integrator, int cells) {
  return "dyka_" + shape + "_" + integrator + "_" + std::to_string(cells);
}
/// The fair comparison's variants: "npcavg" (Eq. 23's average), "feblend" (forward Euler with a PIC/FLIP blend).
std::string fair_name(const std::string& shape, const std::string& variant, int cells) {
  return "dyka_" + shape + "_" + variant + "_" + std::to_string(cells);
}
std::vector<std::string> mesh_settings(const std::string& shape, int cells) {
  std::vector<std::string> overrides = verification::shape_settings(shape);
  overrides.insert(overrides.end(), {"grid.cells=[" + std::to_string(cells) + "]", "grid.margin_min=[" + std::to_string(4 + cells / 100) + "]",
                                     "solver.lme_gamma=3.0", "output.snapshots=[]"});
  return overrides;
}
std::vector<int> fair_cells();  // the meshes without grid crossing, below

std::string gamma_name(const std::string& integrator, double gamma) {
  std::ostringstream name;
  name << "dyka_gamma_" << integrator << "_" << gamma;
  return name.str();
}

/// Today's baselines beside the paper's methods (paper/08_test_cases.md, "Today's baselines"): quadratic and cubic
/// B-splines with both integrators, forward Euler with the stress updated last (USL, MUSL), and LME at the small
/// gammas 0.8 and 1.5, on the sweep's meshes 40, 160 and 640; the cubic B-spline also at 2560 cells, the crossing
/// mesh, where the paper's claim about uGIMP and LME is tested. At one particle per cell the quadratic B-spline is
/// uGIMP (the hat averaged over the particle's width h), which the report checks on the meshes it runs; the others
/// stop at 640 cells to keep make figures within its time.
struct Baseline {
  std::string method;
  std::vector<std::string> settings;
  bool at_crossing;
};
const std::vector<Baseline> baselines{
    {"bspline2_fe", {"solver.shape=\"bspline2\"", "solver.integrator=\"fe\""}, false},
    {"bspline2_npc", {"solver.shape=\"bspline2\"", "solver.integrator=\"npc\""}, false},
    {"bspline3_fe", {"solver.shape=\"bspline3\"", "solver.integrator=\"fe\""}, true},
    {"bspline3_npc", {"solver.shape=\"bspline3\"", "solver.integrator=\"npc\""}, true},
    {"linear_usl", {"solver.shape=\"linear\"", "solver.stress_update=\"usl\""}, false},
    {"linear_musl", {"solver.shape=\"linear\"", "solver.stress_update=\"musl\""}, false},
    {"bspline2_usl", {"solver.shape=\"bspline2\"", "solver.stress_update=\"usl\""}, false},
    {"bspline2_musl", {"solver.shape=\"bspline2\"", "solver.stress_update=\"musl\""}, false},
    {"lme0.8_fe", {"solver.shape=\"lme\"", "solver.integrator=\"fe\"", "solver.lme_gamma=0.8"}, false},
    {"lme0.8_npc", {"solver.shape=\"lme\"", "solver.integrator=\"npc\"", "solver.lme_gamma=0.8"}, false},
    {"lme1.5_fe", {"solver.shape=\"lme\"", "solver.integrator=\"fe\"", "solver.lme_gamma=1.5"}, false},
    {"lme1.5_npc", {"solver.shape=\"lme\"", "solver.integrator=\"npc\"", "solver.lme_gamma=1.5"}, false}};
const std::vector<int> baseline_cells{40, 160, 640, 2560};
std::string baseline_name(const std::string& method, int cells) { return "dyka_base_" + method + "_" + std::to_string(cells); }

std::vector<CaseSpec> all_cases() {
  std::vector<CaseSpec> cases;
  for (int cells : sweep_cells)
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators)
        // room beyond the free end: 4 cells, and 1% of the bar more on fine meshes, where grid
        // crossing can set the end particle adrift (paper/09_choices.md, 'Grid margins')
      {
        std::vector<std::string> overrides = verification::shape_settings(shape);
        overrides.insert(overrides.end(), {"grid.cells=[" + std::to_string(cells) + "]", "grid.margin_min=[" + std::to_string(4 + cells / 100) + "]",
                                           "solver.integrator=\"" + integrator + "\"", "solver.lme_gamma=3.0", "output.snapshots=[]"});
        cases.push_back({sweep_name(shape, integrator, cells), overrides});
      }
  for (int cells : fair_cells())
    for (const auto& shape : shapes) {
      std::vector<std::string> overrides = mesh_settings(shape, cells);
      overrides.insert(overrides.end(), {"solver.integrator=\"npc\"", "solver.npc_velocity=\"average\""});
      cases.push_back({fair_name(shape, "npcavg", cells), overrides});
    }
  for (const auto& integrator : integrators)
    for (double gamma : gammas) {
      std::ostringstream value;
      value << "solver.lme_gamma=" << std::fixed << std::setprecision(2) << gamma;
      cases.push_back({gamma_name(integrator, gamma),
                       {"grid.cells=[40]", "solver.shape=\"lme\"", "solver.integrator=\"" + integrator + "\"", value.str(),
                        "output.snapshots=[]"}});
    }
  for (const auto& baseline : baselines)
    for (int cells : baseline_cells) {
      if (cells > 640 && !baseline.at_crossing) continue;
      std::vector<std::string> overrides = mesh_settings("linear", cells);
      overrides.insert(overrides.end(), baseline.settings.begin(), baseline.settings.end());
      cases.push_back({baseline_name(baseline.method, cells), overrides});
    }
  // The longest cases first, so that the two cores finish together.
  std::stable_sort(cases.begin(), cases.end(), [](const CaseSpec& a, const CaseSpec& b) {
    auto weight = [](const CaseSpec& spec) {
      int cells = 40;
      for (const auto& o : spec.overrides)
        if (o.rfind("grid.cells=[", 0) == 0) cells = std::stoi(o.substr(12));
      const double shape = spec.name.find("_lme") != std::string::npos ? 6.0 : spec.name.find("_linear_") != std::string::npos ? 1.0 : 2.0;
      return double(cells) * cells * shape;
    };
    return weight(a) > weight(b);
  });
  return cases;
}

/// Grid-crossing ratio of paper/08_test_cases.md: delta = u_max / d_face, d_face = h / (2 ppc), ppc = 1.
double crossing_ratio(int cells) { return largest_displacement / (0.5 * 0.1333 / cells); }
std::string band_of(int cells) {
  const double delta = crossing_ratio(cells);
  return delta < 0.1 ? "negligible" : delta < 1.0 ? "transition" : "crossing";
}
/// The meshes of the sweep in a band, as text: "10-160", or "2560" for one.
std::string band_meshes(const std::string& band) {
  std::vector<int> cells;
  for (int n : sweep_cells)
    if (band_of(n) == band) cells.push_back(n);
  if (cells.empty()) return "none";
  return cells.size() == 1 ? std::to_string(cells[0]) : std::to_string(cells.front()) + "-" + std::to_string(cells.back());
}
std::vector<int> fair_cells() {
  std::vector<int> cells;
  for (int n : sweep_cells)
    if (band_of(n) == "negligible") cells.push_back(n);
  return cells;
}
/// The finest mesh of the sweep, and the finest without grid crossing (the last of the transition band).
int finest_mesh() { return sweep_cells.back(); }
int finest_without_crossing() {
  int finest = sweep_cells.front();
  for (int n : sweep_cells)
    if (band_of(n) != "crossing") finest = n;
  return finest;
}

/// Report helpers: one table row per claim.
struct Claim {
  std::string claim, measured;
  bool holds;
  bool hard;  ///< a bound of the theory: failing it fails `make figures`
};

std::string verdict(const Claim& claim) {
  return claim.holds ? "**holds**" : (claim.hard ? "**FAILS (hard check)**" : "**does not hold**");
}

std::string fixed(double value, int digits = 4) {
  std::ostringstream text;
  text << std::setprecision(digits) << value;
  return text.str();
}

/// A fitted order for the report: "none" when the band held fewer than two finished runs (NaN).
std::string order_text(double order) { return std::isnan(order) ? "none" : fixed(order, 3); }

}  // namespace

int main(int argc, char** argv) {
  const unsigned cores = verification::suite_threads(argc, argv);
  if (argc != 4 || cores == 0) {
    std::fprintf(stderr, "usage: dyka_suite DATA_DIR REPORT SCENE [--threads N]\n");
    return 2;
  }
  const std::string folder = argv[1], report_path = argv[2], scene = argv[3];
  const auto cases = all_cases();
  std::vector<verification::DykaResult> results(cases.size());
  std::vector<std::string> names;
  for (const auto& spec : cases) names.push_back(spec.name);
  // Every case on one thread (see verification/parallel.hpp, run_cases, for why).
  const std::vector<bool> wide(cases.size(), false);
  verification::run_cases("dyka", names, wide, cores, [&](size_t k, int threads) {
    results[k] = verification::run_dyka(scene, cases[k].name, cases[k].overrides, threads);
    verification::write_series(results[k], folder + "/" + cases[k].name + ".csv");
  });
  std::map<std::string, const verification::DykaResult*> by_name;
  for (const auto& result : results) by_name[result.name] = &result;
  auto result = [&](const std::string& name) -> const verification::DykaResult& { return *by_name.at(name); };

  // Forward Euler given the predictor-corrector's energy loss: per mesh, bisection on the FLIP fraction of
  // linear + FE until its energy at 200 us matches linear + NPC's (to 1e-4 of it), then every shape at that fraction.
  const std::vector<int> fair_meshes = fair_cells();
  std::vector<double> flip_fraction(fair_meshes.size(), 1.0);
  std::vector<std::vector<verification::DykaResult>> blends(fair_meshes.size());
  std::vector<std::string> fair_names;
  for (int cells : fair_meshes) fair_names.push_back("dyka_fair_" + std::to_string(cells));
  verification::run_cases("dyka", fair_names, std::vector<bool>(fair_meshes.size(), false), cores, [&](size_t k, int threads) {
    const int cells = fair_meshes[k];
    const double target = result(sweep_name("linear", "npc", cells)).final_energy_ratio;
    auto blended = [&](const std::string& shape, double fraction) {
      std::vector<std::string> overrides = mesh_settings(shape, cells);
      std::ostringstream setting;
      setting << std::setprecision(17) << "solver.flip_fraction=" << fraction;
      overrides.insert(overrides.end(), {"solver.integrator=\"fe\"", setting.str()});
      return verification::run_dyka(scene, fair_name(shape, "feblend", cells), overrides, threads);
    };
    double low = 0.0, high = 1.0;  // the energy left grows with the FLIP fraction
    for (int iteration = 0; iteration < 40; ++iteration) {
      const double middle = 0.5 * (low + high);
      const double energy = blended("linear", middle).final_energy_ratio;
      if (std::abs(energy - target) <= 1e-4 * target) {
        low = high = middle;
        break;
      }
      (energy > target ? high : low) = middle;
    }
    flip_fraction[k] = 0.5 * (low + high);
    for (const auto& shape : shapes) {
      blends[k].push_back(blended(shape, flip_fraction[k]));
      verification::write_series(blends[k].back(), folder + "/" + blends[k].back().name + ".csv");
    }
  });
  for (const auto& mesh : blends)
    for (const auto& run : mesh) by_name[run.name] = &run;

  // The choices of paper/09_choices.md, each switched on its own on the sweep's run (40 cells unless stated; the
  // free end's margin cells at 2560 too, where a particle reaches past them), and compared with that run.
  struct ChoiceCase {
    std::string choice, shape, integrator;
    int cells;
    std::vector<std::string> overrides;
    std::string reference;  ///< the run it is compared with
  };
  std::vector<ChoiceCase> choice_cases{
      {"fe_position_start", "linear", "fe", 40, {"solver.fe_position_velocity=\"start\""}, ""},
      {"fe_position_start", "lme", "fe", 40, {"solver.fe_position_velocity=\"start\""}, ""},
      {"no_free_end_margin", "lme", "fe", 40, {"grid.margin_min=[0]"}, ""},
      {"no_free_end_margin", "lme", "fe", 2560, {"grid.margin_min=[0]"}, ""},
      {"beta_mean_neighbour_distance", "lme", "fe", 40, {"solver.lme_beta=\"mean_neighbour_distance\""}, ""},
      {"beta_mean_neighbour_distance", "lme", "npc", 40, {"solver.lme_beta=\"mean_neighbour_distance\""}, ""},
      {"lme_tol_1e-5", "lme", "npc", 40, {"solver.lme_tol=1e-5"}, ""},
      {"courant_sum", "linear", "fe", 40, {"solver.courant=\"sum\""}, ""},
      {"courant_sum", "linear", "npc", 40, {"solver.courant=\"sum\""}, ""},
      {"default_snapshots", "linear", "fe", 40, {"output.snapshots=[0.0, 1.0e-4, 2.0e-4]"}, ""},
      {"rigid_support_margin_gamma0.8", "lme", "npc", 40, {"grid.margin_max=[4]", "solver.lme_gamma=0.80"}, gamma_name("npc", 0.8)},
  };
  std::vector<verification::DykaResult> choice_runs(choice_cases.size());
  std::vector<std::string> choice_names;
  for (auto& c : choice_cases) {
    choice_names.push_back("dyka_choice_" + c.choice + "_" + c.shape + "_" + c.integrator + "_" + std::to_string(c.cells));
    if (c.reference.empty()) c.reference = sweep_name(c.shape, c.integrator, c.cells);
  }
  verification::run_cases("dyka", choice_names, std::vector<bool>(choice_cases.size(), false), cores, [&](size_t k, int threads) {
    std::vector<std::string> overrides = mesh_settings(choice_cases[k].shape, choice_cases[k].cells);
    overrides.push_back("solver.integrator=\"" + choice_cases[k].integrator + "\"");
    overrides.insert(overrides.end(), choice_cases[k].overrides.begin(), choice_cases[k].overrides.end());
    choice_runs[k] = verification::run_dyka(scene, choice_names[k], overrides, threads);
  });

  // Energy over 10 periods (10 x 4L/c = 1.0551 ms) at 40 cells, the runs of tests/energy.cpp: every shape with
  // both integrators at CFL 0.5, and the predictor-corrector at CFL 0.1 (its loss falls with the step).
  struct EnergyCase {
    std::string shape, integrator;
    double cfl;
  };
  std::vector<EnergyCase> energy_cases;
  for (const auto& shape : shapes) {
    for (const auto& integrator : integrators) energy_cases.push_back({shape, integrator, 0.5});
    energy_cases.push_back({shape, "npc", 0.1});
  }
  std::vector<verification::DykaResult> energy_runs(energy_cases.size());
  std::vector<std::string> energy_names;
  for (const auto& c : energy_cases) energy_names.push_back("dyka_energy_" + c.shape + "_" + c.integrator + "_cfl" + fixed(c.cfl));
  verification::run_cases("dyka", energy_names, std::vector<bool>(energy_cases.size(), false), cores, [&](size_t k, int threads) {
    std::vector<std::string> overrides = verification::shape_settings(energy_cases[k].shape);
    overrides.insert(overrides.end(), {"solver.integrator=\"" + energy_cases[k].integrator + "\"", "solver.cfl=" + fixed(energy_cases[k].cfl),
                                       "solver.end_time=1.0551e-3", "output.snapshots=[]"});
    energy_runs[k] = verification::run_dyka(scene, energy_names[k], overrides, threads);
  });

  // --- Data files --------------------------------------------------------------------------
  std::ofstream sweep(folder + "/dyka_sweep.csv");  // Fig. 6 and the work-precision chart
  sweep << std::setprecision(8)
        << "shape,integrator,cells,h,crossing_ratio,band,rms,rms_over_v0,largest_speed_over_v0,wall_seconds,steps,status,"
           "rms_own_time_over_v0,newton_mean,newton_max,neighbours_mean\n";
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators)
      for (int cells : sweep_cells) {
        const auto& run = result(sweep_name(shape, integrator, cells));
        sweep << shape << "," << integrator << "," << cells << "," << 0.1333 / cells << "," << crossing_ratio(cells) << ","
              << band_of(cells) << "," << run.rms << "," << run.rms / speed_v0 << "," << run.largest_speed / speed_v0 << ","
              << run.wall_seconds << "," << run.steps << "," << (run.failed ? "failed" : "ok") << "," << run.rms_own_time / speed_v0 << ","
              << run.newton_mean << "," << run.newton_max << "," << run.neighbours_mean << "\n";
      }
  std::ofstream fair(folder + "/dyka_fair.csv");  // FE against NPC, fairly
  fair << std::setprecision(8)
       << "shape,cells,fe,fe_own_time,npc,npc_average,fe_blend,flip_fraction,energy_fe,energy_npc,energy_npc_average,energy_fe_blend\n";
  for (const auto& shape : shapes)
    for (size_t k = 0; k < fair_meshes.size(); ++k) {
      const int cells = fair_meshes[k];
      const auto &fe = result(sweep_name(shape, "fe", cells)), &npc = result(sweep_name(shape, "npc", cells));
      const auto &average = result(fair_name(shape, "npcavg", cells)), &blend = result(fair_name(shape, "feblend", cells));
      fair << shape << "," << cells << "," << fe.rms / speed_v0 << "," << fe.rms_own_time / speed_v0 << "," << npc.rms / speed_v0 << ","
           << average.rms / speed_v0 << "," << blend.rms / speed_v0 << "," << flip_fraction[k] << "," << fe.final_energy_ratio << ","
           << npc.final_energy_ratio << "," << average.final_energy_ratio << "," << blend.final_energy_ratio << "\n";
    }
  std::ofstream choice_file(folder + "/dyka_choices.csv");  // the measured effects of paper/09_choices.md
  choice_file << std::setprecision(8)
              << "choice,shape,integrator,cells,rms_over_v0,reference_rms_over_v0,steps,reference_steps,end_time,status,"
                 "largest_velocity_difference,rms_velocity_difference\n";
  for (size_t k = 0; k < choice_cases.size(); ++k) {
    const auto &run = choice_runs[k], &reference = result(choice_cases[k].reference);
    // v_A against the reference run's, where both sampled the same times (else nan)
    double largest = std::nan(""), rms = std::nan("");
    if (!run.failed && !reference.failed && run.time.size() == reference.time.size() && run.time.size() > 1) {
      bool same_times = true;
      std::vector<double> difference;
      for (size_t n = 0; n < run.time.size(); ++n) {
        // the step follows the solution (Eq. 42), so the two runs' times may differ by round-off
        same_times = same_times && std::abs(run.time[n] - reference.time[n]) <= 1e-3 * (reference.time[1] - reference.time[0]);
        difference.push_back(run.velocity[n] - reference.velocity[n]);
      }
      if (same_times) {
        largest = 0.0;
        for (double d : difference) largest = std::max(largest, std::abs(d));
        rms = mpm::rms_error(difference, std::vector<double>(difference.size(), 0.0));
      }
    }
    choice_file << choice_cases[k].choice << "," << choice_cases[k].shape << "," << choice_cases[k].integrator << "," << choice_cases[k].cells
                << "," << (run.failed ? std::nan("") : run.rms / speed_v0) << "," << reference.rms / speed_v0 << "," << run.steps << ","
                << reference.steps << "," << (run.time.empty() ? 0.0 : run.time.back()) << "," << (run.failed ? "failed" : "ok") << ","
                << largest << "," << rms << "\n";
  }
  std::ofstream energy_file(folder + "/dyka_energy.csv");  // energy over 10 periods, 40 cells
  energy_file << std::setprecision(8)
              << "shape,integrator,cfl,periods,smallest_over_initial,largest_over_initial,final_over_initial,"
                 "largest_step_increase_over_initial,steps,status\n";
  for (size_t k = 0; k < energy_cases.size(); ++k) {
    const auto& run = energy_runs[k];
    energy_file << energy_cases[k].shape << "," << energy_cases[k].integrator << "," << energy_cases[k].cfl << ",10,"
                << run.smallest_energy_ratio << "," << run.largest_energy_ratio << "," << run.final_energy_ratio << ","
                << run.largest_energy_step_increase << "," << run.steps << "," << (run.failed ? "failed" : "ok") << "\n";
  }
  std::ofstream gamma_file(folder + "/dyka_gamma.csv");  // Fig. 8, second panel
  gamma_file << std::setprecision(8) << "gamma,rms_fe,rms_npc,rms_fe_over_v0,rms_npc_over_v0,rms_fe_own_time_over_v0\n";
  for (double gamma : gammas)
    gamma_file << gamma << "," << result(gamma_name("fe", gamma)).rms << "," << result(gamma_name("npc", gamma)).rms << ","
               << result(gamma_name("fe", gamma)).rms / speed_v0 << "," << result(gamma_name("npc", gamma)).rms / speed_v0 << ","
               << result(gamma_name("fe", gamma)).rms_own_time / speed_v0 << "\n";

  // --- Fitted orders per band (Fig. 6) -------------------------------------------------------
  std::ofstream orders(folder + "/dyka_orders.csv");
  orders << "shape,integrator,band,order,first_cells,last_cells,meshes\n";
  std::map<std::string, double> order_of, own_time_order_of;
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators)
      for (const std::string band : {"negligible", "transition", "crossing"}) {
        std::vector<int> cells;
        std::vector<double> rms;
        for (int n : sweep_cells)
          if (band_of(n) == band && !result(sweep_name(shape, integrator, n)).failed)
            cells.push_back(n), rms.push_back(result(sweep_name(shape, integrator, n)).rms);
        const double order = verification::fitted_order(cells, rms, 2);  // two meshes of the band at the least
        order_of[shape + "_" + integrator + "_" + band] = order;
        std::vector<double> rms_own_time;
        for (int n : cells) rms_own_time.push_back(result(sweep_name(shape, integrator, n)).rms_own_time);
        own_time_order_of[shape + "_" + integrator + "_" + band] = verification::fitted_order(cells, rms_own_time, 2);
        orders << shape << "," << integrator << "," << band << "," << order << "," << (cells.empty() ? 0 : cells.front()) << ","
               << (cells.empty() ? 0 : cells.back()) << "," << cells.size() << "\n";
      }

  // --- Claims and checks ---------------------------------------------------------------------
  std::vector<std::pair<std::string, std::vector<Claim>>> sections;  // title, claims; figures named in `title`
  bool hard_failure = false;
  auto add = [&](std::vector<Claim>& list, Claim claim) {
    if (claim.hard && !claim.holds) hard_failure = true;
    list.push_back(std::move(claim));
  };

  {  // Every run
    std::vector<Claim> list;
    double worst_mass = 0.0;
    int failed = 0;
    std::string failures;
    for (const auto& run : results) {
      worst_mass = std::max(worst_mass, run.mass_error);
      if (run.failed) ++failed, failures += " `" + run.name + "`: " + run.failure + ";";
    }
    add(list, {"Mass is conserved: the nodal masses sum to the particle mass (Eq. 13 with the partition of unity), every step of every run",
               "largest relative error " + fixed(worst_mass, 3), worst_mass <= 1e-12, true});
    add(list, {"Every run of the sweep reaches 200 µs (no NaN, no particle off the grid, no energy growth)",
               std::to_string(failed) + " of " + std::to_string(results.size()) + " runs failed" + failures, failed == 0, false});
    sections.push_back({"All Dyka runs", list});
  }
  {  // Fig. 6
    std::vector<Claim> list;
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators) {
        const double rms40 = result(sweep_name(shape, integrator, 40)).rms, rms160 = result(sweep_name(shape, integrator, 160)).rms;
        const double order = order_of[shape + "_" + integrator + "_negligible"];
        add(list, {"Without grid crossing the error falls under refinement (" + shape + ", " + integrator + ")",
                   "RMS/v0 " + fixed(rms40 / speed_v0) + " at 40 cells, " + fixed(rms160 / speed_v0) + " at 160; order " +
                       fixed(order, 3) + " over 10-160 cells",
                   rms160 < rms40 && order > 0.0, true});
      }
    for (const auto& shape : shapes) {
      int npc_better = 0, meshes = 0;
      for (int cells : sweep_cells)
        if (band_of(cells) == "negligible") {
          ++meshes;
          if (result(sweep_name(shape, "npc", cells)).rms < result(sweep_name(shape, "fe", cells)).rms) ++npc_better;
        }
      add(list, {"The predictor-corrector is more accurate than forward Euler (Fig. 6, " + shape + ", meshes without crossing)",
                 "NPC below FE on " + std::to_string(npc_better) + " of " + std::to_string(meshes) + " meshes", npc_better == meshes, false});
    }
    // Grid crossing: the finest mesh (in the crossing band) against the finest without crossing.
    const int fine_cells = finest_mesh(), coarse_cells = finest_without_crossing();
    const std::string fine_text = std::to_string(fine_cells), coarse_text = std::to_string(coarse_cells);
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators) {
        const double light = order_of[shape + "_" + integrator + "_negligible"];
        const auto& coarse = result(sweep_name(shape, integrator, coarse_cells));
        const auto& fine = result(sweep_name(shape, integrator, fine_cells));
        const std::string measured = fine.failed ? "the " + fine_text + "-cell run stopped: " + fine.failure
                                                 : "RMS/v0 " + fixed(coarse.rms / speed_v0) + " at " + coarse_text + " cells, " +
                                                       fixed(fine.rms / speed_v0) + " at " + fine_text + " (order " + fixed(light, 3) + " without crossing)";
        add(list, {"Grid crossing spoils the solution: the error at " + fine_text + " cells exceeds the error at " + coarse_text + " (" + shape + ", " +
                       integrator + ")",
                   measured, fine.failed || fine.rms > coarse.rms, false});
      }
    for (const auto& integrator : integrators) {
      const auto& linear = result(sweep_name("linear", integrator, fine_cells));
      const auto& ugimp = result(sweep_name("ugimp", integrator, fine_cells));
      const auto& lme = result(sweep_name("lme", integrator, fine_cells));
      const auto& ugimp_coarse = result(sweep_name("ugimp", integrator, coarse_cells));
      const auto& lme_coarse = result(sweep_name("lme", integrator, coarse_cells));
      const std::string linear_text = linear.failed ? "stopped (" + linear.failure.substr(linear.failure.find(": ") + 2) + ")"
                                                    : "RMS/v0 " + fixed(linear.rms / speed_v0);
      add(list, {"uGIMP and LME withstand grid crossing better than linear shape functions (" + fine_text + " cells, " + integrator + ")",
                 "linear " + linear_text + "; uGIMP RMS/v0 " + fixed(ugimp.rms / speed_v0) + ", LME " + fixed(lme.rms / speed_v0),
                 !ugimp.failed && !lme.failed && (linear.failed || (ugimp.rms < linear.rms && lme.rms < linear.rms)), false});
      add(list, {"... and stay accurate through it: their error at " + fine_text + " cells is below their error at " + coarse_text + " (" + integrator + ")",
                 "uGIMP " + fixed(ugimp_coarse.rms / speed_v0) + " -> " + fixed(ugimp.rms / speed_v0) + ", LME " + fixed(lme_coarse.rms / speed_v0) +
                     " -> " + fixed(lme.rms / speed_v0),
                 !ugimp.failed && !lme.failed && ugimp.rms < ugimp_coarse.rms && lme.rms < lme_coarse.rms, false});
    }
    sections.push_back({"Fig. 6: error at point A against the number of cells (`dyka_fig6`)", list});
  }
  {  // Fig. 7
    std::vector<Claim> list;
    const auto& fe = result(sweep_name("lme", "fe", 40));
    const auto& npc = result(sweep_name("lme", "npc", 40));
    add(list, {"The predictor-corrector removes the spurious oscillations of forward Euler (LME gamma 3, 40 cells)",
               "largest |v_A|/v0: FE " + fixed(fe.largest_speed / speed_v0) + ", NPC " + fixed(npc.largest_speed / speed_v0) +
                   "; RMS/v0: FE " + fixed(fe.rms / speed_v0) + ", NPC " + fixed(npc.rms / speed_v0),
               npc.largest_speed < fe.largest_speed && npc.rms < fe.rms, false});
    add(list, {"paper/08_test_cases.md: NPC stays within 1.0-1.09 v0, FE overshoots to 1.3-1.6 v0",
               "NPC " + fixed(npc.largest_speed / speed_v0) + " v0, FE " + fixed(fe.largest_speed / speed_v0) + " v0",
               npc.largest_speed / speed_v0 <= 1.09 && fe.largest_speed / speed_v0 >= 1.3, false});
    sections.push_back({"Fig. 7: predictor-corrector against forward Euler (`dyka_fig7`)", list});
  }
  {  // FE against NPC, fairly
    std::vector<Claim> list;
    double lowest_fraction = 1.0, highest_fraction = 0.0;
    for (double fraction : flip_fraction) lowest_fraction = std::min(lowest_fraction, fraction), highest_fraction = std::max(highest_fraction, fraction);
    const std::string meshes = std::to_string(fair_meshes.front()) + "-" + std::to_string(fair_meshes.back()) + " cells";
    for (const auto& shape : shapes) {
      int own_time = 0, average = 0, blend = 0;
      double blend_gap = 0.0;  // largest |RMS(FE + blend) - RMS(NPC)| / RMS(NPC)
      std::string own_row, average_row, blend_row;
      for (int cells : fair_meshes) {
        const auto &fe = result(sweep_name(shape, "fe", cells)), &npc = result(sweep_name(shape, "npc", cells));
        const auto &npc_average = result(fair_name(shape, "npcavg", cells)), &fe_blend = result(fair_name(shape, "feblend", cells));
        own_time += npc.rms < fe.rms_own_time;
        average += npc.rms < npc_average.rms;
        blend += npc.rms < 0.99 * fe_blend.rms;
        blend_gap = std::max(blend_gap, std::abs(fe_blend.rms - npc.rms) / npc.rms);
        own_row += " " + std::to_string(cells) + ": " + fixed(fe.rms_own_time / speed_v0) + " (at t: " + fixed(fe.rms / speed_v0) + ") against " +
                   fixed(npc.rms / speed_v0) + ";";
        average_row += " " + std::to_string(cells) + ": " + fixed(npc_average.rms / speed_v0) + " against " + fixed(npc.rms / speed_v0) + ";";
        blend_row += " " + std::to_string(cells) + ": " + fixed(fe_blend.rms / speed_v0) + " against " + fixed(npc.rms / speed_v0) + ";";
      }
      const std::string count = " of " + std::to_string(fair_meshes.size()) + " meshes";
      add(list, {"NPC is more accurate than FE with FE's velocity compared at t + dt/2, the time it approximates (" + shape + ", " + meshes + ")",
                 "NPC below FE on " + std::to_string(own_time) + count + "; RMS/v0 of FE at t + dt/2 against NPC:" + own_row,
                 own_time == static_cast<int>(fair_meshes.size()), false});
      add(list, {"NPC as printed (Eq. 32, damped) is more accurate than the undamped Newmark average (" + shape + ")",
                 "Eq. (32) below the average on " + std::to_string(average) + count + "; RMS/v0 of the average against Eq. (32):" + average_row,
                 average == static_cast<int>(fair_meshes.size()), false});
      add(list, {"NPC's lower RMS is more than its damping: NPC is more accurate, by more than 1 %, than FE given the same energy loss by a PIC/FLIP "
                 "blend (" + shape + "; the blend's fraction calibrated on linear shapes, paper/10_integrator_analysis.md)",
                 "NPC more than 1 % below FE + blend on " + std::to_string(blend) + count + ", the two within " + fixed(100.0 * blend_gap, 2) +
                     " % of each other on every mesh (FLIP fraction " + fixed(lowest_fraction, 5) + "-" + fixed(highest_fraction, 5) +
                     "); RMS/v0 of FE + blend against NPC:" + blend_row,
                 blend == static_cast<int>(fair_meshes.size()), false});
    }
    sections.push_back({"FE against NPC, fairly: FE at its own time, the Newmark average, FE damped like NPC (`dyka_fair`)", list});
  }
  {  // Fig. 8
    std::vector<Claim> list;
    double best = 1e300, worst = 0.0, best_gamma = 0.0;
    std::string row;
    for (double gamma : gammas) {
      const double rms = result(gamma_name("npc", gamma)).rms;
      row += " γ=" + fixed(gamma, 2) + ": " + fixed(rms / speed_v0) + ";";
      if (rms < best) best = rms, best_gamma = gamma;
      worst = std::max(worst, rms);
    }
    add(list, {"The LME result is sensitive to gamma (NPC, 40 cells): RMS/v0 varies by more than 5% over gamma in [0.8, 5]",
               "RMS/v0" + row + " best at γ = " + fixed(best_gamma, 2) + ", spread " + fixed(100.0 * (worst - best) / best, 3) + "%",
               worst > 1.05 * best, false});
    sections.push_back({"Fig. 8: sensitivity to gamma (`dyka_fig8`)", list});
  }
  {  // Figs. 9 and 10
    std::vector<Claim> list;
    for (const auto& integrator : integrators) {
      const double linear = result(sweep_name("linear", integrator, 40)).rms;
      const double ugimp = result(sweep_name("ugimp", integrator, 40)).rms, lme = result(sweep_name("lme", integrator, 40)).rms;
      const double spread = (std::max({linear, ugimp, lme}) - std::min({linear, ugimp, lme})) / std::min({linear, ugimp, lme});
      add(list, {"Without grid crossing the three shape functions give nearly the same v_A (paper/08_test_cases.md: within about 1%; " + integrator + ", 40 cells)",
                 "RMS/v0 linear " + fixed(linear / speed_v0) + ", uGIMP " + fixed(ugimp / speed_v0) + ", LME " + fixed(lme / speed_v0) +
                     ": spread " + fixed(100.0 * spread, 3) + "%",
                 spread <= 0.05, false});
    }
    // A bound of the theory: a discontinuity smeared over a width ~ sqrt(h) (first-order dissipation)
    // or ringing over a few cells leaves an L2-in-time error that falls at least like h^(1/4); we
    // require an observed order >= 0.2 over 10-160 cells and the 640-cell error below (1/16)^0.2 =
    // 0.574 times the 40-cell error. Anything slower means the exact solution is not being approached.
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators) {
        const double rms40 = result(sweep_name(shape, integrator, 40)).rms, rms640 = result(sweep_name(shape, integrator, 640)).rms;
        const double order = order_of[shape + "_" + integrator + "_negligible"];
        add(list, {"Bound: the exact solution is approached under refinement, order >= 0.2 and RMS(640) <= 0.574 RMS(40) (" + shape + ", " + integrator + ")",
                   "order " + fixed(order, 3) + "; RMS/v0 " + fixed(rms640 / speed_v0) + " at 640 cells, " + fixed(rms40 / speed_v0) + " at 40 (ratio " +
                       fixed(rms640 / rms40, 3) + ")",
                   order >= 0.2 && rms640 <= 0.574 * rms40 && !result(sweep_name(shape, integrator, 640)).failed, true});
      }
    sections.push_back({"Figs. 9 and 10: shape functions compared (`dyka_fig9`: FE, `dyka_fig10`: NPC)", list});
  }
  {  // LME Newton statistics
    std::vector<Claim> list;
    double mean = 0.0;
    int largest = 0, count = 0;
    for (const auto& run : results)
      if (run.name.find("_lme_") != std::string::npos || run.name.find("gamma") != std::string::npos)
        mean += run.newton_mean, ++count, largest = std::max(largest, run.newton_max);
    add(list, {"Warm-started Newton iterations for lambda stay few (paper/09_choices.md: 2-6)",
               "mean " + fixed(mean / count, 3) + " iterations per particle-step over the LME runs, largest " + std::to_string(largest),
               mean / count <= 6.0, false});
    sections.push_back({"LME Newton iterations", list});
  }
  {  // Energy over 10 periods
    std::vector<Claim> list;
    std::string fe_text, npc_text;
    bool fe_holds = true, npc_holds = true;
    for (size_t k = 0; k < energy_cases.size(); ++k) {
      const auto& run = energy_runs[k];
      const std::string label = energy_cases[k].shape + (energy_cases[k].cfl == 0.5 ? "" : " at CFL " + fixed(energy_cases[k].cfl));
      if (energy_cases[k].integrator == "fe") {
        fe_holds = fe_holds && !run.failed && run.smallest_energy_ratio >= 0.965 && run.largest_energy_ratio <= 1.035 &&
                   std::abs(run.final_energy_ratio - 1.0) <= 0.02;
        fe_text += label + ": [" + fixed(run.smallest_energy_ratio) + ", " + fixed(run.largest_energy_ratio) + "], at the end " +
                   fixed(run.final_energy_ratio) + "; ";
      } else {
        npc_holds = npc_holds && !run.failed && run.largest_energy_step_increase <= 1e-12 && run.final_energy_ratio < 1.0;
        npc_text += label + ": " + fixed(run.final_energy_ratio) + " left, largest rise in a step " + fixed(run.largest_energy_step_increase, 2) + "; ";
      }
    }
    add(list, {"Forward Euler conserves energy on average: over 10 periods E/E0 stays within [0.965, 1.035] and ends within 2 % of 1",
               fe_text, fe_holds, false});
    add(list, {"The predictor-corrector (Eq. 32) dissipates: E/E0 rises in no step (by at most 1e-12) and falls over 10 periods",
               npc_text, npc_holds, false});
    sections.push_back({"Energy over 10 periods (40 cells, CFL 0.5 unless stated; data/dyka_energy.csv)", list});
  }

  // Today's baselines: every method of the sweep and of the baselines, per mesh, by error and by cost.
  struct Entry {
    std::string method;
    const verification::DykaResult* run;
  };
  auto entries_at = [&](int cells) {
    std::vector<Entry> entries;
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators) entries.push_back({shape + (shape == "lme" ? "3" : "") + "_" + integrator, &result(sweep_name(shape, integrator, cells))});
    for (const auto& baseline : baselines)
      if (cells <= 640 || baseline.at_crossing) entries.push_back({baseline.method, &result(baseline_name(baseline.method, cells))});
    return entries;
  };
  std::ofstream baseline_file(folder + "/dyka_baselines.csv");
  baseline_file << std::setprecision(8) << "method,cells,rms_over_v0,wall_seconds,steps,status,pareto\n";
  std::map<int, std::string> most_accurate, pareto_text;
  for (int cells : baseline_cells) {
    const auto entries = entries_at(cells);
    for (const auto& entry : entries) {
      // on the front of error against cost: no finished method is both more accurate and clearly cheaper (by more than
      // 10 % of wall time: the runs are timed once, two side by side, and closer times are within their noise)
      bool dominated = entry.run->failed;
      for (const auto& other : entries)
        dominated = dominated || (!other.run->failed && other.run->rms < entry.run->rms && other.run->wall_seconds < 0.9 * entry.run->wall_seconds);
      baseline_file << entry.method << "," << cells << "," << (entry.run->failed ? std::nan("") : entry.run->rms / speed_v0) << ","
                    << entry.run->wall_seconds << "," << entry.run->steps << "," << (entry.run->failed ? "failed" : "ok") << ","
                    << (dominated ? 0 : 1) << "\n";
      if (!dominated) pareto_text[cells] += (pareto_text[cells].empty() ? "" : ", ") + entry.method + " " + fixed(entry.run->rms / speed_v0);
      if (!entry.run->failed &&
          (most_accurate[cells].empty() || entry.run->rms < result(most_accurate[cells].substr(0, most_accurate[cells].find('|'))).rms))
        most_accurate[cells] = entry.run->name + "|" + entry.method;
    }
  }
  {
    std::vector<Claim> list;
    auto method_of = [&](int cells) { return most_accurate[cells].substr(most_accurate[cells].find('|') + 1); };
    auto rms_of = [&](int cells) { return result(most_accurate[cells].substr(0, most_accurate[cells].find('|'))).rms / speed_v0; };
    for (int cells : baseline_cells) {
      const bool paper = method_of(cells).rfind("ugimp", 0) == 0 || method_of(cells).rfind("lme3", 0) == 0;
      add(list, {"With today's baselines in the comparison, a method of the paper (uGIMP, LME gamma 3) is still the most accurate of the "
                     "methods run at " + std::to_string(cells) + " cells (" + band_of(cells) + ")",
                 "most accurate: " + method_of(cells) + " (RMS/v0 " + fixed(rms_of(cells)) + "); most accurate for its cost (no method both "
                 "more accurate and over 10 % faster, one timing per run): " + pareto_text[cells],
                 paper, false});
    }
    double largest_gap = 0.0;  // uGIMP against the quadratic B-spline, relative
    for (const std::string integrator : {"fe", "npc"})
      for (int cells : baseline_cells)
        if (cells <= 640) {
          const double ugimp = result(sweep_name("ugimp", integrator, cells)).rms, quadratic = result(baseline_name("bspline2_" + integrator, cells)).rms;
          largest_gap = std::max(largest_gap, std::abs(ugimp - quadratic) / ugimp);
        }
    add(list, {"At one particle per cell uGIMP is the quadratic B-spline (the hat averaged over the particle's width h): their errors agree to 1e-4",
               "largest relative difference of RMS, 40-640 cells, FE and NPC: " + fixed(largest_gap, 3), largest_gap <= 1e-4, false});
    for (const std::string integrator : {"fe", "npc"}) {
      const auto &cubic = result(baseline_name("bspline3_" + integrator, 2560)), &cubic640 = result(baseline_name("bspline3_" + integrator, 640));
      const auto &linear = result(sweep_name("linear", integrator, 2560)), &ugimp = result(sweep_name("ugimp", integrator, 2560)),
                 &lme = result(sweep_name("lme", integrator, 2560));
      add(list, {"The cubic B-spline stays accurate through grid crossing: it finishes at 2560 cells with an error below its 640-cell one (" +
                     integrator + "; linear " + std::string(linear.failed ? "stops" : "finishes") + " there)",
                 "RMS/v0 at 640 -> 2560 cells: cubic " + fixed(cubic640.rms / speed_v0) + " -> " + (cubic.failed ? "stopped" : fixed(cubic.rms / speed_v0)) +
                     "; at 2560: uGIMP " + fixed(ugimp.rms / speed_v0) + ", LME " + fixed(lme.rms / speed_v0),
                 !cubic.failed && cubic.rms < cubic640.rms, false});
    }
    {
      const double usf = result(sweep_name("linear", "fe", 40)).rms / speed_v0, usl = result(baseline_name("linear_usl", 40)).rms / speed_v0,
                   musl = result(baseline_name("linear_musl", 40)).rms / speed_v0;
      const double below = 1.0 - usl / usf, above = musl / usf - 1.0;
      add(list, {"USL and MUSL differ from USF by 5-11 % on the Dyka bar at 40 cells, USL below and MUSL above",
                 "linear FE, RMS/v0: USF " + fixed(usf) + ", USL " + fixed(usl) + " (" + fixed(100.0 * below, 3) + " % below), MUSL " +
                     fixed(musl) + " (" + fixed(100.0 * above, 3) + " % above)",
                 below >= 0.05 && below <= 0.11 && above >= 0.05 && above <= 0.11, false});
    }
    {
      const double g08 = result(baseline_name("lme0.8_npc", 640)).rms, g15 = result(baseline_name("lme1.5_npc", 640)).rms,
                   g3 = result(sweep_name("lme", "npc", 640)).rms;
      add(list, {"A wider LME (gamma 0.8, 1.5) buys accuracy over gamma 3 at 640 cells (NPC)",
                 "RMS/v0: gamma 0.8 " + fixed(g08 / speed_v0) + ", 1.5 " + fixed(g15 / speed_v0) + ", 3 " + fixed(g3 / speed_v0),
                 g08 < g3 && g15 < g3, false});
    }
    {
      // The free end: the Dyka bar's own linearised step (40 cells, forward Euler) at rest and with every particle moved
      // outward, towards its free end at x = 0, by 1e-6 h (mpm::moved_body_cfl_limit), for each stress update.
      std::ofstream free_end(folder + "/dyka_free_end.csv");
      free_end << std::setprecision(8) << "method,cfl_limit_at_rest,cfl_limit_moved\n";
      std::string text;
      bool explains = true;
      for (const std::string method : {"linear_usl", "bspline2_usf", "bspline2_usl", "bspline2_musl", "bspline3_usl"}) {
        const std::string shape = method.substr(0, method.find('_')), update = method.substr(method.find('_') + 1);
        const mpm::io::Scene bar = mpm::load_scene(scene, {"solver.shape=\"" + shape + "\"", "solver.integrator=\"fe\"",
                                                            "solver.stress_update=\"" + update + "\"", "grid.cells=[40]"});
        const double rest = mpm::moved_body_cfl_limit<1>(bar, 0.0), moved = mpm::moved_body_cfl_limit<1>(bar, -1e-6);
        free_end << method << "," << rest << "," << moved << "\n";
        text += std::string(text.empty() ? "" : "; ") + method + " " + fixed(rest) + " -> " + fixed(moved);
        explains = explains && (method == "bspline2_usl" ? moved < 0.9 * rest : std::abs(moved / rest - 1.0) < 5e-3);
        if (method == "bspline2_usl") {  // the runs of the stability map (v0/100, 20 ms, energy limit 100) on either side of it
          for (const double factor : {0.98, 1.02}) {
            const auto run = verification::run_dyka(scene, "dyka_free_end_" + fixed(factor), {"solver.shape=\"bspline2\"", "solver.integrator=\"fe\"",
                "solver.stress_update=\"usl\"", "grid.cells=[40]", "solver.end_time=2e-2", "solver.energy_growth_limit=100",
                "initial_velocity[0].velocity=[-0.05]", "solver.cfl=" + std::to_string(factor * moved), "output.every=100000", "output.snapshots=[]"});
            text += std::string("; its run at ") + fixed(factor) + " x " + fixed(moved) + (run.failed ? " stops" : " finishes");
            explains = explains && run.failed == (factor > 1.0);
          }
        }
      }
      add(list, {"The quadratic B-spline with USL stops on the free bar at CFL numbers its held bar's step calls stable because of the "
                 "free end: moved outward by 1e-6 h, the end particle brings the node 1.5 h beyond it into its support with a vanishing "
                 "mass, and the step's limit on the Dyka bar falls by over 10 %; USF, MUSL, linear USL and the cubic B-spline keep theirs "
                 "within 0.5 %; the run at v0/100 finishes at 0.98 times that lower limit and stops at 1.02 times it (40 cells; "
                 "data/dyka_free_end.csv)",
                 "limit of the Dyka bar's linearised step at rest -> moved by 1e-6 h: " + text, explains, false});
    }
    sections.push_back({"Today's baselines: B-splines, USL and MUSL, LME at small gamma (data/dyka_baselines.csv)", list});
  }

  std::ofstream report(report_path);
  report << "## Dyka bar (section 3.1)\n\n"
         << "Scene `scenes/dyka_bar.toml`; error = Eq. (43) over every step of v_A against the exact solution (appendix A) "
            "at particle A's reference position; 1 particle per cell, CFL 0.5, 200 µs; RMS divided by |v0| = 5 m/s.\n\n";
  for (const auto& [title, list] : sections) {
    report << "### " << title << "\n\n";
    for (size_t at = title.find('`'); at != std::string::npos; at = title.find('`', title.find('`', at + 1) + 1)) {
      const std::string figure = title.substr(at + 1, title.find('`', at + 1) - at - 1);
      report << "![" << figure << "](figures/" << figure << ".png)\n\n";
    }
    report << "| claim | measured | verdict |\n|---|---|---|\n";
    for (const auto& claim : list) report << "| " << claim.claim << " | " << claim.measured << " | " << verdict(claim) << " |\n";
    report << "\n";
  }
  report << "Fitted orders of convergence (GSL least squares on log RMS against log cells, per band of paper/08_test_cases.md; "
            "none where the band holds fewer than two finished runs):\n\n"
         << "| shape | integrator | negligible (" << band_meshes("negligible") << ") | transition (" << band_meshes("transition")
         << ") | crossing (" << band_meshes("crossing") << ") |\n|---|---|---|---|---|\n";
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators)
      report << "| " << shape << " | " << integrator << " | " << order_text(order_of[shape + "_" + integrator + "_negligible"]) << " | "
             << order_text(order_of[shape + "_" + integrator + "_transition"]) << " | " << order_text(order_of[shape + "_" + integrator + "_crossing"])
             << " |\n";
  report << "\n";
  report << "The same orders with forward Euler's velocity compared with the exact solution at t + dt/2, the time it approximates on "
            "smooth data (the predictor-corrector's, first order at t and at any shift of it, unchanged). The impact starts from a jump, "
            "and the shift raises forward Euler's RMS on every mesh of the sweep:\n\n"
         << "| shape | integrator | negligible | transition | crossing |\n|---|---|---|---|---|\n";
  for (const auto& shape : shapes)
    report << "| " << shape << " | fe | " << order_text(own_time_order_of[shape + "_fe_negligible"]) << " | "
           << order_text(own_time_order_of[shape + "_fe_transition"]) << " | " << order_text(own_time_order_of[shape + "_fe_crossing"]) << " |\n";
  report << "\n";
  std::printf("dyka_suite: %zu runs, hard checks %s\n", results.size(), hard_failure ? "FAILED" : "passed");
  return hard_failure ? 1 : 0;
}
