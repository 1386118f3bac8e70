// The smooth-data part of `make studies`: the vibrating bar's convergence per shape function, integrator,
// amplitude, particles per cell and CFL; the grid-crossing error isolated (error against amplitude / h on a fixed
// mesh); the 2D manufactured solutions; the Dyka bar at 2 particles per cell; each with today's baselines beside the
// paper's methods (B-splines, USL and MUSL, and LME at small gamma in the two crossing studies). The studies are
// data (smooth_study.hpp), run in parallel (smooth_runs.hpp); one analysis function per figure evaluates each claim
// on every run of its study (smooth_bar_claims.hpp, smooth_crossing_claims.hpp, smooth_fig6_2ppc.hpp). Writes the
// data of each figure as CSV into DATA_DIR and the report fragment REPORT (Markdown). Exit code 1 when a hard check
// (a bound the theory gives) fails anywhere in its domain.
//
//   build/bin/smooth_suite DATA_DIR REPORT BAR_SCENE DYKA_SCENE MANUFACTURED_SCENE
//   build/bin/smooth_suite --fig6-2ppc DATA_DIR REPORT   (after the Dyka suite: Fig. 6 at 1 and 2 ppc)
//
// Errors: RMS over every particle at T/4, T/2, 3T/4 and T of v_p - v(X_p, t), divided by V, and of
// sigma_p - sigma(X_p, t), divided by Z V, against the exact first mode (small amplitude) or the
// finite-strain reference (large amplitude).

#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include "verification/smooth_bar_claims.hpp"
#include "verification/smooth_cost.hpp"
#include "verification/smooth_crossing_claims.hpp"
#include "verification/smooth_report.hpp"

namespace {

using namespace verification::smooth;
using verification::BarScene;
using verification::DomainClaim;
using verification::number;

/// A section of the report: its title, its figure (or none), its claims, any text after them and what the figure draws.
struct Section {
  std::string title, figure;
  std::vector<DomainClaim> claims;
  std::string after, drawn;
};

const char* const timing_note =
    "Cost: each run's CPU time (one thread per run, in the CSV files). Its spread is measured on a sample (every method of "
    "the bar at 64 cells and of the 2D solutions at 16 cells, each run 5 times, interleaved: data/smooth_cpu_spread.csv); a "
    "run counts as cheaper than another only by a margin larger than that spread, otherwise the two are a tie. Where "
    "the spread is not measured every cost comparison is a tie.\n\n";

/// Fig. 6 at 2 particles per cell against the Dyka suite's 1 particle per cell: run after both suites, from their
/// CSV files. Writes the report fragment; its claims are the paper's (soft).
int fig6_two_particles_report(const std::string& folder, const std::string& report_path) {
  const DykaTable d = read_dyka_runs(folder);
  write_fig6_runs(folder, d);
  std::ofstream report(report_path);
  report << "### Fig. 6 at 2 particles per cell (`dyka_fig6_2ppc`)\n\n![dyka_fig6_2ppc](figures/dyka_fig6_2ppc.png)\n\n"
         << "The Dyka bar as in Fig. 6 with 2 particles per cell (CFL 0.5, 200 µs), meshes 40, 160, 1280 and 2560 cells, against the "
            "1-particle-per-cell sweep of the Dyka suite (CFL 0.5): the claims compare the two on the same meshes, the figure draws "
            "the whole 1-ppc sweep (10-2560 cells) beside them. At 2 particles per cell the particles start h/4 "
            "from a cell face, so the crossing ratio of paper/08_test_cases.md (grid-crossing bands) doubles: crossing (ratio >= 1) "
            "starts at 1011 cells instead of 2021, and 2560 cells cross at both. 2560 cells at 2 particles per cell are run for every "
            "method but uGIMP and linear with the predictor-corrector (a choice of cost: their comparisons at 2560 cells have no "
            "2-ppc run); 5120 cells are not run: they alone would cost 4x the 2560-cell set. Each claim is evaluated on every mesh of this study, by the report's "
            "one rule: a pair with a run that stopped, or two runs that both failed, is counted as stopped (and the stop is "
            "named again in the rows \"every run finishes\"), never compared with an error.\n\n";
  const std::vector<DomainClaim> at_a = fig6_claims(d);
  std::vector<DomainClaim> all = fig6_claims(read_dyka_runs(folder, true));
  verification::write_domain_claims(report, at_a);
  std::string changed;
  for (std::size_t c = 0; c < all.size(); ++c) {
    verification::add_changed_verdicts(changed, at_a[c].statement, at_a[c], all[c]);
    all[c].statement += " *[all particles: the space-time norm]*";
  }
  report << "The same claims scored by the all-particle space-time norm (the RMS of v_p - v(X_p, t) over every particle and "
            "every step, the columns space_time_over_v0 of data/dyka_sweep.csv and data/dyka_2ppc.csv) instead of point A's "
            "RMS; verdicts that change: " << (changed.empty() ? "none" : changed) << ".\n\n";
  verification::write_domain_claims(report, all);
  report << "#### Today's baselines at 2 particles per cell\n\n"
         << "Quadratic and cubic B-splines (bspline2, bspline3), linear shapes with the stress updated last (usl) or modified-last (musl), "
            "LME at γ = 0.8 and 1.5 (lme0.8, lme1.5), beside the paper's methods: every one at 160 cells (no crossing); at 1280 cells "
            "(crossing) the B-splines with both integrators, LME γ = 0.8 and 1.5 with the predictor-corrector, and USL and MUSL "
            "(data/dyka_2ppc.csv).\n\n";
  std::vector<DomainClaim> baselines = fig6_baseline_claims(d);
  const CpuSpread spread = read_spread(folder);
  for (int cells : {160, 1280}) {
    std::vector<CostRun> runs;
    for (const DykaRun& r : d.runs)
      if (r.ppc == 2 && r.cells == cells) runs.push_back({r.where(), r.method.paper() && r.method.shape != "linear", r.rms, r.cpu});
    baselines.push_back(front_claim(runs, spread, "Dyka bar, 2 ppc, " + std::to_string(cells) + " cells, RMS/v0"));
  }
  verification::write_domain_claims(report, baselines);
  report << timing_note;
  std::printf("smooth_suite: Fig. 6 at 2 particles per cell reported\n");
  return 0;
}

/// The report fragment's opening: the scene, the errors, the baselines.
void write_introduction(std::ostream& report, const BarScene& bar) {
  report << "## Smooth data: the vibrating bar\n\n"
         << "Scene `scenes/vibrating_bar.toml`: the first mode of the steel bar (L = " << bar.length << " m) free at X = 0 and fixed at X = L, "
            "started unstressed with v = V cos(πX/2L), run to one period T = 4L/c. Error: RMS over every particle at T/4, T/2, 3T/4 "
            "and T of v_p - v(X_p, t) divided by V, and of σ_p - σ(X_p, t) divided by ZV; against the exact mode "
            "(`mpm/exact/vibrating_bar.hpp`) at small amplitude, the finite-strain reference σ = E ln λ "
            "(`mpm/exact/vibrating_bar_finite_strain.hpp`, " << reference_cells << " cells) at large amplitude. "
         << "Orders: GSL least squares of log error against log cells, 16 cells and finer, with their standard errors; none on fewer "
            "than 3 meshes or over a run that stopped. A run that finishes with a velocity error no smaller than a flat field's (the "
            "RMS of the exact velocity about its mean over the same particles and times, about V/2 here) has failed, by the report's "
            "one rule: it approximates nothing; it is left out of its series' order fit and counted there (as `mpm study` does; a series "
            "whose failed runs leave fewer than 3 meshes fails an order claim), and a comparison of two failed runs is counted as stopped (the CSVs' column `ending`: done, failed or stopped). "
            "At small amplitude uGIMP gives the same numbers as linear shape functions: while "
            "a particle's domain lies inside one cell, its uGIMP weights and gradients equal the linear ones at its centre.\n\n"
         << "Each claim is evaluated on every run (or series of meshes) of its study, and the table says where it holds and where it "
            "fails. Today's baselines run beside the paper's methods (paper/08_test_cases.md, \"Today's baselines\"): quadratic and cubic "
            "B-splines (bspline2, bspline3) with both integrators, and linear shapes with forward Euler and the stress updated last "
            "(usl) or modified-last (musl), at CFL 0.5; on the bar at 8-128 cells, 1 and 2 ppc, in 2D at 2x2 ppc, 12-32 cells; in the "
            "crossing onset also LME at γ = 0.8 and 1.5 (lme0.8, lme1.5).\n\n"
         << timing_note;
}

/// Runs the suite's studies, writes their data and the report; 1 when a hard claim fails.
int run_suite(const std::string& folder, const std::string& report_path, const Scenes& scenes, unsigned cores) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const auto all = studies();
  const Runs runs = run_all(all, scenes, cores);
  write_runs(folder, all, runs);
  write_bar_orders(folder, runs);
  write_manufactured_orders(folder, runs);
  write_dyka_runs(folder, all, runs);
  const CpuSpread spread = measure_cpu_spread(runs, scenes, spread_sample(), cores);
  write_spread(folder, spread);
  const auto bar_fronts = front_claims(runs, spread, Group::bar);
  std::ostringstream onset_table;
  std::vector<Section> sections{
      {"The exact solutions and their references", "", reference_claims(runs, scenes.bar), "", ""},
      {"Vibrating bar, small amplitude (V/ω = 1e-6 L): no grid crossing", "smooth_bar_small", small_bar_claims(runs), "",
       "the RMS errors of velocity and stress against cells, one panel per shape function (the paper's three on top, "
       "today's baselines below), the integrator its dash and marker, 2 particles per cell open markers, the paper's shapes "
       "also at CFL 0.1 (thin); under each panel the ratio of the twins that lie on each other (2 ppc over 1, CFL 0.1 "
       "over 0.5, MUSL over USL), their largest departure from 1 in its title."},
      {"Vibrating bar, large amplitude (V/ω = 0.05 L): particles cross cells", "smooth_bar_large", large_bar_claims(runs), "",
       "the same errors at large amplitude against the finite-strain reference (CFL 0.5); runs that stopped or failed on "
       "the strip above each panel, at their mesh, one named row per integrator and particles per cell; under each panel "
       "2 ppc over 1 and NPC over FE at 1 ppc (MUSL over USL), their largest departure from 1 where they coincide in its "
       "title."},
      {"The grid-crossing error isolated: " + std::to_string(crossing_cells) + " cells, amplitude swept", "smooth_crossing",
       crossing_claims(runs, folder, onset_table), "",
       "the RMS velocity error against U/h, one panel per integrator and particles per cell, one curve per shape function "
       "(and linear with USL and MUSL under FE); under each panel every method's error over uGIMP's at the same U/h; runs "
       "that stopped or failed on the strip, one named row per method; the titles give what coincides, computed."},
      {"2D manufactured solutions, plane strain ν = 0.3", "smooth_manufactured", manufactured_claims(runs), "",
       "the RMS errors of velocity and stress against the cells per side: small amplitude on top (linear and LME; uGIMP "
       "gives linear's numbers), the errors of uGIMP and LME over linear's (and MUSL's over USL's) in the middle row, "
       "large amplitude below it and, under that, the 1x1 runs over linear + FE's, uGIMP's 2x2 over 1x1 and the "
       "baselines' NPC over FE, what coincides computed in the titles; today's baselines in the right column; runs that "
       "failed on the strip, named."}};
  sections[1].claims.insert(sections[1].claims.end(), bar_fronts.begin(), bar_fronts.begin() + 2);
  sections[2].claims.insert(sections[2].claims.end(), bar_fronts.begin() + 2, bar_fronts.end());
  for (Group group : {Group::crossing, Group::manufactured}) {
    const auto fronts = front_claims(runs, spread, group);
    auto& claims = sections[group == Group::crossing ? 3 : 4].claims;
    claims.insert(claims.end(), fronts.begin(), fronts.end());
  }
  sections[3].after = "Onset per method: the first U/h of the sweep at which the velocity error exceeds twice its no-crossing value (at "
                      "U/h = 0.01); \"stopped at\" where a run stopped before its error doubled (the onset is then not measured, and "
                      "a comparison of it counts as stopped). Geometry: the particle next to the free end reaches a cell face at U/h = 1/(2 ppc).\n\n" +
                      onset_table.str();
  std::ofstream report(report_path);
  write_introduction(report, scenes.bar);
  bool hard = true;
  for (const Section& s : sections) {
    report << "### " << s.title << (s.figure.empty() ? "" : " (`" + s.figure + "`)") << "\n\n";
    if (!s.figure.empty()) report << "![" << s.figure << "](figures/" << s.figure << ".png)\n\n";
    if (!s.drawn.empty()) report << "The figure: " << s.drawn << "\n\n";
    verification::write_domain_claims(report, s.claims);
    report << s.after;
    hard = hard && verification::hard_claims_hold(s.claims);
  }
  write_orders(report, runs);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  report << "Suite time: " << number(seconds, "%.1f") << " s wall, " << number(cpu, "%.1f") << " s of CPU on " << cores << " threads ("
         << runs.cases.size() << " runs, the references, and " << spread.cases * spread.repeats << " runs measuring the CPU spread).\n\n";
  std::printf("smooth_suite: %zu runs in %.1f s wall (runs %.1f s), %.1f s CPU, hard checks %s\n", runs.cases.size(), seconds, runs.seconds, cpu,
              hard ? "passed" : "FAILED");
  return hard ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const unsigned cores = verification::suite_threads(argc, argv);
  if (cores == 0) {
    std::fprintf(stderr, "smooth_suite: --threads needs a whole number >= 1\n");
    return 2;
  }
  try {
    if (argc == 4 && std::string(argv[1]) == "--fig6-2ppc") return fig6_two_particles_report(argv[2], argv[3]);
    if (argc == 6) return run_suite(argv[1], argv[2], {BarScene(argv[3]), argv[4], argv[5]}, cores);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "smooth_suite: %s\n", error.what());
    return 1;
  }
  std::fprintf(stderr, "usage: smooth_suite DATA_DIR REPORT BAR_SCENE DYKA_SCENE MANUFACTURED_SCENE [--threads N]\n"
                       "       smooth_suite --fig6-2ppc DATA_DIR REPORT\n");
  return 2;
}
