/// \file
/// `mpm trace --diff A.csv B.csv` and `mpm trace SCENE --step N --against OTHER.toml | --against-set KEY=VALUE`: two
/// traces of one step (`mpm trace ... --format csv`, perhaps written by two builds) compared phase by phase, row by row
/// (node or particle), column by column, and the first quantity where they part named, with how many values differ
/// and the first of each phase. Two values differ when \f$ |A - B| > T \max(|A|, |B|, 1) \f$, T the tolerance
/// (default 1e-12): relative above 1 in magnitude, absolute below (in the column's SI unit), so that a sum that
/// cancels to round-off, 1e-17 in one build and 0 in the other, agrees; the title's t_k and dt, relative only. A phase,
/// a row or a column in one trace only is itself a difference. Exit codes: 0 agree, 1 differ, 2 a file that is not
/// a trace (`FILE:LINE: why`; only regular files are read, so a FIFO never waits), 3 a run failed (--against).
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/cli/trace_file.hpp"
#include "mpm/io/csv_file.hpp"

namespace mpm::cli {

/// What `mpm trace` compares: two trace files, or the scene's run and a second run.
struct TraceComparisonRequest {
  std::vector<std::string> files;        ///< --diff A.csv B.csv
  std::string against;                   ///< --against OTHER.toml: the second run's scene (default: the first's)
  std::vector<std::string> against_set;  ///< --against-set KEY=VALUE ...: the second run's overrides, after the rest
  double tolerance = 1e-12;              ///< --tolerance
  bool runs() const { return !against.empty() || !against_set.empty(); }
};

/// Where two traces differ: the place in a phase ("node 1, f_I_k1_int_x"; "" for the phase itself) and what each
/// trace says there; `a` or `b` empty where that trace lacks it.
struct TraceDifference {
  std::string place, a, b;
  /// "PLACE: -3 (A) vs -20 (B)", or "PLACE: in A only".
  std::string text() const {
    const std::string where = place.empty() ? "" : place + ": ";
    if (a.empty() || b.empty()) return where + "in " + (a.empty() ? "B" : "A") + " only";
    return where + a + " (A) vs " + b + " (B)";
  }
};

/// The differences of one phase (or of the step the titles name): how many, and the first.
struct PhaseDifferences {
  explicit PhaseDifferences(std::string label_) : label(std::move(label_)) {}
  std::string label;                       ///< "phase 5 (forces, Eqs. (14)-(15))", or "the step"
  std::size_t values = 0, unmatched = 0;  ///< values that differ; phases, tables, rows or columns in one trace only
  TraceDifference first;
  void add(TraceDifference difference, bool in_one_only) {
    if (values + unmatched == 0) first = std::move(difference);
    ++(in_one_only ? unmatched : values);
  }
  /// "phase 5 (forces, Eqs. (14)-(15)), node 1, f_I_k1_int_x: -3 (A) vs -20 (B)", "phase 7 (...): in B only".
  std::string located_text() const { return label + (first.place.empty() ? ": " : ", ") + first.text(); }
};

/// Two traces compared: each phase that differs, in the traces' order, and how many values were compared.
struct TraceComparison {
  std::vector<PhaseDifferences> phases;
  std::size_t compared = 0, phases_compared = 0;
};

/// True when a and b agree within `tolerance`: |a - b| <= tolerance max(|a|, |b|, 1).
inline bool values_agree(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance * std::max({std::abs(a), std::abs(b), 1.0});
}

/// A number as the trace writes it (15 significant digits).
inline std::string trace_value_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.15g", value);
  return text;
}

/// The titles' step, t_k, dt (relative to the larger: a time step is small), dimension and integrator.
inline void compare_titles(const ReadTrace& a, const ReadTrace& b, double tolerance, TraceComparison& comparison) {
  PhaseDifferences step{"the step"};
  const auto relative = [&](double u, double v) {
    return std::abs(u - v) <= tolerance * std::max(std::abs(u), std::abs(v));
  };
  if (a.step != b.step) step.add({"step", std::to_string(a.step), std::to_string(b.step)}, false);
  if (!relative(a.time, b.time)) step.add({"t_k", trace_value_text(a.time), trace_value_text(b.time)}, false);
  if (!relative(a.dt, b.dt)) step.add({"dt", trace_value_text(a.dt), trace_value_text(b.dt)}, false);
  if (a.dimension != b.dimension)
    step.add({"dimension", std::to_string(a.dimension) + "D", std::to_string(b.dimension) + "D"}, false);
  if (a.integrator != b.integrator) step.add({"integrator", a.integrator, b.integrator}, false);
  if (step.values) comparison.phases.push_back(step);
}

/// The cell of `row` in `column` as the trace writes it.
inline std::string cell_text(const TraceRows& table, std::size_t row, std::size_t column) {
  if (static_cast<int>(column) == table.text_column) return table.texts[row];
  return trace_value_text(table.values[row * table.columns.size() + column]);
}

/// One table of a phase in both traces (`at`: node or particle): its columns in one only, its rows in one only, and
/// each value of the rows and columns of both, in A's order.
inline void compare_rows(const TraceRows& a, const TraceRows& b, const std::string& at, double tolerance,
                         PhaseDifferences& differences, std::size_t& compared) {
  if (a.index.empty() || b.index.empty()) {
    if (a.index.size() + b.index.size())
      differences.add({at + "s", a.index.empty() ? "" : "rows", b.index.empty() ? "" : "rows"}, true);
    return;
  }
  std::unordered_map<std::string, std::size_t> b_column;
  for (std::size_t k = 0; k < b.columns.size(); ++k) b_column[b.columns[k]] = k;
  std::vector<std::pair<std::size_t, std::size_t>> common;  // A's column, B's
  for (std::size_t k = 0; k < a.columns.size(); ++k) {
    const auto found = b_column.find(a.columns[k]);
    if (found == b_column.end()) differences.add({at + "s, column " + a.columns[k], "column", ""}, true);
    if (found != b_column.end()) common.emplace_back(k, found->second), b_column.erase(found);
  }
  for (const std::string& name : b.columns)
    if (b_column.count(name)) differences.add({at + "s, column " + name, "", "column"}, true);
  for (std::size_t row = 0; row < a.index.size(); ++row) {
    const std::string place = at + " " + std::to_string(a.index[row]);
    const auto other = b.row_of.find(a.index[row]);
    if (other == b.row_of.end()) {
      differences.add({place, "row", ""}, true);
      continue;
    }
    for (const auto& [k, j] : common) {
      ++compared;
      const bool words = static_cast<int>(k) == a.text_column || static_cast<int>(j) == b.text_column;
      const bool agree = words ? cell_text(a, row, k) == cell_text(b, other->second, j)
                               : values_agree(a.values[row * a.columns.size() + k],
                                              b.values[other->second * b.columns.size() + j], tolerance);
      if (!agree)
        differences.add({place + ", " + a.columns[k], cell_text(a, row, k), cell_text(b, other->second, j)}, false);
    }
  }
  for (std::size_t row = 0; row < b.index.size(); ++row)
    if (!a.row_of.count(b.index[row])) differences.add({at + " " + std::to_string(b.index[row]), "", "row"}, true);
}

/// The two traces compared: the titles, then the phases by name in A's order, each phase of B that A lacks where B
/// has it.
inline TraceComparison compare_traces(const ReadTrace& a, const ReadTrace& b, double tolerance) {
  TraceComparison comparison;
  compare_titles(a, b, tolerance, comparison);
  std::size_t b_next = 0;  // B's phases before it reported
  const auto b_only_until = [&](std::size_t end) {
    for (; b_next < end; ++b_next)
      if (!a.find(b.phases[b_next].name)) {
        comparison.phases.emplace_back(b.phases[b_next].label);
        comparison.phases.back().add({"", "", "phase"}, true);
      }
  };
  for (const TracePhase& phase : a.phases) {
    PhaseDifferences differences{phase.label};
    const TracePhase* other = b.find(phase.name);
    if (!other) {
      differences.add({"", "phase", ""}, true);
    } else {
      const std::size_t position = static_cast<std::size_t>(other - b.phases.data());
      b_only_until(position);
      b_next = std::max(b_next, position + 1);
      ++comparison.phases_compared;
      compare_rows(phase.nodes, other->nodes, "node", tolerance, differences, comparison.compared);
      compare_rows(phase.particles, other->particles, "particle", tolerance, differences, comparison.compared);
    }
    if (differences.values + differences.unmatched) comparison.phases.push_back(std::move(differences));
  }
  b_only_until(b.phases.size());
  return comparison;
}

/// "1 value", "3 values".
inline std::string count_of(std::size_t count, const std::string& what) {
  return std::to_string(count) + " " + what + (count == 1 ? "" : "s");
}

/// How many differ: "3 values differ", "1 value differs and 2 in one trace only"; `named`, what the 2 are: "2 phases,
/// tables, rows or columns in one trace only,".
inline std::string differ_text(std::size_t values, std::size_t unmatched, bool named = false) {
  const std::string what = unmatched == 1 ? " phase, table, row or column" : " phases, tables, rows or columns";
  const std::string only = std::to_string(unmatched) + (named ? what : "") + " in one trace only" + (named ? "," : "");
  if (!values) return only;
  return count_of(values, "value") + (values == 1 ? " differs" : " differ") + (unmatched ? " and " + only : "");
}

/// Prints the comparison of the traces `a_name` (A) and `b_name` (B): that they agree, or the first difference, how
/// many differ and where, and (when more than one phase differs) the first difference of each phase.
/// Returns the exit code: 0 when they agree within `tolerance`, 1 when they differ.
inline int print_trace_comparison(const TraceComparison& comparison, const std::string& a_name,
                                  const std::string& b_name, double tolerance, std::ostream& out) {
  std::ostringstream rule;
  rule << tolerance << " max(|A|, |B|, 1)";
  out << "A: " << a_name << "\nB: " << b_name << "\n";
  if (comparison.phases.empty()) {
    out << "the traces agree: " << count_of(comparison.compared, "value") << " in "
        << count_of(comparison.phases_compared, "phase") << ", |A - B| <= " << rule.str() << "\n";
    return 0;
  }
  std::size_t values = 0, unmatched = 0, phases = 0;
  for (const PhaseDifferences& phase : comparison.phases)
    values += phase.values, unmatched += phase.unmatched, phases += phase.label != "the step";
  const bool step = comparison.phases.front().label == "the step", each = comparison.phases.size() > 1;
  out << "first difference: " << comparison.phases.front().located_text() << "\n"
      << differ_text(values, unmatched, true) << " in " << (step ? "the step" : "") << (step && phases ? " and " : "")
      << (phases ? count_of(phases, "phase") : "") << " (|A - B| > " << rule.str() << ")"
      << (each ? "; the first of each:" : "") << "\n";
  for (std::size_t k = 0; each && k < comparison.phases.size(); ++k)
    out << "  " << differ_text(comparison.phases[k].values, comparison.phases[k].unmatched) << ": "
        << comparison.phases[k].located_text() << "\n";
  return 1;
}

/// `mpm trace --diff A.csv B.csv`: reads both (nothing printed when either is refused), compares, prints.
inline int diff_trace_files(const TraceComparisonRequest& request, std::ostream& out) {
  if (request.files.size() != 2)
    throw Refused("--diff: give two trace files, A.csv B.csv, not " + std::to_string(request.files.size()));
  const ReadTrace a = read_trace_file(request.files[0]), b = read_trace_file(request.files[1]);
  return print_trace_comparison(compare_traces(a, b, request.tolerance), request.files[0], request.files[1],
                                request.tolerance, out);
}

/// `SCENE --set K=V ...` as the comparison names a run.
inline std::string run_name(const std::string& scene, const std::vector<std::string>& overrides) {
  std::string name = scene;
  for (const std::string& assignment : overrides) name += " --set " + assignment;
  return name;
}

/// `mpm trace SCENE --step N [--set ...] --against OTHER.toml | --against-set KEY=VALUE ...`: traces the scene (A),
/// then the second run (B: OTHER.toml, or SCENE with its --set, and every --against-set after), each by
/// `trace(scene, overrides, out)`, which writes its CSV trace and returns its exit code; compares them as --diff
/// does. An error of an --against-set is named as one (`--against-set(1):1: KEY: why`). Returns the exit code.
template <class Trace>
int compare_trace_runs(const std::string& scene, const std::vector<std::string>& overrides,
                       const TraceComparisonRequest& request, Trace trace, std::ostream& out) {
  const std::string other = request.against.empty() ? scene : request.against;
  std::vector<std::string> other_overrides = request.against.empty() ? overrides : std::vector<std::string>{};
  const std::size_t inherited = other_overrides.size();
  other_overrides.insert(other_overrides.end(), request.against_set.begin(), request.against_set.end());
  std::ostringstream a_text, b_text;
  if (const int code = trace(scene, overrides, a_text)) return code;
  try {
    if (const int code = trace(other, other_overrides, b_text)) return code;
  } catch (SceneError& error) {
    const bool set = error.file.rfind("--set(", 0) == 0;  // `--set(N)`: the Nth override of the second run
    const std::size_t number = set ? std::strtoul(error.file.c_str() + 6, nullptr, 10) : 0;
    if (number > inherited) error.file = "--against-set(" + std::to_string(number - inherited) + ")";
    throw;
  }
  const std::string a_name = run_name(scene, overrides), b_name = run_name(other, other_overrides);
  const ReadTrace a = read_trace_text(a_text.str(), "A"), b = read_trace_text(b_text.str(), "B");
  return print_trace_comparison(compare_traces(a, b, request.tolerance), a_name, b_name, request.tolerance, out);
}

/// The options of the comparison, added to `mpm trace`'s parser `app`, each excluding what it makes needless:
/// --diff the scene and every option of a run, --against and --against-set --format.
inline void add_trace_comparison_options(CLI::App& app, TraceComparisonRequest& request) {
  auto diff = app.add_option("--diff", request.files,
                             "compares two traces written with --format csv (by two builds, say) phase by phase, row\n"
                             "by row, column by column; prints the first value that differs and how many; exit 0 when\n"
                             "they agree, 1 when they differ, 2 for a file that is not a trace")
                  ->expected(1, 1 << 20)  // two, said by diff_trace_files (CLI11 says 'given more than once' of three)
                  ->type_name("A.csv B.csv");
  auto against = app.add_option("--against", request.against,
                                "traces step N of OTHER.toml too (its own keys and --against-set, not --set) and\n"
                                "compares the two runs as --diff does")
                     ->type_name("OTHER.toml")
                     ->check([](const std::string& path) { return path.empty() ? "must name a scene file" : ""; });
  auto against_set = app.add_option("--against-set", request.against_set,
                                    "overrides a key of the second run only, after SCENE's --set (or on --against's\n"
                                    "scene); repeat for more. Without --against: SCENE against SCENE with these")
                         ->allow_extra_args(false)
                         ->type_name("KEY=VALUE");
  app.add_option("--tolerance", request.tolerance,
                 "with --diff, --against or --against-set: two values differ when |A - B| > TOL max(|A|, |B|, 1),\n"
                 "relative above 1 in magnitude, absolute below (0: any printed digit)")
      ->check(number_in(0.0, 1.0));
  for (const char* name : {"SCENE.toml", "--step", "--set", "--kernels", "--format", "--against", "--against-set"})
    diff->excludes(app.get_option(name));
  for (CLI::Option* option : {against, against_set}) option->excludes(app.get_option("--format"));
}

/// What a run of `mpm trace` needs that the parser cannot say: SCENE.toml and --step unless --diff, --tolerance only
/// with a comparison. \throws Refused.
inline void check_trace_request(const std::string& scene, long step, const TraceComparisonRequest& request,
                                const CLI::App& app) {
  if (scene.empty()) throw Refused("SCENE.toml: required (mpm trace --help), or --diff A.csv B.csv");
  if (step == 0) throw Refused("--step: required (mpm trace --help)");
  if (app.count("--tolerance") && !request.runs())
    throw Refused("--tolerance: only with --diff, --against or --against-set: there is nothing to compare");
}

TEST_CASE("mpm trace --diff: two traces compared phase by phase, row by row, column by column") {
  // The worked example's step (paper/12), two of its phases; the lab's planted bug (exercise 7: Eq. (14) with m_p
  // for V_p) makes f_I^int (-20, 40, -20) instead of (-3, 9, -6).
  const std::string title =
      "# mpm trace we.toml: step 1 from t_k = 0 s to t_k + dt, dt = 0.2 s; 1D; forward Euler (fe), usf\n"
      "# k: the value at t_k\n";
  const std::string stress =
      "# phase 4 of 7: stress, Eqs. (16) (17) (3): strain rate and strain; density; stress\n"
      "phase,equation,at,index,x_I,fixed,m_I\n"
      "stress,(16) (17) (3),node,0,0,-,1.5\nstress,(16) (17) (3),node,1,1,-,2.5\nstress,(16) (17) (3),node,2,2,x,2\n"
      "phase,equation,at,index,m_p,sigma_p_k1_xx\n"
      "stress,(16) (17) (3),particle,0,2,-10\nstress,(16) (17) (3),particle,1,4,5\n";
  const auto forces = [&](const char* f_0, const char* f_1, const char* f_2, const char* fixed_2 = "x") {
    return read_trace_text(title + stress + "# phase 5 of 7: forces, Eqs. (14)-(15): f_I = f_I^int + f_I^ext\n" +
                               "phase,equation,at,index,x_I,fixed,f_I_k1_ext_x,f_I_k1_int_x\n" +
                               "forces,(14)-(15),node,0,0,-,15," + f_0 + "\nforces,(14)-(15),node,1,1,-,25," + f_1 +
                               "\nforces,(14)-(15),node,2,2," + fixed_2 + ",20," + f_2 + "\n",
                           "trace");
  };
  const ReadTrace before = forces("-3", "9", "-6");
  REQUIRE(before.phases.size() == 2);
  CHECK(before.phases[1].label == "phase 5 (forces, Eqs. (14)-(15))");
  CHECK(before.phases[0].particles.columns == std::vector<std::string>{"m_p", "sigma_p_k1_xx"});
  CHECK((before.step == 1 && before.time == 0.0 && before.dt == 0.2 && before.dimension == 1));
  CHECK(before.integrator == "forward Euler (fe), usf");
  const auto report = [](const ReadTrace& a, const ReadTrace& b, double tolerance = 1e-12) {
    std::ostringstream out;
    const int code = print_trace_comparison(compare_traces(a, b, tolerance), "a.csv", "b.csv", tolerance, out);
    return std::to_string(code) + " " + out.str();
  };
  CHECK(report(before, before) ==
        "0 A: a.csv\nB: b.csv\nthe traces agree: 25 values in 2 phases, |A - B| <= 1e-12 max(|A|, |B|, 1)\n");
  CHECK(report(before, forces("-20", "40", "-20")) ==
        "1 A: a.csv\nB: b.csv\n"
        "first difference: phase 5 (forces, Eqs. (14)-(15)), node 0, f_I_k1_int_x: -3 (A) vs -20 (B)\n"
        "3 values differ in 1 phase (|A - B| > 1e-12 max(|A|, |B|, 1))\n");
  // The tolerance: relative above 1 in magnitude, absolute below; a word (`fixed`) compared as it is written.
  const ReadTrace close = forces("-3.000000001", "9", "-6.0000000000006");
  CHECK(report(before, close, 1e-9).rfind("0 ", 0) == 0);
  CHECK(report(before, close, 1e-10).find("first difference: phase 5 (forces, Eqs. (14)-(15)), node 0, f_I_k1_int_x: "
                                          "-3 (A) vs -3.000000001 (B)\n1 value differs in 1 phase") !=
        std::string::npos);
  CHECK(report(before, close, 1e-14).find("\n2 values differ") != std::string::npos);
  CHECK(values_agree(1e-17, 0.0, 1e-12));
  CHECK(!values_agree(1e-17, 0.0, 0.0));
  CHECK(!values_agree(2.0, 2.0 + 4e-12, 1e-12));
  CHECK(report(before, forces("-3", "9", "-6", "-")).find("node 2, fixed: x (A) vs - (B)") != std::string::npos);
  // The step the titles name first, then the phases, the first difference of each.
  ReadTrace halved = forces("-20", "40", "-20");
  halved.dt = 0.1;
  CHECK(report(before, halved) ==
        "1 A: a.csv\nB: b.csv\nfirst difference: the step, dt: 0.2 (A) vs 0.1 (B)\n"
        "4 values differ in the step and 1 phase (|A - B| > 1e-12 max(|A|, |B|, 1)); the first of each:\n"
        "  1 value differs: the step, dt: 0.2 (A) vs 0.1 (B)\n"
        "  3 values differ: phase 5 (forces, Eqs. (14)-(15)), node 0, f_I_k1_int_x: -3 (A) vs -20 (B)\n");
}

TEST_CASE("mpm trace --diff: a phase, a column or a row in one trace only is a difference, and named") {
  const std::string title = "# mpm trace s.toml: step 2 from t_k = 0.1 s to t_k + dt, dt = 0.1 s; 1D; fe\n";
  const std::string reset =
      "# phase 0 of 2: reset: zero\nphase,equation,at,index,m_p,x_p_k\nreset,-,particle,0,1,0.5\n";
  const std::string nodes = "# phase 1 of 2: mass_momentum, Eq. (13): P2G\nphase,equation,at,index,x_I,m_I\n"
                            "mass_momentum,(13),node,0,0,0.5\nmass_momentum,(13),node,1,1,0.5\n";
  const ReadTrace a = read_trace_text(title + reset + nodes, "A");
  auto first = [&](const std::string& b_text) {
    const TraceComparison comparison = compare_traces(a, read_trace_text(b_text, "B"), 1e-12);
    return comparison.phases.empty() ? "" : comparison.phases[0].located_text();
  };
  CHECK(first(title + reset + nodes).empty());
  CHECK(first(title + nodes) == "phase 0 (reset): in A only");
  CHECK(first(title + reset + nodes + "# phase 2 of 2: forces: f\n") == "phase 2 (forces): in B only");
  const std::string three = "phase,equation,at,index,x_I,m_I,p_I_k_x\nmass_momentum,(13),node,0,0,0.5,0\n"
                            "mass_momentum,(13),node,1,1,0.5,0\n";
  CHECK(first(title + reset + nodes.substr(0, nodes.find("phase,")) + three) ==
        "phase 1 (mass_momentum, Eq. (13)), nodes, column p_I_k_x: in B only");
  const std::string one_node = nodes.substr(0, nodes.rfind("mass_momentum,(13),node,1"));
  CHECK(first(title + reset + one_node) == "phase 1 (mass_momentum, Eq. (13)), node 1: in A only");
}

}  // namespace mpm::cli
