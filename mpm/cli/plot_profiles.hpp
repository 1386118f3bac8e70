/// \file
/// `mpm plot`'s profiles: at each snapshot of a run, profile_NNNN.png. In 1D the particles' velocity v_x(x) and
/// stress sigma_xx(x) (snapshot_NNNN.csv) against the exact profile of the run (exact_NNNN.csv, drawn at the exact
/// position X + u), over the grid's nodes; in 2D the particles coloured by a chosen field (--field) over the grid
/// lines, beside the exact field at the same material points when the run wrote it. What is drawn comes from the
/// run's own files (grid.csv, snapshots.pvd for the times): plot reads no scene.
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/cli/plot_table.hpp"

namespace mpm::cli {

/// The most snapshots drawn (profile_NNNN.png each); a run with more gets the first ones and a note.
constexpr std::size_t most_profiles = 100;
/// The most grid lines drawn on an axis; a finer grid is drawn without its lines (the title says so).
constexpr int most_grid_lines = 200;

/// One snapshot of a run: its number, its files (exact empty: none) and its time (NaN: not known).
struct SnapshotFiles {
  int index = 0;
  std::string csv, exact;
  double time = std::numeric_limits<double>::quiet_NaN();
};

/// The snapshots of the run in `folder`, in order: each snapshot_NNNN.csv, the exact_NNNN.csv beside it, and its
/// time as snapshots.pvd lists it.
inline std::vector<SnapshotFiles> snapshot_files(const std::string& folder) {
  namespace fs = std::filesystem;
  static const std::regex name(R"(snapshot_(\d{4})\.csv)");
  std::vector<SnapshotFiles> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    std::smatch match;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, match, name) || !entry.is_regular_file(error)) continue;
    SnapshotFiles snapshot{std::stoi(match[1]), file, "exact_" + match[1].str() + ".csv"};
    if (!fs::is_regular_file(fs::path(folder) / snapshot.exact, error)) snapshot.exact.clear();
    found.push_back(snapshot);
  }
  std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.index < b.index; });
  std::ifstream pvd(folder + "/snapshots.pvd");
  static const std::regex dataset(R"re(timestep="([^"]*)"[^>]*file="snapshot_(\d{4})\.vtp")re");
  for (std::string line; std::getline(pvd, line);) {
    std::smatch match;
    if (!std::regex_search(line, match, dataset)) continue;
    const double time = std::strtod(match[1].str().c_str(), nullptr);
    for (auto& snapshot : found)
      if (snapshot.index == std::stoi(match[2]) && std::isfinite(time)) snapshot.time = time;
  }
  return found;
}

/// The grid of grid.csv: per axis its first and last line (m) and its cells; none when the run wrote no grid.csv.
struct GridLines {
  std::vector<double> lower, upper;
  std::vector<int> cells;
};

/// grid.csv read and checked (finite ends in order, 1 to 10^9 cells). \throws Refused.
inline GridLines read_grid_lines(const std::string& folder) {
  const std::string path = folder + "/grid.csv";
  const PlotTable table = plot_table(path);
  GridLines grid;
  for (const char* axis : {"x", "y"}) {
    const int low = table.column(std::string(axis) + "_min"), high = table.column(std::string(axis) + "_max");
    const int cells = table.column(std::string(axis) + "_cells");
    if (low < 0 || high < 0 || cells < 0) break;
    const double count = table.low[cells];
    if (!(table.low[low] < table.high[high]) || !(count >= 1 && count <= 1e9) || count != std::round(count))
      throw Refused(path + ": " + axis + "_min < " + axis + "_max and a whole number of " + axis +
                    "_cells from 1 to 10^9 are needed");
    grid.lower.push_back(table.low[low]);
    grid.upper.push_back(table.high[high]);
    grid.cells.push_back(static_cast<int>(count));
  }
  return grid;
}

/// The gnuplot lines drawing the grid's lines behind the data (x lines only in 1D) and fixing the axes to the
/// grid; "" without a grid, and no lines where an axis has more than most_grid_lines.
inline std::string grid_arrows(const GridLines& grid, std::size_t axes) {
  std::ostringstream gp;
  gp.precision(17);
  for (std::size_t axis = 0; axis < std::min(axes, grid.cells.size()); ++axis) {
    const char* name = axis == 0 ? "x" : "y";
    gp << "set " << name << "range [" << grid.lower[axis] << ":" << grid.upper[axis] << "]\n";
    if (grid.cells[axis] > most_grid_lines) continue;
    for (int line = 0; line <= grid.cells[axis]; ++line) {
      const int cells = grid.cells[axis];  // weighted ends: a line at 0 is written 0, not 1.7e-18
      const double at = (grid.lower[axis] * (cells - line) + grid.upper[axis] * line) / cells;
      gp << "set arrow from " << (axis == 0 ? "first " : "graph 0, first ") << at << (axis == 0 ? ", graph 0" : "")
         << " to " << (axis == 0 ? "first " : "graph 1, first ") << at << (axis == 0 ? ", graph 1" : "")
         << " nohead back lc rgb c_context\n";
    }
  }
  return gp.str();
}

/// The column number (gnuplot counts from 1) of `name` in `table` of `file`. \throws Refused when it has none.
inline std::string column_number(const PlotTable& table, const std::string& name, const std::string& file) {
  const int k = table.column(name);
  if (k < 0) throw Refused(file + ": has no column " + name + "; is it a snapshot of an `mpm run`?");
  return std::to_string(k + 1);
}

/// The title of a snapshot's picture: its number, its time and what is missing.
inline std::string profile_title(const SnapshotFiles& snapshot, const GridLines& grid) {
  char title[96];
  std::snprintf(title, sizeof title, "snapshot %04d, t = %.6g s", snapshot.index, snapshot.time);
  std::string text = std::isnan(snapshot.time) ? "snapshot " + std::to_string(snapshot.index) : title;
  if (snapshot.exact.empty()) text += " (no exact solution)";
  for (int cells : grid.cells)
    if (cells > most_grid_lines) text += " (grid lines not drawn: more than " + std::to_string(most_grid_lines) + ")";
  return text;
}

/// The panels of a 1D snapshot: each quantity of `fields` of the particles against x, with the exact profile at
/// X + u_x when exact_NNNN.csv has it.
inline std::string profile_1d(const SnapshotFiles& snapshot, const PlotTable& particles, const PlotTable& exact,
                              const std::vector<std::string>& fields) {
  std::string gp = "set xlabel 'position x (m)'\n";
  const std::string x = column_number(particles, "x", snapshot.csv);
  for (const auto& field : fields) {
    ValueRange range;
    range.add(particles, particles.column(field));
    std::string plot = "plot '" + snapshot.csv + "' using " + x + ":" + column_number(particles, field, snapshot.csv) +
                       " with points pt 7 ps 0.8 lc rgb c_particle title 'particles'";
    if (exact.column(field) >= 0) {
      range.add(exact, exact.column(field));
      plot = "plot '" + snapshot.exact + "' using (column(" + column_number(exact, "X", snapshot.exact) +
             ") + column(" + column_number(exact, "u_x", snapshot.exact) + ")):" +
             column_number(exact, field, snapshot.exact) + " smooth unique with lines @exact_style title 'exact at X + u', " +
             plot.substr(5);
    }
    gp += "set ylabel " + gnuplot_quoted(quantity_label(field)) + "\n" + axis_range("y", range.low, range.high) +
          plot + "\n";
  }
  return gp;
}

/// The panels of a 2D snapshot: the particles at (x, y) coloured by `field`, and the exact field at (X + u, Y + v)
/// when exact_NNNN.csv has it, on one colour scale.
inline std::string profile_2d(const SnapshotFiles& snapshot, const PlotTable& particles, const PlotTable& exact,
                              const std::string& field) {
  ValueRange range;
  range.add(particles, particles.column(field));
  const bool with_exact = exact.column(field) >= 0;
  if (with_exact) range.add(exact, exact.column(field));
  std::string gp = "set size ratio -1\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset cblabel " +
                   gnuplot_quoted(quantity_label(field)) + "\n" + axis_range("cb", range.low, range.high) +
                   "set title 'particles'\nplot '" + snapshot.csv + "' using " +
                   column_number(particles, "x", snapshot.csv) + ":" + column_number(particles, "y", snapshot.csv) +
                   ":" + column_number(particles, field, snapshot.csv) + " with points pt 7 ps 0.6 palette notitle\n";
  if (!with_exact) return gp + "unset size\nunset title\n";
  const auto at = [&](const char* reference, const char* displacement) {
    return "(column(" + column_number(exact, reference, snapshot.exact) + ") + column(" +
           column_number(exact, displacement, snapshot.exact) + "))";
  };
  return gp + "set title 'exact at X + u'\nplot '" + snapshot.exact + "' using " + at("X", "u_x") + ":" +
         at("Y", "u_y") + ":" + column_number(exact, field, snapshot.exact) +
         " with points pt 7 ps 0.6 palette notitle\nunset size\nunset title\n";
}

/// The script of every snapshot's profile_NNNN.png (at most most_profiles), each file read and checked first.
/// `field`: the 2D colour ("" for sigma_yy), in 1D a panel after v_x and sigma_xx. \throws Refused.
inline std::string profile_script(const std::string& folder, const std::vector<SnapshotFiles>& snapshots,
                                  const std::string& field, std::vector<std::string>& pictures) {
  const GridLines grid = read_grid_lines(folder);
  std::string gp = "set key outside right top\nset autoscale\n";
  for (std::size_t k = 0; k < std::min(snapshots.size(), most_profiles); ++k) {
    const SnapshotFiles& snapshot = snapshots[k];
    const PlotTable particles = plot_table(folder + "/" + snapshot.csv);
    const PlotTable exact = snapshot.exact.empty() ? PlotTable{} : plot_table(folder + "/" + snapshot.exact);
    const bool two = particles.column("y") >= 0;
    const std::string colour = field.empty() ? "sigma_yy" : field;
    if (two ? particles.column(colour) < 0 || colour == "id" : !field.empty() && particles.column(field) < 0)
      throw Refused("--field: '" + colour + "' is not a column of " + folder + "/" + snapshot.csv +
                    " (give one of its columns after id: v_x, sigma_xx, density...)");
    char picture[32];
    std::snprintf(picture, sizeof picture, "profile_%04d.png", snapshot.index);
    pictures.push_back(folder + "/" + picture);
    std::vector<std::string> fields{"v_x", "sigma_xx"};
    if (!two && !field.empty() && field != "v_x" && field != "sigma_xx") fields.push_back(field);
    gp += std::string("set terminal pngcairo noenhanced size ") + (two ? "1000,480" : "1000,") +
          (two ? "" : std::to_string(260 * fields.size())) + " font ',11'\nset output '" + picture +
          "'\nset lmargin " + (two ? "-1" : "14") + "\nset rmargin " + (two ? "-1" : "at screen 0.8") +
          "\nset format x\nset format y\nset multiplot layout " + (two ? "1,2" : std::to_string(fields.size()) + ",1") +
          " title " +
          gnuplot_quoted(profile_title(snapshot, grid)) + "\n" + grid_arrows(grid, two ? 2 : 1) +
          (two ? profile_2d(snapshot, particles, exact, colour) : profile_1d(snapshot, particles, exact, fields)) +
          "unset multiplot\nunset output\nunset arrow\nset autoscale\n";
  }
  return gp;
}

TEST_CASE("mpm plot: profiles of a snapshot against the exact one, over the grid, round-off drawn flat") {
  // A flat 4.5 +- 1e-8 gets a range of 4.5 +- 4.5e-6, where it is a flat line; a real spread is autoscaled.
  CHECK(axis_range("y", 4.5 - 1e-8, 4.5 + 1e-8) == "set yrange [4.49999549999999:4.50000450000001]\n"
                                                   "set format y '%.10g'\n");
  CHECK(axis_range("y", 4.4, 4.5) == "set autoscale y\nset format y\n");
  CHECK(axis_range("cb", 0.0, 0.0) == "set autoscale cb\nset format cb\n");  // all zero: gnuplot widens it
  const GridLines grid{{-0.5, 0.0}, {1.5, 1.0}, {4, 2}};  // x lines at -0.5, 0, ..., 1.5; y at 0, 0.5, 1
  const std::string lines = grid_arrows(grid, 2);
  CHECK(lines.find("set xrange [-0.5:1.5]\n") == 0);
  CHECK(lines.find("set arrow from first 1, graph 0 to first 1, graph 1 nohead back") != std::string::npos);
  CHECK(lines.find("set arrow from graph 0, first 0.5 to graph 1, first 0.5 nohead back") != std::string::npos);
  CHECK(grid_arrows(grid, 1).find("graph 0, first") == std::string::npos);  // 1D: the nodes only
  const PlotTable particles{{"id", "x", "v_x", "sigma_xx", "density"}, {0, 0, -5, 0, 1}, {3, 1, 0, 2, 2}};
  const PlotTable exact{{"id", "X", "u_x", "v_x", "sigma_xx"}, {0, 0, 0, -5, 0}, {3, 1, 0, 0, 2}};
  const std::string gp = profile_1d({2, "snapshot_0002.csv", "exact_0002.csv", 1e-4}, particles, exact,
                                    {"v_x", "sigma_xx", "density"});
  CHECK(gp.find("set ylabel 'velocity v_x (m/s)'\n") != std::string::npos);
  CHECK(gp.find("plot 'exact_0002.csv' using (column(2) + column(3)):4 smooth unique with lines @exact_style title "
                "'exact at X + u', 'snapshot_0002.csv' using 2:3 with points") != std::string::npos);  // exact under
  CHECK(gp.find("'exact_0002.csv' using (column(2) + column(3)):5 smooth unique") != std::string::npos);
  CHECK(gp.find("set ylabel 'density (kg/m^3)'\nset autoscale y\nset format y\nplot 'snapshot_0002.csv' using 2:5 "
                "with points pt 7 ps 0.8 lc rgb c_particle title 'particles'\n") != std::string::npos);  // no exact
  CHECK(profile_title({2, "", "", 1e-4}, grid) == "snapshot 0002, t = 0.0001 s (no exact solution)");
  const PlotTable plane{{"id", "x", "y", "sigma_yy"}, {0, 0, 0, -1}, {1, 1, 1, 0}};
  const std::string colour = profile_2d({0, "snapshot_0000.csv", "", 0.0}, plane, {}, "sigma_yy");
  CHECK(colour.find("set cblabel 'stress sigma_yy (Pa, tension > 0)'\n") != std::string::npos);
  CHECK(colour.find("plot 'snapshot_0000.csv' using 2:3:4 with points pt 7 ps 0.6 palette") != std::string::npos);
  CHECK_THROWS_WITH_AS(column_number(plane, "v_y", "s.csv"),
                       "s.csv: has no column v_y; is it a snapshot of an `mpm run`?", Refused);
}

}  // namespace mpm::cli
