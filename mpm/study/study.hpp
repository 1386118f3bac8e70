/// \file
/// `mpm study STUDY.toml [--out DIR] [--jobs N]`: a study of any scene from its study file (study_file.hpp),
/// in this order:
///   1. the study file is read and every key checked; the scene with the study's [set] is resolved by
///      `mpm run --print-scene` (a refusal there is the study's: its `--set(n)` named by the study's line) and
///      the observer looked up in it; the folder is checked. Any problem: `error: FILE:LINE: KEY: why`, exit 2,
///      nothing written;
///   2. the folder is locked (a second study into it is refused), the stop signals caught, and what an earlier study
///      wrote there removed;
///   3. the cases run in parallel (runner.hpp, cases.hpp), each run with half the machine's memory shared among the
///      jobs (--max-memory), with a progress line on stderr;
///   4. study.csv, fits.csv (with a refine axis) and the pictures are written (write.hpp), and their names printed.
/// Exit codes: 0 written (whatever the runs' outcomes: they are rows of study.csv); 2 a bad study, scene or folder;
/// 3 a file could not be written (`error: FILE: cannot write: why`), gnuplot failed, or a case could not run (its
/// folder made a link or held by another run meanwhile: its row says why); 128 + N after stop signal N, forwarded to
/// the runs and waited for (stop_signals.hpp), study.csv then not written.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "mpm/io/run_folder.hpp"
#include "mpm/study/runner.hpp"
#include "mpm/study/write.hpp"

namespace mpm::study {

/// What `mpm study` was asked.
struct StudyRequest {
  std::string study_path, out;  ///< out "": `runs/STUDY`, STUDY the study file's name
  unsigned jobs = 0;            ///< 0: the machine's cores
  std::string program = "/proc/self/exe";
};

/// The files a study writes into its folder (besides cases/).
inline const std::vector<std::string>& study_output_names() {
  static const std::vector<std::string> names{"study.csv", "fits.csv", "study.gp", "error.png", "cost.png"};
  return names;
}

/// A refusal by `mpm run --print-scene` of the scene with the study's [set], its `--set(n):1:` replaced by the
/// study file and the line of the n-th [set] entry.
inline std::string study_refusal(const Study& study, const std::string& message) {
  const std::string prefix = "error: --set(";
  if (message.rfind(prefix, 0) != 0) return message;
  const std::size_t close = message.find("):1:");
  const std::size_t n = std::strtoul(message.c_str() + prefix.size(), nullptr, 10);
  if (close == std::string::npos || n < 1 || n > study.set.size()) return message;
  return "error: " + study.path + ":" + std::to_string(study.set[n - 1].line) + ":" + message.substr(close + 4);
}

/// Resolves the study's scene with its [set] (a child `mpm run --print-scene`); checks its observer and says
/// whether the scene has an exact solution to score against. \throws SceneError (the study's) or InputError.
inline bool check_scene(const Study& study, const std::string& program) {
  std::vector<std::string> overrides;
  for (const auto& setting : study.set) overrides.push_back(setting.key + "=" + setting.value.toml);
  const ChildRun printed = run_child(program, child_arguments({"run", study.scene, "--print-scene"}, overrides));
  if (printed.exit_code != 0) throw InputError(study.path, study_refusal(study, reason_line(printed.err)));
  const toml::table resolved = toml::parse(printed.out);
  std::vector<std::string> names;
  if (const auto* observers = resolved["observer"].as_array())
    for (const auto& observer : *observers)
      if (const auto* table = observer.as_table()) names.push_back((*table)["name"].value_or(std::string()));
  if (study.observer && std::find(names.begin(), names.end(), *study.observer) == names.end()) {
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
    throw SceneError(study.path, study.observer_line, "observer", "no [[observer]] '" + *study.observer + "' in the scene (" +
                                                                      (list.empty() ? "it has none" : list) + ")");
  }
  return resolved["exact"].value_or(std::string("none")) != "none";
}

/// Refuses a --out that is not a folder, a link or a non-file under a name the study writes, and a `cases` that
/// is not a folder; writes nothing. \throws InputError.
inline void check_study_folder(const std::string& out) {
  namespace fs = std::filesystem;
  io::check_run_folder(out);  // the folder itself, as mpm run checks it
  std::error_code error;
  for (const auto& name : study_output_names()) {
    const auto status = fs::symlink_status(out + "/" + name, error);
    if (fs::exists(status) && !fs::is_regular_file(status))
      throw InputError(out + "/" + name, "is a symbolic link or not a regular file, where mpm study writes a file: remove it, or give another --out");
  }
  const auto cases = fs::symlink_status(out + "/cases", error);
  if (fs::exists(cases) && !fs::is_directory(cases))
    throw InputError(out + "/cases", "is not a folder (a link, a file), where mpm study writes the cases' folders: remove it, or give another --out");
  for (const auto& entry : fs::directory_iterator(out + "/cases", error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() == 4 && name.find_first_not_of("0123456789") == std::string::npos &&
        (entry.is_symlink(error) || !entry.is_directory(error)))
      throw InputError(entry.path().string(), "is a symbolic link or not a folder, where mpm study writes a case's "
                                              "folder (it writes through no link): remove it, or give another --out");
  }
}

/// Removes what an earlier study wrote into `out`: its files, and in cases/NNNN what the runs wrote (a case folder
/// left empty is removed; another file in it is kept), stopping after a stop signal. \throws OutputFailure,
/// io::Interrupted.
inline void clear_study_folder(const std::string& out) {
  namespace fs = std::filesystem;
  std::error_code error;
  for (const auto& name : study_output_names())
    if (fs::remove(out + "/" + name, error), error) throw OutputFailure(out + "/" + name, "cannot remove an earlier study's file: " + error.message());
  for (const auto& entry : fs::directory_iterator(out + "/cases", error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() != 4 || name.find_first_not_of("0123456789") != std::string::npos || entry.is_symlink() || !entry.is_directory()) continue;
    io::check_run_folder(entry.path().string());
    const io::FolderLock lock(entry.path().string());  // a run of another study or a user's writing there: refused
    io::clear_run_folder(entry.path().string());  // its run.json first: a clear cut short leaves none saying "done"
    fs::remove(entry.path() / "observers_shifted.csv", error);
    fs::remove(entry.path(), error);  // only when empty
  }
}

/// Draws `pictures` (names in `out`) with gnuplot running `script` there; a picture not drawn whole is removed.
/// \throws OutputFailure naming it, with gnuplot's first message.
inline void draw_pictures(const std::string& out, const std::string& script, const std::vector<std::string>& pictures) {
  std::vector<std::string> paths;
  for (const auto& picture : pictures) paths.push_back(out + "/" + picture);
  cli::draw_with_gnuplot(out, script, paths);
}

/// Writes the study's files into `out` and returns their paths. \throws OutputFailure.
inline std::vector<std::string> write_study(const Study& study, const std::vector<Case>& cases, const std::vector<CaseResult>& results,
                                            const std::string& out) {
  std::vector<std::string> written{out + "/study.csv"};
  io::write_file(written.back(), study_csv(study, cases, results));
  if (study.refine >= 0) io::write_file(out + "/fits.csv", fits_csv(study, fit_orders(study, cases, results))), written.push_back(out + "/fits.csv");
  const auto at_t = study.refine >= 0 ? score_curves(study, cases, results, "rms_at_t", false) : std::vector<Curve>{};
  const auto shifted = study.refine >= 0 ? score_curves(study, cases, results, "rms_at_integrator_time", false) : std::vector<Curve>{};
  const auto cost = score_curves(study, cases, results, "rms_at_integrator_time", true);
  std::vector<std::string> pictures;
  if (!at_t.empty() || !shifted.empty()) pictures.push_back("error.png");
  if (!cost.empty()) pictures.push_back("cost.png");
  if (pictures.empty()) return written;
  std::string refine, tics;
  if (study.refine >= 0) {
    refine = study.axes[study.refine].key;
    for (const auto& value : study.axes[study.refine].values) tics += (tics.empty() ? "(" : ", ") + number_cell(value.number);
    tics += ")";
  }
  const std::string script = study_script(at_t, shifted, cost, refine, tics, "error.png", "cost.png");
  io::write_file(out + "/study.gp", script);
  written.push_back(out + "/study.gp");
  draw_pictures(out, script, pictures);
  for (const auto& picture : pictures) written.push_back(out + "/" + picture);
  return written;
}

/// Writes `message` and a line break on `err`; returns `code`.
inline int report(std::ostream& err, const std::string& message, int code) {
  err << message << "\n";
  return code;
}

/// Names on `err` each case the study could not run (CaseResult::not_run); returns 3 if there is one, else 0.
inline int cases_not_run(const std::vector<Case>& cases, const std::vector<CaseResult>& results, const std::string& out,
                         std::ostream& err) {
  int code = 0;
  for (std::size_t k = 0; k < results.size(); ++k)
    if (!results[k].not_run.empty())
      code = report(err, "error: " + case_folder(out, cases[k].index) + ": the case could not run (" + results[k].not_run + ")", 3);
  return code;
}

/// `mpm study`: checks, runs and writes the study; returns the exit code (0, 2 or 3), messages on `err`.
inline int run_study(const StudyRequest& request, std::ostream& out, std::ostream& err) {
  Study study;
  std::string folder;
  bool scored = false;
  try {
    study = read_study(request.study_path);
    scored = check_scene(study, request.program);
    try {
      folder = request.out.empty() ? io::default_folder(study.path) : request.out;
    } catch (const InputError& error) {  // the study file's own name: `error: FILE: why`
      return report(err, error.message(), 2);
    }
    check_study_folder(folder);
  } catch (const SceneError& error) {
    return report(err, error.message(), 2);
  } catch (const InputError& error) {  // the scene's refusal comes whole, its own `error: FILE:LINE: KEY: why`
    return report(err, error.path == study.path ? std::string(error.what()) : error.message(), 2);
  } catch (const toml::parse_error& error) {
    return report(err, "error: " + study.scene + ": mpm run --print-scene: " + std::string(error.description()), 2);
  }
  try {
    std::filesystem::create_directories(folder + "/cases");
    const io::FolderLock lock(folder);
    io::catch_stop_signals();
    clear_study_folder(folder);
    const auto cases = expand_cases(study);
    const unsigned jobs = request.jobs ? request.jobs : std::max(1u, std::thread::hardware_concurrency());
    const std::string observer = study.observer.value_or("");
    const std::vector<std::string> limits{"--max-memory", std::to_string(io::default_max_memory() / jobs)};
    const auto results = run_cases(
        cases, jobs, [&](const Case& one) { return run_case(request.program, study.scene, one, folder, observer, scored, limits); },
        err);
    if (io::stop_signal != 0) throw io::Interrupted{io::stop_signal};
    for (const auto& path : write_study(study, cases, results, folder)) out << path << "\n";
    return cases_not_run(cases, results, folder, err);
  } catch (const io::Interrupted& interrupted) {
    return report(err, "interrupted: " + io::signal_name(interrupted.signal) + "; the runs it had started were told and have ended (their "
                       "run.json say so); study.csv not written", 128 + interrupted.signal);
  } catch (const InputError& error) {
    return report(err, error.message(), 2);
  } catch (const OutputFailure& error) {
    return report(err, error.message(), 3);
  } catch (const std::filesystem::filesystem_error& error) {
    return report(err, "error: " + error.path1().string() + ": cannot write: " + error.code().message(), 3);
  }
  return 0;
}

TEST_CASE("study: a refusal of its [set] named by the study's line, its folder's links refused") {
  Study study;
  study.path = "s.toml";
  study.set.push_back({"solver.cfl", {"-1", "-1", -1.0}, 7});
  CHECK(study_refusal(study, "error: --set(1):1: solver.cfl: must be > 0") == "error: s.toml:7: solver.cfl: must be > 0");
  CHECK(study_refusal(study, "error: x.toml:3: grid.cells: bad") == "error: x.toml:3: grid.cells: bad");
  CHECK(study_refusal(study, "error: --set(2):1: k: bad") == "error: --set(2):1: k: bad");
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("mpm_study_folder_" + std::to_string(::getpid()));
  fs::create_directories(folder / "cases" / "0003");
  io::write_file((folder / "cases" / "0003" / "run.json").string(), "{}\n");
  io::write_file((folder / "cases" / "0003" / "notes.txt").string(), "mine\n");
  fs::create_directories(folder / "cases" / "0004");
  io::write_file((folder / "cases" / "0004" / "observers_shifted.csv").string(), "t\n");
  io::write_file((folder / "study.csv").string(), "old\n");
  check_study_folder(folder.string());
  clear_study_folder(folder.string());
  CHECK(!fs::exists(folder / "study.csv"));
  CHECK(!fs::exists(folder / "cases" / "0003" / "run.json"));
  CHECK(fs::exists(folder / "cases" / "0003" / "notes.txt"));  // not the study's: kept, and its folder with it
  CHECK(!fs::exists(folder / "cases" / "0004"));
  fs::create_symlink("/etc/passwd", folder / "fits.csv");
  CHECK_THROWS_AS(check_study_folder(folder.string()), InputError);
  fs::remove_all(folder);
}

}  // namespace mpm::study
