/// \file
/// A run's output folder before the run writes into it: a new run removes every file of the names `mpm run` and
/// `mpm plot` write (run_output_name) that an earlier run or plot left, so that the folder never mixes two runs,
/// and touches no other file; run.json says "clearing" meanwhile, or is removed first. A symbolic link under one of those names is refused before anything is written.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/io/stop_signals.hpp"

namespace mpm::io {

/// True if `name` is a file `mpm run` or `mpm plot` writes: run.json, snapshots.pvd, snapshot_NNNN.csv / .vtp
/// (and the .vtk of earlier versions), exact_NNNN.csv, the hidden temporaries of those (".run.json.partial"),
/// observers.csv, energy.csv, exact.csv, grid.csv, plot.gp, plot.log, observers.png, energy.png and
/// profile_NNNN.png.
inline bool run_output_name(const std::string& name) {
  static const std::regex names(
      R"((\.(run\.json|snapshots\.pvd|snapshot_\d{4}\.(csv|vtp|vtk)|exact_\d{4}\.csv|grid\.csv)\.partial)|)"
      R"(run\.json|snapshots\.pvd|snapshot_\d{4}\.(csv|vtp|vtk)|exact_\d{4}\.csv|profile_\d{4}\.png|)"
      R"((observers|energy|exact|grid)\.csv|plot\.(gp|log)|(observers|energy)\.png)");
  return std::regex_match(name, names);
}

/// The entries of `folder` (none if it does not exist) that run_output_name names.
inline std::vector<std::filesystem::directory_entry> run_outputs_in(const std::string& folder) {
  std::vector<std::filesystem::directory_entry> outputs;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return outputs;  // made later, or not a folder: a write fails
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (run_output_name(entry.path().filename().string())) outputs.push_back(entry);
  return outputs;
}

/// The default folder of a run or a study of `file`: runs/NAME, NAME the file's name without its extension. A name
/// of "", "." or ".." (a file named `...toml` or `..toml`) would make it runs/ itself or the current folder: refused.
/// \throws InputError naming the file.
inline std::string default_folder(const std::string& file) {
  namespace fs = std::filesystem;
  const std::string name = fs::path(file).stem().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(file, "its name without the extension is '" + name + "', and runs/" + name +
                               " is no folder of its own; give --out DIR, or rename the file");
  const std::string folder = "runs/" + name;
  std::error_code error;  // runs/NAME, or runs/, a link to the current folder or one above it: the same refusal
  const fs::path resolved = fs::weakly_canonical(folder, error), here = fs::current_path(error);
  const fs::path up = here.lexically_relative(resolved);  // "." or "a/b" when it is here or above; "../x" else
  if (!error && !resolved.empty() && !up.empty() && *up.begin() != "..")
    throw InputError(folder, "leads (through a symbolic link) to " + resolved.string() +
                                 ", the current folder or one above it; give --out DIR, or remove the link");
  return folder;
}

/// Refuses an --out that is not a folder (a file, a device, a link to nothing) and a folder holding a symbolic
/// link or a non-file under an output's name; writes nothing. \throws InputError naming the path.
inline void check_run_folder(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_symlink(fs::symlink_status(folder, error)) && !fs::exists(fs::status(folder, error)))
    throw InputError(folder, "is a symbolic link to nothing; give a folder (--out), or a link to one");
  if (fs::exists(fs::status(folder, error)) && !fs::is_directory(fs::status(folder, error)))
    throw InputError(folder, "is not a folder; give a folder (--out), made if it does not exist");
  for (const auto& entry : run_outputs_in(folder)) {
    if (entry.is_symlink(error))
      throw InputError(entry.path().string(), "is a symbolic link where mpm writes a file; mpm writes through no "
                                              "link: remove it, or give another --out");
    if (!entry.is_regular_file(error))
      throw InputError(entry.path().string(), "is not a regular file, and mpm writes a file of that name: remove "
                                              "it, or give another --out");
  }
}

/// An exclusive lock (flock(2) on the folder itself, ending with the process) while a run or a plot writes into a
/// folder, so that a second one is refused rather than mix its files with the first's.
class FolderLock {
 public:
  /// \throws InputError if another process holds the folder, OutputFailure if it cannot be opened.
  explicit FolderLock(const std::string& folder)
      : descriptor_(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (descriptor_ < 0) throw OutputFailure(folder, std::strerror(errno));
    if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
      ::close(descriptor_);
      throw InputError(folder, "another mpm run or plot is writing into this folder; wait for it to end, or give "
                               "another --out");
    }
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock() { ::close(descriptor_); }

  /// True if `folder` is still the folder locked (not moved away, nor replaced by another or by a link meanwhile).
  bool still_at(const std::string& folder) const {
    struct stat locked {}, now {};
    return ::fstat(descriptor_, &locked) == 0 && ::stat(folder.c_str(), &now) == 0 && locked.st_dev == now.st_dev &&
           locked.st_ino == now.st_ino;
  }

  /// The path of `name` in the folder locked, wherever it is now (Linux's /proc/self/fd/N).
  std::string path_in(const std::string& name) const {
    return "/proc/self/fd/" + std::to_string(descriptor_) + "/" + name;
  }

 private:
  int descriptor_;
};

/// What clear_run_folder() does with the earlier run.json.
enum class EarlierRunJson {
  remove_first,  ///< removed before any other file: a clear cut short leaves no run.json saying "done" (a study's)
  keep           ///< kept, already rewritten as "clearing" (`mpm run`'s), to be rewritten again as "running"
};

/// Removes the files an earlier run or plot wrote into `folder` (after check_run_folder), stopping between two
/// removals after a stop signal (stop_signals.hpp). \throws OutputFailure if one cannot be removed, Interrupted.
inline void clear_run_folder(const std::string& folder, EarlierRunJson run_json = EarlierRunJson::remove_first) {
  const auto remove = [](const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::remove(path, error);
    if (error) throw OutputFailure(path.string(), "cannot remove the file of an earlier run: " + error.message());
  };
  if (run_json == EarlierRunJson::remove_first) remove(std::filesystem::path(folder) / "run.json");
  for (const auto& entry : run_outputs_in(folder)) {
    stop_if_signalled();
    if (entry.path().filename() != "run.json") remove(entry.path());
  }
}

TEST_CASE("run folder: an earlier run's files removed, other files kept, a link refused") {
  for (const char* name : {"snapshot_0001.csv", "snapshot_9999.vtk", ".run.json.partial", ".snapshot_0003.vtp.partial",
                           "plot.log", "energy.png", "exact.csv", "snapshots.pvd", "exact_0002.csv", "grid.csv",
                           "profile_0002.png", ".exact_0002.csv.partial"})
    CHECK_MESSAGE(run_output_name(name), name);
  for (const char* name : {"snapshot_12345.vtk", "snapshot_00001.csv", ".plot.gp.partial", ".notes.partial", ".partial",
                           "snapshot_001.csv", "snapshot_00a1.csv", "snapshot_0001.txt", "notes.csv", ".run.json",
                           "run.json.partial", "xrun.json", "exact_002.csv", "profile_0002.csv"})
    CHECK_MESSAGE(!run_output_name(name), name);
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("mpm_run_folder_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  for (const char* name : {"exact.csv", "snapshot_0009.vtk", "plot.gp", "mine.csv"}) std::ofstream(folder / name) << "x\n";
  check_run_folder(folder.string());
  std::ofstream(folder / "run.json") << "{\"status\": \"clearing\"}\n";
  stop_signal = SIGTERM;  // a stop signal: the clear stops before its first removal, run.json and the rest kept
  CHECK_THROWS_AS(clear_run_folder(folder.string(), EarlierRunJson::keep), Interrupted);
  CHECK(fs::exists(folder / "exact.csv"));
  stop_signal = 0;
  clear_run_folder(folder.string(), EarlierRunJson::keep);
  CHECK(fs::exists(folder / "run.json"));
  CHECK(!fs::exists(folder / "exact.csv"));
  clear_run_folder(folder.string());
  CHECK(!fs::exists(folder / "run.json"));
  CHECK(!fs::exists(folder / "snapshot_0009.vtk"));
  CHECK(!fs::exists(folder / "plot.gp"));
  CHECK(fs::exists(folder / "mine.csv"));
  fs::create_symlink(folder / "mine.csv", folder / "energy.csv");
  CHECK_THROWS_WITH_AS(check_run_folder(folder.string()), doctest::Contains("symbolic link"), InputError);
  fs::remove(folder / "energy.csv");
  {
    FolderLock first(folder.string());
    CHECK_THROWS_WITH_AS(FolderLock{folder.string()}, doctest::Contains("another mpm run"), InputError);
  }
  FolderLock again(folder.string());  // the first lock ended with its object
  CHECK_THROWS_WITH_AS(check_run_folder((folder / "mine.csv").string()), doctest::Contains("not a folder"), InputError);
  CHECK(default_folder("scenes/dyka_bar.toml") == "runs/dyka_bar");
  CHECK(default_folder("a/.hidden.toml") == "runs/.hidden");
  for (const char* dotted : {"...toml", "..toml", "dir/...toml", "..", "."})
    CHECK_THROWS_WITH_AS(default_folder(dotted), doctest::Contains("no folder of its own"), InputError);
  const fs::path here = fs::current_path();  // runs/up, a link to the folder above the current one: refused
  fs::current_path(folder);
  fs::create_directories("runs");
  fs::create_symlink("../..", "runs/up");
  fs::create_symlink(".", "runs/own");
  CHECK_THROWS_WITH_AS(default_folder("up.toml"), doctest::Contains("the current folder or one above it"), InputError);
  CHECK_NOTHROW(default_folder("own.toml"));  // runs/own is runs/ itself, below the current folder
  CHECK(default_folder("new.toml") == "runs/new");
  fs::current_path(here);
  fs::create_symlink(folder / "nothing", folder / "dangling");
  CHECK_THROWS_WITH_AS(check_run_folder((folder / "dangling").string()), doctest::Contains("link to nothing"), InputError);
  fs::create_directory(folder / "run.json");
  CHECK_THROWS_AS(check_run_folder(folder.string()), InputError);
  CHECK(again.still_at(folder.string()));
  fs::rename(folder, folder.string() + "_moved");
  fs::create_directories(folder);
  CHECK(!again.still_at(folder.string()));  // another folder under its name
  std::ofstream(again.path_in("left.txt")) << "x\n";
  CHECK(fs::exists(folder.string() + "_moved/left.txt"));
  fs::remove_all(folder.string() + "_moved");
  fs::remove_all(folder);
}

}  // namespace mpm::io
