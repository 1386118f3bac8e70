/// \file
/// `mpm run SCENE.toml`: validates the scene, then runs it into its folder, which tells the truth at
/// every moment:
///   1. everything that can be checked before the run is checked (the scene, its particles, the folder:
///      no link where a file goes); a mistake exits 2 and writes nothing;
///   2. the files an earlier run or plot left in the folder are removed (mpm/io/run_folder.hpp);
///   3. run.json is written with "status": "running";
///   4. the run writes its CSV files and snapshots;
///   5. run.json is rewritten as "done", "failed" (exit 3, the failure in "failure") or "interrupted"
///      (SIGINT or SIGTERM: exit 128 + the signal's number, as a shell reports a process killed by it).
/// run.json is replaced atomically, so it is never seen half-written.
#pragma once
#include <signal.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/io/exact_series.hpp"
#include "mpm/io/run_folder.hpp"
#include "mpm/io/run_writer.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/scene_warnings.hpp"
#include "mpm/run.hpp"
#include "mpm/stability.hpp"

namespace mpm::cli {

/// The signal (SIGINT, SIGTERM) that asked the run to stop; 0 while none did.
inline volatile std::sig_atomic_t stop_signal = 0;

inline void on_stop_signal(int signal) { stop_signal = signal; }

/// From now on SIGINT and SIGTERM stop the run at the end of its current step; a second one kills it at once.
inline void stop_on_signals() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  action.sa_flags = SA_RESETHAND;  // the second signal takes its default action
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

/// Raised between two steps after a stop signal.
struct Interrupted {
  int signal;
};

/// Passes everything on to the run's writers, and ends the run after the step in which a signal came.
template <int Dim>
class StopOnSignal : public Monitor<Dim> {
 public:
  explicit StopOnSignal(Monitor<Dim>& next) : next_(next) {}
  void sample(long step, double time, const Particles<Dim>& particles, const Balances<Dim>& balances) override {
    next_.sample(step, time, particles, balances);
  }
  void snapshot(int index, double time, const Particles<Dim>& particles) override { next_.snapshot(index, time, particles); }
  void progress(double time, double end_time) override {
    next_.progress(time, end_time);
    if (stop_signal != 0) throw Interrupted{stop_signal};
  }

 private:
  Monitor<Dim>& next_;
};

/// What `mpm run` was asked to do.
struct RunRequest {
  std::string scene_path, folder;
  std::vector<std::string> overrides;
  bool print_scene = false;
  io::Budget budget;
  int threads = 0;  ///< 0: every core
  io::RunIdentity identity;
};

/// Steps 3-5 of the file's comment: run.json "running", the run, run.json's end. Returns the exit code.
template <int Dim>
int run_into_folder(const io::Scene& scene, const Setup<Dim>& setup, const RunRequest& request) {
  const std::string run_json = request.folder + "/run.json";
  const int count = setup.particles.size();
  RunSummary summary;
  io::write_run_json(run_json, scene, summary, io::RunState::running, "", count, request.identity);
  stop_on_signals();
  io::RunState state = io::RunState::done;
  std::string failure;
  int code = 0;
  try {
    io::RunWriter<Dim> writer(request.folder, scene, setup.observed);
    io::ExactWriter<Dim> exact_then_writer(request.folder, scene, setup.particles, writer);
    StopOnSignal<Dim> monitor(exact_then_writer);
    summary = run_setup<Dim>(scene, setup, monitor, &summary);
    exact_then_writer.finish();
    writer.finish();
  } catch (const SimulationFailure& error) {
    std::cerr << error.message() << "\n";
    state = io::RunState::failed, failure = error.what(), code = 3;
  } catch (const OutputFailure& error) {
    std::cerr << error.message() << "\n";
    state = io::RunState::failed, failure = error.message(), code = 3;
  } catch (const Interrupted& interrupted) {
    const char* name = interrupted.signal == SIGINT ? "SIGINT" : "SIGTERM";
    std::cerr << "interrupted: " << name << " at t = " << summary.final_time << " s; " << run_json << " says so\n";
    state = io::RunState::interrupted, failure = std::string("stopped by ") + name, code = 128 + interrupted.signal;
  } catch (const std::exception& defect) {  // a bug: run.json says so, main() reports it
    io::write_run_json(run_json, scene, summary, io::RunState::failed, std::string("internal error: ") + defect.what(), count,
                       request.identity);
    throw;
  }
  io::write_run_json(run_json, scene, summary, state, failure, count, request.identity);
  if (code != 0) return code;
  std::printf("%s: %ld steps to t = %g s, %d particles, %.3g s wall, %.3g particle-steps/s\nwrote %s\n", scene.title.c_str(),
              summary.steps, summary.final_time, count, summary.wall_seconds, summary.particle_steps_per_second,
              request.folder.c_str());
  return 0;
}

/// Builds the run (which validates what the scene alone cannot: each particle against the shape function)
/// and, unless only --print-scene was asked, runs it. Returns the exit code. \throws SceneError, InputError.
template <int Dim>
int run_scene(io::Scene scene, RunRequest request) {
  scene.control.threads = request.threads;
  const Setup<Dim> setup = build_setup<Dim>(scene);
  if (request.print_scene) {
    io::print_resolved_scene(scene, std::cout);
    return 0;
  }
  for (size_t k = 0; k < setup.observed.size(); ++k) {
    const int p = setup.observed[k];
    const auto& X = setup.particles.reference_position[p];
    request.identity.observed.push_back({scene.observers[k].name, setup.particles.id[p], std::vector<double>(X.data(), X.data() + Dim)});
  }
  io::check_run_folder(request.folder);
  std::unique_ptr<io::FolderLock> lock;  // held until the run has ended
  try {
    std::filesystem::create_directories(request.folder);
    lock = std::make_unique<io::FolderLock>(request.folder);
    io::clear_run_folder(request.folder);
  } catch (const std::filesystem::filesystem_error& error) {
    std::cerr << OutputFailure(request.folder, error.code().message()).message() << "\n";
    return 3;
  } catch (const OutputFailure& failure) {
    std::cerr << failure.message() << "\n";
    return 3;
  }
  try {
    return run_into_folder<Dim>(scene, setup, request);
  } catch (const OutputFailure& failure) {  // run.json itself could not be written
    std::cerr << failure.message() << "\n";
    return 3;
  }
}

/// `mpm run`'s parser, its options bound to `request`.
inline std::unique_ptr<CommandParser> run_parser(RunRequest& request) {
  auto app = std::make_unique<CommandParser>(
      "run",
      "Runs a scene and writes observers.csv, energy.csv, exact.csv (when the scene names an exact solution),\n"
      "snapshot_NNNN.csv/.vtp, snapshots.pvd (ParaView time series) and run.json into its folder; run.json says\n"
      "\"running\", then \"done\", \"failed\" or \"interrupted\". Files of an earlier run there are removed first.\n"
      "Warnings (`warning: FILE:LINE: KEY: ...` on stderr) flag a suspicious but valid scene; they never stop a run.");
  app->add_option("SCENE.toml", request.scene_path, "the scene file (TOML; README.md, \"Scene files\")")->required();
  app->add_option("--out", request.folder, "output folder (default runs/<scene file name>)")->type_name("DIR")
      ->check(CLI::Validator([](const std::string& text) { return text.empty() ? "must not be empty" : ""; }, "DIR"));
  app->add_option("--set", request.overrides,
                  "overrides a scene key with a TOML value: --set solver.cfl=0.2, --set 'solver.shape=\"lme\"',\n"
                  "--set grid.cells=[160], --set 'body[0].max=[1.0]'; repeat for more")
      ->allow_extra_args(false)
      ->type_name("KEY=VALUE");
  app->add_option("--threads", request.threads, "cores to run on (0: all; the results are the same bits on any number)")
      ->check(whole_in(0, 4096));
  app->add_flag("--print-scene", request.print_scene, "prints the resolved scene (every key, defaults filled in) and exits");
  app->add_option("--max-memory", request.budget.max_bytes, "refuse a scene whose estimated memory exceeds SIZE: bytes or <n>K, <n>M, <n>G (0: half the machine's)")
      ->transform(CLI::Validator(
          [](std::string& text) -> std::string {
            const auto bytes = io::parse_byte_size(text);
            if (!bytes) return "'" + text + "' is not a size; give bytes or <n>K, <n>M, <n>G, <n>T";
            text = std::to_string(*bytes);
            return "";
          },
          "SIZE"));
  app->add_option("--max-steps", request.budget.max_steps, "refuse a scene whose end_time / dt at t = 0 exceeds N")
      ->check(number_in(1.0, 1e300));
  app->add_flag("--force", request.budget.force, "run even beyond --max-steps");
  return app;
}

/// `mpm run --help`: the parser's own help.
inline std::string run_usage() {
  RunRequest request;
  return run_parser(request)->help();
}

/// Reads `mpm run`'s arguments into `request`. Returns nullopt when the run should go on, else the exit code.
inline std::optional<int> read_run_options(const std::vector<std::string>& arguments, RunRequest& request, std::ostream& out,
                                           std::ostream& err) {
  if (const auto code = parse_arguments(*run_parser(request), arguments, "run", out, err)) return code;
  if (request.folder.empty()) request.folder = "runs/" + std::filesystem::path(request.scene_path).stem().string();
  return std::nullopt;
}

/// `mpm run` once its options are read. Returns the exit code.
inline int run_command(const RunRequest& request) {
  try {
    const io::Scene scene = load_scene(request.scene_path, request.overrides, request.budget);
    for (const auto& warning : io::scene_warnings(request.scene_path, request.overrides, scene, scene_cfl_limit_if_exceeded(scene)))
      std::cerr << warning << "\n";
    return scene.dimension == 1 ? run_scene<1>(scene, request) : run_scene<2>(scene, request);
  } catch (const SceneError& error) {
    std::cerr << error.message() << "\n";
    return 2;
  } catch (const InputError& error) {
    std::cerr << error.message() << "\n";
    return 2;
  }
}

}  // namespace mpm::cli
