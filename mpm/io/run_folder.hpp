/// \file
/// A run's output folder before the run writes into it. `mpm run` and `mpm plot` write files of known
/// names only (run_output_name); a new run first removes every such file an earlier run or plot left
/// there, so that the folder never mixes two runs (a stale exact.csv drawn beside new observers, the
/// snapshots of a longer run), and touches no other file. A symbolic link under one of those names was
/// not written by mpm: the run refuses it before writing anything rather than write through it.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/io/output_file.hpp"

namespace mpm::io {

/// True if `name` is a file `mpm run` writes atomically: run.json, snapshots.pvd, snapshot_NNNN.csv / .vtp (four
/// digits: at most 10000 snapshots), and the .vtk of earlier versions.
inline bool atomic_output_name(const std::string& name) {
  if (name == "run.json" || name == "snapshots.pvd") return true;
  const std::string prefix = "snapshot_";
  if (name.size() != prefix.size() + 8 || name.rfind(prefix, 0) != 0) return false;
  for (size_t k = prefix.size(); k < prefix.size() + 4; ++k)
    if (!std::isdigit(static_cast<unsigned char>(name[k]))) return false;
  const std::string extension = name.substr(prefix.size() + 4);
  return extension == ".csv" || extension == ".vtp" || extension == ".vtk";
}

/// True if `name` is a file `mpm run` or `mpm plot` writes: the atomic ones and their hidden temporaries
/// (".run.json.partial"), observers.csv, energy.csv, exact.csv, plot.gp, plot.log, observers.png, energy.png.
inline bool run_output_name(const std::string& name) {
  const std::string partial = ".partial";
  if (name.size() > partial.size() + 1 && name[0] == '.' && name.compare(name.size() - partial.size(), partial.size(), partial) == 0)
    return atomic_output_name(name.substr(1, name.size() - partial.size() - 1));
  static const std::vector<std::string> fixed{"observers.csv", "energy.csv", "exact.csv", "plot.gp", "plot.log",
                                              "observers.png", "energy.png"};
  return atomic_output_name(name) || std::find(fixed.begin(), fixed.end(), name) != fixed.end();
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
    std::error_code error;
    if (entry.is_symlink(error))
      throw InputError(entry.path().string(), "is a symbolic link where mpm writes a file; mpm writes through no link: "
                                              "remove it, or give another --out");
    if (!entry.is_regular_file(error))
      throw InputError(entry.path().string(), "is not a regular file, and mpm writes a file of that name: remove it, "
                                              "or give another --out");
  }
}

/// An exclusive lock on a folder while a run or a plot writes into it (flock(2) on the folder itself: no file is
/// made, and the lock ends with the process, however it ends). A second run or plot into the same folder is
/// refused while the first goes on, so that the folder never mixes their files.
class FolderLock {
 public:
  /// \throws InputError if another process holds the folder, OutputFailure if it cannot be opened.
  explicit FolderLock(const std::string& folder) : descriptor_(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (descriptor_ < 0) throw OutputFailure(folder, std::strerror(errno));
    if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
      ::close(descriptor_);
      throw InputError(folder, "another mpm run or plot is writing into this folder; wait for it to end, or give another --out");
    }
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock() { ::close(descriptor_); }

 private:
  int descriptor_;
};

/// Removes the files an earlier run or plot wrote into `folder` (after check_run_folder).
/// \throws OutputFailure if one cannot be removed.
inline void clear_run_folder(const std::string& folder) {
  for (const auto& entry : run_outputs_in(folder)) {
    std::error_code error;
    std::filesystem::remove(entry.path(), error);
    if (error) throw OutputFailure(entry.path().string(), "cannot remove the file of an earlier run: " + error.message());
  }
}

TEST_CASE("run folder: an earlier run's files removed, other files kept, a link refused") {
  CHECK(run_output_name("snapshot_0001.csv"));
  CHECK(run_output_name("snapshot_9999.vtk"));
  CHECK(!run_output_name("snapshot_12345.vtk"));  // mpm writes four digits
  CHECK(!run_output_name("snapshot_00001.csv"));
  CHECK(!run_output_name(".plot.gp.partial"));    // plot writes no temporary
  CHECK(run_output_name(".run.json.partial"));
  CHECK(run_output_name(".snapshot_0003.vtp.partial"));
  CHECK(!run_output_name(".notes.partial"));
  CHECK(!run_output_name(".partial"));
  CHECK(!run_output_name("snapshot_001.csv"));
  CHECK(!run_output_name("snapshot_00a1.csv"));
  CHECK(!run_output_name("snapshot_0001.txt"));
  CHECK(!run_output_name("notes.csv"));
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("mpm_run_folder_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  for (const char* name : {"exact.csv", "snapshot_0009.vtk", "plot.gp", "mine.csv"}) std::ofstream(folder / name) << "x\n";
  check_run_folder(folder.string());
  clear_run_folder(folder.string());
  CHECK(!fs::exists(folder / "exact.csv"));
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
  fs::create_symlink(folder / "nothing", folder / "dangling");
  CHECK_THROWS_WITH_AS(check_run_folder((folder / "dangling").string()), doctest::Contains("link to nothing"), InputError);
  fs::create_directory(folder / "run.json");
  CHECK_THROWS_AS(check_run_folder(folder.string()), InputError);
  fs::remove_all(folder);
}

}  // namespace mpm::io
