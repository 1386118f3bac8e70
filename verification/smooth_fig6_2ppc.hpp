// Fig. 6 at 2 particles per cell (`dyka_fig6_2ppc`): the smooth suite's Dyka runs at 2 ppc (dyka_2ppc.csv) against the
// Dyka suite's sweep at 1 ppc (dyka_sweep.csv, CFL 0.5), read after both suites; its claims over every mesh both ran.
#pragma once
#include <fstream>
#include <set>
#include <sstream>

#include "mpm/analysis/verdict.hpp"
#include "verification/smooth_fit.hpp"
#include "verification/smooth_study.hpp"

namespace verification::smooth {

// The crossing ratio of paper/08_test_cases.md (Grid-crossing bands), u_max / (h / 2 ppc): crossing (ratio >= 1) from
// 2021 cells at 1 ppc, 1011 at 2.
constexpr double dyka_speed = 5.0, dyka_largest_displacement = 3.298e-5, dyka_length = 0.1333;
inline double dyka_crossing_ratio(int cells, int ppc) { return dyka_largest_displacement / (0.5 * dyka_length / cells / ppc); }

/// Rows of a CSV file with a header, as maps from column name to text.
inline std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  auto split = [](const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    return fields;
  };
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const auto fields = split(line);
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size() && k < fields.size(); ++k) row[header[k]] = fields[k];
    rows.push_back(row);
  }
  return rows;
}

/// One Dyka run of either suite.
struct DykaRun {
  Method method;
  int ppc = 1, cells = 0;
  double rms = std::nan("");  ///< RMS / v0; NaN: stopped
  double cpu = std::nan("");  ///< CPU seconds (2 ppc only)
  double band = 0.0;           ///< the band of rms from its even and odd rows (mpm::band_of_halves)
  bool failed = false;         ///< finished no better than a flat line (mpm::score_ending)
  std::string failure;
  bool stopped() const { return !std::isfinite(rms); }
  /// rms with its band and ending, for the one rule (mpm::judge)
  mpm::Measured measured() const {
    return {rms, band, stopped() ? mpm::Ending::stopped : failed ? mpm::Ending::failed : mpm::Ending::done};
  }
  std::string where() const {
    return method.name() + ", " + std::to_string(ppc) + " ppc, " + std::to_string(cells) + " cells" +
           (dyka_crossing_ratio(cells, ppc) >= 1.0 ? " (crossing)" : "");
  }
};

/// Both suites' Dyka runs at CFL 0.5 (rows of another CFL, where the sweep has a cfl column, are left out).
struct DykaTable {
  std::vector<DykaRun> runs;
  const DykaRun* find(const Method& m, int ppc, int cells) const {
    for (const DykaRun& r : runs)
      if (r.method == m && r.ppc == ppc && r.cells == cells) return &r;
    return nullptr;
  }
  /// The meshes of the 2-ppc study (every one its runs use).
  std::set<int> meshes() const {
    std::set<int> cells;
    for (const DykaRun& r : runs)
      if (r.ppc == 2) cells.insert(r.cells);
    return cells;
  }
};
/// `all_particles`: each run scored by the all-particle space-time norm (columns space_time_over_v0 and its band) instead
/// of point A's RMS (the ending stays the RMS's).
inline DykaTable read_dyka_runs(const std::string& folder, bool all_particles = false) {
  DykaTable table;
  for (int ppc : {1, 2})
    for (const auto& row : read_csv(folder + (ppc == 1 ? "/dyka_sweep.csv" : "/dyka_2ppc.csv"))) {
      if (row.count("cfl") && std::abs(std::stod(row.at("cfl")) - 0.5) > 1e-9) continue;
      if (row.count("ppc") && std::stoi(row.at("ppc")) != ppc) continue;
      DykaRun run;
      run.method = {row.at("shape"), row.at("integrator")}, run.ppc = ppc, run.cells = std::stoi(row.at("cells"));
      const std::string score = all_particles ? "space_time_over_v0" : "rms_over_v0";
      const std::string band = all_particles ? "space_time_band_over_v0" : "rms_band_over_v0";
      if (row.at("status") == "ok") run.rms = std::stod(row.at(score));
      if (row.count("cpu_seconds")) run.cpu = std::stod(row.at("cpu_seconds"));
      if (row.count("failure")) run.failure = row.at("failure");
      if (row.count(band) && !run.stopped()) run.band = std::stod(row.at(band));
      run.failed = row.count("ending") && row.at("ending") == "failed";
      table.runs.push_back(run);
    }
  return table;
}

/// A stopped run's diagnosis for a table cell: its first 80 characters, no '|'.
inline std::string diagnosis(const DykaRun& run) {
  std::string text = run.failure.substr(0, 80) + (run.failure.size() > 80 ? "..." : "");
  std::replace(text.begin(), text.end(), '|', '/');
  return text.empty() ? std::string("stopped") : text;
}

/// dyka_fig6_2ppc.csv: the runs of Fig. 6 at 2 ppc beside 1 (the figure reads the same runs from dyka_sweep.csv and dyka_2ppc.csv, which also say how each ended), both ppc (the 1-ppc sweep at CFL 0.5 only), one row each.
inline void write_fig6_runs(const std::string& folder, const DykaTable& d) {
  std::ofstream out(folder + "/dyka_fig6_2ppc.csv");
  out << "ppc,shape,integrator,cells,crossing_ratio,rms_over_v0,status\n";
  for (const DykaRun& r : d.runs)
    out << r.ppc << "," << r.method.shape << "," << r.method.integrator << "," << r.cells << "," << dyka_crossing_ratio(r.cells, r.ppc) << ","
        << r.rms << "," << (r.stopped() ? "stopped" : "ok") << "\n";
}

/// Adds to `claim` the ratio a.rms / b.rms decided by the one rule (mpm::judge, the ratio's band from the two runs'):
/// a pair with a stopped run, or two failed runs, is a stopped sample, named so (not dropped); a pair not run is none.
inline void add_pair(DomainClaim& claim, const DykaRun* a, const DykaRun* b, const std::string& against) {
  if (!a || !b) return;
  const mpm::Measured r = mpm::ratio(a->measured(), b->measured());
  const mpm::Outcome outcome = mpm::judge(r, mpm::Side::below, mpm::threshold(1.0));
  if (outcome == mpm::Outcome::stopped) {
    claim.add(a->where() + ", " + against + ": " + (a->stopped() ? "it stopped" : b->stopped() ? against + " stopped" : "both failed"),
              std::nan(""), outcome);
    return;
  }
  claim.add(a->where() + ": " + number(a->rms, "%.3g") + ", " + against + " " + number(b->rms, "%.3g") + ", ratio ± " +
                number(r.band, "%.2g"),
            r.value, outcome);
}

/// The paper's claims through crossing at 1 and 2 ppc, on every mesh of the 2-ppc study.
inline std::vector<DomainClaim> fig6_claims(const DykaTable& d) {
  // The paper's claims are made at 1 ppc (its Fig. 6): scored there; at 2 ppc, this study's extension, rows of their own.
  DomainClaim smooth{"Paper (Fig. 6, 1 ppc): uGIMP and LME are more accurate than linear shape functions (they suffer less from grid crossing)",
                     "RMS/v0 of uGIMP or LME over linear's, same integrator and mesh, 1 ppc, < 1 beyond its band", {}, false};
  DomainClaim converging{"... and keep converging through crossing (1 ppc): the error on a crossing mesh stays below the method's own at 160 cells",
                         "RMS/v0 on the crossing mesh over the method's RMS/v0 at 160 cells (no crossing), 1 ppc, < 1 beyond its band", {}, false};
  DomainClaim smooth2{"At 2 ppc (beyond the paper): uGIMP and LME are more accurate than linear shape functions",
                      "RMS/v0 of uGIMP or LME over linear's, same integrator and mesh, 2 ppc, < 1 beyond its band", {}, false};
  DomainClaim converging2{"At 2 ppc (beyond the paper): uGIMP and LME keep converging through crossing, the error on a crossing mesh below their own at 160 cells",
                          "RMS/v0 on the crossing mesh over the method's RMS/v0 at 160 cells (no crossing), 2 ppc, < 1 beyond its band", {}, false};
  DomainClaim two{"2 particles per cell are more accurate than 1 (the paper's methods)", "RMS/v0 at 2 ppc over 1 ppc's, same method and mesh, < 1 beyond its band", {}, false};
  DomainClaim finish{"Every run finishes (the paper's methods on the meshes of the 2-ppc study, 1 and 2 ppc)",
                     "the run reaches 200 µs (1) or stops (0): here a stop is what the claim counts, a fail (elsewhere a stopped run is its own outcome, never scored against an error)", {}, false};
  for (int cells : d.meshes())
    for (const Method& m : paper_methods())
      for (int ppc : {1, 2}) {
        const DykaRun* run = d.find(m, ppc, cells);
        if (!run) continue;
        finish.add(run->where() + (run->stopped() ? ": " + diagnosis(*run) : ""), run->stopped() ? 0.0 : 1.0, !run->stopped());
        if (m.shape != "linear") add_pair(ppc == 1 ? smooth : smooth2, run, d.find({"linear", m.integrator}, ppc, cells), "linear");
        if (dyka_crossing_ratio(cells, ppc) >= 1.0) add_pair(ppc == 1 ? converging : converging2, run, d.find(m, ppc, 160), "at 160 cells");
        if (ppc == 2) add_pair(two, run, d.find(m, 1, cells), "1 ppc");
      }
  return {smooth, converging, smooth2, converging2, two, finish};
}

/// Today's baselines at 2 ppc against the paper's methods: the most accurate per mesh, each against linear, and stops.
inline std::vector<DomainClaim> fig6_baseline_claims(const DykaTable& d) {
  DomainClaim best{"With today's baselines in the comparison, uGIMP or LME γ = 3 is still the most accurate (2 ppc)",
                   "the smallest RMS/v0 of uGIMP and LME γ = 3 below the smallest of the other finished runs of the mesh, beyond "
                   "their bands (value: their ratio)", {}, false};
  DomainClaim against{"Today's baseline is more accurate than linear shape functions (2 ppc; USL and MUSL against linear FE)",
                      "RMS/v0 of the baseline over linear's, same mesh, < 1 beyond its band", {}, false};
  DomainClaim finish{"Every run of today's baselines finishes (2 ppc)", "the run reaches 200 µs (1) or stops (0): here a stop is what the claim counts, a fail", {}, false};
  for (int cells : {160, 1280}) {
    std::vector<const DykaRun*> of_paper, of_others;  // the mesh's finished runs, and their measures, per group
    std::vector<mpm::Measured> paper_rms, others_rms;
    for (const Method& m : with_paper(crossing_baselines())) {
      const DykaRun* run = d.find(m, 2, cells);
      if (!run || run->stopped()) continue;
      const bool paper = (m.shape == "ugimp" || m.shape == "lme") && m.paper();
      (paper ? of_paper : of_others).push_back(run);
      (paper ? paper_rms : others_rms).push_back(run->measured());
    }
    const BestOfGroups judged = judge_best(paper_rms, others_rms);
    if (judged.paper != BestOfGroups::none && judged.other != BestOfGroups::none) {
      const DykaRun &paper = *of_paper[judged.paper], &other = *of_others[judged.other];
      best.add(std::to_string(cells) + " cells: paper's best " + paper.method.name() + " " + number(paper.rms, "%.3g") + " ± " +
                   number(paper.band, "%.2g") + ", the others' best " + other.method.name() + " " + number(other.rms, "%.3g") +
                   " ± " + number(other.band, "%.2g"),
               paper.rms / other.rms, judged.outcome);
    }
    for (const Method& m : crossing_baselines()) {
      const DykaRun* run = d.find(m, 2, cells);
      if (!run) continue;
      finish.add(run->where() + (run->stopped() ? ": " + diagnosis(*run) : ""), run->stopped() ? 0.0 : 1.0, !run->stopped());
      add_pair(against, run, d.find({"linear", m.integrator == "npc" ? "npc" : "fe"}, 2, cells), "linear");
    }
  }
  return {best, against, finish};
}

}  // namespace verification::smooth
