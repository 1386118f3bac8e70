/// \file
/// A body's particles read from a CSV file (body.shape = "file", body.file = "PATH"): one particle per row,
/// columns found by name in the header, any order, others ignored: x (and y in 2D, m), volume (m^3 per unit
/// area or thickness) or mass (kg likewise), optionally v_x (and v_y, m/s; default: body.velocity).
#pragma once
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "mpm/io/csv_file.hpp"

namespace mpm::io {

/// One particle of a file: position, mass (kg per unit area or thickness) and velocity, both axes (y ignored in 1D).
struct FileParticle {
  double x = 0.0, y = 0.0, mass = 0.0, v_x = 0.0, v_y = 0.0;
  double half_length = 0.0;  ///< l_p = V^(1/Dim) / 2 per axis: half the side of a square of its volume (uGIMP's)
  int line = 0;              ///< its row's line in the file, for errors found later (too large for uGIMP)
};

/// The most rows a particle file may hold.
inline constexpr std::size_t most_file_particles = 1'000'000;

/// Reads the particles of `path`; `default_velocity` where the file has no velocity columns. Returns an
/// empty list with `error` ("PATH:LINE: ...", the first bad row) on a problem.
inline std::vector<FileParticle> read_particle_file(const std::string& path, int dimension, double density,
                                                    const std::vector<double>& default_velocity, std::string& error) {
  CsvFile file(path);
  if (!file.read_header()) {
    error = file.error().empty()
                ? path + ": empty; a header line (x[,y],volume|mass[,v_x[,v_y]]) and one row per particle are needed"
                : file.error();
    return {};
  }
  const std::vector<std::string>& header = file.header();
  auto need = [&](bool holds, const std::string& what) {
    if (!holds && error.empty()) error = file.where() + what;
  };
  const std::vector<std::string> names{"x", "y", "volume", "mass", "v_x", "v_y"};
  std::vector<int> column;  // of each name, -1 where the header lacks it
  for (const std::string& name : names) {
    const auto first = std::find(header.begin(), header.end(), name);
    const bool twice = first != header.end() && std::find(first + 1, header.end(), name) != header.end();
    need(!twice, "column '" + name + "' appears twice");
    column.push_back(first == header.end() ? -1 : static_cast<int>(first - header.begin()));
  }
  if (dimension == 1) column[1] = column[5] = -1;  // y and v_y ignored
  need(column[0] >= 0 && (dimension == 1 || column[1] >= 0),
       dimension == 2 ? "the header needs the columns x and y" : "the header needs the columns x");
  need((column[2] < 0) != (column[3] < 0), "the header needs one of the columns volume or mass");
  need(dimension == 1 || (column[4] < 0) == (column[5] < 0), "give both v_x and v_y, or neither");
  std::vector<FileParticle> particles;
  for (std::vector<std::string> fields; error.empty() && file.next_row(fields);) {
    double value[6] = {0.0, 0.0, 0.0, 0.0, default_velocity.at(0), dimension == 2 ? default_velocity.at(1) : 0.0};
    for (int c = 0; c < 6; ++c) {
      const std::string wrong = column[c] < 0 ? "" : read_finite_number(fields[column[c]], value[c]);
      need(wrong.empty(), names[c] + ": " + wrong);
    }
    const double mass = column[2] >= 0 ? density * value[2] : value[3];
    need(mass > 0.0, names[column[2] >= 0 ? 2 : 3] + ": must be > 0");
    need(particles.size() < most_file_particles, "more than 1000000 particles");
    const double half_length = 0.5 * std::pow(mass / density, 1.0 / dimension);
    particles.push_back({value[0], value[1], mass, value[4], value[5], half_length, file.line()});
  }
  if (error.empty() && !file.error().empty()) error = file.error();
  else if (error.empty() && particles.empty()) error = path + ": holds no particle";
  return error.empty() ? particles : std::vector<FileParticle>{};
}

TEST_CASE("Particle file: columns by name, mass from volume, velocity optional, each bad row located") {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mpm_particle_file_" + std::to_string(::getpid()) + ".csv")).string();
  auto read = [&](const std::string& text, int dimension, std::string& error) {
    std::ofstream(path) << text;
    return read_particle_file(path, dimension, 1000.0, {0.5, -0.5}, error);
  };
  std::string error;
  const auto two = read("# two particles\nid,y,x,volume,v_y,v_x\n1,0.2,0.1,0.0025,3,4\n2, 0.3 ,0.4,0.01,0,0\n", 2, error);
  CHECK(error.empty());
  REQUIRE(two.size() == 2);
  CHECK(two[0].x == 0.1);
  CHECK(two[0].y == 0.2);
  CHECK(two[0].mass == doctest::Approx(2.5));  // 1000 kg/m^3 x 0.0025 m^2
  CHECK(two[0].v_x == 4.0);
  CHECK(two[1].y == 0.3);
  const auto bar = read("x,mass\n0.05,7.8\n", 1, error);
  REQUIRE(bar.size() == 1);
  CHECK(bar[0].mass == 7.8);
  CHECK(bar[0].v_x == 0.5);  // the body's velocity
  CHECK(read("\xEF\xBB\xBFx,mass\n0.05,7.8\n", 1, error).size() == 1);  // a spreadsheet's byte-order mark: x is still found
  CHECK(error.empty());
  read("x,y,mass\n0.1,0.2,-1\n", 2, error);
  CHECK(error == path + ":2: mass: must be > 0");
  error.clear();
  read("x,y,mass\n0.1,0.2\n", 2, error);
  CHECK(error == path + ":2: 2 fields; the header has 3");
  error.clear();
  read("x,mass\n0.1,heavy\n", 1, error);
  CHECK(error == path + ":2: mass: 'heavy' is not a finite number");
  error.clear();
  read("x,volume\n0.1,1e-320\n", 1, error);  // finite but subnormal: too small, not "not a finite number"
  CHECK(error.rfind(path + ":2: volume: '1e-320' is too small (below 2.2e-308", 0) == 0);
  error.clear();
  read("x,volume,mass\n0.1,1,1\n", 1, error);
  CHECK(error == path + ":1: the header needs one of the columns volume or mass");
  error.clear();
  read("x,y,mass,v_x\n0,0,1,1\n", 2, error);
  CHECK(error == path + ":1: give both v_x and v_y, or neither");
  std::filesystem::remove(path);
}

}  // namespace mpm::io
