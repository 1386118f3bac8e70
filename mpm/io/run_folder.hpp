/// \file
/// A run's output folder before the run writes into it. `mpm run` and `mpm plot` write files of known
/// names only (run_output_name); a new run first removes every such file an earlier run or plot left
/// there, so that the folder never mixes two runs (a stale exact.csv drawn beside new observers, the
/// snapshots of a longer run), and touches no other file. A symbolic link under one of those names was
/// not written by mpm: the run refuses it before writing anything rather than write through it.
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/core/errors.hpp"
#include "mpm/io/output_file.hpp"

namespace mpm::io {

/// True if `name` is a file `mpm run` or `mpm plot` writes: observers.csv, energy.csv, exact.csv, run.json,
/// snapshots.pvd, snapshot_NNNN.csv / .vtp (and the .vtk of earlier versions), plot.gp, plot.log, observers.png,
/// energy.png, and the hidden temporaries of the atomic writes (".run.json.partial", ".snapshot_0001.csv.partial").
inline bool run_output_name(const std::string& name) {
  const std::string partial = ".partial";
  if (name.size() > partial.size() + 1 && name[0] == '.' && name.compare(name.size() - partial.size(), partial.size(), partial) == 0)
    return run_output_name(name.substr(1, name.size() - partial.size() - 1));  // an atomic write's temporary
  static const std::vector<std::string> fixed{"observers.csv", "energy.csv", "exact.csv", "run.json", "snapshots.pvd",
                                              "plot.gp", "plot.log", "observers.png", "energy.png"};
  for (const std::string& file : fixed)
    if (name == file) return true;
  const std::string prefix = "snapshot_";
  const auto dot = name.rfind('.');
  if (name.rfind(prefix, 0) != 0 || dot == std::string::npos || dot < prefix.size() + 4) return false;
  for (size_t k = prefix.size(); k < dot; ++k)
    if (!std::isdigit(static_cast<unsigned char>(name[k]))) return false;
  const std::string extension = name.substr(dot);
  return extension == ".csv" || extension == ".vtp" || extension == ".vtk";
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

/// Refuses a folder holding a symbolic link or a non-file under an output's name; writes nothing.
/// \throws InputError naming the entry.
inline void check_run_folder(const std::string& folder) {
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
  CHECK(run_output_name("snapshot_12345.vtk"));
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
  fs::create_directory(folder / "run.json");
  CHECK_THROWS_AS(check_run_folder(folder.string()), InputError);
  fs::remove_all(folder);
}

}  // namespace mpm::io
