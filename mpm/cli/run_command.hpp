/// \file
/// `mpm run SCENE.toml`: checks all it can (the scene, its particles, its steps, the folder) before writing anything
/// (exit 2), removes what an earlier run or plot left in the folder (run.json "clearing"), writes run.json "running",
/// runs, and rewrites run.json as "done", "failed" (exit 3) or "interrupted" (a stop signal, stop_signals.hpp: exit
/// 128 + the signal's number).
#pragma once
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mpm/cli/options.hpp"
#include "mpm/io/exact_series.hpp"
#include "mpm/io/run_folder.hpp"
#include "mpm/io/run_writer.hpp"
#include "mpm/io/scene_resolved.hpp"
#include "mpm/io/scene_warnings.hpp"
#include "mpm/io/stop_signals.hpp"
#include "mpm/run_api.hpp"
#include "mpm/stability_api.hpp"

namespace mpm::cli {

/// What `mpm run` was asked to do.
struct RunRequest {
  std::string scene_path, folder;
  std::vector<std::string> overrides;
  bool print_scene = false;
  io::Budget budget;
  int threads = 0;  ///< 0: every core
  io::RunIdentity identity;
};

/// Writes run.json "running", runs (a stop signal ending the run after the current step, stop_signals.hpp), and
/// rewrites run.json as the run ended. Returns the exit code. \throws OutputFailure.
template <int Dim>
int run_into_folder(const io::Scene& scene, const Setup<Dim>& setup, const RunRequest& request, const io::FolderLock& lock) {
  std::string run_json = request.folder + "/run.json";
  const int count = setup.particles.size();
  RunSummary summary;
  io::write_run_json(run_json, scene, summary, io::RunState::running, "", count, request.identity);
  io::RunState state = io::RunState::failed;
  std::string failure;
  int code = 3;
  bool cannot_write = false;  // then run.json likely cannot be written either: one `cannot write` line is enough
  try {
    io::RunWriter<Dim> writer(request.folder, scene, setup.observed);
    io::ExactWriter<Dim> monitor(request.folder, scene, setup.particles, setup.observed, writer);
    summary = run_setup<Dim>(scene, setup, monitor, &summary);
    monitor.finish();
    writer.finish();
    state = io::RunState::done;
    code = 0;
  } catch (const SimulationFailure& error) {
    std::cerr << error.message() << "\n";
    failure = error.what();
  } catch (const OutputFailure& error) {
    std::cerr << error.message() << "\n";
    failure = error.message();
    cannot_write = true;
  } catch (const io::Interrupted& interrupted) {
    const std::string name = io::signal_name(interrupted.signal);
    std::cerr << "interrupted: " << name << " at t = " << summary.final_time << " s; " << run_json << " says so\n";
    state = io::RunState::interrupted;
    failure = "stopped by " + name;
    code = 128 + interrupted.signal;
  } catch (const std::exception& defect) {  // a bug: run.json says so, main() reports it
    failure = std::string("internal error: ") + defect.what();
    io::write_run_json(run_json, scene, summary, state, failure, count, request.identity);
    throw;
  }
  if (!cannot_write && !lock.still_at(request.folder)) {  // moved or replaced during the run: run.json where it began
    std::cerr << "error: " << request.folder << ": moved or replaced during the run; its run.json says so in the "
              << "folder the run began in\n";
    run_json = lock.path_in("run.json"), state = io::RunState::failed, code = 3;
    failure = "the folder " + request.folder + " was moved or replaced during the run";
  }
  try {
    io::write_run_json(run_json, scene, summary, state, failure, count, request.identity);
  } catch (const OutputFailure&) {
    if (!cannot_write) throw;
  }
  if (code != 0) return code;
  std::printf("%s: %ld steps to t = %g s, %d particles, %.3g s wall, %.3g particle-steps/s\nwrote %s\n",
              scene.title.c_str(), summary.steps, summary.final_time, count, summary.wall_seconds,
              summary.particle_steps_per_second, request.folder.c_str());
  return 0;
}

/// Removes what an earlier run or plot left in the run's (locked) folder, run.json saying "clearing" meanwhile.
/// Returns 0, or the exit code of a stop signal during the clear (run.json then says "interrupted").
/// \throws OutputFailure.
template <int Dim>
int clear_earlier_run(const io::Scene& scene, const Setup<Dim>& setup, const RunRequest& request) {
  if (io::run_outputs_in(request.folder).empty()) return 0;
  const std::string run_json = request.folder + "/run.json";
  const int count = setup.particles.size();
  io::write_run_json(run_json, scene, {}, io::RunState::clearing, "", count, request.identity);
  try {
    io::clear_run_folder(request.folder, io::EarlierRunJson::keep);
  } catch (const io::Interrupted& interrupted) {
    const std::string name = io::signal_name(interrupted.signal);
    std::cerr << "interrupted: " << name << " while removing an earlier run's files; " << run_json << " says so\n";
    io::write_run_json(run_json, scene, {}, io::RunState::interrupted,
                       "stopped by " + name + " while removing an earlier run's files", count, request.identity);
    return 128 + interrupted.signal;
  }
  return 0;
}

/// The fastest particle at t = 0, whatever set its velocity (the scene, a formula, an exact solution).
template <int Dim>
double fastest_particle_speed(const Particles<Dim>& particles) {
  double fastest = 0.0;
  for (int p = 0; p < particles.size(); ++p) fastest = std::max(fastest, particles.velocity[p].norm());
  return fastest;
}

/// Builds the run (which checks each particle against the shape function) and checks its steps at the particles'
/// own speeds, then prints the resolved scene (--print-scene) or runs it into its folder, locked and cleared.
/// Returns the exit code. \throws SceneError, InputError, OutputFailure.
template <int Dim>
int run_scene(io::Scene scene, RunRequest request) {
  scene.control.threads = request.threads;
  const double most_steps = request.budget.force ? 0.0 : std::min(request.budget.max_steps, 9e18);
  scene.control.max_steps = static_cast<long>(most_steps);
  const Setup<Dim> setup = build_setup<Dim>(scene);
  io::check_step_budget(scene, request.budget, io::initial_time_step(scene, fastest_particle_speed(setup.particles)));
  if (request.print_scene) {
    io::print_resolved_scene(scene, std::cout);
    return 0;
  }
  for (size_t k = 0; k < setup.observed.size(); ++k) {
    const int p = setup.observed[k];
    const auto& X = setup.particles.reference_position[p];
    request.identity.observed.push_back(
        {scene.observers[k].name, setup.particles.id[p], std::vector<double>(X.data(), X.data() + Dim)});
  }
  io::check_run_folder(request.folder);
  std::error_code error;
  std::filesystem::create_directories(request.folder, error);
  if (error) throw OutputFailure(request.folder, error.message());
  const io::FolderLock lock(request.folder);  // held until the run has ended
  io::catch_stop_signals();
  if (const int code = clear_earlier_run<Dim>(scene, setup, request)) return code;
  return run_into_folder<Dim>(scene, setup, request, lock);
}

/// A parser of a command that runs a scene (`mpm run`, `mpm trace`), with the options they share, declared
/// once: SCENE.toml, required, and --set KEY=VALUE, repeatable, bound to `scene_path` and `overrides`, and
/// --kernels K, which adds the override solver.kernels = K after them.
inline std::unique_ptr<CommandParser> scene_command_parser(const std::string& name, const std::string& description,
                                                           std::string& scene_path,
                                                           std::vector<std::string>& overrides) {
  auto app = std::make_unique<CommandParser>(name, description);
  app->add_option("SCENE.toml", scene_path, "the scene file (TOML; README.md, \"Scene files\")")->required();
  app->add_option("--set", overrides,
                  "overrides a scene key with a TOML value: --set solver.cfl=0.2, --set 'solver.shape=\"lme\"',\n"
                  "--set grid.cells=[160], --set 'body[0].max=[1.0]'; repeat for more")
      ->allow_extra_args(false)
      ->type_name("KEY=VALUE");
  const auto& words = io::choice_words<io::KernelsKind>;
  app->add_option_function<std::string>(
         "--kernels",
         [&overrides](const std::string& kernels) { overrides.push_back("solver.kernels=\"" + kernels + "\""); },
         "short for --set 'solver.kernels=\"...\"' (after every --set): fast (default) | reference, the plain kernels "
         "the book shows")
      ->check(one_of(std::vector<std::string>(words.begin(), words.end())));
  return app;
}

/// `mpm run`'s parser, its options bound to `request`.
inline std::unique_ptr<CommandParser> run_parser(RunRequest& request) {
  auto app = scene_command_parser(
      "run",
      "Runs a scene and writes observers.csv, energy.csv, grid.csv, exact.csv and exact_NNNN.csv (when the scene\n"
      "names an exact solution), snapshot_NNNN.csv/.vtp, snapshots.pvd (ParaView time series) and run.json into\n"
      "its folder; run.json says \"running\", then \"done\", \"failed\" or \"interrupted\". Files of an earlier run\n"
      "there are removed first.\n"
      "Warnings (`warning: FILE:LINE: KEY: ...` on stderr) flag a suspicious but valid scene; they never stop a run.",
      request.scene_path, request.overrides);
  app->add_option("--out", request.folder, "output folder (default runs/<scene file name>)")
      ->type_name("DIR")
      ->check(CLI::Validator([](const std::string& text) { return text.empty() ? "must not be empty" : ""; }, "DIR"));
  app->add_option("--threads", request.threads, "cores to run on (0: all; the results are the same bits on any number)")
      ->check(whole_in(0, 4096));
  app->add_flag("--print-scene", request.print_scene,
                "prints the resolved scene (every key, defaults filled in) and exits");
  app->add_option("--max-memory", request.budget.max_bytes,
                  "refuse a scene whose estimated memory exceeds SIZE: bytes or <n>K, <n>M, <n>G "
                  "(0: half the machine's)")
      ->transform(CLI::Validator(
          [](std::string& text) -> std::string {
            const auto bytes = io::parse_byte_size(text);
            if (!bytes) return "'" + text + "' is not a size; give bytes or <n>K, <n>M, <n>G, <n>T";
            text = std::to_string(*bytes);
            return "";
          },
          "SIZE"));
  app->add_option("--max-steps", request.budget.max_steps, "refuse a scene whose end_time / dt at t = 0 (with a step for each output time) exceeds N,\n"
                  "and stop a run (exit 3) that would take a step more")
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
inline std::optional<int> read_run_options(const std::vector<std::string>& arguments, RunRequest& request,
                                           std::ostream& out, std::ostream& err) {
  if (const auto code = parse_arguments(*run_parser(request), arguments, "run", out, err)) return code;
  try {
    if (request.folder.empty()) request.folder = io::default_folder(request.scene_path);
  } catch (const InputError& error) {
    err << error.message() << "\n";
    return 2;
  }
  return std::nullopt;
}

/// `mpm run` once its options are read. Returns the exit code: 2 for a mistake in the input, 3 for a file that
/// cannot be written.
inline int run_command(const RunRequest& request) {
  try {
    const io::Scene scene = load_scene(request.scene_path, request.overrides, request.budget);
    for (const auto& warning :
         io::scene_warnings(request.scene_path, request.overrides, scene, scene_cfl_limit_if_exceeded(scene)))
      std::cerr << warning << "\n";
    return scene.dimension == 1 ? run_scene<1>(scene, request) : run_scene<2>(scene, request);
  } catch (const SceneError& error) {
    std::cerr << error.message() << "\n";
    return 2;
  } catch (const InputError& error) {
    std::cerr << error.message() << "\n";
    return 2;
  } catch (const OutputFailure& failure) {
    std::cerr << failure.message() << "\n";
    return 3;
  }
}

}  // namespace mpm::cli
