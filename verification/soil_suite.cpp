// The soil block (paper section 3.2, paper/08_test_cases.md, paper/07_exact_column.md) in two parts: `make figures`
// runs the paper's Figs. 11-13 on its 2 m grid (--part figures: every shape function with NPC and FE, and FE's stress
// updates USL and MUSL); `make studies` runs everything beyond the paper (--part studies: the error-cost fronts of today's
// baselines with repeated timings, the refinement to 1 and 0.5 m cells, cell crossing, nu = 0.3, the stability sweep, the
// boundaries, free sides), and the 2 m grid's runs again for its comparisons. Each part runs its cases in parallel on the
// machine's cores, writes its data as CSV into DATA_DIR (files soil_*.csv) and its report fragment REPORT (Markdown) with
// each claim, the numbers we measured and whether it holds. Exits 1 when a hard check (a bound of the theory) fails.
//
//   build/bin/soil_suite DATA_DIR REPORT SCENES_DIR --part figures|studies [--threads N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "verification/parallel.hpp"
#include "verification/claims.hpp"
#include "verification/soil_data.hpp"
#include "verification/soil_domain.hpp"
#include "verification/soil_gamma.hpp"
#include "verification/soil_plane.hpp"
#include "verification/soil_report.hpp"

namespace {

using verification::Claim;
using verification::DomainClaim;
using verification::number;
using verification::run_name;

struct CaseSpec {
  std::string name;
  std::string scene_file;  ///< in SCENES_DIR
  std::vector<std::string> overrides;
  bool must_complete = false;  ///< a run of the 2 m grid, nu = 0.3 or free sides: failing it is a hard failure
};

/// Which target's part of the suite runs (`--part`).
enum class Part { figures, studies };

// The shape functions of Fig. 13, all on a grid whose edges are the walls and the base
// (scenes/soil_block.toml): LME interpolates there, so the fixed nodes hold the particles, and
// uGIMP clips its particle domains there (shape/ugimp.hpp). Rigid margin rows behind the walls
// are a case of their own for LME ("_wall_margins").
const std::vector<std::string> methods{"linear", "ugimp", "lme0.8", "lme3", "bspline2", "bspline3"};
/// The paper's shape functions of Fig. 13 (make figures); the B-splines are today's baselines (make studies).
const std::vector<std::string> paper_methods{"linear", "ugimp", "lme0.8", "lme3"};
/// Today's baselines of forward Euler: the stress updated last (USL) and the modified update (MUSL), with linear shapes
/// and the quadratic B-spline, on the paper's 2 m grid; its CFL 0.1 lies far below USL's limit (mpm/stability.hpp).
const std::vector<std::string> stress_updates{"linear_usl", "linear_musl", "bspline2_usl", "bspline2_musl"};
/// Forward Euler under refinement, beside the predictor-corrector's: USF (the default), USL and MUSL, with linear shapes and
/// the quadratic B-spline.
const std::vector<std::string> fe_refined{"linear", "linear_usl", "linear_musl", "bspline2", "bspline2_usl", "bspline2_musl"};
const std::vector<std::string> wall_margins{"grid.margin_min=[1,1]", "grid.margin_max=[1,0]"};

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<std::string> method_overrides(const std::string& method) {
  const auto update = method.find('_');  // "linear_usl": a shape and forward Euler's stress update
  if (update != std::string::npos)
    return join(method_overrides(method.substr(0, update)), {"solver.stress_update=\"" + method.substr(update + 1) + "\""});
  if (method == "linear") return {"solver.shape=\"linear\""};
  if (method == "ugimp") return {"solver.shape=\"ugimp\""};
  if (method == "bspline2" || method == "bspline3") return {"solver.shape=\"" + method + "\""};
  return {"solver.shape=\"lme\"", "solver.lme_gamma=" + method.substr(3)};  // "lme0.8", "lme3"
}

/// Cells of size h over the 10 m block, 2 x 2 particles per cell; the observer is the top-row particle
/// at x = W/2 - h/4 (the nearer of the two next to the middle, as (4.5, 9.5) for h = 2 m).
std::vector<std::string> cell_overrides(double h) {
  const int cells = static_cast<int>(std::lround(10.0 / h));
  char observer[96];
  std::snprintf(observer, sizeof observer, "observer[0].position=[%.6g,%.6g]", 5.0 - h / 4.0, 10.0 - h / 4.0);
  return {"grid.cells=[" + std::to_string(cells) + "," + std::to_string(cells) + "]", observer};
}

const std::vector<double> refinement{2.0, 1.0, 0.5};
/// CFL numbers of the stability sweep (LME gamma = 3, NPC, 2 m cells), for nu = 0 and nu = 0.3.
const std::vector<double> sweep_cfl{1.0, 1.05, 1.1, 1.15, 1.2, 1.25, 1.3, 1.35, 1.4, 1.45, 1.5};
std::string sweep_name(double nu, double cfl) { return "lme3_npc_h2_nu" + number(nu, "%g") + "_cfl" + number(cfl, "%g"); }

/// The 2 m grid's runs of `shapes` with NPC and with FE (USF); with the baselines also FE's stress updates USL and MUSL.
std::vector<CaseSpec> grid_cases(const std::vector<std::string>& shapes, bool baselines) {
  std::vector<CaseSpec> cases;
  for (const auto& integrator : {"npc", "fe"})
    for (const auto& method : shapes)
      cases.push_back({run_name(method, integrator, 2.0), "soil_block.toml",
                       join(method_overrides(method), {std::string("solver.integrator=\"") + integrator + "\""}), true});
  if (baselines)
    for (const auto& method : stress_updates)
      cases.push_back({run_name(method, "fe", 2.0), "soil_block.toml", join(method_overrides(method), {"solver.integrator=\"fe\""}), true});
  return cases;
}

/// Figs. 12 and 13 on the paper's 2 m grid: the paper's shape functions with NPC and with FE.
std::vector<CaseSpec> figure_cases() { return grid_cases(paper_methods, false); }

/// make studies: the refinement (most expensive first, so that the threads finish together), the 2 m grid's runs of
/// figure_cases() again with today's baselines (the B-splines, USL, MUSL), nu = 0.3, free sides, the wall margins and the stability sweep.
std::vector<CaseSpec> study_cases() {
  std::vector<CaseSpec> cases;
  for (double h : {0.5, 1.0})  // refinement, predictor-corrector (h = 2 m is the paper's grid, below)
    for (const auto& method : {"lme0.8", "lme3", "bspline3", "bspline2", "ugimp", "linear"})
      cases.push_back({run_name(method, "npc", h), "soil_block.toml", join(method_overrides(method), cell_overrides(h))});
  for (double h : {0.5, 1.0})  // refinement, forward Euler with each stress update (h = 2 m: below)
    for (const auto& method : fe_refined)
      cases.push_back({run_name(method, "fe", h), "soil_block.toml",
                       join(join(method_overrides(method), {"solver.integrator=\"fe\""}), cell_overrides(h))});
  for (auto& spec : grid_cases(methods, true)) cases.push_back(std::move(spec));
  cases.push_back({"lme3_npc_h2_nu0.3", "soil_block.toml", {"material.poisson_ratio=0.3"}, true});
  cases.push_back({"lme3_npc_h2_nu0.3_wall_margins", "soil_block.toml", join({"material.poisson_ratio=0.3"}, wall_margins)});
  cases.push_back({"lme3_npc_h2_free_sides", "soil_block_free_sides.toml", {}, true});
  // snapshots over the last period of the column at nu = 0.3 (T1 = 1.19 s), averaged by the equilibrium check (soil_plane.hpp)
  cases.push_back({"lme3_npc_h2_free_sides_nu0.3", "soil_block_free_sides.toml",
                   {"material.poisson_ratio=0.3", "output.snapshots=[0,18.8,18.95,19.1,19.25,19.4,19.55,19.7,19.85,20]"}, true});
  for (const auto& method : verification::soil_gamma_methods())  // LME's gamma on the 2 m grid (0.8 and 3 run above)
    if (method != "lme0.8" && method != "lme3")
      for (const auto& integrator : {"npc", "fe"})
        cases.push_back({run_name(method, integrator, 2.0), "soil_block.toml",
                         join(method_overrides(method), {std::string("solver.integrator=\"") + integrator + "\""})});
  for (const auto& method : {"lme0.8", "lme3"})
    cases.push_back({run_name(method, "npc", 2.0) + "_wall_margins", "soil_block.toml", join(method_overrides(method), wall_margins)});
  for (double nu : {0.0, 0.3})
    for (double cfl : sweep_cfl)
      cases.push_back({sweep_name(nu, cfl), "soil_block.toml",
                       {"material.poisson_ratio=" + number(nu, "%g"), "solver.cfl=" + number(cfl, "%g"), "output.snapshots=[]"}});
  return cases;
}

using Outcome = verification::SoilOutcome;

/// "name (x.x s)" of the run that took longest.
std::string slowest(const std::vector<Outcome>& outcomes) {
  const Outcome* worst = &outcomes.front();
  for (const auto& o : outcomes)
    if (o.result.solver_seconds > worst->result.solver_seconds) worst = &o;
  return worst->result.name + " (" + number(worst->result.solver_seconds, "%.1f") + " s)";
}


/// The report's opening: the set-up, the choices where the paper is silent, the finite-strain gap, the wall time.
void write_introduction(std::ostream& report, Part part, const Outcome& paper, size_t runs, double runs_seconds, double suite_seconds,
                        unsigned threads, const std::string& slowest_run) {
  report << (part == Part::figures ? "## Soil block under ramped gravity (paper section 3.2, Figs. 11-13)\n\n"
                                   : "## Soil block beyond the paper (section 3.2)\n\n")
         << "A 10 m x 10 m elastic block in plane strain (E = 5 MPa, rho = 6000 kg/m^3, nu = 0), 2 m cells with 2 x 2 particles "
            "at the quarter points, on a frictionless base between frictionless walls (`scenes/soil_block.toml`; free sides: "
            "`scenes/soil_block_free_sides.toml`), under gravity ramped by Eq. (44) over 10 s (T = 20 s) and evaluated at the end "
            "of each step, to t = 20 s with CFL 0.1 on sqrt(E/rho) (Eq. 42). The exact solution is the 1D column of paper/07_exact_column.md "
            "(`mpm/exact/column.hpp`), evaluated at each particle's reference height Y, with the ramp g(t) of Eq. (44) "
            "continuous in time; the solver's gravity at the end of each step shifts the load by dt/2 = 3.5 ms (u changes "
            "in the fifth digit when it is evaluated at the start instead).\n\n"
         << "Choices where the paper is silent: nu = 0 and lateral rollers (paper/09_choices.md); particles at the quarter points "
            "(the top row at Y = 9.5 m; the authors' post-processing script reads its top particle at the Gauss point 9.577 m); the observed particle "
            "is the top-row particle at (4.5, 9.5) m (4.5 and 5.5 are equally near W/2; we take the first); no grid margins, "
            "so the walls and base are the edges of the grid, where LME interpolates and uGIMP's particle domains are clipped "
            "to the grid (the domain's part inside the grid, `mpm/shape/ugimp.hpp`).\n\n"
         << "**Finite strain.** The strain at the base reaches rho g H / E = 12 %. The solver is updated Lagrangian: it "
            "accumulates the strain from the velocity gradient on the current configuration (Eq. 16), i.e. the logarithmic "
            "strain, with Hooke's law on it. Its static column (`mpm/exact/column_log_strain.hpp`) has the same stress "
            "sigma(Y) = -rho g (H - Y) but settles "
         << verification::metres(-verification::log_strain_column(paper.result.scene).displacement(10.0))
         << " at the top instead of the small-strain 0.5886 m the paper quotes: 3.8 % less. "
         << (part == Part::figures ? "Which runs converge to it is make studies' grid refinement (1 and 0.5 m cells); "
                                   : "Which runs converge to it, and on which grids, is the refinement below; ")
         << "every comparison with the small-strain exact solution carries that model gap, and the tolerances include it.\n\n"
         << "Wall time: " << runs << " runs in " << number(runs_seconds, "%.1f") << " s on " << threads << " threads (the whole suite "
         << number(suite_seconds, "%.1f") << " s); per run in `data/soil_summary.csv`. The paper's block (LME gamma = 3, NPC, 2 m) took "
         << number(paper.result.solver_seconds, "%.2f") << " s for " << paper.result.steps << " steps; the slowest run, "
         << slowest_run << ".\n\n";
}

/// Fig. 13's table: one row per shape function and integrator on the 2 m grid.
void write_fig13_table(std::ostream& report, Part part, const verification::SoilLookup& get) {
  const auto& shapes = part == Part::figures ? paper_methods : methods;
  report << "| shape | integrator | u(20 s) | exact u(20 s) | error | RMS over 0-20 s (Eq. 43) | mean after the ramp | "
            "swing after the ramp (exact) | energy drift after the ramp | sigma_yy RMS at 20 s | wall time |\n"
         << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string integrator : {"npc", "fe"})
    for (const auto& method : integrator == "fe" && part == Part::studies ? join(methods, stress_updates) : shapes) {
      const auto& o = get(run_name(method, integrator, 2.0));
      const auto& s = o.settlement;
      const std::string stress = o.result.snapshots.size() == 3
                                     ? verification::percent(verification::measure_stress(o.result, o.result.snapshots[2]).rms_relative)
                                     : std::string("-");
      report << "| " << verification::method_label(method) << " | " << integrator << " | " << verification::metres(s.final_displacement)
             << " | " << verification::metres(s.exact_final) << " | " << verification::metres(s.final_error) << " | "
             << verification::metres(s.rms_error) << " | " << verification::metres(s.mean_settlement) << " | "
             << number(1e3 * s.swing, "%.1f") << " mm (" << number(1e3 * s.exact_swing, "%.1f") << " mm) | "
             << verification::percent(s.energy_drift) << " | " << stress << " | " << number(o.result.solver_seconds, "%.2f") << " s |\n";
    }
  report << "\n\"Mean\" and \"swing\" are the time average and the range (max - min) of u over the last four periods "
            "T1 = 4H/c = 1.386 s of the run; \"energy drift\" is the range of kinetic + strain + gravity potential energy "
            "over t >= 10 s, relative to the strain energy; \"sigma_yy RMS\" is over the particles, relative to rho g H, "
            "against the exact sigma_yy(Y, 20 s). Linear shape functions with forward Euler (USF): after the ramp the energy grows by "
            "tens of percent under constant gravity and the top particle rises, once the row of particles below the top one has "
            "crossed y = 8 m during the ramp. "
         << (part == Part::figures
                 ? "Whether crossing makes the energy grow is make studies' section on cell crossing, which counts the crossings of "
                   "every linear run. "
                 : "Particles cross cell faces in every linear run, with the predictor-corrector, USL and MUSL too, whose energy "
                   "drifts by under 1 % on the same grid: crossing alone does not make the energy grow here (the claims on the "
                   "refinement below count the crossings of every linear run). ")
         << "The FEM reference of the paper (the authors' code) is not available; the exact solution replaces it.\n\n";
}

/// The refinement table: one row per method and cell size, with the given integrator.
void write_refinement_table(std::ostream& report, const verification::SoilLookup& get, const std::vector<std::string>& methods,
                            const std::string& integrator) {
  report << "Errors of the top particle (Y = H - h/4): RMS of u - u_exact over 0-20 s and u - u_exact at 20 s against "
            "the small-strain exact solution, and mean after the ramp - finite-strain static settlement.";
  if (integrator == "npc")
    report << " Against the small-strain solution the errors do not fall with h: they tend to the model gap, 0.022 m at the top (on "
              "the 2 m grid the discretisation error, which adds settlement, partly offsets it).";
  report << " " << verification::refinement_summary(get, methods, refinement, integrator)
         << " *Floor*: the range of the mean after the ramp as its 4-T1 window's end moves back over one T1; a change of the gap "
            "within the two runs' floors is not resolved.";
  report << "\n\n| shape | h | RMS | error at 20 s | mean - finite-strain static | floor | particles crossed | steps | wall time | "
            "status |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& method : methods)
    for (double h : refinement) {
      const auto& o = get(run_name(method, integrator, h));
      const auto& s = o.settlement;
      report << "| " << verification::method_label(method) << " | " << number(h, "%g") << " m | " << verification::metres(s.rms_error)
             << " | " << verification::metres(s.final_error) << " | "
             << (o.result.failed ? std::string("-") : verification::metres(s.mean_settlement - s.static_log_strain)) << " | "
             << (o.result.failed ? std::string("-") : verification::metres(s.mean_floor)) << " | " << o.result.particles_crossed << " | "
             << o.result.steps << " | " << number(o.result.solver_seconds, "%.2f") << " s | "
             << (o.result.failed ? o.result.failure : "ok") << " |\n";
    }
  report << "\n";
}

/// make studies' data: nu = 0.3's stresses at 20 s and the refinement of each method.
void write_study_data(const verification::SoilLookup& get, const std::string& folder) {
  const Outcome& poisson = get("lme3_npc_h2_nu0.3");
  if (!poisson.result.snapshots.empty())
    verification::write_particle_stress(poisson.result, poisson.result.snapshots.back(), folder + "/soil_poisson_t20.csv");
  auto write_refinement = [&](const std::string& method, const std::string& integrator, const std::string& file) {
    std::vector<const Outcome*> sizes;
    for (double h : refinement) sizes.push_back(&get(run_name(method, integrator, h)));
    verification::write_refinement(sizes, folder + "/" + file);
  };
  for (const auto& method : methods) write_refinement(method, "npc", "soil_refinement_" + method + ".csv");
  for (const auto& method : fe_refined) write_refinement(method, "fe", "soil_refinement_" + method + "_fe.csv");
}

/// The data of the figures: the geometry, every settlement history, Fig. 12's stresses, the summary; in make studies
/// nu = 0.3 and the refinement.
void write_figure_data(Part part, const std::vector<Outcome>& outcomes, const verification::SoilLookup& get, const std::string& scenes,
                       const std::string& folder) {
  verification::write_summary(outcomes, folder + "/soil_summary.csv");
  for (const auto& outcome : outcomes)
    verification::write_settlement(outcome.result, outcome.settlement, folder + "/soil_settlement_" + outcome.result.name + ".csv");
  if (part == Part::studies) return write_study_data(get, folder);
  verification::write_geometry(mpm::load_scene(scenes + "/soil_block.toml", {}), folder);
  const Outcome& paper = get("lme3_npc_h2");  // Fig. 12: LME gamma = 3, NPC, CFL 0.1
  for (const auto& snap : paper.result.snapshots) {
    const std::string tag = number(snap.time, "%g");
    verification::write_particle_stress(paper.result, snap, folder + "/soil_stress_t" + tag + ".csv");
    verification::write_stress_profile(paper.result.scene, snap.time, folder + "/soil_stress_profile_t" + tag + ".csv");
  }
}

/// The claims of the report, by kind: the paper's and the theory's as one verdict each, and those over a study's domain.
struct SuiteClaims {
  std::vector<Claim> fig12, fig13, baselines, poisson, stability, boundary, mass;
  std::vector<DomainClaim> fig13_domain, refined, refined_fe, finest, crossing, lme3, plane, sweep, completes;
};

/// The runs of the 2 m grid's error-cost fronts (the baselines' comparison): every shape with NPC and FE, and FE's
/// stress updates.
std::vector<std::string> front_runs() {
  std::vector<std::string> names;
  for (const std::string integrator : {"npc", "fe"})
    for (const auto& method : methods) names.push_back(run_name(method, integrator, 2.0));
  for (const auto& method : stress_updates) names.push_back(run_name(method, "fe", 2.0));
  return names;
}

/// The claims of make studies: the baselines' fronts, the refinement, crossing, nu = 0.3, the boundaries, the plane check,
/// the stability sweep.
void evaluate_study_claims(const verification::SoilLookup& get, SuiteClaims& c) {
  const Outcome& poisson = get("lme3_npc_h2_nu0.3");
  c.baselines = verification::baseline_claims(get, methods, stress_updates);
  c.refined = {verification::refinement_domain_claim(get, methods, refinement, "npc"),
               verification::finest_gap_claim(get, methods, refinement.back(), "npc")};
  c.refined_fe = {verification::refinement_domain_claim(get, fe_refined, refinement, "fe"),
                  verification::finest_gap_claim(get, fe_refined, refinement.back(), "fe")};
  c.crossing = verification::crossing_claims(get, refinement);
  c.lme3 = verification::lme3_convergence_claims(get, refinement);
  std::vector<const Outcome*> timed;
  for (const auto& name : front_runs()) timed.push_back(&get(name));
  c.finest = verification::finest_grid_claims(get, methods, fe_refined, refinement.back(), verification::timing_spread(timed));
  c.poisson = verification::poisson_claims(poisson, get("lme3_npc_h2_nu0.3_wall_margins"));
  c.boundary = verification::boundary_claims(get);
  c.plane = verification::plane_claims(get("lme3_npc_h2_free_sides_nu0.3"), verification::stress_tolerance);
  c.stability = verification::stability_claims(get, poisson, sweep_cfl, sweep_name);
  c.sweep = {verification::stability_sweep_claim(get, sweep_cfl, sweep_name)};
}

/// The claims of a part: Figs. 12 and 13 in make figures, everything beyond the paper in make studies; the hard checks
/// of its runs in both.
SuiteClaims evaluate_claims(Part part, const std::vector<CaseSpec>& cases, const std::vector<Outcome>& outcomes,
                            const verification::SoilLookup& get) {
  SuiteClaims c;
  if (part == Part::figures) {
    c.fig12 = verification::fig12_claims(get("lme3_npc_h2"));
    c.fig13 = {verification::fig13_settlement_claim(get)};
    c.fig13_domain = verification::fig13_claims(get, paper_methods, {});
  } else {
    c.fig13_domain = verification::fig13_claims(get, methods, stress_updates);
    evaluate_study_claims(get, c);
  }
  std::vector<const Outcome*> paper_runs, all_runs;
  for (size_t k = 0; k < cases.size(); ++k) {
    all_runs.push_back(&outcomes[k]);
    if (cases[k].must_complete) paper_runs.push_back(&outcomes[k]);
  }
  c.completes = {verification::completes_claim(part == Part::figures ? "Figs. 12-13"
                                                                     : "the 2 m grid (every shape with NPC and FE; USL, MUSL), nu = 0.3 and free sides",
                                               paper_runs)};
  c.mass = {verification::mass_claim(all_runs)};
  return c;
}

/// Figs. 11-13 on the paper's grid (make figures).
void write_paper_sections(std::ostream& report, const verification::SoilLookup& get, const SuiteClaims& c) {
  report << "### Fig. 11: geometry, grid and boundary conditions\n\n"
         << "![Fig. 11](figures/soil_fig11_geometry.png)\n\n"
         << "Drawn from `scenes/soil_block.toml` through the solver's own set-up (`build_setup`): grid lines, the 100 "
            "particles, the fixed degrees of freedom (v_y = 0 on the base, v_x = 0 on the walls) and the observed particle.\n\n";
  report << "### Fig. 12: sigma_yy at t = 0, 5 and 20 s (LME gamma = 3, NPC, CFL 0.1)\n\n"
         << "![Fig. 12](figures/soil_fig12_stress.png)\n\n"
         << "Left: sigma_yy on the particles at their current positions, one colour scale. Middle: the particles' sigma_yy "
            "against their current height, with the exact sigma_yy(Y, t) drawn at the exact current height Y + u(Y, t) "
            "(and, at 20 s, the finite-strain static column, which lies under it). Right: the particles' sigma_yy minus "
            "the exact one at their reference height Y, and at 20 s the finite-strain static column minus the "
            "small-strain one on its own top axis (under 1 kPa: the two columns coincide at the middle panel's scale).\n\n";
  verification::write_claims(report, c.fig12);
  report << "### Fig. 13: vertical displacement of the top particle (4.5, 9.5) m\n\n"
         << "![Fig. 13](figures/soil_fig13_settlement.png)\n\n"
         << "The paper's four shape functions; top: the predictor-corrector, bottom: forward Euler; left: 0-20 s, right: the "
            "dashed box on the left (t = 10-20 s) enlarged, with the static settlement of the finite-strain column (grey, "
            "dotted). "
            "Today's baselines on the same grid (the B-splines, USL, MUSL) are make studies'.\n\n";
  write_fig13_table(report, Part::figures, get);
  verification::write_domain_claims(report, c.fig13_domain);
  verification::write_claims(report, c.fig13);
}

/// Today's baselines on the paper's grid (make studies): the Fig. 13 table again, and the error-cost fronts.
void write_baseline_section(std::ostream& report, const verification::SoilLookup& get, const SuiteClaims& c) {
  report << "### Today's baselines on the paper's 2 m grid: B-splines, USL and MUSL\n\n"
         << "Every run of make figures' Fig. 13 table, repeated here, with forward Euler's stress updated last (USL) or by the modified update (MUSL) "
            "beside the default (USF). Cost: the run's CPU time (one thread per run), " << verification::timing_repeats
         << " more runs of each, interleaved, after the suite's runs; a run is off the front only when another is more accurate "
            "and faster by more than the range of their repeats (the table's wall time is the first run's time-step loop).\n\n";
  write_fig13_table(report, Part::studies, get);
  verification::write_domain_claims(report, c.fig13_domain);
  verification::write_claims(report, c.baselines);
}

/// The refinement with NPC and with forward Euler's stress updates, and the linear runs' crossings against their energy.
void write_refinement_sections(std::ostream& report, const verification::SoilLookup& get, const SuiteClaims& c) {
  report << "### Beyond the paper: grid refinement (2, 1, 0.5 m cells, 2 x 2 particles per cell, NPC)\n\n"
         << "![refinement](figures/soil_refinement.png)\n\n";
  write_refinement_table(report, get, methods, "npc");
  verification::write_domain_claims(report, c.refined);
  verification::write_domain_claims(report, c.lme3);
  report << "### Beyond the paper: forward Euler's stress updates under refinement (USF, USL, MUSL)\n\n"
         << "The same grids with forward Euler, its stress updated first (USF, the default), last (USL) or by the modified update (MUSL), "
            "with linear shapes and the quadratic B-spline. Cost (the claim after the table): each run's CPU time, one run each, "
            "widened by the largest relative spread of the 2 m grid's repeats (these runs take seconds; the table's wall time is the "
            "time-step loop's).\n\n";
  write_refinement_table(report, get, fe_refined, "fe");
  verification::write_domain_claims(report, c.refined_fe);
  verification::write_domain_claims(report, c.finest);
  report << "### Beyond the paper: cell crossing and the energy of linear shapes\n\n"
         << "Every run with linear shapes (NPC; forward Euler with USF, USL, MUSL) on every grid, with the particles that left "
            "their initial cell at some sample (every 10 steps) and the energy drift after the ramp.\n\n";
  verification::write_domain_claims(report, c.crossing);
}

/// nu = 0.3, the stability sweep, the boundaries and the run-level hard checks.
void write_other_sections(std::ostream& report, const SuiteClaims& c) {
  report << "### Beyond the paper: nu = 0.3 with lateral rollers\n\n"
         << "![nu = 0.3](figures/soil_poisson.png)\n\n"
         << "The figure: left, sigma_xx against sigma_yy on every particle at 20 s beside sigma_xx = nu/(1-nu) sigma_yy, "
            "and below each particle's relative difference from that line; right, the top particle's u_y(t) beside the "
            "exact column and the finite-strain static settlement, and below u_y - u_exact. "
            "The exact column uses the constrained modulus M = E(1-nu)/((1+nu)(1-2nu)) = 6.73 MPa; Eq. (42) still uses "
            "sqrt(E/rho) = 28.9 m/s, slower than the P-wave speed sqrt(M/rho) = 33.5 m/s.\n\n";
  verification::write_claims(report, c.poisson);
  verification::write_claims(report, c.stability);
  verification::write_domain_claims(report, c.sweep);
  report << "### Beyond the paper: boundaries\n\n"
         << "LME interpolates only on the boundary of the convex hull of the nodes. With a rigid margin row behind a wall, "
            "the wall's own nodes are inside the hull, where the LME functions of the free nodes beyond "
            "them do not vanish, so the particles next to the wall move with those nodes: the wall yields. The wider the "
            "support (smaller gamma), the more it yields.\n\n";
  verification::write_claims(report, c.boundary);
  report << "### Beyond the paper: a check that is not one-dimensional (free sides, nu = 0.3)\n\n"
         << "Every check above is one-dimensional by construction: with lateral rollers (and with free sides at nu = 0) every "
            "particle of a row moves alike, and the 2D block is the 1D column of the exact solution; they test the 2D kernels "
            "on a 1D field. With free sides and nu = 0.3 (`scenes/soil_block_free_sides.toml`, LME gamma = 3, NPC, 2 m cells) "
            "the block spreads sideways, more at the top than at the frictionless base: u_x varies with x and y and sigma_yy "
            "along each row, and no closed form is known. Two exact statements remain: the rows carry the weight above them "
            "(equilibrium of the part above a material line whose ends are traction-free), and the mirror symmetry about "
            "x = W/2.\n\n";
  verification::write_domain_claims(report, c.plane);
}

/// Whether every hard claim holds; each one that does not is printed.
bool hard_checks_pass(const SuiteClaims& c) {
  std::vector<Claim> every;
  for (const auto* group : {&c.fig12, &c.fig13, &c.baselines, &c.poisson, &c.stability, &c.boundary, &c.mass})
    every.insert(every.end(), group->begin(), group->end());
  std::vector<DomainClaim> domain;
  for (const auto* group : {&c.fig13_domain, &c.refined, &c.refined_fe, &c.finest, &c.crossing, &c.lme3, &c.plane, &c.sweep, &c.completes})
    domain.insert(domain.end(), group->begin(), group->end());
  for (const Claim& claim : every)
    if (claim.hard && !claim.holds) std::fprintf(stderr, "soil_suite: hard check failed: %s: %s\n", claim.text.c_str(), claim.measured.c_str());
  for (const DomainClaim& claim : domain)
    if (claim.hard && (claim.samples.empty() || claim.count(false) > 0))
      std::fprintf(stderr, "soil_suite: hard check failed: %s: %s\n", claim.statement.c_str(), verification::places(claim, false).c_str());
  return verification::hard_claims_hold(every) && verification::hard_claims_hold(domain);
}

/// Every case after each scene with its overrides has been read without error; false (and a message) if one cannot be.
bool run_all(const std::vector<CaseSpec>& cases, const std::string& scenes, unsigned cores, std::vector<Outcome>& outcomes) {
  for (const auto& spec : cases) {
    try {
      verification::require_fast_kernels(mpm::load_scene(scenes + "/" + spec.scene_file, spec.overrides),
                                         scenes + "/" + spec.scene_file);
    } catch (const mpm::SceneError& error) {
      std::fprintf(stderr, "soil_suite: case %s: %s\n", spec.name.c_str(), error.message().c_str());
      return false;
    }
  }
  outcomes.assign(cases.size(), Outcome{});
  std::vector<std::string> names;
  for (const auto& spec : cases) names.push_back(spec.name);
  // Every case on one thread (see verification/parallel.hpp, run_cases, for why).
  const std::vector<bool> wide(cases.size(), false);
  verification::run_cases("soil", names, wide, cores, [&](size_t k, int threads) {
    outcomes[k].result = verification::run_soil_case(scenes + "/" + cases[k].scene_file, cases[k].name, cases[k].overrides, threads);
    outcomes[k].settlement = verification::measure_settlement(outcomes[k].result);
  });
  return true;
}

/// The runs of the 2 m grid's fronts, each verification::timing_repeats times more: every round runs each of them
/// once, in an order rotated from round to round, `cores` at a time on one thread each; their CPU times are kept.
void time_repeats(const std::vector<CaseSpec>& cases, const std::string& scenes, unsigned cores, std::vector<Outcome>& outcomes) {
  std::vector<size_t> timed, which;
  for (const auto& name : front_runs())
    for (size_t k = 0; k < cases.size(); ++k)
      if (cases[k].name == name) timed.push_back(k);
  std::vector<std::string> names;
  for (int round = 0; round < verification::timing_repeats; ++round)
    for (size_t k = 0; k < timed.size(); ++k) {
      which.push_back(timed[(k + static_cast<size_t>(round) * 3) % timed.size()]);
      names.push_back("soil_timing_" + std::to_string(round));
    }
  std::vector<double> cpu(names.size());
  verification::run_cases("soil", names, std::vector<bool>(names.size(), false), cores, [&](size_t k, int threads) {
    const CaseSpec& spec = cases[which[k]];
    cpu[k] = verification::run_soil_case(scenes + "/" + spec.scene_file, spec.name, spec.overrides, threads).cpu_seconds;
  });
  for (size_t k = 0; k < names.size(); ++k) outcomes[which[k]].cpu_repeats.push_back(cpu[k]);
}

}  // namespace

int main(int argc, char** argv) {
  const unsigned cores = verification::suite_threads(argc, argv);
  const int part_number = verification::suite_part(argc, argv);
  if (argc != 4 || cores == 0 || part_number == 0) {
    std::fprintf(stderr, "usage: soil_suite DATA_DIR REPORT SCENES_DIR --part figures|studies [--threads N]\n");
    return 2;
  }
  const Part part = part_number == 1 ? Part::figures : Part::studies;
  const std::string folder = argv[1], report_path = argv[2], scenes = argv[3];
  const auto suite_start = std::chrono::steady_clock::now();
  const auto cases = part == Part::figures ? figure_cases() : study_cases();
  std::vector<Outcome> outcomes;
  if (!run_all(cases, scenes, cores, outcomes)) return 2;
  if (part == Part::studies) time_repeats(cases, scenes, cores, outcomes);
  std::map<std::string, const Outcome*> by_name;
  for (const auto& outcome : outcomes) by_name[outcome.result.name] = &outcome;
  const verification::SoilLookup get = [&](const std::string& name) -> const Outcome& { return *by_name.at(name); };
  const double runs_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - suite_start).count();

  write_figure_data(part, outcomes, get, scenes, folder);
  const SuiteClaims claims = evaluate_claims(part, cases, outcomes, get);
  const double suite_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - suite_start).count();
  std::ofstream report(report_path);
  write_introduction(report, part, get("lme3_npc_h2"), outcomes.size(), runs_seconds, suite_seconds, cores, slowest(outcomes));
  if (part == Part::figures) {
    write_paper_sections(report, get, claims);
  } else {
    write_baseline_section(report, get, claims);
    write_refinement_sections(report, get, claims);
    write_other_sections(report, claims);
    verification::write_soil_gamma_section(report, get, folder);
  }
  report << "### Soil block: hard checks of the runs\n\n";
  verification::write_domain_claims(report, claims.completes);
  verification::write_claims(report, claims.mass);
  const bool passed = hard_checks_pass(claims);
  std::printf("soil_suite: %zu runs in %.1f s, hard checks %s\n", outcomes.size(), suite_seconds, passed ? "hold" : "FAILED");
  return passed ? 0 : 1;
}
