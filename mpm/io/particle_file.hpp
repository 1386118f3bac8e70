/// \file
/// A body's particles read from a CSV file (body.shape = "file", body.file = "PATH"): one particle per row,
/// the columns found by name in the header line, any order, other columns ignored:
///   x (and y in 2D)          reference position, m
///   volume or mass           m^3 (1D: m, 2D: m^2, per unit area or thickness) or kg likewise; mass = density volume
///   v_x (and v_y), optional  initial velocity, m/s (default: body.velocity)
/// Each particle's half-length per axis is half the side of a square of its volume, l_p = V^(1/Dim) / 2
/// (what uGIMP needs). The path is relative to the scene file's folder. Every row is validated: a located
/// error `FILE:LINE: what` names the first bad one.
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/csv_file.hpp"

namespace mpm::io {

/// One particle of a file: position, mass (kg per unit area or thickness) and velocity, both axes (y ignored in 1D).
struct FileParticle {
  double x = 0.0, y = 0.0, mass = 0.0, v_x = 0.0, v_y = 0.0;
  int line = 0;  ///< its row's line in the file, for the errors found later (a particle too large for uGIMP)
};

/// The most rows a particle file may hold.
inline constexpr std::size_t most_file_particles = 1'000'000;

/// Reads the particles of `path`; `default_velocity` where the file has no velocity columns. Returns an
/// empty list with `error` ("PATH:LINE: ...") on a problem.
inline std::vector<FileParticle> read_particle_file(const std::string& path, int dimension, double density,
                                                    const std::vector<double>& default_velocity, std::string& error) {
  CsvFile file(path);
  if (!file.read_header()) {
    error = file.error().empty() ? path + ": empty; a header line (x[,y],volume|mass[,v_x[,v_y]]) and one row per particle are needed"
                                 : file.error();
    return {};
  }
  const std::vector<std::string>& header = file.header();
  int column_x = -1, column_y = -1, column_volume = -1, column_mass = -1, column_vx = -1, column_vy = -1;
  for (int k = 0; k < static_cast<int>(header.size()); ++k) {
    const std::string& name = header[k];
    int* column = name == "x" ? &column_x : name == "y" ? &column_y : name == "volume" ? &column_volume : name == "mass" ? &column_mass
                : name == "v_x" ? &column_vx : name == "v_y" ? &column_vy : nullptr;
    if (column && *column >= 0) {
      error = file.where() + "column '" + name + "' appears twice";
      return {};
    }
    if (column) *column = k;
  }
  if (column_x < 0 || (dimension == 2 && column_y < 0)) error = file.where() + "the header needs the columns x" + (dimension == 2 ? " and y" : "");
  else if ((column_volume < 0) == (column_mass < 0)) error = file.where() + "the header needs one of the columns volume or mass";
  else if (dimension == 2 && (column_vx < 0) != (column_vy < 0)) error = file.where() + "give both v_x and v_y, or neither";
  if (!error.empty()) return {};
  std::vector<FileParticle> particles;
  for (std::vector<std::string> fields; file.next_row(fields);) {
    const std::string where = file.where();
    auto number_at = [&](int column, double& value) {
      if (column < 0) return true;
      const std::string wrong = read_finite_number(fields[column], value);
      if (!wrong.empty()) error = where + header[column] + ": " + wrong;
      return wrong.empty();
    };
    FileParticle particle;
    particle.line = file.line();
    particle.v_x = default_velocity.at(0), particle.v_y = dimension == 2 ? default_velocity.at(1) : 0.0;
    double volume = 0.0;
    if (!number_at(column_x, particle.x) || !number_at(dimension == 2 ? column_y : -1, particle.y) ||
        !number_at(column_volume, volume) || !number_at(column_mass, particle.mass) || !number_at(column_vx, particle.v_x) ||
        !number_at(dimension == 2 ? column_vy : -1, particle.v_y))
      return {};
    if (column_volume >= 0) particle.mass = density * volume;
    if (!(particle.mass > 0.0)) {
      error = where + (column_volume >= 0 ? "volume" : "mass") + ": must be > 0";
      return {};
    }
    if (particles.size() == most_file_particles) {
      error = where + "more than 1000000 particles";
      return {};
    }
    particles.push_back(particle);
  }
  if (!file.error().empty()) error = file.error();
  else if (particles.empty()) error = path + ": holds no particle";
  return error.empty() ? particles : std::vector<FileParticle>{};
}

TEST_CASE("Particle file: columns by name, mass from volume, velocity optional, each bad row located") {
  const std::string path = (std::filesystem::temp_directory_path() / "mpm_particle_file_test.csv").string();
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
