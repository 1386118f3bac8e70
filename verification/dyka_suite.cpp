// The Dyka-bar suite, in two parts: `make figures` runs the paper's Figs. 6-10 (--part figures), `make studies`
// everything beyond the paper (--part studies; dyka_cases.hpp, Part). Runs every case of its part in parallel on the
// machine's cores, writes the data of each figure as CSV into DATA_DIR, and the report fragment REPORT (Markdown) with
// the claims, each evaluated on every run of its study and reported as where it holds and where it fails.
// Exit code 1 when a hard check (a bound the theory gives) fails somewhere.
//
//   build/bin/dyka_suite DATA_DIR REPORT SCENE --part figures|studies [--threads N]
//
// The studies are data (verification/dyka_cases.hpp); the runs (dyka_runs.hpp): every independent case of the part,
// then (studies) forward Euler with a PIC/FLIP blend calibrated per shape and mesh to the shape's own NPC energy, then
// the runs of the error-cost fronts on 40 and 160 cells timed 5 times more, interleaved (CPU time). One analysis
// function per figure: dyka_accuracy.hpp (Figs. 6, 7), dyka_fair.hpp (Figs. 8-10; dyka_fair, Newton, energy),
// dyka_rules.hpp (LME's claims under both beta rules), dyka_baselines.hpp (fronts).

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "verification/dyka_accuracy.hpp"
#include "verification/dyka_profile_claims.hpp"
#include "verification/dyka_baselines.hpp"
#include "verification/dyka_data.hpp"
#include "verification/dyka_experiments.hpp"
#include "verification/dyka_fair.hpp"
#include "verification/dyka_rules.hpp"

using namespace verification;
using namespace verification::dyka;

namespace {

void write_report(const std::string& path, Part part, const std::vector<Section>& sections) {
  std::ofstream report(path);
  report << (part == Part::figures ? "## Dyka bar (section 3.1)\n\n" : "## Dyka bar beyond the paper (section 3.1)\n\n")
         << "Scene `scenes/dyka_bar.toml`; error = Eq. (43) over every step of v_A against the exact solution (appendix A) at particle A's "
            "reference position; 1 particle per cell, CFL 0.5 unless stated, 200 µs; RMS divided by |v0| = 5 m/s. Each claim is evaluated on "
            "every run of its study: *holds on* and *fails on* list where, with the value measured there; a comparison with a run the "
            "solver stopped, or with two failed runs, is counted as stopped (the report's one rule), never scored as an error; "
            "a CSV's `status` failed is a stopped run, its `ending` the rule's outcome (done, failed, stopped).\n\n";
  if (part == Part::figures)
    report << "LME under the authors' β runs here on " << cells_text(authors_cells) << " cells; `make studies` runs it on "
           << "every mesh of the sweep and compares the two rules' verdicts (\"LME under the two β rules\").\n\n";
  for (const auto& section : sections) dyka::write_section(report, section);
}

/// make figures: the sweep (the authors' beta to authors_figures_cells), the large CFLs, the gammas; Figs. 6-10.
std::vector<Section> figures_part(Runs& runs) {
  authors_cells.erase(std::remove_if(authors_cells.begin(), authors_cells.end(), [](int n) { return n > authors_figures_cells; }),
                      authors_cells.end());
  run_all(runs, independent_cases(Part::figures), true);
  write_sweep(runs), write_gamma(runs), write_orders(runs);
  return {all_runs_section(runs), fig6_section(runs), fig7_section(runs), profile_section(runs), fig8_section(runs),
          fig9_10_section(runs)};
}

/// make studies: the sweep again as the reference, the fair comparison, the choices, the energy, the baselines and the
/// timing of their fronts; the experiments that decide the claims (dyka_experiments.hpp).
std::vector<Section> studies_part(Runs& runs) {
  run_all(runs, independent_cases(Part::studies), true);
  calibrate_blends(runs);
  std::vector<std::string> timed;
  for (int cells : repeated_cells)
    for (const auto& name : front_runs(cells)) timed.push_back(name);
  time_repeats(runs, timed);
  write_sweep(runs), write_fair(runs), write_choices(runs), write_energy(runs), write_orders(runs);
  const auto entries = fronts(runs);
  write_fronts(entries, runs.folder + "/dyka_baselines.csv");
  return {all_runs_section(runs),       fair_section(runs),      rules_section(runs),         newton_section(runs),
          energy_section(runs),         baselines_section(runs, entries), space_time_section(runs), gamma_meshes_section(runs),
          temporal_section(runs),       amplitude_section(runs)};
}

}  // namespace

int main(int argc, char** argv) {
  const unsigned cores = suite_threads(argc, argv);
  const int part = suite_part(argc, argv);
  if (argc != 4 || cores == 0 || part == 0) {
    std::fprintf(stderr, "usage: dyka_suite DATA_DIR REPORT SCENE --part figures|studies [--threads N]\n");
    return 2;
  }
  Runs runs;
  runs.folder = argv[1], runs.scene = argv[3], runs.cores = cores;
  const Part which = part == 1 ? Part::figures : Part::studies;
  std::vector<Section> sections;
  try {
    sections = which == Part::figures ? figures_part(runs) : studies_part(runs);
  } catch (const mpm::SceneError& error) {  // a scene file that does not read, or asks for the reference kernels
    std::fprintf(stderr, "dyka_suite: %s\n", error.message().c_str());
    return 2;
  }
  write_report(argv[2], which, sections);
  bool hard = true;
  for (const auto& section : sections) hard = hard && hard_claims_hold(section.claims);
  std::printf("dyka_suite: %zu runs, hard checks %s\n", runs.by_name.size(), hard ? "passed" : "FAILED");
  return hard ? 0 : 1;
}
