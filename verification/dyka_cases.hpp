// The studies of the Dyka-bar suite as data: which runs each figure needs, by name and scene overrides.
//
// sweep:     Fig. 6's mesh sweep, 10 to 2560 cells, linear, uGIMP and LME gamma 3, forward Euler and the
//            predictor-corrector, CFL 0.5 (also Figs. 7, 9, 10 and the work-precision chart);
// cfl:       the same methods at CFL 1.0 and 1.3 on 40 and 160 cells (where the comparison of the integrators
//            might turn with the step);
// npcavg:    the predictor-corrector with the Newmark average on the meshes without grid crossing (dyka_fair);
// authors:   the LME runs of the sweep, of the large CFLs and of the Newmark average again
//            under the authors' beta (Figs. 6, 7, 9, 10 under both rules);
// gamma:     Fig. 8's LME gammas at 40 cells, under this project's beta and the authors';
// baselines: today's baselines on 40, 160, 640 cells (the cubic B-spline also 2560);
// choices:   each choice of paper/09_choices.md switched on its own (dyka_choices.csv);
// energy:    every shape over 10 periods at 40 cells (the runs of tests/energy.cpp, dyka_energy.csv).
//
// The sweep stops at 2560 cells, the first mesh where particles cross cells at 1 particle per cell (crossing
// ratio 1.27): 5120 cells alone would cost more than the rest of the suite (see the smooth suite for crossing).
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "verification/dyka_case.hpp"
#include "verification/error_cost.hpp"

namespace verification::dyka {

struct CaseSpec {
  std::string name;
  std::vector<std::string> overrides;
};

const std::vector<int> sweep_cells{10, 20, 40, 80, 160, 320, 640, 1280, 2560};
const std::vector<std::string> shapes{"linear", "ugimp", "lme"}, integrators{"fe", "npc"};
const std::vector<double> gammas{0.8, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0};
const std::vector<double> large_cfls{1.0, 1.3};
const std::vector<int> large_cfl_cells{40, 160};
constexpr double speed_v0 = 5.0;                   // |v0|, m/s
constexpr double largest_displacement = 3.298e-5;  // a |v0| / c, m (paper/08_test_cases.md)

/// LME under the authors' beta (shape_settings), run as a shape of its own on `authors_cells`: every mesh of the sweep
/// in `make studies` (at 2560 cells one run takes about twice this project's LME run there); `make figures` runs it
/// on the meshes up to authors_figures_cells only (dyka_suite --part figures trims this list).
const std::string authors_lme = "lme_authors";
inline std::vector<int> authors_cells{10, 20, 40, 80, 160, 320, 640, 1280, 2560};
constexpr int authors_figures_cells = 640;
/// The shapes of the sweep with LME under both beta rules.
const std::vector<std::string> both_rules_shapes{"linear", "ugimp", "lme", authors_lme};
/// True if the sweep ran `shape` on `cells`: every mesh, but authors_lme only on authors_cells.
inline bool swept(const std::string& shape, int cells) {
  if (shape != authors_lme) return true;
  for (int n : authors_cells)
    if (n == cells) return true;
  return false;
}
/// The shape as the report and the figures name it: "LME, the authors' β" for authors_lme.
inline std::string shape_label(const std::string& shape) {
  return shape == authors_lme ? "LME, the authors' β" : shape;
}

inline std::string text(double value, const char* format = "%g") {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

/// Grid-crossing ratio of paper/08_test_cases.md: delta = u_max / d_face, d_face = h / (2 ppc), ppc = 1.
inline double crossing_ratio(int cells) { return largest_displacement / (0.5 * 0.1333 / cells); }
inline std::string band_of(int cells) {
  const double delta = crossing_ratio(cells);
  return delta < 0.1 ? "negligible" : delta < 1.0 ? "transition" : "crossing";
}
/// The meshes of the sweep in a band.
inline std::vector<int> band_cells(const std::string& band) {
  std::vector<int> cells;
  for (int n : sweep_cells)
    if (band_of(n) == band) cells.push_back(n);
  return cells;
}
/// "10-160", "2560", "none"
inline std::string cells_text(const std::vector<int>& cells) {
  if (cells.empty()) return "none";
  return cells.size() == 1 ? std::to_string(cells[0]) : std::to_string(cells.front()) + "-" + std::to_string(cells.back());
}

inline std::string sweep_name(const std::string& shape, const std::string& integrator, int cells, double cfl = 0.5) {
  return "dyka_" + (cfl == 0.5 ? std::string() : "cfl" + text(cfl) + "_") + shape + "_" + integrator + "_" + std::to_string(cells);
}
/// The fair comparison's variants: "npcavg" (Eq. 23's average), "feblend" (forward Euler with a PIC/FLIP blend).
inline std::string fair_name(const std::string& shape, const std::string& variant, int cells) {
  return "dyka_" + shape + "_" + variant + "_" + std::to_string(cells);
}
inline std::string gamma_name(const std::string& integrator, double gamma) { return "dyka_gamma_" + integrator + "_" + text(gamma); }
/// Fig. 8 again under `solver.lme_beta = "authors"`: the authors' gamma (paper/09_choices.md, 'The beta rule').
inline std::string authors_gamma_name(const std::string& integrator, double gamma) {
  return "dyka_gamma_authors_" + integrator + "_" + text(gamma);
}
inline std::string baseline_name(const std::string& method, int cells) { return "dyka_base_" + method + "_" + std::to_string(cells); }

/// A shape on a mesh: room beyond the free end, 4 cells and 1 % of the bar more on fine meshes, where grid crossing
/// can set the end particle adrift (paper/09_choices.md, 'Grid margins'); LME at gamma 3 unless stated.
inline std::vector<std::string> mesh_settings(const std::string& shape, int cells) {
  std::vector<std::string> overrides = shape_settings(shape);
  overrides.insert(overrides.end(), {"grid.cells=[" + std::to_string(cells) + "]", "grid.margin_min=[" + std::to_string(4 + cells / 100) + "]",
                                     "solver.lme_gamma=3.0", "output.snapshots=[]"});
  return overrides;
}
inline std::vector<std::string> with(std::vector<std::string> overrides, const std::vector<std::string>& more) {
  overrides.insert(overrides.end(), more.begin(), more.end());
  return overrides;
}
inline std::string integrator_setting(const std::string& integrator) { return "solver.integrator=\"" + integrator + "\""; }

/// Today's baselines beside the paper's methods (paper/08_test_cases.md, "Today's baselines"). At one particle per
/// cell the quadratic B-spline is uGIMP, which the report checks on the meshes it runs.
struct Baseline {
  std::string method;
  std::vector<std::string> settings;
  bool at_crossing;  ///< also run at 2560 cells
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
/// The meshes whose runs are timed timing_repeats (error_cost.hpp) more times, interleaved, for the error-cost fronts
/// (the others once each).
const std::vector<int> repeated_cells{40, 160};

/// The choices of paper/09_choices.md, each switched on its own on the sweep's run (or on `reference`).
struct ChoiceCase {
  std::string choice, shape, integrator;
  int cells;
  std::vector<std::string> overrides;
  std::string reference;  ///< the run it is compared with; empty: the sweep's
  std::string name() const { return "dyka_choice_" + choice + "_" + shape + "_" + integrator + "_" + std::to_string(cells); }
  std::string reference_name() const { return reference.empty() ? sweep_name(shape, integrator, cells) : reference; }
};
const std::vector<ChoiceCase> choice_cases{
    {"fe_position_start", "linear", "fe", 40, {"solver.fe_position_velocity=\"start\""}, ""},
    {"fe_position_start", "lme", "fe", 40, {"solver.fe_position_velocity=\"start\""}, ""},
    {"no_free_end_margin", "lme", "fe", 40, {"grid.margin_min=[0]"}, ""},
    {"no_free_end_margin", "lme", "fe", 2560, {"grid.margin_min=[0]"}, ""},
    {"beta_mean_neighbour_distance", "lme", "fe", 40, {"solver.lme_beta=\"mean_neighbour_distance\""}, ""},
    {"beta_mean_neighbour_distance", "lme", "npc", 40, {"solver.lme_beta=\"mean_neighbour_distance\""}, ""},
    {"beta_authors", "lme", "fe", 40, {"solver.lme_beta=\"authors\""}, ""},
    {"beta_authors", "lme", "npc", 40, {"solver.lme_beta=\"authors\""}, ""},
    {"lme_tol_1e-5", "lme", "npc", 40, {"solver.lme_tol=1e-5"}, ""},
    {"courant_sum", "linear", "fe", 40, {"solver.courant=\"sum\""}, ""},
    {"courant_sum", "linear", "npc", 40, {"solver.courant=\"sum\""}, ""},
    {"default_snapshots", "linear", "fe", 40, {"output.snapshots=[0.0, 1.0e-4, 2.0e-4]"}, ""},
    {"rigid_support_margin_gamma0.8", "lme", "npc", 40, {"grid.margin_max=[4]", "solver.lme_gamma=0.80"}, gamma_name("npc", 0.8)},
};

/// Energy over 10 periods (10 x 4L/c = 1.0551 ms) at 40 cells: every shape with both integrators at CFL 0.5, and the
/// predictor-corrector at CFL 0.1 (its loss falls with the step).
struct EnergyCase {
  std::string shape, integrator;
  double cfl;
  std::string name() const { return "dyka_energy_" + shape + "_" + integrator + "_cfl" + text(cfl); }
};
inline std::vector<EnergyCase> energy_cases() {
  std::vector<EnergyCase> cases;
  for (const auto& shape : shapes) {
    for (const auto& integrator : integrators) cases.push_back({shape, integrator, 0.5});
    cases.push_back({shape, "npc", 0.1});
  }
  return cases;
}

/// The referee's experiments (dyka_experiments.hpp). LME's gamma of Fig. 8 on a mesh without crossing, one in the
/// transition band and the crossing mesh of the sweep, with both integrators:
const std::vector<int> gamma_meshes{160, 640, 2560};
inline std::string gamma_mesh_name(const std::string& integrator, double gamma, int cells) {
  return "dyka_gammamesh_" + integrator + "_" + text(gamma) + "_" + std::to_string(cells);
}
/// The temporal order alone: the step refined at fixed h (CFL halved from 0.4 to 0.0125), against the run at
/// temporal_reference_cfl, 16 times finer than the finest, on two meshes without crossing.
const std::vector<int> temporal_cells{40, 160};
const std::vector<double> temporal_cfls{0.4, 0.2, 0.1, 0.05, 0.025, 0.0125};
constexpr double temporal_reference_cfl = 0.00078125;
inline std::vector<double> with_reference(std::vector<double> cfls) {
  cfls.push_back(temporal_reference_cfl);
  return cfls;
}
inline std::string temporal_name(const std::string& shape, const std::string& integrator, int cells, double cfl) {
  return "dyka_dt_" + shape + "_" + integrator + "_" + std::to_string(cells) + "_cfl" + text(cfl);
}
/// Grid crossing isolated: the loaded quarter's initial speed swept on one mesh so that the free end's largest
/// displacement U = |v0| (L/4) / c is the fraction U/h listed (the scene's 5 m/s gives 0.158 there); the particle next
/// to the free end reaches a cell face at U/h = 1/2.
constexpr int amplitude_cells = 640;
const std::vector<double> amplitude_ratios{0.01, 0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0};
inline double amplitude_speed(double ratio) { return ratio * (0.1333 / amplitude_cells) / largest_displacement * speed_v0; }
inline std::string amplitude_name(const std::string& shape, const std::string& integrator, double ratio) {
  return "dyka_amp_" + shape + "_" + integrator + "_" + text(ratio);
}
inline std::vector<CaseSpec> experiment_cases() {
  std::vector<CaseSpec> cases;
  for (int cells : gamma_meshes)
    for (const auto& integrator : integrators)
      for (double gamma : gammas)
        cases.push_back({gamma_mesh_name(integrator, gamma, cells),
                         with(mesh_settings("lme", cells), {integrator_setting(integrator), "solver.lme_gamma=" + text(gamma, "%.2f")})});
  for (int cells : temporal_cells)
    for (const auto& shape : shapes)
      for (const auto& integrator : integrators)
        for (double cfl : with_reference(temporal_cfls))
          cases.push_back({temporal_name(shape, integrator, cells, cfl),
                           with(mesh_settings(shape, cells), {integrator_setting(integrator), "solver.cfl=" + text(cfl)})});
  for (const auto& shape : shapes)
    for (const auto& integrator : integrators)
      for (double ratio : amplitude_ratios)
        cases.push_back({amplitude_name(shape, integrator, ratio),
                         with(mesh_settings(shape, amplitude_cells),
                              {integrator_setting(integrator), "initial_velocity[0].velocity=[" + text(-amplitude_speed(ratio), "%.17g") + "]"})});
  return cases;
}

/// Every run that depends on no other: the sweep, the large CFLs, the Newmark average, the gammas, the baselines,
/// the choices and the energy runs (the authors' beta on authors_cells as it stands).
inline std::vector<CaseSpec> independent_cases_of_both() {
  std::vector<CaseSpec> cases;
  for (int cells : sweep_cells)
    for (const auto& shape : both_rules_shapes)
      for (const auto& integrator : integrators)
        if (swept(shape, cells))
          cases.push_back({sweep_name(shape, integrator, cells),
                           with(mesh_settings(shape, cells), {integrator_setting(integrator)})});
  for (double cfl : large_cfls)
    for (int cells : large_cfl_cells)
      for (const auto& shape : both_rules_shapes)
        for (const auto& integrator : integrators)
          cases.push_back({sweep_name(shape, integrator, cells, cfl), with(mesh_settings(shape, cells), {integrator_setting(integrator), "solver.cfl=" + text(cfl)})});
  for (int cells : band_cells("negligible"))
    for (const auto& shape : both_rules_shapes)
      cases.push_back({fair_name(shape, "npcavg", cells), with(mesh_settings(shape, cells), {"solver.integrator=\"npc\"", "solver.npc_velocity=\"average\""})});
  for (const auto& integrator : integrators)
    for (double gamma : gammas) {
      const std::vector<std::string> settings{"grid.cells=[40]", "solver.shape=\"lme\"", integrator_setting(integrator),
                                              "solver.lme_gamma=" + text(gamma, "%.2f"), "output.snapshots=[]"};
      cases.push_back({gamma_name(integrator, gamma), settings});
      cases.push_back({authors_gamma_name(integrator, gamma), with(settings, {"solver.lme_beta=\"authors\""})});
    }
  for (const auto& baseline : baselines)
    for (int cells : baseline_cells)
      if (cells <= 640 || baseline.at_crossing) cases.push_back({baseline_name(baseline.method, cells), with(mesh_settings("linear", cells), baseline.settings)});
  for (const auto& c : choice_cases)
    cases.push_back({c.name(), with(with(mesh_settings(c.shape, c.cells), {integrator_setting(c.integrator)}), c.overrides)});
  for (const auto& c : energy_cases())
    cases.push_back({c.name(), with(shape_settings(c.shape), {integrator_setting(c.integrator), "solver.cfl=" + text(c.cfl),
                                                              "solver.end_time=1.0551e-3", "output.snapshots=[]"})});
  for (auto& spec : experiment_cases()) cases.push_back(std::move(spec));
  return cases;
}

/// The two parts of the suite: `make figures` (the paper's Figs. 6-10: the sweep, the large CFLs that bound its claims,
/// Fig. 8's gammas) and `make studies` (everything beyond the paper: the fair comparison, the baselines and their
/// fronts, the choices, the energy over 10 periods, the two beta rules on every mesh; the sweep again as their
/// reference, and of Fig. 8's gammas only those a choice is compared with).
enum class Part { figures, studies };

/// True if a choice of choice_cases is compared with the run `name` (e.g. a gamma of Fig. 8).
inline bool choice_reference(const std::string& name) {
  for (const auto& c : choice_cases)
    if (c.reference_name() == name) return true;
  return false;
}

/// True if the case `name` belongs to `part`.
inline bool in_part(const std::string& name, Part part) {
  auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
  if (starts("dyka_gamma_")) return part == Part::figures || choice_reference(name);
  const bool beyond = starts("dyka_base_") || starts("dyka_choice_") || starts("dyka_energy_") || starts("dyka_gammamesh_") ||
                      starts("dyka_dt_") || starts("dyka_amp_") ||
                      name.find("_npcavg_") != std::string::npos;
  return part == Part::studies || !beyond;
}

/// The independent cases of `part`.
inline std::vector<CaseSpec> independent_cases(Part part) {
  std::vector<CaseSpec> chosen;
  for (auto& spec : independent_cases_of_both())
    if (in_part(spec.name, part)) chosen.push_back(std::move(spec));
  return chosen;
}

/// Cost weight of a case for the order of the queue (longest first, so that the cores finish together).
inline double case_weight(const CaseSpec& spec) {
  int cells = 40;
  double cfl = 0.5;
  for (const auto& o : spec.overrides) {
    if (o.rfind("grid.cells=[", 0) == 0) cells = std::stoi(o.substr(12));
    if (o.rfind("solver.cfl=", 0) == 0) cfl = std::stod(o.substr(11));
  }
  const double shape = spec.name.find("_lme") != std::string::npos ? 6.0 : spec.name.find("_linear_") != std::string::npos ? 1.0 : 2.0;
  return double(cells) * cells * shape * 0.5 / cfl;
}

}  // namespace verification::dyka

#ifndef DOCTEST_CONFIG_DISABLE
#include <doctest/doctest.h>

TEST_CASE("Dyka suite's parts: Fig. 8's gammas only in make figures, the studies beyond the paper only in make studies") {
  using namespace verification::dyka;
  CHECK(in_part("dyka_gamma_npc_3", Part::figures));
  CHECK(!in_part("dyka_gamma_npc_3", Part::studies));
  // a gamma a choice is compared with runs in both (rigid_support_margin_gamma0.8 against LME gamma 0.8, NPC)
  CHECK(in_part(gamma_name("npc", 0.8), Part::studies));
  for (const auto& c : choice_cases) CHECK(in_part(c.reference_name(), Part::studies));
  for (const char* beyond : {"dyka_base_bspline3_fe_40", "dyka_choice_courant_sum_linear_fe_40", "dyka_energy_lme_npc_cfl0.1",
                             "dyka_linear_npcavg_40", "dyka_gammamesh_npc_0.8_640", "dyka_dt_lme_fe_160_cfl0.05", "dyka_amp_ugimp_npc_1.5"}) {
    CHECK(!in_part(beyond, Part::figures));
    CHECK(in_part(beyond, Part::studies));
  }
  // the sweep is both parts': the figures' data, the studies' reference
  CHECK(in_part("dyka_lme_npc_2560", Part::figures));
  CHECK(in_part("dyka_lme_npc_2560", Part::studies));
  // every case runs in one part at least, and neither part runs them all
  const auto all = independent_cases_of_both();
  int in_neither = 0;
  for (const auto& spec : all) in_neither += !in_part(spec.name, Part::figures) && !in_part(spec.name, Part::studies);
  CHECK(in_neither == 0);
  CHECK(independent_cases(Part::figures).size() < all.size());
  CHECK(independent_cases(Part::studies).size() < all.size());
}
#endif
