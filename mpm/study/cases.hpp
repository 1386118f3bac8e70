/// \file
/// A study's cases and how one is run. The cases are the product of the axes, the last axis varying fastest;
/// case k runs in DIR/cases/kkkk (four digits). One case is a few children of the same `mpm` program:
///   mpm run SCENE --set ... --print-scene          the resolved scene (or exit 2: the case is `refused`)
///   mpm run SCENE --set ... --out CASE --threads 1  the run: `done`, `stopped` (energy growth) or `failed`
/// (both with --max-memory: the study's share of the machine)
///   mpm compare CASE/observers.csv SCENE --set ... --at X --column A.v_x=v_x         the score at t
///   mpm compare CASE/observers_shifted.csv ...                                        at the integrator's time
/// so that a study scores exactly as a user would. The wall and CPU time are those of the run.
#pragma once
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>
#include <unistd.h>

#include "mpm/study/measures.hpp"
#include "mpm/study/process.hpp"
#include "mpm/study/study_file.hpp"

namespace mpm::study {

/// One case of a study: the index of each axis's value, and the overrides it runs with ([set] first, then the axes).
struct Case {
  std::size_t index = 0;
  std::vector<std::size_t> choice;  ///< per axis, the index of its value
  std::vector<std::string> overrides;
};

/// What a case gave.
struct CaseResult {
  std::string status = "failed";  ///< done | stopped | refused | failed (| interrupted: the study's stop signal ended it)
  std::string why;                ///< the first line of the refusal or failure; for a done run without scores, why
  /// The two scores (compare_score): rms_normalised of the velocity, the band of its own sampling, and its ending
  /// (done, or failed when no better than a flat line); none when the case is not done or has no exact solution.
  std::optional<Measured> score_at_t, score_shifted;
  std::optional<double> energy_drift, steps;
  double wall_s = 0.0, cpu_s = 0.0;
  /// Why the study could not run the case (its folder a link or busy, mpm not started), else empty: the case is a
  /// failed row of study.csv and the study exits 3.
  std::string not_run;
};

/// Every case of `study`, the last axis varying fastest.
inline std::vector<Case> expand_cases(const Study& study) {
  std::size_t count = 1;
  for (const auto& axis : study.axes) count *= axis.values.size();
  std::vector<Case> cases(count);
  for (std::size_t index = 0; index < count; ++index) {
    Case& one = cases[index];
    one.index = index;
    one.choice.assign(study.axes.size(), 0);
    for (std::size_t rest = index, k = study.axes.size(); k-- > 0; rest /= study.axes[k].values.size())
      one.choice[k] = rest % study.axes[k].values.size();
    for (const auto& setting : study.set) one.overrides.push_back(setting.key + "=" + setting.value.toml);
    for (std::size_t k = 0; k < study.axes.size(); ++k)  // a linked axis: one override per key
      for (const std::string& assignment : axis_overrides(study.axes[k], study.axes[k].values[one.choice[k]]))
        one.overrides.push_back(assignment);
  }
  return cases;
}

/// The folder of case `index` under `out`: out/cases/0042.
inline std::string case_folder(const std::string& out, std::size_t index) {
  char name[16];
  std::snprintf(name, sizeof name, "%04zu", index);
  return out + "/cases/" + name;
}

/// The arguments of `mpm COMMAND FIRST [SECOND] --set ...` for a case.
inline std::vector<std::string> child_arguments(const std::vector<std::string>& head, const std::vector<std::string>& overrides) {
  std::vector<std::string> arguments{"mpm"};
  arguments.insert(arguments.end(), head.begin(), head.end());
  for (const auto& assignment : overrides) arguments.push_back("--set"), arguments.push_back(assignment);
  return arguments;
}

/// Scores `csv` (a case's observers, at their times or shifted) with `mpm compare` against the scene's exact solution
/// at the observer's reference position; nullopt with `why` set if compare gives no score.
inline std::optional<Measured> score_with_compare(const std::string& program, const std::string& scene, const std::vector<std::string>& overrides,
                                                const std::string& csv, const std::vector<double>& at, const std::vector<std::string>& columns,
                                                std::string& why) {
  std::string position;
  char number[32];
  for (double coordinate : at) std::snprintf(number, sizeof number, "%.17g", coordinate), position += (position.empty() ? "" : ",") + std::string(number);
  std::vector<std::string> head{"compare", csv, scene, "--at", position};
  for (const auto& column : columns)
    head.push_back("--column"), head.push_back(column + "=" + column.substr(column.rfind('.') + 1));
  const ChildRun compare = run_child(program, child_arguments(head, overrides));
  const auto score = compare.exit_code == 0 ? compare_score(compare.out) : std::nullopt;
  if (!score) why = "mpm compare: " + reason_line(compare.err);
  return score;
}

/// `overrides` and, after them, solver.end_time at the last time of the shifted CSV `shifted` when it is after
/// `end_time`: its samples reach up to half a step past the run's end, and mpm compare scores no time after the
/// scene's end time.
inline std::vector<std::string> shifted_overrides(std::vector<std::string> overrides, const std::string& shifted,
                                                  double end_time) {
  std::string error;
  const auto times = read_columns(shifted, {"t"}, error);
  char number[40];
  if (!times.empty() && !times[0].empty() && times[0].back() > end_time)
    std::snprintf(number, sizeof number, "solver.end_time=%.17g", times[0].back()), overrides.push_back(number);
  return overrides;
}

/// The measures of a finished run in `folder` (status done): the two scores of observer
/// `observer` (none when `scored` is false: the scene has no exact solution).
inline void measure_run(const std::string& program, const std::string& scene, const Case& one, const std::string& folder,
                        const toml::table& resolved, const std::string& observer, bool scored, CaseResult& result) {
  std::string error;
  if (!scored || observer.empty()) {
    result.why = scored ? "the scene has no [[observer]] to score" : "the scene names no exact solution: no score";
    return;
  }
  const std::string json = io::read_scene_text(folder + "/run.json");
  const auto at = observer_reference(json, observer);
  std::vector<std::string> columns{observer + ".v_x"};
  if (resolved["dimension"].value_or(1) == 2) columns.push_back(observer + ".v_y");
  result.score_at_t = score_with_compare(program, scene, one.overrides, folder + "/observers.csv", at, columns, result.why);
  const double fraction = velocity_time_shift(resolved), end_time = resolved["solver"]["end_time"].value_or(0.0);
  if (!write_shifted(folder + "/observers.csv", folder + "/observers_shifted.csv", columns, fraction, result.steps.value_or(0),
                     json_number(json, "final_time").value_or(0.0), error))
    result.why = error;
  else {
    const std::string shifted = folder + "/observers_shifted.csv";
    const auto overrides = shifted_overrides(one.overrides, shifted, end_time);
    result.score_shifted = score_with_compare(program, scene, overrides, shifted, at, columns, result.why);
  }
}

/// Why the case folder `folder` cannot take a run of the study ("" if it can): a symbolic link or not a folder.
/// A study's run never writes through a link, nor beside the earlier run's scores (observers_shifted.csv is removed).
inline std::string case_folder_problem(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  const auto status = fs::symlink_status(folder, error);
  if (fs::is_symlink(status)) return "error: " + folder + ": is a symbolic link, and a study's run writes through no link";
  if (fs::exists(status) && !fs::is_directory(status)) return "error: " + folder + ": is not a folder";
  fs::remove(fs::path(folder) / "observers_shifted.csv", error);
  return "";
}

/// Runs case `one` of a study of `scene` into `out`/cases/NNNN with the `mpm` program `program` and the options
/// `limits` (--max-memory), scoring observer `observer` ("" for the scene's first).
/// \throws OutputFailure if the shifted CSV cannot be written.
inline CaseResult run_case(const std::string& program, const std::string& scene, const Case& one, const std::string& out,
                           std::string observer, bool scored, const std::vector<std::string>& limits) {
  CaseResult result;
  std::vector<std::string> print_head{"run", scene, "--print-scene"};
  print_head.insert(print_head.end(), limits.begin(), limits.end());
  const ChildRun printed = run_child(program, child_arguments(print_head, one.overrides));
  if (printed.exit_code != 0) {
    result.status = printed.exit_code == 2 ? "refused" : "failed";
    result.why = reason_line(printed.err);
    if (printed.exit_code == 127) result.not_run = result.why;
    return result;
  }
  toml::table resolved;
  try {
    resolved = toml::parse(printed.out);
  } catch (const toml::parse_error& error) {
    result.why = "mpm run --print-scene: " + std::string(error.description());
    return result;
  }
  if (observer.empty()) observer = resolved["observer"][0]["name"].value_or(std::string());
  const std::string folder = case_folder(out, one.index);
  if (!(result.not_run = case_folder_problem(folder)).empty()) {
    result.why = result.not_run;
    return result;
  }
  std::vector<std::string> run_head{"run", scene, "--out", folder, "--threads", "1"};
  run_head.insert(run_head.end(), limits.begin(), limits.end());
  const ChildRun run = run_child(program, child_arguments(run_head, one.overrides));
  result.wall_s = run.wall_s, result.cpu_s = run.cpu_s;
  std::string json;
  try {
    json = io::read_scene_text(folder + "/run.json");
  } catch (const SceneError&) {  // refused before it wrote anything
  }
  result.steps = json_number(json, "steps");
  const auto failure = json_string(json, "failure");
  if (io::stop_signal != 0 && run.exit_code >= 128) result.status = "interrupted", result.why = "stopped by " + io::signal_name(io::stop_signal);
  else if (run.exit_code == 0) result.status = "done";
  else if (run.exit_code == 2 || run.exit_code == 127)  // the scene passed --print-scene: the folder, or no mpm
    result.why = result.not_run = reason_line(run.err).empty() ? "exit " + std::to_string(run.exit_code) : reason_line(run.err);
  else if (run.exit_code == 3 && failure && failure->find("energy grew") != std::string::npos) result.status = "stopped", result.why = *failure;
  else result.why = failure ? *failure : reason_line(run.err).empty() ? "exit " + std::to_string(run.exit_code) : reason_line(run.err);
  std::string error;
  if (const std::string moved = case_folder_problem(folder); !moved.empty())  // made a link during the run
    result.status = "failed", result.why = result.not_run = moved;
  if (result.not_run.empty()) result.energy_drift = energy_drift(folder + "/energy.csv", error);  // a stopped run's growth too
  if (result.status == "done") measure_run(program, scene, one, folder, resolved, observer, scored, result);
  return result;
}

TEST_CASE("study cases: the product of the axes, the last varying fastest, with [set] before the axes") {
  Study study;
  study.set.push_back({"solver.end_time", {"1e-05", "1e-05", 1e-5}, 3});
  study.axes.push_back({"grid.cells", {{"[10]", "10", 10.0}, {"[20]", "20", 20.0}}, 5});
  study.axes.push_back({"solver.shape", {{"\"linear\"", "linear", {}}, {"\"lme\"", "lme", {}}, {"\"ugimp\"", "ugimp", {}}}, 6});
  const auto cases = expand_cases(study);
  REQUIRE(cases.size() == 6);
  CHECK(cases[4].choice == std::vector<std::size_t>{1, 1});
  CHECK(cases[4].overrides == std::vector<std::string>{"solver.end_time=1e-05", "grid.cells=[20]", "solver.shape=\"lme\""});
  study.axes = {{"grid.cells, solver.dt", {{"[[10], 1e-05]", "10 1e-05", 10.0}}, 7}};
  CHECK(expand_cases(study).at(0).overrides ==
        std::vector<std::string>{"solver.end_time=1e-05", "grid.cells=[10]", "solver.dt=1e-05"});
  CHECK(case_folder("runs/s", 42) == "runs/s/cases/0042");
  CHECK(child_arguments({"run", "a.toml"}, {"x=1"}) == std::vector<std::string>{"mpm", "run", "a.toml", "--set", "x=1"});
  // a shifted CSV whose last time is half a step past the end time 2e-4: compare's end time moved to it, not before
  const std::string shifted =
      (std::filesystem::temp_directory_path() / ("mpm_study_shifted_" + std::to_string(::getpid()) + ".csv")).string();
  std::ofstream(shifted) << "t,A.v_x\n0.5e-4,1\n2.5e-4,1\n";
  CHECK(shifted_overrides({"x=1"}, shifted, 2e-4) == std::vector<std::string>{"x=1", "solver.end_time=0.00025000000000000001"});
  CHECK(shifted_overrides({"x=1"}, shifted, 2.5e-4) == std::vector<std::string>{"x=1"});
  std::filesystem::remove(shifted);
}

}  // namespace mpm::study
